"""Cell fields: the logarithmic strain of a cell against the stretches and rotation it was given, and
the components named by the kinematics.

Exact by construction: a cell moved by x = R diag(l) X + c has F = R diag(l), whose Hencky strain is
R diag(ln l) R^T exactly (round-off: 1e-12); in axisymmetry a radial stretch l_r gives the hoop
strain ln l_r at the cell's centre (F_hoop = r / R).
"""
import numpy as np
import pytest

from shockfem.elements.cells import AXISYMMETRIC, PLANE_STRAIN, THREE_D
from shockfem.output import cell_fields

# dolfinx's P1 vertex order (tensor product) on the unit square and cube
QUAD = np.array([[0, 0], [1, 0], [0, 1], [1, 1]], float)
HEX = np.array([[i, j, k] for k in (0, 1) for j in (0, 1) for i in (0, 1)], float)


def _rotation(angle, axis):
    axis = np.asarray(axis, float) / np.linalg.norm(axis)
    K = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + np.sin(angle) * K + (1 - np.cos(angle)) * K @ K


def _stored(tensor):
    return tensor[(0, 1, 2, 1, 0, 0), (0, 1, 2, 2, 2, 1)]


@pytest.mark.parametrize("cell, vertices", [("hexahedron", HEX), ("tetrahedron", HEX[[0, 1, 2, 4]])])
def test_hencky_strain_of_a_stretched_rotated_cell(cell, vertices):
    stretch = np.array([1.3, 0.8, 1.05])
    R = _rotation(0.7, (1.0, 2.0, -0.5))
    X = 2e-3 * vertices + np.array([0.1, -0.2, 0.3])
    x = X @ (R @ np.diag(stretch)).T + np.array([1.0, 2.0, 3.0])
    F = cell_fields.deformation_gradient(X, x, np.arange(len(X))[None, :], cell, False)
    assert np.allclose(F[0], R @ np.diag(stretch), atol=1e-12)
    h = cell_fields.hencky_strain(F)[0]
    assert np.allclose(h, _stored(R @ np.diag(np.log(stretch)) @ R.T), atol=1e-12)


def test_small_strain_is_the_engineering_strain():
    """eps = 1e-3 uniaxial: ln(1 + eps) = eps - eps^2/2, 5e-7 from eps (second order, as stated)."""
    X = HEX.copy()
    x = X * np.array([1.001, 1.0, 1.0])
    h = cell_fields.hencky_strain(cell_fields.deformation_gradient(X, x, np.arange(8)[None, :], "hexahedron",
                                                                   False))[0]
    assert h[0] == pytest.approx(1e-3, abs=6e-7) and h[0] == pytest.approx(np.log(1.001), rel=1e-12)
    assert np.abs(h[1:]).max() < 1e-15


def test_axisymmetric_hoop_strain_is_the_radial_stretch():
    X = np.array([1.0, 0.0]) + 0.1 * QUAD          # a ring cell at r = 1 .. 1.1
    x = X * np.array([1.02, 0.97])                  # r -> 1.02 r, z -> 0.97 z
    F = cell_fields.deformation_gradient(X, x, np.arange(4)[None, :], "quadrilateral", True)
    h = cell_fields.hencky_strain(F)[0]
    assert np.allclose(h[:3], np.log([1.02, 0.97, 1.02]), atol=1e-12) and np.abs(h[3:]).max() < 1e-15
    # plane strain: no strain out of the plane
    F = cell_fields.deformation_gradient(X, x, np.arange(4)[None, :], "quadrilateral", False)
    assert cell_fields.hencky_strain(F)[0][2] == 0.0


def test_components_are_named_by_the_kinematics():
    assert [a for a, _ in cell_fields.components(AXISYMMETRIC)] == ["rr", "zz", "hoop", "rz"]
    assert [c for _, c in cell_fields.components(AXISYMMETRIC)] == [0, 1, 2, 5]
    assert [a for a, _ in cell_fields.components(PLANE_STRAIN)] == ["xx", "yy", "zz", "xy"]
    assert [a for a, _ in cell_fields.components(THREE_D)] == ["xx", "yy", "zz", "yz", "xz", "xy"]


def test_von_mises_and_pressure():
    s = np.array([[100.0, 0, 0, 0, 0, 0], [0, 0, 0, 0, 0, 50.0], [-30.0, -30.0, -30.0, 0, 0, 0]])
    assert np.allclose(cell_fields.von_mises(s), [100.0, 50.0 * np.sqrt(3), 0.0])
    assert np.allclose(cell_fields.pressure(s), [-100.0 / 3, 0.0, 30.0])


@pytest.mark.parametrize("stretch", [(1.3, 0.8), (1.05, 1.05), (1.0 + 1e-9, 1.0), (10.0, 0.1), (1.0, 1e-3)])
def test_two_dimensional_closed_form_is_the_rotated_log_stretch(stretch):
    """``cell_fields._log_2x2`` (the in-plane strain of 2D cells without an eigen-solver): F = R diag(l) gives
    R diag(ln l) R^T, with equal stretches (a repeated eigenvalue), a stretch 1e-9 from the other (the series),
    and stretches 100 and 1000 apart (the far branch).  Round-off: 4e-15 of ln 1000."""
    angle = 0.4
    R = np.array([[np.cos(angle), -np.sin(angle)], [np.sin(angle), np.cos(angle)]])
    F = np.zeros((1, 3, 3))
    F[0, :2, :2] = R @ np.diag(stretch)
    F[0, 2, 2] = 1.1
    h = cell_fields.hencky_strain(F)[0]
    exact = R @ np.diag(np.log(stretch)) @ R.T
    assert np.allclose(h[[0, 1, 5]], exact[[0, 1, 0], [0, 1, 1]], rtol=0, atol=4e-15 * np.log(1000))
    assert h[2] == pytest.approx(np.log(1.1), rel=1e-15) and h[3] == h[4] == 0.0


def test_two_dimensional_closed_form_agrees_with_the_eigenvectors():
    """Random in-plane gradients (det above 0.05): the closed form against numpy's ``eigh`` of the same F with
    a third direction that is not principal removed, i.e. the 3D path.  ``eigh`` loses digits as F nears
    singular (1e-12 at det 1e-3 against a 40-digit reference, where the closed form was within 1e-14)."""
    rng = np.random.default_rng(7)
    F = np.zeros((2000, 3, 3))
    F[:, :2, :2] = np.eye(2) + rng.normal(scale=0.3, size=(2000, 2, 2))
    F[:, 2, 2] = rng.uniform(0.8, 1.2, 2000)
    F = F[np.linalg.det(F[:, :2, :2]) > 0.05]
    w, V = np.linalg.eigh(F @ np.swapaxes(F, 1, 2))
    reference = ((V * (0.5 * np.log(w))[:, None, :]) @ np.swapaxes(V, 1, 2))[:, (0, 1, 2, 1, 0, 0), (0, 1, 2, 2, 2, 1)]
    assert np.abs(cell_fields.hencky_strain(F) - reference).max() < 1e-13

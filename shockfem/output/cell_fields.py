"""What a cell field is: one value per cell, from the solver's stress points and the cell's motion.

The stress is stored per point as ``[s11, s22, s33, s23, s13, s12]`` (``elements/cells.py``); a cell's
value is the mean over its points.  Components are named by the kinematics' axes: ``rr, zz, hoop, rz``
in axisymmetry (coordinates (r, z), index 2 the hoop direction), ``xx, yy, zz, xy`` in plane strain
(``zz`` out of plane), ``xx, yy, zz, yz, xz, xy`` in 3D.

The strain is the logarithmic (Hencky) strain of the cell's deformation at its centre,
h = 1/2 ln(F F^T) in the current axes (the axes of the Cauchy stress): exact for any stretch and
rotation, equal to the engineering strain to second order when the strain is small (0.1%:
1e-6 apart), and the measure whose rate is the deformation rate d the kernels integrate, so that
a uniaxial bar's strain reads ln(l / l0).  F is dx/dX at the cell's reference centre (the
one-point elements' own point); in axisymmetry F_hoop = r / R at the centre.
"""
from __future__ import annotations

import numpy as np

from ..elements.cells import AXISYMMETRIC, PLANE_STRAIN
from ..materials.layout import S_EPS, S_RATE
from ..model import kinematics as kin

# (axis suffix, stress-storage column) per kinematics code
COMPONENTS = {
    AXISYMMETRIC: (("rr", 0), ("zz", 1), ("hoop", 2), ("rz", 5)),
    PLANE_STRAIN: (("xx", 0), ("yy", 1), ("zz", 2), ("xy", 5)),
}
COMPONENTS_3D = (("xx", 0), ("yy", 1), ("zz", 2), ("yz", 3), ("xz", 4), ("xy", 5))

# the scene's ``outputs.fields`` names of cell fields and the unit of each value they give
SCALARS = {"von_mises": "Pa", "pressure": "Pa", "plastic_strain": "-", "plastic_strain_rate": "1/s"}
TENSORS = {"stress": "Pa", "strain": "-"}


def components(kinematics: int) -> tuple:
    """The (axis suffix, storage column) pairs of a symmetric tensor in ``kinematics``."""
    return COMPONENTS.get(kinematics, COMPONENTS_3D)


def von_mises(sigma: np.ndarray) -> np.ndarray:
    """sqrt(3/2 s:s) of stresses stored as [..., 6] = [11, 22, 33, 23, 13, 12] [Pa]."""
    p = sigma[..., :3].mean(axis=-1)
    s = sigma[..., :3] - p[..., None]
    return np.sqrt(1.5 * ((s ** 2).sum(axis=-1) + 2.0 * (sigma[..., 3:] ** 2).sum(axis=-1)))


def pressure(sigma: np.ndarray) -> np.ndarray:
    """-tr(sigma)/3 [Pa], positive in compression."""
    return -sigma[..., :3].mean(axis=-1)


def deformation_gradient(X: np.ndarray, x: np.ndarray, dofmap: np.ndarray, cell: str,
                         axisymmetric: bool) -> np.ndarray:
    """F = dx/dX at the reference centre of every cell of ``dofmap``, (cells, 3, 3).

    X, x: (nodes, gdim) reference and current positions; ``cell`` the dolfinx cell name.  In 2D the
    third direction is the hoop (F_33 = r / R at the centre) or the plane-strain depth (1)."""
    dN = kin.centre_gradients(cell)                       # (nn, tdim), reference cell
    Xe, xe = X[dofmap], x[dofmap]                         # (cells, nn, gdim)
    # sum over the cell's nodes as one matrix product (a stack of small products runs cell by cell)
    J0 = np.tensordot(Xe, dN, axes=([1], [0]))            # dX/dxi (cells, gdim, tdim)
    J = np.tensordot(xe, dN, axes=([1], [0]))             # dx/dxi
    gdim = X.shape[1]
    F = np.zeros((len(dofmap), 3, 3))
    F[:, :gdim, :gdim] = J @ _inverse(J0)
    if gdim == 2:
        F[:, 2, 2] = xe[:, :, 0].mean(axis=1) / Xe[:, :, 0].mean(axis=1) if axisymmetric else 1.0
    return F


def _inverse(A: np.ndarray) -> np.ndarray:
    """The inverses of a stack of square matrices; 2 x 2 ones by the adjugate over the determinant (numpy's
    batched ``inv`` calls LAPACK matrix by matrix: 15x the time at 100k cells)."""
    if A.shape[1:] != (2, 2):
        return np.linalg.inv(A)
    det = A[:, 0, 0] * A[:, 1, 1] - A[:, 0, 1] * A[:, 1, 0]
    inv = np.empty_like(A)
    inv[:, 0, 0], inv[:, 1, 1] = A[:, 1, 1] / det, A[:, 0, 0] / det
    inv[:, 0, 1], inv[:, 1, 0] = -A[:, 0, 1] / det, -A[:, 1, 0] / det
    return inv


def hencky_strain(F: np.ndarray) -> np.ndarray:
    """h = 1/2 ln(F F^T) of (cells, 3, 3) deformation gradients, stored as (cells, 6) [11, 22, 33, 23, 13, 12].

    In 2D (F's third row and column zero but F_33: the hoop or the depth) the third direction is a principal
    one and the in-plane logarithm has a closed form (``_log_2x2``); otherwise from the eigenvectors."""
    if F[:, 2, :2].any() or F[:, :2, 2].any():
        w, V = np.linalg.eigh(F @ np.swapaxes(F, 1, 2))
        h = (V * (0.5 * np.log(w))[:, None, :]) @ np.swapaxes(V, 1, 2)
        return h[:, (0, 1, 2, 1, 0, 0), (0, 1, 2, 2, 2, 1)]
    h = np.zeros((len(F), 6))
    b11, b22, b12 = _log_2x2(F[:, :2, :2])
    h[:, 0], h[:, 1], h[:, 5] = 0.5 * b11, 0.5 * b22, 0.5 * b12
    h[:, 2] = np.log(np.abs(F[:, 2, 2]))
    return h


def _log_2x2(F2: np.ndarray):
    """ln(B) of B = F2 F2^T, (cells, 2, 2) in-plane gradients, as its entries (11, 22, 12).

    With B's eigenvalues l1,2 = m +- r (m its mean, r = sqrt(((B11 - B22) / 2)^2 + B12^2)), ln(B) = a I + b (B - m I)
    with a = (ln l1 + ln l2) / 2 = ln |det F2| and b = (ln l1 - ln l2) / (l1 - l2).  Neither needs the
    eigenvectors, and a repeated eigenvalue needs care only in b: b = atanh(r / m) / r, which is 1 / m as
    r -> 0 (its series below r / m = 1e-4).  Where the eigenvalues are more than a factor 3 apart (r > m / 2)
    b comes from l1 and l2 = det B / l1 instead: atanh near 1 loses digits in 1 - r / m.  Against numpy's
    ``eigh``: 5e-15 on random gradients with det F2 > 0.05 (``tests/unit/output/test_cell_fields.py``); nearer
    singular, eigh is the less accurate of the two (against a 40-digit mpmath reference on the five cells
    where they differ most, det F 1e-3 to 1e-2: this within 9e-15, eigh 1e-12 to 9e-12 off)."""
    f11, f12, f21, f22 = F2[:, 0, 0], F2[:, 0, 1], F2[:, 1, 0], F2[:, 1, 1]
    B11, B22, B12 = f11 * f11 + f12 * f12, f21 * f21 + f22 * f22, f11 * f21 + f12 * f22
    det = np.abs(f11 * f22 - f12 * f21)
    m = 0.5 * (B11 + B22)
    r = np.hypot(0.5 * (B11 - B22), B12)
    x = r / m
    near = x <= 0.5
    xs = np.where(near, x, 0.5)
    # atanh(x) / x, and its series 1 + x^2 / 3 (+ x^4 / 5, below 2e-17 there) where x < 1e-4
    ratio = np.where(xs > 1e-4, np.arctanh(xs) / np.where(xs > 1e-4, xs, 1.0), 1.0 + xs * xs / 3.0)
    l1 = m + r
    l2 = det * det / l1
    b = np.where(near, ratio / m, np.log(l1 / l2) / np.where(near, 1.0, l1 - l2))
    a = np.log(det)
    return a + b * (B11 - m), a + b * (B22 - m), b * B12


def cell_fields(solver, names, cells: int | None = None) -> dict[str, np.ndarray]:
    """The requested cell fields (``SCALARS`` and ``TENSORS`` names) of the first ``cells`` cells (all by
    default): ``{field name: (cells,) values}``, a tensor as one entry per component
    (``stress_rr``, ``strain_xy``, ...)."""
    m = solver.model
    n = len(m.dofmap) if cells is None else cells
    sigma = solver.sigma[:n].mean(axis=1)
    out = {}
    for name in names:
        if name == "von_mises":
            out[name] = von_mises(sigma)
        elif name == "pressure":
            out[name] = pressure(sigma)
        elif name in ("plastic_strain", "plastic_strain_rate"):
            column = S_EPS if name == "plastic_strain" else S_RATE
            out[name] = (solver.plastic_state[:n, :, column].mean(axis=1) if m.plastic else np.zeros(n))
        elif name in TENSORS:
            if name == "stress":
                tensor = sigma
            else:
                F = deformation_gradient(m.X0, solver.x, m.dofmap[:n], m.meshed.mesh.topology.cell_name(),
                                         m.axisymmetric)
                tensor = hencky_strain(F)
            for axes, column in components(m.kinematics):
                out[f"{name}_{axes}"] = np.ascontiguousarray(tensor[:, column])
    return out


def units(solver, names) -> dict[str, str]:
    """The unit of every value ``cell_fields`` gives for ``names``."""
    out = {}
    for name in names:
        if name in SCALARS:
            out[name] = SCALARS[name]
        elif name in TENSORS:
            for axes, _ in components(solver.model.kinematics):
                out[f"{name}_{axes}"] = TENSORS[name]
    return out

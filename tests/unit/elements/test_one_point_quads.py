"""The one-point quad pass in lanes: its two copies, and the blocks.

Provenance: the elastic copy updates the stress in lanes (``materials.update.elastic_update_stress``),
the general copy cell by cell through ``update_stress``, the same arithmetic for elastic rows; only the
compiler's order of operations may differ (fastmath), so every output must agree to round-off: 1e-13
of its largest entry (the differences seen are below 1e-15).  Against the scalar kernel this pass
replaced (session 22, ``git show 4c4bad2:shockfem/elements/one_point.py``) both copies agreed to 4.7e-16.
The forces themselves are checked against the one-point UFL form in ``test_one_point.py``.
"""
import numpy as np
import pytest

from shockfem.elements import kernels, one_point, one_point_quads
from shockfem.materials import layout

from element_helpers import NO_CURVES, NO_STATE, steel_params


def _mesh(nx=9, ny=7, seed=3):
    """A perturbed nx x ny grid of quads in tensor vertex order, r in [1, 50] mm."""
    rng = np.random.default_rng(seed)
    xs, ys = np.meshgrid(np.linspace(0.001, 0.05, nx + 1), np.linspace(0.0, 0.08, ny + 1), indexing="ij")
    x = np.c_[xs.ravel(), ys.ravel()] + rng.normal(size=((nx + 1) * (ny + 1), 2)) * 3e-4

    def node(i, j):
        return i * (ny + 1) + j
    dofmap = np.array([[node(i, j), node(i + 1, j), node(i, j + 1), node(i + 1, j + 1)]
                       for i in range(nx) for j in range(ny)], dtype=np.int32)
    return x, dofmap


def _params():
    """Two elastic rows, the second damped, both with bulk viscosity."""
    p = np.vstack([steel_params(), steel_params(E=70e9, rho=2700.0, beta=2e-8)])
    p[:, layout.P_Q_QUADRATIC], p[:, layout.P_Q_LINEAR] = 1.5, 0.06
    return p


def _run(kernel, x, dofmap, cells, v, axisymmetric, form, sign=None):
    n = len(dofmap)
    rng = np.random.default_rng(5)
    sigma = rng.normal(size=(n, 1, 6)) * 1e7
    sigma[..., 3:5] = 0.0
    hourglass = rng.normal(size=(n, 2)) * 10.0
    f = np.zeros_like(x)
    body_energy = np.zeros((2, 3))
    materials = (np.arange(n) % 3 == 0).astype(np.int32)
    sign = np.ones(n) if sign is None else sign
    out = kernel(cells, dofmap, materials, sign, x, v, 2e-7, axisymmetric, 0.7, form, 0.1, _params(), NO_CURVES,
                 NO_STATE, sigma, hourglass, f, body_energy)
    return out, {"f": f, "sigma": sigma, "hourglass": hourglass, "body_energy": body_energy}


@pytest.mark.parametrize("axisymmetric", [True, False])
@pytest.mark.parametrize("form", [one_point.HOURGLASS_FORMS["stiffness"], one_point.HOURGLASS_FORMS["viscous"]])
def test_elastic_lanes_agree_with_the_update_cell_by_cell(axisymmetric, form):
    """63 cells in shuffled order (one full block of LANES and a partial one), velocities that compress
    some cells and stretch others, two rows: every output to round-off, the critical cell exactly."""
    x, dofmap = _mesh()
    assert len(dofmap) % one_point_quads.LANES != 0 and len(dofmap) > one_point_quads.LANES
    cells = np.random.default_rng(7).permutation(len(dofmap)).astype(np.int32)
    v = np.random.default_rng(11).normal(size=x.shape) * 20.0
    ref_out, ref = _run(kernels.one_point_kernel(2, False), x, dofmap, cells, v, axisymmetric, form)
    out, got = _run(kernels.one_point_kernel(2, True), x, dofmap, cells, v, axisymmetric, form)
    for name in ref:
        scale = np.abs(ref[name]).max()
        assert np.abs(got[name] - ref[name]).max() <= 1e-13 * scale, name
    dt_stable, critical, damping, viscosity, plastic, hourglass_power, bad = out
    assert critical == ref_out[1] and bad == ref_out[6] == -1 and plastic == 0.0
    assert viscosity > 0.0 and damping > 0.0           # both viscous terms ran
    for a, b in zip((dt_stable, damping, viscosity, hourglass_power),
                    (ref_out[0], ref_out[2], ref_out[3], ref_out[5])):
        assert abs(a - b) <= 1e-13 * abs(b)


def test_an_inverted_cell_is_reported():
    """A cell of negative area (its orientation flipped) is reported by both copies."""
    x, dofmap = _mesh()
    cells = np.arange(len(dofmap), dtype=np.int32)
    sign = np.ones(len(dofmap))
    sign[40] = -1.0
    v = np.zeros_like(x)
    ref_out, _ = _run(kernels.one_point_kernel(2, False), x, dofmap, cells, v, True, 0, sign)
    out, _ = _run(kernels.one_point_kernel(2, True), x, dofmap, cells, v, True, 0, sign)
    assert out[6] == ref_out[6] == 40

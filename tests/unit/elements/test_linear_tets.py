"""The linear tetrahedra's pass in lanes (``elements.linear_tets``) against the general pass it replaces for
tets (``full_integration.stress_divergence``, itself checked against the UFL form in
``test_full_integration.py``).

Provenance: the two compute the same formulas (the mid-step gradients, Hooke's law after the
Hughes-Winget rotation, LS-DYNA's 3 V / largest face for the bulk viscosity and the stable step, the
forces V sigma grad N_a, the energies on the mid-step volume); only the order of operations differs (the
Jacobian from edges, fastmath), so every output agrees to round-off: 1e-12 of its largest entry (seen
on this mesh: at most 1.7e-15), the critical cell exactly.  Leaving node 0's force out, the damping, the bulk viscosity or
the rotation, or taking the end-of-step volume for the energies, fails them by far more.
"""
import numpy as np
import pytest
from dolfinx import fem, mesh
from mpi4py import MPI

from shockfem.elements import blocks, cells as ec, full_integration, kernels, linear_tets
from shockfem.materials import layout
from shockfem.model import kinematics as kin
from shockfem.output.cell_fields import von_mises

from element_helpers import NO_CURVES, NO_STATE, run_pass, steel_params


def _tets(seed=3):
    """A box of 720 tetrahedra (22 blocks of LANES and a partial one), its nodes perturbed."""
    m = mesh.create_box(MPI.COMM_SELF, [np.zeros(3), np.array([0.06, 0.04, 0.05])], [6, 4, 5],
                        mesh.CellType.tetrahedron)
    V = fem.VectorFunctionSpace(m, ("CG", 1))
    dofmap = np.ascontiguousarray(V.dofmap.list.array.reshape(-1, 4), dtype=np.int32)
    x = np.ascontiguousarray(V.tabulate_dof_coordinates())
    x += np.random.default_rng(seed).normal(size=x.shape) * 5e-4
    return x, dofmap


def _params():
    """Two elastic rows, the second damped, both with bulk viscosity."""
    p = np.vstack([steel_params(), steel_params(E=70e9, rho=2700.0, beta=2e-8)])
    p[:, layout.P_Q_QUADRATIC], p[:, layout.P_Q_LINEAR] = 1.5, 0.06
    return p


def _j2(yield_stress, points=1, tangent_modulus=0.0):
    """``_params``' rows made J2 with a yield stress [Pa] (a one-point curve, or two with a tangent modulus)."""
    p = _params()
    p[:, layout.P_LAW] = layout.J2
    p[:, layout.P_CURVE_POINTS] = points
    curves = np.zeros((2, 2, 2))
    curves[:, 0] = 0.0, yield_stress
    curves[:, 1] = 1.0, yield_stress + tangent_modulus
    return p, curves


def _run(kernel, x, dofmap, cells, v, materials, params, curves=NO_CURVES, plastic=False, sign=None):
    n = len(dofmap)
    rng = np.random.default_rng(5)
    sigma = rng.normal(size=(n, 1, 6)) * 1e7
    state = np.zeros((n, 1, layout.STATE_SIZE)) if plastic else NO_STATE
    f = np.zeros_like(x)
    body_energy = np.zeros((len(params), 3))
    points, wq, N, dN = kin.quadrature("tetrahedron", "3d")
    sign = ec.cell_orientation(dofmap, x, dN) if sign is None else sign
    peak = blocks.no_peak(len(params))
    out = run_pass(kernel, cells, dofmap, materials, sign, x, v, 2e-7, params, curves, state, sigma, f, body_energy,
                   rule=(N, dN, wq), kinematics=ec.THREE_D, cell_kind=kin.CELL_KINDS["tetrahedron"], peak=peak)
    return out, {"f": f, "sigma": sigma, "body_energy": body_energy, "state": state, "peak": peak}


def _agree(out, got, ref_out, ref, tol=1e-12):
    """Every output to ``tol`` of its largest entry.  Each row's peak stress to ``tol`` and its time exactly;
    its cell one that holds the peak in the reference's stresses, to ``tol`` (yielded cells of a perfectly
    plastic row all sit at the yield stress, to round-off: which of them is highest is round-off's choice)."""
    peak, ref_peak = got.pop("peak"), ref.pop("peak")
    np.testing.assert_allclose(peak[:, blocks.PEAK_VM2], ref_peak[:, blocks.PEAK_VM2], rtol=tol)
    np.testing.assert_array_equal(peak[:, blocks.PEAK_TIME], ref_peak[:, blocks.PEAK_TIME])
    ref_vm2 = von_mises(ref["sigma"])[:, 0] ** 2
    for row, ref_row in zip(peak, ref_peak):
        assert (row[blocks.PEAK_CELL] >= 0) == (ref_row[blocks.PEAK_CELL] >= 0)
        if ref_row[blocks.PEAK_CELL] >= 0:
            assert ref_vm2[int(row[blocks.PEAK_CELL])] == pytest.approx(ref_row[blocks.PEAK_VM2], rel=tol)
    for name in ref:
        scale = np.abs(ref[name]).max()
        assert np.abs(got[name] - ref[name]).max() <= tol * max(scale, 1e-300), name
    assert out[1] == ref_out[1] and out[6] == ref_out[6]            # critical and inverted cells
    assert out[5] == ref_out[5] == 0.0                             # no hourglass modes
    for a, b in zip((out[0], out[2], out[3], out[4]), (ref_out[0], ref_out[2], ref_out[3], ref_out[4])):
        assert abs(a - b) <= tol * abs(b)


@pytest.mark.parametrize("elastic_only", [True, False])
def test_the_tet_pass_agrees_with_the_general_pass(elastic_only):
    """Shuffled cells on two rows (every third on the damped one: mixed blocks), velocities that compress
    some cells and stretch others: forces, stresses, energies, step and powers to round-off."""
    x, dofmap = _tets()
    assert len(dofmap) % linear_tets.LANES != 0
    cells = np.random.default_rng(7).permutation(len(dofmap)).astype(np.int32)
    materials = (np.arange(len(dofmap)) % 3 == 0).astype(np.int32)
    v = np.random.default_rng(11).normal(size=x.shape) * 20.0
    args = (x, dofmap, cells, v, materials, _params())
    out, got = _run(kernels.element_pass(ec.TETRAHEDRON, False, elastic_only), *args)
    ref_out, ref = _run(full_integration.stress_divergence_kernel(elastic_only), *args)
    assert out[3] > 0.0 and out[2] > 0.0          # bulk viscosity and damping both ran
    _agree(out, got, ref_out, ref)


@pytest.mark.parametrize("points, tangent_modulus, one_row", [(1, 0.0, True), (2, 2e9, True), (1, 0.0, False)])
def test_yielding_tets_return_as_in_the_general_pass(points, tangent_modulus, one_row):
    """J2 rows with a yield stress (200 MPa) some cells' trial exceeds and others' does not: the lanes' trial
    for the latter, the return for the former, in lanes (a block of one row of linear hardening) or cell
    by cell (mixed blocks), against the general pass's ``update_stress`` at every cell: the same cells
    yield, and every output agrees to 1e-12 of its largest entry."""
    x, dofmap = _tets()
    cells = np.random.default_rng(7).permutation(len(dofmap)).astype(np.int32)
    materials = np.zeros(len(dofmap), np.int32) if one_row else (np.arange(len(dofmap)) % 3 == 0).astype(np.int32)
    v = np.random.default_rng(11).normal(size=x.shape) * 20.0
    params, curves = _j2(2e8, points, tangent_modulus)
    args = (x, dofmap, cells, v, materials, params, curves, True)
    out, got = _run(kernels.element_pass(ec.TETRAHEDRON, False, False), *args)
    ref_out, ref = _run(full_integration.stress_divergence_kernel(False), *args)
    yielded = ref["state"][:, 0, layout.S_EPS] > 0.0
    assert 0.1 < yielded.mean() < 0.9
    np.testing.assert_array_equal(got["state"][:, 0, layout.S_EPS] > 0.0, yielded)
    assert out[4] > 0.0
    _agree(out, got, ref_out, ref)


@pytest.mark.parametrize("elastic_only", [True, False])
def test_an_inverted_tet_is_reported(elastic_only):
    x, dofmap = _tets()
    cells = np.arange(len(dofmap), dtype=np.int32)
    points, wq, N, dN = kin.quadrature("tetrahedron", "3d")
    sign = ec.cell_orientation(dofmap, x, dN)
    sign[40] *= -1.0
    out, _ = _run(kernels.element_pass(ec.TETRAHEDRON, False, elastic_only), x, dofmap, cells, np.zeros_like(x),
                  np.zeros(len(dofmap), np.int32), _params(), sign=sign)
    assert out[6] == 40


def test_a_rigid_rotation_rotates_the_stress_exactly():
    """Objectivity: a rigid rotation over the step leaves sigma_np1 = R sigma_n R^T (as in
    ``test_full_integration.py``)."""
    x, dofmap = _tets()
    theta, dt = 0.3, 1e-5
    c, s = np.cos(theta), np.sin(theta)
    R = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1.0]]) @ np.array([[1, 0, 0], [0, 0.8, -0.6], [0, 0.6, 0.8]])
    x_np1 = np.ascontiguousarray(x @ R.T)
    v = (x_np1 - x) / dt
    points, wq, N, dN = kin.quadrature("tetrahedron", "3d")
    s0 = np.array([100e6, -20e6, 5e6, 7e6, -3e6, 11e6])
    sigma = np.tile(s0, (len(dofmap), 1, 1))
    run_pass(kernels.element_pass(ec.TETRAHEDRON, False, True), np.arange(len(dofmap), dtype=np.int32), dofmap,
             np.zeros(len(dofmap), np.int32), ec.cell_orientation(dofmap, x, dN), x_np1, v, dt, _params(), NO_CURVES,
             NO_STATE, sigma, np.zeros_like(x), np.zeros((2, 3)), rule=(N, dN, wq), kinematics=ec.THREE_D,
             cell_kind=ec.TETRAHEDRON)
    S0 = np.array([[s0[0], s0[5], s0[4]], [s0[5], s0[1], s0[3]], [s0[4], s0[3], s0[2]]])
    S1 = R @ S0 @ R.T
    expected = np.array([S1[0, 0], S1[1, 1], S1[2, 2], S1[1, 2], S1[0, 2], S1[0, 1]])
    assert np.allclose(sigma, expected, rtol=0, atol=1e-6 * np.abs(s0).max())


def test_other_cells_keep_the_general_pass():
    for kind in (ec.TRIANGLE, ec.QUADRILATERAL, ec.HEXAHEDRON):
        for elastic_only in (True, False):
            assert kernels.element_pass(kind, False, elastic_only) is full_integration.stress_divergence_kernel(elastic_only)

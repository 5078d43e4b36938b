"""The compiled stress-divergence kernel against its UFL definition, assembled by dolfinx."""
import numpy as np
import pytest
import ufl
from dolfinx import fem, mesh

from shockfem import compat
from shockfem.model import kinematics as kin
from shockfem.elements import blocks, cells as ec, full_integration
from shockfem.materials import layout
from shockfem.output.cell_fields import von_mises

from element_helpers import NO_CURVES, NO_STATE, distorted_mesh as _mesh, run_pass, steel_params as _params

CASES = [("axisymmetric", mesh.CellType.quadrilateral), ("axisymmetric", mesh.CellType.triangle),
         ("plane-strain", mesh.CellType.quadrilateral), ("3d", mesh.CellType.hexahedron),
         ("3d", mesh.CellType.tetrahedron)]


def _arrays(m, kinematics):
    V = fem.VectorFunctionSpace(m, ("CG", 1))
    gdim = m.geometry.dim
    cell = m.topology.cell_name()
    nn = {"triangle": 3, "quadrilateral": 4, "tetrahedron": 4, "hexahedron": 8}[cell]
    dofmap = np.ascontiguousarray(V.dofmap.list.array.reshape(-1, nn), dtype=np.int32)
    X = np.ascontiguousarray(V.tabulate_dof_coordinates()[:, :gdim])
    points, wq, N, dN = kin.quadrature(cell, kinematics)
    return V, dofmap, X, wq, N, dN, kin.CELL_KINDS[cell]


@pytest.mark.parametrize("kinematics, cell", CASES)
def test_internal_force_matches_ufl_form(kinematics, cell):
    m = _mesh(kinematics, cell)
    V, dofmap, X, wq, N, dN, kind = _arrays(m, kinematics)
    ncell = len(dofmap)
    nq = len(wq)
    rng = np.random.default_rng(1)
    sigma = rng.normal(size=(ncell, nq, 6)) * 1e6
    if kinematics != "3d":
        sigma[..., 3:5] = 0.0        # no out-of-plane shear in 2D
    f = np.zeros_like(X)
    cells = np.arange(ncell, dtype=np.int32)
    # dt = 0 and v = 0: the stress stays as given and the kernel only assembles the force
    sign = ec.cell_orientation(dofmap, X, dN)
    run_pass(full_integration.stress_divergence, cells, dofmap, np.zeros(ncell, np.int32), sign, X, np.zeros_like(X),
             0.0, _params(), NO_CURVES, NO_STATE, sigma.copy(), f, np.zeros((1, 3)), rule=(N, dN, wq),
             kinematics=kin.CODES[kinematics], thickness=0.7, cell_kind=kind)
    degree = kin.quadrature_degree(m.topology.cell_name(), kinematics)
    Qe = ufl.VectorElement("Quadrature", m.ufl_cell(), degree=degree, dim=6, quad_scheme="default")
    s6 = fem.Function(fem.FunctionSpace(m, Qe))
    s6.x.array[:] = sigma.ravel()
    w = ufl.TestFunction(V)
    dx = ufl.dx(metadata={"quadrature_degree": degree, "quadrature_scheme": "default"})
    form = fem.form(kin.internal_force_form(s6, w, kinematics, thickness=0.7) * dx)
    b = np.zeros(f.size)
    compat.assemble_vector_into(b, form)
    assert np.allclose(f.ravel(), b, rtol=1e-12, atol=1e-12 * np.abs(b).max())


@pytest.mark.parametrize("elastic_only", [True, False])
def test_rigid_rotation_rotates_stress_exactly(elastic_only):
    """Objectivity: a rigid rotation by R over the step leaves sigma_np1 = R sigma_n R^T, in both copies
    of the kernel (without law calls, and for any law)."""
    m = _mesh("3d", mesh.CellType.hexahedron)
    V, dofmap, X, wq, N, dN, kind = _arrays(m, "3d")
    theta, dt = 0.3, 1e-5
    c, s = np.cos(theta), np.sin(theta)
    R = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1.0]]) @ np.array([[1, 0, 0], [0, 0.8, -0.6], [0, 0.6, 0.8]])
    x_np1 = np.ascontiguousarray(X @ R.T)
    v = (x_np1 - X) / dt
    ncell, nq = len(dofmap), len(wq)
    s0 = np.array([100e6, -20e6, 5e6, 7e6, -3e6, 11e6])
    sigma = np.tile(s0, (ncell, nq, 1))
    run_pass(full_integration.stress_divergence_kernel(elastic_only), np.arange(ncell, dtype=np.int32), dofmap,
             np.zeros(ncell, np.int32), ec.cell_orientation(dofmap, X, dN), x_np1, v, dt, _params(), NO_CURVES,
             NO_STATE, sigma, np.zeros_like(X), np.zeros((1, 3)), rule=(N, dN, wq), kinematics=ec.THREE_D,
             cell_kind=kind)
    S0 = np.array([[s0[0], s0[5], s0[4]], [s0[5], s0[1], s0[3]], [s0[4], s0[3], s0[2]]])
    S1 = R @ S0 @ R.T
    expected = np.array([S1[0, 0], S1[1, 1], S1[2, 2], S1[1, 2], S1[0, 2], S1[0, 1]])
    assert np.allclose(sigma, expected, rtol=0, atol=1e-6 * np.abs(s0).max())


@pytest.mark.parametrize("elastic_only", [True, False])
def test_uniform_stretch_gives_hooke_stress(elastic_only):
    """A uniform velocity gradient over one step adds dt * C : d at every point."""
    m = _mesh("plane-strain", mesh.CellType.quadrilateral)
    V, dofmap, X, wq, N, dN, kind = _arrays(m, "plane-strain")
    L = np.array([[1.0, 0.0], [0.0, -0.5]])     # 1/s
    dt = 1e-6
    v = X @ L.T
    x_np1 = X + dt * v
    ncell, nq = len(dofmap), len(wq)
    sigma = np.zeros((ncell, nq, 6))
    p = _params()
    run_pass(full_integration.stress_divergence_kernel(elastic_only), np.arange(ncell, dtype=np.int32), dofmap,
             np.zeros(ncell, np.int32), ec.cell_orientation(dofmap, X, dN), x_np1, v, dt, p, NO_CURVES, NO_STATE,
             sigma, np.zeros_like(X), np.zeros((len(p), 3)), rule=(N, dN, wq), kinematics=ec.PLANE_STRAIN,
             cell_kind=kind)
    lam, mu = p[0, layout.P_LAMBDA], p[0, layout.P_MU]
    # the mid-step configuration differs from X by dt/2 * v: strain rate exact to O(dt)
    tr = 0.5
    assert np.allclose(sigma[..., 0], dt * (lam * tr + 2 * mu * 1.0), rtol=1e-5)
    assert np.allclose(sigma[..., 1], dt * (lam * tr - 2 * mu * 0.5), rtol=1e-5)
    assert np.allclose(sigma[..., 2], dt * lam * tr, rtol=1e-5)


def test_characteristic_length_of_unit_cells():
    sq = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0.0]])
    assert ec.characteristic_length(sq, 1, 4) == pytest.approx(1 / np.sqrt(2))
    tri = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0.0]])
    assert ec.characteristic_length(tri, 0, 3) == pytest.approx(1 / np.sqrt(2))   # smallest altitude
    cube = np.array([[i & 1, (i >> 1) & 1, (i >> 2) & 1] for i in range(8)], dtype=float)
    assert ec.characteristic_length(cube, 3, 8) == pytest.approx(1 / np.sqrt(3))
    tet = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1.0]])
    assert ec.characteristic_length(tet, 2, 4) == pytest.approx(1 / np.sqrt(3))


@pytest.mark.parametrize("kinematics, cell", CASES)
def test_cell_orientation_is_the_sign_of_the_jacobian(kinematics, cell):
    """+1 or -1 per cell as det(J) at the first point (numpy's determinant), and the opposite sign for the
    cells whose vertex order is mirrored (every other cell)."""
    m = _mesh(kinematics, cell)
    V, dofmap, X, wq, N, dN, kind = _arrays(m, kinematics)
    mirror = {3: [1, 0, 2], 4: [1, 0, 2, 3] if cell == mesh.CellType.tetrahedron else [1, 0, 3, 2],
              8: [1, 0, 3, 2, 5, 4, 7, 6]}[dofmap.shape[1]]
    flipped = dofmap.copy()
    flipped[::2] = dofmap[::2][:, mirror]
    for d in (dofmap, flipped):
        J = np.einsum("cai,ak->cik", X[d], dN[0][:, :X.shape[1]])
        np.testing.assert_array_equal(ec.cell_orientation(d, X, dN), np.sign(np.linalg.det(J)))
    np.testing.assert_array_equal(ec.cell_orientation(flipped, X, dN)[::2], -ec.cell_orientation(dofmap, X, dN)[::2])


@pytest.mark.parametrize("elastic_only", [True, False])
def test_each_row_keeps_the_peak_over_its_cells_points(elastic_only):
    """2x2 quads, shuffled, on two rows (every third cell on row 1), the stress left as given (dt = 0, v = 0):
    each row's peak is the largest squared von Mises stress over its cells' points (to 1e-12: the pass's
    formula, in another order), at the pass's time, in the first cell of ``cells`` that holds it (exactly);
    the stresses doubled at a later time move all three."""
    m = _mesh("axisymmetric", mesh.CellType.quadrilateral)
    V, dofmap, X, wq, N, dN, kind = _arrays(m, "axisymmetric")
    ncell, nq = len(dofmap), len(wq)
    cells = np.random.default_rng(3).permutation(ncell).astype(np.int32)
    rows = (np.arange(ncell) % 3 == 0).astype(np.int32)
    p = np.vstack([_params(), _params(E=100e9)])
    sigma = np.random.default_rng(4).normal(size=(ncell, nq, 6)) * 1e7
    sigma[..., 3:5] = 0.0
    peak = blocks.no_peak(len(p))

    def step(t):
        run_pass(full_integration.stress_divergence_kernel(elastic_only), cells, dofmap, rows,
                 ec.cell_orientation(dofmap, X, dN), X, np.zeros_like(X), 0.0, p, NO_CURVES, NO_STATE, sigma,
                 np.zeros_like(X), np.zeros((len(p), 3)), rule=(N, dN, wq), kinematics=ec.AXISYMMETRIC,
                 cell_kind=kind, t_np1=t, peak=peak)

    def expected(t):
        vm2 = (von_mises(sigma) ** 2).max(axis=1)               # each cell's largest over its points
        out = []
        for r in range(len(p)):
            mine = cells[rows[cells] == r]
            out.append((vm2[mine].max(), t, mine[np.argmax(vm2[mine])]))
        return np.array(out)

    step(1e-6)
    first = expected(1e-6)
    assert (np.argmax(von_mises(sigma), axis=1) > 0).any()     # some cells' highest point is not their first
    np.testing.assert_allclose(peak[:, blocks.PEAK_VM2], first[:, 0], rtol=1e-12)
    np.testing.assert_array_equal(peak[:, 1:], first[:, 1:])
    sigma *= 2.0
    step(2e-6)
    np.testing.assert_allclose(peak[:, blocks.PEAK_VM2], 4.0 * first[:, 0], rtol=1e-12)
    np.testing.assert_array_equal(peak[:, 1:], expected(2e-6)[:, 1:])

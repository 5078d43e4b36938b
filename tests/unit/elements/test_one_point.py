"""One-point quads and hexes: the force against the one-point UFL form, hourglass control, objectivity."""
import basix
import numpy as np
import pytest
import ufl
from dolfinx import fem, mesh

from shockfem import compat
from shockfem.model import kinematics as kin
from shockfem.elements import cells as ec, kernels, one_point
from shockfem.materials import layout

from element_helpers import NO_CURVES, NO_STATE, distorted_mesh as _mesh, run_pass, steel_params as _params

STIFFNESS, VISCOUS = one_point.HOURGLASS_FORMS["stiffness"], one_point.HOURGLASS_FORMS["viscous"]


def _arrays(m):
    V = fem.VectorFunctionSpace(m, ("CG", 1))
    gdim = m.geometry.dim
    nn = 4 if gdim == 2 else 8
    dofmap = np.ascontiguousarray(V.dofmap.list.array.reshape(-1, nn), dtype=np.int32)
    X = np.ascontiguousarray(V.tabulate_dof_coordinates()[:, :gdim])
    _, _, _, dN = kin.quadrature(m.topology.cell_name(), "3d" if gdim == 3 else "plane-strain", "reduced")
    return V, dofmap, X, ec.cell_orientation(dofmap, X, dN)


def _run(kinematics, dofmap, sign, x, v, dt, sigma, hourglass, form=STIFFNESS, coefficient=0.05, params=None,
         elastic_only=True):
    """Call the one-point kernel for the kinematics; returns (f, dt_stable, damping_power, hourglass_power, bad)
    (the critical cell, bulk viscosity power and plastic work are left out: elastic, no viscosity).
    ``elastic_only`` picks the kernel's loop (both must give the same for elastic rows)."""
    f = np.zeros_like(x)
    cells = np.arange(len(dofmap), dtype=np.int32)
    mats = np.zeros(len(dofmap), np.int32)
    p = _params() if params is None else params
    out = run_pass(kernels.element_pass(ec.HEXAHEDRON if kinematics == "3d" else ec.QUADRILATERAL, True, elastic_only),
                   cells, dofmap, mats, sign, x, v, dt, p, NO_CURVES, NO_STATE, sigma, f, np.zeros((len(p), 3)),
                   kinematics=kin.CODES[kinematics], thickness=0.7, hourglass=hourglass, hourglass_form=form,
                   hourglass_coefficient=coefficient)
    dt_stable, _, damping_power, _, _, hourglass_power, bad = out
    return f, dt_stable, damping_power, hourglass_power, bad


@pytest.mark.parametrize("kinematics, cell", [("axisymmetric", mesh.CellType.quadrilateral),
                                              ("plane-strain", mesh.CellType.quadrilateral),
                                              ("3d", mesh.CellType.hexahedron)])
def test_force_matches_one_point_ufl_form(kinematics, cell):
    """Stress only (v = 0, no hourglass resultant): the force is the stress divergence at the centre point."""
    m = _mesh(kinematics, cell)
    V, dofmap, X, sign = _arrays(m)
    rng = np.random.default_rng(2)
    sigma = rng.normal(size=(len(dofmap), 1, 6)) * 1e6
    if kinematics != "3d":
        sigma[..., 3:5] = 0.0
    hg = np.zeros((len(dofmap), 2 if kinematics != "3d" else 12))
    f, *_ = _run(kinematics, dofmap, sign, X, np.zeros_like(X), 0.0, sigma.copy(), hg)
    Qe = ufl.VectorElement("Quadrature", m.ufl_cell(), degree=1, dim=6, quad_scheme="default")
    s6 = fem.Function(fem.FunctionSpace(m, Qe))
    s6.x.array[:] = sigma.ravel()
    dx = ufl.dx(metadata={"quadrature_degree": 1, "quadrature_scheme": "default"})
    form = fem.form(kin.internal_force_form(s6, ufl.TestFunction(V), kinematics, thickness=0.7) * dx)
    b = np.zeros(f.size)
    compat.assemble_vector_into(b, form)
    assert np.allclose(f.ravel(), b, rtol=1e-12, atol=1e-12 * np.abs(b).max())


@pytest.mark.parametrize("kinematics, cell", [("plane-strain", mesh.CellType.quadrilateral),
                                              ("axisymmetric", mesh.CellType.quadrilateral),
                                              ("3d", mesh.CellType.hexahedron)])
def test_linear_velocity_field_excites_no_hourglass(kinematics, cell):
    """Flanagan-Belytschko shape vectors are orthogonal to linear fields: a uniform strain rate
    on a distorted mesh gives zero hourglass rate, resultant and power."""
    m = _mesh(kinematics, cell)
    _, dofmap, X, sign = _arrays(m)
    gdim = X.shape[1]
    L = np.array([[0.3, 0.1, -0.2], [0.05, -0.4, 0.1], [0.2, 0.0, 0.25]])[:gdim, :gdim]
    v = X @ L.T + 0.7
    dt = 1e-7
    hg = np.zeros((len(dofmap), 2 if gdim == 2 else 12))
    for form in (STIFFNESS, VISCOUS):
        hg[:] = 0.0
        _, _, _, power, bad = _run(kinematics, dofmap, sign, X + dt * v, v, dt, np.zeros((len(dofmap), 1, 6)), hg,
                                   form=form, coefficient=0.1)
        assert bad == -1
        assert abs(power) < 1e-12 * 1e9 * dt
        assert np.abs(hg).max() < 1e-10 * (1e9 * dt)


@pytest.mark.parametrize("gdim", [2, 3])
def test_hourglass_mode_is_resisted_and_its_energy_counted(gdim):
    """One unit square (cube) moving in its xi*eta hourglass mode: no strain at the centre point, so
    the only force is the hourglass resultant; it opposes the mode with the documented stiffness."""
    ref = basix.geometry(basix.CellType.quadrilateral if gdim == 2 else basix.CellType.hexahedron)
    h = one_point.hourglass_vectors(ref)
    X = np.ascontiguousarray(ref * 0.01)                     # a 10 mm square / cube
    dofmap = np.arange(len(X), dtype=np.int32)[None, :]
    sign = np.ones(1)
    v = np.zeros_like(X)
    v[:, 0] = h[0]                                           # 1 m/s amplitude of the xi eta mode along x
    dt = 1e-7
    hg = np.zeros((1, 2 if gdim == 2 else 12))
    sigma = np.zeros((1, 1, 6))
    kinematics = "plane-strain" if gdim == 2 else "3d"
    p = _params()
    f, dt_stable, _, power, _ = _run(kinematics, dofmap, sign, X + dt * v, v, dt, sigma, hg, coefficient=0.1,
                                     params=p)
    lam, mu = p[0, layout.P_LAMBDA], p[0, layout.P_MU]
    n = len(X)
    # b:b of a square (cube) of side a: 2/a^2 (3/(2 a^2)); volume a^2 * thickness (a^3); q = |h|^2 = n
    a = 0.01
    vol, bb = (a * a * 0.7, 2 / a ** 2) if gdim == 2 else (a ** 3, 1.5 / a ** 2)
    k = 0.1 * (lam + 2 * mu) * vol * bb / n ** 2
    Q = k * dt * n
    assert np.abs(sigma).max() < 1e-6 * (lam * dt / a)     # the centre point sees no strain
    # to O(dt v / a) = 1e-5: the end-of-step cell is the square moved by dt * v
    assert np.allclose(f[:, 0], h[0] * Q, rtol=1e-4)
    assert np.allclose(f[:, 1:], 0.0, atol=1e-4 * Q)
    assert power == pytest.approx(0.5 * Q * n, rel=1e-4)    # (0 + Q)/2 . q > 0: the mode is resisted
    c = p[0, layout.P_WAVE_SPEED]
    assert dt_stable == pytest.approx(a / (np.sqrt(gdim) * c), rel=1e-4)


@pytest.mark.parametrize("elastic_only", [True, False])
def test_rigid_rotation_rotates_stress_and_hourglass_resultants(elastic_only):
    """Objectivity of the one-point hex: over a step that rotates the mesh rigidly by R, the stress
    becomes R sigma R^T and the stiffness-form resultants R Q, in both copies of the kernel's loop
    (the elastic one and the one that calls the laws)."""
    m = _mesh("3d", mesh.CellType.hexahedron)
    _, dofmap, X, sign = _arrays(m)
    theta, dt = 0.3, 1e-5
    c, s = np.cos(theta), np.sin(theta)
    R = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1.0]]) @ np.array([[1, 0, 0], [0, 0.8, -0.6], [0, 0.6, 0.8]])
    x_np1 = np.ascontiguousarray(X @ R.T)
    v = (x_np1 - X) / dt
    s0 = np.array([100e6, -20e6, 5e6, 7e6, -3e6, 11e6])
    sigma = np.tile(s0, (len(dofmap), 1, 1))
    q0 = np.tile(np.arange(1.0, 13.0), (len(dofmap), 1))
    hg = q0.copy()
    _run("3d", dofmap, sign, x_np1, v, dt, sigma, hg, elastic_only=elastic_only)
    S0 = np.array([[s0[0], s0[5], s0[4]], [s0[5], s0[1], s0[3]], [s0[4], s0[3], s0[2]]])
    S1 = R @ S0 @ R.T
    expected = np.array([S1[0, 0], S1[1, 1], S1[2, 2], S1[1, 2], S1[0, 2], S1[0, 1]])
    assert np.allclose(sigma[:, 0], expected, rtol=0, atol=1e-6 * np.abs(s0).max())
    # the rigid motion adds no hourglass rate, so the resultants are only rotated
    assert np.allclose(hg.reshape(-1, 4, 3), q0.reshape(-1, 4, 3) @ R.T, atol=1e-6 * 12)

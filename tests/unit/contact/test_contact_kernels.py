"""Penalty contact kernels: a single node against a segment and against a plane."""
import numpy as np
import pytest

from shockfem.contact import kernels


def _one_node_on_segment(gap, v_close=0.0, zeta=0.0, k=1e6, soft_scale=0.0, dt=0.0):
    # master segment from (1, 0) to (0, 0): outward normal (t_y, -t_x) = (0, +1), slave above it
    x = np.array([[1.0, 0.0], [0.0, 0.0], [0.25, gap]])
    v = np.array([[0.0, 0.0], [0.0, 0.0], [0.0, -v_close]])
    mass = np.array([1.0, 1.0, 2.0])
    f = np.zeros_like(x)
    g = np.zeros(1)
    active, dt = kernels.node_to_segment_2d(np.array([2]), np.array([[0, 1]]), np.array([k]),
                                            np.array([0, 1]), np.array([0]), x, v, mass, zeta, soft_scale, dt,
                                            0.1, f, g, np.zeros(1))
    return f, g, active, dt


def test_penetrating_node_is_pushed_out_and_master_pushed_back():
    f, g, active, dt = _one_node_on_segment(-1e-4)
    assert active == 1 and g[0] == pytest.approx(-1e-4)
    assert f[2] == pytest.approx([0.0, 1e6 * 1e-4])               # k |g| along the outward normal
    # reaction shared by the shape functions at xi = 0.75 from node 0 to node 1
    assert f[0] == pytest.approx([0.0, -0.25 * 100.0]) and f[1] == pytest.approx([0.0, -0.75 * 100.0])
    assert f.sum(axis=0) == pytest.approx([0.0, 0.0], abs=1e-12)   # momentum conserved
    m_master = 0.25 * 1.0 + 0.75 * 1.0
    m_eff = 2.0 * m_master / (2.0 + m_master)
    assert dt == pytest.approx(np.sqrt(2 * m_eff / 1e6))


def test_separated_node_feels_nothing_and_contact_never_pulls():
    f, g, active, _ = _one_node_on_segment(+1e-4)
    assert active == 0 and not f.any()
    # penetrating but separating fast: damping would pull; the force is clipped at zero
    f, _, active, _ = _one_node_on_segment(-1e-6, v_close=-100.0, zeta=0.5)
    assert active == 1 and not f.any()


def test_penalty_spring_stores_the_work_done_on_it():
    """Pushing a node in quasi-statically from g = 0 to -d stores k d^2 / 2."""
    k, d, n = 1e6, 1e-4, 2000
    work = 0.0
    for gap in np.linspace(0.0, -d, n + 1)[1:]:
        f, *_ = _one_node_on_segment(gap, k=k)
        work += f[2, 1] * (d / n)
    assert work == pytest.approx(0.5 * k * d ** 2, rel=2e-3)


def test_node_against_moving_plane():
    x = np.array([[0.0, -2e-5], [1.0, 1e-3]])
    v = np.zeros_like(x)
    f = np.zeros_like(x)
    g = np.zeros(2)
    active, _ = kernels.node_to_plane(np.array([0, 1]), np.array([1e7, 1e7]), np.array([0.0, 0.0]),
                                      np.array([0.0, 1.0]), np.array([0.0, 0.0]), x, v, np.ones(2), 0.0, 0.0, 0.0,
                                      0.1, f, g, np.zeros(2))
    assert active == 1
    assert f[0] == pytest.approx([0.0, 1e7 * 2e-5]) and not f[1].any()


def test_soft_penalty_raises_a_weak_spring_to_the_nodal_mass_stiffness():
    """penalty = "soft": k = max(k_segment, scale m* / (2 dt^2)) (LS-DYNA SOFT=1); a stiffer segment wins."""
    dt, scale = 1e-6, 0.1
    m_master = 1.0
    m_eff = 2.0 * m_master / (2.0 + m_master)
    k_soft = 0.5 * scale * m_eff / dt ** 2
    f, *_ = _one_node_on_segment(-1e-6, k=1.0, soft_scale=scale, dt=dt)
    assert f[2, 1] == pytest.approx(k_soft * 1e-6)
    f, *_ = _one_node_on_segment(-1e-6, k=10 * k_soft, soft_scale=scale, dt=dt)
    assert f[2, 1] == pytest.approx(10 * k_soft * 1e-6)


"""Penalty contact kernels: a single node against a segment, a face, a plane and a cylinder; friction."""
import numpy as np
import pytest

from shockfem.contact import kernels

NO_FRICTION = np.zeros(3)


def _one_node_on_segment(gap, v_close=0.0, zeta=0.0, k=1e6, soft_scale=0.0, dt=0.0, v_slide=0.0,
                         friction=NO_FRICTION, ft=None):
    # master segment from (1, 0) to (0, 0): outward normal (t_y, -t_x) = (0, +1), slave above it
    x = np.array([[1.0, 0.0], [0.0, 0.0], [0.25, gap]])
    v = np.array([[0.0, 0.0], [0.0, 0.0], [v_slide, -v_close]])
    mass = np.array([1.0, 1.0, 2.0])
    f = np.zeros_like(x)
    ff = np.zeros_like(x)
    g = np.zeros(1)
    ft = np.zeros((1, 3)) if ft is None else ft
    stiff = np.zeros(3)
    active = kernels.node_to_facets(np.array([2]), np.array([[0, 1]]), np.array([k]), np.array([0, 1]),
                                    np.array([0]), x, v, mass, zeta, soft_scale, dt, 0.1, friction, f, ff, ft,
                                    g, np.zeros(1), stiff)
    return f, g, active, stiff, ff


def test_penetrating_node_is_pushed_out_and_master_pushed_back():
    f, g, active, stiff, _ = _one_node_on_segment(-1e-4)
    assert active == 1 and g[0] == pytest.approx(-1e-4)
    assert f[2] == pytest.approx([0.0, 1e6 * 1e-4])               # k |g| along the outward normal
    # reaction shared by the shape functions at xi = 0.75 from node 0 to node 1
    assert f[0] == pytest.approx([0.0, -0.25 * 100.0]) and f[1] == pytest.approx([0.0, -0.75 * 100.0])
    assert f.sum(axis=0) == pytest.approx([0.0, 0.0], abs=1e-12)   # momentum conserved
    # absolute row sums of the spring's stiffness matrix, 2 k w_i, for the Gershgorin step bound
    assert stiff == pytest.approx([2e6 * 0.25, 2e6 * 0.75, 2e6])


def test_separated_node_feels_nothing_and_contact_never_pulls():
    f, g, active, *_ = _one_node_on_segment(+1e-4)
    assert active == 0 and not f.any()
    # penetrating but separating fast: damping would pull; the force is clipped at zero
    f, _, active, *_ = _one_node_on_segment(-1e-6, v_close=-100.0, zeta=0.5)
    assert active == 1 and not f.any()


def test_arriving_node_counts_its_spring_in_the_stable_step_but_takes_no_force():
    """A node 1 um in front of the segment closing at 1 m/s: with dt = 1 us it crosses within two
    steps, so its spring's row sums (2 k w_i, as if active) bound the next step (docs/theory.md);
    at 0.4 m/s it does not, and counts nothing.  Either way no force and not active."""
    f, g, active, stiff, _ = _one_node_on_segment(1e-6, v_close=1.0, dt=1e-6)
    assert active == 0 and not f.any()
    assert stiff == pytest.approx([2e6 * 0.25, 2e6 * 0.75, 2e6])
    f, g, active, stiff, _ = _one_node_on_segment(1e-6, v_close=0.4, dt=1e-6)
    assert active == 0 and not f.any() and not stiff.any()


def test_penalty_spring_stores_the_work_done_on_it():
    """Pushing a node in quasi-statically from g = 0 to -d stores k d^2 / 2."""
    k, d, n = 1e6, 1e-4, 2000
    work = 0.0
    for gap in np.linspace(0.0, -d, n + 1)[1:]:
        f, *_ = _one_node_on_segment(gap, k=k)
        work += f[2, 1] * (d / n)
    assert work == pytest.approx(0.5 * k * d ** 2, rel=2e-3)


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


def test_friction_sticks_elastically_then_slides_at_mu_fn():
    """Stick: the tangential spring k moves by -k dt v_t; slip: capped at mu f_n against the sliding."""
    k, gap, mu = 1e6, -1e-4, 0.3
    fn = k * 1e-4
    ft = np.zeros((1, 3))
    friction = np.array([mu, mu, 0.0])
    # a slow slide of 1e-6 m in one step: elastic, f_t = -k * 1e-6 = -1 N (< mu f_n = 30 N)
    f, _, _, _, ff = _one_node_on_segment(gap, k=k, dt=1e-6, v_slide=1.0, friction=friction, ft=ft)
    assert ff[2] == pytest.approx([-1.0, 0.0])
    assert ff.sum(axis=0) == pytest.approx([0.0, 0.0], abs=1e-12)       # the master gets it back
    assert ff[0, 0] == pytest.approx(0.25 * 1.0) and ff[1, 0] == pytest.approx(0.75 * 1.0)
    # the stick force is history: the same slide again adds another -1 N
    f, _, _, _, ff = _one_node_on_segment(gap, k=k, dt=1e-6, v_slide=1.0, friction=friction, ft=ft)
    assert ff[2, 0] == pytest.approx(-2.0)
    # a long step of slip: capped at mu f_n, opposing the sliding velocity
    f, _, _, _, ff = _one_node_on_segment(gap, k=k, dt=1e-3, v_slide=1.0, friction=friction, ft=ft)
    assert ff[2] == pytest.approx([-mu * fn, 0.0])
    # sliding the other way reverses it
    f, _, _, _, ff = _one_node_on_segment(gap, k=k, dt=1e-3, v_slide=-1.0, friction=friction, ft=ft)
    assert ff[2] == pytest.approx([mu * fn, 0.0])
    # out of contact the history is forgotten
    _one_node_on_segment(+1e-4, k=k, dt=1e-3, friction=friction, ft=ft)
    assert not ft.any()


def test_friction_coefficient_decays_from_static_to_dynamic():
    """mu = mu_d + (mu_s - mu_d) exp(-decay |v_t|) (LS-DYNA FS, FD, DC)."""
    k, mu_s, mu_d, decay, speed = 1e6, 0.5, 0.2, 2.0, 0.7
    f, _, _, _, ff = _one_node_on_segment(-1e-4, k=k, dt=1.0, v_slide=speed, friction=np.array([mu_s, mu_d, decay]))
    mu = mu_d + (mu_s - mu_d) * np.exp(-decay * speed)
    assert -ff[2, 0] == pytest.approx(mu * k * 1e-4)


def _node_on_unit_square(face, slave, k=1e6):
    x = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0], slave])
    f = np.zeros_like(x)
    g = np.zeros(1)
    active = kernels.node_to_facets(np.array([4]), np.array([face]), np.array([k]), np.array([0, 1]),
                                    np.array([0]), x, np.zeros_like(x), np.ones(5), 0.0, 0.0, 0.0, 0.1,
                                    NO_FRICTION, f, np.zeros_like(x), np.zeros((1, 3)), g, np.zeros(1), np.zeros(5))
    return f, g, active


@pytest.mark.parametrize("face", [[0, 1, 2, 3], [0, 1, 2]])
def test_node_against_a_3d_face_bilinear_quad_and_triangle(face):
    """The outward normal (p1 - p0) x (p_last - p0) is +z: a node 1e-4 behind the face at (0.3, 0.2) is
    pushed along +z, and the reaction is shared by the face's shape functions at the contact point."""
    f, g, active = _node_on_unit_square(face, [0.3, 0.2, -1e-4])
    assert active == 1 and g[0] == pytest.approx(-1e-4)
    assert f[4] == pytest.approx([0.0, 0.0, 100.0])
    if len(face) == 4:
        w = [0.7 * 0.8, 0.3 * 0.8, 0.3 * 0.2, 0.7 * 0.2]           # bilinear weights at (0.3, 0.2)
    else:
        w = [0.7, 0.1, 0.2, 0.0]                                    # barycentric in triangle (0, 1, 2)
    assert f[:4, 2] == pytest.approx([-100.0 * wi for wi in w])
    assert f.sum(axis=0) == pytest.approx([0.0, 0.0, 0.0], abs=1e-10)


def test_node_beside_a_3d_face_is_not_caught():
    f, g, active = _node_on_unit_square([0, 1, 2, 3], [1.3, 0.5, -1e-4])
    assert active == 0 and not f.any()


def test_bilinear_projection_on_a_warped_face():
    """A warped face (one corner lifted): the node on the surface itself has zero gap."""
    x = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.2], [0.0, 1.0, 0.0], [0.0, 0.0, 0.0]])
    xi, eta = 0.4, -0.1
    N = 0.25 * np.array([(1 - xi) * (1 - eta), (1 + xi) * (1 - eta), (1 + xi) * (1 + eta), (1 - xi) * (1 + eta)])
    x[4] = N @ x[:4]
    w, n = np.zeros(4), np.zeros(3)
    g, outside = kernels._project(np.array([0, 1, 2, 3]), x, 4, w, n)
    assert outside == 0.0 and abs(g) < 1e-12 and w == pytest.approx(N)


def _rigid(kind, x, direction, point, radius=0.0, inside=False, k=1e7, velocity=None, offset=None):
    x = np.asarray(x, dtype=float)
    offset = np.zeros(len(x)) if offset is None else offset
    v = np.zeros_like(x)
    f = np.zeros_like(x)
    g = np.zeros(len(x))
    vel = np.zeros(x.shape[1]) if velocity is None else np.asarray(velocity, dtype=float)
    every = np.arange(len(x))
    active = kernels.node_to_rigid(every, every, np.full(len(x), k), kind, np.asarray(point, dtype=float),
                                   np.asarray(direction, dtype=float), radius, inside, vel, x, v,
                                   np.ones(len(x)), 0.0, 0.0, 0.0, 0.1, NO_FRICTION, f, np.zeros_like(x),
                                   np.zeros((len(x), 3)), g, offset, np.zeros(len(x)))
    return f, g, active


def test_node_against_moving_plane():
    f, g, active = _rigid(kernels.PLANE, [[0.0, -2e-5], [1.0, 1e-3]], [0.0, 1.0], [0.0, 0.0])
    assert active == 1
    assert f[0] == pytest.approx([0.0, 1e7 * 2e-5]) and not f[1].any()


def test_nodes_inside_a_rigid_tube_are_pushed_back_toward_the_axis():
    """A tube of radius 1 along z: a node at r = 1 + 1e-5 is pushed radially inward, one at r = 0.9 is free."""
    d = 1e-5
    x = [[(1 + d) / np.sqrt(2), (1 + d) / np.sqrt(2), 5.0], [0.9, 0.0, 0.0]]
    f, g, active = _rigid(kernels.CYLINDER, x, [0.0, 0.0, 1.0], [0.0, 0.0, 0.0], radius=1.0, inside=True)
    assert active == 1 and g[0] == pytest.approx(-d)
    assert f[0] == pytest.approx([-1e7 * d / np.sqrt(2), -1e7 * d / np.sqrt(2), 0.0]) and not f[1].any()


def test_a_tunnel_holds_only_what_has_passed_its_mouth():
    """A tunnel of radius 1 from the origin along -z (a penetrator's hole): a node 1e-5 outside it at
    z = -2 is pushed back toward the axis; the same node at z = +2, not yet at the mouth, is free."""
    d = 1e-5
    x = [[1 + d, 0.0, -2.0], [1 + d, 0.0, 2.0]]
    f, g, active = _rigid(kernels.TUNNEL, x, [0.0, 0.0, -1.0], [0.0, 0.0, 0.0], radius=1.0, inside=True,
                          offset=np.zeros(2))
    assert active == 1 and g[0] == pytest.approx(-d)
    assert f[0] == pytest.approx([-1e7 * d, 0.0, 0.0]) and not f[1].any()


def test_a_node_entering_a_tunnel_outside_it_is_held_where_it_entered():
    """A yawed tail crosses the mouth 0.1 outside the radius: no push inward at entry (its wall is where
    it entered); moved a further 1e-5 out it is pushed back by k 1e-5; moved in, its wall stays."""
    d = 1e-5
    offset = np.full(1, kernels.NOT_ENTERED)
    f, g, _ = _rigid(kernels.TUNNEL, [[1.1, 0.0, -0.5]], [0.0, 0.0, -1.0], [0.0, 0.0, 0.0], radius=1.0, inside=True,
                     offset=offset)
    assert not f.any() and offset[0] == pytest.approx(-0.1)
    f, g, _ = _rigid(kernels.TUNNEL, [[1.1 + d, 0.0, -0.6]], [0.0, 0.0, -1.0], [0.0, 0.0, 0.0], radius=1.0,
                     inside=True, offset=offset)
    assert f[0] == pytest.approx([-1e7 * d, 0.0, 0.0])
    _rigid(kernels.TUNNEL, [[1.0, 0.0, -0.7]], [0.0, 0.0, -1.0], [0.0, 0.0, 0.0], radius=1.0, inside=True,
           offset=offset)
    assert offset[0] == pytest.approx(-0.1)


def test_nodes_outside_a_rigid_cylinder_and_the_axisymmetric_and_plane_forms():
    d = 1e-5
    # outside a 3D cylinder along x through (0, 0, 1): a node at distance 0.5 - d is pushed away
    f, g, active = _rigid(kernels.CYLINDER, [[3.0, 0.0, 1.0 - (0.5 - d)]], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0],
                          radius=0.5)
    assert active == 1 and f[0] == pytest.approx([0.0, 0.0, -1e7 * d])
    # axisymmetric: the cylinder r = 1 about the symmetry axis, node at r = 1 + d inside it
    f, g, active = _rigid(kernels.CYLINDER, [[1 + d, 0.3]], [0.0, 1.0], [0.0, 0.0], radius=1.0, inside=True)
    assert f[0] == pytest.approx([-1e7 * d, 0.0])
    # plane strain: the circle of radius 1 about (2, 0), node at (2, 1 - d) inside the disc
    f, g, active = _rigid(kernels.CYLINDER, [[2.0, 1 - d]], [0.0, 0.0], [2.0, 0.0], radius=1.0)
    assert f[0] == pytest.approx([0.0, 1e7 * d])


def test_node_behind_a_concave_vertex_is_caught():
    """A dented master (body below): segments (2,0)-(1,0) and (1,0)-(0,0.1) meet at a concave vertex (1, 0).
    Below it, the projections of a node with 1 - 0.1 |y| < x < 1 fall beyond the ends of both segments;
    such a node, inside the body, is caught at the vertex."""
    x = np.array([[2.0, 0.0], [1.0, 0.0], [0.0, 0.1], [1.0 - 0.5e-5, -1e-4]])
    f = np.zeros_like(x)
    g = np.zeros(1)
    segments = np.array([[0, 1], [1, 2]])
    w, n = np.zeros(4), np.zeros(3)
    outside = [kernels._project(segments[j], x, 3, w, n)[1] for j in range(2)]
    assert min(outside) > 0.0                        # neither segment takes the node's projection
    active = kernels.node_to_facets(np.array([3]), segments, np.array([1e6, 1e6]), np.array([0, 2]),
                                    np.array([0, 1]), x, np.zeros_like(x), np.ones(4), 0.0, 0.0, 0.0, 0.1,
                                    NO_FRICTION, f, np.zeros_like(x), np.zeros((1, 3)), g, np.zeros(1), np.zeros(4))
    assert active == 1 and g[0] < 0.0 and f[3, 1] > 0.0


def test_rigid_master_facets_take_the_slave_sides_stiffness():
    """A rigid body's modulus is a placeholder: against a foam its facets get the foam's bulk modulus
    (the pad's light nodes would otherwise need a hundredfold shorter step); a deformable master keeps
    its own (LS-DYNA's k = scale K A^2 / V)."""
    from shockfem.contact.pairs import master_stiffness
    from shockfem.contact.surfaces import Surface
    one = np.ones(2)
    steel = Surface("striker.bottom", 1, np.zeros((2, 2), dtype=np.int64), 2e-4 * one, 0.01 * one, 175e9 * one,
                    1e-6 * one)
    foam = Surface("pad.top", 0, np.zeros((2, 2), dtype=np.int64), 1e-4 * one, 0.01 * one, 50e6 * one, 1e-6 * one)
    assert np.allclose(master_stiffness(steel, foam, 0.1, rigid=True), 0.1 * 50e6 * 4e-8 / 1e-6, rtol=1e-14)
    assert np.allclose(master_stiffness(steel, foam, 0.1, rigid=False), 0.1 * 175e9 * 4e-8 / 1e-6, rtol=1e-14)

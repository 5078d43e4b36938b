"""metrics.flexure: a body's bending from stations on its axis."""
import numpy as np
import pytest

from shockfem.metrics.flexure import station_travel, tail_flexure


def test_a_rigid_motion_bends_nothing_and_a_parabola_bends_uniformly():
    """Five stations over L = 0.4 m (spacing s = 0.1 m).  A translation plus a rotation, u = a + b z,
    gives no deflection and no stress; a parabola u = c z^2 has curvature 2c everywhere (stress E R 2c)
    and its base stands 8 c s^2 off the line through the tip and mid-length (u_0 - (2 u_2 - u_4))."""
    z = np.linspace(0.0, 0.4, 5)[:, None]
    rigid = 1e-3 + 2e-2 * z * np.ones((1, 3))
    deflection, bending = tail_flexure(rigid, 0.4, 0.03, 200e9)
    assert np.allclose(deflection, 0.0, atol=1e-15) and np.allclose(bending, 0.0, atol=1e-3)
    c = 0.05
    deflection, bending = tail_flexure(c * z ** 2 * np.ones((1, 3)), 0.4, 0.03, 200e9)
    assert deflection == pytest.approx(np.full(3, 8 * c * 0.1 ** 2))
    assert bending == pytest.approx(np.full(3, 200e9 * 0.03 * 2 * c))
    # vectors: the magnitude of the lateral components
    vec = np.stack([c * z ** 2, -c * z ** 2], axis=-1) * np.ones((1, 3, 1))
    deflection, bending = tail_flexure(vec, 0.4, 0.03, 200e9)
    assert deflection == pytest.approx(np.full(3, np.sqrt(2) * 8 * c * 0.1 ** 2))


def test_station_travel_integrates_the_velocities():
    t = np.linspace(0.0, 1.0, 101)
    u = station_travel(t, np.array([2 * t, np.ones_like(t)]))
    assert u[0, -1] == pytest.approx(1.0) and u[1, -1] == pytest.approx(1.0) and u[:, 0].tolist() == [0.0, 0.0]
    with pytest.raises(ValueError, match="odd number of stations"):
        tail_flexure(np.zeros((4, 3)), 1.0, 0.1, 1.0)

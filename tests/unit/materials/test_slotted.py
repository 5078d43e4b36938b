"""The slotted ring's hoop law at one material point (``materials/slotted.py``), through the material
update the one-point kernel calls (``materials.update.update_stress``): the hoop rate it
gives the metal of an open ring keeps the hoop stress at zero through plastic flow (and is the
rate the material-point driver finds for zero hoop stress), the slots close at their width of
circumference, and a closed ring carries hoop compression but opens again rather than pull."""
import math

import numpy as np
import pytest

from shockfem.materials.layout import S_EPS, S_SLOT, STATE_SIZE
from shockfem.materials.update import update_stress
from shockfem.model.materials import parameter_table
from shockfem.verify.material_point import COPPER, MaterialPoint, material

R = 0.03          # radius of the point [m]


class SlottedPoint:
    """One point of a slotted ring at radius R, stepped by the one-point kernel's material update (no spin)."""

    def __init__(self, fields, width):
        mat = material(fields)
        self.params, self.curves = parameter_table([mat], None, (0.0, 0.0), [width])
        self.sigma = np.zeros(6)
        self.state = np.zeros((1, 1, STATE_SIZE))

    def step(self, d, dt):
        """Advance by dt at the ring's strain rate d; returns the hoop rate the metal took."""
        s, d_metal, _ = update_stress(self.params, self.curves, 0, self.state, 0, 0, tuple(map(float, self.sigma)),
                                      tuple(map(float, d)), (0.0, 0.0, 0.0), dt, R, False)
        self.sigma = np.array(s)
        return d_metal[2]

    @property
    def closed(self):
        return self.state[0, 0, S_SLOT]


def test_open_slots_keep_the_hoop_stress_zero_through_plastic_flow():
    """Radial crushing of an open ring's metal (axial strain held): it yields (von Mises reaches
    the copper's 400 MPa), its hoop stress stays zero, and its hoop rate is the driver's."""
    point = SlottedPoint(COPPER, width=1.0)           # slots far too wide to close
    driver = MaterialPoint(material(COPPER))
    dt, rate = 1e-7, -2e3
    for _ in range(100):                              # to 2% radial strain, 5 times yield
        d2 = point.step([rate, 0.0, 0.0, 0.0, 0.0, 0.0], dt)
        assert abs(point.sigma[2]) < 1e-6 * 400e6
        d = driver.step({0: rate, 1: 0.0}, (2,), dt)
        assert d2 == pytest.approx(d[2], rel=1e-6, abs=1e-9)
    assert point.state[0, 0, S_EPS] > 0.01
    assert np.allclose(point.sigma, driver.sigma, rtol=1e-6, atol=1e-3)


def test_slots_close_at_their_width_then_carry_compression_and_open_rather_than_pull():
    """An elastic ring shrinking at a hoop rate d (radial and axial strain held): no stress until
    the circumference has shrunk by the slots' width, then lambda + 2 mu times the further hoop
    strain; reversed, the stress falls back to zero and the slots open instead of the metal
    pulling."""
    width = 0.002
    point = SlottedPoint({"density": 7850.0, "youngs_modulus": 210e9, "poisson_ratio": 0.3}, width)
    E = 210e9
    modulus = E * 0.7 / (1.3 * 0.4)                                  # lambda + 2 mu at nu = 0.3
    dt, d2 = 1e-7, -100.0
    steps_to_close = width / (2 * math.pi * R) / (-d2 * dt)          # about 1061
    n = 0
    while n < steps_to_close - 1:
        point.step([0, 0, d2, 0, 0, 0], dt)
        n += 1
        assert point.sigma[2] == 0.0 or abs(point.sigma[2]) < 1e-9 * E
    for _ in range(200):
        point.step([0, 0, d2, 0, 0, 0], dt)
        n += 1
    assert point.closed == pytest.approx(width)
    # after closing, the metal takes the ring's hoop strain: closed at n_c, stress (lambda + 2 mu) d2 dt (n - n_c)
    expected = modulus * d2 * dt * (n - steps_to_close)
    assert point.sigma[2] == pytest.approx(expected, rel=0.01)
    # reverse: unload elastically to zero, then open instead of pulling
    for _ in range(400):
        point.step([0, 0, -d2, 0, 0, 0], dt)
        assert point.sigma[2] <= 1e-9 * E
    assert point.sigma[2] == pytest.approx(0.0, abs=1e-6 * E * 1e-3)
    assert point.closed < width

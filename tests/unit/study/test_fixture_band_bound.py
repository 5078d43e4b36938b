"""The fixture study's bound on the closing speed (section 4.1) reads the band's least velocity change from
the pulse the band checks against (a rectangle is checked as MIL-STD-810's trapezoid, 10% ramps), not from
the rectangle's own A T."""
import numpy as np
import pytest

from shockfem.metrics import shapes
from shockfem.programmer.dashpot_design import STRIKER_RATIO
from shockfem.study.fixture.common import DURATION, PEAK, SIZES, Context, band_of
from shockfem.study.fixture.design import _bounds
from shockfem.study.report import Report


def _trapezoid_record(scale: float):
    """The specified trapezoid at ``scale`` of its level, from first contact, sampled at 10 us."""
    ideal = shapes.specified("trapezoid", PEAK, DURATION, start=1e-5)
    t = np.arange(0.0, 2.5 * DURATION, 1e-5)
    return t, scale * ideal(t), scale * ideal.velocity_change


def test_the_least_velocity_change_is_the_checked_trapezoids(tmp_path):
    bounds = _bounds(Report(str(tmp_path), "bounds"), Context(SIZES["smoke"], str(tmp_path), lambda *a: None))
    trapezoid = shapes.specified("trapezoid", PEAK, DURATION).velocity_change       # 0.9 A T: 441.3 m/s
    assert bounds["least_velocity_change"] == pytest.approx(0.9 * trapezoid, rel=1e-12)
    assert bounds["least_closing_speed"] == pytest.approx(bounds["least_velocity_change"] * (1 + 1 / STRIKER_RATIO),
                                                          rel=1e-12)
    # the bound is the band's own: the trapezoid a little above it (its level 0.905, inside the band's
    # 20% amplitude) passes the band, a little below it (0.895) fails on the velocity change alone
    for scale, passes in ((0.905, True), (0.895, False)):
        t, a, dv = _trapezoid_record(scale)
        _, band = band_of(t, a, "rectangle")
        assert band.passed == passes, scale
        assert (dv >= bounds["least_velocity_change"]) == passes


@pytest.mark.parametrize("shape, by_hand", [("rectangle", 0.9 * 0.9 * PEAK * DURATION),       # as the trapezoid
                                            ("half-sine", 0.9 * 2 * PEAK * DURATION / np.pi)])
def test_the_pulse_specs_least_velocity_change_by_hand(shape, by_hand):
    from shockfem.programmer.dashpot_design import PulseSpec
    assert PulseSpec(shape, PEAK, DURATION).least_velocity_change() == pytest.approx(by_hand, rel=1e-12)

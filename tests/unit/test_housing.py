"""The housing's closed forms (``programmer/housing.py``) against hand values, and the closed-form limits
and the striker of the column designer (``programmer/column_design.py``) that read them."""
import math

import numpy as np
import pytest

from shockfem.programmer.housing import (HOUSING_STEELS, PRACTICAL_RATIO, bore_von_mises, critical_flaw,
                                         dynamic_factor, fixture_mass, floor_for, held_pressure, least_self_consistent,
                                         step_factor, wall_factor, wall_for, wall_ratio)

MARAGING = HOUSING_STEELS["maraging_300"]
S = 1830e6 / 2.4                         # the lesser of 1790 / 1.5 and 1830 / 2.4 [Pa]


def test_the_design_stress_is_asmes_lesser_margin():
    assert MARAGING.allowed_stress() == pytest.approx(S, rel=1e-12)


def test_lames_von_mises_at_the_bore_by_hand():
    """a = 1, b = 2, p = 200 MPa, closed ends: sigma_theta = 200 (4 + 1) / 3 = 333.3, sigma_r = -200,
    sigma_z = 200 / 3 = 66.7 MPa; von Mises sqrt(((533.3)^2 + (266.7)^2 + (266.7)^2) / 2) = 461.9 MPa."""
    st, sr, sz = 200e6 * 5 / 3, -200e6, 200e6 / 3
    by_hand = math.sqrt(((st - sr) ** 2 + (sr - sz) ** 2 + (sz - st) ** 2) / 2)
    assert by_hand == pytest.approx(461.88e6, rel=1e-4)
    assert bore_von_mises(200e6, 1.0, 2.0) == pytest.approx(by_hand, rel=1e-12)


def test_the_viii2_wall_is_s_ln_y():
    """VIII-2 4.3.3, t = (D / 2) (exp(P / (S E)) - 1), E = 1: P = S ln 2 gives t = D / 2 (b = 2a), P = S gives
    b = e a (by hand); and an independent script (the plain
    oil design, 645 MPa x 1.40 in a 29.2 mm bore 1.236 m long) gives Y = 3.27 and 256 kg of maraging steel."""
    a = 0.05
    assert wall_for(S * math.log(2.0), a).outer_radius == pytest.approx(2 * a, rel=1e-12)
    assert wall_for(S, a).ratio == pytest.approx(math.e, rel=1e-12)
    w = wall_for(645e6 * 1.40, 29.2e-3)
    assert w.ratio == pytest.approx(3.27, abs=0.005)
    assert w.mass_per_length * 1.236 == pytest.approx(256, abs=0.5)
    assert w.within_practical and w.governing.startswith("ASME VIII-2")
    # the elastic check governs nothing: the bore's von Mises is Lame's at that wall, here below yield
    assert w.bore_von_mises == pytest.approx(bore_von_mises(903e6, 29.2e-3, w.outer_radius), rel=1e-12)
    assert not w.first_yield
    # beyond the practical ratio the wall still has a finite mass, and says so
    far = wall_for(S * math.log(2 * PRACTICAL_RATIO), 0.03)
    assert not far.within_practical and math.isfinite(far.mass_per_length) and "Y_max" in far.governing


def test_the_shakedown_rule_is_the_collapse_then_twice_the_elastic_range():
    """(2 / sqrt 3) S min(1 - 1 / Y^2, ln Y): ln 1.5 below the corner (Y = 2.218, where 1 - 1/Y^2 = ln Y),
    1 - 1/16 at Y = 4 (825 MPa for maraging 300), 2 S / sqrt 3 at no wall; its inverse is the ratio."""
    k = 2 / math.sqrt(3) * S
    assert held_pressure(1.5, S, "shakedown") == pytest.approx(k * math.log(1.5), rel=1e-12)
    assert held_pressure(4.0, S, "shakedown") == pytest.approx(k * 15 / 16, rel=1e-12)
    assert held_pressure(4.0, S, "shakedown") == pytest.approx(825.4e6, rel=1e-4)
    for y in (1.5, 2.2, 2.3, 3.0, 10.0):
        assert wall_ratio(held_pressure(y, S, "shakedown"), S, "shakedown") == pytest.approx(y, rel=1e-9)
    assert math.isinf(wall_ratio(1.01 * k, S, "shakedown"))


def test_the_floor_is_viii2s_integral_flat_head():
    """t = d sqrt(C P / S), C = 0.17: at P = S, t = 2 a sqrt(0.17) = 0.8246 a."""
    assert floor_for(S, 0.04) == pytest.approx(0.04 * 2 * math.sqrt(0.17), rel=1e-12)
    assert 2 * math.sqrt(0.17) == pytest.approx(0.8246, rel=1e-4)


def test_the_critical_flaw_by_hand():
    """p = 500 MPa, Y = 2: hoop 500 x 5 / 3 = 833.3 MPa, with the pressure on the faces 1333.3 MPa:
    a_c = (80 / (1.12 x 1333.3))^2 / pi = 0.9135 mm."""
    assert critical_flaw(500e6, 2.0, MARAGING) == pytest.approx(0.9135e-3, rel=1e-3)


def test_a_step_is_a_factor_2():
    assert step_factor() == pytest.approx(2.0, rel=1e-9)


def test_the_fixture_is_weighed_whole_and_finite_beyond_the_old_elastic_bound():
    """``fixture_mass`` on a slow ramp (factor 1): the wall is ``wall_for`` at the peak, the parts sum to
    the fixture; 600 MPa (above Lame's s / sqrt 3 = 440 MPa) is a wall of Y = exp(600 / 762.5) = 2.20;
    1200 MPa needs Y = 4.82, beyond Y_max: finite, and no housing within it."""
    d = {"bore_radius": 0.03, "column": 1.0, "piston_mass": 0.2, "liquid_mass": 2.5,
         "pin": [[0.0, 1e-3], [1.0, 0.0]]}
    t = np.linspace(0.0, 0.1, 20001)
    ramp = np.clip(t / 0.05, 0, 1)                 # a rise 50 ms long: hundreds of breathing periods
    w = fixture_mass(d, t, 300e6 * ramp, 300e6 * ramp)
    assert w["dynamic_factor"] == pytest.approx(1.0, abs=1e-3)
    assert w["outer_radius"] == pytest.approx(wall_for(300e6 * w["dynamic_factor"], 0.03).outer_radius, rel=1e-12)
    assert w["fixture"] == pytest.approx(w["piston"] + w["pin"] + w["housing"] + w["liquid"], rel=1e-12)
    assert w["pin"] == pytest.approx(MARAGING.density * 0.5e-3, rel=1e-9)   # 1e-3 m^2 x 1 m / 2 of steel
    high = fixture_mass(d, t, 600e6 * ramp, 600e6 * ramp)
    assert high["wall_ratio"] == pytest.approx(math.exp(600e6 * high["dynamic_factor"] / S), rel=1e-12)
    assert high["wall_ratio"] == pytest.approx(2.20, abs=0.01) and high["housing_holds"]
    beyond = fixture_mass(d, t, 1200e6 * ramp, 1200e6 * ramp)
    assert math.isfinite(beyond["fixture"]) and not beyond["housing_holds"]
    # the pin stands in the liquid: its von Mises is the pressure, held to S
    assert high["pin_holds"] and not beyond["pin_holds"]


def test_the_closed_form_limits_read_one_wall_and_one_factor():
    """``contact_pressure_limit``: the front at the limit times the reflection and the step's factor is
    what the wall holds at Y_max (S ln 4 = 1057 MPa); ``upstream_pressure_limit`` returns the speed at which
    the quasi-steady upstream pressure is the bound.  An independent solver: 735 MPa upstream
    of n = 0.5625 in oil at 539.4 m/s, 595 MPa at 485.4 m/s."""
    from shockfem.programmer.column_design import contact_pressure_limit, upstream_pressure_limit, wall_holds
    from shockfem.programmer.dashpot_design import upstream_pressure
    from shockfem.programmer.liquids import MINERAL_OIL as oil
    assert wall_holds() == pytest.approx(S * math.log(4.0), rel=1e-12)
    speed, front, factor, holds = contact_pressure_limit(oil, reflection=2.0)
    assert front * 2.0 * factor == pytest.approx(holds, rel=1e-12) and factor == pytest.approx(2.0, rel=1e-9)
    assert upstream_pressure(0.5625, 539.4, oil.density) == pytest.approx(735e6, rel=2e-3)
    assert upstream_pressure(0.5625, 485.4, oil.density) == pytest.approx(595e6, rel=2e-3)
    v = upstream_pressure_limit(oil, S)
    assert upstream_pressure(0.5625, v, oil.density) == pytest.approx(S, rel=1e-9)


def test_the_striker_carries_its_housing_and_sets_the_closing_speed():
    """``striker_report``: the least striker is (housing + pin + liquid) x 1.2; the least closing speed is the
    band floor's velocity change times 1 + m / M (the collision law at restitution 0), the band's being
    the checked trapezoid's (10% ramps: 0.9 A T) within 10%, not the rectangle's A T."""
    from shockfem.programmer.column_design import striker_report
    from shockfem.programmer.dashpot_design import PulseSpec
    from shockfem.units import G0
    pulse = PulseSpec("rectangle", 10_000 * G0, 5e-3)
    d = {"payload_mass": 6.0, "striker_mass": 400.0, "striker_speed": 500.0}
    r = striker_report(d, pulse, {"housing_carried": 300.0, "pin": 5.0, "liquid": 10.0})
    assert r["carrying"] == pytest.approx(378.0, rel=1e-12) and r["carries"]      # (300 + 5 + 10) 1.2
    trapezoid = 0.9 * 10_000 * G0 * 5e-3                  # A (T - the two half ramps), by hand
    assert r["least_closing_speed"] == pytest.approx(0.9 * trapezoid * (1 + 6.0 / 400.0), rel=1e-9)


def test_the_carried_striker_is_a_fixed_point_with_its_housing():
    """``carried_ratio`` on the 12 lb article in oil at 40 cells: the striker it returns carries (within
    ``STRIKER_TOLERANCE``) the housing of the closed-form design at that striker, and is heavier than
    ten payloads (the housing is hundreds of kilograms at these pressures)."""
    from shockfem.programmer import column_design as cd
    from shockfem.programmer.column_dashpot import simulate_column
    from shockfem.programmer.dashpot_design import LUMPED_SAMPLES, PulseSpec, dashpot_lumped, striker_carrying
    from shockfem.programmer.liquids import MINERAL_OIL as oil
    from shockfem.units import G0, LB
    pulse = PulseSpec("rectangle", 10_000 * G0, 5e-3)
    ratio = cd.carried_ratio(pulse, 12 * LB, 0.0, oil, cells=40)
    d = cd._design(pulse, 12 * LB, 0.0, oil, cd.closed_form_bore(pulse, 12 * LB, 0.0, oil, ratio), cd.START, ratio)
    w = cd.weigh(d, simulate_column(dashpot_lumped(d), pulse.record_end(), LUMPED_SAMPLES, 40, oil.column()))
    assert ratio > 10.0
    assert d["striker_mass"] == pytest.approx(striker_carrying(w["housing_carried"], w["liquid"]),
                                              rel=2 * cd.STRIKER_TOLERANCE)


def _node_stepped_factor(t, p, period, subdivide):
    """An independent reference for ``dynamic_factor``: the history cut into ``subdivide`` pieces a sample
    interval, the oscillator stepped in closed form (cos / sin of each piece) and |x| read at the nodes
    only.  It lies below the exact largest |x| by at most |x''| h^2 / 8 <= A_max (w h)^2 / 8 at piece h."""
    tf = np.linspace(t[0], t[-1], (len(t) - 1) * subdivide + 1)
    pf = np.interp(tf, t, p)
    w, x, v, largest = 2 * math.pi / period, 0.0, 0.0, 0.0
    for k in range(len(tf) - 1):
        h = tf[k + 1] - tf[k]
        m = (pf[k + 1] - pf[k]) / h
        y, yd = x - pf[k], v - m
        c, s = math.cos(w * h), math.sin(w * h)
        x, v = y * c + yd / w * s + pf[k + 1], -y * w * s + yd * c + m
        largest = max(largest, abs(x))
    return largest / pf.max()


def _two_fronts(t, first, delay):
    """A column's wall history: the contact front to 0.4 at ``first``, its reflection to 1.0 ``delay``
    later (each over one sample), a decay and a small ringing after."""
    p = 0.4 * np.clip((t - first) / (t[1] - t[0]), 0, 1) + 0.6 * np.clip((t - first - delay) / (t[1] - t[0]), 0, 1)
    span = t[-1] - t[0]
    return p * np.exp(-np.clip(t - first - delay, 0, None) / span) * (1 + 0.03 * np.sin(37 * t / span))


@pytest.mark.parametrize("period_over_sample", [1.5, 3.0, 8.0, 16.0 * (1 - 1e-3), 16.0 * (1 + 1e-3), 40.0, 100.0])
def test_the_dynamic_factor_is_the_exact_largest_response_between_samples(period_over_sample):
    """``dynamic_factor`` on two fronts against the node-stepped reference at 400 pieces a sample: the
    reference lies below the exact maximum by at most A_max (w h / 400)^2 / 8 (A_max <= 2 peak), which is
    under 2e-5 of the peak at a period of 1.5 samples, so the factor lies within [ref, ref + 2e-5] (and
    never below the reference less round-off, 1e-12: an exact maximum is at least any sampled value).
    Sampling ratios from coarse (1.5 samples a period) to fine, and either side of 16 samples a period."""
    t = np.linspace(0.0, 1.0, 401)
    period = period_over_sample * (t[1] - t[0])
    p = _two_fronts(t, 0.05, 0.31)
    reference = _node_stepped_factor(t, p, period, 400)
    exact = dynamic_factor(t, p, period)
    bound = 2.0 * (2 * math.pi / period_over_sample / 400) ** 2 / 8
    assert reference - 1e-12 <= exact <= reference + bound


def test_the_dynamic_factor_is_continuous_across_sixteen_samples_a_period():
    """Either side of 16 samples a period, a share 1e-8 of it apart, the factor moves by at most what the
    period's change can move the response, x = w int sin(w (t - s)) p(s) ds: |dx/dw| <= (t_end + w
    t_end^2 / 2) peak, so dF <= (w t_end + (w t_end)^2 / 2) dT / T = (157 + 12,300) 2e-8 = 2.5e-4
    (w t_end = 2 pi 400 / 16); a switch between two bounds of the interval's maximum there moves it by
    tenths."""
    t = np.linspace(0.0, 1.0, 401)
    p = _two_fronts(t, 0.05, 0.31)
    sample = t[1] - t[0]
    below, above = (dynamic_factor(t, p, 16.0 * sample * (1 + e)) for e in (-1e-8, 1e-8))
    assert abs(above - below) <= 2.5e-4


def test_the_least_self_consistent_size_is_the_least_root():
    """A need 1 + x / 2 meets its size at 2 only, from below and from a lower bound already past it (the
    bound halved first); a need x + 0.3 (3 - x)(5 - x)(8 - x) / (1 + x), at most x on [3, 5] and beyond 8,
    gives the least, 3; a need that turns infinite gives the size where it did."""
    assert least_self_consistent(lambda x: 1 + x / 2, 0.5) == pytest.approx(2.0, rel=1e-9)
    assert least_self_consistent(lambda x: 1 + x / 2, 3.0) == pytest.approx(2.0, rel=1e-9)
    need = lambda x: x + 0.3 * (3 - x) * (5 - x) * (8 - x) / (1 + x)      # noqa: E731 (below x on (3, 5) and > 8)
    assert least_self_consistent(need, 1.0) == pytest.approx(3.0, rel=1e-9)
    assert least_self_consistent(lambda x: math.inf if x > 2 else 1 + x, 1.5) > 2


def test_the_wall_is_sized_for_its_worst_slice_not_the_envelope():
    """Two fronts on the column: the piston's face sees the contact front (0.4) and the reflection's
    return (to 1.0) two transits later, the floor sees them together, a step of 1.0 at one transit.
    The floor's slice responds as a step (2, its plateau many periods long), so the wall's factor is 2,
    while the envelope of the two histories (0.4 at contact, 1.0 at one transit: no slice's) reads
    1 + |0.4 + 0.6 e^(i w D)| with its delay D of one transit: 1.2 at 5.5 periods (each step over one
    sample of T / 200, whose rise lowers the sum by under 1e-4: 1 - sin(x) / x, x = pi / 200)."""
    T, transit = 1e-4, 5.5e-4                      # a transit of 5.5 ring periods
    t = np.linspace(0.0, 4e-3, 8001)
    step = lambda at: np.clip((t - at) / (t[1] - t[0]), 0, 1)          # noqa: E731
    piston = 0.4 * step(0.0) + 0.6 * step(2 * transit)
    floor = step(transit)
    assert wall_factor(t, np.vstack((piston, floor)), T) == pytest.approx(2.0, abs=1e-3)
    assert wall_factor(t, np.maximum(piston, floor), T) == pytest.approx(1.2, abs=1e-3)
    # one history alone is the oscillator's own factor
    assert wall_factor(t, floor, T) == dynamic_factor(t, floor, T)


def test_the_wall_holds_its_own_response_at_its_own_period():
    """``fixture_mass``'s wall: its outer radius is the wall ``wall_for`` gives at the peak times the
    factor at the breathing period of that radius (2 pi b / c) within SIZE_TOLERANCE, and the floor's
    thickness likewise at its own period; on a ramp of rise 3 periods of the radius 2.5 a, a factor that
    depends on the period (1 + |sin x| / x)."""
    a = 0.03
    d = {"bore_radius": a, "column": 1.0, "piston_mass": 0.2, "liquid_mass": 2.5, "pin": [[0.0, 1e-3], [1.0, 0.0]]}
    rise = 3 * 2 * math.pi * 2.5 * a / MARAGING.bar_speed()
    t = np.linspace(0.0, 20 * rise, 4001)
    p = 500e6 * np.clip(t / rise, 0, 1)
    w = fixture_mass(d, t, p, p)
    b = w["outer_radius"]
    # the factor is read at the root, the radius is the wall at it: they agree to the root's tolerance
    assert w["dynamic_factor"] == pytest.approx(dynamic_factor(t, p, 2 * math.pi * b / MARAGING.bar_speed()), rel=1e-8)
    assert b == pytest.approx(wall_for(500e6 * w["dynamic_factor"], a).outer_radius, rel=1e-8)
    assert w["floor_thickness"] == pytest.approx(floor_for(500e6 * w["floor_dynamic_factor"], a), rel=1e-8)
    x = math.pi * rise * MARAGING.bar_speed() / (2 * math.pi * b)
    assert w["dynamic_factor"] == pytest.approx(1 + abs(math.sin(x)) / x, rel=1e-9)


def test_a_pin_over_its_steels_s_scores_worse_by_its_log_ratio():
    """``design_objective`` weighs the metering pin as it weighs the housing: the same design on the same
    column run, once with its pin under S and once over it, differs by ``PENALTY`` ln(sigma / S) and by
    nothing else.  The design is a mild dashpot (2,000 g for 10 ms on 5.44 kg, 40 cells), whose peak
    pressure is far under S and whose housing holds; its pin is put over S through the quasi-steady
    upstream pressure ``fixture_mass`` takes for the pin's stress (1.25 S: 10 ln 1.25 = 2.23 more, by
    hand), which nothing else of the objective reads.  An objective blind to the pin, or reading a pin
    stress other than the verdict's, fails here."""
    from shockfem.programmer import column_design as cd
    from shockfem.programmer.column_dashpot import simulate_column
    from shockfem.programmer.dashpot_design import LUMPED_SAMPLES, PulseSpec, dashpot_design, dashpot_lumped
    from shockfem.programmer.liquids import MINERAL_OIL as oil
    from shockfem.units import G0
    pulse, article = PulseSpec("rectangle", 2000 * G0, 0.01), 5.44
    d = dashpot_design(pulse, article, 1.2 * cd.closed_form_bore(pulse, article, 0.0, oil), (1.0, 1.3, 1.0, 1.0),
                       liquid=oil)
    run = simulate_column(dashpot_lumped(d), pulse.record_end(), LUMPED_SAMPLES, 40, oil.column())
    under, over = d, {**d, "upstream_pressure": 1.25 * S}
    assert cd.weigh(under, run)["pin_holds"] and cd.weigh(under, run)["housing_holds"]
    assert not cd.weigh(over, run)["pin_holds"]
    assert cd.weigh(over, run)["pin_stress_ratio"] == pytest.approx(1.25, rel=1e-12)
    penalty = (cd.design_objective(over, run, pulse, oil) - cd.design_objective(under, run, pulse, oil))
    assert penalty == pytest.approx(cd.PENALTY * math.log(1.25), rel=1e-9)

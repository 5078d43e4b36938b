"""The liquid column (``fluid/column.py``), its dashpot (``programmer/column_dashpot.py``), the range checks
and the housing's mass: conservation and closed forms on small grids (``shockfem verify liquid_column``
runs the convergence cases)."""
import math

import numpy as np
import pytest

from shockfem.fluid.column import ColumnLiquid, LiquidColumn
from shockfem.fluid.orifice import AREA_RATIO, FIXED_CD

OIL = ColumnLiquid()


def _drive(col, t_end, v_piston, area=0.0):
    t = 0.0
    while t < t_end:
        dt = min(col.stable_step(0.0, v_piston), t_end - t)
        col.step(0.0, v_piston, area, dt)
        t += dt


def test_a_closed_column_keeps_its_mass_and_makes_joukowskys_pressure():
    """A piston at 2 m/s on 1 m of oil, 100 cells: the mass to round-off; rho c V at the piston before the
    front returns (0.5%: measured 0.07% at 40 cells, the shock of Tait's linear law is 0.08% above)."""
    col = LiquidColumn(OIL, 0.0, 1.0, 1e-3, 100)
    m0 = col.mass()
    _drive(col, 0.5 / OIL.sound_speed(), -2.0)
    assert col.mass() == pytest.approx(m0, rel=1e-13)
    assert col.piston_pressure == pytest.approx(OIL.density * OIL.sound_speed() * 2.0, rel=0.005)


def test_the_orifice_takes_out_what_the_column_loses_and_the_energy_balances():
    """A piston at 10 m/s into 1 m of oil through a fifth of its area: mass out + mass left = mass in
    (round-off); the walls' work = the column's energy change + what the jet carried + D, D >= 0 and
    below a tenth of the work (the scheme dissipates at the fronts only)."""
    col = LiquidColumn(OIL, 0.0, 1.0, 1e-3, 100, AREA_RATIO)
    m0 = col.mass()
    _drive(col, 4.0 / OIL.sound_speed(), -10.0, 2e-4)
    s = col.summary()
    assert col.mass() + s["mass out [kg]"] == pytest.approx(m0, rel=1e-12)
    work = s["work of the piston [J]"]
    assert work > 0.0
    assert 0.0 <= s["column dissipation [J]"] <= 0.1 * work


def test_a_pulled_piston_parts_the_column_at_the_vapour_pressure():
    """Pulled away at V with rho c V far above p0 - p_v: the piston sees p_v and a gap opens at
    (V - (p0 - p_v) / (rho c)) A (the characteristics), within 5% over a quarter transit."""
    p0, V, A = 0.0, 5.0, 1e-3
    col = LiquidColumn(OIL, 0.0, 1.0, A, 200, pressure0=p0)
    T = 0.25 / OIL.sound_speed()
    _drive(col, T, V)
    expected = (V - (p0 - OIL.vapour_pressure) / (OIL.density * OIL.sound_speed())) * A * T
    assert col.piston_pressure == OIL.vapour_pressure
    assert col.void() == pytest.approx(expected, rel=0.05)


def test_the_column_dashpot_follows_the_lumped_one_when_short_and_slow():
    """``verify liquid_column``'s control-volume case at 20 cells: the deceleration within 1%."""
    from shockfem.verify.column_cases import control_volume_recovered
    (c,) = control_volume_recovered(200)
    assert c["passed"], c


def test_the_range_checks_flag_the_studys_first_design():
    """The study's plain dashpot on its first law: the pin at the whole bore (a / A = 1, beyond the
    fixed law's 0.32), the piston at Mach 0.36, the oil 62% of the payload: outside the lumped range."""
    from shockfem.programmer import dashpot_design as law
    from shockfem.programmer.dashpot_validity import dashpot_limits, lumped_holds
    from shockfem.programmer.lumped_dashpot import simulate
    from shockfem.units import G0, LB
    spec = law.PulseSpec("rectangle", 10_000 * G0, 5e-3)
    d = law.dashpot_design(spec, 12 * LB, 0.032, (1.029, 1.143, 0.896, 0.867), law=FIXED_CD)
    lumped = law.dashpot_lumped(d)
    limits = {(lim.name, lim.models): lim for lim in dashpot_limits(lumped, simulate(lumped, spec.record_end(), 3000))}
    assert limits[("orifice area ratio a / A", "the orifice law")].value == pytest.approx(1.0)
    assert limits[("piston Mach number in the liquid", "lumped")].value == pytest.approx(0.356, abs=0.005)
    assert limits[("liquid mass / payload", "lumped")].value == pytest.approx(3.619 / 5.822, rel=1e-3)
    assert not lumped_holds(list(limits.values()))
    assert np.isfinite(limits[("column transit time / pulse rise", "lumped")].value)


def test_the_walls_dynamic_factor_is_biggs_for_a_step_and_a_ramp():
    """``housing.dynamic_factor`` against Biggs' closed forms (ch. 2): 2 for a step, 1 + |sin x| / x,
    x = pi t_r / T, for a ramp; the stepping is exact for piecewise-linear loads (measured 4e-15)."""
    from shockfem.programmer.housing import dynamic_factor
    T = 1e-4
    t = np.linspace(0.0, 20 * T, 4001)
    assert dynamic_factor(t, np.ones_like(t), T) == pytest.approx(2.0, rel=1e-12)
    for ratio in (0.25, 0.5, 1.5):
        x = math.pi * ratio
        assert dynamic_factor(t, np.clip(t / (ratio * T), 0, 1), T) == pytest.approx(1 + abs(math.sin(x)) / x,
                                                                                    rel=1e-12)


def test_roelands_viscosity_and_the_ice_vi_melting_pressure():
    """Roelands at no pressure is the reference; at 300 MPa (Z = 2e-8 / (5.1e-9 (ln 0.028 + 9.67)) =
    0.644): log10 mu[cP] = (log10 28 + 1.2) (1 + 300 / 196.1)^0.644 - 1.2, worked by hand to 4.07 Pa s;
    water's ice VI at 20 degC from IAPWS R14-08 eq. 3: 891 MPa less the atmosphere."""
    from shockfem.programmer.liquids import MINERAL_OIL, WATER
    assert MINERAL_OIL.viscosity_at(0.0) == MINERAL_OIL.viscosity
    z = 2e-8 / (5.1e-9 * (math.log(0.028) + 9.67))
    by_hand = 10 ** ((math.log10(28.0) + 1.2) * (1 + 300 / 196.1) ** z - 1.2) * 1e-3
    assert MINERAL_OIL.viscosity_at(300e6) == pytest.approx(by_hand, rel=1e-12)
    assert by_hand == pytest.approx(4.07, rel=0.01)
    assert WATER.viscosity_at(500e6) == WATER.viscosity
    theta = 293.15 / 273.31
    assert WATER.solid_pressure() == pytest.approx(632.4e6 * (1 - 1.07476 * (1 - theta ** 4.6)) - 1e5, rel=1e-12)
    assert math.isinf(MINERAL_OIL.solid_pressure())


def test_the_oil_stiffens_at_haywards_tangent_slope_and_the_liquids_heat_as_they_are_compressed():
    """ISO VG 32's Tait slope 2 x 5.6 - 1 = 10.2 (Hayward's secant slope as a tangent one); the isentropic
    T0 exp(alpha p / (rho c_p)) by hand: water at 1 GPa, 293.15 exp(2.07e-4 1e9 / (998 x 4180)) = 308.0 K;
    Roelands' temperature index brings VG 32 at no pressure to its 4.5 mPa s at 100 degC (the point it is
    fitted to) and thins it at 80 degC between 40 and 100's values."""
    from shockfem.programmer.liquids import MINERAL_OIL, WATER
    assert MINERAL_OIL.tait_exponent == pytest.approx(10.2, rel=1e-12)
    assert WATER.compressed_temperature(1e9) == pytest.approx(293.15 * math.exp(2.07e-4 * 1e9 / (998 * 4180)),
                                                              rel=1e-12)
    assert WATER.compressed_temperature(1e9) == pytest.approx(308.0, abs=0.1)
    assert MINERAL_OIL.compressed_temperature(-1e5) == MINERAL_OIL.temperature
    assert MINERAL_OIL.viscosity_at(0.0, 373.15) == pytest.approx(4.5e-3, rel=1e-9)
    assert 4.5e-3 < MINERAL_OIL.viscosity_at(0.0, 353.15) < 0.028
    assert WATER.viscosity_at(500e6, 330.0) == WATER.viscosity


def test_ice_vi_melts_higher_at_the_compressed_waters_temperature():
    """IAPWS R14-08 eq. 3 at 40 degC: 632.4 (1 + 1.07476 ((313.15 / 273.31)^4.6 - 1)) = 1223.8 MPa (an
    independent 1224 MPa); the margin of a pressure is taken at the temperature compression brings it to,
    above the isothermal one; an oil has none."""
    from shockfem.programmer.liquids import MINERAL_OIL, WATER
    assert WATER.solid_pressure(313.15) == pytest.approx(1223.8e6, rel=2e-4)
    p = 1.1e9
    assert WATER.freezing_margin(p) == pytest.approx(p / WATER.solid_pressure(WATER.compressed_temperature(p)),
                                                     rel=1e-12)
    assert WATER.freezing_margin(p) < p / WATER.solid_pressure()
    assert MINERAL_OIL.freezing_margin(p) == 0.0


def _made_up_run(pressure):
    """A bore of 50 mm with a fixed opening of a quarter of it (a hole of 25 mm, no pin in it) under a
    constant deceleration at a constant ``pressure``."""
    from types import SimpleNamespace
    from shockfem.programmer.lumped_dashpot import LumpedDashpot
    A = math.pi * 0.025 ** 2
    d = LumpedDashpot(10.0, 1.0, 10.0, A, 1.0, ((0.0, 0.25 * A), (10.0, 0.25 * A)), 998.0, 2.2e9, 0.7,
                      law=AREA_RATIO, orifice_land=0.015)
    t = np.linspace(0.0, 1.0, 1001)
    run = SimpleNamespace(t=t, striker_speed=10.0 * (1 - t), payload_speed=0 * t, pressure=np.full_like(t, pressure),
                          stroke=0 * t, acceleration=np.full_like(t, 10.0))
    return d, run


def test_the_orifice_state_of_a_run_by_hand():
    """Water at 1 MPa through a 25 mm hole in a 15 mm piston: l / d_h = 0.6; K = 1.1 / 1.0, so the land,
    whose thick-edged coefficient is 1.12 times the thin one's, chokes at sqrt(1.1) = 1.0488 (Nurick); Re
    = 0.025 sqrt(2e6 / 998) 998 / 1e-3 = 1.117e6, Lichtarowicz's shift 1 / (1 + Cc 20 (1 + 2.25 x 0.6) / Re);
    the coefficient error is the force's |1 / C^2 - 1| at every sample of the constant deceleration."""
    from shockfem.fluid import orifice
    from shockfem.programmer.dashpot_validity import choked_share, coefficient_error, orifice_states
    from shockfem.programmer.liquids import WATER
    d, run = _made_up_run(1e6)
    s = orifice_states(d, run, WATER)
    assert s["land"][0] == pytest.approx(0.6, rel=1e-9)
    assert s["cavitation"][0] == pytest.approx(1.1, rel=1e-12)
    assert s["reynolds"][0] == pytest.approx(0.025 * math.sqrt(2e6 / 998) * 998 / 1e-3, rel=1e-9)
    assert orifice.thick_discharge_ratio(0.6) > math.sqrt(1.1)
    viscous = 1 / (1 + orifice.contraction(0.25) * 20 * (1 + 2.25 * 0.6) / s["reynolds"][0])
    assert s["coefficient"][0] == pytest.approx(math.sqrt(1.1) * viscous, rel=1e-12)
    assert choked_share(s, run.acceleration) == 1.0
    assert coefficient_error(s, run.acceleration) == pytest.approx(1 - 1 / (1.1 * viscous ** 2), rel=1e-9)


def test_flagged_checks_report_but_do_not_veto():
    """The made-up run's checks: the land (0.6 > 0.015), the cavitation and the bore (50 mm, ISO's least:
    holds at equality) flag or hold; the coefficient's error (9.1%: 1 - 1 / 1.1) is above the 3% margin
    and vetoes; a flag outside alone leaves the column a design model."""
    from shockfem.programmer.dashpot_validity import COEFFICIENT_ERROR, Limit, column_holds, dashpot_limits
    from shockfem.programmer.liquids import WATER
    d, run = _made_up_run(1e6)
    limits = {lim.name.split(" (")[0]: lim for lim in dashpot_limits(d, run, WATER)}
    land = limits["orifice land / hydraulic diameter l / d_h"]
    assert not land.holds and not land.vetoes and land.verdict == "flagged"
    assert limits["bore diameter [mm] against ISO 5167-2's least"].holds
    coefficient = limits["velocity-change error of the orifice's coefficient"]
    assert coefficient.value > COEFFICIENT_ERROR and coefficient.vetoes and not column_holds([coefficient])
    assert column_holds([land, Limit("b", 49.0, 50.0, "column", lower=True, vetoes=False)])
    assert not column_holds([Limit("b", 49.0, 50.0, "column", lower=True)])


def test_a_wider_largest_opening_lowers_the_least_force_and_raises_the_speed_the_wall_holds():
    """n_max = 0.8: the least force per area is the Borda-Carnot rho (u_j - V)^2 / 2 at u_j = V / (Cc n),
    Cc(0.8) = 1 / (1 + 0.707 sqrt(0.2)) = 0.7598, by hand; the speed at which the front fits the wall is
    higher than at the default 0.5625."""
    from shockfem.fluid.orifice import OrificeLaw
    from shockfem.programmer.column_design import contact_pressure_limit, least_force_per_area
    from shockfem.programmer.liquids import MINERAL_OIL
    V, law = 400.0, OrificeLaw(largest_ratio=0.8)
    u_jet = V / (0.75978 * 0.8)
    assert least_force_per_area(V, 870.0, law) == pytest.approx(870.0 * (u_jet - V) ** 2 / 2, rel=1e-4)
    assert contact_pressure_limit(MINERAL_OIL, law=law)[0] > contact_pressure_limit(MINERAL_OIL)[0]


def test_the_upstream_pressure_limit_follows_the_designs_largest_opening():
    """``upstream_pressure_limit`` at n_max = 0.8: the speed at which the pressure upstream of n = 0.8 (not
    the checked 0.5625) is the bound.  The pressure the flow needs falls as the opening widens (the
    jet's speed is V / (Cc n)), so the speed the wall holds is higher; a bound read at 0.5625 whatever
    the design's n_max (the pressure there 3.4 times that at 0.8, by ``upstream_pressure``: 549 against
    1013 m/s in oil at S = 762.5 MPa) fails both."""
    from shockfem.fluid.orifice import OrificeLaw
    from shockfem.programmer.column_design import upstream_pressure_limit
    from shockfem.programmer.dashpot_design import upstream_pressure
    from shockfem.programmer.liquids import MINERAL_OIL
    held, law = 762.5e6, OrificeLaw(largest_ratio=0.8)
    v = upstream_pressure_limit(MINERAL_OIL, held, law)
    assert upstream_pressure(0.8, v, MINERAL_OIL.density, law) == pytest.approx(held, rel=1e-9)
    assert v > 1.5 * upstream_pressure_limit(MINERAL_OIL, held)


def test_the_contact_front_is_the_hugoniot_shock_with_the_orifice_passing_its_flow():
    """``column_design.contact_shock`` closed orifice: no flow, so the liquid moves with the piston and
    the pressure is the Hugoniot's rho0 s V, s = V / 2 + sqrt(V^2 / 4 + c^2) for Tait's n = 1; with an
    opening the front is lower and the force on the piston lower still (the jet's reaction)."""
    import dataclasses
    from shockfem.programmer.column_design import contact_shock
    from shockfem.programmer.liquids import MINERAL_OIL
    oil = dataclasses.replace(MINERAL_OIL, tait_exponent=1.0)
    V, A = 100.0, 1e-3
    c = oil.sound_speed()
    p_closed, f_closed = contact_shock(V, 1e-12 * A, A, oil)
    assert p_closed == pytest.approx(oil.density * (V / 2 + math.sqrt(V * V / 4 + c * c)) * V, rel=1e-6)
    p_open, f_open = contact_shock(V, 0.5 * A, A, oil)
    assert p_open < p_closed and f_open < p_open * A


def test_the_compiled_interpolation_is_numpys():
    """``column._interpolate`` (the section and the pin's table at every face) against np.interp, the ends
    held, to round-off."""
    from shockfem.fluid.column import _interpolate
    rng = np.random.default_rng(3)
    xs = np.cumsum(rng.uniform(0.01, 0.2, 40))
    ys = rng.uniform(1e-4, 1e-2, 40)
    for x in np.concatenate([rng.uniform(xs[0] - 0.5, xs[-1] + 0.5, 200), xs]):
        assert _interpolate(x, xs, ys) == pytest.approx(float(np.interp(x, xs, ys)), rel=1e-12)
    assert _interpolate(0.3, np.array([0.0, 1.0]), np.array([2.0, 2.0])) == 2.0


def test_the_linear_laws_shortcut_is_taits_at_n_1():
    """pressure, density, sound speed and the vapour density of the linear law without powers equal Tait's
    general forms at n = 1 (n slightly off 1 takes the general path): to 1e-6 of the general at n = 1 + 1e-9."""
    from shockfem.fluid.column import density, pressure, sound_speed, vapour_density
    linear = ColumnLiquid().params()
    general = ColumnLiquid(tait_exponent=1.0 + 1e-9).params()
    for rho in (800.0, 870.0, 900.0):
        assert pressure(rho, linear) == pytest.approx(pressure(rho, general), rel=1e-6, abs=1e-3)
        assert sound_speed(rho, linear) == pytest.approx(sound_speed(rho, general), rel=1e-6)
    for p in (-5e4, 0.0, 3e8):
        assert density(p, linear) == pytest.approx(density(p, general), rel=1e-9)
    assert vapour_density(linear) == pytest.approx(vapour_density(general), rel=1e-9)


@pytest.mark.parametrize("n, mach", [(1.0, 0.1), (1.0, 0.5), (7.0, 0.1), (7.0, 0.5)])
def test_a_fast_piston_makes_taits_hugoniot_pressure(n, mach):
    """A piston driven at Mach 0.1 and 0.5 into the closed column (``column.MACH_LIMIT``'s range), Tait's
    n = 1 and 7, 200 cells: its face's pressure against Tait's Rankine-Hugoniot shock p = rho0 s V,
    rho0 s = rho1 (s - V) (0.5%: measured at most 0.04% at 400 cells; Joukowsky's acoustic rho c V is 5% to
    49% under it, which a column taking the acoustic wall pressure alone would give)."""
    from scipy.optimize import brentq
    oil = ColumnLiquid(tait_exponent=n)
    rho0, K, c = oil.density, oil.bulk_modulus, oil.sound_speed()
    V = mach * c
    col = LiquidColumn(oil, 0.0, 1.0, 1e-3, 200)
    t, T, pressures = 0.0, 1.0 / c, []
    while t < 0.6 * T:
        dt = col.stable_step(0.0, -V)
        col.step(0.0, -V, 0.0, dt)
        t += dt
        if t > 0.3 * T:
            pressures.append(col.piston_pressure)
    rho1 = brentq(lambda r: K / n * ((r / rho0) ** n - 1) - rho0 * V * r * V / (r - rho0), rho0 * (1 + 1e-9), 5 * rho0)
    assert np.mean(pressures) == pytest.approx(K / n * ((rho1 / rho0) ** n - 1), rel=0.005)


@pytest.mark.parametrize("orifice", [0.0, 5e-5])
def test_the_column_dashpots_energy_balances_and_a_liquid_spring_rebounds(orifice):
    """A 10 kg striker at 20 m/s on a 1 kg payload through 0.1 m of oil in a 10 cm^2 bore, 100 cells, 3 ms.
    The run's balance: the kinetic energy in = the bodies' + the column's stored + the jet's + D, to 0.5%
    of the relative kinetic energy 1/2 mu V^2 (181.8 J; the residual the coupling's first-order error:
    measured -0.96 / -0.49 / -0.20 J at 50 / 100 / 200 cells with the piston closed, -0.22 J through the
    orifice), D >= 0.  Closed (no orifice), the liquid is a spring: the bodies part at nearly the
    elastic collision's speed, restitution 0.97 (1 for a massless spring; the liquid's ringing keeps
    the rest), the spring's energy at the common speed given back as the rebound's, and the rebound check
    vetoes it (``test_a_rebound_beyond_the_margin_vetoes_the_design``)."""
    from shockfem.programmer.column_dashpot import simulate_column
    from shockfem.programmer.dashpot_validity import REBOUND, dashpot_limits
    from shockfem.programmer.lumped_dashpot import LumpedDashpot
    V, M, m = 20.0, 10.0, 1.0
    d = LumpedDashpot(M, m, V, 1e-3, 0.1, ((0.0, orifice), (1.0, orifice)), OIL.density, OIL.bulk_modulus, 0.6,
                      law=FIXED_CD)
    run = simulate_column(d, 3e-3, 600, 100)
    s = run.summary
    relative = 0.5 * M * m / (M + m) * V ** 2
    parts = ("housing's kinetic energy [J]", "payload's kinetic energy [J]", "column's stored energy [J]",
             "jet's energy out [J]", "column dissipation [J]")
    assert s["kinetic energy in [J]"] - sum(s[k] for k in parts) == pytest.approx(s["energy balance residual [J]"])
    assert abs(s["energy balance residual [J]"]) <= 0.005 * relative
    assert s["column dissipation [J]"] >= 0.0
    if orifice:
        assert s["jet's energy out [J]"] > 0.5 * relative
        return
    restitution = (run.payload_speed[-1] - run.striker_speed[-1]) / V
    assert 0.95 <= restitution <= 1.0
    # the spring holds the relative kinetic energy at the common speed (measured 178.7 of 181.8 J) and
    # gives the rebound most of it (171.8 J)
    assert 0.95 * relative <= s["compression energy at the common speed [J]"] <= relative
    assert 0.9 * s["compression energy at the common speed [J]"] <= s["rebound's kinetic energy [J]"]
    (rebound,) = [lim for lim in dashpot_limits(d, run) if lim.name.startswith("rebound")]
    assert rebound.value > REBOUND and not rebound.holds and rebound.vetoes


def test_a_push_on_the_striker_carries_its_sabot_and_its_work_balances():
    """``column_dashpot.StrikerPush`` on the same dashpot, through the orifice: a 4 kg sabot carried with no
    force is a 14 kg striker (the same arithmetic, to round-off); with 20 to 0 kN over 2 ms and the sabot
    released at 1.5 ms, the balance takes the push's work in and the sabot's kinetic energy out (dropping
    either leaves 12% or 25% of the energy in: the 0.5% catches both), and the striker ends faster than
    the unpushed run's, by less than the impulse over the striker alone (the dashpot takes some of it)."""
    from dataclasses import replace
    from shockfem.programmer.column_dashpot import StrikerPush, simulate_column
    from shockfem.programmer.lumped_dashpot import LumpedDashpot
    V, M, m, sabot = 20.0, 10.0, 1.0, 4.0
    d = LumpedDashpot(M, m, V, 1e-3, 0.1, ((0.0, 5e-5), (1.0, 5e-5)), OIL.density, OIL.bulk_modulus, 0.6,
                      law=FIXED_CD)
    carried = simulate_column(d, 3e-3, 600, 100, push=StrikerPush(np.array([0.0, 1.0]), np.zeros(2), sabot, 1.0))
    heavier = simulate_column(replace(d, striker_mass=M + sabot), 3e-3, 600, 100)
    assert np.array_equal(carried.acceleration, heavier.acceleration)
    force = StrikerPush(np.array([0.0, 1e-3, 2e-3]), np.array([2e4, 1e4, 0.0]), sabot, 1.5e-3)
    pushed = simulate_column(d, 3e-3, 600, 100, push=force)
    s = pushed.summary
    energy = s["kinetic energy in [J]"] + s["push's work on the striker [J]"]
    assert s["kinetic energy in [J]"] == pytest.approx(0.5 * (M + sabot) * V ** 2 + 0.0, rel=1e-9)
    assert abs(s["energy balance residual [J]"]) <= 0.005 * energy
    assert s["carried mass's kinetic energy at its release [J]"] == pytest.approx(
        0.5 * sabot * np.interp(1.5e-3, pushed.t, pushed.striker_speed) ** 2, rel=0.01)
    free = simulate_column(d, 3e-3, 600, 100)
    gained = pushed.striker_speed[-1] - free.striker_speed[-1]
    assert 0.0 < gained < np.trapz(force.force, force.time) / M
    assert "push's work on the striker [J]" not in free.summary


def test_a_rebound_beyond_the_margin_vetoes_the_design():
    """The closed column of ``test_the_column_dashpots_energy_balances_and_a_liquid_spring_rebounds`` (a
    10 kg striker at 20 m/s on 1 kg, restitution 0.95-1): by momentum the article leaves at
    (1 + e) M V / (M + m) and the striker e V slower, a rebound of e (M + m) / ((1 + e) M), 0.535-0.550
    (measured 0.543) against the 3% margin.  Every other check that bounds the column holds on it, so
    the rebound alone takes the column out of its range (the verdict "outside the laws' ranges"), and
    the search's objective reads it as it reads every veto, ``PENALTY`` ln(rebound / REBOUND) more than
    the same run without it (ln(0.54 / 0.03) = 2.9, by hand).  A rebound that only flags fails here.
    Through an orifice of a tenth of the bore the jet takes the energy and the striker still closes on
    the article at the record's end (measured -0.17): the check holds (a twentieth still rebounds, 0.078)."""
    from shockfem.programmer.column_dashpot import simulate_column
    from shockfem.programmer.column_design import PENALTY, _objective_of
    from shockfem.programmer.dashpot_design import PulseSpec
    from shockfem.programmer.dashpot_validity import REBOUND, column_holds, dashpot_limits, lumped_holds
    from shockfem.programmer.lumped_dashpot import LumpedDashpot
    from shockfem.units import G0
    V, M, m = 20.0, 10.0, 1.0

    def limits_of(orifice):
        d = LumpedDashpot(M, m, V, 1e-3, 0.1, ((0.0, orifice), (1.0, orifice)), OIL.density, OIL.bulk_modulus,
                          0.6, law=FIXED_CD)
        run = simulate_column(d, 3e-3, 600, 100)
        return run, dashpot_limits(d, run)
    run, limits = limits_of(0.0)
    (rebound,) = [lim for lim in limits if lim.name.startswith("rebound")]
    others = [lim for lim in limits if lim is not rebound]
    e = (run.payload_speed[-1] - run.striker_speed[-1]) / V
    # the bodies' momentum is the striker's less the ringing liquid's (87 g of oil: measured 0.21% off)
    assert rebound.value == pytest.approx(e * (M + m) / ((1 + e) * M), rel=0.005)
    assert 0.53 <= rebound.value <= 0.55 and rebound.vetoes and not rebound.holds
    assert column_holds(others) and not column_holds(limits) and not lumped_holds(limits)
    pulse = PulseSpec("rectangle", 2000 * G0, 0.002)
    _, band = pulse.band(run.t, run.acceleration)
    penalty = _objective_of(pulse, band, limits) - _objective_of(pulse, band, others)
    assert penalty == pytest.approx(PENALTY * math.log(rebound.value / REBOUND), rel=1e-12)
    _, through = limits_of(1e-4)
    (held,) = [lim for lim in through if lim.name.startswith("rebound")]
    assert held.value < 0.0 and held.holds

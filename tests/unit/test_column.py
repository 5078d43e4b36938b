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


def test_lame_wall_holds_the_allowed_stress_at_the_bore():
    from shockfem.programmer.housing import bore_outer_radius, bore_von_mises
    p, a, s = 200e6, 0.032, 690e6
    b = bore_outer_radius(p, a, s)
    assert bore_von_mises(p, a, b) == pytest.approx(s, rel=1e-12)
    # no wall holds p >= s / sqrt(3)
    assert math.isinf(bore_outer_radius(s / math.sqrt(3.0), a, s))


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

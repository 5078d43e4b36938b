"""Verification of the orifice law (``fluid/orifice.py``) and the liquid column (``fluid/column.py``).

* ``orifice_law``: the law's flow written in ISO 5167's form, C = Cc sqrt((1 - n^2) / (1 - (Cc n)^2)),
  against ISO 5167-2:2003's Reader-Harris/Gallagher equation for a thin orifice plate with corner
  tappings at beta = 0.3, 0.5, 0.7 (Re_D -> infinity, D >= 71.12 mm: C = 0.5961 + 0.0261 beta^2 -
  0.216 beta^8), within 3% (the standard's own uncertainty is 0.5-1%; the 3% is the law's range).
* ``orifice_reynolds``: the same against the Reader-Harris/Gallagher equation with its Reynolds terms,
  at the least Re_D ISO 5167-2 holds it to (5000, or 16000 beta^2 above beta = 0.56) and at 1e6:
  within 6% (the law, a turbulent orifice's, has no Reynolds number; the standard's coefficient rises
  2-5% as the flow slows to the range's end).
* ``liquid_column``, an oil column (870 kg/m^3, 1.5 GPa, c = 1313 m/s) 1 m long:
  - Joukowsky: a piston started at V = 2 m/s on the column closed at its floor: rho c V at the piston,
    the front at the floor after L / c, 2 rho c V there after the reflection (Wylie & Streeter, Fluid
    Transients in Systems, ch. 1); the plateau means within 0.5% (Tait's linear law's shock is
    rho0 s V, s = V / 2 + sqrt(V^2 / 4 + c^2): 0.08% above rho c V at 2 m/s).
  - A fixed orifice (a = A / 5, Idelchik's law) in a piston driven into the column (a half-cosine ramp
    to 10 m/s over L / (2c)): the piston's pressure against an independent method-of-characteristics
    solve (acoustic, on its own fixed grid, its orifice boundary solved by scipy's brentq), over
    10 L / c; the RMS difference over the largest pressure, at two grids, within 2%.  It does not fall
    with the grid (0.72% at 400 and 800 cells): what is left is the characteristics' acoustics on a
    fixed boundary against the column's moving piston (7.6 mm of stroke, 0.8% of the column) and its
    density's rise with the pressure.
  - Column separation and collapse, the textbook reservoir-pipe-valve case (Wylie & Streeter ch. 8;
    Bergant, Simpson & Tijsseling, J. Fluids Struct. 22 (2006), fig. 2's sequence), frictionless: the
    column flows at V0 from a reservoir at p0 into a valve that shuts at t = 0.  With
    D = (p0 - p_v) / (rho c) and D < V0 < 2 D, the characteristics give exactly: p0 + rho c V0 at the
    valve until 2 L / c; then a cavity at the valve, growing at (V0 - D) A to its largest,
    2 (L / c) (V0 - D) A, at 4 L / c; closing at (3 D - V0) A, at t_c = 4 L / c + 2 (L / c) (V0 - D) /
    (3 D - V0); its collapse raises the valve's pressure to p0 + rho c (2 D - V0).
  - The control volume recovered: a column 20 mm long under a piston at 5 m/s with a fixed orifice
    (``dashpot.lumped_fixed_orifice``'s case) against the lumped dashpot with the same law: its
    transit time is 1/200 of the pulse's time constant, its oil 0.2% of the piston.
  - The column dashpot's energy balance (``column_dashpot.energy_balance``), exact by conservation: a
    10 kg striker at 20 m/s on a 1 kg payload through 0.1 m of oil in a 10 cm^2 bore, the piston closed
    (a liquid spring: the bodies part) and through a fixed orifice of a twentieth of the bore (the jet
    takes the energy): the kinetic energy in less the bodies', the column's stored, the jet's and D, over
    the relative kinetic energy 1/2 mu V^2, within 0.5% (the coupling's first-order error: 0.27% and
    0.12% at 100 cells, halving with the grid).
  - A push on the striker (``column_dashpot.StrikerPush``, a gun's gas on a directly fired striker's base):
    a 4 kg sabot carried with no force through the run is a 14 kg striker, the same run to 1e-12 (exact:
    the same arithmetic); with 20 to 0 kN over 2 ms and the sabot released at 1.5 ms, the energy balance
    with the push's work in and the sabot's kinetic energy out, over the energy in, within 0.5%.
"""
from __future__ import annotations

import math
import time

import numpy as np
from scipy.optimize import brentq

from ..fluid import orifice
from ..fluid.column import ColumnLiquid, LiquidColumn
from ..fluid.orifice import AREA_RATIO, FIXED_CD
from .checks import check

OIL = ColumnLiquid()
CELLS = {"coarse": 200, "default": 400, "fine": 800}
LENGTH, AREA = 1.0, 1e-3


def orifice_law(size, workdir):
    """Idelchik's law in ISO 5167's form against the Reader-Harris/Gallagher coefficient."""
    t0 = time.perf_counter()
    rows = []
    for beta in (0.3, 0.5, 0.7):
        rhg = orifice.reader_harris_gallagher(beta, math.inf)
        rows.append((beta, rhg, orifice.iso_discharge_coefficient(beta ** 2)))
    wall = time.perf_counter() - t0
    # the law's range: 3% of ISO's coefficient up to beta = 0.75 (module docstring)
    return [check(f"orifice.iso5167_beta_{beta:g} [-]", rhg, law, 0.03, wall, 0) for beta, rhg, law in rows]


# the law against ISO's coefficient at the least Reynolds number the standard holds it to: measured
# 2.3%, 3.1%, 4.8% below it at beta 0.3, 0.5, 0.7 (the coefficient rises as the flow slows; the law,
# a turbulent orifice's, does not); 6% bounds the law's error over its whole Reynolds range
REYNOLDS_TOLERANCE = 0.06


def orifice_reynolds(size, workdir):
    """The law over its Reynolds range: against ISO 5167-2's Reader-Harris/Gallagher coefficient at the
    least Re_D the standard holds it to (``orifice.least_reynolds``) and at Re_D = 1e6, at three area
    ratios; the law has no Reynolds number in it, so its error is largest at the range's lower end."""
    t0 = time.perf_counter()
    rows = []
    for beta in (0.3, 0.5, 0.7):
        law = orifice.iso_discharge_coefficient(beta ** 2)
        for reynolds in (orifice.least_reynolds(beta ** 2), 1e6):
            rows.append((beta, reynolds, orifice.reader_harris_gallagher(beta, reynolds), law))
    wall = time.perf_counter() - t0
    return [check(f"orifice.iso5167_beta_{beta:g}_re_{reynolds:.3g} [-]", rhg, law, REYNOLDS_TOLERANCE, wall, 0)
            for beta, reynolds, rhg, law in rows]


def _drive(column, t_end, v_floor, v_piston, area, probe):
    """Step ``column`` to ``t_end`` with wall velocities and orifice area given as functions of time,
    calling ``probe(t)`` after each step."""
    t = 0.0
    while t < t_end:
        dt = min(column.stable_step(v_floor(t), v_piston(t)), t_end - t)
        column.step(v_floor(t), v_piston(t), area(t), dt)
        t += dt
        probe(t)


def joukowsky(cells):
    """A piston started at V on a closed column: rho c V, the front at L / c, 2 rho c V at the floor."""
    V, c, rho = 2.0, OIL.sound_speed(), OIL.density
    col = LiquidColumn(OIL, 0.0, LENGTH, AREA, cells)
    T = LENGTH / c
    rows = []
    t0 = time.perf_counter()
    _drive(col, 1.9 * T, lambda t: 0.0, lambda t: -V, lambda t: 0.0,
           lambda t: rows.append((t, col.piston_pressure, col.floor_pressure)))
    wall = time.perf_counter() - t0
    t, p_piston, p_floor = np.array(rows).T
    piston = p_piston[(t > 0.2 * T) & (t < 0.8 * T)].mean()
    floor = p_floor[(t > 1.2 * T) & (t < 1.8 * T)].mean()
    arrival = t[np.argmax(p_floor > rho * c * V)]
    return [check("column.joukowsky.piston [Pa]", rho * c * V, piston, 0.005, wall, cells),
            check("column.joukowsky.floor_after_reflection [Pa]", 2 * rho * c * V, floor, 0.005, wall, cells),
            # the front's middle reaches the floor at L / c (measured 0.12% at 400 cells); its width is a few cells
            check("column.joukowsky.arrival [s]", T, arrival, 0.02, wall, cells)]


def _ramp(V, rise):
    return lambda t: -V * (0.5 - 0.5 * math.cos(math.pi * min(t / rise, 1.0)))


def moc_orifice(nodes, a, V, rise, t_end, law):
    """An independent method-of-characteristics solve of the column (acoustic, rigid walls, Wylie &
    Streeter ch. 3): ``nodes`` reaches of L / nodes, dt = dx / c; the floor closed; at the piston (moving
    at the ramp) the C+ characteristic p + rho c u = C+ and the orifice's outflow
    rho A (u - w) = mdot(p), solved for p by brentq.  Returns (t, the piston's pressure)."""
    rho, c = OIL.density, OIL.sound_speed()
    z = rho * c
    code = law.code()
    p = np.zeros(nodes + 1)
    u = np.zeros(nodes + 1)
    dt = LENGTH / nodes / c
    v_piston = _ramp(V, rise)
    ts, ps = [0.0], [0.0]
    for k in range(1, int(round(t_end / dt)) + 1):
        t = k * dt
        pn, un = p.copy(), u.copy()
        pn[1:-1] = 0.5 * (p[:-2] + p[2:]) + 0.5 * z * (u[:-2] - u[2:])
        un[1:-1] = 0.5 * (u[:-2] + u[2:]) + 0.5 * (p[:-2] - p[2:]) / z
        pn[0], un[0] = p[1] - z * u[1], 0.0
        w = v_piston(t)
        c_plus = p[-2] + z * u[-2]

        def mismatch(pp):
            return (c_plus - pp) / z - w - orifice.mass_flow(pp, rho, c, a, AREA, code) / (rho * AREA)
        if c_plus - z * w <= 0.0:
            pn[-1] = c_plus - z * w
        else:
            pn[-1] = brentq(mismatch, 0.0, c_plus - z * w, xtol=1e-6)
        un[-1] = (c_plus - pn[-1]) / z
        p, u = pn, un
        ts.append(t)
        ps.append(p[-1])
    return np.array(ts), np.array(ps)


def fixed_orifice_vs_moc(cells):
    """The column's piston pressure against the method of characteristics: RMS difference / peak."""
    V, c = 10.0, OIL.sound_speed()
    T = LENGTH / c
    a, rise, t_end = AREA / 5, 0.5 * T, 10 * T
    t_moc, p_moc = moc_orifice(2000, a, V, rise, t_end, AREA_RATIO)
    errors, wall = [], 0.0
    for n in (cells, 2 * cells):
        col = LiquidColumn(OIL, 0.0, LENGTH, AREA, n, AREA_RATIO)
        rows = []
        t0 = time.perf_counter()
        _drive(col, t_end, lambda t: 0.0, _ramp(V, rise), lambda t: a, lambda t: rows.append((t, col.piston_pressure)))
        wall = time.perf_counter() - t0
        t, p = np.array(rows).T
        errors.append(float(np.sqrt(np.mean((np.interp(t_moc, t, p) - p_moc) ** 2)) / p_moc.max()))
    # 2%: the acoustic, fixed-boundary characteristics against the nonlinear moving column (docstring)
    return [check(f"column.fixed_orifice_vs_moc.rms_over_peak_{n}_cells [-, abs]", 0.0, e, 0.02, wall, n,
                  absolute=True) for n, e in zip((cells, 2 * cells), errors)]


def separation(cells):
    """Column separation at a shut valve and its collapse, against the characteristics' exact sequence."""
    rho, c = OIL.density, OIL.sound_speed()
    p0 = 1.0e6
    D = (p0 - OIL.vapour_pressure) / (rho * c)
    V0 = 1.5 * D
    T = LENGTH / c
    col = LiquidColumn(OIL, 0.0, LENGTH, AREA, cells, pressure0=p0, velocity0=V0, reservoir=p0)
    rows = []
    t0 = time.perf_counter()
    _drive(col, 5.5 * T, lambda t: 0.0, lambda t: 0.0, lambda t: 0.0,
           lambda t: rows.append((t, col.piston_pressure, col.void())))
    wall = time.perf_counter() - t0
    t, p, void = np.array(rows).T
    largest = 2 * T * (V0 - D) * AREA
    t_collapse = 4 * T + 2 * T * (V0 - D) / (3 * D - V0)
    open_ = np.flatnonzero(void > 0.02 * largest)
    closed = t[open_[-1]] if len(open_) else float("nan")
    after = (t > t_collapse + 0.1 * T) & (t < min(t_collapse + 0.9 * T, 6 * T))
    return [check("column.separation.joukowsky [Pa]", p0 + rho * c * V0, p[(t > 0.5 * T) & (t < 1.5 * T)].mean(),
                  0.005, wall, cells),
            # the scheme smears the waves that start and stop the cavity's growth: 7.2% short at 160 cells,
            # 4.2% at 400 (first order at the cavity's edges); a wrong growth rate is off by tens of percent
            check("column.separation.largest_cavity [m^3]", largest, void.max(), 0.06, wall, cells),
            check("column.separation.largest_at [s]", 4 * T, t[np.argmax(void)], 0.03, wall, cells),
            check("column.separation.collapse_at [s]", t_collapse, closed, 0.03, wall, cells),
            check("column.separation.collapse_pressure [Pa]", p0 + rho * c * (2 * D - V0), p[after].mean(), 0.02,
                  wall, cells)]


def control_volume_recovered(cells):
    """A short slow column against the lumped dashpot (a control volume), the same law and bodies."""
    from ..programmer.column_dashpot import simulate_column
    from ..programmer.lumped_dashpot import LumpedDashpot, simulate
    R, rho_steel, column = 0.02, 7850.0, 0.02
    A = math.pi * R ** 2
    M = rho_steel * A * 0.02
    V0, cd = 5.0, FIXED_CD.discharge
    a = A / 5
    k = OIL.density * A ** 3 / (2 * cd * cd * a ** 2)
    a0 = k * V0 ** 2 / M
    T = 3 * V0 / a0
    d = LumpedDashpot(1e6 * M, M, V0, A, column, ((0.0, a), (1.0, a)), OIL.density, OIL.bulk_modulus, cd,
                      initial_pressure=k * V0 ** 2 / A, law=FIXED_CD)
    t0 = time.perf_counter()
    col = simulate_column(d, T, 300, cells=cells // 10)
    wall = time.perf_counter() - t0
    lumped = simulate(d, T, 300)
    diff = np.abs(col.acceleration - lumped.acceleration).max() / lumped.acceleration.max()
    return [check("column.control_volume_recovered.deceleration [-, abs]", 0.0, diff, 0.01, wall, cells // 10,
                  absolute=True)]


def dashpot_energy_balance(cells):
    """The column dashpot's energy balance closed, a liquid spring and a jet."""
    from ..programmer.column_dashpot import simulate_column
    from ..programmer.lumped_dashpot import LumpedDashpot
    V, M, m = 20.0, 10.0, 1.0
    relative = 0.5 * M * m / (M + m) * V ** 2
    out = []
    for name, a in (("closed", 0.0), ("orifice", 5e-5)):
        d = LumpedDashpot(M, m, V, 1e-3, 0.1, ((0.0, a), (1.0, a)), OIL.density, OIL.bulk_modulus,
                          FIXED_CD.discharge, law=FIXED_CD)
        t0 = time.perf_counter()
        run = simulate_column(d, 3e-3, 600, cells)
        out.append(check(f"column.dashpot_energy_balance.{name}.residual [-, abs]", 0.0,
                         run.summary["energy balance residual [J]"] / relative, 0.005, time.perf_counter() - t0,
                         cells, absolute=True))
    return out


def dashpot_push(cells):
    """A push on the column dashpot's striker (``StrikerPush``): a sabot carried with no force is a heavier
    striker (the same run, to round-off), and with a force and the sabot released mid-run the energy
    balance closes with the push's work in and the sabot's kinetic energy out."""
    from dataclasses import replace
    from ..programmer.column_dashpot import StrikerPush, simulate_column
    from ..programmer.lumped_dashpot import LumpedDashpot
    V, M, m, sabot, a = 20.0, 10.0, 1.0, 4.0, 5e-5
    d = LumpedDashpot(M, m, V, 1e-3, 0.1, ((0.0, a), (1.0, a)), OIL.density, OIL.bulk_modulus,
                      FIXED_CD.discharge, law=FIXED_CD)
    t0 = time.perf_counter()
    carried = simulate_column(d, 3e-3, 600, cells, push=StrikerPush(np.array([0.0, 1.0]), np.zeros(2), sabot, 1.0))
    heavier = simulate_column(replace(d, striker_mass=M + sabot), 3e-3, 600, cells)
    same = np.abs(carried.acceleration - heavier.acceleration).max() / np.abs(heavier.acceleration).max()
    force = StrikerPush(np.array([0.0, 1e-3, 2e-3]), np.array([2e4, 1e4, 0.0]), sabot, 1.5e-3)
    pushed = simulate_column(d, 3e-3, 600, cells, push=force)
    s = pushed.summary
    energy = s["kinetic energy in [J]"] + s["push's work on the striker [J]"]
    wall = time.perf_counter() - t0
    return [check("column.dashpot_push.carried_is_heavier [-, abs]", 0.0, same, 1e-12, wall, cells, absolute=True),
            check("column.dashpot_push.residual [-, abs]", 0.0, s["energy balance residual [J]"] / energy, 0.005,
                  wall, cells, absolute=True)]


def liquid_column(size, workdir):
    """The liquid column: Joukowsky, a fixed orifice against the characteristics, column separation and
    collapse, the control volume recovered."""
    cells = CELLS[size]
    # separation at 400 cells or more at every size: its largest cavity converges at first order (7.2% short
    # at 160 cells, 6.3% at 200, 4.2% at 400) and its 6% tolerance is set for 400
    return (joukowsky(cells) + fixed_orifice_vs_moc(cells) + separation(max(cells, CELLS["default"]))
            + control_volume_recovered(cells) + dashpot_energy_balance(max(cells // 2, 100))
            + dashpot_push(max(cells // 2, 100)))

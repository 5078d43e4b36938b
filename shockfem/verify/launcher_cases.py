"""Verification of the gas-gun model (``shockfem/launcher``).

* Constant-pressure limit (a reservoir a million times the barrel, no valve, massless gas,
  evacuated barrel): v = sqrt(2 p A L / m), exact.
* Adiabatic expansion with no orifice (the gas starts in the dead volume V0 at p0): exact
  v^2 = 2 p0 V0 / ((g - 1) m) [1 - (V0 / V)^(g - 1)].
* Simple-wave base pressure: the muzzle speed against x(v) = m / (A p0) int_0^v u du /
  (1 - (g-1) u / (2 c0))^(2g/(g-1)) by quadrature; and the lumped gun with the same gas never
  exceeds it.
* Energy of the full lumped model (valve, Lagrange gas inertia, air ahead, friction, seal drag)
  to 1e-6; the muzzle speed converges as the ODE tolerance tightens.

``launcher_design``: the optimiser against brute force.  Over a grid of bore x length x pressure
inside the limits, the tank that just reaches the speed is found by root-finding at each point;
the lightest grid gun must not beat the optimiser's, and the optimiser's gun meets the speed.
"""
from __future__ import annotations

import math
import time

from scipy.integrate import quad
from scipy.optimize import brentq

from ..launcher.gas import GASES
from ..launcher.design import Limits, Sizing, _with, lightest_launcher, valve_ratio_of, weights
from ..launcher.gun import Gun, fire
from .checks import check
from ..units import FT, IN, PSI

# The white paper's gun: 12 in bore, 6 ft barrel, 2000 psi.
BORE, LENGTH, PRESSURE = 12 * IN, 6 * FT, 2000 * PSI


def launcher_model(size, workdir):
    """Gas gun: constant-pressure and adiabatic closed forms exact, simple-wave bound, energy, convergence."""
    out = []
    m = 100.0
    A = math.pi * BORE ** 2 / 4
    g = Gun(1e6 * A * LENGTH, PRESSURE, BORE, LENGTH, m, air_ahead="evacuated", gas_inertia="none")
    s = fire(g)
    out.append(check("launcher.constant_pressure [m/s]", math.sqrt(2 * PRESSURE * A * LENGTH / m) *
                     math.sqrt(1 - 0.0), s.muzzle_velocity, 2e-6, s.wall_time_s, 0))
    out[-1]["note"] = "the reservoir is 1e6 barrel volumes: its pressure falls by 1.4e-6 over the shot"
    V0 = 0.05
    g = Gun(V0, PRESSURE, BORE, LENGTH, m, air_ahead="evacuated", gas_inertia="none")
    s = fire(g)
    V = V0 + A * LENGTH
    exact = math.sqrt(2 * PRESSURE * V0 / (0.4 * m) * (1 - (V0 / V) ** 0.4))
    out.append(check("launcher.adiabatic_no_orifice [m/s]", exact, s.muzzle_velocity, 1e-7, s.wall_time_s, 0))
    # simple wave: the muzzle speed from the closed-form x(v)
    gas = GASES["air"]
    c0 = gas.sound_speed(PRESSURE, 293.15)
    k = 2 * gas.gamma / (gas.gamma - 1)

    def x_of(v):
        return m / (A * PRESSURE) * quad(lambda u: u / (1 - (gas.gamma - 1) * u / (2 * c0)) ** k, 0, v,
                                         epsabs=0, epsrel=1e-12, limit=200)[0]
    # the limit speed 2 c0 / (g - 1) is never reached: bracket below it
    v_ref = brentq(lambda v: x_of(v) - LENGTH, 0.0, 0.9 * 2 * c0 / (gas.gamma - 1), xtol=1e-12)
    g_sw = Gun(1.0, PRESSURE, BORE, LENGTH, m, air_ahead="evacuated", gas_inertia="simple-wave")
    s = fire(g_sw)
    out.append(check("launcher.simple_wave_closed_form [m/s]", v_ref, s.muzzle_velocity, 1e-7, s.wall_time_s, 0))
    # ordering: a chamber of the bore's section 20 barrels long with Lagrange gas inertia stays below
    # the infinite chamber's simple-wave speed, which stays below the massless-gas (no inertia) one
    chamber = 20 * A * LENGTH
    lagrange = fire(Gun(chamber, PRESSURE, BORE, LENGTH, m, air_ahead="evacuated", gas_inertia="lagrange"))
    massless = fire(Gun(chamber, PRESSURE, BORE, LENGTH, m, air_ahead="evacuated", gas_inertia="none"))
    ordered = lagrange.muzzle_velocity <= s.muzzle_velocity <= massless.muzzle_velocity
    out.append(check("launcher.lagrange<simple_wave<massless [1 = yes]", 1.0, float(ordered), 0.0,
                     lagrange.wall_time_s + massless.wall_time_s, 0))
    out[-1]["note"] = (f"chamber of 20 barrel volumes: Lagrange {lagrange.muzzle_velocity:.2f} m/s, simple wave "
                       f"(infinite chamber) {s.muzzle_velocity:.2f} m/s, massless gas {massless.muzzle_velocity:.2f} m/s"
                       f": a massless gas overstates a 100 kg projectile's speed")
    full = Gun(0.5, PRESSURE, BORE, LENGTH, 944.3, valve_area=0.05, opening_time=2e-3, air_ahead="atmosphere",
               bore_friction=2000.0, seal_drag=0.02, gas_inertia="lagrange")
    s = fire(full)
    out.append(check("launcher.energy_balance_full_model [-, abs]", 0.0, s.energy_balance_error, 1e-6,
                     s.wall_time_s, 0, absolute=True))
    t0 = time.perf_counter()
    v = {rtol: fire(full, rtol=rtol).muzzle_velocity for rtol in (1e-5, 1e-7, 1e-9, 1e-11)}
    wall = time.perf_counter() - t0
    errors = [abs(v[r] - v[1e-11]) / v[1e-11] for r in (1e-5, 1e-7, 1e-9)]
    out.append(check("launcher.converges_with_tolerance [1 = yes]", 1.0,
                     float(errors[0] >= errors[1] >= errors[2] and errors[2] < 1e-8), 0.0, wall, 0))
    out[-1]["note"] = "muzzle speed change against rtol 1e-11: " + ", ".join(
        f"rtol {r:g}: {e:.1e}" for r, e in zip((1e-5, 1e-7, 1e-9), errors))
    return out


def launcher_design(size, workdir):
    """Launcher design: SLSQP's lightest gun against a brute-force grid; the speed it must reach."""
    n = {"coarse": 3, "default": 5, "fine": 7}[size]
    template = Gun(0.02, 1000 * PSI, 4 * IN, 2.0, 20.0, valve_area=math.pi * (3 * IN) ** 2 / 4,
                   opening_time=1e-3)
    speed = 150.0
    limits = Limits(max_length=3.0, max_bore=8 * IN, max_pressure=3000 * PSI, min_bore=2 * IN, min_length=0.5,
                    min_pressure=300 * PSI)
    sizing = Sizing()
    t0 = time.perf_counter()
    d = lightest_launcher(template, speed, limits, sizing, report_binding=False)
    wall_opt = time.perf_counter() - t0
    return against_grid("launcher_design", d, template, speed, limits, sizing, n, wall_opt)


def grid_lightest(template: Gun, speed: float, limits: Limits, sizing: Sizing, n: int) -> float:
    """The lightest gun [kg] of an n x n x n grid of bore, length and pressure within ``limits``, each with
    the tank that just reaches ``speed`` (root-found): the brute force an optimiser must not lose to."""
    ratio = valve_ratio_of(template)
    best = math.inf
    for bore in _geom(limits.min_bore, limits.max_bore, n):
        for length in _geom(limits.min_length, limits.max_length, n):
            for p in _geom(limits.min_pressure, limits.max_pressure, n):
                def short(log_v):
                    return fire(_with(template, ratio, (bore, length, p, math.exp(log_v))),
                                samples=2).muzzle_velocity - speed
                if short(math.log(limits.max_volume)) < 0:
                    continue
                log_v = brentq(short, math.log(limits.min_volume), math.log(limits.max_volume), xtol=1e-9)
                best = min(best, sum(weights(_with(template, ratio, (bore, length, p, math.exp(log_v))), sizing)))
    return best


def against_grid(name: str, d, template: Gun, speed: float, limits: Limits, sizing: Sizing, n: int,
                 wall_opt: float) -> list[dict]:
    """A launcher design ``d`` against the brute-force grid (no grid gun lighter, 1e-3) and its speed (2e-4,
    the optimiser's constraint tolerance)."""
    t0 = time.perf_counter()
    best = grid_lightest(template, speed, limits, sizing, n)
    wall_grid = time.perf_counter() - t0
    out = [check(f"{name}.no_grid_gun_lighter [kg]", best, max(d.weight, best), 1e-3, wall_opt + wall_grid, 0)]
    out[-1]["note"] = (f"optimiser {d.weight:.2f} kg ({d.evaluations} shots, {wall_opt:.1f} s); best of a "
                       f"{n}x{n}x{n} grid with the tank root-found {best:.2f} kg ({wall_grid:.1f} s), "
                       f"{d.weight / best - 1:+.2%}")
    out.append(check(f"{name}.meets_speed [m/s]", speed, d.muzzle_velocity, 2e-4, 0.0, 0))
    return out


def _geom(lo, hi, n):
    return [lo * (hi / lo) ** (k / (n - 1)) for k in range(n)]

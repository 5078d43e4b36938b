"""The quasi-1D gas column (``fluid.gas_column``) against exact solutions, and the 12 lb gas drive's ported end on it
against the ported law's bracket (``machine.drive_end``).

* ``gas_column``: Sod's shock tube (rho, u, p = 1, 0, 1 and 0.125, 0, 0.1, gamma 1.4, t = 0.2; Toro, Riemann
  Solvers and Numerical Methods for Fluid Dynamics, 3rd ed., sec. 4.3.3, test 1) against the exact Riemann
  solution (Toro ch. 4, ``exact_riemann``): the density's L1 error at 100 and 200 cells and its observed order
  (first order at the shock and the contact, which dominate the L1 norm); the plateau's pressure between the
  rarefaction and the shock against the exact's 0.30313.
* A piston withdrawn impulsively at V from air at rest: the face pressure is the simple wave's,
  p0 (1 - (gamma - 1) V / (2 c0))^(2 gamma / (gamma - 1)) (``launcher.simple_wave.base_pressure_ratio``), exact
  until the rarefaction's echo off the breech returns; at 200 and 400 cells, V = 0.3 c0.
* The simple-wave gun: a free piston (k = p0 A / m) driven by a column at rest, its speed after a travel short of
  the breech's echo against ``launcher.simple_wave.muzzle_speed``; at 200 and 400 cells.
* ``gas_column_design``: the 12 lb design in helium (``scripts/gas-drive-12lb.py``'s) fired on the column from the
  ports' opening (the chambered state the law takes there) to the arrest, radial and axial jets, the holes'
  discharge coefficient at both ends of ``drive_end.DISCHARGE_RANGE``, at 100, 200 and 400 cells: the face
  pressure at the separation against the law's bracket (each case inside it, to the change from 200 to 400
  cells); printed beside it, the same with all the ports at the face (the law's picture: the difference is the
  ports' spread over the band), the column with no ports against the chambered law (the column's own inertia),
  and each case's pulse against the band.
"""
from __future__ import annotations

import dataclasses
import math
import time

import numpy as np
from scipy.optimize import brentq

from .checks import check

# Sod's test 1 (Toro sec. 4.3.3)
SOD_LEFT, SOD_RIGHT, SOD_GAMMA, SOD_TIME = (1.0, 0.0, 1.0), (0.125, 0.0, 0.1), 1.4, 0.2
SOD_STAR_PRESSURE = 0.30313   # Toro table 4.2, test 1
# MUSCL-Hancock's L1 density error on Sod falls as dx^0.6-0.9 (first order at the shock and the contact, which
# dominate the norm): measured 0.0064 at 100 cells, 0.0035 at 200, 0.0020 at 400 (order 0.88, 0.82); the error
# asked at 200 cells with a margin of 1.4, its fall per halving at least 1.5 (a scheme losing its limiter or its
# predictor changes both)
SOD_L1_TOL = 0.005            # the density's L1 error at 200 cells [kg/m^3 m]
SOD_RATIO = 1.5               # the error's fall per halving of the cells
SOD_STAR_TOL = 0.005          # the plateau's mean pressure: measured 2e-4 off at 100 cells, 6e-5 at 200
# the simple wave's face pressure: measured 3e-6 off at 200 cells, 2e-7 at 400 (the impulsive start's first cells)
WITHDRAW_TOL = 1e-4
GUN_TOL = 1e-4                # the gun's speed: measured 1e-6 off at 200 and 400 cells (the midpoint coupling)
GRIDS = (200, 400)
DESIGN_GRIDS = (100, 200, 400)


def _f_k(p, rho, p_k, gamma):
    """Toro's pressure function f_K and its derivative (eqs. 4.6, 4.7)."""
    c = math.sqrt(gamma * p_k / rho)
    if p > p_k:
        A, B = 2 / ((gamma + 1) * rho), (gamma - 1) / (gamma + 1) * p_k
        s = math.sqrt(A / (p + B))
        return (p - p_k) * s, s * (1 - 0.5 * (p - p_k) / (B + p))
    r = p / p_k
    return (2 * c / (gamma - 1) * (r ** ((gamma - 1) / (2 * gamma)) - 1),
            r ** (-(gamma + 1) / (2 * gamma)) / (rho * c))


def exact_riemann(left, right, gamma, xi):
    """The exact Riemann solution (Toro ch. 4) of ``left`` and ``right`` = (rho, u, p) sampled at x / t = ``xi``
    (an array): (rho, u, p) arrays, and p*."""
    (rl, ul, pl), (rr, ur, pr) = left, right
    cl, cr = math.sqrt(gamma * pl / rl), math.sqrt(gamma * pr / rr)
    p = brentq(lambda p: _f_k(p, rl, pl, gamma)[0] + _f_k(p, rr, pr, gamma)[0] + ur - ul, 1e-12, 10 * max(pl, pr),
               xtol=1e-15)
    u = 0.5 * (ul + ur) + 0.5 * (_f_k(p, rr, pr, gamma)[0] - _f_k(p, rl, pl, gamma)[0])
    g1, g2 = (gamma - 1) / (gamma + 1), (gamma - 1) / (2 * gamma)
    out = np.empty((3, len(xi)))
    for j, s in enumerate(xi):
        if s <= u:
            rho_k, u_k, p_k, c_k, sign = rl, ul, pl, cl, 1
        else:
            rho_k, u_k, p_k, c_k, sign = rr, ur, pr, cr, -1
        if p > p_k:                # a shock (Toro eqs. 4.52, 4.59)
            S = u_k - sign * c_k * math.sqrt((gamma + 1) / (2 * gamma) * p / p_k + g2)
            star = rho_k * (p / p_k + g1) / (g1 * p / p_k + 1)
            out[:, j] = (rho_k, u_k, p_k) if sign * (S - s) > 0 else (star, u, p)
            continue
        c_star = c_k * (p / p_k) ** g2
        head, tail = u_k - sign * c_k, u - sign * c_star
        if sign * (head - s) > 0:
            out[:, j] = (rho_k, u_k, p_k)
        elif sign * (tail - s) < 0:
            out[:, j] = (rho_k * (p / p_k) ** (1 / gamma), u, p)
        else:                      # inside the fan (Toro eq. 4.56)
            f = 2 / (gamma + 1) + sign * (gamma - 1) / ((gamma + 1) * c_k) * (u_k - s)
            c = c_k * f
            out[:, j] = (rho_k * f ** (2 / (gamma - 1)), 2 / (gamma + 1) * (sign * c_k + (gamma - 1) / 2 * u_k + s),
                         p_k * f ** (2 * gamma / (gamma - 1)))
    return out, p


def sod(cells: int):
    """Sod's tube on [0, 1], the diaphragm at 0.5, walls at both ends (no wave reaches them by t = 0.2): the
    density's L1 error against the exact solution, the plateau's mean pressure and the run's (wall, steps)."""
    from ..fluid.gas_column import GasColumn

    def profile(x):
        left = x < 0.5
        rho = np.where(left, SOD_LEFT[0], SOD_RIGHT[0])
        p = np.where(left, SOD_LEFT[2], SOD_RIGHT[2])
        return p, p / rho, np.zeros_like(x)
    t0 = time.perf_counter()
    col = GasColumn(SOD_GAMMA, 1.0, 1.0, cells, profile=profile)
    t, steps = 0.0, 0
    while t < SOD_TIME * (1 - 1e-12):
        dt = min(col.stable_step(0.0), SOD_TIME - t)
        col.step(0.0, dt)
        t, steps = t + dt, steps + 1
    wall = time.perf_counter() - t0
    xc, rho, u, p = col.state()
    exact, _ = exact_riemann(SOD_LEFT, SOD_RIGHT, SOD_GAMMA, (xc - 0.5) / SOD_TIME)
    l1 = float(np.sum(np.abs(rho - exact[0])) / cells)
    # the plateau between the rarefaction's tail and the shock, away from both and the contact
    plateau = (xc > 0.5 + 0.05) & (xc < 0.5 + 1.4 * SOD_TIME) & (np.abs(exact[2] - SOD_STAR_PRESSURE) < 1e-4)
    return l1, float(np.mean(p[plateau])), wall, steps


def withdrawn_piston(cells: int, mach: float = 0.3):
    """Air at rest (1 bar, 293 K) in [0, 1] m, the piston withdrawn at ``mach`` c0 from t = 0: the face's p / p0
    at t = 0.8 L / c0 (before the echo off the breech returns), and the run's (wall, steps)."""
    from ..fluid.gas_column import GasColumn
    from ..launcher.gas import GASES
    g = GASES["air"]
    p0, T0 = 1e5, 293.0
    c0 = g.sound_speed(p0, T0)
    t0 = time.perf_counter()
    col = GasColumn(g.gamma, g.R, 1.0, cells, p0, T0)
    v, t, end, steps = mach * c0, 0.0, 0.8 / c0, 0
    while t < end * (1 - 1e-12):
        dt = min(col.stable_step(v), end - t)
        p = col.step(v, dt)
        t, steps = t + dt, steps + 1
    return p / p0, time.perf_counter() - t0, steps


def gun(cells: int):
    """The simple-wave gun: air at rest at 1 MPa, 293 K in a 4 m column, a piston of k = p0 A / m = 1e4 m/s^2
    free from rest, its speed after 1 m of travel (the breech's echo still behind it), and (wall, steps)."""
    from ..fluid.gas_column import GasColumn
    from ..launcher.gas import GASES
    g = GASES["air"]
    p0, T0, L, travel, k = 1e6, 293.0, 4.0, 1.0, 1e4
    t0 = time.perf_counter()
    col = GasColumn(g.gamma, g.R, L, cells, p0, T0)
    u, a, steps = 0.0, k, 0
    while col.face < L + travel - 1e-12:
        dt = col.stable_step(u)
        dt = min(dt, (L + travel - col.face) / (u + 0.5 * dt * a))
        # the piston's speed over the step the midpoint's, from the last step's acceleration
        p = col.step(u + 0.5 * dt * a, dt)
        a = k * p / p0
        u += dt * a
        steps += 1
    return u, time.perf_counter() - t0, steps


def _sod_checks() -> list[dict]:
    (e1, s1, w1, n1), (e2, s2, w2, n2) = (sod(c) for c in (100, 200))
    order = math.log2(e1 / e2)
    out = [check("gas_column.sod density L1 error at 200 cells [kg/m^3 m, absolute]", 0.0, e2, SOD_L1_TOL, w2, 200,
                 absolute=True),
           check(f"gas_column.sod L1 error's fall per halving (100 to 200 cells) short of {SOD_RATIO:g} [-, absolute]",
                 0.0, max(SOD_RATIO - e1 / e2, 0.0), 0.0, w1, 100, absolute=True),
           check("gas_column.sod plateau pressure at 200 cells [-]", SOD_STAR_PRESSURE, s2, SOD_STAR_TOL, 0.0, 200)]
    out[0]["note"] = f"L1 {e1:.3g} at 100 cells, {e2:.3g} at 200: observed order {order:.2f}; {n2} steps"
    out[1]["note"] = f"the fall {e1 / e2:.3g} (at least {SOD_RATIO:g} asked)"
    return out


def _withdrawn_checks() -> list[dict]:
    from ..launcher.gas import GASES
    from ..launcher.simple_wave import base_pressure_ratio
    g = GASES["air"]
    exact = base_pressure_ratio(0.3, 1.0, g.gamma)
    out = []
    for cells in GRIDS:
        r, wall, steps = withdrawn_piston(cells)
        out.append(check(f"gas_column.withdrawn_piston face p/p0 at 0.3 c0, {cells} cells", exact, r, WITHDRAW_TOL,
                         wall, cells))
        out[-1]["note"] = f"{steps} steps"
    return out


def _gun_checks() -> list[dict]:
    from ..launcher.gas import GASES
    from ..launcher.simple_wave import muzzle_speed
    g = GASES["air"]
    c0 = g.sound_speed(1e6, 293.0)
    exact = muzzle_speed(1.0, 1.0, 1e4, 1.0, c0, g.gamma)
    out = []
    for cells in GRIDS:
        u, wall, steps = gun(cells)
        out.append(check(f"gas_column.simple_wave_gun speed after 1 m, {cells} cells [m/s]", exact, u, GUN_TOL, wall,
                         cells))
        out[-1]["note"] = f"{steps} steps"
    return out


def _design_column() -> list[dict]:
    """The 12 lb design in helium's ported end on the column at 100, 200 and 400 cells, each (Cd, jets) against
    the law's bracket, with the bleed spread over the band and all at the face (the law's picture)."""
    from ..fluid.gas_column import RADIAL
    from ..machine import drive_end as E
    from ..machine.fixture import article_length
    from ..machine.gas_drive import design_gas_drive
    from ..machine.spec import read_spec
    from ..units import LB
    spec = read_spec({"article": "12 lb"})
    d = design_gas_drive(spec, "helium", 12 * LB, spec.diameter, article_length(spec))
    p = d.pulse
    lower, upper = d.column["law"]
    args = (p.specific_force, p.ports, p.port_speed, p.stroke, p.port_time, p.arrest_travel)
    bare = E.column_fall(*args[:1], dataclasses.replace(p.ports, beta=0.0), *args[2:], DESIGN_GRIDS[-1])
    law_bare = E.ported_fall(p.specific_force, dataclasses.replace(p.ports, beta=0.0), *args[2:5], x_end=args[5],
                             samples=2).end_ratio
    out = []
    for (cd, jets), band in d.column_bands.items():
        ports = dataclasses.replace(p.ports, discharge=cd)
        runs = []
        for cells in DESIGN_GRIDS:
            t0 = time.perf_counter()
            f = E.column_fall(p.specific_force, ports, *args[2:], cells, jets)
            runs.append((cells, f, time.perf_counter() - t0))
        face = E.column_fall(p.specific_force, ports, *args[2:], DESIGN_GRIDS[-1], jets, at_face=True)
        law = E.ported_fall(p.specific_force, dataclasses.replace(ports, recovery=jets == RADIAL), *args[2:5],
                            x_end=args[5], samples=2).end_ratio
        kind = "radial" if jets == RADIAL else "axial"
        finest = runs[-1][1].end_ratio
        # inside the bracket: the distance past its nearer end, zero inside it
        outside = max(finest - upper, lower - finest, 0.0)
        out.append(check(f"gas_column.design helium 12 lb, Cd {cd:g} {kind} jets: outside the law's bracket [p/p0, "
                         "absolute]", 0.0, outside, abs(runs[-1][1].end_ratio - runs[-2][1].end_ratio), runs[-1][2],
                         DESIGN_GRIDS[-1], absolute=True))
        grids = ", ".join(f"{f.end_ratio:.4f} ({c} cells, {w:.3f} s)" for c, f, w in runs)
        out[-1]["note"] = (f"face p/p0 at the separation {grids}"
                           f"; all the ports at the face {face.end_ratio:.4f}; the law {law:.4f}, its bracket {lower:.4f} to "
                           f"{upper:.4f}; no ports: column {bare.end_ratio:.4f}, law {law_bare:.4f}; the column's "
                           f"largest Mach number {runs[-1][1].inflow_mach:.3f}; its pulse "
                           f"{'in' if band.passed else 'OUTSIDE'} the band (worst excess {band.worst_excess:.3g})")
    return out


def gas_column_design(size: str, workdir: str) -> list[dict]:
    """The 12 lb gas drive's ported end on the column against the law's bracket (module docstring)."""
    return _design_column()


def gas_column(size: str, workdir: str) -> list[dict]:
    """The gas column against Sod's exact solution, the simple wave's face pressure and the simple-wave gun."""
    return _sod_checks() + _withdrawn_checks() + _gun_checks()

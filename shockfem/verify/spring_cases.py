"""Verification of discrete springs and dashpots: two bodies joined by a spring (a two-mass oscillator).

Two steel cylinders (axisymmetric) joined by a spring k between their facing ends, one launched
at v0 away from the other: the extension is e(t) = (v0 / omega) sin(omega t) with
omega^2 = k (1/m_a + 1/m_b).  The spring's force is shared in proportion to nodal mass, so the
cylinders accelerate as rigid bodies and carry no stress: the exact solution holds for the
discrete model too, up to the central-difference phase error (omega dt)^2 / 24, far below the
tolerances here.  With a dashpot c = 2 zeta sqrt(k m*) successive peaks fall by
exp(-2 pi zeta / sqrt(1 - zeta^2)); the damped case gives the spring as a tabulated curve.
"""
from __future__ import annotations

import math

import numpy as np

from .checks import SIZES, check, element_count, parallel_agreement
from .scenes import STEEL, solve

RADIUS, LENGTH, GAP, V0, K = 0.01, 0.02, 0.01, 1.0, 1e6


def _scene(h, damping=0.0, curve=False):
    m = STEEL["density"] * math.pi * RADIUS ** 2 * LENGTH
    omega = math.sqrt(K * 2.0 / m)
    period = 2 * math.pi / omega
    spring = {"name": "link", "a": "lower.top", "b": "upper.bottom", "damping": damping}
    if curve:
        d = 1e-3                    # two points: the linear spring, extrapolated beyond them
        spring["curve"] = [[-d, -K * d], [d, K * d]]
    else:
        spring["stiffness"] = K
    body = {"material": "steel", "shape": "cylinder", "radius": RADIUS, "length": LENGTH, "element_size": h}
    return {"scene": {"name": "spring_oscillator", "kinematics": "axisymmetric", "end_time": 2.2 * period},
            "materials": {"steel": dict(STEEL)},
            "bodies": [dict(body, name="lower", position=[0.0, 0.0]),
                       dict(body, name="upper", position=[0.0, LENGTH + GAP], velocity=[0.0, V0])],
            "spring": [spring],
            "outputs": {"field_interval": 2.2 * period, "history_interval": period / 50}}, m, omega


def _run(raw, workdir):
    samples = []
    solver, wall = solve(raw, cache_dir=workdir,
                         probe=lambda s: samples.append((s.t, s.springs[0].extension)))
    t, e = np.array(samples).T
    return solver, wall, t, e


def _peaks(t, e):
    """Times and values of the local maxima of e (parabola through each peak sample and its neighbours)."""
    i = np.flatnonzero((e[1:-1] > e[:-2]) & (e[1:-1] >= e[2:])) + 1
    a, b, c = e[i - 1], e[i], e[i + 1]
    shift = 0.5 * (a - c) / (a - 2 * b + c)
    dt = t[i + 1] - t[i]
    return t[i] + shift * dt, b - 0.25 * (a - c) * shift


def spring_oscillator(size, workdir):
    """Linear spring: period 2 pi / omega and amplitude v0 / omega; a tabulated spring with a
    dashpot: the logarithmic decrement of zeta = 0.05; energy balance in both; the same under mpirun."""
    h = 0.005 * SIZES[size]
    raw, m, omega = _scene(h)
    solver, wall, t, e = _run(raw, workdir)
    tp, ep = _peaks(t, e)
    n = element_count(solver)
    out = [check("spring.period [s]", 2 * math.pi / omega, tp[1] - tp[0], 0.005, wall, n),
           check("spring.amplitude [m]", V0 / omega, ep[0], 0.005, wall, n),
           check("spring.energy_balance [-, abs]", 0.0, solver.energy.balance_error, 0.01, wall, n, absolute=True)]
    zeta = 0.05
    m_eff = 0.5 * m
    raw, _, _ = _scene(h, damping=2 * zeta * math.sqrt(K * m_eff), curve=True)
    solver, wall, t, e = _run(raw, workdir)
    tp, ep = _peaks(t, e)
    out += [check("spring.damped_peak_ratio [-]", math.exp(-2 * math.pi * zeta / math.sqrt(1 - zeta ** 2)),
                  ep[1] / ep[0], 0.01, wall, n),
            check("spring.damped_energy_balance [-, abs]", 0.0, solver.energy.balance_error, 0.01, wall, n,
                  absolute=True)]
    # the ends' mean motions are sums over ranks: mpirun -n 2 must give the one-process history
    out.append(parallel_agreement(raw, "spring.np2_vs_np1", workdir, ["lower.v_z", "upper.v_z", "energy.contact"]))
    return out

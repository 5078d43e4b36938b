"""Verification of the amplifier's rigid-body models (``shockfem/amplifier``).

* The event-driven model's first pass equals the closed forms of both architectures
  (launched chain G, stack on anvil (1 + e) G - 1) to 1e-12, over n = 2..6 masses,
  e = 1, 0.9, 0.75, 0.5 and R = m_n / m_1 = 0.5, 0.1, 0.01.
* Geometric mass ratios maximise the gain for a given R: an optimiser started from random
  ratios finds no larger gain and converges to the geometric ratios.
* Momentum is conserved through every collision, and energy too at e = 1.
"""
from __future__ import annotations

import time

import numpy as np

from ..amplifier import gain, rigid
from .cases import check

NS, ES, RS = (2, 3, 4, 5, 6), (1.0, 0.9, 0.75, 0.5), (0.5, 0.1, 0.01)


def amplifier_rigid(size, workdir):
    """Event-driven chains against the launched-chain and stack-on-anvil closed forms; geometric ratios optimal."""
    out = []
    for arch, run in (("launched-chain", rigid.launched_chain), ("stack-on-anvil", rigid.stack_on_anvil)):
        t0 = time.perf_counter()
        worst, worst_p, worst_e, count = 0.0, 0.0, 0.0, 0
        for n in NS:
            for e in ES:
                for R in RS:
                    q = R ** (1 / (n - 1))
                    masses = [10.0 * q ** k for k in range(n)]
                    r = run(masses, 10.0, e)
                    exact = gain.gain(arch, e, R, n)
                    worst = max(worst, abs(r.first_pass[-1] / 10.0 - exact) / abs(exact))
                    if arch == "launched-chain":      # no anvil: momentum is conserved
                        p0, p1 = r.masses @ r.initial, r.masses @ r.final
                        worst_p = max(worst_p, abs(p1 - p0) / abs(p0))
                    if e == 1.0:
                        k0, k1 = r.kinetic_energy
                        worst_e = max(worst_e, abs(k1 - k0) / k0)
                    count += 1
        wall = time.perf_counter() - t0
        out.append(check(f"amplifier_rigid.{arch}.first_pass_vs_closed_form [-, max rel]", 0.0, worst, 1e-12,
                         wall, count, absolute=True))
        if arch == "launched-chain":
            out.append(check(f"amplifier_rigid.{arch}.momentum [-, max rel]", 0.0, worst_p, 1e-12, wall, count,
                             absolute=True))
        out.append(check(f"amplifier_rigid.{arch}.energy_at_e=1 [-, max rel]", 0.0, worst_e, 1e-12, wall, count,
                         absolute=True))
    out += _geometric_is_optimal()
    return out


def _geometric_is_optimal():
    """Maximise prod (1 + e) / (1 + r_k) over ratios r_k with prod r_k = R, from random starts."""
    from scipy.optimize import minimize
    t0 = time.perf_counter()
    rng = np.random.default_rng(0)
    worst_gain, worst_ratio = 0.0, 0.0
    for n, e, R in ((4, 0.9, 0.01), (5, 0.8, 0.001), (6, 1.0, 0.05)):
        def negative_gain(s):          # s: log ratios of the first n - 2 stages; the last closes prod = R
            logs = np.append(s, np.log(R) - s.sum())
            return -np.prod((1 + e) / (1 + np.exp(logs)))
        best = min((minimize(negative_gain, rng.uniform(np.log(R), 0, n - 2), method="BFGS",
                             options={"gtol": 1e-12}) for _ in range(5)), key=lambda res: res.fun)
        geometric = gain.chain_gain(e, R, n)
        worst_gain = max(worst_gain, (-best.fun - geometric) / geometric)
        logs = np.append(best.x, np.log(R) - best.x.sum())
        worst_ratio = max(worst_ratio, float(np.abs(np.exp(logs) / R ** (1 / (n - 1)) - 1).max()))
    wall = time.perf_counter() - t0
    # an optimiser's answer: the gain to its tolerance, the ratios to the square root of it
    return [check("amplifier_rigid.optimum_gain_above_geometric [-]", 0.0, max(worst_gain, 0.0), 1e-9, wall, 3,
                  absolute=True),
            check("amplifier_rigid.optimum_ratios_vs_geometric [-, max rel]", 0.0, worst_ratio, 1e-4, wall, 3,
                  absolute=True)]

"""Verification of the amplifier's rigid-body models (``shockfem/amplifier``).

* The event-driven model's first pass equals the closed forms of both architectures
  (launched chain G, stack on anvil (1 + e) G - 1) to 1e-12, over n = 2..6 masses,
  e = 1, 0.9, 0.75, 0.5 and R = m_n / m_1 = 0.5, 0.1, 0.01.
* Geometric mass ratios maximise the gain for a given R: an optimiser started from random
  ratios finds no larger gain and converges to the geometric ratios.
* Momentum is conserved through every collision, and energy too at e = 1.
* Pads (``amplifier_pads``): three steel cylinders meeting on 2%-damped elastic pads whose
  contact lasts ten wave transits: the bodies act as rigid ones, so the 1D bars restitute as
  rigid bodies on a spring-dashpot that never pulls (``rigid.pad_restitution``) and the
  axisymmetric run as the 1D bars, each within 0.5%.
"""
from __future__ import annotations

import json
import math
import os
import time

import numpy as np

from ..amplifier import gain, rigid
from ..amplifier.bars import Bar, Interface, run_bars
from ..amplifier.chain import run_chain_scene
from ..metrics import shapes
from ..metrics.pulse import pulse_metrics
from ..metrics.signals import acceleration_from_velocity
from ..metrics.stages import stage_table
from ..output.history_file import read_history_csv
from ..runner import run_scene
from ..scene import resolve
from .checks import SIZES, check
from .contact_cases import RADIUS, SPEED
from .scenes import STEEL, steel_c0

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


def _bar_stage(bars, end_time):
    """Run two bars through a kinematic contact; the stage of their collision and the run."""
    r = run_bars(bars, [Interface("impact")], end_time)
    stages = stage_table(r.history, r.masses, [{"name": "impact", "a": bars[0].name, "b": bars[1].name}], "z",
                         ("z",))
    return r, stages


def _plateau(h, pair, start, end):
    """Mean contact force of ``pair`` over the middle half of [start, end] [N] (the peak rides
    on the ringing of the discrete front, 7% above the plateau at 400 elements)."""
    t = h["time"]
    span = end - start
    on = (t > start + 0.25 * span) & (t < end - 0.25 * span)
    return float(h[f"contact.{pair}.normal_z"][on].mean())


def _fitted_duration(h, body):
    """Foot-to-foot duration of the classical shape fitted to a body's rigid-body pulse [s]."""
    t, a = acceleration_from_velocity(h["time"], h[f"{body}.v_z"])
    p = pulse_metrics(t, a)
    return shapes.classify(t, a, p).ideal.duration


def amplifier_1d(size, workdir):
    """1D bars against St Venant (contact time 2L1/c0, restitution L1/L2, force rho c0 v A/2); axisymmetric vs 1D."""
    c0, rho, E = steel_c0(), STEEL["density"], STEEL["youngs_modulus"]
    A = math.pi * RADIUS ** 2
    L2 = 0.1
    out = []
    for ratio in (1.0, 0.5, 0.3):
        L1 = ratio * L2
        r, stages = _bar_stage([Bar("striker", L1, A, rho, E, SPEED), Bar("target", L2, A, rho, E)], 2.5 * L2 / c0)
        s = stages[0]
        n = sum(int(round(L / (L1 / 400))) for L in (L1, L2))
        # 1D theory is exact for these bars; 1% is the acceptance tolerance (measured: within 0.6%)
        out += [check(f"amplifier_1d.L1/L2={ratio:g}.stages [count]", 1, len(stages), 0.0, r.wall_time_s, n,
                      absolute=True),
                check(f"amplifier_1d.L1/L2={ratio:g}.contact_time [s]", 2 * L1 / c0, s.end - s.start, 0.01,
                      r.wall_time_s, n),
                check(f"amplifier_1d.L1/L2={ratio:g}.restitution [-]", ratio, s.restitution, 0.01, r.wall_time_s, n),
                check(f"amplifier_1d.L1/L2={ratio:g}.plateau_force [N]", rho * c0 * SPEED * A / 2,
                      _plateau(r.history, s.pair, s.start, s.end), 0.01, r.wall_time_s, n),
                check(f"amplifier_1d.L1/L2={ratio:g}.energy_balance [-, abs]", 0.0, r.energy_balance_error, 1e-3,
                      r.wall_time_s, n, absolute=True)]
    out += _axisymmetric_vs_1d(size, workdir)
    return out


def _axisymmetric_vs_1d(size, workdir):
    """The slender unequal rods of the contact verification (L1 = 0.1 m, L2 = 0.2 m, R = 2.5 mm)
    through the axisymmetric solver and the 1D model, measured by the same stage table and pulse fit."""
    c0 = steel_c0()
    L1, L2, gap = 0.1, 0.2, 1e-5
    end = gap / SPEED + 2.5 * 2 * L1 / c0
    h = 0.00025 * SIZES[size]
    rod = {"material": "steel", "shape": "cylinder", "radius": RADIUS, "element_size": h}
    raw = {"scene": {"name": "axisymmetric_vs_1d", "kinematics": "axisymmetric", "end_time": end},
           "materials": {"steel": dict(STEEL)},
           "bodies": [{"name": "striker", **rod, "length": L1, "position": [0.0, L2 + gap], "velocity": [0.0, -SPEED]},
                      {"name": "target", **rod, "length": L2, "position": [0.0, 0.0]}],
           "contact": [{"name": "impact", "a": "striker.bottom", "b": "target.top", "penalty_scale": 1.0}],
           "outputs": {"field_interval": end, "history_interval": 2 * L1 / c0 / 400}}
    fe = run_scene(resolve(raw), workdir, progress=False, write_fields=False, quiet=True)
    fe_stage = fe.summary["shock"]["stages"][0]
    h_fe = read_history_csv(f"{workdir}/history.csv")
    A = math.pi * RADIUS ** 2
    rho, E = STEEL["density"], STEEL["youngs_modulus"]
    # the 1D striker moves along +x: mirror the axis (speeds compare by magnitude)
    r, stages = _bar_stage([Bar("striker", L1, A, rho, E, SPEED), Bar("target", L2, A, rho, E)], end - gap / SPEED)
    s = stages[0]
    wall, n = fe.summary["wall_time_s"], fe.summary["elements"]
    fe_plateau = abs(_plateau(h_fe, fe_stage["pair"], fe_stage["start"], fe_stage["end"]))
    d_1d, d_fe = _fitted_duration(r.history, "target"), _fitted_duration(h_fe, "target")
    # the rods are 20 D long: lateral inertia and the interface stay within the 3% acceptance bound
    out = [
        check("amplifier_1d.axisymmetric_vs_1d.restitution [-]", s.restitution, fe_stage["restitution"], 0.03,
              wall, n),
        check("amplifier_1d.axisymmetric_vs_1d.target_speed [m/s]", abs(s.struck_after),
              abs(fe_stage["struck_after"]), 0.03, wall, n),
        check("amplifier_1d.axisymmetric_vs_1d.plateau_force [N]", _plateau(r.history, s.pair, s.start, s.end),
              fe_plateau, 0.03,
              wall, n),
    ]
    out[-1]["note"] = (f"the fitted pulse lasts {d_fe * 1e6:.4g} us in the axisymmetric run against "
                       f"{d_1d * 1e6:.4g} us in 1D ({d_fe / d_1d - 1:+.1%}): lateral inertia rounds the "
                       f"edges, which 1D theory does not have (reported, not checked)")
    return out


def amplifier_pads(size, workdir):
    """Three steel cylinders (R 20/14/10 mm, L 80/60/40 mm) launched at 10 m/s onto 50 MN/m pads,
    2% damped: rigid, 1d and axisymmetric restitution per stage and gain."""
    zeta = 0.02
    bodies = [{"name": f"m{k + 1}", "material": "steel", "shape": "cylinder", "radius": r, "length": L,
               "element_size": 0.002 * SIZES[size]} for k, (r, L) in enumerate(((0.02, 0.08), (0.014, 0.06),
                                                                                 (0.01, 0.04)))]
    raw = {"chain": {"name": "pads", "launch_speed": 10.0, "gap": 0.002, "pad_stiffness": 5e7,
                     "pad_thickness": 0.02, "pad_damping": zeta},
           "materials": {"steel": dict(STEEL)}, "bodies": bodies}
    runs = {}
    for fidelity in ("rigid", "1d", "axisymmetric"):
        runs[fidelity] = run_chain_scene(raw, os.path.join(workdir, f"pads_{fidelity}"), fidelity, progress=False,
                                         echo=lambda *a: None)
    e_pad = rigid.pad_restitution(zeta)
    out = []
    with open(os.path.join(workdir, "pads_axisymmetric", "summary.json")) as fh:
        n_fe = json.load(fh)["elements"]
    for k in range(2):
        e1 = runs["1d"]["stages"][k]["restitution"]
        efe = runs["axisymmetric"]["stages"][k]["restitution"]
        out += [check(f"amplifier_pads.stage{k + 1}.1d_vs_rigid_pad [-]", e_pad, e1, 0.005,
                      runs["1d"]["wall_time_s"], 0),
                check(f"amplifier_pads.stage{k + 1}.axisymmetric_vs_1d [-]", e1, efe, 0.005,
                      runs["axisymmetric"]["wall_time_s"], n_fe)]
    out.append(check("amplifier_pads.gain.axisymmetric_vs_rigid [-]", runs["rigid"]["gain"],
                     runs["axisymmetric"]["gain"], 0.005, runs["axisymmetric"]["wall_time_s"], n_fe))
    return out

"""The velocity-amplifier study (the white paper's task 3): ``shockfem study amplifier``.

Sections, each a table and where useful a figure in ``report.md``:

1. The white paper's sizing claim (12 lb to 1600 ft/s with five masses from 300-350 ft/s, under
   800 lb of intermediate masses at e = 0.9) from the closed forms, for both architectures, and
   Eq. 2 against the launched chain's gain.
2. Apparent restitution of two steel cylinders against their natural-frequency ratio (striker
   length varied, target fixed, 2% damping), elastic and elastic-plastic, at the 1d and
   axisymmetric fidelities; and against the contact duration over the target's natural period.
3. The five-mass design run at each fidelity: restitution per stage against the assumed one,
   gain, peak interface stress against yield; wall time and difference from the finest model.
4. The white paper's own illustration (diminishing steel rods, 10%-damped contacts, soft springs
   between the first and the last) rebuilt in 1D, elastic and elastic-plastic.
5. Cylinders against thick plates: the design's masses at several length / diameter ratios, gain
   against the volume the stack occupies (axisymmetric).
6. Interfaces that keep the design elastic: flat and crowned faces against yield, pads sized to
   a face stress below it, the padded design at every fidelity, and its effective restitution
   against the assumed 0.9, 0.8 and 0.75.

Sizes: ``smoke`` (a minute, for tests), ``default`` (``make run``, under 15 minutes on 2 cores).
"""
from __future__ import annotations

import dataclasses
import math
import os
import time

from ..output.figures import pyplot

from ..amplifier import rigid
from ..amplifier.bars import Bar, Interface, Tether, run_bars
from ..amplifier.chain import default_end_time, parting_end_time, run_chain_scene
from ..amplifier.gain import chain_gain, cylinder_size, design, stack_gain
from ..amplifier.interfaces import (flat_face_stress, hertz_yield_speed, pad_for_force,
                                    reduced_mass)
from ..errors import UnstableRun
from ..metrics.stages import first_impacts, stage_table
from ..scene.library import LIBRARY, property_si
from ..units import FT, LB, to_si
from .cases import run_chain_cases
from .report import Report

FTS, FT3 = FT, FT ** 3              # ft/s and cubic feet in SI
MATERIAL = "high_strength_steel"
# pads (section 6): their damping ratio, the face stress they allow over yield, their thickness
# over their travel, and the working stress of the spring steel that bounds their volume
PAD_DAMPING = 0.02
ALLOWABLE = 0.8
PAD_SPACE = 1.5
SPRING_STRESS = 1.5e9
ASSUMED_RESTITUTION = (0.9, 0.8, 0.75)
# The structural damping models compared in sections 2 and 3: 2% of critical held over each body's first
# 20 free-free modes (the chain's default), 2% stiffness-proportional at its first mode, and none
DAMPING_MODELS = {"band": {"damping": 0.02, "damping_type": "band"},
                  "stiffness": {"damping": 0.02, "damping_type": "stiffness"},
                  "none": {"damping": 0.0}}
SIZES = {
    # frequency-ratio sweep: striker lengths as fractions of the target's; element size [m]
    # the design's runs: (fidelity, element size [m]; rigid and 1d do not mesh)
    "smoke": {"ratios": (0.5, 1.0), "h_pair": 0.004, "rod_speeds": (10.0,), "rod_elements": 10,
              "plate_aspects": (1.0, 0.25), "plate_h": 0.04, "plate_bore": False, "pad_h": 0.03,
              "design": (("rigid", 0.03), ("1d", 0.03), ("axisymmetric", 0.03))},
    "default": {"ratios": (0.25, 0.4, 0.5, 0.7, 1.0, 1.5, 2.0), "h_pair": 0.002, "rod_speeds": (10.0, 99.06),
                "rod_elements": 40, "plate_aspects": (2.0, 1.0, 0.5, 0.25), "plate_h": 0.02, "plate_bore": True,
                "pad_h": 0.02,
                "design": (("rigid", 0.03), ("1d", 0.03), ("3d", 0.03), ("axisymmetric", 0.02),
                           ("axisymmetric", 0.01))},
}


def _steel() -> dict:
    return {"steel": {"library": MATERIAL}}


def _chain_raw(name, bodies, speed, fidelity, gap=5e-4, e=0.9, damping="band", architecture="launched-chain",
               end_time=None):
    """A chain scene; ``damping`` one of DAMPING_MODELS (2% of critical, or none)."""
    chain = {"name": name, "architecture": architecture, "launch_speed": speed, "fidelity": fidelity,
             "gap": gap, "restitution": e, **DAMPING_MODELS[damping]}
    if end_time:
        chain["end_time"] = end_time
    return {"chain": chain, "materials": _steel(), "bodies": bodies}


def _cylinder(name, radius, length, h, **extra):
    return {"name": name, "material": "steel", "shape": "cylinder", "radius": radius, "length": length,
            "element_size": h, **extra}


def sizing_claims(rep: Report):
    rep.heading("1. The white paper's sizing claim")
    rep.text("A 12 lb test article at 1600 ft/s from a first mass at 300-350 ft/s, five masses, e = 0.9: the paper "
             "claims under 800 lb of intermediate masses (under 4 cubic feet of steel). Geometric mass ratios "
             "(optimal for a given mass ratio), closed forms of `shockfem/amplifier/gain.py`.")
    rho = property_si(MATERIAL, "density", "density")
    rows = []
    for arch in ("launched-chain", "stack-on-anvil"):
        for e in (0.9, 0.8, 0.75):
            for v in (300, 325, 350):
                d = design(arch, 12 * LB, 1600 * FTS, v * FTS, e, 5)
                if not d.feasible:
                    rows.append([arch, e, v, "-", "-", "-", "-", d.reason])
                    continue
                rows.append([arch, e, v, d.masses[0] / LB, d.intermediate_mass / LB,
                             d.intermediate_mass / rho / FT3, d.efficiency,
                             "yes" if d.intermediate_mass / LB < 800 else "no"])
    rep.table("sizing_claims", ["architecture", "e", "launch [ft/s]", "first mass [lb]", "intermediate [lb]",
               "intermediate [ft^3]", "efficiency", "under 800 lb"], rows,
              ["{}", "{:g}", "{}", "{:.0f}", "{:.0f}", "{:.2f}", "{:.1%}", "{}"])
    rep.text("Eq. 2 of the paper, (1+e)^n / (1 + R^(1/(n-1)))^(n-1) - 1, is the gain of a stack falling onto an "
             "anvil; a gun-launched chain gains G = [(1+e)/(1 + R^(1/(n-1)))]^(n-1):")
    rows = [[n, e, R, chain_gain(e, R, n), stack_gain(e, R, n)] for n in (3, 5) for e in (0.9, 0.75)
            for R in (0.1, 0.01)]
    rep.table("gain_formulas", ["n", "e", "R = m_n/m_1", "launched chain G", "Eq. 2 (stack on anvil)"], rows,
              ["{}", "{:g}", "{:g}", "{:.3f}", "{:.3f}"])
    return design("launched-chain", 12 * LB, 1600 * FTS, 325 * FTS, 0.9, 5)


def _pair_raw(fidelity, ratio, speed, h, elastic, damping="band") -> dict:
    """Striker of length ratio * L2 on a target L2 = 100 mm, both R = 10 mm."""
    L2 = 0.1
    bodies = [_cylinder("striker", 0.01, ratio * L2, h), _cylinder("target", 0.01, L2, h)]
    raw = _chain_raw(f"pair_{ratio:g}", bodies, speed, fidelity, damping=damping)
    if elastic:
        raw["materials"] = {"steel": {"density": "7850 kg/m^3", "youngs_modulus": "210 GPa", "poisson_ratio": 0.3}}
    return raw


def pair_cases(size: str) -> list[tuple[str, dict, tuple[str, float, str]]]:
    """Section 2's runs: (name, chain scene, (model, striker length ratio, damping model)), at each of
    DAMPING_MODELS."""
    cases = []
    for elastic, speed in ((True, 1.0), (False, 60.0)):
        for fidelity in ("1d", "axisymmetric"):
            key = f"{fidelity}, {'elastic 1 m/s' if elastic else 'elastic-plastic 60 m/s'}"
            for ratio in SIZES[size]["ratios"]:
                for damping in DAMPING_MODELS:
                    suffix = "" if damping == "band" else f"_{damping}"
                    cases.append((f"pairs/{fidelity}_{speed:g}_{ratio:g}{suffix}",
                                  _pair_raw(fidelity, ratio, speed, SIZES[size]["h_pair"], elastic, damping),
                                  (key, ratio, damping)))
    return cases


def restitution_sweep(rep: Report, size: str, runs: "ChainRuns"):
    plt = pyplot()
    rep.heading("2. Apparent restitution against natural-frequency ratio")
    c0 = math.sqrt(210e9 / 7850)
    rep.text("Two steel cylinders of radius 10 mm: the target 100 mm long, the striker L1 = ratio x 100 mm, 2% "
             "structural damping held over each body's first 20 free-free modes (band). The first free-free longitudinal frequency of a cylinder is about c0 / 2L, so "
             "the frequency ratio striker/target is L2/L1. Elastic at 1 m/s (E 210 GPa), and elastic-plastic at "
             f"60 m/s ({MATERIAL}: rho c0 v / 2 = 1.2 GPa at the face against its 690 MPa yield, with Cowper-Symonds "
             "rate effects). Restitution from the stage table (mean velocities before and after); contact "
             "duration over the target's natural period 2 L2 / c0.")
    rows, curves, by_damping = [], {}, {}
    for name, raw, (key, ratio, damping) in pair_cases(size):
        chain, problem = runs.run(name, raw)
        by_damping[(key, ratio, damping)] = chain["stages"][0]["restitution"] if chain else None
        if damping != "band":
            continue
        curves.setdefault(key, [])
        if chain is None:
            rows.append([key, ratio, 1 / ratio, "stopped: " + problem[:60], "-", "-", "-"])
            continue
        s = chain["stages"][0]
        duration = (s["end"] - s["start"]) / (2 * 0.1 / c0)
        curves[key].append((1 / ratio, s["restitution"], duration))
        rows.append([key, ratio, 1 / ratio, s["restitution"], duration, s["vibration_share"], chain["wall_time_s"]])
    rep.table("restitution_sweep", ["model", "L1/L2", "f_striker/f_target", "restitution", "contact / target period",
               "energy left ringing", "wall [s]"], rows,
              ["{}", "{:g}", "{:.3g}", "{:.4f}", "{:.3f}", "{:.1%}", "{:.1f}"])
    damping_models(rep, by_damping)
    stopped = sum(isinstance(r[3], str) for r in rows)
    if stopped:             # the readings compare whole curves: a curve with holes would mislead
        rep.text(f"Reading: {stopped} of the {len(rows)} runs stopped (above): the sweep is read only when every "
                 "run completes.")
        return rows
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for key, pts in curves.items():
        fr, e, d = zip(*pts)
        style = "-o" if "axisymmetric" in key else "--s"
        axes[0].plot(fr, e, style, label=key)
        axes[1].plot(d, e, style, label=key)
    axes[0].set_xscale("log")
    axes[0].set_xlabel("frequency ratio striker / target (L2 / L1)")
    axes[1].set_xlabel("contact duration / target natural period")
    for ax in axes:
        ax.set_ylabel("apparent restitution")
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=7)
    rep.figure("restitution_vs_frequency_ratio.png", "Apparent restitution of two steel cylinders against their "
               "frequency ratio and against contact duration over the target's natural period", fig)
    findings = []
    for key, pts in curves.items():
        best = max(pts, key=lambda p: p[1])
        findings.append(f"{key}: highest restitution {best[1]:.3f} at frequency ratio {best[0]:.3g} "
                        f"(contact / target period {best[2]:.2f})")
    rep.text("Reading: " + "; ".join(findings) + ". " + _sweep_reading(rep, curves))
    return rows


def damping_models(rep: Report, restitution: dict):
    """Section 2's restitutions at each damping model side by side (``restitution``: (model, length ratio,
    damping model) -> restitution or None), and how much of each loss the damping model makes."""
    rep.text("The same pairs at each structural damping model: none, 2% stiffness-proportional at each body's "
             "first free-free frequency (zeta = 2% x f / f1, so the short waves of an impact are overdamped; the "
             "1d bars are then no finer than that damping resolves, as `run_bars` does), and 2% held over the "
             "first 20 modes (band, the default). Each damping's loss is the undamped restitution less its own; "
             "band - stiffness is the part of the stiffness-proportional loss owed to its frequency dependence.")
    rows, losses = [], {}
    for (key, ratio, damping), e in restitution.items():
        if damping != "none":
            continue
        stiff, band = restitution.get((key, ratio, "stiffness")), restitution.get((key, ratio, "band"))
        if None in (e, stiff, band):
            rows.append([key, ratio, e, stiff, band, "-", "-", "-"])
            continue
        losses.setdefault(key, []).append((e - stiff, e - band))
        rows.append([key, ratio, e, stiff, band, e - stiff, e - band, band - stiff])
    rep.table("restitution_by_damping", ["model", "L1/L2", "e undamped", "e stiffness 2%", "e band 2%",
                                         "loss stiffness", "loss band", "band - stiffness"], rows,
              ["{}", "{:g}", "{:.4f}", "{:.4f}", "{:.4f}", "{:+.4f}", "{:+.4f}", "{:+.4f}"])
    words = []
    for key, pairs in losses.items():
        stiff = rep.value(f"damping_loss.stiffness.{key}", sum(p[0] for p in pairs) / len(pairs))
        band = rep.value(f"damping_loss.band.{key}", sum(p[1] for p in pairs) / len(pairs))
        words.append(f"{key}: 2% takes {stiff:+.3f} of restitution stiffness-proportional and {band:+.3f} as a band "
                     f"on average over the ratios")
    if words:
        elastic = [p for key, pairs in losses.items() if "elastic 1 m/s" in key for p in pairs]
        biggest = max(elastic, key=lambda p: p[0], default=None)
        rep.text("Reading: " + "; ".join(words) + "." + (
            f" Where the stiffness-proportional damping costs most (elastic, {biggest[0]:.3f}), the band still takes "
            f"{biggest[1]:.3f}: most of that loss is 2% of damping acting on the sharp wave of an impact, which "
            "carries energy at every harmonic, each losing 4 pi zeta of its energy per cycle; the rest, "
            f"{biggest[0] - biggest[1]:.3f}, is the stiffness-proportional model overdamping the harmonics."
            if biggest and biggest[0] > 0.01 else "") + _plastic_words(restitution, losses))


def _plastic_words(restitution: dict, losses: dict) -> str:
    """Whether the elastic-plastic pairs lose more to yielding (1 - e undamped) than to either damping."""
    plastic = [k for k in losses if "plastic" in k]
    yielding = [1 - e for (key, _, damping), e in restitution.items() if key in plastic and damping == "none" and e]
    damped = [abs(x) for key in plastic for pair in losses[key] for x in pair]
    if not yielding or not damped:
        return ""
    return (f" Elastic-plastic pairs lose {min(yielding):.2f} to {max(yielding):.2f} of restitution undamped, "
            + ("far more than either damping takes" if min(yielding) > 3 * max(damped) else
               f"against up to {max(damped):.3f} for the damping")
            + " (the 1d stiffness column runs on coarser bars, which moves its plastic restitution too).")


def _sweep_reading(rep: Report, curves: dict) -> str:
    """What the restitution sweep shows, each sentence chosen by the numbers (``curves``: model ->
    [(frequency ratio, restitution, duration)])."""
    def mean_e(key):
        return sum(p[1] for p in curves[key]) / len(curves[key])
    words = []
    for fidelity in ("1d", "axisymmetric"):
        pts = curves[f"{fidelity}, elastic 1 m/s"]
        best = max(pts, key=lambda p: p[1])
        tuned = min(pts, key=lambda p: abs(math.log(p[0])))
        words.append(f"elastic {fidelity} bodies restitute best "
                     + ("when tuned to the same frequency" if best is tuned else
                        f"at frequency ratio {best[0]:.3g}, not at the tuned one ({tuned[0]:.3g})"))
    e = {k: rep.value(f"mean_restitution.{k}", mean_e(k)) for k in curves}
    axi_el, one_el = e["axisymmetric, elastic 1 m/s"], e["1d, elastic 1 m/s"]
    axi_pl, one_pl = e["axisymmetric, elastic-plastic 60 m/s"], e["1d, elastic-plastic 60 m/s"]
    words.append(f"averaged over the ratios the axisymmetric bodies restitute {axi_el:.3f} elastic against 1D's "
                 f"{one_el:.3f}")
    words.append(f"yielding {'lowers' if max(axi_pl, one_pl) < min(axi_el, one_el) else 'does not lower'} it "
                 f"(axisymmetric {axi_pl:.3f}, 1D {one_pl:.3f} at 60 m/s)")
    if one_pl < axi_pl:
        words.append("the 1D bar (uniaxial stress) yields over its whole section where the real face is confined, "
                     "so it overstates the loss")
    return "; ".join(words) + "."


def _design_sizes(d) -> list[dict]:
    """The design's masses as cylinders with L = D."""
    rho = property_si(MATERIAL, "density", "density")
    return [cylinder_size(m, rho, 1.0) for m in d.masses]


def design_cases(d, size: str, damping: str = "band") -> list[tuple[str, dict, str]]:
    """Section 3's runs: (name, chain scene, label) of the five-mass design at each fidelity, with the
    ``damping`` model; at another than the default band, only the 1d and the first axisymmetric fidelity
    (section 3's comparison of damping models)."""
    bodies = [_cylinder(f"m{k + 1}", s["diameter"] / 2, s["length"], 0.02) for k, s in enumerate(_design_sizes(d))]
    end = parting_end_time(_chain_raw("five_mass", bodies, d.launch_speed, "rigid"))
    cases = []
    fidelities = SIZES[size]["design"]
    if damping != "band":
        fidelities = [next(f for f in fidelities if f[0] == kind) for kind in ("1d", "axisymmetric")]
    for fidelity, h in fidelities:
        label = fidelity if fidelity in ("rigid", "1d") else f"{fidelity} ({h * 1e3:g} mm)"
        raw = _chain_raw("five_mass", [dict(b, element_size=h) for b in bodies], d.launch_speed, fidelity,
                         end_time=end, damping=damping)
        suffix = "" if damping == "band" else f"_{damping}"
        cases.append(("design/" + label.replace(" ", "_").replace("(", "").replace(")", "") + suffix, raw, label))
    return cases


def design_at_fidelities(rep: Report, d, size: str, chain_runs: "ChainRuns"):
    rep.heading("3. The five-mass design at each fidelity")
    sizes = _design_sizes(d)
    rep.text(f"Launched chain, 12 lb at 1600 ft/s from 325 ft/s, e = 0.9 assumed, {MATERIAL} cylinders with "
             "L = D. The rigid model uses the assumed restitution; the others find their own.")
    rep.table("design_masses", ["mass", "kg", "lb", "diameter [mm]", "length [mm]"],
              [[k + 1, m, m / LB, s["diameter"] * 1e3, s["length"] * 1e3]
               for k, (m, s) in enumerate(zip(d.masses, sizes))], ["{}", "{:.4g}", "{:.4g}", "{:.4g}", "{:.4g}"])
    cases = design_cases(d, size)
    runs = [(label, *chain_runs.run(name, raw)) for name, raw, label in cases]
    rows = []
    finest = next((c for _, c, _ in reversed(runs) if c and c["gain"] is not None), None)
    for label, chain, problem in runs:
        if chain is None:
            rows.append([label, "stopped: " + problem[:80], "-", "-", "-", "-"])
            continue
        es = ", ".join(f"{e:.3f}" for e in first_impacts(chain["stages"]).values())
        if chain["contact_at_end"]:
            es += " (still in contact at the end)"
        ratio = max(chain["stress_over_yield"].values(), default=float("nan"))
        gain = chain["gain"] if chain["gain"] is not None else float("nan")
        diff = (gain / finest["gain"] - 1) if finest and finest["gain"] else float("nan")
        rows.append([label, es, gain, diff, ratio, chain["wall_time_s"]])
    rep.text("The finest model is the last in the table (axisymmetric at 10 mm at default size). The XDMF "
             "fields of each finite-element run are in `design/<fidelity>/fields.xdmf`.")
    rep.text("Restitution per stage from the stage table (the mean velocities of the two bodies at the start of a "
             "contact and before either body's next one); gain = the test article's speed at the end of the run "
             "over the launch speed.")
    rep.table("design_fidelities", ["fidelity", "restitution per stage", "gain", "gain vs finest", "peak stress / yield", "wall [s]"],
              rows, ["{}", "{}", "{:.3f}", "{:+.1%}", "{:.2f}", "{:.3g}"])
    if finest:
        es = list(first_impacts(finest["stages"]).values())
        worst = max(finest["stress_over_yield"].values(), default=float("nan"))
        short = rep.value("design.finest_gain_over_rigid", finest["gain"] / d.gain)
        yielding = [k for k, v in finest["stress_over_yield"].items() if v > 1.0]
        verdict = ("does not amplify as the rigid model assumes" if short < 0.9 else
                   "amplifies as the rigid model assumes" if short < 1.1 else "amplifies more than the rigid model")
        rep.text(f"Reading: with flat steel faces this design {verdict}: the finest model finds restitutions "
                 f"{min(es):.2f} to {max(es):.2f} per stage (0.9 assumed) and a gain of {finest['gain']:.2f} against "
                 f"{d.gain:.2f} ({short:.0%}). Peak von Mises stress is up to {worst:.1f} times the {MATERIAL} yield; "
                 + (f"{len(yielding)} of {len(finest['stress_over_yield'])} bodies yield, so energy goes into "
                    "plastic work and into bodies that keep moving together, and the interfaces must be made to "
                    "stay elastic (crowned faces, pads, tuned lengths, stronger materials) before e = 0.9 can be "
                    "assumed: section 6." if yielding else "no interface yields."))
    design_damping(rep, d, size, chain_runs)
    # the pictures of the finest finite-element run, the last in the table (rigid and 1d have no mesh)
    meshed = [(name, label) for (name, raw, label), (_, chain, _) in zip(cases, runs)
              if chain and raw["chain"]["fidelity"] in ("axisymmetric", "3d")]
    if meshed:
        name, label = meshed[-1]
        rep.run_pictures(name, f"The five-mass design, {label},", "the r-z half-section, m1 at the top, the chain moving along -z")
    return runs


def design_damping(rep: Report, d, size: str, runs: "ChainRuns"):
    """The design at 1d and the first axisymmetric fidelity with each damping model: how much of the
    stages' loss of restitution and of the gain is the damping model."""
    results = {damping: [(label, runs.run(name, raw)[0]) for name, raw, label in design_cases(d, size, damping)]
               for damping in DAMPING_MODELS}
    rows, gains = [], {}
    for damping, runs_at in results.items():
        for label, chain in runs_at:
            if label == "rigid" or (damping == "band" and label not in dict(results["none"])):
                continue
            if chain is None or chain["gain"] is None:
                rows.append([label, damping, "stopped", "-"])
                continue
            gains[(label, damping)] = chain["gain"]
            rows.append([label, damping, ", ".join(f"{e:.3f}" for e in first_impacts(chain["stages"]).values()),
                         chain["gain"]])
    rows.sort(key=lambda r: (r[0], list(DAMPING_MODELS).index(r[1])))
    rep.text("The design at each damping model (2% band over each body's first 20 modes, the default; 2% "
             "stiffness-proportional at each body's first mode; none), at 1d and the coarsest axisymmetric mesh:")
    rep.table("design_by_damping", ["fidelity", "damping", "restitution per stage", "gain"], rows,
              ["{}", "{}", "{}", "{:.3f}"])
    words, moves = [], []
    for label in dict(results["none"]):
        g = [gains.get((label, m)) for m in ("none", "stiffness", "band")]
        if None in g:
            continue
        moves.append(rep.value(f"design.damping_moves_gain.{label}", max(abs(g[1] - g[0]), abs(g[2] - g[0])) / g[0]))
        words.append(f"{label}: gain {g[0]:.3f} undamped, {g[1]:.3f} stiffness-proportional, {g[2]:.3f} band "
                     f"(the damping moves it by up to {moves[-1]:.1%})")
    if words:
        verdict = (f"the damping model moves the gain by at most {max(moves):.1%}, against the {1 - min(gains.values()) / d.gain:.0%} "
                   "that the bodies themselves cost the rigid chain's: damping is not what sets this design's gain"
                   if max(moves) < 0.1 else "the damping model moves the gain by as much as the rest of the physics: "
                   "the design's gain depends on it")
        rep.text("Reading: " + "; ".join(words) + f"; {verdict}.")


def _steel_bar(name, diameter, length, speed=0.0, plastic=True) -> Bar:
    lib = LIBRARY[MATERIAL]
    E, Et = to_si(lib["youngs_modulus"], "pressure"), to_si(lib["tangent_modulus"], "pressure")
    return Bar(name, length, math.pi * diameter ** 2 / 4, to_si(lib["density"], "density"), E, speed,
               elements=0, yield_stress=to_si(lib["yield_stress"], "pressure") if plastic else math.inf,
               hardening=E * Et / (E - Et) if plastic else 0.0)


def paper_rods(rep: Report, size: str):
    """The white paper's Figure 9 experiment in 1D: diminishing steel rods, 10%-damped contacts,
    then soft springs between the first and the last rod."""
    rep.heading("4. The white paper's diminishing rods")
    cfg = SIZES[size]
    # diameters shrinking by 0.55 (masses by 0.166 per stage): a rigid chain at e = 0.5 gains 2.7
    n, shrink, d0 = 5, 0.55, 0.1
    diameters = [d0 * shrink ** k for k in range(n)]
    lengths = [2 * d for d in diameters]
    names = [f"rod{k + 1}" for k in range(n)]
    K = property_si(MATERIAL, "youngs_modulus", "pressure") / (3 * (1 - 2 * 0.3))
    h = lengths[-1] / cfg["rod_elements"]
    # LS-DYNA's default penalty for a face of area A on elements of size h: SLSFAC K A / h,
    # SLSFAC = 0.1; the smaller face of each pair
    pads = [0.1 * K * math.pi * diameters[k + 1] ** 2 / 4 / h for k in range(n - 1)]
    masses = [_steel_bar(nm, d, L).mass for nm, d, L in zip(names, diameters, lengths)]
    gap = 1e-3
    rep.text("The paper (Proof Engineering's illustration, its Figure 9): 'arbitrary but diminishing sized "
             "cylindrical rods, elastic-plastic materials with properties of steel, and contacts with 10% "
             "damping ... restitution coefficients on the order of 0.5. The overall velocity amplification of 3.5 "
             "was achieved only after connecting the first and the last body with soft springs, otherwise "
             "velocity gain was under 3.0.' Its rods are not given; here: "
             f"{n} {MATERIAL} rods, diameters {', '.join(f'{d * 1e3:.0f}' for d in diameters)} mm, each twice as "
             f"long as wide (mass ratio {shrink ** 3:.3f} per stage, {masses[-1] / masses[0]:.3f} overall), "
             f"launched chain, 1D bars ({cfg['rod_elements']} elements in the shortest; bilinear plasticity, no "
             "rate effect), 2% structural damping. Contacts as LS-DYNA's default penalty, 0.1 K A / h on the "
             f"smaller face ({pads[0] / 1e9:.3g} to {pads[-1] / 1e9:.3g} GN/m), with 10% of critical damping on "
             "the two rods' reduced mass; or exact (kinematic) contact for comparison. Soft springs: a tether "
             "between the middle of the first and the last rod whose period on the two masses is four times the "
             "rigid cascade at e = 0.5. Restitution per stage: the first strike of each pair. Gain: the last "
             "rod's largest speed over the launch speed (and its speed at the end of the run).")
    cascade = rigid.launched_chain(masses, 1.0, 0.5, lengths, gap)
    t_cascade = max(c.time for c in cascade.collisions)
    m_star = reduced_mass(masses[0], masses[-1])
    c0 = _steel_bar("x", 1, 1).c0
    rows = []
    for speed in cfg["rod_speeds"]:
        t_run = t_cascade / speed * 3 + 6 * lengths[0] / c0
        k_tether = m_star * (2 * math.pi / (4 * t_cascade / speed)) ** 2
        rigid_gain = rigid.launched_chain(masses, speed, 0.5, lengths, gap).final[-1] / speed
        for label, with_pads, tether in (("exact contact", False, False), ("10%-damped penalty", True, False),
                                         ("10%-damped penalty + soft spring", True, True)):
            bars = [_steel_bar(nm, d, L, speed if k == 0 else 0.0)
                    for k, (nm, d, L) in enumerate(zip(names, diameters, lengths))]
            bars = [dataclasses.replace(b, elements=max(1, round(b.length / h))) for b in bars]
            ifaces = [Interface(f"{names[k]}_{names[k + 1]}", gap, pads[k] if with_pads else None,
                                0.1 if with_pads else 0.0) for k in range(n - 1)]
            tethers = (Tether("spring", 0, n - 1, k_tether),) if tether else ()
            r = run_bars(bars, ifaces, t_run, damping_ratio=0.02,
                         damping_frequency=[b.c0 / (2 * b.length) for b in bars], tethers=tethers)
            contacts = [{"name": i.name, "a": names[k], "b": names[k + 1]} for k, i in enumerate(ifaces)]
            stages = stage_table(r.history, r.masses, contacts, "z", ("z",))
            es = list(first_impacts(stages).values())
            last = r.history[f"{names[-1]}.v_z"]
            rows.append([speed, label, ", ".join(f"{e:.2f}" for e in es), float(last.max()) / speed,
                         float(last[-1]) / speed, rigid_gain,
                         max(r.interface_stress.values()) / property_si(MATERIAL, "yield_stress", "pressure"),
                         r.energy_balance_error, r.wall_time_s])
    rep.table("paper_rods", ["launch [m/s]", "contacts", "restitution per stage", "gain (peak)", "gain (end)",
               "rigid, e = 0.5", "interface stress / yield", "energy balance", "wall [s]"], rows,
              ["{:g}", "{}", "{}", "{:.2f}", "{:.2f}", "{:.2f}", "{:.2f}", "{:.1e}", "{:.2f}"])
    by = {(r[0], r[1]): r for r in rows}
    words = []
    for speed in cfg["rod_speeds"]:
        plain, pad, spring = (by[(speed, k)] for k in ("exact contact", "10%-damped penalty",
                                                        "10%-damped penalty + soft spring"))
        es = [float(e) for e in pad[2].split(", ")]
        words.append(f"at {speed:g} m/s the damped contacts give restitutions {min(es):.2f} to {max(es):.2f} "
                     f"(paper: about 0.5) and a gain of {pad[3]:.2f} (paper: under 3.0; exact contact "
                     f"{plain[3]:.2f}); the soft spring {'raises' if spring[3] > pad[3] else 'does not raise'} the "
                     f"peak gain ({spring[3]:.2f} against {pad[3]:.2f}; paper: 3.5), and the last rod's speed is "
                     f"{spring[4]:.2f} times the launch speed at the end")
    matched = [speed for speed in cfg["rod_speeds"]
               if abs(by[(speed, "10%-damped penalty")][3] / 3.0 - 1) < 0.2
               and all(abs(float(e) - 0.5) < 0.15 for e in by[(speed, "10%-damped penalty")][2].split(", "))]
    rep.value("paper_rods.speeds_matching_the_paper", matched)
    rep.text("Reading: " + "; ".join(words) + ". With the rods' sizes unknown the paper's experiment can only be "
             "matched in kind: " + (f"at {', '.join(f'{v:g}' for v in matched)} m/s the damped contacts restitute "
                                   "within 0.15 of 0.5 with a gain within 20% of 3.0" if matched else
                                   "at no launch speed do the damped contacts restitute within 0.15 of 0.5 with a "
                                   "gain within 20% of 3.0") + ".")
    return rows


def _plate_variants(d, size: str) -> list[tuple[str, list[dict]]]:
    """Every body at one length / diameter ratio (the stack's envelope is then the same whatever the
    ratio: D^2 L is fixed by the mass), and every body of one diameter, the test article's as a thick
    plate (L = D / 4): a stack that fits one bore, long rods above a plate."""
    cfg = SIZES[size]
    rho = property_si(MATERIAL, "density", "density")
    variants = [(f"L/D {a:g}", [cylinder_size(m, rho, a) for m in d.masses]) for a in cfg["plate_aspects"]]
    if cfg["plate_bore"]:
        bore = cylinder_size(d.masses[-1], rho, 0.25)["diameter"]
        variants.append((f"one bore {bore * 1e3:.0f} mm",
                         [{"diameter": bore, "length": m / rho / (math.pi * bore ** 2 / 4)} for m in d.masses]))
    return variants


def plate_cases(d, size: str) -> list[tuple[str, dict, tuple[str, str, list[dict]]]]:
    """Section 5's runs: (name, chain scene, (model, bodies, their sizes))."""
    cases = []
    for elastic, speed in ((True, 10.0), (False, d.launch_speed)):
        key = "elastic, 10 m/s" if elastic else f"elastic-plastic, {speed:.4g} m/s"
        for shape, sizes in _plate_variants(d, size):
            bodies = [_cylinder(f"m{k + 1}", s["diameter"] / 2, s["length"],
                                min(SIZES[size]["plate_h"], s["length"] / 4)) for k, s in enumerate(sizes)]
            raw = _chain_raw(shape.replace(" ", "_").replace("/", ""), bodies, speed, "axisymmetric", gap=1e-3)
            if elastic:
                raw["materials"] = {"steel": {"density": "7850 kg/m^3", "youngs_modulus": "210 GPa",
                                              "poisson_ratio": 0.3}}
            raw["chain"]["end_time"] = parting_end_time(raw)
            label = f"{'elastic' if elastic else 'plastic'}_{shape.replace(' ', '_').replace('/', '')}"
            cases.append((f"plates/{label}", raw, (key, shape, sizes)))
    return cases


def cylinders_vs_plates(rep: Report, d, size: str, runs: "ChainRuns"):
    """The five-mass design's masses as cylinders of several length / diameter ratios, down to
    thick plates: gain against the volume the stack occupies (axisymmetric, elastic and
    elastic-plastic)."""
    plt = pyplot()
    rep.heading("5. Cylinders against thick plates")
    rep.text("The five masses of section 3 at several length / diameter ratios, from long cylinders to thick "
             "plates, and all of one diameter (a stack that fits one bore: long rods above a thick plate); "
             "launched chain, axisymmetric, 2% damping, 1 mm gaps. Occupied volume: the envelope of the "
             "stack, a cylinder of the widest body's diameter and the bodies' total length (gaps aside). Elastic "
             "steel at 10 m/s (the geometry's own losses: waves and radial modes) and "
             f"{MATERIAL} at the design's {d.launch_speed:.4g} m/s (with yielding). Each body is damped 2% "
             "over a band from its own first mode up (the chains' default band damping), and its elements are "
             "a quarter of its length, at most "
             f"{SIZES[size]['plate_h'] * 1e3:g} mm. Restitution: each pair's first impact.")
    rows, curves = [], {}
    for name, raw, (key, shape, sizes) in plate_cases(d, size):
        curves.setdefault(key, [])
        chain, problem = runs.run(name, raw)
        if chain is None:
            rows.append([key, shape, "-", "-", "-", "stopped: " + problem[:60], "-"])
            continue
        envelope = math.pi / 4 * max(s["diameter"] for s in sizes) ** 2 * sum(s["length"] for s in sizes)
        es = ", ".join(f"{e:.2f}" for e in first_impacts(chain["stages"]).values())
        worst = max(chain["stress_over_yield"].values(), default=None)
        rows.append([key, shape, envelope * 1e3, chain["gain"], es,
                     "elastic" if worst is None else worst, chain["wall_time_s"]])
        curves[key].append((envelope * 1e3, chain["gain"], shape))
    rep.table("cylinders_vs_plates", ["model", "bodies", "occupied volume [L]", "gain", "restitution per stage", "peak stress / yield",
               "wall [s]"], rows, ["{}", "{}", "{:.4g}", "{:.3f}", "{}", "{:.2f}", "{:.3g}"])
    fig, ax = plt.subplots(figsize=(6, 4))
    for key, pts in curves.items():
        if pts:
            vol, g, a = zip(*pts)
            ax.plot(vol, g, "o-", label=key)
            for x, y, asp in pts:
                ax.annotate(asp, (x, y), fontsize=7)
    ax.set_xlabel("occupied volume [L]")
    ax.set_ylabel("gain")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    rep.figure("gain_vs_volume.png", "Gain of the five-mass design against the volume its stack occupies, "
               "cylinders to thick plates", fig)
    words = []
    for key, pts in curves.items():
        if pts:
            best = max(pts, key=lambda p: p[1])
            small = min(pts, key=lambda p: p[0])
            words.append(f"{key}: the highest gain {best[1]:.2f} with {best[2]} ({best[0]:.0f} L); the "
                         f"smallest stack is {small[2]} ({small[0]:.0f} L, gain {small[1]:.2f})")
    rep.text("Reading: " + "; ".join(words) + ".")
    return rows


@dataclasses.dataclass(frozen=True)
class PadDesign:
    """Section 6's pads: the stiffest linear pad on each struck face that holds its stress at ALLOWABLE x
    yield, sized on the closing speeds of a rigid chain with the pads' own restitution."""
    restitution: float              # of rigid bodies on a pad damped PAD_DAMPING
    closing_speeds: list            # of the rigid chain at that restitution, per stage [m/s]
    pads: list                      # ``interfaces.pad_for_force``'s, per stage
    thickness: list                 # PAD_SPACE x each pad's travel [m]
    sequenced_gap: float            # the gap that lets each stage end before the next begins [m]


def pad_design(d) -> PadDesign:
    Y = property_si(MATERIAL, "yield_stress", "pressure")
    masses = list(d.masses)
    areas = [math.pi * s["diameter"] ** 2 / 4 for s in _design_sizes(d)]
    e_pad = rigid.pad_restitution(PAD_DAMPING)
    dvs = rigid.first_closing_speeds(masses, d.launch_speed, e_pad)
    pads = [pad_for_force(dv, reduced_mass(masses[k], masses[k + 1]), ALLOWABLE * Y * areas[k + 1])
            for k, dv in enumerate(dvs)]
    # the struck body, accelerated over the contact to about its final speed, moves some 0.6 v tau
    # before the pad lets go
    v_after = [dvs[0]] + [rigid.launched_chain(masses, d.launch_speed, e_pad).first_pass[k]
                          for k in range(1, len(masses))]
    sequenced = max(0.6 * v_after[k + 1] * p.duration for k, p in enumerate(pads))
    return PadDesign(e_pad, dvs, pads, [PAD_SPACE * p.travel for p in pads], sequenced)


def padded_cases(d, size: str) -> list[tuple[str, dict, tuple[str, float]]]:
    """Section 6's runs: (name, chain scene, (label, gap [m])): the padded design with 1 mm gaps (rigid, 1d,
    axisymmetric) and with the gaps that keep its stages in sequence (1d, axisymmetric)."""
    pd, h = pad_design(d), SIZES[size]["pad_h"]
    bodies = [_cylinder(f"m{k + 1}", s["diameter"] / 2, s["length"], h) for k, s in enumerate(_design_sizes(d))]
    cases = []
    for gap in (1e-3, pd.sequenced_gap):
        for fidelity in ("rigid", "1d", "axisymmetric") if gap == 1e-3 else ("1d", "axisymmetric"):
            raw = _chain_raw("padded", bodies, d.launch_speed, fidelity, gap=gap)
            raw["chain"].update({"pad_stiffness": [p.stiffness for p in pd.pads], "pad_thickness": pd.thickness,
                                 "pad_damping": PAD_DAMPING})
            label = fidelity if fidelity != "axisymmetric" else f"axisymmetric ({h * 1e3:g} mm)"
            cases.append((f"padded/{fidelity}_gap_{gap * 1e3:.0f}mm", raw, (label, gap)))
    return cases


def elastic_interfaces(rep: Report, d, size: str, runs_of: "ChainRuns"):
    """What keeps the five-mass design elastic: flat faces and crowned faces against yield, then
    pads sized to a face stress below yield, run at every fidelity; the effective restitution per
    stage against the assumed 0.9, 0.8 and 0.75."""
    rep.heading("6. Interfaces that keep the design elastic")
    mat = LIBRARY[MATERIAL]
    rho, E = to_si(mat["density"], "density"), to_si(mat["youngs_modulus"], "pressure")
    nu, Y = float(mat["poisson_ratio"]), to_si(mat["yield_stress"], "pressure")
    c0, e_star = math.sqrt(E / rho), E / (2 * (1 - nu ** 2))
    masses = list(d.masses)
    sizes = _design_sizes(d)
    areas = [math.pi * s["diameter"] ** 2 / 4 for s in sizes]
    n = len(masses)
    pairs = [(k, k + 1) for k in range(n - 1)]
    rep.text(f"The design of section 3 ({MATERIAL}, yield {Y / 1e6:.0f} MPa, cylinders L = D). Closing speeds "
             f"from the rigid chain at e = {d.restitution:g}. Flat faces: the 1D impedance stress dv Z_a Z_b / (Z_a + Z_b) "
             "over the smaller face, and the largest closing speed that keeps it below yield. Crowned faces: "
             "the closing speed at which a crown of radius ten times the smaller diameter first yields "
             "(Hertz, p0 = 1.6 Y; `shockfem/amplifier/interfaces.py`).")
    dvs = rigid.first_closing_speeds(masses, d.launch_speed, d.restitution)
    rows = []
    for (a, b), dv in zip(pairs, dvs):
        z_a, z_b = rho * c0 * areas[a], rho * c0 * areas[b]
        sigma = flat_face_stress(dv, z_a, z_b, areas[b])
        crown = 10 * sizes[b]["diameter"]
        rows.append([f"m{a + 1}-m{b + 1}", dv, sigma / 1e6, sigma / Y, dv * Y / sigma,
                     hertz_yield_speed(reduced_mass(masses[a], masses[b]), crown, e_star, Y)])
    rep.table("flat_face_stress", ["stage", "closing speed [m/s]", "flat-face stress [MPa]", "/ yield", "flat faces elastic up to [m/s]",
               "crown R = 10 D yields at [m/s]"], rows, ["{}", "{:.1f}", "{:.0f}", "{:.2f}", "{:.1f}", "{:.2f}"])
    pd = pad_design(d)
    zeta, e_pad, dvs_pad, pads, sequenced = PAD_DAMPING, pd.restitution, pd.closing_speeds, pd.pads, pd.sequenced_gap
    rep.text(f"Pads: a linear elastic pad on each struck face, {zeta:.0%} damped (restitution of rigid bodies on "
             f"it {e_pad:.4f}), as stiff as keeps the face stress at {ALLOWABLE:.0%} of yield: k = (F / dv)^2 / M* "
             f"with F = {ALLOWABLE:g} Y A (closing speeds of the rigid chain at e = {e_pad:.3f}). Its travel, "
             "the energy it stores, and the contact duration against the struck body's first period 2L / c0 "
             f"(above 1: the bodies move as rigid ones). Ideal spring volume: the energy over the most a "
             f"spring steel at {SPRING_STRESS / 1e9:g} GPa stores, sigma^2 / 2E (real springs need several "
             f"times more). In the finite-element runs each pad is {PAD_SPACE:g} times its travel thick.")
    prow = []
    for (a, b), dv, p in zip(pairs, dvs_pad, pads):
        period = 2 * sizes[b]["length"] / c0
        prow.append([f"m{a + 1}-m{b + 1}", dv, p.stiffness / 1e6, p.travel * 1e3, p.energy / 1e3,
                     p.duration * 1e3, p.duration / period, p.energy / (SPRING_STRESS ** 2 / (2 * E)) * 1e3])
    rep.table("pads", ["stage", "closing speed [m/s]", "pad stiffness [MN/m]", "travel [mm]", "energy [kJ]", "contact [ms]",
               "contact / struck period", "ideal spring volume [L]"], prow,
              ["{}", "{:.1f}", "{:.4g}", "{:.1f}", "{:.4g}", "{:.3f}", "{:.2g}", "{:.3g}"])
    runs = []
    for name, raw, (label, gap) in padded_cases(d, size):
        chain, problem = runs_of.run(name, raw)
        if chain is None:
            runs.append([label, gap * 1e3, "stopped: " + problem[:80], "-", "-", "-", "-", "-"])
            continue
        es = list(first_impacts(chain["stages"]).values())
        runs.append([label, gap * 1e3, ", ".join(f"{e:.3f}" for e in es),
                     "yes" if contacts_overlap(chain["stages"]) else "no",
                     rigid.effective_restitution(masses, d.launch_speed, chain["gain"]), chain["gain"],
                     max(chain["stress_over_yield"].values(), default=float("nan")), chain["wall_time_s"]])
    for e in ASSUMED_RESTITUTION:
        g = rigid.launched_chain(masses, d.launch_speed, e).final[-1] / d.launch_speed
        runs.append([f"rigid, e = {e:g} assumed", "-", ", ".join([f"{e:.3f}"] * (n - 1)), "no", e, g, "-", "-"])
    rep.text("The padded design at every fidelity (launched chain, 2% structural damping on each body over a "
             f"band from its own first mode up) with 1 mm gaps before the pads, and with {sequenced * 1e3:.0f} mm "
             "gaps that let each "
             "stage end before the next begins; and the rigid chain at the restitutions the paper assumes. "
             "Restitution per stage: each pair's first contact, meaningless when contacts overlap (the bodies "
             "then act as one chain of springs). Effective restitution: the one e that gives the rigid chain of "
             "these masses the same gain. The finite-element XDMF fields are in `padded/*/fields.xdmf`.")
    rep.table("padded_chain", ["model", "gaps [mm]", "restitution per stage", "contacts overlap", "effective e", "gain",
               "peak stress / yield", "wall [s]"], runs,
              ["{}", "{:.0f}", "{}", "{}", "{:.3f}", "{:.3f}", "{:.2f}", "{:.3g}"])
    fe = [r for r in runs if r[0].startswith("axisymmetric") and isinstance(r[5], float)]
    flat = rows

    def span(values, fmt):
        lo, hi = fmt.format(min(values)), fmt.format(max(values))
        return lo if lo == hi else f"{lo}-{hi}"
    strong = 2000e6 / Y * min(r[4] for r in flat)        # flat-face elastic limit of a 2 GPa steel
    crowned_worse = max(r[5] for r in flat) < min(r[4] for r in flat)
    words = (f"Flat steel faces stay elastic only below {span([r[4] for r in flat], '{:.0f}')} m/s of closing speed, "
             f"and the design closes at {span(dvs, '{:.0f}')} m/s ({span([r[3] for r in flat], '{:.1f}')} times "
             f"yield); a 2 GPa steel would allow {strong:.0f} m/s, "
             + ("still below the design's slowest closing speed" if strong < min(dvs) else "enough for some stages")
             + f", and a crowned face yields at {span([r[5] for r in flat], '{:.2g}')} m/s"
             + (", sooner than a flat one" if crowned_worse else "") + f". Pads sized to "
             f"hold the faces below yield: {span([p.stiffness / 1e6 for p in pads], '{:.0f}')} MN/m with "
             f"{span([p.travel * 1e3 for p in pads], '{:.0f}')} mm of travel, storing up to "
             f"{max(p.energy for p in pads) / 1e3:.0f} kJ")
    for r in fe:
        words += (f"; with {r[1]:.0f} mm gaps the axisymmetric model finds a gain of {r[5]:.2f} at {r[6]:.2f} of "
                  f"yield, an effective restitution of {r[4]:.3f} (contacts {'overlap' if r[3] == 'yes' else 'in sequence'}; "
                  f"test article at {r[5] * d.launch_speed / FTS:.0f} ft/s)")
    overlapping = [r for r in fe if r[3] == "yes"]
    sequenced_runs = [r for r in fe if r[3] != "yes"]
    if overlapping and sequenced_runs:
        lost, kept = max(r[5] for r in overlapping), max(r[5] for r in sequenced_runs)
        words += (f". Overlapping contacts {'lose' if lost < kept else 'do not lose'} gain against stages in "
                  f"sequence ({lost:.2f} against {kept:.2f})" + (": gaps that keep the stages in sequence recover "
                                                                  "it at the cost of machine length" if lost < kept else ""))
    rep.text("Reading: " + words + f"; the rigid chain at the assumed e = 0.9 / 0.8 / 0.75 gains "
             f"{runs[-3][5]:.2f} / {runs[-2][5]:.2f} / {runs[-1][5]:.2f}. The price of pads is their volume: each "
             "must store its stage's energy elastically.")
    return runs


def contacts_overlap(stages) -> bool:
    """Whether a contact begins before an earlier one has ended (dicts of the stage table)."""
    spans = sorted((st["start"], st["end"]) for st in stages if st["struck"] != "wall")
    return any(b[0] < a[1] for a, b in zip(spans, spans[1:]))


class ChainRuns:
    """The study's chain runs, each into ``out_dir/<name>``: its finite-element ones (every section's)
    run first, all together as one table on both cores (``cases.run_chain_cases``: ``cases.csv`` beside
    the report, ``--resume`` reads back completed ones), longest first so that both cores finish together;
    the rigid and 1d ones run in this process when a section asks for them (a fraction of a second each,
    where a process of their own would spend seconds starting)."""

    def __init__(self, cases: list[tuple[str, dict]], out_dir: str, echo):
        self.out_dir = out_dir
        fe = [(name, raw) for name, raw in cases if raw["chain"]["fidelity"] in ("axisymmetric", "3d")]
        fe.sort(key=lambda case: -_work(case[1]))
        self.table = run_chain_cases(fe, out_dir, echo) if fe else {}

    def run(self, name: str, raw: dict) -> tuple[dict | None, str | None]:
        """The chain's results (``summary.json``'s ``chain``) or None, and why it stopped."""
        if name in self.table:
            chain, _, status, diagnosis = self.table[name]
            return chain, None if chain else f"{status}: {diagnosis}"
        try:
            return run_chain_scene(raw, os.path.join(self.out_dir, name), progress=False, echo=lambda *a: None), None
        except UnstableRun as e:
            return None, f"unstable: {e.diagnosis}"


def _work(raw: dict) -> float:
    """A finite-element chain run's work, in proportion: its elements times its steps, (section area /
    h^2) x (end time / h) for bodies of steel alike (the step is h over the wave speed)."""
    end = raw["chain"].get("end_time") or default_end_time(raw)
    h = min(b["element_size"] for b in raw["bodies"])
    area = sum(b["radius"] * b["length"] for b in raw["bodies"])
    return area / h ** 2 * end / h * (2 * math.pi * max(b["radius"] for b in raw["bodies"]) / h
                                      if raw["chain"]["fidelity"] == "3d" else 1.0)


def run_study(size: str = "default", out_dir: str = "results/amplifier", echo=print) -> str:
    t0 = time.perf_counter()
    rep = Report(out_dir, "Velocity amplifier study (white paper task 3)")
    rep.text(f"`shockfem study amplifier --size {size}`; every number below was computed by this run.")
    echo("1/7 sizing claims (closed forms)")
    d = sizing_claims(rep)
    cases = [case[:2] for case in pair_cases(size) + design_cases(d, size) + design_cases(d, size, "stiffness")
             + design_cases(d, size, "none") + plate_cases(d, size) + padded_cases(d, size)]
    fe = sum(raw["chain"]["fidelity"] in ("axisymmetric", "3d") for _, raw in cases)
    echo(f"2/7 the finite-element chain runs of sections 2, 3, 5 and 6: {fe} cases as one table, both cores")
    runs = ChainRuns(cases, out_dir, echo)
    echo("3/7 restitution against frequency ratio (1d and axisymmetric pairs)")
    restitution_sweep(rep, size, runs)
    echo("4/7 the five-mass design at each fidelity")
    design_at_fidelities(rep, d, size, runs)
    echo("5/7 the white paper's diminishing rods (1d)")
    paper_rods(rep, size)
    echo("6/7 cylinders against thick plates (axisymmetric)")
    cylinders_vs_plates(rep, d, size, runs)
    echo("7/7 interfaces that keep the design elastic (pads; rigid, 1d, axisymmetric)")
    elastic_interfaces(rep, d, size, runs)
    return rep.finish(t0, echo)

"""Section 2: the white paper's screening design, a 2^(4-1) resolution IV fractional factorial (D = ABC)
on yaw, concrete strength, spin and impact velocity, plus a centre point, each run in 3D; at default size
its fold-over half too (D = -ABC), which with the first makes the full 2^4 and frees the two-factor
interactions from their aliases."""
from __future__ import annotations

import math

import numpy as np

from ...output.figures import pyplot
from ...metrics.flexure import station_travel, tail_flexure
from ...units import FT, to_si
from ..cases import run_cases
from ..doe import effect_columns, effects, fold_over, fractional_factorial, lenth, physical_coefficients, significant
from ...parts.catalog import ogive
from ...scene.library import initial_yield_stress
from ..fixture.common import ARTICLE, article_dims, article_length
from ..report import Report
from .common import KSI, MATERIAL, STATIONS, Context, event_end, shot_scene

# (name, letter, low, high, unit shown, SI per unit shown)
FACTORS = (("yaw", "A", 0.0, 4.0, "deg", 1.0), ("f'c", "B", 5.0, 10.0, "ksi", KSI),
           ("spin", "C", 0.0, 100.0, "rev/s", 2 * math.pi), ("velocity", "D", 1400.0, 1800.0, "ft/s", FT))
LETTERS = "".join(f[1] for f in FACTORS)
RESPONSES = (("tail deflection [mm]", "deflection"), ("bending stress [MPa]", "bending"),
             ("peak deceleration [g]", "deceleration"), ("depth [m]", "depth"))


def design_runs(centre_points: int, fold: bool) -> tuple[np.ndarray, list[str], list[list[float]]]:
    """The coded design (8 runs of D = ABC, the fold-over's 8 of D = -ABC if ``fold``, then the centre
    points), the runs' names and each run's levels in the units shown."""
    half = fractional_factorial("a b c abc")
    blocks = [half] + ([fold_over(half, 3)] if fold else []) + [np.zeros((centre_points, 4))]
    coded = np.vstack(blocks)
    names = ([f"doe_run{k + 1}" for k in range(8)] + ([f"doe_fold{k + 1}" for k in range(8)] if fold else [])
             + [f"doe_centre{k + 1}" for k in range(centre_points)])
    levels = [[0.5 * (lo + hi) + 0.5 * (hi - lo) * x for x, (_, _, lo, hi, _, _) in zip(row, FACTORS)]
              for row in coded]
    return coded, names, levels


def responses(fe, length: float) -> dict:
    """What a run answers: the tail's flexural deflection (``metrics.flexure`` on the stations' lateral
    x-y motion), the bending stress along the body (the sections' outer fibre, ``outputs.sections``;
    beside it the bending the stations' curvature reads), the axial deceleration's peak (rigid-body
    mean, CFC 1000), the depth, the friction torque, the tunnel's lateral push (tail slap)."""
    h, s = fe.history, fe.summary
    along = s["sections"]["projectile"]
    peak_slab = int(np.argmax(along["max_bending"]))
    t = h["time"]
    lateral = np.stack([np.column_stack([h[f"accelerometer.station{k}.v_{ax}"] for ax in "xy"])
                        for k in range(STATIONS)])
    deflection, bending = tail_flexure(station_travel(t, lateral), length, ARTICLE["radius"],
                                       to_si(MATERIAL["youngs_modulus"], "pressure"))
    push = np.hypot(h["contact.penetration.tunnel.normal_x"], h["contact.penetration.tunnel.normal_y"])
    torque = float(np.max(h["penetration.torque"]))
    return {"deflection": float(deflection.max()) * 1e3, "bending": max(along["max_bending"]) / 1e6,
            "bending_at": along["position"][peak_slab], "curvature_bending": float(bending.max()) / 1e6,
            "axial_compression": -min(along["max_axial_compression"]) / 1e6, "along": along,
            "deceleration": s["shock"]["channels"]["projectile"]["pulse"]["peak_g"],
            "depth": s["penetration"]["max_depth"], "torque": torque,
            "shear": 2 * torque / (math.pi * ARTICLE["radius"] ** 3) / 1e6, "tunnel_push": float(push.max()) / 1e3,
            "von_mises": s["bodies"]["projectile"]["max_von_mises"] / initial_yield_stress(ARTICLE["library"]),
            "curves": (t, deflection, bending)}


def screening(rep: Report, ctx: Context):
    rep.heading("2. Screening design: yaw, concrete strength, spin and velocity")
    fold = ctx.cfg["fold_over"]
    coded, names, levels = design_runs(ctx.cfg["centre_points"], fold)
    length = article_length()
    rows, results = [], []
    # the runs are independent: one table for the batch runner, as many at a time as there are cores
    scenes = []
    for name, lv in zip(names, levels):
        yaw, fc, spin, speed = (v * f[5] for v, f in zip(lv, FACTORS))
        ctx.echo(f"  {name}: {_label(lv)}")
        scenes.append((name, shot_scene(name, "3d", ctx.cfg["h_3d"], fc, speed, event_end(fc, speed, ctx.cfg),
                                        ctx.cfg["history"], yaw, spin, sections=ctx.cfg["sections"],
                                        curve_elements=ctx.cfg["curve_elements"])))
    factors = [{f"{f[0]} [{f[4]}]": v for f, v in zip(FACTORS, lv)} for lv in levels]
    for name, x, lv, (fe, wall, status) in zip(names, coded, levels, run_cases(scenes, ctx.out_dir, ctx.echo,
                                                                                factors)):
        r = responses(fe, length) if fe is not None else None
        results.append(r)
        rows.append([name] + [int(c) for c in x] + lv + [status]
                    + ([r["deflection"], r["bending"], r["bending_at"], r["curvature_bending"],
                        r["axial_compression"], r["deceleration"], r["depth"], r["shear"], r["tunnel_push"],
                        r["von_mises"], fe.summary["energy"]["balance_error"]] if r else [float("nan")] * 11)
                    + [wall])
    rep.table("doe_runs", ["run"] + list(LETTERS) + [f"{f[0]} [{f[4]}]" for f in FACTORS]
              + ["status", "tail deflection [mm]", "bending stress [MPa]", "where, from the nose tip [m]",
                 "bending from the stations' curvature [MPa]", "axial compression [MPa]", "peak deceleration [g]",
                 "depth [m]", "torsional shear 2T/(pi a^3) [MPa]", "tunnel's lateral push [kN]",
                 "von Mises / yield [-]", "energy balance [-]", "wall [s]"], rows,
              ["{}"] * 5 + ["{:g}"] * 4 + ["{}", "{:.3f}", "{:.1f}", "{:.3f}", "{:.1f}", "{:.0f}", "{:.0f}", "{:.3f}",
                                          "{:.1f}", "{:.1f}", "{:.2f}", "{:.1e}", "{:.0f}"])
    factorial = results[:8]
    if any(r is None for r in factorial):
        rep.text("A run of the fractional design did not complete: no regression.")
        return
    centres = results[16:] if fold else results[8:]
    _analysis(rep, coded[:8], factorial, centres)
    _doe_figure(rep, factorial, levels)
    _along_figure(rep, factorial, levels, length)
    worst = max(range(8), key=lambda k: factorial[k]["bending"])
    rep.run_pictures(names[worst], f"The design's run of the largest bending stress, {names[worst]} "
                     f"({_label(levels[worst])}),", "the 3D article; the concrete is the load on the nose, not a mesh")
    if fold:
        if any(r is None for r in results[8:16]):
            rep.text("A run of the fold-over half did not complete: the interactions stay aliased.")
            return
        _full_factorial(rep, coded[:16], results[:16])


def _analysis(rep: Report, coded: np.ndarray, runs: list[dict], centres: list[dict]):
    columns = effect_columns(coded, LETTERS)
    rows, models = [], []
    verdicts = {}
    for label, key in RESPONSES:
        y = np.array([r[key] for r in runs])
        e = effects(columns, y)
        pse, margin = lenth(e.values())
        flagged = [n for n, v in e.items() if significant(v, margin)]
        verdicts[key] = (e, margin, flagged)
        curvature = float(np.mean([c[key] for c in centres if c]) - y.mean()) if any(centres) else float("nan")
        rows.append([label, float(y.mean())] + [e[n] for n in columns] + [margin, ", ".join(flagged) or "none",
                                                                          curvature])
        coded_b = {n: e[n] / 2 for n in LETTERS}
        c0, slopes = physical_coefficients(coded_b, float(y.mean()), [0.5 * (f[2] + f[3]) for f in FACTORS],
                                           [0.5 * (f[3] - f[2]) for f in FACTORS], LETTERS)
        models.append(f"- {label} = {y.mean():.4g} " + " ".join(f"{b:+.4g} x_{n}" for n, b in coded_b.items())
                      + f" (coded); = {c0:.4g} " + " ".join(f"{slopes[n]:+.4g} {f[0]}[{f[4]}]"
                                                              for n, f in zip(LETTERS, FACTORS)) + " (physical)")
    rep.table("doe_effects", ["response", "mean"] + [f"effect {n}" for n in columns]
              + ["Lenth margin (95%)", "significant", "centre - factorial mean"], rows,
              ["{}"] + ["{:.4g}"] * (len(columns) + 2) + ["{}", "{:.4g}"])
    rep.text("Main-effect models (coded x = -1 .. +1 over the levels; physical in the units shown; the two-factor "
             "columns are left out of them):", "\n".join(models))
    # at zero yaw a body of revolution has nothing to bend it: what those runs read is the measure's floor
    # (a tetrahedral mesh is not quite balanced, and a section's centroid not quite on the axis, so a
    # spinning one circles)
    floor = [(r["deflection"], r["bending"], x[2]) for r, x in zip(runs, coded) if x[0] < 0]
    spun = [f for f in floor if f[2] > 0] or floor
    rep.value("zero_yaw_floor_deflection_mm", max(f[0] for f in spun))
    rep.value("zero_yaw_floor_bending_mpa", max(f[1] for f in spun))
    e_b, margin_b, flagged_b = verdicts["bending"]
    e_d, margin_d, flagged_d = verdicts["deflection"]
    spin_bending = rep.value("spin_effect_on_bending_mpa", e_b["C"])
    rep.value("spin_effect_on_deflection_mm", e_d["C"])
    shear = max(r["shear"] for r, x in zip(runs, coded) if x[2] > 0)
    rolled = max(r["shear"] for r, x in zip(runs, coded) if x[2] < 0)       # unspun: what the yaw sets rolling
    bending = max(r["bending"] for r in runs)
    yield_mpa = initial_yield_stress(ARTICLE["library"]) / 1e6
    rep.text(
        "Design: 2^(4-1) with D = ABC (I = ABCD, resolution IV): main effects are clear of two-factor interactions "
        "but the interactions are aliased in pairs, AB = CD, AC = BD, AD = BC; so the yaw x spin column (AC) is the "
        "concrete strength x velocity one (BD) too, and a large AC effect cannot be told from BD without the "
        "fold-over half (the other 8 runs, D = -ABC; run at default size, below). A simulation repeats itself exactly, so centre points give no "
        "error estimate; the centre run tells curvature (its response less the factorial mean, the last column: a "
        "straight-line model predicts zero), and significance comes from Lenth's pseudo standard error of the 7 "
        "effects (margin of error t(0.975, 7/3) PSE).",
        f"Spin against bending: the spin's effect on the bending stress is {spin_bending:+.3g} MPa over 0 -> "
        f"{FACTORS[2][3]:g} rev/s (Lenth margin {margin_b:.3g} MPa: "
        f"{'significant' if 'C' in flagged_b else 'not significant'}); on the tail deflection {e_d['C']:+.3g} mm "
        f"(margin {margin_d:.3g} mm: {'significant' if 'C' in flagged_d else 'not significant'}): "
        + ("spin matters to the bending. " if "C" in flagged_b or "C" in flagged_d else
           "spin does not measurably change the bending. ")
        + f"Torsion is another matter: the friction torque mu F a / 2, which acts while the article spins, puts up "
        f"to {shear:.0f} MPa of torsional shear on the nose's section (2T / pi a^3, the torque taken whole there; "
        f"sqrt(3) tau = {math.sqrt(3) * shear:.0f} MPa of von Mises, {math.sqrt(3) * shear / yield_mpa:.2f} of the "
        f"4340's yield), against bending stresses up to {bending:.0f} MPa; unspun, up to {rolled:.0f} MPa (a yawed "
        "article is set rolling about its axis, and friction resists that too): a test that leaves out spin leaves "
        "out most of that torsion, not the bending."
        + f" At zero yaw nothing bends a body of revolution: the unyawed runs read at most "
        f"{max(f[0] for f in spun):.3g} mm and {max(f[1] for f in spun):.3g} MPa with spin "
        f"({max(f[0] for f in floor if f[2] < 0):.3g} mm, {max(f[1] for f in floor if f[2] < 0):.3g} MPa without): "
        "the measure's floor (the stations are cross-sections centred on the axis; a tetrahedral mesh is still "
        "not quite a body of revolution), below which no effect above means anything.")


def _label(levels: list[float]) -> str:
    """A run's levels in the units shown."""
    return ", ".join(f"{name} {v:g} {unit}" for v, (name, _, _, _, unit, _) in zip(levels, FACTORS))


def _doe_figure(rep: Report, runs: list[dict], levels: list[list[float]]):
    series = [(_label(lv), r["curves"][0] * 1e3, r["curves"][1] * 1e3, r["curves"][2] / 1e6, "-")
              for r, lv in zip(runs, levels)]
    _runs_figure(rep, "doe.png", "the eight runs of the fractional design: the tail's flexural deflection and the "
                 "bending stress", series, ("tail deflection [mm]", "bending stress [MPa]"), "time [ms]")


def _along_figure(rep: Report, runs: list[dict], levels: list[list[float]], length: float):
    series = [(_label(lv), np.array(r["along"]["position"]) * 1e3, np.array(r["along"]["max_bending"]) / 1e6,
               -np.array(r["along"]["max_axial_compression"]) / 1e6, "o-") for r, lv in zip(runs, levels)]
    _, nose = ogive(article_dims(length))
    _runs_figure(rep, "doe_along_body.png", "the stress along the body: each run's largest bending stress (outer "
                 "fibre) and axial compression at each section over the event (`outputs.sections`)", series,
                 ("largest bending stress [MPa]", "largest axial compression [MPa]"),
                 "distance from the nose tip along the axis [mm] (dotted: the nose meets the shank)", mark=nose * 1e3)


def _runs_figure(rep: Report, filename: str, caption: str, series, ylabels, xlabel: str, mark: float | None = None):
    """Two panels sharing x, a line per run in each: series of (label, x, upper y, lower y, style)."""
    plt = pyplot()
    fig, axes = plt.subplots(2, 1, figsize=(7, 7), sharex=True)
    for label, x, upper, lower, style in series:
        axes[0].plot(x, upper, style, ms=3, label=label)
        axes[1].plot(x, lower, style, ms=3)
    for ax, ylabel in zip(axes, ylabels):
        ax.set_ylabel(ylabel)
        if mark is not None:
            ax.axvline(mark, color="k", lw=0.8, ls=":")
    axes[1].set_xlabel(xlabel)
    axes[0].legend(fontsize=7)
    rep.figure(filename, caption, fig)


def _full_factorial(rep: Report, coded: np.ndarray, runs: list[dict]):
    """The two halves together: the full 2^4, every effect estimated clear of the others."""
    columns = effect_columns(coded, LETTERS, order=4)
    shown = [n for n in columns if len(n) <= 2]
    rows, interaction = [], {}
    for label, key in RESPONSES:
        y = np.array([r[key] for r in runs])
        e = effects(columns, y)
        _, margin = lenth(e.values())
        flagged = [n for n, v in e.items() if significant(v, margin)]
        interaction[key] = (e["AC"], e["BD"], margin)
        rows.append([label, float(y.mean())] + [e[n] for n in shown] + [margin, ", ".join(flagged) or "none"])
    rep.table("doe_full_effects", ["response", "mean"] + [f"effect {n}" for n in shown]
              + ["Lenth margin (95%, 15 effects)", "significant (of all 15)"], rows,
              ["{}"] + ["{:.4g}"] * (len(shown) + 2) + ["{}"])
    for key, (ac, bd, margin) in interaction.items():
        rep.value(f"full_factorial_{key}_yaw_x_spin", ac)
        rep.value(f"full_factorial_{key}_fc_x_velocity", bd)
    lines = [f"- {label}: yaw x spin (AC) {interaction[key][0]:+.4g}, f'c x velocity (BD) {interaction[key][1]:+.4g} "
             f"(margin {interaction[key][2]:.3g}; the half fraction read their sum)" for label, key in RESPONSES]
    rep.text("The fold-over half (D = -ABC) with the first is the full 2^4 factorial: the 15 effects (main, "
             "two-, three- and four-factor) are estimated each clear of the others, and Lenth's margin now rests "
             "on 15 of them. The aliased pair of the half fraction, separated:", "\n".join(lines))

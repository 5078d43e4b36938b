"""Section 3: dynamic stress amplification, the peak stress a force pulse puts in the article over the
quasi-static stress of the same force, against the pulse's duration over the article's own periods: an
axial pulse on the nose (axisymmetric) against the first axial period, a lateral one (3D, the load a yawed
nose takes) against the first bending period."""
from __future__ import annotations

import math

import numpy as np

from ...geometry import build_mesh
from ...modal.eigen import body_modes
from ...modal.labels import firsts, label_modes
from ...model import build_model
from ...output.figures import pyplot
from ...metrics.flexure import inertia_relief_moment
from ...metrics.srs import shock_response_spectrum
from ...output.sections import SectionStresses
from ...parts.catalog import PARTS, ogive
from ...scene import resolve
from ...solver.explicit import ExplicitSolver
from ..fixture.common import ARTICLE, DURATION, article_dims, article_length
from ..report import Report
from .common import Context, projectile_mass, shot_scene

# the amplification a test may add and still load the article like a slow pulse
QUASI_STATIC = 1.10          # a pulse whose peak stress is within 10% of the quasi-static loads like a slow one


def article_periods(ctx: Context) -> dict:
    """The article's first free-free frequencies by kind (3D tetrahedra, ``modal``)."""
    raw = shot_scene("article_modes", "3d", ctx.cfg["h_3d"], 35e6, 0.0, 1e-6, 1e-6)
    raw.pop("penetration")
    raw["shock"].pop("accelerometers")
    scene = resolve(raw)
    meshed = build_mesh(scene, log=lambda *a: None, cache_dir=ctx.out_dir)
    modes = body_modes(scene, meshed, "projectile", count=8, constrained=False)
    return firsts(label_modes(modes, meshed.cell_tags.find(1)), modes.frequencies)


def junction_stress(ctx: Context, force: float, duration: float, end: float) -> tuple[float, float]:
    """The largest axial stress over the section where the nose meets the shank (mean over its slab of
    cells, axisymmetric, elastic) under a half-sine force ``force`` of ``duration`` on the nose, and the
    quasi-static stress of that force there: F m_behind / (m A), the section carrying what lies behind
    it as a rigid body decelerates."""
    model, solver = _pulse_run(ctx, "axisymmetric", "z", force, duration, end)
    _, nose = ogive(article_dims())
    centres = model.X0[model.dofmap[model.kernel_cells]].mean(axis=1)
    slab = np.abs(centres[:, 1] - 1e-4 - nose) < 0.6 * ctx.cfg["h_axi"]      # (the tip starts 0.1 mm up)
    weights = centres[slab, 0]                  # the section's rings: 2 pi r dr
    peak = 0.0
    for _ in solver.steps(end):
        stress = float(np.average(solver.sigma[model.kernel_cells[slab], :, 1].mean(axis=1), weights=weights))
        peak = max(peak, abs(stress))
    behind = projectile_mass() - _nose_mass()
    return peak, force * behind / (projectile_mass() * math.pi * ARTICLE["radius"] ** 2)


def lateral_bending(ctx: Context, force: float, duration: float, end: float) -> tuple[float, float, float]:
    """The largest bending stress along the article (``outputs.sections``, 3D, elastic) under a half-sine
    lateral force ``force`` of ``duration`` spread over its nose, and the quasi-static bending stress of
    that force: the free body's inertia relief (``metrics.flexure.inertia_relief_moment`` on the mesh's
    own masses) over each section's modulus I / R; and where along the body that peaks [m from the tip]."""
    model, solver = _pulse_run(ctx, "3d", "x", force, duration, end)
    sections = SectionStresses(solver, model.sections[0])
    for step in solver.steps(end):
        if step.step % 4 == 0:
            sections.record()
    sections.record()
    nodes = np.flatnonzero(model.node_body == 0)
    load = model.loads[0]
    tip = model.X0[nodes, 2].min()
    at = float(load.shares @ model.X0[load.dofs // 3, 2]) - tip          # the force's line of action
    moment = inertia_relief_moment(model.X0[nodes, 2] - tip, model.X0[nodes, 0], model.mass[nodes], force, at,
                                   sections.positions)
    quasi = moment * sections.radius / sections.second_moment
    k = int(np.argmax(quasi))
    return float(sections.max_bending.max()), float(quasi[k]), float(sections.positions[k])


def _pulse_run(ctx: Context, kinematics: str, direction: str, force: float, duration: float, end: float):
    """The article at rest, elastic and free, under a half-sine force of ``duration`` spread over its nose
    along ``direction``: its model and solver, ready to step to ``end``."""
    raw = shot_scene(f"pulse_{direction}", kinematics, ctx.cfg["h_axi" if kinematics == "axisymmetric" else "h_3d"],
                     35e6, 0.0, end, end, sections=ctx.cfg["sections"])
    raw.pop("penetration")
    raw["shock"].pop("accelerometers")
    raw["bodies"][0]["velocity"] = [0.0] * len(raw["bodies"][0]["velocity"])
    samples = np.linspace(0.0, duration, 41)
    raw["boundary"] = [{"region": "projectile.nose", "type": "force", "direction": direction,
                        "history": [[float(t), float(force * math.sin(math.pi * t / duration))] for t in samples]
                        + [[duration * 1.0001, 0.0], [end, 0.0]]}]
    scene = resolve(raw)
    model = build_model(scene, build_mesh(scene, log=lambda *a: None, cache_dir=ctx.out_dir))
    return model, ExplicitSolver(model)


def _nose_mass() -> float:
    """The ogive's share of the article's mass (the catalogue's volumes)."""
    d = article_dims(article_length())
    _, nose = ogive(d)
    full = PARTS["projectile"].volume(d, 2)
    shank = math.pi * d["radius"] ** 2 * (d["length"] - nose)
    return projectile_mass() * (full - shank) / full


def amplification(rep: Report, ctx: Context):
    rep.heading("3. Dynamic stress amplification")
    f = article_periods(ctx)
    f_axial, f_bending = f.get("longitudinal", float("nan")), f.get("bending", float("nan"))
    T_axial, T_bending = 1 / f_axial, 1 / f_bending
    rep.value("first_axial_hz", f_axial)
    rep.value("first_bending_hz", f_bending)
    force = 1e6
    rows, ratios, dafs, sdofs = [], [], [], []
    for ratio in ctx.cfg["duration_ratios"]:
        duration = ratio * T_axial
        peak, quasi = junction_stress(ctx, force, duration, duration + 1.5 * T_axial)
        sdof = _one_mode(duration, f_axial)
        rows.append([ratio, duration * 1e3, duration / T_bending, peak / 1e6, quasi / 1e6, peak / quasi, sdof])
        ratios.append(ratio)
        dafs.append(peak / quasi)
        sdofs.append(sdof)
    rep.table("amplification", ["duration / axial period [-]", "duration [ms]", "duration / bending period [-]",
                                "peak stress [MPa]", "quasi-static stress [MPa]", "amplification [-]",
                                "one-mode (SDOF) amplification [-]"], rows,
              ["{:g}", "{:.4f}", "{:.3f}", "{:.1f}", "{:.1f}", "{:.3f}", "{:.3f}"])
    shortest_quasi = _shortest_quasi_static(ratios, dafs)
    rep.value("shortest_quasi_static_duration_ms", shortest_quasi * T_axial * 1e3)
    rep.text(
        f"The article's first free-free modes (3D tetrahedra, `shockfem modes`): axial {f_axial:,.0f} Hz "
        f"(period {T_axial * 1e3:.4f} ms), bending {f_bending:,.0f} Hz (period {T_bending * 1e3:.4f} ms). A "
        "half-sine force of 1 MN on the nose, axisymmetric and elastic, each duration a run; the stress is the "
        "mean axial stress over the section where the nose meets the shank, against the quasi-static stress of "
        "the same force there, F m_behind / (m A) (the shank carrying what lies behind it as the body "
        "decelerates rigidly). The one-mode column is the undamped shock spectrum of the same half-sine at the "
        "axial frequency (`metrics.srs`, Q infinite): the article as its first axial mode.",
        f"Pulses of {shortest_quasi:g} axial periods and longer "
        f"({shortest_quasi * T_axial * 1e3:.3f} ms) stay within {QUASI_STATIC - 1:.0%} of the quasi-static stress: "
        "shorter pulses amplify it (the shortest event that reproduces a given damage without overstating it "
        f"is about that long); the specification's {DURATION * 1e3:g} ms is "
        f"{DURATION / T_axial:.0f} axial periods, quasi-static for the article's axial modes, and "
        f"{DURATION / T_bending:.0f} bending periods."
        + "".join(f" The {name} shot's force rises over the crater in {rise * 1e3:.3f} ms, {rise / T_axial:.1f} "
                  "axial periods." for name, rise in _crater_rises(ctx).items()))
    bending = _bending(rep, ctx, f_bending)
    _figure(rep, ratios, dafs, sdofs, bending)


def _one_mode(duration: float, frequency: float) -> float:
    """The undamped shock spectrum of a unit half-sine of ``duration`` at ``frequency``: the largest
    response of one mode over its static response (``metrics.srs``, Q infinite)."""
    dt = duration / 400
    t = np.arange(0.0, duration + 3 / frequency, dt)
    pulse = np.where(t <= duration, np.sin(math.pi * t / duration), 0.0)
    return float(shock_response_spectrum(pulse, dt, [frequency], q=math.inf).maximax[0])


def _shortest_quasi_static(ratios: list[float], amplifications: list[float]) -> float:
    """The shortest duration ratio past the longest amplified one (above ``QUASI_STATIC``) whose
    amplification is within it (nan if none)."""
    longest_amplified = max((r for r, a in zip(ratios, amplifications) if a > QUASI_STATIC), default=float("nan"))
    return min((r for r, a in zip(ratios, amplifications) if r > longest_amplified and a <= QUASI_STATIC),
               default=float("nan"))


def _crater_rises(ctx: Context) -> dict:
    """Section 1's shots: the time their force took to rise over the crater, strike to tunnel [s]."""
    out = {}
    for name, (fe, _) in ctx.shots.items():
        pen = fe.summary["penetration"]
        if pen["tunnel_time"] is not None:
            out[name] = pen["tunnel_time"] - pen["strike_time"]
    return out


def _bending(rep: Report, ctx: Context, f_bending: float) -> tuple[list, list, list]:
    """The lateral pulses: bending amplification against the duration over the first bending period."""
    T = 1 / f_bending
    force = 1e3              # small: the body turns by well under a degree over the longest run
    rows, ratios, dafs, sdofs = [], [], [], []
    for ratio in ctx.cfg["bending_ratios"]:
        duration = ratio * T
        peak, quasi, where = lateral_bending(ctx, force, duration, duration + 1.5 * T)
        sdof = _one_mode(duration, f_bending)
        rows.append([ratio, duration * 1e3, peak / 1e6, quasi / 1e6, where * 1e3, peak / quasi, sdof])
        ratios.append(ratio)
        dafs.append(peak / quasi)
        sdofs.append(sdof)
    rep.table("bending_amplification", ["duration / bending period [-]", "duration [ms]",
                                        "peak bending stress, FE [MPa]", "quasi-static bending stress [MPa]",
                                        "quasi-static peak, from the tip [mm]", "amplification [-]",
                                        "one-mode (SDOF) amplification [-]"], rows,
              ["{:g}", "{:.4f}", "{:.3f}", "{:.3f}", "{:.0f}", "{:.3f}", "{:.3f}"])
    shortest_quasi = _shortest_quasi_static(ratios, dafs)
    rep.value("bending_peak_amplification", max(dafs))
    rep.value("bending_shortest_quasi_static_duration_ms", shortest_quasi * T * 1e3)
    worst = ratios[int(np.argmax(dafs))]
    rep.text(
        f"A lateral half-sine force of {force / 1e3:g} kN spread over the nose (3D tetrahedra, elastic, the article "
        "free): the largest bending stress along the body (`outputs.sections`, outer fibre, over the run) against "
        "the quasi-static bending of the same force, the free article's inertia relief (its rigid-body "
        "acceleration and turn under the force, the d'Alembert moment across each section from the mesh's own "
        "masses, `metrics.flexure.inertia_relief_moment`, over the section's I / R). The largest amplification, "
        f"{max(dafs):.2f}, comes at a pulse of {worst:g} bending period{'' if worst == 1 else 's'} (one-mode shock "
        f"spectrum {sdofs[ratios.index(worst)]:.2f}); "
        + (f"from {shortest_quasi:g} bending periods ({shortest_quasi * T * 1e3:.3f} ms) on, the bending stays within "
           f"{QUASI_STATIC - 1:.0%} of quasi-static."
           if math.isfinite(shortest_quasi) else
           f"no pulse run here stays within {QUASI_STATIC - 1:.0%} of quasi-static after the last amplified one.")
        + f" A lateral load on a yawed nose builds over the tunnel's force rise: "
          f"the specification's {DURATION * 1e3:g} ms is {DURATION * f_bending:.0f} bending periods.")
    return ratios, dafs, sdofs


def _figure(rep: Report, ratios, dafs, sdofs, bending):
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7, 4))
    ax.semilogx(ratios, dafs, "o-", label="axial: finite elements, nose-shank section")
    ax.semilogx(ratios, sdofs, "s--", label="axial: first axial mode alone (SDOF shock spectrum)")
    b_ratios, b_dafs, b_sdofs = bending
    ax.semilogx(b_ratios, b_dafs, "^-", label="bending: finite elements, largest along the body")
    ax.semilogx(b_ratios, b_sdofs, "v--", label="bending: first bending mode alone (SDOF)")
    ax.axhline(QUASI_STATIC, color="k", lw=0.8, ls=":", label=f"quasi-static + {QUASI_STATIC - 1:.0%}")
    ax.set_xlabel("pulse duration / the first period of its kind (axial or bending) [-]")
    ax.set_ylabel("peak stress / quasi-static stress [-]")
    ax.legend(fontsize=8)
    rep.figure("amplification.png", "dynamic stress amplification against the half-sine force's duration, axial "
               "and lateral", fig)

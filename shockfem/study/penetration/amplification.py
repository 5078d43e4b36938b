"""Section 3: dynamic stress amplification, the peak stress a force pulse puts in the article over the
quasi-static stress of the same force, against the pulse's duration over the article's own periods."""
from __future__ import annotations

import math

import numpy as np

from ...geometry import build_mesh
from ...modal.eigen import body_modes
from ...modal.labels import firsts, label_modes
from ...model import build_model
from ...output.figures import pyplot
from ...metrics.srs import shock_response_spectrum
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
    raw = shot_scene("amplification", "axisymmetric", ctx.cfg["h_axi"], 35e6, 0.0, end, end)
    raw.pop("penetration")
    raw["shock"].pop("accelerometers")
    raw["bodies"][0]["velocity"] = [0.0, 0.0]
    samples = np.linspace(0.0, duration, 41)
    raw["boundary"] = [{"region": "projectile.nose", "type": "force", "direction": "z",
                        "history": [[float(t), float(force * math.sin(math.pi * t / duration))] for t in samples]
                        + [[duration * 1.0001, 0.0], [end, 0.0]]}]
    scene = resolve(raw)
    model = build_model(scene, build_mesh(scene, log=lambda *a: None, cache_dir=ctx.out_dir))
    solver = ExplicitSolver(model)
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
        dt = duration / 400
        t = np.arange(0.0, duration + 3 * T_axial, dt)
        pulse = np.where(t <= duration, np.sin(math.pi * t / duration), 0.0)
        sdof = float(shock_response_spectrum(pulse, dt, [f_axial], q=math.inf).maximax[0])
        rows.append([ratio, duration * 1e3, duration / T_bending, peak / 1e6, quasi / 1e6, peak / quasi, sdof])
        ratios.append(ratio)
        dafs.append(peak / quasi)
        sdofs.append(sdof)
    rep.table("amplification", ["duration / axial period [-]", "duration [ms]", "duration / bending period [-]",
                                "peak stress [MPa]", "quasi-static stress [MPa]", "amplification [-]",
                                "one-mode (SDOF) amplification [-]"], rows,
              ["{:g}", "{:.4f}", "{:.3f}", "{:.1f}", "{:.1f}", "{:.3f}", "{:.3f}"])
    longest_amplified = max((r for r, a in zip(ratios, dafs) if a > QUASI_STATIC), default=float("nan"))
    shortest_quasi = min((r for r, a in zip(ratios, dafs) if r > longest_amplified and a <= QUASI_STATIC),
                         default=float("nan"))
    rep.value("shortest_quasi_static_duration_ms", shortest_quasi * T_axial * 1e3)
    _figure(rep, ratios, dafs, sdofs)
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
        f"{DURATION / T_bending:.0f} bending periods. Bending amplification (a lateral force pulse in 3D) is not "
        "run here."
        + "".join(f" The {name} shot's force rises over the crater in {rise * 1e3:.3f} ms, {rise / T_axial:.1f} "
                  "axial periods." for name, rise in _crater_rises(ctx).items()))


def _crater_rises(ctx: Context) -> dict:
    """Section 1's shots: the time their force took to rise over the crater, strike to tunnel [s]."""
    out = {}
    for name, (fe, _) in ctx.shots.items():
        pen = fe.summary["penetration"]
        if pen["tunnel_time"] is not None:
            out[name] = pen["tunnel_time"] - pen["strike_time"]
    return out


def _figure(rep: Report, ratios, dafs, sdofs):
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7, 4))
    ax.semilogx(ratios, dafs, "o-", label="finite elements, nose-shank section")
    ax.semilogx(ratios, sdofs, "s--", label="first axial mode alone (SDOF shock spectrum)")
    ax.axhline(QUASI_STATIC, color="k", lw=0.8, ls=":", label=f"quasi-static + {QUASI_STATIC - 1:.0%}")
    ax.set_xlabel("pulse duration / first axial period [-]")
    ax.set_ylabel("peak stress / quasi-static stress [-]")
    ax.legend(fontsize=8)
    rep.figure("amplification.png", "dynamic stress amplification against the half-sine force's duration", fig)

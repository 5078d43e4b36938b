"""The machine's top-level drawing: one sheet (SVG, PDF, PNG) with three views and an isometric of the
assembly, its main dimensions and a parts list with masses and materials.

The views are drawn from the layout's components, each a solid of revolution on the machine's axis
(cylinders, tubes, the tank's capsule, the article's ogive) or a box (rails, frame): side elevation and
plan show their outlines (bores dashed), the end view their circles, the isometric their end ellipses and
silhouettes.  Dimensions are in millimetres; the SVG keeps its text as text, so a reader (or a test)
finds the dimension values in it.
"""
from __future__ import annotations

import math
import os

import numpy as np

from ..output.figures import partial_path, pyplot
from ..parts.catalog import PARTS, solid_ogive
from ..units import G0, LB
from .layout import rail_geometry
from .spec import REFERENCE_ARTICLE

SHEET = (16.54, 11.69)               # A3 landscape [in]
COLOURS = {"tank": "#9db4c0", "barrel": "#9db4c0", "mass": "#c2c5cc", "pad": "#e0b04a", "housing": "#8fa7c7",
           "oil": "#d9c27a", "pin": "#8fa7c7", "piston": "#8fa7c7", "article": "#c0504d", "stop": "#7f7f7f", "rail": "#5b6770",
           "frame": "#3d4a52"}
AXIAL_KINDS = ("tank", "barrel", "mass", "pad", "housing", "oil", "pin", "piston", "article", "stop")


def _ogive_outline(it):
    """The article's (z, r) outline, base at its rear, nose forward."""
    R = it.diameter / 2
    dims = solid_ogive(R, REFERENCE_ARTICLE["crh"], REFERENCE_ARTICLE["meplat_over_radius"] * R, it.length)
    pts = []
    for seg in PARTS["projectile"].profile(dims).outline:
        pts += list(_segment_points(seg))
    r = np.array([p[0] for p in pts])
    z = it.length - np.array([p[1] for p in pts])          # turned end over end: the nose forward
    return it.x0 + z, r


def _segment_points(seg, n=24):
    if hasattr(seg, "centre"):
        (r0, z0), (r1, z1), (rc, zc) = seg.start, seg.end, seg.centre
        a0, a1 = math.atan2(z0 - zc, r0 - rc), math.atan2(z1 - zc, r1 - rc)
        if a1 - a0 > math.pi:          # the arc is shorter than a half turn: go the short way round
            a1 -= 2 * math.pi
        elif a0 - a1 > math.pi:
            a1 += 2 * math.pi
        rad = math.hypot(r0 - rc, z0 - zc)
        for a in np.linspace(a0, a1, n):
            yield rc + rad * math.cos(a), zc + rad * math.sin(a)
    else:
        yield seg.start
        yield seg.end


def _outline(ax, it, s, lateral=False):
    """One component in side elevation (or plan), the axis horizontal, scale s [drawing units per m]."""
    c = COLOURS.get(it.kind, "0.6")
    if it.kind == "article":
        z, r = _ogive_outline(it)
        ax.fill(np.concatenate([z, z[::-1]]) * s, np.concatenate([r, -r[::-1]]) * s, color=c, lw=0.4, ec="k")
        return
    if it.kind == "rail":
        h, xs, y = rail_geometry(it.diameter)
        for x in xs:
            lo = x if lateral else y
            ax.add_patch(_rect(it.x0 * s, lo * s, it.length * s, h * s, c))
        return
    if it.kind == "frame":
        return
    R = it.diameter / 2
    ax.add_patch(_rect(it.x0 * s, -R * s, it.length * s, 2 * R * s, c))
    if it.inner:
        for y in (-it.inner / 2, it.inner / 2):
            ax.plot([it.x0 * s, (it.x0 + it.length) * s], [y * s, y * s], "k--", lw=0.4)


def _rect(x, y, w, h, colour):
    from matplotlib.patches import Rectangle
    return Rectangle((x, y), w, h, fc=colour, ec="k", lw=0.4)


def _dimension(ax, x0, x1, y, text, s, vertical=False):
    """A dimension line with arrows between x0 and x1 [m] at y [m], its value written on it."""
    kw = dict(arrowprops=dict(arrowstyle="<->", lw=0.6), annotation_clip=False)
    if vertical:
        ax.annotate("", (y * s, x0 * s), (y * s, x1 * s), **kw)
        ax.text(y * s, (x0 + x1) / 2 * s, text, rotation=90, ha="right", va="center", fontsize=6)
    else:
        ax.annotate("", (x0 * s, y * s), (x1 * s, y * s), **kw)
        ax.text((x0 + x1) / 2 * s, y * s, text, ha="center", va="bottom", fontsize=6)


def _mm(x: float) -> str:
    return f"{x * 1000:.0f}"


def _side(ax, machine, lateral):
    lay = machine.layout
    s = 1.0
    for it in lay.items:
        _outline(ax, it, s, lateral)
    W = lay.overall_width
    a = math.sqrt(lay.frame_section)
    for side in ((-W / 2 - a, W / 2) if lateral else (-W / 2 - a,)):
        ax.add_patch(_rect(0, side, lay.overall_length, a, COLOURS["frame"]))
    ax.axhline(0, color="k", lw=0.3, ls="-.")
    ax.set_aspect("equal")
    ax.axis("off")
    return s


def draw_sheet(machine, path_stem: str) -> list[str]:
    """Write ``<stem>.svg``, ``.pdf`` and ``.png``; returns the paths."""
    plt = pyplot()
    import matplotlib
    matplotlib.rcParams["svg.fonttype"] = "none"          # text stays text in the SVG
    lay, spec, f = machine.layout, machine.spec, machine.fixture
    items = {it.name: it for it in lay.items}
    fig = plt.figure(figsize=SHEET)
    side = fig.add_axes([0.03, 0.70, 0.94, 0.22])
    plan = fig.add_axes([0.03, 0.47, 0.94, 0.20])
    end = fig.add_axes([0.03, 0.05, 0.18, 0.36])
    iso = fig.add_axes([0.23, 0.05, 0.30, 0.36])
    table = fig.add_axes([0.55, 0.02, 0.44, 0.43])
    s = _side(side, machine, lateral=False)
    side.set_title("side elevation (machine axis horizontal; dimensions in mm)", fontsize=8, loc="left", pad=28)
    W, L = lay.overall_width, lay.overall_length
    low = -W / 2 - 2.5 * math.sqrt(lay.frame_section)
    _dimension(side, 0.0, L, low - 0.25 * W, f"overall length {_mm(L)}", s)
    tank, barrel, catcher = items["tank"], items["barrel"], items["catcher"]
    top = W / 2 + 0.12 * W
    _dimension(side, tank.x0, tank.x0 + tank.length, top, f"tank {_mm(tank.length)}", s)
    _dimension(side, barrel.x0, barrel.x0 + barrel.length, top, f"barrel {_mm(barrel.length)}", s)
    first_pad = next(it for it in lay.items if it.kind == "pad")
    mouth = items["striker"].x0 + items["striker"].length
    _dimension(side, first_pad.x0, mouth, top, f"amplifier {_mm(mouth - first_pad.x0)}", s)
    _dimension(side, mouth, catcher.x0 + catcher.length, top,
               f"fixture and arrest {_mm(catcher.x0 + catcher.length - mouth)}", s)
    _dimension(side, -W / 2, W / 2, -0.02 * L, f"{_mm(W)}", s, vertical=True)
    side.set_xlim(-0.05 * L, 1.01 * L)
    _side(plan, machine, lateral=True)
    plan.set_title("plan (rails and frame side members either side of the axis)", fontsize=8, loc="left")
    plan.set_xlim(-0.05 * L, 1.01 * L)
    _end_view(end, machine)
    _isometric(iso, machine)
    _parts_list(table, machine)
    g = machine.launcher.design.gun
    fig.suptitle(f"shockfem: shock tester for a {spec.article_mass / LB:.4g} lb article, {spec.pulse.shape} "
                 f"{spec.pulse.peak / G0:,.0f} g for {spec.pulse.duration * 1e3:g} ms - bore {_mm(g.bore)} mm, "
                 f"reservoir {g.reservoir_pressure / 1e6:.3g} MPa, striker {f.striker_mass:.4g} kg at "
                 f"{f.striker_speed:.0f} m/s, total {machine.totals['machine_mass']:,.0f} kg",
                 fontsize=10, x=0.03, ha="left")
    paths = []
    for ext in ("svg", "pdf", "png"):
        path = f"{path_stem}.{ext}"
        partial = partial_path(path)
        fig.savefig(partial, format=ext, dpi=150)
        os.replace(partial, path)
        paths.append(path)
    plt.close(fig)
    return paths


def _end_view(ax, machine):
    """Looking back along the axis from the catcher: every body's circle, the rails and the frame."""
    from matplotlib.patches import Circle
    lay = machine.layout
    for it in sorted((i for i in lay.items if i.kind in AXIAL_KINDS), key=lambda i: -i.diameter):
        ax.add_patch(Circle((0, 0), it.diameter / 2, fc=COLOURS.get(it.kind, "0.7"), ec="k", lw=0.3))
    for it in lay.items:
        if it.kind == "rail":
            h, xs, y = rail_geometry(it.diameter)
            for x in xs:
                ax.add_patch(_rect(x, y, h, h, COLOURS["rail"]))
    W, a = lay.overall_width, math.sqrt(lay.frame_section)
    for x in (-W / 2 - a, W / 2):
        ax.add_patch(_rect(x, -W / 2 - a, a, a, COLOURS["frame"]))
    _dimension(ax, -W / 2, W / 2, -W / 2 - 2.2 * a, f"{_mm(W)}", 1.0)
    ax.set_xlim(-W * 0.75, W * 0.75)
    ax.set_ylim(-W * 0.85, W * 0.65)
    ax.set_aspect("equal")
    ax.axis("off")
    ax.set_title("end view (from the catcher)", fontsize=8, loc="left")


def _isometric(ax, machine):
    """An isometric projection of the bodies on the axis (end ellipses and silhouettes) and the frame."""
    c, s30 = math.cos(math.pi / 6), math.sin(math.pi / 6)

    def project(x, y, z):
        return (z - x) * c, y + (z + x) * s30
    lay = machine.layout
    theta = np.linspace(0, 2 * math.pi, 60)
    for it in lay.items:
        if it.kind not in AXIAL_KINDS:
            continue
        R = it.diameter / 2
        rings = []
        for z in (it.x0, it.x0 + it.length):
            u, v = project(R * np.cos(theta), R * np.sin(theta), np.full_like(theta, z))
            rings.append((u, v))
            ax.plot(u, v, color="k", lw=0.25)
        # silhouettes: the points of the end circle farthest either side of the projected axis (c, s30)
        u0, v0 = rings[0]
        across = -s30 * u0 + c * v0
        for k in (int(np.argmax(across)), int(np.argmin(across))):
            ax.plot([rings[0][0][k], rings[1][0][k]], [rings[0][1][k], rings[1][1][k]], color="k", lw=0.25)
        ax.fill(rings[1][0], rings[1][1], color=COLOURS.get(it.kind, "0.7"), lw=0)
    W, a, L = lay.overall_width, math.sqrt(lay.frame_section), lay.overall_length
    for x in (-W / 2 - a / 2, W / 2 + a / 2):
        u, v = zip(project(x, -W / 2 - a / 2, 0.0), project(x, -W / 2 - a / 2, L))
        ax.plot(u, v, color=COLOURS["frame"], lw=1.2)
    ax.set_aspect("equal")
    ax.axis("off")
    ax.set_title("isometric", fontsize=8, loc="left")


def _parts_list(ax, machine):
    rows = []
    for k, it in enumerate(machine.layout.items, start=1):
        rows.append([str(k), it.name, it.kind, it.material or "-", f"{it.mass:,.1f}" if it.mass else "-",
                     f"{_mm(it.length)}", f"{_mm(it.diameter)}"])
    rows.append(["", "total", "", "", f"{machine.totals['machine_mass']:,.0f}", _mm(machine.layout.overall_length),
                 _mm(machine.layout.overall_width)])
    ax.axis("off")
    t = ax.table(cellText=rows, colLabels=["item", "name", "kind", "material", "mass [kg]", "length [mm]",
                                           "diameter [mm]"], loc="upper left", cellLoc="left")
    t.auto_set_font_size(False)
    t.set_fontsize(5.5)
    t.scale(1.0, 0.78)
    ax.set_title("parts list (masses as designed; '-': arrangement drawn, section not designed)", fontsize=8,
                 loc="left")

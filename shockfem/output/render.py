"""Off-screen pictures (pyvista): a part's mesh as the user will see it in ParaView, and a run's deformed
shape coloured by von Mises from its XDMF files."""
from __future__ import annotations

import os

import numpy as np

from .figures import pyvista


def _grid(meshed):
    from dolfinx import plot
    pv = pyvista()
    topology, cell_types, x = plot.create_vtk_mesh(meshed.mesh)
    grid = pv.UnstructuredGrid(topology, cell_types, x)
    body = np.zeros(grid.n_cells, dtype=np.int32)
    body[meshed.cell_tags.indices] = meshed.cell_tags.values
    grid.cell_data["body"] = body
    return grid


def _framed(plotter, grid, dim: int, cut: bool):
    """Point the camera: 2D face on; 3D from above one side, the mesh cut open along two half planes
    through the axis (the quarter x > 0, y < 0 removed, whole cells, so the element edges show on the
    cut) to show bores and cavities.  Returns the grid to draw."""
    if dim == 3 and cut:
        grid = grid.clip_box(bounds=(0, 1e3, -1e3, 0, -1e3, 1e3), invert=True, crinkle=True)
        plotter.camera_position = [(1.0, -1.6, 0.9), (0, 0, 0), (0, 0, 1)]
    else:
        plotter.camera_position = "xy"
    return grid


def _scale_length(extent: float) -> float:
    """A round length (1, 2 or 5 times a power of ten) near a quarter of ``extent`` [m]."""
    target = 0.25 * extent
    power = 10.0 ** np.floor(np.log10(target))
    return max((k * power for k in (1.0, 2.0, 5.0) if k * power <= target), default=power)


def _annotate(plotter, grid, body_names=()):
    """What a picture needs to be read on the shape itself: a scale bar under the shape with its length,
    and each shown body's name at its centre (the axes and the colour bar are drawn around the cropped
    picture, ``_compose``)."""
    pv = pyvista()
    if grid.n_cells == 0:
        return
    lo, hi = np.array(grid.bounds[0::2]), np.array(grid.bounds[1::2])
    extent = float(np.max(hi - lo))
    length = _scale_length(extent)
    start = np.array([lo[0], lo[1] - 0.08 * extent, lo[2]])
    end = start + np.array([length, 0.0, 0.0])
    plotter.add_mesh(pv.Line(start, end), color="black", line_width=4)
    label = f"{length * 1e3:g} mm" if length < 1.0 else f"{length:g} m"
    plotter.add_point_labels([0.5 * (start + end)], [label], font_size=14, shape=None, show_points=False,
                             always_visible=True)
    if body_names and "body" in grid.cell_data:
        centres = grid.cell_centers().points
        numbers = np.asarray(grid.cell_data["body"])
        where, names = [], []
        for k, name in enumerate(body_names):
            mine = numbers == k + 1
            if mine.any():
                where.append(centres[mine].mean(axis=0))
                names.append(name)
        if names:
            plotter.add_point_labels(np.array(where), names, font_size=14, shape_opacity=0.6, show_points=False,
                                     always_visible=True)


def _axis_arrows(plotter, grid, axisymmetric: bool) -> list[tuple[str, float, float]]:
    """The scene's axes as the camera shows them: for each axis whose projection is not a point, its name
    (r, z in axisymmetry) and its unit direction in the picture (right, up)."""
    renderer = plotter.renderer
    centre = np.array(grid.center if grid.n_cells else (0.0, 0.0, 0.0))
    length = max(float(grid.length), 1e-9) * 0.1
    names = ("r", "z", "") if axisymmetric else ("x", "y", "z")

    def display(point):
        renderer.SetWorldPoint(*point, 1.0)
        renderer.WorldToDisplay()
        return np.array(renderer.GetDisplayPoint()[:2])

    origin, arrows = display(centre), []
    for k, name in enumerate(names):
        step = display(centre + length * np.eye(3)[k]) - origin
        if name and np.hypot(*step) > 1e-6 * max(plotter.window_size):
            arrows.append((name, *(step / np.hypot(*step))))
    return arrows


def _cropped(image: np.ndarray, margin: int = 12) -> np.ndarray:
    """``image`` (rows, columns, channels) cut to what differs from its background (the corner pixel's
    colour), with ``margin`` pixels around."""
    drawn = np.any(image != image[0, 0], axis=2)
    if not drawn.any():
        return image
    rows, cols = np.flatnonzero(drawn.any(axis=1)), np.flatnonzero(drawn.any(axis=0))
    top, bottom = max(rows[0] - margin, 0), min(rows[-1] + margin + 1, image.shape[0])
    left, right = max(cols[0] - margin, 0), min(cols[-1] + margin + 1, image.shape[1])
    return image[top:bottom, left:right]


def _wrapped(title: str, width_px: float) -> str:
    """Each line of ``title`` broken at spaces to fit ``width_px`` pixels at 9 pt and 110 dpi (a
    character is about 7.6 pixels wide there), so that a long title on a narrow picture is not cut."""
    import textwrap
    chars = max(20, int(width_px / 7.6))
    return "\n".join(piece for line in title.splitlines() for piece in (textwrap.wrap(line, chars) or [""]))


def _compose(image, path: str, title: str, arrows, colours=None):
    """The rendered shape, cropped to the bodies, as a matplotlib figure: the title above, the axes'
    directions beside the shape, and (``colours``: label with its unit, (low, high), colour map) a colour
    bar: to the right of a tall shape, under a wide one.

    matplotlib draws the colour bar, not VTK: VTK's scalar bar (9.x wheels) lays its tick labels out
    through std::regex, which aborts the process (std::bad_alloc in ``vtk::is_printf_format``) once
    dolfinx's libraries are loaded beside it (``import dolfinx`` and then any pyvista scalar bar)."""
    from matplotlib import colors as mcolors
    from matplotlib.cm import ScalarMappable

    from .figures import partial_path, pyplot
    plt = pyplot()
    image = _cropped(image)
    dpi = 110
    w, h = image.shape[1] / dpi, image.shape[0] / dpi           # inches, one image pixel a figure pixel
    tall = h >= w
    bar = colours is not None
    side, below = ((1.4 if bar else 1.0), 0.0) if tall else (0.0, (1.1 if bar else 0.9))
    W = max(w + side, 4.5 if bar else 3.0)                          # inches
    title = _wrapped(title, W * dpi)
    top = 0.1 + 0.16 * (title.count("\n") + 1) if title else 0.1    # a 9 pt line is 0.16 in
    H = h + top + below
    fig = plt.figure(figsize=(W, H), dpi=dpi)
    ax = fig.add_axes([0.0, below / H, w / W, h / H])
    ax.imshow(image, interpolation="none")
    ax.set_axis_off()
    if title:
        fig.suptitle(title, fontsize=9, y=1.0 - 0.05 / H, va="top")
    compass = fig.add_axes([(w + 0.2) / W if tall else 0.05 / W, 0.05 / H, 0.9 / W, 0.9 / H])
    compass.set_xlim(-1.4, 1.4)
    compass.set_ylim(-1.4, 1.4)
    compass.set_aspect("equal")
    compass.set_axis_off()
    for name, right, up in arrows:
        compass.annotate("", xy=(0.8 * right, 0.8 * up), xytext=(0.0, 0.0),
                         arrowprops=dict(arrowstyle="->", lw=1.5, color="black"))
        compass.text(1.1 * right, 1.1 * up, name, ha="center", va="center", fontsize=9)
    if colours is not None:
        label, (low, high), cmap = colours
        scale = ScalarMappable(norm=mcolors.Normalize(vmin=low, vmax=high), cmap=cmap)
        where = ([(w + 0.25) / W, (below + 1.3) / H, 0.18 / W, max(h - 1.5, 0.5 * h) / H] if tall
                 else [1.3 / W, 0.6 / H, (W - 1.7) / W, 0.18 / H])
        fig.colorbar(scale, cax=fig.add_axes(where), label=label, orientation="vertical" if tall else "horizontal")
    partial = partial_path(path)
    fig.savefig(partial, dpi=dpi)
    plt.close(fig)
    os.replace(partial, path)


def _rendered(plotter, grid, dim: int, axisymmetric: bool):
    """Render ``plotter`` once framed: its picture as an array and the axes' directions in it."""
    plotter.reset_camera()
    image = plotter.screenshot(None, return_img=True)
    arrows = _axis_arrows(plotter, grid, axisymmetric)
    plotter.close()
    return image, arrows


def render_mesh(meshed, path: str, title: str = "", cut: bool = True, body_names=(), axisymmetric: bool = False):
    """A PNG of the mesh with its element edges, coloured by body, with the axes, a scale and the bodies'
    names, cropped to the bodies; 3D meshes are cut open along two half planes through the axis (a quarter
    removed) to show bores and cavities."""
    pv = pyvista()
    grid = _grid(meshed)
    plotter = pv.Plotter(off_screen=True, window_size=(900, 900))
    grid = _framed(plotter, grid, meshed.mesh.geometry.dim, cut)
    plotter.add_mesh(grid, scalars="body", show_edges=True, cmap="Pastel1", show_scalar_bar=False,
                     edge_color="#333333", line_width=0.5)
    _annotate(plotter, grid, body_names)
    image, arrows = _rendered(plotter, grid, meshed.mesh.geometry.dim, axisymmetric)
    _compose(image, path, title, arrows)


def _draw(grid, path: str, label: str, title: str, dim: int, cut: bool, body_names=(), axisymmetric=False):
    """``grid`` coloured by its cell array ``label`` (its name with its unit) with edges, framed and
    annotated as ``render_mesh`` does, with a colour bar, to ``path``."""
    pv = pyvista()
    plotter = pv.Plotter(off_screen=True, window_size=(900, 900))
    grid = _framed(plotter, grid, dim, cut)
    _annotate(plotter, grid, body_names)
    shown = np.asarray(grid.cell_data[label]) if grid.n_cells else np.zeros(1)
    low, high = float(shown.min()), float(shown.max())
    top = high if high > low else low + 1.0          # a uniform field: its colour at the bar's foot, not mid-range
    plotter.add_mesh(grid, scalars=label, show_edges=True, cmap="viridis", clim=(low, top),
                     edge_color="#333333", line_width=0.3, show_scalar_bar=False)
    image, arrows = _rendered(plotter, grid, dim, axisymmetric)
    _compose(image, path, f"{title}\nlargest {label.split(' [')[0]}: {high:.4g} {_unit(label)}".rstrip(), arrows,
             (label, (low, top), "viridis"))


def _unit(label: str) -> str:
    """The unit in a label ``"name [unit]"`` (empty for ``[-]``)."""
    unit = label.rsplit("[", 1)[-1].rstrip("]") if "[" in label else ""
    return "" if unit == "-" else unit


def warm_up():
    """Draw a picture of a 2 x 2 grid through ``_draw``, the run pictures' own path, into a temporary folder
    and throw it away.  The first picture of a process pays for pyvista's plotting modules, VTK's rendering
    modules and the OpenGL context (about 0.3 s here); the picture process does this while the run steps,
    not after it asks for its pictures."""
    import tempfile
    pv = pyvista()
    grid = pv.ImageData(dimensions=(3, 3, 1)).cast_to_unstructured_grid()
    grid.cell_data["value"] = np.arange(grid.n_cells, dtype=float)
    grid.cell_data["body"] = np.ones(grid.n_cells, dtype=np.int32)
    with tempfile.TemporaryDirectory() as folder:
        _draw(grid, os.path.join(folder, "warm_up.png"), "value", "warm-up", 2, False, ("part",))


def _label(field: str) -> tuple[str, float]:
    """The picture's name of a cell field and the scale to its unit (stresses in MPa)."""
    stress = field in ("von_mises", "pressure") or field.startswith("stress_")
    name = "von Mises stress" if field == "von_mises" else field.replace("_", " ")
    return f"{name} [{'MPa' if stress else '-'}]", (1e-6 if stress else 1.0)


def _run_peak(run_dir: str, scale: float, unit: str) -> str:
    """A second line, "run's peak, every step: X at t = T ms", from summary.json's peaks over the bodies
    ("" without them)."""
    import json
    try:
        with open(os.path.join(run_dir, "summary.json")) as fh:
            bodies = json.load(fh)["bodies"]
    except (OSError, ValueError, KeyError):
        return ""
    peaks = [(b["max_von_mises"], b.get("max_von_mises_time")) for b in bodies.values()]
    peaks = [p for p in peaks if p[1] is not None]
    if not peaks:
        return ""
    value, when = max(peaks)
    return f"\nrun's peak, every step: {value * scale:.4g} {unit} at t = {when * 1e3:.4g} ms"


def render_run(run_dir: str, bodies: list[int] | None = None, cut: bool = True) -> list[str]:
    """A run directory's pictures, from its files: ``peak_stress.png``, the frame of ``fields.xdmf`` with
    the highest von Mises stress (of the frames: the run's own peak, tracked every step, is in
    ``summary.json``, and the title gives both), warped by its displacement, and ``final_shape.png``, the deformed mesh
    of ``final_shape.xdmf``, both coloured by von Mises.  ``bodies``: the body indices (scene order) to
    show, all by default.  Returns the pictures written (none without the files or von Mises)."""
    import json

    import h5py
    pv = pyvista()
    written = []
    with open(os.path.join(run_dir, "resolved_scene.json")) as fh:
        axisymmetric = json.load(fh).get("kinematics") == "axisymmetric"
    for name, picture in (("fields", "peak_stress.png"), ("final_shape", "final_shape.png")):
        xdmf = os.path.join(run_dir, f"{name}.xdmf")
        if not os.path.exists(xdmf):
            continue
        with h5py.File(os.path.join(run_dir, f"{name}.h5"), "r") as h5:
            shown = (np.ones(len(h5["mesh/body"]), bool) if bodies is None
                     else np.isin(h5["mesh/body"][()], np.asarray(bodies) + 1))
            frames = [(float(g.attrs["time"]), g["von_mises"][()][shown].max(initial=0.0))
                      for g in h5["frames"].values() if "von_mises" in g]
            dim = 3 if np.ptp(h5["mesh/geometry"][:, 2]) > 0 else 2
            names = [str(n) for n in h5["mesh/body"].attrs["names"]]
        if not frames:
            continue
        t, peak = max(frames, key=lambda f: f[1])
        reader = pv.get_reader(xdmf)
        reader.set_active_time_value(t)
        grid = reader.read()
        if "displacement" in grid.point_data:
            grid = grid.warp_by_vector("displacement")
        label, scale = _label("von_mises")
        grid.cell_data[label] = grid.cell_data["von_mises"] * scale
        grid = grid.extract_cells(np.flatnonzero(shown))
        unit = label.split("[")[-1].rstrip("]")
        title = (f"field frame of highest von Mises ({peak * scale:.4g} {unit}): t = {t * 1e3:.4g} ms "
                 f"(deformed, true scale){_run_peak(run_dir, scale, unit)}"
                 if name == "fields" else f"final shape: t = {t * 1e3:.4g} ms (deformed, true scale)")
        _draw(grid, os.path.join(run_dir, picture), label, title, dim, cut, names, axisymmetric)
        written.append(os.path.join(run_dir, picture))
    return written

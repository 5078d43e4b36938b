"""Off-screen pictures of meshes (pyvista): a part as the user will see it in ParaView."""
from __future__ import annotations

import os

import numpy as np

from .figures import partial_path, pyvista


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


def render_mesh(meshed, path: str, title: str = "", cut: bool = True):
    """A PNG of the mesh with its element edges, coloured by body; 3D meshes are cut open along
    two half planes through the axis (a quarter removed) to show bores and cavities."""
    pv = pyvista()
    grid = _grid(meshed)
    plotter = pv.Plotter(off_screen=True, window_size=(900, 900))
    grid = _framed(plotter, grid, meshed.mesh.geometry.dim, cut)
    plotter.add_mesh(grid, scalars="body", show_edges=True, cmap="Pastel1", show_scalar_bar=False,
                     edge_color="#333333", line_width=0.5)
    if title:
        plotter.add_text(title, font_size=12)
    plotter.reset_camera()
    plotter.screenshot(partial_path(path))
    plotter.close()
    os.replace(partial_path(path), path)


def render_state(solver, path: str, field: str = "von_mises", title: str = "", cut: bool = True,
                 bodies: list[int] | None = None):
    """A PNG of the solver's current, deformed mesh coloured by a cell field (``fields.CELL_FIELDS``;
    stresses in MPa), cut open in 3D as ``render_mesh`` does: a run's final shape and stress field.
    ``bodies``: the body indices (scene order) to show, all by default."""
    from .fields import cell_values
    pv = pyvista()
    m = solver.model
    mesh = m.meshed.mesh
    grid = _grid(m.meshed)
    # P1 geometry nodes and the solver's nodes list a cell's vertices alike (``fields.write_final_shape``)
    points = np.array(mesh.geometry.x, copy=True)
    geometry = mesh.geometry.dofmap.array.reshape(-1, m.dofmap.shape[1])[:len(m.dofmap)]
    points[geometry, :m.gdim] = solver.x[m.dofmap]
    grid.points = points
    values = cell_values(solver, field)
    stress = field in ("von_mises", "pressure")
    label = f"{field.replace('_', ' ')} [{'MPa' if stress else '-'}]"
    grid.cell_data[label] = values[:grid.n_cells] / (1e6 if stress else 1.0)
    if bodies is not None:
        grid = grid.extract_cells(np.flatnonzero(np.isin(m.cell_body[:grid.n_cells], bodies)))
    plotter = pv.Plotter(off_screen=True, window_size=(900, 900))
    grid = _framed(plotter, grid, mesh.geometry.dim, cut)
    # no scalar bar: VTK's (9.x wheels) lays out its tick labels through std::regex, which aborts the
    # process here (std::bad_alloc in vtk::is_printf_format); the colour range is written instead
    shown = grid.cell_data[label]
    plotter.add_mesh(grid, scalars=label, show_edges=True, cmap="viridis", edge_color="#333333", line_width=0.3,
                     show_scalar_bar=False)
    plotter.add_text(f"{title or f't = {solver.t * 1e3:.4g} ms'}\n{label}: {shown.min():.4g} (dark blue) to "
                     f"{shown.max():.4g} (yellow)", font_size=10)
    plotter.reset_camera()
    plotter.screenshot(partial_path(path))
    plotter.close()
    os.replace(partial_path(path), path)

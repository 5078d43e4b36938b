"""Off-screen pictures of meshes (pyvista): a part as the user will see it in ParaView."""
from __future__ import annotations

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


def render_mesh(meshed, path: str, title: str = "", cut: bool = True):
    """A PNG of the mesh with its element edges, coloured by body; 3D meshes are cut open along
    two half planes through the axis (a quarter removed) to show bores and cavities."""
    pv = pyvista()
    grid = _grid(meshed)
    plotter = pv.Plotter(off_screen=True, window_size=(900, 900))
    if meshed.mesh.geometry.dim == 3 and cut:
        # remove the quarter x > 0, y < 0 (whole cells, so the element edges show on the cut)
        grid = grid.clip_box(bounds=(0, 1e3, -1e3, 0, -1e3, 1e3), invert=True, crinkle=True)
        plotter.camera_position = [(1.0, -1.6, 0.9), (0, 0, 0), (0, 0, 1)]
    else:
        plotter.camera_position = "xy"
    plotter.add_mesh(grid, scalars="body", show_edges=True, cmap="Pastel1", show_scalar_bar=False,
                     edge_color="#333333", line_width=0.5)
    if title:
        plotter.add_text(title, font_size=12)
    plotter.reset_camera()
    plotter.screenshot(path)
    plotter.close()

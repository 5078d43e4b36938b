"""The XDMF time series: what meshio reads back is what was written, frame by frame; a resumed file is
cut back to its checkpoint; a frame a kill cut short is never listed and is replaced; cells are in
XDMF's vertex order (counter-clockwise quads)."""
import meshio
import numpy as np
import pytest

from shockfem.output.xdmf import Field, Mesh, TimeSeries, read_frames, three_coordinates, xdmf_cells

# two unit quads side by side, vertices in dolfinx's tensor-product order
POINTS = np.array([[0, 0], [1, 0], [0, 1], [1, 1], [2, 0], [2, 1]], float)
DOFMAP = np.array([[0, 1, 2, 3], [1, 4, 3, 5]])
FIELDS = [Field("displacement", "Node", 3, "m"), Field("von_mises", "Cell", 1, "Pa")]


def _mesh():
    return Mesh(three_coordinates(POINTS), xdmf_cells(DOFMAP, "quadrilateral"), "quadrilateral",
                np.array([1, 2]), ("striker", "target"))


def _frame(t):
    return {"displacement": t * POINTS, "von_mises": np.array([t, 2 * t])}


def _read(path):
    r = meshio.xdmf.TimeSeriesReader(str(path))
    points, cells = r.read_points_cells()
    return points, cells, [r.read_data(k) for k in range(r.num_steps)]


def test_frames_read_back(tmp_path):
    path = tmp_path / "fields.xdmf"
    series = TimeSeries(str(path), _mesh(), FIELDS)
    for t in (0.0, 1.0, 2.5):
        series.append(t, _frame(t))
    # between rewrites the file lists the first frames (a kill leaves it readable), at close all
    listed = read_frames(str(path))
    assert listed == [(0, 0.0), (1, 1.0), (2, 2.5)][:len(listed)]
    series.close()
    points, cells, frames = _read(path)
    assert np.array_equal(points, three_coordinates(POINTS))
    # counter-clockwise: the shoelace area of each quad in the file's order is +1
    q = points[cells[0].data][:, :, :2]
    area = 0.5 * (q[:, :, 0] * np.roll(q[:, :, 1], -1, axis=1) - np.roll(q[:, :, 0], -1, axis=1) * q[:, :, 1]).sum(1)
    assert np.allclose(area, 1.0)
    assert [f[0] for f in frames] == [0.0, 1.0, 2.5]
    t, point_data, cell_data = frames[2]
    assert np.array_equal(point_data["displacement"], three_coordinates(2.5 * POINTS))
    assert np.array_equal(cell_data["von_mises"][0], [2.5, 5.0]) and np.array_equal(cell_data["body"][0], [1, 2])
    assert "striker" in path.read_text() and "von_mises: Pa" in path.read_text()


def test_resume_cuts_back_and_a_cut_frame_is_replaced(tmp_path):
    path = tmp_path / "fields.xdmf"
    series = TimeSeries(str(path), _mesh(), FIELDS)
    for t in (0.0, 1.0, 2.0, 3.0):
        series.append(t, _frame(t))
    series.close()
    resumed = TimeSeries(str(path), _mesh(), FIELDS, resume_after=1.5)
    assert read_frames(str(path)) == [(0, 0.0), (1, 1.0)]
    # the data of a frame a kill cut short (in the HDF5 file, never in the XDMF) is written again
    import h5py
    with h5py.File(tmp_path / "fields.h5", "a") as h5:
        h5["frames"].create_group("2")
    resumed.append(2.0, _frame(7.0))
    resumed.close()
    _, _, frames = _read(path)
    assert [f[0] for f in frames] == [0.0, 1.0, 2.0]
    assert np.array_equal(frames[2][2]["von_mises"][0], [7.0, 14.0])


@pytest.mark.parametrize("cell, n", [("triangle", 3), ("tetrahedron", 4), ("hexahedron", 8)])
def test_cell_orders(cell, n):
    cells = xdmf_cells(np.arange(n)[None, :], cell)
    assert sorted(cells[0]) == list(range(n))
    if cell == "hexahedron":    # the bottom face counter-clockwise, the top above it
        assert list(cells[0]) == [0, 1, 3, 2, 4, 5, 7, 6]

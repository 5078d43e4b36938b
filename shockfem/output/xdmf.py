"""An XDMF3 time series that ParaView's default reader, pyvista and meshio all open as one mesh.

Every XDMF file of a run is such a series (a run's last state too, as a series of one frame: pyvista
0.49's XDMF reader fails on a file without time steps; meshio reads series with
``meshio.xdmf.TimeSeriesReader``).

Why not dolfinx's ``XDMFFile``: it writes each function as a temporal collection of its own and the
cell tags as another grid, so ParaView 5.11's default (XDMF3) reader opens a multiblock in which the
deformed mesh shows no arrays, and meshio's time-series reader finds no single mesh.  Here the file
holds one temporal collection and nothing else; every frame is a whole grid - the same topology and
reference geometry (written once to the HDF5 file, referenced by every frame), the body of each cell,
and every field of that time - so *File > Open*, *Warp By Vector* and *Threshold* work on it as on any
unstructured grid.

Layout of the HDF5 file: ``/mesh/geometry`` (points, 3) [m], ``/mesh/topology`` (cells, nodes) in
XDMF's vertex order, ``/mesh/body`` (cells,) the body number (1 = the scene's first body), with the
body names as the attribute ``names``; ``/frames/<k>/<field>`` the k-th frame's values, each dataset
with its ``units`` and the group with its ``time`` [s].  The XDMF file names the body numbers and
every field's unit in a comment, and the body numbers by name in an ``Information`` element (as meshio
writes gmsh's physical names: meshio reads them as ``field_data``).

Written by one process (the run's last rank gathers, ``fields.FieldWriter``): the HDF5 file is opened
to append a frame and closed again, and the XDMF file, which lists only frames whose data is whole,
is rewritten beside and renamed into place after it: a run killed at any moment leaves both files
readable to the last frame they list, except a kill inside the HDF5 write itself (a few milliseconds
a frame), which can leave the HDF5 file unreadable.
"""
from __future__ import annotations

import os
import time
from dataclasses import dataclass
from xml.etree import ElementTree

import h5py
import numpy as np

# dolfinx P1 vertex order -> XDMF's (VTK's): quads and hexes are tensor-product ordered in dolfinx
CELL_TYPES = {"triangle": ("Triangle", (0, 1, 2)), "quadrilateral": ("Quadrilateral", (0, 1, 3, 2)),
              "tetrahedron": ("Tetrahedron", (0, 1, 2, 3)),
              "hexahedron": ("Hexahedron", (0, 1, 3, 2, 4, 5, 7, 6))}


@dataclass(frozen=True)
class Field:
    """A field of every frame: ``center`` "Node" or "Cell", ``components`` 1 (a scalar) or 3 (a vector)."""
    name: str
    center: str
    components: int
    units: str


@dataclass(frozen=True)
class Mesh:
    """What every frame shares: reference points (3 coordinates), cells in XDMF order, their bodies."""
    points: np.ndarray
    cells: np.ndarray
    cell_type: str            # dolfinx's cell name
    body: np.ndarray
    body_names: tuple


def xdmf_cells(dofmap: np.ndarray, cell_type: str) -> np.ndarray:
    """dolfinx-ordered cell vertices (cells, nn) in XDMF's order."""
    return np.ascontiguousarray(dofmap[:, list(CELL_TYPES[cell_type][1])], dtype=np.int64)


def three_coordinates(values: np.ndarray) -> np.ndarray:
    """(n, gdim) points or vectors padded to (n, 3): ParaView warps by 3-vectors, pyvista needs 3D points."""
    out = np.zeros((len(values), 3))
    out[:, :values.shape[1]] = values
    return out


def _h5_name(path: str) -> str:
    return os.path.splitext(os.path.basename(path))[0] + ".h5"


def _item(parent, h5: str, dataset: str, shape, dtype: str = "Float", precision: int = 8):
    e = ElementTree.SubElement(parent, "DataItem", Dimensions=" ".join(str(int(s)) for s in shape),
                               Format="HDF", DataType=dtype, Precision=str(precision))
    e.text = f"{h5}:{dataset}"


def _grid(parent, name: str, mesh_shapes, h5: str, cell_type: str):
    """A uniform grid with the mesh's topology and geometry and the body numbers."""
    (num_points, _), (num_cells, nn) = mesh_shapes
    grid = ElementTree.SubElement(parent, "Grid", Name=name, GridType="Uniform")
    topo = ElementTree.SubElement(grid, "Topology", TopologyType=CELL_TYPES[cell_type][0],
                                  NumberOfElements=str(num_cells), NodesPerElement=str(nn))
    _item(topo, h5, "/mesh/topology", (num_cells, nn), "Int")
    geo = ElementTree.SubElement(grid, "Geometry", GeometryType="XYZ")
    _item(geo, h5, "/mesh/geometry", (num_points, 3))
    body = ElementTree.SubElement(grid, "Attribute", Name="body", AttributeType="Scalar", Center="Cell")
    _item(body, h5, "/mesh/body", (num_cells,), "Int", 4)
    return grid


def _attribute(grid, h5: str, field: Field, dataset: str, count: int):
    a = ElementTree.SubElement(grid, "Attribute", Name=field.name,
                               AttributeType="Scalar" if field.components == 1 else "Vector", Center=field.center)
    _item(a, h5, dataset, (count,) if field.components == 1 else (count, field.components))


def _body_information(parent, body_names):
    """The body numbers by name: in its ``Value`` (ParaView's reader requires one) and in its text as meshio
    writes gmsh's physical names (meshio reads them as field data, ``{name: [number, dim]}``)."""
    info = ElementTree.Element("main")
    for k, name in enumerate(body_names):
        ElementTree.SubElement(info, "map", key=name, dim="0").text = str(k + 1)
    e = ElementTree.SubElement(parent, "Information", Name="body",
                               Value="; ".join(f"{k + 1}: {n}" for k, n in enumerate(body_names)))
    e.text = ElementTree.tostring(info, encoding="unicode")


def _document(fields) -> tuple[ElementTree.Element, ElementTree.Element]:
    """The root and its domain, the units in a comment (readers skip it; an ``Information`` element
    inside an attribute would stop meshio)."""
    root = ElementTree.Element("Xdmf", Version="3.0")
    domain = ElementTree.SubElement(root, "Domain")
    units = "; ".join(["time: s", "coordinates: m"] + [f"{f.name}: {f.units}" for f in fields])
    domain.append(ElementTree.Comment(f" shockfem fields; units: {units} "))
    return root, domain


def _write_mesh(h5: h5py.File, mesh: Mesh):
    g = h5.create_group("mesh")
    g.create_dataset("geometry", data=mesh.points).attrs["units"] = "m"
    g.create_dataset("topology", data=mesh.cells)
    body = g.create_dataset("body", data=mesh.body.astype(np.int32))
    body.attrs["names"] = list(mesh.body_names)


def _values(field: Field, v: np.ndarray) -> np.ndarray:
    return three_coordinates(v) if field.components == 3 else np.asarray(v, dtype=float)


class TimeSeries:
    """``path`` (.xdmf) and its .h5: frames appended one at a time (``append``), the XDMF file rewritten
    as they come, but for no more than 2% of the time since its last rewrite (a long run with a frame
    every step would otherwise spend its time rewriting a list that grows), and whole at ``close``."""

    WRITE_SHARE = 0.02

    def __init__(self, path: str, mesh: Mesh, fields: list[Field], resume_after: float | None = None):
        """A new file with ``mesh``; or, with ``resume_after`` (a resumed run), the existing one cut back to
        its frames at times up to that, to be appended to."""
        self.path, self.h5_path = path, os.path.join(os.path.dirname(path), _h5_name(path))
        self.fields, self.shapes = list(fields), (mesh.points.shape, mesh.cells.shape)
        self.cell_type = mesh.cell_type
        self.frames: list[tuple[int, float]] = []
        if resume_after is None:
            with h5py.File(self.h5_path, "w") as h5:
                _write_mesh(h5, mesh)
                h5.create_group("frames")
        else:
            self.frames = [(k, t) for k, t in read_frames(path) if t <= resume_after]
            kept = {str(k) for k, _ in self.frames}
            with h5py.File(self.h5_path, "a") as h5:
                for name in list(h5["frames"]):
                    if name not in kept:
                        del h5["frames"][name]
        self.head, self.tail = self._frame_less_document(mesh.body_names)
        self.texts = [self._frame_text(k, t) for k, t in self.frames]
        self.written_at, self.write_time, self.listed = 0.0, 0.0, -1
        self.flush()

    def append(self, t: float, values: dict[str, np.ndarray]):
        """One frame at time ``t`` [s]: ``values`` has an array for every field."""
        k = self.frames[-1][0] + 1 if self.frames else 0
        with h5py.File(self.h5_path, "a") as h5:
            if str(k) in h5["frames"]:         # left by a frame a kill cut short, never listed
                del h5["frames"][str(k)]
            g = h5["frames"].create_group(str(k))
            g.attrs["time"] = t
            for f in self.fields:
                g.create_dataset(f.name, data=_values(f, values[f.name])).attrs["units"] = f.units
        self.frames.append((k, t))
        self.texts.append(self._frame_text(k, t))
        if time.perf_counter() - self.written_at >= self.write_time / self.WRITE_SHARE:
            self.flush()

    def flush(self):
        """The XDMF file listing every frame written (beside, then renamed into place)."""
        if self.listed == len(self.frames):
            return
        start = time.perf_counter()
        partial = self.path + ".partial"
        with open(partial, "w", encoding="utf-8") as fh:
            fh.write(self.head)
            fh.writelines(self.texts)
            fh.write(self.tail)
        os.replace(partial, self.path)
        self.written_at = time.perf_counter()
        self.write_time, self.listed = self.written_at - start, len(self.frames)

    close = flush

    def _frame_less_document(self, body_names) -> tuple[str, str]:
        """The XDMF text before and after the frames."""
        root, domain = _document(self.fields)
        _body_information(domain, body_names)
        series = ElementTree.SubElement(domain, "Grid", Name="fields", GridType="Collection",
                                        CollectionType="Temporal")
        series.append(ElementTree.Comment("frames"))
        ElementTree.indent(root)
        text = ElementTree.tostring(root, encoding="unicode", xml_declaration=True)
        head, tail = text.split("<!--frames-->")
        return head.rstrip(" "), tail.lstrip("\n")

    def _frame_text(self, k: int, t: float) -> str:
        h5 = _h5_name(self.path)
        grid = _grid(ElementTree.Element("Grid"), f"frame_{k}", self.shapes, h5, self.cell_type)
        ElementTree.SubElement(grid, "Time", Value=repr(float(t)))
        for f in self.fields:
            _attribute(grid, h5, f, f"/frames/{k}/{f.name}", self.shapes[0][0] if f.center == "Node" else self.shapes[1][0])
        ElementTree.indent(grid, space="  ", level=3)
        return "      " + ElementTree.tostring(grid, encoding="unicode") + "\n"


def read_frames(path: str) -> list[tuple[int, float]]:
    """The (frame number, time) of every frame an XDMF file of ``TimeSeries`` lists."""
    domain = ElementTree.parse(path).getroot().find("Domain")
    return [(int(g.get("Name").split("_")[1]), float(g.find("Time").get("Value")))
            for g in domain.find("Grid[@CollectionType='Temporal']").findall("Grid")]

"""From a scene's bodies to one distributed dolfinx mesh with body and region tags.

All bodies go into one gmsh model and so into one dolfinx mesh: one function space,
one dofmap and one kernel call serve every body, and the bodies stay disconnected (they
share no nodes).  Cell tags are body numbers (1, 2, ...); facet tags number every named
region ``body.region``.  The gmsh file is cached (``default_cache_dir``: the checkout's ``meshes/``
for its own scenes, the user's cache folder for others) under a hash of what determines it, so
rerunning a scene does not remesh.
"""
from __future__ import annotations

import hashlib
import json
import os
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from mpi4py import MPI

from .. import compat
from ..errors import ModelError
if TYPE_CHECKING:                         # the scene imports the catalog of parts from this package
    from ..scene import Scene
from . import draw
from ..parts.catalog import CAD_FILES

MESH_FORMAT_VERSION = 5   # bump when part drawing changes, to invalidate caches


@dataclass
class MeshedScene:
    mesh: object                 # dolfinx.mesh.Mesh
    cell_tags: object            # MeshTags: body number (1-based, scene order) per cell
    facet_tags: object           # MeshTags: region number per boundary facet
    region_ids: dict[str, int]   # "body.region" -> facet tag value
    source: str                  # path of the gmsh file used


def default_cache_dir(scene_folder: str = "") -> str:
    """Where meshes are cached: the folder ``SHOCKFEM_MESH_CACHE`` names; else the checkout's ``meshes/``
    for a scene inside the checkout (``scene_folder``; a scene built in code counts from the working
    folder); else the user's cache folder, ``$XDG_CACHE_HOME/shockfem/meshes`` (``~/.cache/...`` when
    unset, the XDG base directory specification), so that a scene run from elsewhere never writes
    into the checkout."""
    if os.environ.get("SHOCKFEM_MESH_CACHE"):
        return os.environ["SHOCKFEM_MESH_CACHE"]
    checkout = os.path.dirname(os.path.dirname(os.path.dirname(os.path.realpath(__file__))))   # shockfem/geometry/
    repo_meshes = os.path.join(checkout, "meshes")
    folder = os.path.realpath(scene_folder or os.getcwd())
    if os.path.isdir(repo_meshes) and os.path.commonpath([folder, checkout]) == checkout:
        return repo_meshes
    user_cache = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return os.path.join(user_cache, "shockfem", "meshes")


def _file_stamp(path: str | None) -> str | None:
    """Content hash of a body's mesh file (so an edited file is remeshed)."""
    if not path:
        return None
    with open(path, "rb") as fh:
        return hashlib.sha256(fh.read()).hexdigest()[:16]


def mesh_key(scene: Scene) -> str:
    """Hash of everything that determines the mesh (shapes, sizes, placement, files, element, gmsh)."""
    import gmsh
    desc = {"v": MESH_FORMAT_VERSION, "gmsh": gmsh.__version__, "kinematics": scene.kinematics,
            "element": scene.element, "curve": scene.curve_elements,
            "bodies": [(b.name, b.shape, sorted(b.dims.items()), b.element_size, b.position,
                        _file_stamp(b.mesh_file), sorted(b.regions.items()), b.refine, b.orientation)
                       for b in scene.bodies]}
    return hashlib.sha256(json.dumps(desc, sort_keys=True).encode()).hexdigest()[:16]


# gmsh element types of the cells and facets shockfem meshes with (first order only)
CELL_TYPES = {"tri": 2, "quad": 3, "tet": 4, "hex": 5}
FACET_TYPES = {"tri": 1, "quad": 1, "tet": 2, "hex": 3}


@dataclass
class BodyMesh:
    """One body's mesh, taken out of its own gmsh model: nodes, cells and region facets."""
    coords: np.ndarray                  # (nodes, 3)
    node_tags: np.ndarray               # gmsh tags of the nodes
    cells: np.ndarray                   # (cells, nodes per cell) node tags
    regions: dict[str, np.ndarray]      # region name -> (facets, nodes per facet) node tags


def _elements(dim: int, entities, gmsh_type: int) -> np.ndarray:
    import gmsh
    nodes = [gmsh.model.mesh.getElementsByType(gmsh_type, e)[1] for e in entities]
    nodes = [n for n in nodes if len(n)]
    _, _, _, per_element, *_ = gmsh.model.mesh.getElementProperties(gmsh_type)
    return np.concatenate(nodes).reshape(-1, per_element) if nodes else np.zeros((0, per_element), dtype=np.int64)


def _reset_options():
    """gmsh options are global: every body starts from gmsh's defaults of the options a body sets, and a
    process that goes on to use gmsh itself finds them so after a mesh (a quad body's full-quad
    recombination left set made a user's own recombined plate mesh lose cells)."""
    import gmsh
    for name, value in (("Mesh.Algorithm", 6), ("Mesh.Algorithm3D", 1), ("Mesh.RecombineAll", 0),
                        ("Mesh.RecombinationAlgorithm", 1), ("Mesh.SubdivisionAlgorithm", 0),
                        ("Mesh.MeshSizeMax", 1e22), ("Mesh.MeshSizeMin", 0.0),
                        ("Mesh.MeshSizeFromCurvature", 0), ("Mesh.MeshSizeExtendFromBoundary", 1),
                        ("Mesh.MeshSizeFromPoints", 1)):
        gmsh.option.setNumber(name, value)


# Elements round a full circle on curved faces, whatever the element size (the scene's curve_elements,
# default 24): keeps a small orifice or a fillet round (and the volume within 0.5%) at a coarse element
# size.


def _draw_part(body, gdim: int, element: str, curve: int):
    """A catalogued part from its (r, z) outline with gmsh's OCC kernel: unstructured quads
    (frontal-Delaunay + full-quad recombination) or triangles in 2D, tetrahedra in 3D, or
    hexahedra by splitting each tetrahedron in four (drawn at twice the size, so the hexes come
    out at the element size; their shape is poorer than a structured mesh's, which the quality
    report shows)."""
    from ..parts.catalog import PARTS
    from .outline import draw
    origin = (0.0, body.position[1], 0.0) if gdim == 2 else tuple(body.position)
    entities, regions = draw(PARTS[body.shape], body.dims, gdim, origin)
    scale = _mesh_options(body, element, curve)
    if body.refine:
        _refinement_field(body, regions, gdim, scale)
    return entities, regions


def _refinement_field(body, regions: dict, gdim: int, scale: float):
    """Element size growing linearly from ``size`` on each refined region to the body's element
    size ``distance`` away (gmsh Distance + Threshold fields, the smallest wins)."""
    import gmsh
    field = gmsh.model.mesh.field
    thresholds = []
    for region, size, distance in body.refine:
        d = field.add("Distance")
        field.setNumbers(d, "CurvesList" if gdim == 2 else "SurfacesList", regions[region])
        field.setNumber(d, "Sampling", 100)
        t = field.add("Threshold")
        field.setNumber(t, "InField", d)
        field.setNumber(t, "SizeMin", scale * size)
        field.setNumber(t, "SizeMax", scale * body.element_size)
        field.setNumber(t, "DistMin", 0.0)
        field.setNumber(t, "DistMax", distance)
        thresholds.append(t)
    smallest = field.add("Min")
    field.setNumbers(smallest, "FieldsList", thresholds)
    field.setAsBackgroundMesh(smallest)
    gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)


def _mesh_options(body, element: str, curve: int) -> float:
    """Element size and type options of one body's gmsh mesh; returns the size scale (hexes come
    from splitting tetrahedra drawn at twice the size)."""
    import gmsh
    scale = 2.0 if element == "hex" else 1.0
    gmsh.option.setNumber("Mesh.MeshSizeMax", scale * body.element_size)
    gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", curve)
    gmsh.option.setNumber("Mesh.MeshSizeFromPoints", 0)
    if element == "quad":
        gmsh.option.setNumber("Mesh.Algorithm", 8)
        gmsh.option.setNumber("Mesh.RecombineAll", 1)
        gmsh.option.setNumber("Mesh.RecombinationAlgorithm", 2)
    if element == "hex":
        gmsh.option.setNumber("Mesh.SubdivisionAlgorithm", 2)
    return scale


def _import_cad(body, gdim: int, element: str, curve: int):
    """A STEP file through gmsh's OCC kernel, converted to metres, meshed at the body's element
    size; its faces (edges in 2D) named by the scene's ``regions`` tags."""
    import gmsh
    _reset_options()
    gmsh.option.setString("Geometry.OCCTargetUnit", "M")
    try:
        gmsh.model.occ.importShapes(body.mesh_file)
        gmsh.model.occ.synchronize()
    except Exception as e:                   # gmsh raises a bare Exception with its own message
        raise ModelError(f"body {body.name}: gmsh cannot read {body.mesh_file}: {e}") from None
    finally:
        gmsh.option.setString("Geometry.OCCTargetUnit", "")
    entities = [tag for _, tag in gmsh.model.getEntities(gdim)]
    if not entities:
        raise ModelError(f"body {body.name}: {body.mesh_file} has no {'solid' if gdim == 3 else 'face'} to mesh "
                         f"for a {gdim}D scene")
    faces = {tag for _, tag in gmsh.model.getEntities(gdim - 1)}
    for name, tags in body.regions.items():
        missing = [t for t in tags if t not in faces]
        if missing:
            raise ModelError(f"body {body.name}: {body.mesh_file} has no {'face' if gdim == 3 else 'edge'} "
                             f"{missing} (region '{name}'); it has {sorted(faces)}: fix bodies.regions")
    _mesh_options(body, element, curve)
    _generate(body, gdim, element)
    _reset_options()
    return entities, {name: list(tags) for name, tags in body.regions.items()}


def _even_curves():
    """gmsh's full-quad recombination halves every curve's segments (it meshes at twice the size and
    splits each quadrangle in four) and refuses a curve with an odd count ("1D mesh cannot be divided
    by 2").  Mesh the curves and give each odd one a segment more."""
    import gmsh
    gmsh.model.mesh.generate(1)
    for _, curve in gmsh.model.getEntities(1):
        segments = sum(len(e) for e in gmsh.model.mesh.getElements(1, curve)[1])
        if segments % 2:
            gmsh.model.mesh.setTransfiniteCurve(curve, segments + 2)
    gmsh.model.mesh.clear()


def _generate(body, gdim: int, element: str):
    """gmsh's mesh of the current model; its failures become a ModelError naming the body."""
    import gmsh
    try:
        gmsh.model.mesh.generate(gdim)
    except Exception as e:                   # gmsh raises a bare Exception with its own message
        if element == "quad" and "divided by 2" in str(e):
            gmsh.model.mesh.clear()
            try:
                _even_curves()
                gmsh.model.mesh.generate(gdim)
                return
            except Exception:
                pass
        raise ModelError(f"body {body.name}: gmsh cannot mesh it with {element} elements of "
                         f"{body.element_size * 1e3:.3g} mm ({e}); try a smaller element_size, or another "
                         "scene.element") from None


def _draw_body(body, gdim: int, element: str, curve: int) -> BodyMesh:
    """Mesh one body in a gmsh model of its own (current model) and take its mesh out.

    Each body gets its own model so that gmsh's coherence, which the built-in kernel needs to
    join the pieces of one part, never joins two bodies that touch (a striker resting on its
    target would be glued to it)."""
    import gmsh
    if body.shape == "mesh" and body.mesh_file.lower().endswith(CAD_FILES):
        entities, regions = _import_cad(body, gdim, element, curve)
    elif body.shape == "mesh":
        gmsh.merge(body.mesh_file)
        entities = [tag for _, tag in gmsh.model.getEntities(gdim)]
        regions = {}
        for name, tag in body.regions.items():
            if tag not in [t for _, t in gmsh.model.getPhysicalGroups(gdim - 1)]:
                raise ModelError(f"body {body.name}: {body.mesh_file} has no physical group of dimension "
                                 f"{gdim - 1} with tag {tag} (for region '{name}'); fix bodies.regions")
            regions[name] = list(gmsh.model.getEntitiesForPhysicalGroup(gdim - 1, tag))
    else:
        _reset_options()
        structured = draw.structured_builder(body, gdim)
        if structured is not None:
            builder, dims = structured
            position = body.position if gdim == 3 else (body.position[0], body.position[1])
            entities, regions = builder(dims, position, body.element_size, element in ("quad", "hex"))
            gmsh.model.geo.synchronize()
        else:
            entities, regions = _draw_part(body, gdim, element, curve)
        _generate(body, gdim, element)
        _reset_options()
    node_tags, coords, _ = gmsh.model.mesh.getNodes()
    coords = coords.reshape(-1, 3)
    cells = _elements(gdim, entities, CELL_TYPES[element])
    if not len(cells):
        found = sorted({int(t) for e in entities for t in gmsh.model.mesh.getElementTypes(gdim, e)})
        raise ModelError(f"body {body.name}: no {element} cells in its mesh (gmsh element types found: {found}); "
                         f"set scene.element to match the mesh, or mesh the file with {element} cells")
    if body.shape == "mesh":
        coords = coords + np.array(list(body.position) + [0.0] * (3 - gdim))
    if body.orientation is not None:
        # turned about its position: x = p + R (X - p)
        p = np.array(list(body.position) + [0.0] * (3 - gdim))
        coords = p + (coords - p) @ np.reshape(body.orientation, (3, 3)).T
    # only the nodes of cells (a construction point, such as an arc's centre, also gets a node)
    used = np.isin(node_tags, cells)
    node_tags, coords = node_tags[used], coords[used]
    return BodyMesh(coords, node_tags.astype(np.int64), cells.astype(np.int64),
                    {name: _elements(gdim - 1, ents, FACET_TYPES[element]).astype(np.int64)
                     for name, ents in regions.items()})


def _build_gmsh_model(scene: Scene) -> dict[str, int]:
    """Mesh every body on its own, then gather them, disconnected, into the current gmsh model as
    discrete entities with physical groups (body number per cell, region number per facet);
    returns region name -> facet tag."""
    import gmsh
    gdim = scene.gdim
    combined = gmsh.model.getCurrent()
    meshes = []
    for i, body in enumerate(scene.bodies):
        gmsh.model.add(f"{combined}-body{i}")
        meshes.append(_draw_body(body, gdim, scene.element, scene.curve_elements))
        gmsh.model.remove()
    gmsh.model.setCurrent(combined)
    region_ids: dict[str, int] = {}
    node_offset = element_offset = 0
    cell_type, facet_type = CELL_TYPES[scene.element], FACET_TYPES[scene.element]
    for i, (body, bm) in enumerate(zip(scene.bodies, meshes)):
        # renumber the body's nodes 1..n after the previous bodies'
        renumber = np.zeros(bm.node_tags.max() + 1, dtype=np.int64)
        renumber[bm.node_tags] = node_offset + 1 + np.arange(len(bm.node_tags))
        volume = gmsh.model.addDiscreteEntity(gdim)
        gmsh.model.mesh.addNodes(gdim, volume, renumber[bm.node_tags], bm.coords.ravel())
        gmsh.model.mesh.addElementsByType(volume, cell_type, element_offset + 1 + np.arange(len(bm.cells)),
                                          renumber[bm.cells].ravel())
        element_offset += len(bm.cells)
        node_offset += len(bm.node_tags)
        gmsh.model.addPhysicalGroup(gdim, [volume], i + 1)
        gmsh.model.setPhysicalName(gdim, i + 1, body.name)
        for rname, facets in bm.regions.items():
            rid = len(region_ids) + 1
            region_ids[f"{body.name}.{rname}"] = rid
            surface = gmsh.model.addDiscreteEntity(gdim - 1)
            gmsh.model.mesh.addElementsByType(surface, facet_type, element_offset + 1 + np.arange(len(facets)),
                                              renumber[facets].ravel())
            element_offset += len(facets)
            gmsh.model.addPhysicalGroup(gdim - 1, [surface], rid)
            gmsh.model.setPhysicalName(gdim - 1, rid, f"{body.name}.{rname}")
    return region_ids


def build_mesh(scene: Scene, comm=MPI.COMM_WORLD, cache_dir: str | None = None,
               log=print) -> MeshedScene:
    """Mesh (or load from the cache) the scene's bodies and distribute the mesh over ``comm``."""
    import gmsh

    cache_dir = cache_dir or default_cache_dir(scene.folder)
    key = mesh_key(scene)
    msh_path = os.path.join(cache_dir, f"{scene.name}-{key}.msh")
    regions_path = msh_path[:-4] + ".regions.json"
    region_ids = None
    if comm.rank == 0:
        if not gmsh.isInitialized():
            gmsh.initialize(interruptible=False)
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.clear()
        if os.path.exists(msh_path) and os.path.exists(regions_path):
            gmsh.open(msh_path)
            with open(regions_path) as fh:
                region_ids = json.load(fh)
            log(f"mesh: reused cached {msh_path}")
        else:
            gmsh.model.add(scene.name)
            region_ids = _build_gmsh_model(scene)
            os.makedirs(cache_dir, exist_ok=True)
            # each file written beside and renamed into place, the regions first: a run started beside
            # this one (a study's table on both cores) that finds the mesh finds both files whole
            tmp = f"{regions_path}.tmp{os.getpid()}"
            with open(tmp, "w") as fh:
                json.dump(region_ids, fh, indent=1)
            os.replace(tmp, regions_path)
            tmp = msh_path + f".tmp{os.getpid()}.msh"
            gmsh.write(tmp)
            os.replace(tmp, msh_path)
            # the run goes on from the file, as every later run will: the file's coordinates are rounded,
            # and a run must be the same whether it meshed or found the mesh cached (a run resumed from a
            # checkpoint finds it cached, and must see the mesh it was checkpointed on)
            gmsh.clear()
            gmsh.open(msh_path)
            log(f"mesh: wrote {msh_path}")
    region_ids = comm.bcast(region_ids, root=0)
    mesh, cell_tags, facet_tags = compat.mesh_from_gmsh(gmsh.model, comm, 0, scene.gdim)
    if comm.rank == 0:
        gmsh.clear()
    mesh.name = "mesh"
    return MeshedScene(mesh, cell_tags, facet_tags, region_ids, msh_path)


def region_facets(meshed: MeshedScene, region: str) -> np.ndarray:
    """Local facet indices of a named region ("body.region")."""
    rid = meshed.region_ids[region]
    return meshed.facet_tags.indices[meshed.facet_tags.values == rid]

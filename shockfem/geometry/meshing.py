"""From a scene's bodies to one distributed dolfinx mesh with body and region tags.

All bodies go into one gmsh model and so into one dolfinx mesh: one function space,
one dofmap and one kernel call serve every body, and the bodies stay disconnected (they
share no nodes).  Cell tags are body numbers (1, 2, ...); facet tags number every named
region ``body.region``.  The gmsh file is cached in ``meshes/`` under a hash of what
determines it, so rerunning a scene does not remesh.
"""
from __future__ import annotations

import hashlib
import json
import os
from dataclasses import dataclass

import numpy as np
from mpi4py import MPI

from ..scene import Scene
from . import parts

MESH_FORMAT_VERSION = 1   # bump when part drawing changes, to invalidate caches


@dataclass
class MeshedScene:
    mesh: object                 # dolfinx.mesh.Mesh
    cell_tags: object            # MeshTags: body number (1-based, scene order) per cell
    facet_tags: object           # MeshTags: region number per boundary facet
    region_ids: dict[str, int]   # "body.region" -> facet tag value
    source: str                  # path of the gmsh file used


def default_cache_dir() -> str:
    here = os.path.dirname(os.path.abspath(__file__))
    repo_meshes = os.path.normpath(os.path.join(here, "..", "..", "meshes"))
    return os.environ.get("SHOCKFEM_MESH_CACHE", repo_meshes)


def mesh_key(scene: Scene) -> str:
    """Hash of everything that determines the mesh (shapes, sizes, placement, element, gmsh)."""
    import gmsh
    desc = {"v": MESH_FORMAT_VERSION, "gmsh": gmsh.__version__, "kinematics": scene.kinematics,
            "element": scene.element,
            "bodies": [(b.name, b.shape, sorted(b.dims.items()), b.element_size, b.position)
                       for b in scene.bodies]}
    return hashlib.sha256(json.dumps(desc, sort_keys=True).encode()).hexdigest()[:16]


def _build_gmsh_model(scene: Scene) -> dict[str, int]:
    """Draw every body into the current gmsh model; returns region name -> facet tag."""
    import gmsh
    gdim = scene.gdim
    structured = scene.element in ("quad", "hex")
    drawn = []
    for body in scene.bodies:
        builder = parts.BUILDERS[(body.shape, gdim)]
        position = body.position if gdim == 3 else (body.position[0], body.position[1])
        drawn.append(builder(body.dims, position, body.element_size, structured))
    gmsh.model.geo.synchronize()
    region_ids: dict[str, int] = {}
    for i, (body, (entities, regions)) in enumerate(zip(scene.bodies, drawn)):
        gmsh.model.addPhysicalGroup(gdim, entities, i + 1)
        gmsh.model.setPhysicalName(gdim, i + 1, body.name)
        for rname, tags in regions.items():
            rid = len(region_ids) + 1
            region_ids[f"{body.name}.{rname}"] = rid
            gmsh.model.addPhysicalGroup(gdim - 1, tags, rid)
            gmsh.model.setPhysicalName(gdim - 1, rid, f"{body.name}.{rname}")
    gmsh.model.mesh.generate(gdim)
    return region_ids


def build_mesh(scene: Scene, comm=MPI.COMM_WORLD, cache_dir: str | None = None,
               log=print) -> MeshedScene:
    """Mesh (or load from the cache) the scene's bodies and distribute the mesh over ``comm``."""
    import gmsh
    from dolfinx.io import gmshio

    cache_dir = cache_dir or default_cache_dir()
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
            tmp = msh_path + f".tmp{os.getpid()}.msh"
            gmsh.write(tmp)
            os.replace(tmp, msh_path)
            with open(regions_path, "w") as fh:
                json.dump(region_ids, fh, indent=1)
            log(f"mesh: wrote {msh_path}")
    region_ids = comm.bcast(region_ids, root=0)
    mesh, cell_tags, facet_tags = gmshio.model_to_mesh(gmsh.model, comm, 0, gdim=scene.gdim)
    if comm.rank == 0:
        gmsh.clear()
    mesh.name = "mesh"
    return MeshedScene(mesh, cell_tags, facet_tags, region_ids, msh_path)


def region_facets(meshed: MeshedScene, region: str) -> np.ndarray:
    """Local facet indices of a named region ("body.region")."""
    rid = meshed.region_ids[region]
    return meshed.facet_tags.indices[meshed.facet_tags.values == rid]

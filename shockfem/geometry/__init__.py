"""Geometry: parametric parts drawn in gmsh and the distributed dolfinx mesh of a scene."""
from .meshing import MeshedScene, build_mesh, region_facets

__all__ = ["MeshedScene", "build_mesh", "region_facets"]

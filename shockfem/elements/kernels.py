"""Which compiled pass a mesh runs."""
from __future__ import annotations

from .cells import HEXAHEDRON, QUADRILATERAL, TETRAHEDRON
from .full_integration import stress_divergence_kernel
from .linear_tets import TET_KERNELS
from .one_point_hexes import HEX_KERNELS
from .one_point_quads import QUAD_KERNELS

# the lane passes (``blocks.py``) of the cells that have one, at one point or at their Gauss points
_ONE_POINT = {QUADRILATERAL: QUAD_KERNELS, HEXAHEDRON: HEX_KERNELS}
_GAUSS_POINTS = {TETRAHEDRON: TET_KERNELS}


def element_pass(cell_kind: int, one_point: bool, elastic_only: bool):
    """The pass of a mesh of cells of ``cell_kind`` (``cells.TETRAHEDRON``...), at one point with hourglass
    control (``one_point``: quads and hexes, ``one_point_quads.py``, ``one_point_hexes.py``) or at their Gauss
    points (linear tetrahedra in lanes, ``linear_tets.py``; any other cell through
    ``full_integration.stress_divergence``), in its copy for ``elastic_only`` (``materials.update.is_elastic_only``:
    every row elastic without slots; no law called) or for any law.  All take the same arguments
    (``blocks.PASS_ARGUMENTS``) and return the same."""
    passes = (_ONE_POINT if one_point else _GAUSS_POINTS).get(cell_kind)
    if passes is None:
        if one_point:
            raise ValueError(f"no one-point pass for cell kind {cell_kind}: quadrilaterals and hexahedra only")
        return stress_divergence_kernel(elastic_only)
    return passes[bool(elastic_only)]

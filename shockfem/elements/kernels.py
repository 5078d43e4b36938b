"""Which compiled pass a mesh runs."""
from __future__ import annotations

from .cells import TETRAHEDRON
from .full_integration import stress_divergence_kernel
from .linear_tets import TET_KERNELS
from .one_point_hexes import HEX_KERNELS
from .one_point_quads import QUAD_KERNELS


def one_point_kernel(gdim: int, elastic_only: bool):
    """The one-point kernel of a mesh of dimension ``gdim``: ``one_point_quads.quad_one_point`` (2) or
    ``one_point_hexes.hex_one_point`` (3), in its copy for ``elastic_only`` (``materials.update.is_elastic_only``:
    every row elastic without slots; no law called) or for any law.  All take the same arguments, but
    for the quads' ``axisymmetric`` and ``thickness``, and return the same."""
    return (QUAD_KERNELS if gdim == 2 else HEX_KERNELS)[bool(elastic_only)]


def cell_pass(cell_kind: int, elastic_only: bool):
    """The pass of a mesh of cells of ``cell_kind`` (``cells.TETRAHEDRON``...) at their Gauss points (no hourglass control): linear tetrahedra in
    lanes (``linear_tets.tet_pass``), any other cell through ``full_integration.stress_divergence``; both
    take the same arguments and return the same, in their copy for ``elastic_only`` or for any law."""
    return TET_KERNELS[bool(elastic_only)] if cell_kind == TETRAHEDRON else stress_divergence_kernel(elastic_only)

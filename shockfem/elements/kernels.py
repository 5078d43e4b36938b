"""Which compiled one-point pass a mesh runs."""
from __future__ import annotations

from .one_point_hexes import HEX_KERNELS
from .one_point_quads import QUAD_KERNELS


def one_point_kernel(gdim: int, elastic_only: bool):
    """The one-point kernel of a mesh of dimension ``gdim``: ``one_point_quads.quad_one_point`` (2) or
    ``one_point_hexes.hex_one_point`` (3), in its copy for ``elastic_only`` (``materials.update.is_elastic_only``:
    every row elastic without slots; no law called) or for any law.  All take the same arguments, but
    for the quads' ``axisymmetric`` and ``thickness``, and return the same."""
    return (QUAD_KERNELS if gdim == 2 else HEX_KERNELS)[bool(elastic_only)]

"""Compile CPU of each element pass in its two copies (elastic only, any law), each alone, from the cache
numba is given (run it with an empty ``NUMBA_CACHE_DIR``): a small block of cells of each kind, one call.

    NUMBA_CACHE_DIR=$(mktemp -d) python scripts/pass-compile-time.py

docs/performance.md ("The element passes' block driver") gives the figures.
"""
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "unit", "elements"))
from element_helpers import NO_CURVES, NO_STATE, run_pass, steel_params  # noqa: E402
from shockfem.elements import cells as ec, kernels  # noqa: E402

# (name, cell kind, one point, nodes, dimension, kinematics, hourglass resultants a cell)
PASSES = (("one-point quads", ec.QUADRILATERAL, True, 4, 2, ec.AXISYMMETRIC, 2),
          ("one-point hexes", ec.HEXAHEDRON, True, 8, 3, ec.THREE_D, 12),
          ("linear tets", ec.TETRAHEDRON, False, 4, 3, ec.THREE_D, 0))
n = 40
params = steel_params()
for name, kind, one_point, nodes, gdim, kinematics, modes in PASSES:
    x = np.random.default_rng(1).random((n * nodes, gdim))
    dofmap = np.arange(n * nodes, dtype=np.int32).reshape(n, nodes)
    rule = (np.ones((1, nodes)), np.zeros((1, nodes, gdim)), np.ones(1))
    for elastic_only in (True, False):
        t0 = time.process_time()
        run_pass(kernels.element_pass(kind, one_point, elastic_only), np.arange(n, dtype=np.int32), dofmap,
                 np.zeros(n, np.int32), np.ones(n), x, x, 1e-7, params, NO_CURVES, NO_STATE, np.zeros((n, 1, 6)),
                 np.zeros_like(x), np.zeros((1, 3)), rule=rule, kinematics=kinematics, cell_kind=kind,
                 hourglass=np.zeros((n, modes)), hourglass_coefficient=0.1)
        print(f"{name:16s} {'elastic only' if elastic_only else 'any law':12s} {time.process_time() - t0:6.1f} s CPU",
              flush=True)

"""Every call that depends on the dolfinx version lives here (written for dolfinx 0.5.2).

A move to a newer dolfinx (``dolfinx.la.InsertMode``, ``fem.assemble_vector`` on
arrays, ``io.gmshio`` signatures) should touch this file only.
"""
from __future__ import annotations

import numpy as np
from dolfinx import cpp
from dolfinx.fem import assemble as _assemble
from dolfinx.la import ScatterMode

def assemble_vector_into(b: np.ndarray, form) -> np.ndarray:
    """Add the local (owned + ghost) contributions of a linear form to the array ``b``.

    Ghost entries still need ``reverse_add`` (collective) to reach their owners.
    """
    constants = _assemble.pack_constants(form)
    coefficients = _assemble.pack_coefficients(form)
    cpp.fem.assemble_vector(b, form, constants, coefficients)
    return b


def reverse_add(function) -> None:
    """Collective: add ghost entries of ``function.x`` into their owners' entries."""
    function.x.scatter_reverse(ScatterMode.add)


def versions() -> dict:
    import dolfinx
    import gmsh
    import numba
    import numpy
    import petsc4py
    return {"dolfinx": dolfinx.__version__, "gmsh": gmsh.__version__, "numpy": numpy.__version__,
            "numba": numba.__version__, "petsc4py": petsc4py.__version__}

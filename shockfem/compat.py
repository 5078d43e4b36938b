"""Every call that depends on the dolfinx version lives here (written for dolfinx 0.5.2).

A move to a newer dolfinx should touch this file only: function spaces (``VectorFunctionSpace``
and ``FunctionSpace`` became ``functionspace`` in 0.8), the dofmap's array (``dofmap.list.array``
became a 2D array in 0.7), ``gmshio.model_to_mesh`` (returns a named tuple from 0.9), subspace
collapsing, and the low-level vector assembly.  Calls that have stayed the same since 0.5
(``fem.form``, ``fem.Function``, ``x.array``, ``x.scatter_forward``, ``io.XDMFFile``,
``fem.locate_dofs_topological``, ``fem.dirichletbc``) are used directly.
"""
from __future__ import annotations

import numpy as np
import dolfinx
from dolfinx import cpp, fem
from dolfinx.fem import assemble as _assemble
from dolfinx.la import ScatterMode

# The dolfinx releases this file is written and tested for (Debian 12's python3-dolfinx).
SUPPORTED = ("0.5",)


def check_dolfinx(version: str = dolfinx.__version__) -> None:
    """Raise a clear error when the installed dolfinx is one this file was not written for."""
    if not version.startswith(SUPPORTED):
        raise ImportError(f"shockfem needs dolfinx {' or '.join(v + '.x' for v in SUPPORTED)} (Debian 12's "
                          f"python3-dolfinx 0.5.2); this Python has dolfinx {version}. Run shockfem from the "
                          f"project's venv (make install), or port shockfem/compat.py to this version.")


check_dolfinx()


def vector_space(mesh, degree: int = 1):
    """Continuous Lagrange vectors of ``degree`` on ``mesh`` (one component per geometric dimension)."""
    return fem.VectorFunctionSpace(mesh, ("CG", degree))


def cell_space(mesh):
    """Piecewise constants (DG0): one value per cell, for cell fields and cell data of forms."""
    return fem.FunctionSpace(mesh, ("DG", 0))


def cell_dofs(space, nodes_per_cell: int) -> np.ndarray:
    """(cells, nodes_per_cell) int32: the dofs of every local cell (owned, then ghosts) in ``space``.

    For a vector space these are block (node) numbers; for ``cell_space`` one dof per cell, which
    need not be the cell's index."""
    return np.ascontiguousarray(space.dofmap.list.array.reshape(-1, nodes_per_cell), dtype=np.int32)


def geometry_nodes(mesh, nodes_per_cell: int) -> np.ndarray:
    """(cells, nodes_per_cell): the rows of ``mesh.geometry.x`` of every local cell's nodes (owned, then
    ghosts), in the cell's order (for a first-order mesh, that of a first-order space's dofs)."""
    return mesh.geometry.dofmap.array.reshape(-1, nodes_per_cell)


def set_cell_values(function, values: np.ndarray, num_cells: int) -> None:
    """Write one value per local cell (``values[:num_cells]``) into a ``cell_space`` function through its
    dofmap, then update the ghosts."""
    dofs = cell_dofs(function.function_space, 1)[:num_cells, 0]
    function.x.array[dofs] = values[:num_cells]
    function.x.scatter_forward()


def global_node_numbers(space) -> np.ndarray:
    """The global number of every local node (owned, then ghosts) of a P1 vector ``space``, int64."""
    imap = space.dofmap.index_map
    return imap.local_to_global(np.arange(imap.size_local + imap.num_ghosts, dtype=np.int32))


def collapse(subspace):
    """A collapsed copy of a subspace (one component of a vector space)."""
    collapsed, _ = subspace.collapse()
    return collapsed


def assemble_petsc_matrix(form, bcs, diagonal: float):
    """The assembled PETSc matrix of a bilinear form, rows and columns of the ``bcs`` dofs zeroed with
    ``diagonal`` on the diagonal."""
    import dolfinx.fem.petsc as fem_petsc
    A = fem_petsc.assemble_matrix(form, bcs=bcs, diagonal=diagonal)
    A.assemble()
    return A


def mesh_from_gmsh(model, comm, rank: int, gdim: int):
    """(mesh, cell tags, facet tags) from the gmsh model held on ``rank``, distributed over ``comm``."""
    from dolfinx.io import gmshio
    return gmshio.model_to_mesh(model, comm, rank, gdim=gdim)

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

"""``compat.py``, the one place of dolfinx-version-specific calls: the version check and cell values
written through the DG0 dofmap."""
import numpy as np
import pytest
import ufl
from dolfinx import fem, mesh
from mpi4py import MPI

from shockfem import compat


def test_an_unsupported_dolfinx_is_named_with_the_fix():
    compat.check_dolfinx("0.5.2")
    with pytest.raises(ImportError, match=r"needs dolfinx 0\.5\.x .* has dolfinx 0\.9\.0.*compat\.py"):
        compat.check_dolfinx("0.9.0")


@pytest.mark.parametrize("cell", [mesh.CellType.quadrilateral, mesh.CellType.triangle])
def test_cell_values_land_on_their_cells(cell):
    """Cell c gets its midpoint's x: then int f dx = sum_c x_c |c| = int x dx = 1/2 on the unit square
    exactly (x is linear, so its cell mean is its midpoint value); a value written to another cell's
    dof would break the sum."""
    m = mesh.create_unit_square(MPI.COMM_WORLD, 7, 5, cell)
    tdim = m.topology.dim
    num_cells = m.topology.index_map(tdim).size_local
    x_mid = mesh.compute_midpoints(m, tdim, np.arange(num_cells, dtype=np.int32))[:, 0]
    f = fem.Function(compat.cell_space(m))
    compat.set_cell_values(f, x_mid, num_cells)
    total = m.comm.allreduce(fem.assemble_scalar(fem.form(f * ufl.dx)), op=MPI.SUM)
    assert total == pytest.approx(0.5, rel=1e-12)

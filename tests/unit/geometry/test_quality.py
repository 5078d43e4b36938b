"""Scaled Jacobian and aspect ratio on cells whose values are known by hand."""
import numpy as np
import pytest

from shockfem.geometry.quality import aspect_ratio, scaled_jacobian

SQUARE = np.array([[[0, 0], [1, 0], [0, 1], [1, 1]]], float)           # dolfinx order 0-1-3-2 around
CUBE = np.array([[[i, j, k] for k in (0, 1) for j in (0, 1) for i in (0, 1)]], float)
TET = np.array([[[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]]], float)      # regular
TRI = np.array([[[0, 0], [1, 0], [0.5, np.sqrt(3) / 2]]])


@pytest.mark.parametrize("cell, x", [("quadrilateral", SQUARE), ("hexahedron", CUBE), ("tetrahedron", TET),
                                     ("triangle", TRI)])
def test_ideal_cells_score_one_either_way_round(cell, x):
    assert scaled_jacobian(x, cell)[0] == pytest.approx(1.0)
    mirrored = x.copy()
    mirrored[..., 0] *= -1               # gmsh may number a cell the other way round
    assert scaled_jacobian(mirrored, cell)[0] == pytest.approx(1.0)


def test_sheared_and_folded_cells():
    sheared = SQUARE.copy()
    sheared[0, 2:, 0] += 1.0             # top edge moved right by the height: 45 degree corners
    assert scaled_jacobian(sheared, "quadrilateral")[0] == pytest.approx(np.sqrt(0.5))
    bowtie = SQUARE[:, [0, 1, 3, 2]]     # corners 2 and 3 swapped: the quad folds over itself
    assert scaled_jacobian(bowtie, "quadrilateral")[0] < 0.0
    flat_hex = CUBE.copy()
    flat_hex[0, 4:, 2] = 0.0             # top face pressed onto the bottom
    assert scaled_jacobian(flat_hex, "hexahedron")[0] == pytest.approx(0.0)


def test_aspect_ratio():
    long_quad = SQUARE * np.array([10.0, 1.0])
    assert aspect_ratio(long_quad, "quadrilateral")[0] == pytest.approx(10.0)
    assert aspect_ratio(TET, "tetrahedron")[0] == pytest.approx(1.0)

"""Kinematics as a choice of strain operator and measure weight, not three solvers.

* axisymmetric: coordinates (r, z) = (x[0], x[1]); hoop strain u_r / r; integrals carry
  the weight 2 pi r, so masses and forces are those of the whole 360-degree body.
* plane strain: out-of-plane strain zero; integrals carry the scene's ``thickness``.
* 3d: nothing added.

The UFL forms here are the reference definitions; the compiled kernel in
``elements/full_integration.py`` is checked against ``internal_force_form`` in the tests.
"""
from __future__ import annotations

import math

import basix
import numpy as np
import ufl

from ..elements.cells import AXISYMMETRIC, HEXAHEDRON, PLANE_STRAIN, QUADRILATERAL, TETRAHEDRON, THREE_D, TRIANGLE

CODES = {"plane-strain": PLANE_STRAIN, "axisymmetric": AXISYMMETRIC, "3d": THREE_D}
CELL_KINDS = {"triangle": TRIANGLE, "quadrilateral": QUADRILATERAL, "tetrahedron": TETRAHEDRON, "hexahedron": HEXAHEDRON}
BASIX_CELLS = {"triangle": basix.CellType.triangle, "quadrilateral": basix.CellType.quadrilateral,
               "tetrahedron": basix.CellType.tetrahedron, "hexahedron": basix.CellType.hexahedron}


def quadrature_degree(cell: str, kinematics: str, integration: str = "full") -> int:
    """Degree of the Gauss rule.  Quads (hexes): one point at the centre for ``reduced``
    integration (with hourglass control, ``elements/one_point.py``), 2x2 (2x2x2) for ``full``,
    the rule Q1 needs.  One point for linear triangles/tetrahedra (constant strain), three
    points for axisymmetric triangles, whose hoop strain u_r/r varies over the cell."""
    if cell in ("quadrilateral", "hexahedron"):
        return 1 if integration == "reduced" else 2
    return 2 if kinematics == "axisymmetric" else 1


def one_point(cell: str, integration: str) -> bool:
    """True when the cells run the one-point kernels (reduced quads and hexes)."""
    return integration == "reduced" and cell in ("quadrilateral", "hexahedron")


def quadrature(cell: str, kinematics: str, integration: str = "full", degree: int = 0):
    """Points, weights, shape functions N (nq, nn) and reference gradients dN (nq, nn, tdim) of the
    solver's rule, or of a rule exact to ``degree``."""
    ct = BASIX_CELLS[cell]
    points, weights = basix.make_quadrature(ct, degree or quadrature_degree(cell, kinematics, integration))
    element = basix.create_element(basix.ElementFamily.P, ct, 1)
    tab = element.tabulate(1, points)
    N = np.ascontiguousarray(tab[0, :, :, 0])
    dN = np.ascontiguousarray(np.moveaxis(tab[1:, :, :, 0], 0, -1))
    return points, np.ascontiguousarray(weights), N, dN


def centre_gradients(cell: str) -> np.ndarray:
    """Reference gradients of the P1 shape functions at the reference cell's centre, (nn, tdim)."""
    ct = BASIX_CELLS[cell]
    centre = basix.geometry(ct).mean(axis=0)[None, :]
    return np.ascontiguousarray(basix.create_element(basix.ElementFamily.P, ct, 1).tabulate(1, centre)[1:, 0, :, 0].T)


def measure_weight(mesh, kinematics: str, thickness: float = 1.0):
    """The factor every volume integral carries: 2 pi r, the plane-strain depth, or 1."""
    if kinematics == "axisymmetric":
        return 2 * math.pi * ufl.SpatialCoordinate(mesh)[0]
    if kinematics == "plane-strain":
        return thickness
    return 1.0


def stress_tensor(sigma6, kinematics: str):
    """The in-plane (2D) or full (3D) stress tensor from the 6 stored components."""
    if kinematics == "3d":
        return ufl.as_matrix([[sigma6[0], sigma6[5], sigma6[4]],
                              [sigma6[5], sigma6[1], sigma6[3]],
                              [sigma6[4], sigma6[3], sigma6[2]]])
    return ufl.as_matrix([[sigma6[0], sigma6[5]], [sigma6[5], sigma6[1]]])


def internal_force_form(sigma6, w, kinematics: str, thickness: float = 1.0):
    """f(w) = int sigma : grad(w) dV (+ sigma_tt w_r / r in axisymmetry), the stress divergence."""
    mesh = w.ufl_function_space().mesh
    integrand = ufl.inner(stress_tensor(sigma6, kinematics), ufl.grad(w))
    if kinematics == "axisymmetric":
        integrand += sigma6[2] * w[0] / ufl.SpatialCoordinate(mesh)[0]
    return integrand * measure_weight(mesh, kinematics, thickness)


def strain_components(u, kinematics: str):
    """(in-plane or 3D small strain tensor, hoop strain or 0) of a displacement ``u``."""
    eps = ufl.sym(ufl.grad(u))
    if kinematics == "axisymmetric":
        return eps, u[0] / ufl.SpatialCoordinate(u.ufl_function_space().mesh)[0]
    return eps, 0


def elastic_energy_form(u, w, lam, mu, kinematics: str, thickness: float = 1.0):
    """k(u, w) = int lam tr eps(u) tr eps(w) + 2 mu eps(u) : eps(w) dV, the hoop strain u_r / r
    counted in axisymmetry (the stiffness of modal analysis; the explicit solver's is the compiled
    kernel)."""
    mesh = u.ufl_function_space().mesh
    eu, hu = strain_components(u, kinematics)
    ew, hw = strain_components(w, kinematics)
    integrand = lam * (ufl.tr(eu) + hu) * (ufl.tr(ew) + hw) + 2 * mu * (ufl.inner(eu, ew) + hu * hw)
    return integrand * measure_weight(mesh, kinematics, thickness)


def inertia_form(u, w, rho, kinematics: str, thickness: float = 1.0):
    """m(u, w) = int rho u . w dV (the consistent mass)."""
    mesh = u.ufl_function_space().mesh
    return rho * ufl.dot(u, w) * measure_weight(mesh, kinematics, thickness)

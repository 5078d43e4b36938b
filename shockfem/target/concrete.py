"""Concrete's resistance to a penetrating nose: Forrestal's cavity-expansion law, facet by facet.

Forrestal et al. (1994) fit the normal stress a concrete target puts on a nose surface moving into it
with the normal speed v_n (the spherical cavity-expansion solution, incompressible, B = 1):

    sigma_n = S f'c + rho v_n^2        on a facet advancing into the target (v_n > 0), 0 behind it,

with f'c the unconfined compressive strength, rho the target's density and S a constant of the
strength, S = 82.6 (f'c / 1 MPa)^-0.544.  Integrated over a tangent ogive of calibre-radius-head psi
moving along its axis at V, the axial force is pi a^2 (S f'c + N rho V^2) with the nose factor

    N = (1 / pi a^2) * integral of n_axial^3 dA = (8 psi - 1) / (24 psi^2)

(the cubic: one factor from v_n = V n_axial squared, one from projecting the normal force on the axis),
so the facet law and the white paper's axial law are one law: ``shockfem verify penetration`` checks the
quadrature.  This module is the one place for S, N and sigma_n; ``penetration/forrestal.py`` builds the
closed-form depth on them.
"""
from __future__ import annotations

import math

from numba import vectorize


def strength_factor(fc: float) -> float:
    """S = 82.6 (f'c / 1 MPa)^-0.544, f'c the unconfined compressive strength [Pa] (Forrestal's fit)."""
    return 82.6 * (fc / 1e6) ** -0.544


def nose_factor(crh: float) -> float:
    """N = (8 psi - 1) / (24 psi^2) of a tangent ogive of ``crh`` calibre-radius-head psi."""
    return (8 * crh - 1) / (24 * crh * crh)


@vectorize(["float64(float64, float64, float64)"], cache=True)
def normal_stress(strength, density, normal_speed):
    """sigma_n = S f'c + rho v_n^2 where the surface advances into the target (v_n > 0), else 0 (the
    target separates from a receding surface).  ``strength`` is S f'c [Pa].  A numba ufunc: numpy arrays
    and numbers from Python, and numbers in the target's compiled step."""
    return strength + density * normal_speed * normal_speed if normal_speed > 0.0 else 0.0


def crater_law(mass: float, radius: float, strength: float, density: float, nose: float, speed: float,
               depth: float) -> tuple[float, float]:
    """Forrestal's crater: the axial force rises linearly with the nose's depth, F = c z, over the crater
    (``depth``, Forrestal's 4a: two calibres) to meet the tunnel law there.  Energy gives the speed
    leaving it, V1^2 = (m Vs^2 - pi a^2 k S f'c) / (m + pi a^2 k N rho), k the crater's depth (4 pi a^3
    for Forrestal's), and c = pi a^2 (S f'c + N rho V1^2) / k.  Returns (c [N/m], V1^2 [m^2/s^2], <= 0 if
    the projectile stops in the crater).  ``strength`` is S f'c [Pa], ``nose`` is N, ``speed`` Vs."""
    area = math.pi * radius * radius
    v1_squared = (mass * speed ** 2 - area * depth * strength) / (mass + area * depth * nose * density)
    c = area * (strength + nose * density * max(v1_squared, 0.0)) / depth
    return c, v1_squared

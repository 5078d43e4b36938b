"""Forrestal's concrete-penetration law (Forrestal et al. 1994; the form checked against Li & Chen 2003).

Beyond a crater about two calibres deep the target resists an ogive-nosed projectile of radius a with
an axial force F = pi a^2 (S f'c + N rho V^2): a strength term (S, a constant of the unconfined
strength f'c) and an inertial term (N, a constant of the nose's shape).  Here are the law's pieces
and its closed-form depth of penetration; ``shockfem verify forrestal`` checks the depth against the
published data point.
"""
from __future__ import annotations

import math


def strength_factor(fc: float) -> float:
    """S = 82.6 (f'c / 1 MPa)^-0.544, f'c the unconfined compressive strength [Pa]."""
    return 82.6 * (fc / 1e6) ** -0.544


def nose_factor(crh: float) -> float:
    """N = (8 psi - 1) / (24 psi^2) of a tangent ogive of ``crh`` calibre-radius-head psi."""
    return (8 * crh - 1) / (24 * crh * crh)


def resisting_stress(fc: float, density: float, speed: float, crh: float) -> float:
    """The mean axial stress on the nose, S f'c + N rho V^2 [Pa]: the confinement a concrete target
    applies at ``speed`` (rho the target's density)."""
    return strength_factor(fc) * fc + nose_factor(crh) * density * speed * speed


def tunnel_force(radius: float, fc: float, density: float, speed: float, crh: float) -> float:
    """F = pi a^2 (S f'c + N rho V^2) [N] in the tunnelling region."""
    return math.pi * radius * radius * resisting_stress(fc, density, speed, crh)


def tunnel_entry_speed_squared(mass: float, radius: float, fc: float, density: float, speed: float,
                               crh: float) -> float:
    """V1^2 = (m Vs^2 - 4 pi a^3 S f'c) / (m + 4 pi a^3 N rho): the square of the speed leaving the
    crater (4a deep, the force rising linearly with depth) for the tunnel; <= 0 if it stops in it."""
    S, N = strength_factor(fc), nose_factor(crh)
    a3 = radius ** 3
    return (mass * speed ** 2 - 4 * math.pi * a3 * S * fc) / (mass + 4 * math.pi * a3 * N * density)


def depth(mass: float, radius: float, fc: float, density: float, speed: float, crh: float) -> float:
    """The depth of penetration [m] of a rigid projectile striking at ``speed``: the crater and the
    tunnel, P = m / (2 pi a^2 rho N) ln(1 + N rho V1^2 / (S f'c)) + 4a."""
    S, N = strength_factor(fc), nose_factor(crh)
    a = radius
    v1_squared = tunnel_entry_speed_squared(mass, radius, fc, density, speed, crh)
    if v1_squared <= 0:
        raise ValueError(f"the projectile stops in the crater at {speed:g} m/s: the tunnel law does not apply")
    return mass / (2 * math.pi * a * a * density * N) * math.log(1 + N * density * v1_squared / (S * fc)) + 4 * a

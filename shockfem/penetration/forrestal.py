"""Forrestal's concrete-penetration law for a rigid projectile (Forrestal et al. 1994; the form checked
against Li & Chen 2003): the white paper's engineering model.

Beyond a crater two calibres (4a) deep the target resists an ogive-nosed projectile of radius a with
an axial force F = pi a^2 (S f'c + N rho V^2); in the crater the force rises linearly with depth.  The
law's pieces (S, N, the crater) are ``target/concrete.py``'s, where the finite-element load applies
them facet by facet; here are the rigid body's axial force and its closed-form depth of penetration.
``shockfem verify forrestal`` checks the depth against the published data point.
"""
from __future__ import annotations

import math

from ..target.concrete import crater_law, nose_factor, strength_factor


def resisting_stress(fc: float, density: float, speed: float, crh: float) -> float:
    """The mean axial stress on the nose, S f'c + N rho V^2 [Pa]: the confinement a concrete target
    applies at ``speed`` (rho the target's density)."""
    return strength_factor(fc) * fc + nose_factor(crh) * density * speed * speed


def tunnel_force(radius: float, fc: float, density: float, speed: float, crh: float) -> float:
    """F = pi a^2 (S f'c + N rho V^2) [N] in the tunnelling region."""
    return math.pi * radius * radius * resisting_stress(fc, density, speed, crh)


def tunnel_entry_speed_squared(mass: float, radius: float, fc: float, density: float, speed: float,
                               crh: float) -> float:
    """V1^2, the square of the speed leaving Forrestal's crater (4a deep) for the tunnel; <= 0 if the
    projectile stops in it."""
    return crater_law(mass, radius, strength_factor(fc) * fc, density, nose_factor(crh), speed, 4 * radius)[1]


def depth(mass: float, radius: float, fc: float, density: float, speed: float, crh: float) -> float:
    """The depth of penetration [m] of a rigid ogive of ``crh`` striking at ``speed`` (Forrestal's S)."""
    return depth_of(mass, radius, strength_factor(fc) * fc, density, nose_factor(crh), speed, 4 * radius)


def depth_of(mass: float, radius: float, strength: float, density: float, nose: float, speed: float,
             crater: float) -> float:
    """The depth of penetration [m] of a rigid projectile of nose factor ``nose`` (N) striking at ``speed``
    a target of ``strength`` S f'c [Pa] whose crater is ``crater`` (k) deep: P = m / (2 pi a^2 rho N)
    ln(1 + N rho V1^2 / (S f'c)) + k (Forrestal's k = 4a)."""
    a = radius
    v1_squared = crater_law(mass, a, strength, density, nose, speed, crater)[1]
    if v1_squared <= 0:
        raise ValueError(f"the projectile stops in the crater at {speed:g} m/s: the tunnel law does not apply")
    return mass / (2 * math.pi * a * a * density * nose) * math.log(1 + nose * density * v1_squared / strength) + crater


def speed_at_depth(z: float, mass: float, radius: float, strength: float, density: float, nose: float,
                   speed: float, crater: float) -> float:
    """The rigid projectile's speed [m/s] when its nose is ``z`` deep: in the crater (z < k, F = c z)
    V^2 = Vs^2 - c z^2 / m; in the tunnel m V dV/dz = -pi a^2 (S f'c + N rho V^2) integrates to
    V^2 = (V1^2 + S f'c / (N rho)) exp(-2 pi a^2 N rho (z - k) / m) - S f'c / (N rho).  0 once stopped.
    ``strength`` is S f'c [Pa], ``nose`` N, ``crater`` k (Forrestal's 4a)."""
    a = radius
    c, v1_squared = crater_law(mass, a, strength, density, nose, speed, crater)
    if z <= crater:
        v2 = speed * speed - c * z * z / mass
    else:
        k = strength / (nose * density)
        v2 = (v1_squared + k) * math.exp(-2 * math.pi * a * a * nose * density * (z - crater) / mass) - k
    return math.sqrt(max(v2, 0.0))

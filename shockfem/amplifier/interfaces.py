"""How hard two amplifier masses press on each other, and what keeps an interface elastic.

Closed forms for one collision of two bodies (reduced mass M* = m_a m_b / (m_a + m_b),
closing speed dv), used by the chain's rigid fidelity and by the study:

* flat faces: the 1D impedance stress dv Z_a Z_b / (Z_a + Z_b) over the smaller face
  (Z = rho c0 A), independent of how long the bodies are;
* a crowned face (radius R on a flat, Hertz): the closing speed at which the material first
  yields, where the peak pressure p0 reaches 1.6 Y (Johnson, Contact Mechanics, 1985, sec. 6.2
  and 11.4);
* a crowned face far above that speed (fully plastic): Johnson's restitution (Contact Mechanics,
  sec. 11.5), a loading at the mean pressure p_m = 3 Y and a Hertzian elastic unloading,
  e = C (Y / E*)^(1/2) (W / (Y R^3))^(-1/8), W = M* dv^2 / 2, C = (18 pi / 5)^(1/2) (3 pi / 4)^(1/8)
  = 3.74 (derived from those two steps; Johnson prints 3.8: check), falling as dv^(-1/4);
* a pad (linear spring k between the faces, bodies rigid): the peak force dv sqrt(k M*), and
  the stiffness that keeps it at a given force, with the pad's travel, stored energy and contact
  duration pi sqrt(M* / k).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

# the peak Hertz pressure at first yield, p0 / Y (von Mises, Poisson's ratio 0.3; Johnson sec. 6.2)
HERTZ_YIELD_PRESSURE = 1.6


def reduced_mass(m_a: float, m_b: float) -> float:
    return m_a * m_b / (m_a + m_b)


def pad_dashpot(zeta: float, stiffness: float, m_a: float, m_b: float) -> float:
    """Dashpot [N s/m] that gives a pad of ``stiffness`` the damping ratio ``zeta`` on two bodies'
    reduced mass, c = 2 zeta sqrt(k M*)."""
    return 2 * zeta * math.sqrt(stiffness * reduced_mass(m_a, m_b))


def flat_face_stress(dv: float, z_a: float, z_b: float, area: float) -> float:
    """Stress [Pa] when two elastic bars of impedances z_a, z_b [kg/s] meet flat at closing speed
    dv [m/s], over the smaller face ``area`` [m^2]."""
    return dv * z_a * z_b / (z_a + z_b) / area


def pad_peak_force(dv: float, stiffness: float, m_star: float) -> float:
    """Peak force [N] of rigid bodies (reduced mass m_star) meeting on an undamped linear pad."""
    return dv * math.sqrt(stiffness * m_star)


@dataclass(frozen=True)
class Pad:
    stiffness: float     # [N/m]
    travel: float        # its largest compression [m]
    energy: float        # stored at the largest compression [J]
    duration: float     # of the contact [s]


def pad_for_force(dv: float, m_star: float, force: float) -> Pad:
    """The stiffest linear pad whose peak force stays at ``force`` [N] when rigid bodies (reduced
    mass m_star) meet on it at closing speed dv: k = (force / dv)^2 / M*."""
    k = (force / dv) ** 2 / m_star
    return Pad(k, force / k, 0.5 * m_star * dv * dv, math.pi * math.sqrt(m_star / k))


def hertz_yield_speed(m_star: float, radius: float, e_star: float, yield_stress: float) -> float:
    """Closing speed [m/s] at which a crowned face of ``radius`` [m] against a flat first yields
    (p0 = 1.6 Y): the contact radius at that pressure a = pi p0 R / (2 E*), the approach
    delta = a^2 / R, the energy stored (8/15) E* sqrt(R) delta^(5/2) = M* v^2 / 2."""
    p0 = HERTZ_YIELD_PRESSURE * yield_stress
    a = math.pi * p0 * radius / (2 * e_star)
    delta = a * a / radius
    energy = 8 / 15 * e_star * math.sqrt(radius) * delta ** 2.5
    return math.sqrt(2 * energy / m_star)


def plastic_restitution(dv: float, m_star: float, radius: float, e_star: float, yield_stress: float) -> float:
    """Restitution of a crowned face of ``radius`` [m] (or a sphere) struck fully plastically at closing
    speed dv [m/s] (module docstring): the energy W = M* dv^2 / 2 indents it at p_m = 3 Y to the contact
    radius a, a^4 = 4 R W / (pi p_m) (a^2 = 2 R delta, the truncated sphere), and the Hertzian unloading
    of that contact returns (3 pi^2 / 10) p_m^2 a^3 / E*, so e^2 = (6 pi / 5) (p_m / E*) R / a.  Valid far
    above the yield onset (``hertz_yield_speed``), where the elastic share of the loading is small."""
    p_m = 3.0 * yield_stress
    a = (4 * radius * 0.5 * m_star * dv * dv / (math.pi * p_m)) ** 0.25
    return math.sqrt(6 * math.pi / 5 * p_m / e_star * radius / a)


def thornton_restitution(dv: float, m_star: float, radius: float, e_star: float, yield_stress: float) -> float:
    """Thornton's restitution of the same impact (J. Appl. Mech. 64 (1997) 383-386): the contact pressure
    capped at the Hertz onset's p_y = 1.6 Y on loading, a Hertzian unloading; with x = V_y / dv (V_y the
    onset's speed, ``hertz_yield_speed``), e = (6 sqrt(3) / 5)^(1/2) (1 - x^2 / 6)^(1/2)
    (x / (x + 2 (6/5 - x^2 / 5)^(1/2)))^(1/4).  Capping the pressure at the onset's, below the fully
    plastic 2.8 to 3 Y, it lets the contact grow wider and so returns less than Johnson's estimate."""
    x = hertz_yield_speed(m_star, radius, e_star, yield_stress) / dv
    return math.sqrt(6 * math.sqrt(3) / 5) * math.sqrt(1 - x * x / 6) * (
        x / (x + 2 * math.sqrt(6 / 5 - x * x / 5))) ** 0.25

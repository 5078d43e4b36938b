"""Wall thickness and weight of the gun's pressure parts: ASME Section VIII Division 1.

UG-27(c)(1), circumferential stress (governs a cylinder): t = P R / (S E - 0.6 P), valid for
P <= 0.385 S E; beyond it, Appendix 1-2(a)(1): t = R (sqrt(Z) - 1), Z = (S E + P) / (S E - P).
UG-32(f), hemispherical head: t = P R / (2 S E - 0.2 P), valid for P <= 0.665 S E.
R is the inside radius, S the allowable stress, E the joint efficiency (1 for seamless pipe and
fully radiographed welds).  No corrosion allowance is added; no wall is thinner than UG-16(b)'s
1/16 in (1.6 mm).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from ..units import PSI

# Allowable tensile stress S at room temperature [Pa], ASME II-D Table 1A as commonly quoted
# (ksi x 6.894757e6), and density [kg/m^3].
MATERIALS = {
    "SA-516-70": {"allowable": 20.0e3 * PSI, "density": 7850.0, "doc": "carbon steel plate (tanks)"},
    "SA-106-B": {"allowable": 17.1e3 * PSI, "density": 7850.0, "doc": "seamless carbon steel pipe"},
    "SA-312-TP304": {"allowable": 20.0e3 * PSI, "density": 8000.0, "doc": "seamless stainless pipe"},
}


# UG-16(b): the minimum thickness of shells and heads after forming [m]
MIN_THICKNESS = 0.0625 * 0.0254


@dataclass
class Shell:
    thickness: float      # [m]
    rule: str             # which paragraph gave it
    hoop_stress: float    # at the design pressure, Lame's inner-wall hoop stress [Pa]
    margin: float         # allowable / hoop stress - 1


def cylinder_thickness(P: float, R: float, S: float, E: float = 1.0) -> Shell:
    """Thickness of a cylinder of inside radius R at pressure P (UG-27 or Appendix 1-2)."""
    if P <= 0.385 * S * E:
        t, rule = P * R / (S * E - 0.6 * P), "UG-27(c)(1)"
    elif P < S * E:
        Z = (S * E + P) / (S * E - P)
        t, rule = R * (math.sqrt(Z) - 1), "Appendix 1-2(a)(1)"
    else:
        raise ValueError(f"pressure {P:.4g} Pa is above S E = {S * E:.4g} Pa: no wall holds it at this allowable")
    if t < MIN_THICKNESS:
        t, rule = MIN_THICKNESS, "UG-16(b) minimum"
    Ro = R + t
    hoop = P * (Ro ** 2 + R ** 2) / (Ro ** 2 - R ** 2)
    return Shell(t, rule, hoop, S / hoop - 1)


def head_thickness(P: float, R: float, S: float, E: float = 1.0) -> float:
    """Hemispherical head of inside radius R (UG-32(f))."""
    if P > 0.665 * S * E:
        raise ValueError(f"pressure {P:.4g} Pa is above 0.665 S E for UG-32(f)")
    return max(P * R / (2 * S * E - 0.2 * P), MIN_THICKNESS)


def max_pressure(material: str, E: float = 1.0) -> float:
    """The highest pressure these rules size a vessel of ``material`` for: a tank's hemispherical
    heads (UG-32(f), 0.665 S E) bind before a cylinder (Appendix 1-2, below S E)."""
    return 0.665 * MATERIALS[material]["allowable"] * E


def barrel_weight(P: float, bore: float, length: float, material: str, E: float = 1.0) -> tuple[Shell, float]:
    m = MATERIALS[material]
    shell = cylinder_thickness(P, bore / 2, m["allowable"], E)
    R = bore / 2
    return shell, m["density"] * math.pi * ((R + shell.thickness) ** 2 - R ** 2) * length


def tank_weight(P: float, volume: float, diameter: float, material: str, E: float = 1.0) -> tuple[Shell, float, float]:
    """A cylindrical tank with hemispherical heads of inside ``diameter`` holding ``volume``:
    (shell, head thickness, weight [kg])."""
    m = MATERIALS[material]
    R = diameter / 2
    L_cyl = max(volume - 4 / 3 * math.pi * R ** 3, 0.0) / (math.pi * R * R)
    shell = cylinder_thickness(P, R, m["allowable"], E)
    t_head = head_thickness(P, R, m["allowable"], E)
    w = m["density"] * (math.pi * ((R + shell.thickness) ** 2 - R ** 2) * L_cyl
                        + 4 / 3 * math.pi * ((R + t_head) ** 3 - R ** 3))
    return shell, t_head, w


def tank_diameter_for(volume: float, aspect: float = 3.0) -> float:
    """Inside diameter of a tank with hemispherical heads holding ``volume`` whose overall
    length is ``aspect`` diameters (aspect >= 1; 1 is a sphere)."""
    # V = pi D^2 / 4 (aspect - 1) D + pi D^3 / 6
    return (volume / (math.pi * (aspect - 1) / 4 + math.pi / 6)) ** (1 / 3)

"""The fluid dashpot's mass as a designer must count it: piston, metering pin, the housing that holds the
peak pressure, and the oil.

    bore wall (Lame, closed ends; Timoshenko & Goodier, Theory of Elasticity, sec. 33; Roark's Formulas
    for Stress and Strain, 7th ed., table 13.5 case 1c), at the bore r = a under pressure p:
        sigma_theta = p (b^2 + a^2) / (b^2 - a^2),  sigma_r = -p,  sigma_z = p a^2 / (b^2 - a^2)
        von Mises  = sqrt(3) p b^2 / (b^2 - a^2)   (sigma_z is the mean of the other two)
    so the outer radius that keeps it at the allowed stress s:  b = a sqrt(k / (k - 1)),
        k = s / (sqrt(3) p), possible only for p < s / sqrt(3)
    floor (a flat plate clamped at the bore under p; Roark table 11.2 case 10b): edge stress
        3 p a^2 / (4 t^2) = s  ->  t = a sqrt(3 p / (4 s))
    pin: the piston's hole is the pin's largest opening a_max; at a stroke s the pin fills
        a_max - a(s) of it: its volume is the integral of that over the stroke.

The allowed stress is the housing steel's yield over a ``safety_factor`` (1: the wall at yield, the
least housing; a pressure-vessel code asks more, e.g. 1.5 on yield in ASME VIII-2's membrane limit) and
a dynamic factor: 2 when the pressure rises in less than the wall's breathing period 2 pi b / c_steel
(a suddenly applied load), else 1 (``liquids-and-machines.md``).  The pressurised bore runs the column and the piston's thickness; the
article's guide beyond it, which holds no pressure, is not counted.
"""
from __future__ import annotations

import math

import numpy as np

from ..scene.library import initial_yield_stress, property_si


def bore_outer_radius(pressure: float, bore: float, allowed: float) -> float:
    """The outer radius [m] at which a thick cylinder of ``bore`` radius holds ``pressure`` [Pa] with its
    von Mises stress at the bore equal to ``allowed`` [Pa]; inf if no wall can."""
    k = allowed / (math.sqrt(3.0) * pressure)
    return bore * math.sqrt(k / (k - 1.0)) if k > 1.0 else math.inf


def bore_von_mises(pressure: float, bore: float, outer: float) -> float:
    """Lame's von Mises stress at the bore of a closed thick cylinder [Pa]."""
    return math.sqrt(3.0) * pressure * outer ** 2 / (outer ** 2 - bore ** 2)


def fixture_mass(design: dict, peak_pressure: float, rise_time: float, steel: str = "high_strength_steel",
                 safety_factor: float = 1.0) -> dict:
    """The dashpot ``design`` (``dashpot_design.dashpot_design``) weighed whole at ``peak_pressure`` [Pa]
    rising in ``rise_time`` [s], its housing of the library metal ``steel``: a dict of the parts [kg],
    the housing's radii [m], the allowed stress and the dynamic factor, and their sum, ``fixture``."""
    rho = property_si(steel, "density", "density")
    E = property_si(steel, "youngs_modulus", "pressure")
    a = design["bore_radius"]
    yield_stress = initial_yield_stress(steel) / safety_factor
    pin = np.array(design["pin"], dtype=float)
    # the breathing period of the wall at a first guess of its radius, then of the wall it gives
    outer = bore_outer_radius(peak_pressure, a, yield_stress)
    factor = 1.0
    for _ in range(3):
        breathing = 2.0 * math.pi * (outer if math.isfinite(outer) else 2 * a) / math.sqrt(E / rho)
        factor = 2.0 if rise_time < breathing else 1.0
        outer = bore_outer_radius(peak_pressure, a, yield_stress / factor)
    allowed = yield_stress / factor
    length = design["column"] + design.get("piston_thickness", 0.015)
    floor = a * math.sqrt(3.0 * peak_pressure / (4.0 * allowed))
    housing = rho * math.pi * ((outer ** 2 - a ** 2) * length + outer ** 2 * floor) if math.isfinite(outer) \
        else math.inf
    pin_volume = float(np.trapz(pin[:, 1].max() - pin[:, 1], pin[:, 0]))
    parts = {"piston": design["piston_mass"], "pin": rho * pin_volume, "housing": housing,
             "oil": design["liquid_mass"]}
    return {**parts, "fixture": sum(parts.values()), "outer_radius": outer, "floor_thickness": floor,
            "allowed_stress": allowed, "dynamic_factor": factor, "peak_pressure": peak_pressure}

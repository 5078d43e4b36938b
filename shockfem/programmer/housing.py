"""The fluid dashpot's mass as a designer must count it: piston, metering pin, the housing that holds the
peak pressure, and the liquid.

    bore wall (Lame, closed ends; Timoshenko & Goodier, Theory of Elasticity, sec. 33; Roark's Formulas
    for Stress and Strain, 7th ed., table 13.5 case 1c), at the bore r = a under pressure p:
        sigma_theta = p (b^2 + a^2) / (b^2 - a^2),  sigma_r = -p,  sigma_z = p a^2 / (b^2 - a^2)
        von Mises  = sqrt(3) p b^2 / (b^2 - a^2)   (sigma_z is the mean of the other two)
    so the outer radius that keeps it at the allowed stress s:  b = a sqrt(k / (k - 1)),
        k = s / (sqrt(3) p), possible only for p < s / sqrt(3)
    floor (a flat plate clamped at the bore under p; Roark table 11.2 case 10b): edge stress
        3 p a^2 / (4 t^2) = s  ->  t = a sqrt(3 p / (4 s))
    floor's own period (its first mode, clamped; Blevins, Formulas for Natural Frequency and Mode
    Shape, table 11-1 case 2, lambda^2 = 10.22):  T = 2 pi a^2 / (10.22 t) sqrt(12 rho (1 - nu^2) / E)
    pin: the piston's hole is the pin's largest opening a_max; at a stroke s the pin fills
        a_max - a(s) of it: its volume is the integral of that over the stroke.

The pressure the wall is sized for is the liquid's peak times a dynamic factor: the wall's breathing
mode (a ring's, period 2 pi b / c, c = sqrt(E / rho): ``liquids-and-machines.md``) driven by the
pressure's own history, as an undamped oscillator x'' + w^2 x = w^2 p(t); the factor is its largest
response over the largest pressure (Biggs, Introduction to Structural Dynamics, 1964, ch. 2: 2 for a
step, 1 + |sin(pi t_r / T)| / (pi t_r / T) for a ramp of rise t_r).  A column's pressure rises in
fronts (its waves), so the factor is read from the history, not assumed.

The allowed stress is the housing steel's design stress by ASME's Boiler and Pressure Vessel Code,
Section VIII Division 2 (the lesser of yield / 1.5 and tensile / 2.4, Part 3 annex 3-A): a housing
that holds a shot's pressure shot after shot.  The steels and their limits: ``HOUSING_STEELS``.  The
pressurised bore runs the column and the piston's thickness; the article's guide beyond it, which
holds no pressure, is not counted.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..scene.library import initial_yield_stress, property_si

YIELD_MARGIN, TENSILE_MARGIN = 1.5, 2.4          # ASME BPVC VIII-2, Part 3 annex 3-A


@dataclass(frozen=True)
class HousingSteel:
    """A housing steel: density [kg/m^3], Young's modulus [Pa], 0.2% yield and tensile strength [Pa],
    and the source of the figures."""
    name: str
    density: float
    youngs_modulus: float
    yield_stress: float
    tensile_strength: float
    source: str

    def allowed_stress(self) -> float:
        """ASME VIII-2's design stress: the lesser of yield / 1.5 and tensile / 2.4."""
        return min(self.yield_stress / YIELD_MARGIN, self.tensile_strength / TENSILE_MARGIN)

    def bar_speed(self) -> float:
        return math.sqrt(self.youngs_modulus / self.density)


def _library_steel(name: str, tensile: float) -> HousingSteel:
    return HousingSteel(name, property_si(name, "density", "density"), property_si(name, "youngs_modulus", "pressure"),
                        initial_yield_stress(name), tensile, f"the material library's {name}")


HOUSING_STEELS = {
    "high_strength_steel": _library_steel("high_strength_steel", 760e6),
    "maraging_300": HousingSteel(
        "maraging_300", 8000.0, 190e9, 1790e6, 1830e6,
        "18Ni(300) maraging steel, aged: ASM Handbook vol. 1 (1990), Maraging Steels, typical properties "
        "(0.2% yield 1790-2070 MPa, tensile 1830-2100 MPa: the lower ends taken), density 8.0 g/cm^3, E 190 GPa"),
}
HOUSING_STEEL = "maraging_300"


def bore_outer_radius(pressure: float, bore: float, allowed: float) -> float:
    """The outer radius [m] at which a thick cylinder of ``bore`` radius holds ``pressure`` [Pa] with its
    von Mises stress at the bore equal to ``allowed`` [Pa]; inf if no wall can."""
    k = allowed / (math.sqrt(3.0) * pressure)
    return bore * math.sqrt(k / (k - 1.0)) if k > 1.0 else math.inf


def bore_von_mises(pressure: float, bore: float, outer: float) -> float:
    """Lame's von Mises stress at the bore of a closed thick cylinder [Pa]."""
    return math.sqrt(3.0) * pressure * outer ** 2 / (outer ** 2 - bore ** 2)


def dynamic_factor(t: np.ndarray, p: np.ndarray, period: float) -> float:
    """The largest response of an undamped oscillator of ``period`` [s], at rest before the history,
    driven by the pressure ``p`` at times ``t`` (linear between samples) over the largest pressure.

    Exact for the piecewise-linear load: on a sample interval the load's own line is a particular
    solution, so x - p oscillates freely at w there; the response is stepped interval by interval."""
    peak = float(np.max(p))
    if peak <= 0.0:
        return 1.0
    w = 2.0 * math.pi / period
    x, v, largest = 0.0, 0.0, 0.0
    for k in range(len(t) - 1):
        h = t[k + 1] - t[k]
        slope = (p[k + 1] - p[k]) / h
        y, yd = x - p[k], v - slope
        c, s = math.cos(w * h), math.sin(w * h)
        x = y * c + yd / w * s + p[k + 1]
        v = -y * w * s + yd * c + slope
        # the largest |x| of the interval, between samples where the oscillation peaks inside it
        largest = max(largest, abs(x), abs(p[k]) + math.hypot(y, yd / w) if w * h > math.pi / 8 else 0.0)
    return largest / peak


# a steel's Poisson ratio, in the floor plate's stiffness (only its square enters)
POISSON = 0.3
# a clamped circular plate's first mode: lambda^2 (Blevins, table 11-1)
PLATE_MODE = 10.22


def floor_period(bore: float, thickness: float, s: HousingSteel) -> float:
    """The first period [s] of a clamped circular floor of radius ``bore`` and ``thickness`` [m]."""
    return 2.0 * math.pi * bore ** 2 / (PLATE_MODE * thickness) * math.sqrt(12.0 * s.density * (1 - POISSON ** 2)
                                                                           / s.youngs_modulus)


def fixture_mass(design: dict, t: np.ndarray, wall_pressure: np.ndarray, floor_pressure: np.ndarray,
                 steel: str = HOUSING_STEEL) -> dict:
    """The dashpot ``design`` (``dashpot_design``) weighed whole, its housing of ``HOUSING_STEELS[steel]``
    sized for the pressure histories on its wall (the largest over the column) and on its floor [Pa] at
    times ``t`` [s]: a dict of the parts [kg], the housing's radii [m], the allowed stress, the dynamic
    factor, and their sum, ``fixture`` (inf where no wall of that steel holds the pressure)."""
    s = HOUSING_STEELS[steel]
    a = design["bore_radius"]
    allowed = s.allowed_stress()
    peak = float(np.max(wall_pressure))
    # the breathing period of the wall it gives, from a first guess at twice the bore
    outer, factor = 2.0 * a, 1.0
    for _ in range(4):
        factor = dynamic_factor(t, wall_pressure, 2.0 * math.pi * outer / s.bar_speed())
        outer = bore_outer_radius(peak * factor, a, allowed)
        if not math.isfinite(outer):
            break
    floor_peak, floor, floor_factor = float(np.max(floor_pressure)), a, 1.0
    for _ in range(4):
        floor_factor = dynamic_factor(t, floor_pressure, floor_period(a, floor, s))
        floor = a * math.sqrt(3.0 * floor_peak * floor_factor / (4.0 * allowed))
    length = design["column"] + design.get("piston_thickness", 0.015)
    housing = (s.density * math.pi * ((outer ** 2 - a ** 2) * length + outer ** 2 * floor) if math.isfinite(outer)
               else math.inf)
    pin = np.array(design["pin"], dtype=float)
    pin_volume = float(np.trapz(pin[:, 1].max() - pin[:, 1], pin[:, 0]))
    parts = {"piston": design["piston_mass"], "pin": s.density * pin_volume, "housing": housing,
             "liquid": design["liquid_mass"]}
    return {**parts, "fixture": sum(parts.values()), "outer_radius": outer, "floor_thickness": floor,
            "allowed_stress": allowed, "dynamic_factor": factor, "floor_dynamic_factor": floor_factor, "peak_pressure": peak, "steel": steel,
            "steel_source": s.source, "holdable_pressure": allowed / math.sqrt(3.0)}

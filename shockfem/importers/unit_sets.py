"""Consistent unit sets: LS-DYNA's numbers have no units, the engineer names the set the deck was written in.

A set is ``length-time-mass-force`` (``mm-ms-kg-kN``, ``mm-s-tonne-N``, ``m-s-kg-N``, ``in-s-lbf*s**2/in-lbf``),
each a unit pint reads; it is consistent when one force unit is one mass unit times one length unit per
time unit squared (Newton's second law with no factor), as an explicit code's equations need. Every other
unit of the deck follows from these four (pressure = force / length^2, density = mass / length^3, ...).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from ..units import UnitError, registry, to_si

# the sets engineers name most often (LS-DYNA's own table of consistent units has these)
COMMON_SETS = ("mm-ms-kg-kN", "mm-s-tonne-N", "m-s-kg-N", "mm-ms-g-N",
               "in-s-lbf*s**2/in-lbf")

# a field's dimension as powers of (length, time, mass, force)
POWERS = {
    "length": (1, 0, 0, 0), "time": (0, 1, 0, 0), "mass": (0, 0, 1, 0), "force": (0, 0, 0, 1),
    "velocity": (1, -1, 0, 0), "pressure": (-2, 0, 0, 1), "density": (-3, 0, 1, 0),
    "strain_rate": (0, -1, 0, 0), "slowness": (-1, 1, 0, 0), "acceleration": (1, -2, 0, 0),
    "angular_velocity": (0, -1, 0, 0),
}


@dataclass(frozen=True)
class UnitSet:
    """The four base units of a deck and the text and SI factor of any dimension built from them."""
    name: str
    length: str
    time: str
    mass: str
    force: str

    def unit(self, dimension: str) -> str:
        """The unit text of a dimension, e.g. ``kN/mm**2`` for a pressure in mm-ms-kg-kN."""
        num, den = [], []
        for base, p in zip((self.length, self.time, self.mass, self.force), POWERS[dimension]):
            term = f"({base})" if "/" in base or "*" in base else base
            if p:
                (num if p > 0 else den).append(term + (f"**{abs(p)}" if abs(p) != 1 else ""))
        text = "*".join(num) or "1"
        return text + ("/" + "/".join(den) if den else "")

    def quantity(self, value: float, dimension: str) -> str:
        """A deck value as a scene string with its unit (``repr`` keeps every digit)."""
        return f"{float(value)!r} {self.unit(dimension)}"

    def si(self, value: float, dimension: str) -> float:
        """The SI value of a deck number of this dimension."""
        return value * to_si(f"1 {self.unit(dimension)}", dimension)


def unit_set(name: str | None) -> UnitSet:
    """The unit set named ``length-time-mass-force``; raises ``UnitError`` naming what is wrong (none
    given, a unit pint does not know or of the wrong kind, a set that is not consistent)."""
    if not name:
        raise UnitError("the numbers of an LS-DYNA deck or an Abaqus file have no units: name the consistent "
                        f"set they are in with --units (one of {', '.join(COMMON_SETS)}, or any length-time-mass-force)")
    parts = name.split("-")
    if len(parts) != 4:
        raise UnitError(f"unit set {name!r}: write it as length-time-mass-force, e.g. mm-ms-kg-kN")
    units = UnitSet(name, *parts)
    factors = []
    for dimension, text in zip(("length", "time", "mass", "force"), parts):
        try:
            factors.append(to_si(f"1 {text}", dimension))
        except UnitError as e:
            raise UnitError(f"unit set {name!r}: its {dimension} unit {text!r}: {e}") from None
    length, time, mass, force = factors
    consistent = mass * length / time ** 2
    if not math.isclose(force, consistent, rel_tol=1e-9):
        q = registry().Quantity(consistent, "N")
        raise UnitError(f"unit set {name!r} is not consistent: one {parts[2]} x {parts[0]} / {parts[1]}^2 is "
                        f"{q.to_compact():~g}, not one {parts[3]}; the force unit of this length, time and mass "
                        f"is {consistent:g} N")
    return units

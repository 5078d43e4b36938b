"""A part's limit checked on a design: a value against the limit its material (or its kind of hardware)
sets, with where the limit comes from.

Stress is one limit among several a shock machine's parts carry: an elastomer pad also has a working
strain, a stored energy per volume and a temperature rise a shot; a slender part a length over its
diameter; a stop a stroke.  A design is feasible only where every ``Limit`` holds; one that does not is
listed with its ratio (``ratio`` over 1: by how much).
"""
from __future__ import annotations

from dataclasses import asdict, dataclass


@dataclass(frozen=True)
class Limit:
    """One check on one part: ``value`` must not exceed ``limit`` (both in ``unit``, SI)."""
    component: str          # the part ("pad m1-m2", "striker housing wall")
    quantity: str           # what is checked ("stress", "strain", "stored energy per volume", ...)
    value: float
    limit: float
    unit: str               # SI unit of value and limit ("Pa", "-", "J/m^3", "K", "m")
    basis: str              # the formula or model that gives the value
    source: str             # where the limit comes from (a standard, a handbook, a maker's data sheet)
    sized: bool = False     # the design set the value to the limit (its ratio is 1 by construction)

    @property
    def ratio(self) -> float:
        return self.value / self.limit if self.limit else float("inf")

    @property
    def holds(self) -> bool:
        # 1e-6: a value the design set to the limit may exceed it in its last digits
        return bool(self.ratio <= 1.0 + 1e-6)

    def as_dict(self) -> dict:
        return {**asdict(self), "ratio": self.ratio, "holds": self.holds}

    def describe(self) -> str:
        state = "holds" if self.holds else f"BROKEN by {100 * (self.ratio - 1):.0f}%"
        return (f"{self.component}: {self.quantity} {self.value:.4g} {self.unit} against {self.limit:.4g} "
                f"{self.unit} ({self.source}): {state}")


def broken(limits: list[Limit]) -> list[Limit]:
    """The limits that do not hold, the worst first."""
    return sorted((lim for lim in limits if not lim.holds), key=lambda lim: -lim.ratio)

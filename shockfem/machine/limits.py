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
        return {**asdict(self), "ratio": self.ratio, "holds": self.holds, "model_range": model_range(self)}

    def describe(self) -> str:
        state = "holds" if self.holds else f"BROKEN by {100 * (self.ratio - 1):.0f}%"
        return (f"{self.component}: {self.quantity} {self.value:.4g} {self.unit} against {self.limit:.4g} "
                f"{self.unit} ({self.source}): {state}")


def broken(limits: list[Limit]) -> list[Limit]:
    """The limits that do not hold, the worst first."""
    return sorted((lim for lim in limits if not lim.holds), key=lambda lim: -lim.ratio)


# the part of the machine a limit belongs to, by its component's name: a verdict lists its broken limits
# by these, so that many limits broken for one reason (the pads' energy per volume) read as one cause
CAUSES = (("the amplifier's pads", ("pad ", "face ", "body ", "interface ")),
          ("the fixture", ("dashpot", "striker housing", "piston", "article")),
          ("the launcher", ("launcher", "first mass in the barrel")),
          ("the stops", ("stop of",)),
          ("the guides and frame", ("guide shoes", "frame")))
TRANSPORT = "the parts' size for transport"


def cause(lim: Limit) -> str:
    """The part of the machine ``lim`` belongs to (``CAUSES``; the transport limits on their own)."""
    if lim.quantity.endswith("for transport"):
        return TRANSPORT
    return next((name for name, starts in CAUSES if lim.component.startswith(starts)), "other")


# a limit that bounds a model's range of validity, not the part's strength or size: broken, it says that the
# model which sized the part is outside the data or the assumptions it was checked on (a finer model, a
# finite-element run, must check the part), not that the part fails.  Read from where the limit comes from:
# a source or basis that names a range, the orifice law's area ratio, the column's linearised faces
MODEL_RANGE_MARKERS = ("range", "iso 5167-2's area ratio", "linearised wall faces")


def model_range(lim: Limit) -> bool:
    """Whether ``lim`` bounds a model's range of validity (``MODEL_RANGE_MARKERS``) rather than a part."""
    text = f"{lim.basis} {lim.source}".lower()
    return any(marker in text for marker in MODEL_RANGE_MARKERS)


def counted(limits: list[Limit]) -> list[Limit]:
    """The limits that could fail: those the design did not set to their limit (a sized one holds by
    construction)."""
    return [lim for lim in limits if not lim.sized]


def by_cause(limits: list[Limit]) -> list[tuple[str, int, Limit]]:
    """The broken limits grouped by ``cause``: (cause, how many, the worst), the worst group first."""
    groups: dict[str, list[Limit]] = {}
    for lim in broken(limits):
        groups.setdefault(cause(lim), []).append(lim)
    return sorted(((c, len(v), v[0]) for c, v in groups.items()), key=lambda g: -g[2].ratio)


def verdict_line(limits: list[Limit]) -> str:
    """The limits in one sentence: how many could fail, how many the design set to their limit, how many
    are broken and by which cause (each with its worst)."""
    causes = "; ".join(f"{c}: {n} (worst {w.component}, {w.quantity}, {w.ratio:.3g} times its limit)"
                       for c, n, w in by_cause(limits))
    ranges = [lim for lim in broken(limits) if model_range(lim)]
    apart = (f" ({len(broken(limits)) - len(ranges)} a part past its material's or its size's limit, {len(ranges)} a "
             "model outside its range, where a finer model must check the part: "
             + ", ".join(f"{lim.component} {lim.quantity}" for lim in ranges) + ")") if ranges else ""
    return (f"{len(counted(limits))} limits checked ({len(limits) - len(counted(limits))} more set by the design to "
            f"their limit), {len(broken(limits))} broken" + apart + (f", by cause: {causes}" if causes else ""))

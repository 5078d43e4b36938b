"""Where the dashpot's reduced models hold, checked on a run: every dashpot design and run reports these.

    area ratio        a / A over the stroke the run used, against the orifice law's range
                      (``fluid.orifice.valid_area_ratio``)
    piston Mach       the largest relative speed over the liquid's sound speed: the lumped liquid is
                      quasi-static below ``LUMPED_MACH`` (``programmer.concepts.INCOMPRESSIBLE_MACH``);
                      the column's wall faces take a linearised Riemann solution, fair below
                      ``COLUMN_MACH``
    liquid mass       the liquid's mass over the payload's: the lumped liquid has none, fair below
                      ``LUMPED_LIQUID_MASS``
    transit time      the column's L / c over the pulse's rise (10% to 90% of its peak): one pressure at
                      every point of the liquid needs many transits per rise, below ``LUMPED_TRANSIT``
    cavitation        the lumped liquid at zero pressure while the stroke goes on (it would part), or
                      the column's cavity opening while the striker still closes on the payload

The lumped model (``lumped_dashpot``) is the design model only where all of them hold; else the column
(``column_dashpot``) is, within its own area ratio and Mach number.
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass

import numpy as np

from ..fluid.orifice import valid_area_ratio
from .concepts import INCOMPRESSIBLE_MACH
from .lumped_dashpot import LumpedDashpot

LUMPED_MACH = INCOMPRESSIBLE_MACH
COLUMN_MACH = 0.5
LUMPED_LIQUID_MASS = 0.1
LUMPED_TRANSIT = 0.1
# a column parted by less than this share of its volume has not cavitated (the void's round-off)
PARTED = 1e-6


@dataclass(frozen=True)
class Limit:
    """One check: its ``name``, the run's ``value`` against ``limit`` (the value must not exceed it),
    the ``models`` it bounds, and whether it ``holds``."""
    name: str
    value: float
    limit: float
    models: str

    @property
    def holds(self) -> bool:
        return bool(self.value <= self.limit)

    def as_dict(self) -> dict:
        return {**asdict(self), "holds": self.holds}

    def describe(self) -> str:
        return (f"{self.name} {self.value:.3g} (limit {self.limit:.3g}, {self.models}): "
                f"{'holds' if self.holds else 'OUTSIDE'}")


def rise_time(t: np.ndarray, a: np.ndarray) -> float:
    """The pulse's first rise from 10% to 90% of its peak [s]."""
    peak = np.max(np.abs(a))
    if peak <= 0.0:
        return float("nan")
    mag = np.abs(a)
    t10 = t[np.argmax(mag >= 0.1 * peak)]
    t90 = t[np.argmax(mag >= 0.9 * peak)]
    return float(max(t90 - t10, t[1] - t[0]))


def dashpot_limits(d: LumpedDashpot, run) -> list[Limit]:
    """The checks of a dashpot ``d`` on its ``run`` (``LumpedRun`` or ``ColumnRun``)."""
    pin = np.array(d.pin, dtype=float).reshape(-1, 2)
    used = pin[:, 0] <= max(float(np.max(run.stroke)), pin[0, 0])
    ratio = float(np.max(pin[used, 1])) / d.piston_area
    c = math.sqrt(d.bulk_modulus / d.density)
    relative = run.striker_speed - run.payload_speed
    mach = float(np.max(np.abs(relative))) / c
    liquid = d.density * d.piston_area * d.column / d.payload_mass
    transit = d.column / c / rise_time(run.t, run.acceleration)
    stroking = relative > 1e-3 * d.speed
    if hasattr(run, "cavity"):
        # while the stroke goes on: after it the payload leaves the oil, which is no cavitation
        cavity = float(np.max(run.cavity[stroking], initial=0.0)) / (d.piston_area * d.column)
    else:
        loaded = np.flatnonzero(run.pressure > 0.0)
        after = np.arange(len(run.t)) > (loaded[0] if len(loaded) else len(run.t))
        cavity = float(np.any(stroking & after & (run.pressure <= 0.0)))
    law = d.orifice_law()
    return [Limit("orifice area ratio a / A", ratio, valid_area_ratio(law), "the orifice law"),
            Limit("piston Mach number in the liquid", mach, LUMPED_MACH, "lumped"),
            Limit("piston Mach number in the liquid", mach, COLUMN_MACH, "column"),
            Limit("liquid mass / payload", liquid, LUMPED_LIQUID_MASS, "lumped"),
            Limit("column transit time / pulse rise", transit, LUMPED_TRANSIT, "lumped"),
            Limit("cavitation (lumped: parts while stroking; column: cavity / column volume)", cavity, PARTED,
                  "lumped and column")]


def lumped_holds(limits: list[Limit]) -> bool:
    """Whether the lumped model is a design model for this run: every check that bounds it holds."""
    return all(lim.holds for lim in limits if "lumped" in lim.models or lim.models == "the orifice law")

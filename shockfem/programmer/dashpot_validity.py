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
    Reynolds number   the share of the velocity change delivered while the orifice's Re_D = rho u D / mu(p)
                      (u the piston's speed through the liquid, D the bore, mu at the liquid's pressure,
                      ``programmer.liquids``) is below the law's least (``fluid.orifice.least_reynolds``),
                      within ``REYNOLDS_SHARE``: every stroke slows through it at its end
    liquid state      the peak pressure against the one at which the liquid freezes (water: ice VI)
    cavitation        the lumped liquid at zero pressure while the stroke goes on (it would part), or
                      the column's cavity opening while the striker still closes on the payload

The lumped model (``lumped_dashpot``) is the design model only where all of them hold; else the column
(``column_dashpot``) is, within its own area ratio and Mach number.
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass

import numpy as np

from ..fluid.column import MACH_LIMIT, PARTED
from ..fluid.orifice import least_reynolds, valid_area_ratio
from .concepts import INCOMPRESSIBLE_MACH
from .liquids import MINERAL_OIL, DesignLiquid
from .lumped_dashpot import LumpedDashpot

LUMPED_MACH = INCOMPRESSIBLE_MACH
COLUMN_MACH = MACH_LIMIT       # the column's own range (``fluid.column``)
LUMPED_LIQUID_MASS = 0.1
LUMPED_TRANSIT = 0.1
# the share of the velocity change a design may deliver below the law's Reynolds range: even a
# coefficient wrong by half there moves the velocity change by a twentieth of the band's 10% tolerance
REYNOLDS_SHARE = 0.01


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


def reynolds_share(d: LumpedDashpot, run, liquid: DesignLiquid) -> float:
    """The share of the payload's velocity change delivered while the orifice's Re_D is below the law's
    least at the area ratio of that moment."""
    pin = np.array(d.pin, dtype=float).reshape(-1, 2)
    diameter = 2.0 * math.sqrt(d.piston_area / math.pi)
    relative = np.abs(run.striker_speed - run.payload_speed)
    mu = np.array([liquid.viscosity_at(p) for p in run.pressure])
    reynolds = liquid.density * relative * diameter / mu
    ratio = np.interp(run.stroke, pin[:, 0], pin[:, 1]) / d.piston_area
    least = np.array([least_reynolds(n) for n in ratio])
    impulse = np.abs(run.acceleration)
    total = float(np.sum(impulse))
    return float(np.sum(impulse[reynolds < least])) / total if total > 0.0 else 0.0


def dashpot_limits(d: LumpedDashpot, run, liquid: DesignLiquid = MINERAL_OIL) -> list[Limit]:
    """The checks of a dashpot ``d`` filled with ``liquid`` on its ``run`` (``LumpedRun`` or ``ColumnRun``)."""
    pin = np.array(d.pin, dtype=float).reshape(-1, 2)
    used = pin[:, 0] <= max(float(np.max(run.stroke)), pin[0, 0])
    ratio = float(np.max(pin[used, 1])) / d.piston_area
    c = math.sqrt(d.bulk_modulus / d.density)
    relative = run.striker_speed - run.payload_speed
    mach = float(np.max(np.abs(relative))) / c
    liquid_mass = d.density * d.piston_area * d.column / d.payload_mass
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
    peak = max(float(np.max(run.pressure)), float(np.max(getattr(run, "floor_pressure", run.pressure))))
    return [Limit("orifice area ratio a / A", ratio, valid_area_ratio(law), "the orifice law"),
            Limit("velocity change delivered below the law's Reynolds range", reynolds_share(d, run, liquid),
                  REYNOLDS_SHARE, "the orifice law"),
            Limit(f"peak pressure [MPa] against the {liquid.name}'s freezing", peak / 1e6,
                  liquid.solid_pressure() / 1e6, "the liquid"),
            Limit("piston Mach number in the liquid", mach, LUMPED_MACH, "lumped"),
            Limit("piston Mach number in the liquid", mach, COLUMN_MACH, "column"),
            Limit("liquid mass / payload", liquid_mass, LUMPED_LIQUID_MASS, "lumped"),
            Limit("column transit time / pulse rise", transit, LUMPED_TRANSIT, "lumped"),
            Limit("cavitation (lumped: parts while stroking; column: cavity / column volume)", cavity, PARTED,
                  "lumped and column")]


def lumped_holds(limits: list[Limit]) -> bool:
    """Whether the lumped model is a design model for this run: every check that bounds it holds."""
    return all(lim.holds for lim in limits if "column" not in lim.models or "lumped" in lim.models)


def column_holds(limits: list[Limit]) -> bool:
    """Whether the column is a design model for this run: every check that bounds it holds."""
    return all(lim.holds for lim in limits if "lumped" not in lim.models or "column" in lim.models)

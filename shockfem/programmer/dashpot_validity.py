"""Where the dashpot's reduced models hold, checked on a run: every dashpot design and run reports these.
A check either vetoes (outside it, the model does not design) or flags (outside it, the run is reported
as resting on an extrapolation or on a condition the model's source did not cover, and still designs).

    area ratio        a / A over the stroke the run used, against the largest the design allows
                      (``fluid.orifice.valid_area_ratio``: ``OrificeLaw.largest_ratio``); vetoes
    extrapolation     the same a / A against the law's checked data (ISO 5167-2's beta 0.75,
                      ``fluid.orifice.VALID_AREA_RATIO``); flags: wider, the law is Idelchik's formula
                      without a measured check
    land              the orifice's length through the piston over its hydraulic diameter, l / d_h, the
                      largest over the pulse (|a| above half its peak; a pin's annulus narrows to the
                      stroke's end), against the thin
                      plate's ``fluid.orifice.THIN_LAND``; flags (its consequence is in the coefficient
                      error below: a thick orifice that cavitates keeps the thin law's coefficient)
    cavitation        the share of the velocity change delivered while the orifice's flow is choked by
                      cavitation (Nurick, ``fluid.orifice.cavitates``); flags: ISO 5167's single-phase
                      condition fails there, and Nurick's Cd = Cc sqrt(K) is the law
    bore diameter     D against ISO 5167-2's least (``fluid.orifice.ISO_DIAMETERS``); flags
    coefficient       the error of the velocity change the orifice's coefficient may carry:
                      sum over the run of |a| e / sum |a|, e = |(C_law / C)^2 - 1| (at most 1) the
                      force's error at a given flow where the coefficient C departs from the law's:
                      Lichtarowicz's viscous shift at the orifice's own Reynolds number (its hydraulic
                      diameter, its ideal jet speed, the viscosity at its pressure and the temperature
                      compression brings it to: ``programmer.liquids``), a thick land's reattachment
                      where it does not cavitate, Nurick's sqrt(K) where it does
                      (``fluid.orifice.coefficient_ratio``).  An open-loop estimate (a dashpot's flow
                      answers a higher force by slowing, which halves it or better), within
                      ``COEFFICIENT_ERROR``; vetoes above it
    liquid state      the peak pressure over the one at which the liquid may freeze at the temperature
                      compression brings it to (water: ice VI, a possible phase change); vetoes
    piston Mach       the largest relative speed over the liquid's sound speed: the lumped liquid is
                      quasi-static below ``LUMPED_MACH`` (``programmer.concepts.INCOMPRESSIBLE_MACH``);
                      the column's wall faces take a linearised Riemann solution, fair below
                      ``COLUMN_MACH``
    liquid mass       the liquid's mass over the payload's: the lumped liquid has none, fair below
                      ``LUMPED_LIQUID_MASS``
    transit time      the column's L / c over the pulse's rise (10% to 90% of its peak): one pressure at
                      every point of the liquid needs many transits per rise, below ``LUMPED_TRANSIT``
    cavity            the lumped liquid at zero pressure while the stroke goes on (it would part), or
                      the column's cavity opening while the striker still closes on the payload
    rebound           the article leaving the striker faster than it (v_p - v_s at the record's end) as a
                      share of its velocity change v_p: the liquid still compressed when the bodies reach
                      a common speed springs them apart (a liquid spring, the energy the column stored
                      given back); the design's premise is restitution 0 (the velocity change made by
                      throttling the striker's closing speed), within ``REBOUND``, the margin the
                      coefficient's error is held to; vetoes above it.  A veto, not the rebound carried
                      into the model: the column already computes the pulse with its own rebound, so
                      carrying it changes nothing; what the column cannot vouch for is the return itself,
                      the energy the liquid stored given back through a rigid, sealed bore (it leaves out
                      the housing's compliance and the piston's leakage, ``docs/fixture.md`` 4.8), so a
                      velocity change resting on more of it than the margin rests on what the model
                      leaves out

The lumped model (``lumped_dashpot``) is the design model only where all of its vetoing checks hold;
else the column (``column_dashpot``) is, within its own area ratio and Mach number.
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass

import numpy as np

from ..fluid.column import MACH_LIMIT, PARTED
from ..fluid import orifice
from ..fluid.orifice import VALID_AREA_RATIO, valid_area_ratio
from .concepts import INCOMPRESSIBLE_MACH
from .liquids import MINERAL_OIL, DesignLiquid
from .lumped_dashpot import LumpedDashpot

LUMPED_MACH = INCOMPRESSIBLE_MACH
COLUMN_MACH = MACH_LIMIT       # the column's own range (``fluid.column``)
LUMPED_LIQUID_MASS = 0.1
LUMPED_TRANSIT = 0.1
# the velocity-change error the orifice's coefficient may carry: the designer's margin inside the band
# (``dashpot_design.DESIGN_MARGIN``, 3% of the band's 10%): a design aimed that far inside stays inside
# while the coefficient's error is smaller.  Below it the error is reported, not a veto
COEFFICIENT_ERROR = 0.03
# the share of the article's velocity change a rebound off the striker may give: the same margin (a design
# aimed that far inside the band at restitution 0 stays inside it with this much given back, or not given
# back where the column's return is more than the real dashpot's)
REBOUND = COEFFICIENT_ERROR


@dataclass(frozen=True)
class Limit:
    """One check: its ``name``, the run's ``value`` against ``limit`` (the value must not exceed it, or,
    for a ``lower`` bound, fall below it), the ``models`` it bounds, whether outside it ``vetoes`` the
    model (else it flags), and whether it ``holds``."""
    name: str
    value: float
    limit: float
    models: str
    vetoes: bool = True
    lower: bool = False

    @property
    def holds(self) -> bool:
        return bool(self.value >= self.limit if self.lower else self.value <= self.limit)

    @property
    def verdict(self) -> str:
        return "holds" if self.holds else "OUTSIDE" if self.vetoes else "flagged"

    def as_dict(self) -> dict:
        return {**asdict(self), "holds": self.holds}

    def describe(self) -> str:
        return (f"{self.name} {self.value:.3g} ({'least' if self.lower else 'limit'} {self.limit:.3g}, "
                f"{self.models}{'' if self.vetoes else ', flag'}): {self.verdict}")


def rise_time(t: np.ndarray, a: np.ndarray) -> float:
    """The pulse's first rise from 10% to 90% of its peak [s]."""
    peak = np.max(np.abs(a))
    if peak <= 0.0:
        return float("nan")
    mag = np.abs(a)
    t10 = t[np.argmax(mag >= 0.1 * peak)]
    t90 = t[np.argmax(mag >= 0.9 * peak)]
    return float(max(t90 - t10, t[1] - t[0]))


def orifice_states(d: LumpedDashpot, run, liquid: DesignLiquid) -> dict:
    """The orifice's state at every sample of ``run``: its area ratio, land l / d_h (``d.orifice_land``
    through the pin's annulus in a hole of the pin table's largest opening), cavitation number, Reynolds
    number (at the compressed liquid's temperature) and coefficient over the law's."""
    pin = np.array(d.pin, dtype=float).reshape(-1, 2)
    hole = float(np.max(pin[:, 1]))
    area = np.interp(run.stroke, pin[:, 0], pin[:, 1])
    law = d.orifice_law()
    code = law.code()
    ratio = area / d.piston_area
    rows = []
    for a, n, p in zip(area, ratio, run.pressure):
        d_h = orifice.annulus_hydraulic_diameter(a, hole)
        k = orifice.cavitation_number(p, liquid.vapour_pressure)
        if d_h <= 0.0:                   # the pin closes the orifice: no flow, no coefficient
            rows.append((math.inf, k, 0.0, 1.0, False))
            continue
        land = d.orifice_land / d_h
        mu = liquid.viscosity_at(p, liquid.compressed_temperature(p))
        re = orifice.jet_reynolds(p, liquid.density, mu, d_h)
        cc = orifice.jet_coefficient(min(n, 1.0), code)
        c = orifice.coefficient_ratio(land, k) * orifice.viscous_coefficient_ratio(re, land, cc)
        rows.append((land, k, re, c, orifice.cavitates(land, k)))
    land, k, re, c, choked = (np.array(col) for col in zip(*rows)) if rows else (np.zeros(0),) * 5
    return {"ratio": ratio, "land": land, "cavitation": k, "reynolds": re, "coefficient": c, "choked": choked}


def coefficient_error(states: dict, acceleration: np.ndarray) -> float:
    """The velocity-change error the orifice's coefficient carries: the impulse-weighted force error
    |(C_law / C)^2 - 1| (at most 1) where the coefficient C departs from the law's."""
    c = states["coefficient"]
    force_error = np.minimum(np.abs(1.0 / np.maximum(c, 1e-12) ** 2 - 1.0), 1.0)
    impulse = np.abs(acceleration)
    total = float(np.sum(impulse))
    return float(np.sum(impulse * force_error)) / total if total > 0.0 else 0.0


def choked_share(states: dict, acceleration: np.ndarray) -> float:
    """The share of the velocity change delivered while the orifice's flow is choked by cavitation."""
    impulse = np.abs(acceleration)
    total = float(np.sum(impulse))
    return float(np.sum(impulse[states["choked"]])) / total if total > 0.0 else 0.0


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
    states = orifice_states(d, run, liquid)
    # the land over the pulse's body (|a| above half its peak), where the orifice meters the force
    body = np.abs(run.acceleration) >= 0.5 * float(np.max(np.abs(run.acceleration), initial=0.0))
    land = float(np.max(states["land"][body], initial=0.0))
    bore = 2.0 * math.sqrt(d.piston_area / math.pi)
    return [Limit("orifice area ratio a / A", ratio, valid_area_ratio(law), "the orifice law"),
            Limit("orifice area ratio a / A beyond the law's checked data (extrapolation)", ratio,
                  VALID_AREA_RATIO, "the orifice law", vetoes=False),
            Limit("orifice land / hydraulic diameter l / d_h (thin plate)", land, orifice.THIN_LAND,
                  "the orifice law", vetoes=False),
            Limit("velocity change delivered with the orifice choked by cavitation (Nurick)",
                  choked_share(states, run.acceleration), 0.0, "the orifice law", vetoes=False),
            Limit("bore diameter [mm] against ISO 5167-2's least", bore * 1e3, orifice.ISO_DIAMETERS[0] * 1e3,
                  "the orifice law", vetoes=False, lower=True),
            Limit("velocity-change error of the orifice's coefficient (viscous, land, cavitation)",
                  coefficient_error(states, run.acceleration), COEFFICIENT_ERROR, "the orifice law"),
            Limit(f"peak pressure over the {liquid.name}'s freezing at its compressed temperature "
                  "(a possible phase change)", liquid.freezing_margin(peak), 1.0, "the liquid"),
            Limit("piston Mach number in the liquid", mach, LUMPED_MACH, "lumped"),
            Limit("piston Mach number in the liquid", mach, COLUMN_MACH, "column"),
            Limit("liquid mass / payload", liquid_mass, LUMPED_LIQUID_MASS, "lumped"),
            Limit("column transit time / pulse rise", transit, LUMPED_TRANSIT, "lumped"),
            Limit("cavitation (lumped: parts while stroking; column: cavity / column volume)", cavity, PARTED,
                  "lumped and column"),
            Limit("rebound off the striker (v_article - v_striker) / v_article at the record's end "
                  "(restitution 0: none)", rebound(run), REBOUND, "the premise")]


def rebound(run) -> float:
    """The article's speed away from the striker at the end of ``run`` over its own speed [-]: 0 for
    bodies that end together (restitution 0), negative while the striker still closes on it."""
    v_p, v_s = float(run.payload_speed[-1]), float(run.striker_speed[-1])
    return (v_p - v_s) / v_p if v_p > 0.0 else 0.0


def lumped_holds(limits: list[Limit]) -> bool:
    """Whether the lumped model is a design model for this run: every check that bounds it holds."""
    return all(lim.holds for lim in limits if lim.vetoes and ("column" not in lim.models or "lumped" in lim.models))


def column_holds(limits: list[Limit]) -> bool:
    """Whether the column is a design model for this run: every check that bounds it holds."""
    return all(lim.holds for lim in limits if lim.vetoes and ("lumped" not in lim.models or "column" in lim.models))

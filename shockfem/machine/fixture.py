"""The fixture: the fluid dashpot the fixture study designs (``programmer.column_design``: the liquid as a
compressible column, Idelchik's sharp-edged orifice with the velocity of approach and the jet's
reaction, the bore a design variable), designed for this article, and the housing the striker *is*.

The dashpot is iterated on the column (``design_on_column``) and confirmed on it at
``column_dashpot.CELLS`` cells; its validity checks on that run (``programmer.dashpot_validity``: the
orifice's area ratio, the share of the velocity change below the law's Reynolds range, the piston's
Mach number in the liquid, cavitation, the liquid's freezing) and the housing's (the wall's peak
pressure times its dynamic factor against the most a wall of the housing steel holds) are the
fixture's ``limits`` (``machine.limits.Limit``): a design outside a law's range is a broken limit of
the machine, with its ratio.  The lumped model's run of the same design is kept beside it
(``design["column_design"]["models"]["lumped"]``), not designed on.

The housing is the fixture study's (``programmer.housing``, the one place for its formulas):
``HOUSING_STEEL`` at ASME VIII-2's design stress S, its wall by VIII-2 4.3.3 (P = S ln Y, Y = b / a) at
the column's peak wall pressure times the dynamic factor of its worst slice (the column's histories at
the piston's face and at the floor, each slice a ring of its own: ``housing.wall_factor``), at most
a monobloc forging's Y_max = ``PRACTICAL_RATIO``, its floor VIII-2 4.6's integral flat head at the
floor's pressure and factor (``housing.fixture_mass``).  The machine's striker carries it over the
whole bore: the column, the piston and the article standing in it (``BORE_HEADROOM`` above its nose),
at the same outer radius, with the metering pin and the oil.  The striker is the column designer's fixed
point of its found design (``programmer.fixed_point.striker_fixed_point``, both ways from the designer's
start, never below the spec's ratio, to its tolerance): the ratio at which this housing, at the outer
radius its wall needs, with pin and oil, weighs the striker (a heavier striker closes slower and needs a
thinner wall); where the designer keeps a heavier striker (the fixed point's design outside a check, or
the search unconverged: ``design["column_design"]["striker_fixed_point"]`` says which), the housing is
drawn at the radius that weighs it and the wall does not set it.  Beyond Y_max the housing is drawn at
Y_max and its limit is broken by how far its wall ratio is past it.

What it leaves out: the bodies' elasticity (the fixture study's finite-element runs), the column's own
(friction on the bore, liquid returning through the orifice: ``fluid.column``).
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass, field

import numpy as np

from ..parts.catalog import solid_ogive_length
from ..programmer.article_base import RAYLEIGH_LOVE, Article
from ..programmer.column_dashpot import CELLS, StrikerPush, simulate_column
from ..programmer.column_design import design_on_column
from ..programmer.dashpot_design import DASHPOT, LUMPED_SAMPLES, dashpot_lumped, design_liquid
from ..programmer.housing import (HOUSING_STEEL, HOUSING_STEELS, PRACTICAL_RATIO, THICK_PLATE, floor_for,
                                  held_pressure)
from ..programmer.liquids import MINERAL_OIL
from ..scene.library import property_si
from .limits import Limit
from .spec import REFERENCE_ARTICLE, MachineSpec

# the free length left in the bore above the article's nose [m]
BORE_HEADROOM = 0.02
# the oil's specific heat [J/(kg K)] (the design liquid's, ``programmer.liquids.MINERAL_OIL``)
OIL_HEAT_CAPACITY = MINERAL_OIL.heat_capacity
LIQUID = MINERAL_OIL
# the column designer's runs and its search grid (``column_design.design_on_column``'s own defaults)
DESIGN_EVALUATIONS = 120
SEARCH_CELLS = 100
# the machine keeps the closed form's quasi-steady pin (no cut on the column, ``programmer.pin_cut``): its
# design loop redesigns the dashpot for each striker, and the cut's column runs at the design grid are the
# fixture study's step (``docs/fixture.md``, 4.2), not yet weighed against the machine's coupled runs
PIN_ITERATIONS = 0


@dataclass
class Fixture:
    article_mass: float           # [kg]
    article_diameter: float       # [m]
    article_length: float         # [m] (the reference ogive scaled to the diameter, solid 4340)
    bore_radius: float            # [m]
    piston_mass: float            # [kg]
    payload_mass: float           # article and piston [kg]
    striker_ratio: float          # striker (housing, pin and oil) over payload
    striker_mass: float           # [kg]
    striker_speed: float          # closing speed on the payload at rest [m/s]
    liquid_mass: float            # [kg]
    column: float                 # the liquid column at rest [m]
    stroke: float                 # relative stroke used by the column run [m]
    peak_pressure: float          # the column's largest wall pressure [Pa]
    housing_outer_radius: float   # [m]
    housing_length: float         # floor and bore [m]
    floor_thickness: float        # [m]
    bore_depth: float             # [m]
    housing_steel_mass: float     # wall and floor [kg]
    housing_binds: bool           # the wall sets the striker's mass (the fixed point above the asked ratio)
    wall_stress: float            # the wall rule's stress at the peak pressure times its factor: S P / P_held(Y) [Pa]
    floor_stress: float           # the flat head's at its peak times its factor: S (t_needed / t)^2 [Pa]
    allowable: float              # the housing steel's design stress S (ASME VIII-2) [Pa]
    peak: float                   # the payload's column pulse: peak [m/s^2]
    duration: float               # [s]
    velocity_change: float        # [m/s]
    band_passed: bool
    worst_excess: float
    after_speed_payload: float    # when the column record ends [m/s]
    after_speed_striker: float    # [m/s]
    striker_travel: float         # over the record (the pulse and the window after it) [m]
    payload_travel: float         # [m]
    oil_heating: float            # if the oil keeps the energy it takes from the bodies [K]
    design_runs: int              # the column runs of every design made
    redesigns: int
    design: dict                  # the dashpot design (``programmer.dashpot_design``), its column designer's record
    # the energy the oil takes from striker and payload over the record [J] (the energy table's fixture row;
    # ``oil_work``), and the payload's parting speed over the closing speed at the record's end [-]
    oil_work: float = math.nan
    restitution: float = math.nan
    housing_steel: str = HOUSING_STEEL
    pin_mass: float = 0.0         # the metering pin, carried by the striker [kg]
    limits: list = field(default_factory=list)      # of ``machine.limits.Limit``: the laws' ranges, the housing
    verdict: str = ""             # the column designer's ("inside", "outside the laws' ranges", "the article yields", ...)
    # the outer radius the wall rule needs and the one at which the housing weighs the striker [m] (the
    # housing is drawn at the larger); the column designer's own striker (it carries its pressurised
    # housing only, ``column_design.carried_ratio``) [kg]
    housing_wall_radius: float = math.nan
    housing_mass_radius: float = math.nan
    design_striker_mass: float = math.nan

    def as_dict(self) -> dict:
        out = asdict(self)
        out["limits"] = [lim.as_dict() for lim in self.limits]
        return out


def article_length(spec: MachineSpec) -> float:
    """The article as the reference ogive (solid 4340) of the spec's diameter at its mass."""
    R = spec.diameter / 2
    return solid_ogive_length(spec.article_mass, property_si(REFERENCE_ARTICLE["library"], "density", "density"), R,
                              REFERENCE_ARTICLE["crh"], REFERENCE_ARTICLE["meplat_over_radius"] * R)


def bore_radius(spec: MachineSpec, rho_piston: float) -> float:
    """A bore by the design oil pressure (``spec.oil_pressure``), for a caller that needs one without
    designing (the premise's map): the payload's force (article and piston) at the pulse's peak is that
    pressure, pi r^2 p = (m_a + rho pi r^2 t) A, so r^2 = m_a A / (pi (p - rho t A)); never narrower than the
    article and its clearance.  (The machine's own dashpot takes the column designer's bore.)"""
    A, p, t = spec.pulse.peak, spec.oil_pressure, DASHPOT["piston_thickness"]
    if p <= rho_piston * t * A:
        return math.inf          # the piston alone would need more than the design pressure
    return max(spec.diameter / 2 + DASHPOT["clearance"], math.sqrt(spec.article_mass * A / (math.pi * (p - rho_piston * t * A))))


@dataclass(frozen=True)
class Housing:
    """The striker's housing around a column design: its outer radius and floor [m], its steel [kg]."""
    outer_radius: float
    floor: float
    depth: float
    steel_mass: float
    striker_mass: float           # steel, pin and liquid [kg]
    wall_radius: float            # the outer radius the wall rule needs (at most Y_max) [m]
    mass_radius: float            # the outer radius at which the housing weighs the design's striker [m]
    wall_mass: float              # the housing at ``wall_radius``, with its pin and liquid [kg]

    @property
    def wall_binds(self) -> bool:
        """The wall the pressure needs is at least as thick as the design's striker's mass gives."""
        return self.wall_radius >= self.mass_radius


def striker_housing(d: dict, weight: dict, depth: float, steel: str) -> Housing:
    """The housing over the whole bore ``depth`` at the wall and floor ``weight`` (``housing.fixture_mass``)
    sized (its wall at most Y_max), or, where the design's striker is heavier, at the outer radius that
    weighs it; both radii are kept, and the mass at the wall's own radius (what the striker must at least
    be: the designer's fixed point, ``design_fixture``)."""
    rho = HOUSING_STEELS[steel].density
    r, t = d["bore_radius"], weight["floor_thickness"]
    carried = weight["pin"] + d["liquid_mass"]

    def steel_of(R):
        return rho * math.pi * ((R * R - r * r) * depth + R * R * t)
    R_wall = min(weight["outer_radius"], PRACTICAL_RATIO * r)
    # the outer radius at which the housing (steel, pin and oil) weighs the design's striker
    R_mass = math.sqrt((max(d["striker_mass"] - carried, 0.0) / (rho * math.pi) + r * r * depth) / (depth + t))
    R = max(R_wall, R_mass)
    return Housing(R, t, depth, steel_of(R), steel_of(R) + carried, R_wall, R_mass, steel_of(R_wall) + carried)


def design_fixture(spec: MachineSpec, echo=None, evaluations: int = DESIGN_EVALUATIONS,
                   search_cells: int = SEARCH_CELLS, steel: str = HOUSING_STEEL) -> Fixture:
    """The dashpot for the spec's article and pulse on the column, and the striker that carries it: the
    column designer's fixed point of the found design (``programmer.fixed_point.striker_fixed_point``,
    never below the spec's striker ratio) with the housing this fixture draws over the whole bore at its
    wall's radius, pin and oil with it (``striker_housing``)."""
    L_article = article_length(spec)

    def housing_of(out):
        d, weight = out["design"], out["fixture"]
        if out["runs"]["column"] is None:
            raise ValueError(f"fixture: the column dashpot designed for the striker ratio "
                             f"{d['striker_mass'] / d['payload_mass']:.3g} did not run "
                             f"({out['walls'].get('column_error', '')})")
        depth = d["column"] + DASHPOT["piston_thickness"] + L_article + BORE_HEADROOM
        return striker_housing(d, weight, depth, steel)

    def carried(out):
        return housing_of(out).wall_mass / out["design"]["payload_mass"]
    out = design_on_column(spec.pulse, spec.article_mass, 0.0, LIQUID, spec.striker_ratio, evaluations, search_cells,
                           steel=steel, echo=echo, pin_iterations=PIN_ITERATIONS, carried=carried,
                           article=Article(spec.diameter / 2, L_article, REFERENCE_ARTICLE["library"]))
    # the column runs of every design made: the search's and each confirmation's two on the column
    runs = out["evaluations"] + 2 * (1 + out["striker_fixed_point"]["redesigns"])
    return _fixture(spec, out, housing_of(out), runs, L_article, steel)


def _fixture(spec, out: dict, housing: Housing, runs: int, L_article: float, steel: str) -> Fixture:
    d, weight, run = out["design"], out["fixture"], out["runs"]["column"]
    pulse, band = spec.pulse.band(run.t, run.acceleration)
    r, R = d["bore_radius"], housing.outer_radius
    s = HOUSING_STEELS[steel]
    allowed = s.allowed_stress()
    wall_pressure = weight["peak_pressure"] * weight["dynamic_factor"]
    floor_pressure = float(np.max(run.floor_pressure)) * weight["floor_dynamic_factor"]
    # the stresses the rules hold at S: the wall's at its ratio (S P / P_held(Y)), the floor's at its
    # thickness (S (t_needed / t)^2, the flat head's t going as sqrt(P / S))
    wall_stress = allowed * wall_pressure / held_pressure(R / r, allowed, weight["rule"])
    floor_stress = allowed * (floor_for(floor_pressure, r, s) / housing.floor) ** 2
    payload_after, striker_after = float(run.payload_speed[-1]), float(run.striker_speed[-1])
    taken = oil_work(run, d)
    record = {k: out[k] for k in ("verdict", "models", "walls", "evaluations", "search_wall", "closed_form_bore",
                                  "lumped_agrees", "objective", "striker_fixed_point")}
    fp = out["striker_fixed_point"]
    record["housing"] = weight
    fixture = Fixture(
        spec.article_mass, spec.diameter, L_article, r, d["piston_mass"], d["payload_mass"],
        housing.striker_mass / d["payload_mass"], housing.striker_mass, d["striker_speed"], d["liquid_mass"], d["column"], float(run.stroke.max()),
        weight["peak_pressure"], R, housing.floor + housing.depth, housing.floor, housing.depth, housing.steel_mass,
        fp["binds"], wall_stress, floor_stress, allowed, pulse.peak, pulse.duration,
        pulse.velocity_change, bool(band.passed), float(band.worst_excess), payload_after, striker_after,
        float(np.trapz(run.striker_speed, run.t)), float(np.trapz(run.payload_speed, run.t)),
        taken / (d["liquid_mass"] * OIL_HEAT_CAPACITY), runs, fp["redesigns"], {**d, "column_design": record},
        taken, (payload_after - striker_after) / d["striker_speed"], steel)
    fixture.verdict = out["verdict"]
    fixture.pin_mass = weight["pin"]
    fixture.limits = fixture_limits(out, weight, s)
    fixture.housing_wall_radius, fixture.housing_mass_radius = housing.wall_radius, housing.mass_radius
    fixture.design_striker_mass = d["striker_mass"]
    return fixture


def pulse_with_push(spec: MachineSpec, fixture: Fixture, push: StrikerPush) -> dict:
    """The fixture's pulse on its column (``programmer.column_dashpot``, the design's liquid at ``CELLS``,
    as the fixture's own run) with ``push`` on the striker: its peak [m/s^2], duration [s], velocity change
    [m/s], band check, the bodies' speeds when the record ends [m/s] and their travels over it [m], and the
    run's energy balance residual over the energy in (the kinetic energy at contact and the push's work)."""
    d = fixture.design
    run = simulate_column(dashpot_lumped(d), spec.pulse.record_end(), LUMPED_SAMPLES, CELLS,
                          design_liquid(d).column(), push)
    pulse, band = spec.pulse.band(run.t, run.acceleration)
    e = run.summary
    energy_in = e["kinetic energy in [J]"] + e.get("push's work on the striker [J]", 0.0)
    return {"peak": pulse.peak, "duration": pulse.duration, "velocity_change": pulse.velocity_change,
            "band_passed": bool(band.passed), "worst_excess": float(band.worst_excess),
            "after_speed_striker": float(run.striker_speed[-1]), "after_speed_payload": float(run.payload_speed[-1]),
            "striker_travel": float(np.trapz(run.striker_speed, run.t)),
            "payload_travel": float(np.trapz(run.payload_speed, run.t)),
            "energy_residual": e["energy balance residual [J]"] / energy_in}


def oil_work(run, d: dict) -> float:
    """The energy the oil takes from striker and payload over the column ``run`` [J]: the kinetic energy
    it had, closing with the housing at V, plus the work its floor pressure takes from the housing,
    less the work its face pressure and jet give the payload (``column_dashpot``: (M - m_l) x_s'' =
    -p_floor A, m x_p'' = p A - J, the payload's force read as m a), less its kinetic energy at the
    record's end moving with the housing (which the striker's stop takes with it), by the trapezoidal
    rule over the run's samples."""
    m_l, V, A = d["liquid_mass"], d["striker_speed"], d["piston_area"]
    from_housing = float(np.trapz(run.floor_pressure * A * run.striker_speed, run.t))
    to_payload = float(np.trapz(d["payload_mass"] * run.acceleration * run.payload_speed, run.t))
    return 0.5 * m_l * (V * V - run.striker_speed[-1] ** 2) + from_housing - to_payload


# the machine's unit of each validity check (``dashpot_validity`` gives the freezing check in MPa)
_MPA = "[MPa]"


def fixture_limits(out: dict, weight: dict, steel) -> list[Limit]:
    """The column run's validity checks (those that bound the column, ``dashpot_validity.column_holds``)
    and the housing's as machine limits: a design outside a law's range is a broken limit."""
    limits = []
    for lim in out["models"]["column"]["limits"]:
        # the checks that bound the column and veto it (a flag, data a law was not checked on, is reported
        # with the design's record, not a limit)
        if ("lumped" in lim["models"] and "column" not in lim["models"]) or not lim.get("vetoes", True):
            continue
        name = lim["name"].replace(" " + _MPA, "")
        scale, unit = (1e6, "Pa") if _MPA in lim["name"] else (1.0, "-")
        value, limit = lim["value"] * scale, lim["limit"] * scale
        if lim.get("lower"):
            # a least value: its ratio is the least over the value
            name, value, limit = f"{name} (the least over it)", limit, value
        limits.append(Limit("dashpot (column run)", name, value, limit, unit, "the column dashpot's run of the design "
                            "(`programmer.column_dashpot`, `programmer.dashpot_validity`)",
                            _RANGE_SOURCE.get(lim["models"], lim["models"])))
    limits += [Limit("dashpot housing", "wall ratio b / a by ASME VIII-2 4.3.3 (P = S ln Y)", weight["wall_ratio"],
                     PRACTICAL_RATIO, "-", "the column's largest wall pressure times its dynamic factor (the worst "
                     "slice's, the piston's face or the floor, `programmer.housing.wall_factor`)", f"a monobloc forging of {steel.name}: "
                     "Y_max (`programmer.housing.PRACTICAL_RATIO`)"),
               Limit("dashpot metering pin", "stress (von Mises, the liquid's pressure all round)",
                     weight["pin_pressure"], weight["allowed_stress"], "Pa",
                     "the largest of the column's peak and the quasi-steady upstream pressure",
                     f"{steel.name}: ASME VIII-2 design stress"),
               Limit("dashpot housing floor", "thickness over diameter", weight["floor_over_diameter"], THICK_PLATE,
                     "-", "VIII-2 4.6's integral flat head at the floor's peak pressure times its factor",
                     "the flat-head formula's thin-plate range (`programmer.housing.THICK_PLATE`)")]
    base = out.get("article_base")
    if base is not None:
        limits.append(Limit("article base on the piston", "stress (mean over the bearing)", base["stress"],
                            base["yield_stress"], "Pa", "the column's payload force m a over the bearing times the "
                            "article's first axial mode's dynamic factor (`programmer.article_base`)",
                            "the article's initial yield stress (`scene.library`)"))
        limits.append(Limit("article base on the piston", "Rayleigh-Love correction to its first axial period",
                            base["rayleigh_love"], RAYLEIGH_LOVE, "-", "the article as a bar of its length",
                            "the base-stress estimate's bar range (`programmer.article_base.RAYLEIGH_LOVE`)"))
    return limits


_RANGE_SOURCE = {"the orifice law": "Idelchik's sharp-edged orifice within ISO 5167-2's area ratio and Reynolds "
                                    "number (`fluid.orifice`)",
                 "the liquid": "the liquid's state (`programmer.liquids`)",
                 "column": "the column's linearised wall faces (`fluid.column`)",
                 "lumped and column": "a column that does not part while the stroke goes on (`fluid.column`)",
                 "the premise": "restitution 0 within the design margin (`programmer.dashpot_validity.REBOUND`)"}

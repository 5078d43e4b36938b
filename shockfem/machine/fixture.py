"""The fixture: the fluid dashpot the fixture study chose, designed for this article, and its housing.

The dashpot law is ``programmer.dashpot_design`` (the fixture study's, iterated on the lumped model to
the band).  What the machine adds is the housing the striker *is*: a steel tube closed at its struck
end, its bore full of oil, sized by two closed forms at the peak oil pressure p and the allowable
S = yield / safety factor:

* wall (Lame, thick cylinder, hoop stress at the bore): p (R^2 + r^2) / (R^2 - r^2) <= S, so
  R >= r sqrt((S + p) / (S - p)), and no wall holds p >= S;
* floor (a clamped circular plate under uniform pressure; Roark, Formulas for Stress and Strain, 7th
  ed., Table 11.2 case 10b: radial stress at the edge 3 p r^2 / (4 t^2)): t >= r sqrt(3 p / (4 S)).

The striker's mass is the housing's and its oil's.  If the housing the dashpot asks for (the striker
ratio times the payload) is lighter than the wall and floor the pressure needs, the striker takes the
housing's mass and the dashpot is designed again for that ratio, until the two agree.
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass

import numpy as np

from ..parts.catalog import solid_ogive_length
from ..programmer.dashpot_design import DASHPOT, design_dashpot
from ..scene.library import initial_yield_stress, property_si
from .spec import REFERENCE_ARTICLE, MachineSpec

# the free length left in the bore above the article's nose [m]
BORE_HEADROOM = 0.02
# the striker ratio has converged when the housing's mass moves it by less than this
RATIO_TOL = 1e-3
MAX_REDESIGNS = 6
# the oil's specific heat [J/(kg K)] (a mineral oil near room temperature)
OIL_HEAT_CAPACITY = 1900.0


@dataclass
class Fixture:
    article_mass: float           # [kg]
    article_diameter: float       # [m]
    article_length: float         # [m] (the reference ogive scaled to the diameter, solid 4340)
    bore_radius: float            # [m]
    piston_mass: float            # [kg]
    payload_mass: float           # article and piston [kg]
    striker_ratio: float          # striker (housing and oil) over payload
    striker_mass: float           # [kg]
    striker_speed: float          # closing speed on the payload at rest [m/s]
    liquid_mass: float            # [kg]
    column: float                 # the liquid column at rest [m]
    stroke: float                 # relative stroke used by the lumped run [m]
    peak_pressure: float          # [Pa]
    housing_outer_radius: float   # [m]
    housing_length: float         # floor and bore [m]
    floor_thickness: float        # [m]
    bore_depth: float             # [m]
    housing_steel_mass: float     # [kg]
    housing_binds: bool           # the wall and floor set the striker's mass, not the striker ratio
    wall_hoop_stress: float       # Lame at the bore, at the peak pressure [Pa]
    floor_stress: float           # [Pa]
    allowable: float              # [Pa]
    peak: float                   # the payload's lumped pulse: peak [m/s^2]
    duration: float               # [s]
    velocity_change: float        # [m/s]
    band_passed: bool
    worst_excess: float
    after_speed_payload: float    # when the lumped record ends [m/s]
    after_speed_striker: float    # [m/s]
    striker_travel: float         # over the lumped record (the pulse and the window after it) [m]
    payload_travel: float         # [m]
    oil_heating: float            # if the oil keeps the energy the orifice throttles [K]
    lumped_runs: int
    redesigns: int
    design: dict                  # the dashpot design (``programmer.dashpot_design``), the pin table included
    # the work the oil's forces take from the two bodies over the record, integrated from the lumped run's
    # pressure, jet and speeds: int (p A (v_s - v_p) + J v_p) dt [J] (the energy table's fixture row)
    oil_work: float = math.nan
    # the payload's parting speed over the closing speed, (v_p - v_s) / V at the record's end [-]
    restitution: float = math.nan

    def as_dict(self) -> dict:
        return asdict(self)


def article_length(spec: MachineSpec) -> float:
    """The article as the reference ogive (solid 4340) of the spec's diameter at its mass."""
    R = spec.diameter / 2
    return solid_ogive_length(spec.article_mass, property_si(REFERENCE_ARTICLE["library"], "density", "density"), R,
                              REFERENCE_ARTICLE["crh"], REFERENCE_ARTICLE["meplat_over_radius"] * R)


def bore_radius(spec: MachineSpec, rho_piston: float) -> float:
    """The bore at which the payload's force (article and piston) at the pulse's peak is the design oil
    pressure: pi r^2 p = (m_a + rho pi r^2 t) A, so r^2 = m_a A / (pi (p - rho t A)); never narrower than
    the article and its clearance."""
    A, p, t = spec.pulse.peak, spec.oil_pressure, DASHPOT["piston_thickness"]
    if p <= rho_piston * t * A:
        return math.inf          # the piston alone would need more than the design pressure
    return max(spec.diameter / 2 + DASHPOT["clearance"], math.sqrt(spec.article_mass * A / (math.pi * (p - rho_piston * t * A))))


def housing_wall(p: float, r: float, S: float) -> float:
    """The smallest outer radius whose Lame hoop stress at the bore r stays at S under p (inf if p >= S)."""
    return r * math.sqrt((S + p) / (S - p)) if p < S else math.inf


def floor_thickness(p: float, r: float, S: float) -> float:
    """The clamped plate's thickness whose edge stress 3 p r^2 / (4 t^2) is S."""
    return r * math.sqrt(3 * p / (4 * S))


def design_fixture(spec: MachineSpec, echo=None) -> Fixture:
    rho_s = property_si(spec.material, "density", "density")
    S = initial_yield_stress(spec.material) / spec.safety_factor
    r = bore_radius(spec, rho_s)
    L_article = article_length(spec)
    ratio, runs, redesigns, near = spec.striker_ratio, 0, 0, None
    while True:
        d, run, n = design_dashpot(spec.pulse, spec.article_mass, r, striker_ratio=ratio, echo=echo, near=near)
        near = d["handles"]
        runs += n
        p = float(run.pressure.max())
        depth = d["column"] + DASHPOT["piston_thickness"] + L_article + BORE_HEADROOM
        t_floor = floor_thickness(p, r, S)
        R_wall = housing_wall(p, r, S)
        # the outer radius at which the housing (steel and oil) weighs the striker's mass
        steel = d["striker_mass"] - d["liquid_mass"]
        R_mass = math.sqrt((steel / (rho_s * math.pi) + r * r * depth) / (depth + t_floor))
        R = max(R_mass, R_wall)
        if not math.isfinite(R):
            break
        housing = rho_s * math.pi * ((R * R - r * r) * depth + R * R * t_floor)
        needed = (housing + d["liquid_mass"]) / d["payload_mass"]
        if needed <= ratio * (1 + RATIO_TOL) or redesigns >= MAX_REDESIGNS:
            break
        ratio, redesigns = needed, redesigns + 1
    pulse_t, pulse_a = run.t, run.acceleration
    pulse, band = spec.pulse.band(pulse_t, pulse_a)
    payload_after, striker_after = float(run.payload_speed[-1]), float(run.striker_speed[-1])
    throttled = (0.5 * d["striker_mass"] * d["striker_speed"] ** 2 - 0.5 * d["striker_mass"] * striker_after ** 2
                 - 0.5 * d["payload_mass"] * payload_after ** 2)
    R_ok = R if math.isfinite(R) else math.nan
    fixture = Fixture(
        spec.article_mass, spec.diameter, L_article, r, d["piston_mass"], d["payload_mass"], ratio, d["striker_mass"],
        d["striker_speed"], d["liquid_mass"], d["column"], float(run.stroke.max()), p, R_ok, t_floor + depth,
        t_floor, depth, housing if math.isfinite(R) else math.nan, redesigns > 0 or R_wall > R_mass,
        p * (R_ok ** 2 + r * r) / (R_ok ** 2 - r * r) if math.isfinite(R) else math.inf,
        3 * p * r * r / (4 * t_floor ** 2), S, pulse.peak, pulse.duration, pulse.velocity_change, bool(band.passed),
        float(band.worst_excess), payload_after, striker_after, float(np.trapz(run.striker_speed, run.t)),
        float(np.trapz(run.payload_speed, run.t)),
        throttled / (d["liquid_mass"] * OIL_HEAT_CAPACITY), runs, redesigns, d)
    fixture.oil_work = oil_work(run, d["piston_area"])
    fixture.restitution = (payload_after - striker_after) / d["striker_speed"]
    return fixture


def oil_work(run, area: float) -> float:
    """The work the oil takes from striker and payload [J]: its pressure p A on the relative motion and
    the jet's reaction J on the payload (``programmer.lumped_dashpot``: m x_p'' = p A - J, M x_s'' = -p A),
    by the trapezoidal rule over the run's samples."""
    jet = getattr(run, "jet_force", np.zeros_like(run.t))
    power = run.pressure * area * (run.striker_speed - run.payload_speed) + jet * run.payload_speed
    return float(np.trapz(power, run.t))


"""The fluid dashpot designed to a pulse specification, for any payload: the closed form and the lumped
designer.

The closed form (``dashpot_design``): the striker carries a housing full of liquid; the article stands
on a light piston in its bore; a metering pin holds the force m A_g on piston and article over the
relative stroke (``fluid.orifice.area_for_force`` at the relative speed a constant force leaves the two
masses, on the sharp-edged law, the pin's opening never beyond that law's largest area ratio).  Four
handles, factors on that closed form (the pin's opening, the liquid column over the stroke, the force
the pin is cut for over m A_g, the striker's speed), are iterated by Nelder-Mead on the lumped model
(``programmer.lumped_dashpot``) by ``design_dashpot`` (the whole machine's fixture, ``shockfem.machine``,
designs with it) to a pulse inside the specification's band narrowed by ``DESIGN_MARGIN``.  Every design
it makes carries the validity checks of ``dashpot_validity``; where the lumped model leaves its range
(at a shock machine's speeds it does: the liquid's Mach number, mass and transit time), the same design
is run on the liquid column and both are reported.  The designer that designs on the column, with the
bore as a handle, is ``programmer.column_design`` (the fixture study's).
"""
from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq, minimize

from ..amplifier.gain import collide
from ..amplifier.interfaces import reduced_mass
from ..metrics import shapes
from ..metrics.pulse import pulse_metrics
from ..metrics.shapes import TOLERANCE
from ..scene.library import property_si
from ..fluid.orifice import AREA_RATIO, OrificeLaw, area_for_force, piston_force, pressure_for_flow
from .column_dashpot import simulate_column
from .dashpot_validity import Limit, dashpot_limits, lumped_holds
from .liquids import LIQUIDS, MINERAL_OIL, DesignLiquid
from .lumped_dashpot import LumpedDashpot, simulate
from .requirement import requirement

# the oil (a mineral hydraulic oil) and the discharge coefficient of the study's first orifice law
OIL = {"density": 870.0, "bulk_modulus": 1.5e9, "discharge": 0.7}
# the orifice's law the dashpot is designed on (``fluid/orifice.py``): Idelchik's sharp-edged orifice with
# the velocity of approach and the jet's reaction, its pin never opening beyond ISO 5167-2's area ratio
ORIFICE_LAW = AREA_RATIO
# the bore clears the article by ``clearance``; the piston's thickness; the metering pin's points; the
# liquid column over the relative stroke at the closed form (the liquid must outlast the stroke)
DASHPOT = {"clearance": 0.002, "piston_thickness": 0.015, "pin_points": 200, "column_over_stroke": 1.3}
CARRIER_STEEL = "high_strength_steel"          # the fixture's metal parts
# striking mass over payload, the least a striker weighs: heavy enough that the payload's velocity change
# costs the striker only a tenth of its speed; a striker is never lighter than what it carries
# (``striker_carrying``)
STRIKER_RATIO = 10.0
# the striker's own structure beyond the housing and its liquid (its guide bands, struck face, the pin's
# anchorage), as a share of those two: an assumption, not a design
STRIKER_STRUCTURE = 0.2
HANDLES = ("pin_scale", "column_over_stroke", "force_factor", "speed_factor")
START = (1.0, DASHPOT["column_over_stroke"], 1.0, 1.0)
DESIGN_MARGIN = 0.03             # the lumped design aims this share of the peak inside the band
LUMPED_SAMPLES = 3000
RESTART_SPREAD = 0.02            # the simplex of a search started near a neighbouring design


@dataclass(frozen=True)
class PulseSpec:
    """A specified pulse: shape (``programmer.shapes.SHAPES``), peak [m/s^2], duration [s]."""
    shape: str
    peak: float
    duration: float

    @property
    def checked_shape(self) -> str:
        """The shape the shock metrics check against: a rectangle as MIL-STD-810's trapezoid (10% ramps)."""
        return "trapezoid" if self.shape == "rectangle" else self.shape

    def record_end(self) -> float:
        """The record a band check needs after first contact: the pulse and the window after it."""
        return self.duration * (1.0 + TOLERANCE["after"]) * 1.2

    def band_velocity_change(self) -> float:
        """The velocity change [m/s] at the centre of what the band accepts: the checked shape's ideal pulse's
        (a rectangle's is MIL-STD-810's trapezoid's, 0.9 A T), not the specified shape's own (A T)."""
        return shapes.specified(self.checked_shape, self.peak, self.duration).velocity_change

    def band_velocity_range(self) -> tuple[float, float]:
        """The least and the largest velocity change [m/s] the band accepts: its centre
        (``band_velocity_change``) less and plus the band's tolerance."""
        dv, tol = self.band_velocity_change(), TOLERANCE["velocity_change"]
        return (1.0 - tol) * dv, (1.0 + tol) * dv

    def least_velocity_change(self) -> float:
        """The least velocity change [m/s] the band accepts (``band_velocity_range``)."""
        return self.band_velocity_range()[0]

    def placed_ideal(self, t, a, pulse):
        """The specified pulse placed on a measured one."""
        return shapes.place(shapes.specified(self.checked_shape, self.peak, self.duration), t, pulse.sign * a, pulse)

    def band(self, t: np.ndarray, a: np.ndarray, margin: float = 0.0):
        """The pulse metrics of a payload acceleration record ``a`` starting at first contact, and its
        check against the band (``metrics.shapes``), the record padded with rest before contact so that
        the band's window is covered."""
        before = TOLERANCE["before"] * self.duration * 1.2
        n = max(int(before / (t[1] - t[0])), 2)
        t = np.concatenate([t[0] - before + np.arange(n) * before / n, t])
        a = np.concatenate([np.zeros(n), a])
        pulse = pulse_metrics(t, a)
        return pulse, shapes.band_check(t, pulse.sign * a, self.placed_ideal(t, a, pulse), margin)


def striker_speed(payload: float, striker: float, dv: float, e: float = 0.0) -> float:
    """The striking speed that gives a payload at rest the velocity change ``dv`` (the rigid collision
    law of the amplifier, restitution ``e``: 0 for a programmer that stops the two together)."""
    return brentq(lambda v: collide(striker, v, payload, 0.0, e)[1] - dv, 0.0, 100.0 * dv)


def striker_carrying(housing_mass: float, liquid_mass: float) -> float:
    """The least striker [kg] that carries a housing and its liquid [kg]: the two and its own structure."""
    return (housing_mass + liquid_mass) * (1.0 + STRIKER_STRUCTURE)


def upstream_pressure(n: float, speed: float, density: float, law: OrificeLaw = ORIFICE_LAW) -> float:
    """The quasi-steady pressure [Pa] upstream of an orifice of area ratio ``n`` in a piston driven at
    ``speed`` [m/s] into incompressible liquid of ``density``: the pressure the liquid's flow needs, which
    the wall, the floor and the pin stand in (at the law's largest ratio, the least any pin makes)."""
    return pressure_for_flow(speed, density, n, 1.0, law.code())


def carrier_density() -> float:
    return property_si(CARRIER_STEEL, "density", "density")


def dashpot_design(pulse: PulseSpec, article_mass: float, bore_radius: float, handles=START,
                   seat_mass: float = 0.0, striker_ratio: float = STRIKER_RATIO,
                   law: OrificeLaw = ORIFICE_LAW, liquid: DesignLiquid = MINERAL_OIL) -> dict:
    """The fluid dashpot for ``pulse`` on an article of ``article_mass`` [kg] in a bore of
    ``bore_radius`` [m]: a piston the article stands on, the metering pin that holds the force m A_g on
    the payload (article, piston and a ``seat_mass`` riding with them) over the relative stroke against a
    striker of ``striker_ratio`` times the payload, by the orifice ``law``, its opening never wider than
    the law's largest area ratio, filled with ``liquid`` (``programmer.liquids``).  ``handles``
    (``HANDLES``) scale that design; the start is the design itself.  SI throughout."""
    pin_scale, column_over_stroke, force_factor, speed_factor = handles
    area = math.pi * bore_radius ** 2
    m_piston = carrier_density() * area * DASHPOT["piston_thickness"]
    payload = article_mass + m_piston + seat_mass
    req = requirement(pulse.shape, pulse.peak, pulse.duration, payload)
    M = striker_ratio * payload
    V = speed_factor * striker_speed(payload, M, req.velocity_change)
    reduced = reduced_mass(payload, M)
    force = force_factor * payload * pulse.peak
    stroke = reduced * V * V / (2 * force)
    rho = liquid.density
    strokes = np.linspace(0.0, stroke, DASHPOT["pin_points"])
    largest = law.largest_ratio * area
    code = law.code()
    # the relative speed the constant force leaves: v^2 = V^2 - 2 F x / mu (mu the reduced mass)
    speeds = np.sqrt(np.maximum(V * V - 2.0 * force * strokes / reduced, 0.0))
    pin = [min(pin_scale * area_for_force(force, v, rho, area, largest, code), largest) for v in speeds]
    p_least = piston_force(largest, V, rho, area, code) / area
    return {"handles": dict(zip(HANDLES, map(float, handles))), "orifice_law": dataclasses.asdict(law),
            "bore_radius": bore_radius, "piston_area": area, "piston_mass": m_piston, "article_mass": article_mass,
            "seat_mass": seat_mass, "payload_mass": payload,
            "striker_mass": M, "striker_speed": V, "force": force, "design_pressure": force / area,
            "least_pressure": p_least, "upstream_pressure": upstream_pressure(law.largest_ratio, V, rho, law),
            "initial_overshoot": p_least * area / force - 1.0, "stroke_design": stroke,
            "column": column_over_stroke * stroke, "pin": [[float(x), float(a)] for x, a in zip(strokes, pin)],
            "liquid_mass": rho * area * column_over_stroke * stroke,
            "liquid": next(k for k, v in LIQUIDS.items() if v == liquid), "piston_thickness": DASHPOT["piston_thickness"]}


def design_liquid(d: dict) -> DesignLiquid:
    """The liquid a design is filled with (the study's oil for a design that names none)."""
    return LIQUIDS[d.get("liquid", "oil")]


def dashpot_lumped(d: dict) -> LumpedDashpot:
    """The lumped model (``programmer.lumped_dashpot``) of a dashpot design, on the design's orifice law."""
    liquid = design_liquid(d)
    return LumpedDashpot(d["striker_mass"], d["payload_mass"], d["striker_speed"],
                         d["piston_area"], d["column"], tuple(map(tuple, d["pin"])), liquid.density,
                         liquid.bulk_modulus, OIL["discharge"], liquid.tait_exponent,
                         law=OrificeLaw(**d["orifice_law"]), orifice_land=d.get("piston_thickness", 0.0))


def design_dashpot(pulse: PulseSpec, article_mass: float, bore_radius: float, seat_mass: float = 0.0,
                   striker_ratio: float = STRIKER_RATIO, echo=None, near: dict | None = None,
                   law: OrificeLaw = ORIFICE_LAW) -> tuple[dict, object, int]:
    """The dashpot's handles iterated on the lumped model (Nelder-Mead from the closed form) to a pulse
    inside the band narrowed by ``DESIGN_MARGIN``: the objective is the narrowed band's worst excess and
    the velocity change beyond its tolerance, with the velocity-change error and the largest deviation
    from the ideal as a small tie-breaker toward the band's middle.  Returns (design, lumped run,
    evaluations).  ``near``: the handles of a design for nearly the same inputs (the same payload with a
    slightly heavier striker); the search then starts there in a simplex RESTART_SPREAD wide, not from
    the closed form's.  ``law``: the orifice law the pin is cut on (``ORIFICE_LAW`` unless given)."""
    end = pulse.record_end()

    def design(h):
        return dashpot_design(pulse, article_mass, bore_radius, h, seat_mass, striker_ratio, law)

    def objective(h):
        if h[0] <= 0.05 or h[1] <= 1.02 or h[2] <= 0.3 or h[3] <= 0.5:
            return 10.0
        run = simulate(dashpot_lumped(design(h)), end, LUMPED_SAMPLES)
        _, band = pulse.band(run.t, run.acceleration, DESIGN_MARGIN)
        allowed = TOLERANCE["velocity_change"] - DESIGN_MARGIN
        return (10.0 * (band.worst_excess + max(0.0, abs(band.velocity_change_error) - allowed))
                + abs(band.velocity_change_error) + 0.1 * band.worst_deviation)
    options = {"xatol": 1e-3, "fatol": 1e-5, "maxfev": 400}
    start = START
    if near:
        start = np.array([near[k] for k in HANDLES])
        options["initial_simplex"] = np.vstack([start, start * (1 + RESTART_SPREAD * np.eye(len(start)))])
    res = minimize(objective, start, method="Nelder-Mead", options=options)
    if echo:
        echo(f"  dashpot design: {res.nfev} lumped runs")
    d = design(tuple(res.x))
    run = simulate(dashpot_lumped(d), end, LUMPED_SAMPLES)
    d.update(check_design(d, run, pulse))
    if echo:
        echo("  " + "; ".join(Limit(**{k: v for k, v in lim.items() if k != "holds"}).describe()
                              for lim in d["limits"]))
    return d, run, int(res.nfev)


def check_design(d: dict, run, pulse: PulseSpec) -> dict:
    """The dashpot's range checks on its lumped ``run`` (``dashpot_validity``) and, where the lumped model
    leaves its range, the same design on the liquid column (``column_dashpot``) with its pulse and its
    own checks: what a designer must read before trusting the lumped pulse."""
    lumped = dashpot_lumped(d)
    limits = dashpot_limits(lumped, run, design_liquid(d))
    out = {"limits": [lim.as_dict() for lim in limits], "lumped_holds": lumped_holds(limits)}
    if not out["lumped_holds"]:
        column = simulate_column(lumped, pulse.record_end(), LUMPED_SAMPLES, liquid=design_liquid(d).column())
        metrics, band = pulse.band(column.t, column.acceleration)
        out["column_check"] = {"peak": float(metrics.peak), "duration": float(metrics.duration),
                               "velocity_change": float(metrics.velocity_change), "band_passed": bool(band.passed),
                               "peak_pressure": float(column.pressure.max()),
                               "peak_floor_pressure": float(column.floor_pressure.max()),
                               "limits": [lim.as_dict() for lim in dashpot_limits(lumped, column, design_liquid(d))],
                               **column.summary}
    return out

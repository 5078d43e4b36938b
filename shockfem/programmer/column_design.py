"""The fluid dashpot designed on a model that holds for it: the liquid as a compressible column
(``column_dashpot``), the orifice as Idelchik's sharp-edged one with the velocity of approach and the
jet's reaction, the bore a design variable, and every design checked against the laws' ranges.

Why the bore is a handle and not the article's calibre.  At the largest area ratio the design allows
(n_max, a parameter: by default 0.5625, ``fluid.orifice.VALID_AREA_RATIO``, the law's checked data;
wider, the law is extrapolated and every run says so) the least force the orifice makes per unit of
piston area is fixed by the closing speed V alone (``least_force_per_area``: the Borda-Carnot loss
rho (u_j - u1)^2 / 2 at u_j = V / (Cc n)), so a bore of area A throttles at least q(V) A at contact.
The payload's force m A_g and q(V) set the bore, A0 = m A_g / q(V) (``bore_for_force``): a wider bore
cannot start the pulse at its level, a narrower one needs a higher pressure, a heavier housing and a
lower Reynolds number.  The handles (``HANDLES``): the bore over A0's radius, the column over the
stroke, the force the pin is cut for over m A_g, the striker's speed over the collision law's; each
is a factor on ``dashpot_design.dashpot_design``'s closed form at that bore.

The search: Nelder-Mead on the column at ``SEARCH_CELLS`` cells, its objective the band's (the
lumped designer's, ``dashpot_design.design_dashpot``) plus a penalty for every check of
``dashpot_validity`` that bounds the column and fails, each weighted by how far it is outside.  The
design found is then run on the column at ``column_dashpot.CELLS`` cells (the difference from the
search's grid printed) and on the lumped model with the same law (the difference printed: the lumped
model designs only where that difference is inside its own checks and the band's margin), and weighed
whole (``housing.fixture_mass``).  The housing is a constraint of the search too: a wall's peak
pressure times its dynamic factor above what the steel holds at its allowed stress adds its log ratio.  A design whose checks do not all hold is reported outside, not
chosen: the search's penalty pushes it in where it can, and where it cannot, the checks say why.
"""
from __future__ import annotations

import math
import time

import numpy as np
from scipy.optimize import brentq, minimize

from ..amplifier.interfaces import reduced_mass
from ..fluid.orifice import AREA_RATIO, VALID_AREA_RATIO, OrificeLaw, jet_reaction, mass_flow, piston_force
from ..metrics.shapes import TOLERANCE
from .column_dashpot import CELLS, simulate_column
from .dashpot_design import (DASHPOT, DESIGN_MARGIN, LUMPED_SAMPLES, STRIKER_RATIO, PulseSpec, carrier_density,
                             dashpot_design, dashpot_lumped, striker_speed)
from .dashpot_validity import Limit, column_holds, dashpot_limits, lumped_holds
from .housing import HOUSING_STEEL, HOUSING_STEELS, fixture_mass
from .liquids import DesignLiquid, MINERAL_OIL
from .lumped_dashpot import simulate
from .requirement import requirement

HANDLES = ("bore_scale", "column_over_stroke", "force_factor", "speed_factor")
START = (1.0, DASHPOT["column_over_stroke"], 1.0, 1.0)
SEARCH_CELLS = 100                      # the column's cells in the search (the design is rerun at CELLS)
# a check outside its limit by a ratio r adds PENALTY ln(r) to the objective (the band's own excess
# weighs 10): a log, since a check can be outside by orders of magnitude (a cavity against 1e-6)
PENALTY = 10.0
# the handles' box: outside it the objective is flat (a design the closed form does not describe)
BOX = ((0.2, 3.0), (1.02, 4.0), (0.3, 3.0), (0.5, 1.5))


def least_force_per_area(speed: float, density: float, law: OrificeLaw = AREA_RATIO) -> float:
    """The least force per unit piston area [Pa] the orifice makes at ``speed`` [m/s] into liquid of
    ``density``: the law's force at its largest area ratio (independent of the bore's size)."""
    return piston_force(law.largest_ratio, speed, density, 1.0, law.code())


def bore_for_force(force: float, speed: float, density: float, law: OrificeLaw = AREA_RATIO) -> float:
    """The bore radius [m] at which the orifice's least force at ``speed`` is ``force`` [N]."""
    return math.sqrt(force / least_force_per_area(speed, density, law) / math.pi)


def closed_form_bore(pulse: PulseSpec, article_mass: float, seat_mass: float, liquid: DesignLiquid,
                     striker_ratio: float = STRIKER_RATIO, law: OrificeLaw = AREA_RATIO) -> float:
    """A0's radius: the bore whose least force at the collision law's closing speed is m A_g, the
    piston's own mass (steel, ``DASHPOT["piston_thickness"]`` thick) in m, by fixed-point iteration."""
    radius = 0.03
    for _ in range(20):
        payload = article_mass + seat_mass + carrier_density() * math.pi * radius ** 2 * DASHPOT["piston_thickness"]
        dv = requirement(pulse.shape, pulse.peak, pulse.duration, payload).velocity_change
        V = striker_speed(payload, striker_ratio * payload, dv)
        radius = bore_for_force(payload * pulse.peak, V, liquid.density, law)
    return radius


def contact_shock(V: float, a: float, A: float, liquid, law: OrificeLaw = AREA_RATIO) -> tuple[float, float]:
    """The exact face pressure [Pa] and force on the piston [N] of a piston with an orifice ``a`` in a
    bore ``A`` driven at ``V`` into the liquid at rest (``programmer.liquids.DesignLiquid``): a shock
    runs ahead of the piston (Rankine-Hugoniot: p = rho0 s u, rho = rho0 s / (s - u), p = Tait's
    p(rho)) and the orifice passes the liquid's flow relative to the piston,
    rho (V - u) A = mdot(p, rho) , solved for the liquid's speed u behind the shock."""
    rho0, K, n = liquid.density, liquid.bulk_modulus, liquid.tait_exponent
    code = law.code()

    def state(u):
        s = brentq(lambda s: rho0 * s * u - K / n * ((s / (s - u)) ** n - 1.0), u * (1 + 1e-12) + 1e-9,
                   100.0 * (liquid.sound_speed() + u))
        rho = rho0 * s / (s - u)
        return rho0 * s * u, rho

    def mismatch(u):
        p, rho = state(u)
        c = math.sqrt((K + n * p) / rho)
        return rho * (V - u) * A - mass_flow(p, rho, c, a, A, code)
    u = brentq(mismatch, 1e-9 * V, V * (1 - 1e-12))
    p, rho = state(u)
    mdot = rho * (V - u) * A
    return p, p * A - jet_reaction(mdot, rho, a, A, code)


def contact_pressure_limit(liquid: DesignLiquid, steel: str = HOUSING_STEEL, factor: float = 2.0,
                           allowed: float | None = None, law: OrificeLaw = AREA_RATIO) -> tuple:
    """The closing speed [m/s] above which no wall of ``steel`` holds the front a piston makes at
    contact with its orifice at the law's largest area ratio (the least front any pin in the law's range
    makes), that front rising as a step on the wall (dynamic ``factor`` 2): (speed, the front [Pa] at it,
    the most the wall holds [Pa]); ``allowed``: the wall's stress [Pa] if not the steel's design stress;
    ``law``: the orifice law with the design's largest area ratio."""
    held = (allowed or HOUSING_STEELS[steel].allowed_stress()) / math.sqrt(3.0) / factor
    A = 1.0e-3
    speed = brentq(lambda V: contact_shock(V, law.largest_ratio * A, A, liquid, law)[0] - held, 1.0, 3000.0)
    return speed, held, held * factor


def _design(pulse, article_mass, seat_mass, liquid, base_radius, h, striker_ratio, law=AREA_RATIO):
    bore_scale, column_over_stroke, force_factor, speed_factor = h
    d = dashpot_design(pulse, article_mass, bore_scale * base_radius, (1.0, column_over_stroke, force_factor,
                                                                        speed_factor),
                       seat_mass, striker_ratio, law, liquid)
    d["handles"] = dict(zip(HANDLES, map(float, h)))
    return d


def _objective_of(pulse, band, limits):
    allowed = TOLERANCE["velocity_change"] - DESIGN_MARGIN
    banded = (10.0 * (band.worst_excess + max(0.0, abs(band.velocity_change_error) - allowed))
              + abs(band.velocity_change_error) + 0.1 * band.worst_deviation)
    outside = sum(math.log(lim.value / lim.limit) for lim in limits
                  if lim.vetoes and ("column" in lim.models or "lumped" not in lim.models) and not lim.holds)
    return banded + PENALTY * outside


def design_on_column(pulse: PulseSpec, article_mass: float, seat_mass: float = 0.0,
                     liquid: DesignLiquid = MINERAL_OIL, striker_ratio: float = STRIKER_RATIO,
                     evaluations: int = 120, search_cells: int = SEARCH_CELLS, cells: int = CELLS,
                     steel: str = HOUSING_STEEL, echo=None, largest_ratio: float = VALID_AREA_RATIO) -> dict:
    """The dashpot for ``pulse`` on an article of ``article_mass`` [kg] (a ``seat_mass`` riding with it)
    filled with ``liquid``, iterated on the column (``evaluations`` runs at most, ``search_cells``
    cells) and confirmed on it at ``cells``, with the lumped model's run of the same design beside it.
    Returns a dict: the design, its runs (``column``, ``search_column``, ``lumped``), their band checks
    and validity checks, the fixture's mass (``housing.fixture_mass`` on ``steel``), the wall times, and
    ``verdict``: "inside" (band passed, every check of the column holds, a housing holds it), "outside
    the laws' ranges", "no housing holds it", or "fails the band".  ``largest_ratio``: the widest the
    pin may open (n_max; beyond ``VALID_AREA_RATIO`` the law is extrapolated, which the checks flag)."""
    end, law = pulse.record_end(), OrificeLaw(largest_ratio=largest_ratio)
    base = closed_form_bore(pulse, article_mass, seat_mass, liquid, striker_ratio, law)
    liquid_column = liquid.column()

    def objective(h):
        if any(not lo <= x <= hi for x, (lo, hi) in zip(h, BOX)):
            return 100.0
        d = _design(pulse, article_mass, seat_mass, liquid, base, h, striker_ratio, law)
        try:
            run = simulate_column(dashpot_lumped(d), end, LUMPED_SAMPLES, search_cells, liquid_column)
        except (RuntimeError, ValueError):        # the piston reached the floor; a striker lighter than its oil
            return 50.0
        _, band = pulse.band(run.t, run.acceleration, DESIGN_MARGIN)
        return (_objective_of(pulse, band, dashpot_limits(dashpot_lumped(d), run, liquid))
                + PENALTY * math.log(max(housing_ratio(d, run, steel), 1.0)))

    t0 = time.perf_counter()
    res = minimize(objective, np.array(START), method="Nelder-Mead",
                   options={"xatol": 1e-3, "fatol": 1e-4, "maxfev": evaluations})
    search_wall = time.perf_counter() - t0
    d = _design(pulse, article_mass, seat_mass, liquid, base, tuple(res.x), striker_ratio, law)
    out = confirm(d, pulse, liquid, search_cells, cells, steel)
    out.update(closed_form_bore=base, evaluations=int(res.nfev), search_wall=search_wall,
               objective=float(res.fun))
    if echo:
        echo(f"  dashpot on the column ({liquid.name}): {res.nfev} runs, {search_wall:.0f} s, {out['verdict']}")
    return out


def confirm(d: dict, pulse: PulseSpec, liquid: DesignLiquid, search_cells: int = SEARCH_CELLS,
            cells: int = CELLS, steel: str = HOUSING_STEEL) -> dict:
    """A design on the column at ``cells`` and ``search_cells`` and on the lumped model, each with its
    pulse, band check and validity checks, and the fixture weighed on the column's pressures."""
    end, lumped_design = pulse.record_end(), dashpot_lumped(d)
    runs, walls = {}, {}
    for name, fn in (("column", lambda: simulate_column(lumped_design, end, LUMPED_SAMPLES, cells, liquid.column())),
                     ("search_column", lambda: simulate_column(lumped_design, end, LUMPED_SAMPLES, search_cells,
                                                               liquid.column())),
                     ("lumped", lambda: simulate(lumped_design, end, LUMPED_SAMPLES))):
        t0 = time.perf_counter()
        try:
            runs[name] = fn()
        except (RuntimeError, ValueError) as exc:
            runs[name] = None
            walls[name + "_error"] = str(exc)
        walls[name] = time.perf_counter() - t0
    models = {}
    for name, run in runs.items():
        if run is None:
            continue
        metrics, band = pulse.band(run.t, run.acceleration)
        limits = dashpot_limits(lumped_design, run, liquid)
        models[name] = {"peak": float(metrics.peak), "duration": float(metrics.duration),
                        "velocity_change": float(metrics.velocity_change), "band_passed": bool(band.passed),
                        "worst_excess": float(band.worst_excess), "peak_pressure": float(np.max(run.pressure)),
                        "limits": [lim.as_dict() for lim in limits],
                        "holds": column_holds(limits) if name != "lumped" else lumped_holds(limits)}
    column = runs["column"]
    weight = (fixture_mass(d, column.t, np.maximum(column.pressure, column.floor_pressure), column.floor_pressure,
                           steel) if column is not None else None)
    col = models.get("column")
    verdict = ("not run" if col is None else "outside the laws' ranges" if not col["holds"]
               else "no housing holds it" if not math.isfinite(weight["fixture"])
               else "fails the band" if not col["band_passed"] else "inside")
    return {"design": d, "runs": runs, "models": models, "fixture": weight, "walls": walls, "verdict": verdict,
            "lumped_agrees": _lumped_agrees(models)}


def housing_ratio(d: dict, run, steel: str = HOUSING_STEEL) -> float:
    """The wall's peak pressure times its dynamic factor over the most a wall of ``steel`` can hold at
    its allowed stress (s / sqrt(3), an infinitely thick wall): above 1 no housing holds the design."""
    weight = fixture_mass(d, run.t, np.maximum(run.pressure, run.floor_pressure), run.floor_pressure, steel)
    return weight["peak_pressure"] * weight["dynamic_factor"] / weight["holdable_pressure"]


def _lumped_agrees(models: dict) -> bool:
    """Whether the lumped model may stand for the column on this design: its own checks hold and its
    peak and velocity change are within the design margin of the column's."""
    lumped, column = models.get("lumped"), models.get("column")
    if lumped is None or column is None:
        return False
    return bool(lumped["holds"] and abs(lumped["peak"] / column["peak"] - 1.0) <= DESIGN_MARGIN
                and abs(lumped["velocity_change"] / column["velocity_change"] - 1.0) <= DESIGN_MARGIN)


def describe_limits(limits: list[dict]) -> str:
    return "; ".join(Limit(**{k: v for k, v in lim.items() if k != "holds"}).describe() for lim in limits)

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
whole (``housing.fixture_mass``: the wall by ASME VIII-2's rule unless another is named).  The housing
is a constraint of the search too: a wall's peak pressure times its dynamic factor above what the steel
holds at the practical wall ratio (``housing.PRACTICAL_RATIO``) adds its log ratio, and so does the
metering pin's von Mises stress (the liquid's pressure all round it) above the steel's S.  A design whose
checks do not all hold is reported outside, not chosen: the search's penalty pushes it in where it can,
and where it cannot, the checks say why.

The metering pin is then cut on the column (``pin_cut.cut_pin``): the handles fix the bore, the column,
the striker and the force, and the pin's area table is iterated against the column's own force at the
design grid, from the pin the handles were searched with; of its iterates the design keeps the one of
the least objective (the search's: band, checks, housing, pin) among those inside every vetoing check of the
column's, so the cut never makes the design worse by that objective nor takes it out of the laws' ranges
(its first iterate is the searched pin, its closing end held at the machinable least gap).  And the
handles are searched with the pin they get (``search_rounds``): the first search on the quasi-steady
pin at ``SEARCH_CELLS``, each next one on the last one's cut pin (its shape carried to the trial handles
as a factor a pin point, ``carried_pin``) at the design grid, where that pin was cut (the coarse grid
reads a pin cut to the fine grid's waves wrongly), the pin cut again after each, until the handles or
the score settle; the round of the least score at the design grid is kept, never worse than the
quasi-steady handles cut after.

The striker carries the housing of the design found.  The handles are searched at a start: the striker
that carries the housing of the closed-form design at the start handles (``carried_ratio``), whose
pressure is not the found design's.  The striker is then the fixed point of the found design with its
own housing, pin and oil (``carried_ratio_of``; ``fixed_point.striker_fixed_point``): both ways from the
start, never below the ratio asked, to ``STRIKER_TOLERANCE``, each trial ratio the found handles designed
again at it (their closed-form bore and collision law at that striker), searched again from them where
that design breaks a check the found one holds or scores worse than the found one by more than
``SCORE_SETTLED`` (``fixed_point.redesigned``).  A lighter striker closes faster and raises the
pressure, so the design kept holds every vetoing check and housing limit the found design holds, where
any trial carrying its housing does (``admissible``, ``design_checks``), and the record
(``striker_fixed_point``) says when the search did not converge.  The confirmed design reports its
striker against what carries its own housing and the closing speed the band then takes
(``striker_report``).  A caller whose striker carries more (the machine's housing over the whole bore)
passes its own ``carried``.

The closed-form limits, before any design (``contact_pressure_limit``, ``upstream_pressure_limit``): the
closing speed above which the least front at contact, reflected at the floor and as a step, exceeds
what a wall of the practical ratio holds; and the one above which the quasi-steady pressure upstream of
the law's largest opening (a lower bound on every pin's start of stroke) exceeds what the wall holds
statically or the pin holds at the steel's S.
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq, minimize

from ..amplifier.interfaces import reduced_mass
from ..fluid.orifice import AREA_RATIO, VALID_AREA_RATIO, OrificeLaw, jet_reaction, mass_flow, piston_force
from ..metrics.shapes import TOLERANCE
from .article_base import Article, base_stress
from .column_dashpot import CELLS, simulate_column
from .dashpot_design import (DASHPOT, DESIGN_MARGIN, LUMPED_SAMPLES, STRIKER_RATIO, PulseSpec, carrier_density,
                             dashpot_design, dashpot_lumped, striker_carrying, striker_speed, upstream_pressure)
from .dashpot_validity import Limit, column_holds, dashpot_limits, lumped_holds
from .housing import (HOUSING_STEEL, HOUSING_STEELS, PRACTICAL_RATIO, WALL_RULE, fixture_mass, held_pressure,
                      step_factor)
from .fixed_point import STRIKER_TOLERANCE, redesigned, striker_fixed_point
from .jet_load import jet_load
from .liquids import DesignLiquid, MINERAL_OIL
from .lumped_dashpot import simulate
from .pin_cut import ITERATIONS as PIN_ITERATIONS, cut_pin, pin_bounds
from .requirement import requirement

HANDLES = ("bore_scale", "column_over_stroke", "force_factor", "speed_factor")
START = (1.0, DASHPOT["column_over_stroke"], 1.0, 1.0)
SEARCH_CELLS = 100                      # the column's cells in the search (the design is rerun at CELLS)
# a check outside its limit by a ratio r adds PENALTY ln(r) to the objective (the band's own excess
# weighs 10): a log, since a check can be outside by orders of magnitude (a cavity against 1e-6)
PENALTY = 10.0
# the pin's cut: an iterate outside a vetoing check of the column's scores this much over its objective
OUTSIDE_SCORE = 1.0e6
# the handle searches (``search_rounds``): the first on the quasi-steady pin, each next on the last one's
# pin cut at the design grid, until no handle moves by more than HANDLES_SETTLED of itself or the round's
# score (the kept quantity) by no more than SCORE_SETTLED of the last round's
PIN_ROUNDS, HANDLES_SETTLED, SCORE_SETTLED = 6, 0.02, 0.02
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


def wall_holds(steel: str = HOUSING_STEEL, rule: str = WALL_RULE, ratio: float = PRACTICAL_RATIO) -> float:
    """The most a wall of ``steel`` holds [Pa] by ``rule`` at the practical wall ratio (``housing``)."""
    return held_pressure(ratio, HOUSING_STEELS[steel].allowed_stress(), rule)


def contact_pressure_limit(liquid: DesignLiquid, steel: str = HOUSING_STEEL, reflection: float = 2.0,
                           rule: str = WALL_RULE, ratio: float = PRACTICAL_RATIO, law: OrificeLaw = AREA_RATIO) -> tuple:
    """The closing speed [m/s] above which no wall of ``steel`` up to ``ratio`` (by ``rule``) holds the
    front a piston makes at contact with its orifice at the law's largest area ratio (the least front any
    pin in the law's range makes in the 1D model), that front ``reflection`` times over (2 at the floor,
    a closed end; 1 on the wall by the piston) and times its dynamic factor, on the designs' basis
    (``housing.dynamic_factor`` of the wall's pressure history; the front's own history is a step:
    ``housing.step_factor``, 2): (speed, the front [Pa] at it, the factor, the most the wall holds [Pa]);
    ``law``: the orifice law with the design's largest area ratio."""
    holds, factor = wall_holds(steel, rule, ratio), step_factor()
    front = holds / (reflection * factor)
    A = 1.0e-3
    speed = brentq(lambda V: contact_shock(V, law.largest_ratio * A, A, liquid, law)[0] - front, 1.0, 3000.0)
    return speed, front, factor, holds


def upstream_pressure_limit(liquid: DesignLiquid, held: float, law: OrificeLaw = AREA_RATIO) -> float:
    """The closing speed [m/s] at which the quasi-steady pressure upstream of the law's largest opening
    (``dashpot_design.upstream_pressure``; it varies over the stroke's time, not a wall's period:
    dynamic factor 1) reaches ``held`` [Pa]: what the wall (``wall_holds``) or the pin (the steel's S:
    von Mises of a pin in the liquid is its pressure, ``housing``) bounds the closing speed to;
    ``law``: the orifice law with the design's largest area ratio (n_max)."""
    return brentq(lambda V: upstream_pressure(law.largest_ratio, V, liquid.density, law) - held, 1.0, 3000.0)


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
                     steel: str = HOUSING_STEEL, rule: str = WALL_RULE, echo=None,
                     largest_ratio: float = VALID_AREA_RATIO, pin_iterations: int = PIN_ITERATIONS,
                     pin_rounds: int = PIN_ROUNDS, carried=None, article: Article | None = None) -> dict:
    """The dashpot for ``pulse`` on an article of ``article_mass`` [kg] (a ``seat_mass`` riding with it)
    filled with ``liquid``, iterated on the column (``evaluations`` runs at most, ``search_cells``
    cells) and confirmed on it at ``cells``, with the lumped model's run of the same design beside it.
    The striker is at least ``striker_ratio`` times the payload and carries the housing of the design
    found: the handles are searched at ``carried_ratio`` (the closed-form design's, a start), and the
    striker is then the fixed point of the found design with its housing (``fixed_point
    .striker_fixed_point``, both ways, to ``STRIKER_TOLERANCE``): at each trial ratio the found handles
    are designed again, and searched again from them where that design breaks a check the found one holds
    (``admissible``) or scores worse than it by more than ``SCORE_SETTLED`` (``fixed_point.redesigned``).
    ``carried(out)``: the ratio a confirmed design's striker must be (default ``carried_ratio_of``: its
    pressurised housing, pin and oil with the striker's structure).  Returns a dict: the design, its runs
    (``column``, ``search_column``, ``lumped``), their band checks and validity checks, the fixture's mass (``housing.fixture_mass`` on
    ``steel`` by ``rule``), the striker (``striker``) and its fixed point's record (``striker_fixed_point``:
    the trials, whether it converged and why its design was kept), the wall times, and ``verdict``: "inside" (band
    passed, every check of the column holds, a housing within the practical wall ratio holds it, the
    pin holds, and with an ``article`` its base within yield), "outside the laws' ranges", "no housing within
    Y_max", "the pin does not hold it", "fails the band" or "the article yields".  ``largest_ratio``: the widest the pin may open (n_max; beyond ``VALID_AREA_RATIO``
    the law is extrapolated, which the checks flag).  ``pin_iterations``: the column runs the pin's cut
    on the column may take after the search (``pin_cut.cut_pin``, at ``cells``; 0: the quasi-steady pin);
    the design's ``pin_cut`` holds its convergence.  ``pin_rounds``: the handle searches, each after the
    first on the last one's pin cut at ``cells`` (``search_rounds``; 1: the handles searched on the
    quasi-steady pin alone, the pin cut after); ``search_rounds`` in the result holds each round's record,
    ``objective`` the kept design's score.  ``article`` (``article_base.Article``): the article standing on the
    piston, whose peak base stress on the kept design's column run is ``article_base`` in the result
    (``article_base.base_stress``) and a check of the verdict: "the article yields" where it is the one
    that fails."""
    law, carried = OrificeLaw(largest_ratio=largest_ratio), carried or carried_ratio_of
    start = carried_ratio(pulse, article_mass, seat_mass, liquid, striker_ratio, search_cells, steel, rule, law)
    designer = _Designer(pulse, article_mass, seat_mass, liquid, law, evaluations, search_cells, cells, steel, rule,
                         pin_iterations, pin_rounds if pin_iterations else 1)
    found = designer.searched(start)

    def kept(state):
        return admissible(state.out, found.out)

    def searched_again(ratio, reused):
        again = designer.searched(ratio, reused.handles)
        if echo:
            echo(f"  striker ratio {ratio:.4g}: the reused handles score {reused.objective:.3f} against the found "
                 f"design's {found.objective:.3f}{'' if kept(reused) else ', outside a check'}: searched again, "
                 f"{again.objective:.3f}{'' if kept(again) else ', outside a check'}")
        return again

    def needed_at(ratio):
        state = found if ratio == start else redesigned(
            lambda: designer.reused(found, ratio), lambda reused: searched_again(ratio, reused), kept,
            lambda s: s.objective, found.objective, SCORE_SETTLED)
        need = carried(state.out)
        if echo:
            echo(f"  striker ratio {ratio:.4g}: its housing asks {need:.4g} ({state.how}, {state.out['verdict']})")
        return need, state
    fp = striker_fixed_point(needed_at, striker_ratio, start, admissible=kept)
    out = fp.state.out
    out.update(closed_form_bore=fp.state.bore, evaluations=designer.evaluations, search_wall=designer.search_wall,
               objective=fp.state.objective, search_rounds=fp.state.rounds, confirm_wall=designer.confirm_wall,
               striker_fixed_point=fp.record())
    if article is not None:
        _check_article(out, article)
    if echo:
        echo(f"  dashpot on the column ({liquid.name}): {out['evaluations']} runs, {designer.search_wall:.0f} s, "
             f"{out['verdict']}; striker {fp.ratio:.4g} payloads in {fp.redesigns} redesigns ({fp.kept})")
        if "pin_cut" in out["design"]:
            echo("  pin cut on the column, peak overshoot by iteration: "
                 + " ".join(f"{s['overshoot']:+.2f}" for s in out["design"]["pin_cut"]["steps"])
                 + f" ({out['design']['pin_cut']['stop']})")
    return out


def design_checks(out: dict) -> dict:
    """A confirmed design's checks a lighter striker (a faster closing, a higher pressure) can break:
    the column's vetoing checks (the laws' ranges), its housing within the practical wall ratio, its pin
    at the steel's S, its floor within the flat-head formula's thin-plate range; each True where it holds."""
    col, weight = out["models"].get("column"), out["fixture"]
    if col is None or weight is None:
        return {"the column ran": False}
    return {"the column ran": True, "the column's vetoing checks": col["holds"],
            "a housing within Y_max": weight["housing_holds"], "the pin at S": weight["pin_holds"],
            "the floor's thin-plate range": not weight["floor_thick"]}


def admissible(out: dict, reference: dict) -> bool:
    """A design the striker's fixed point may keep: every check that holds for the ``reference`` design
    (the search's, at the start) holds for it too (``design_checks``), so the striker's search never takes
    the design into a region where one of its models or the housing's rules does not hold."""
    held = design_checks(out)
    return all(held.get(name, False) for name, ok in design_checks(reference).items() if ok)


def carried_ratio_of(out: dict) -> float:
    """The striker over the payload that carries a confirmed design's own housing, pin and oil
    (``carried_by``)."""
    return carried_by(out["fixture"]) / out["design"]["payload_mass"]


def carried_by(weight: dict) -> float:
    """The least striker [kg] that carries a weighed fixture's (``weigh``) housing, pin and oil with its
    own structure (``dashpot_design.striker_carrying``)."""
    return striker_carrying(weight["housing_carried"] + weight["pin"], weight["liquid"])


@dataclass(frozen=True)
class Designed:
    """A confirmed design (``confirm``'s dict) with what made it: its handles and pin correction (to
    design again at another striker), the closed-form bore, its score, its search rounds and how."""
    out: dict
    handles: tuple
    correction: object
    bore: float
    objective: float
    rounds: list
    how: str


class _Designer:
    """The column designer's two ways to a design at a striker ratio: the handles searched
    (``searched``, ``search_rounds``) or the handles found at another ratio reused (``reused``), each
    confirmed; it keeps the runs and wall time they took."""

    def __init__(self, pulse, article_mass, seat_mass, liquid, law, evaluations, search_cells, cells, steel, rule,
                 pin_iterations, rounds):
        self.pulse, self.article_mass, self.seat_mass = pulse, article_mass, seat_mass
        self.liquid, self.law = liquid, law
        self.max_evaluations, self.search_cells, self.cells, self.steel, self.rule = (evaluations, search_cells, cells,
                                                                                       steel, rule)
        self.pin_iterations, self.rounds = pin_iterations, rounds
        self.evaluations, self.search_wall, self.confirm_wall = 0, 0.0, 0.0

    def bore(self, ratio):
        return closed_form_bore(self.pulse, self.article_mass, self.seat_mass, self.liquid, ratio, self.law)

    def design(self, h, correction, ratio, bore):
        return carried_pin(_design(self.pulse, self.article_mass, self.seat_mass, self.liquid, bore, h, ratio,
                                   self.law), correction)

    def cut(self, d):
        return _cut(d, self.pulse, self.liquid, self.cells, self.pin_iterations, self.steel, self.rule)

    def confirm(self, d):
        t0 = time.perf_counter()
        out = confirm(d, self.pulse, self.liquid, self.search_cells, self.cells, self.steel, self.rule)
        self.confirm_wall += time.perf_counter() - t0
        return out

    def searched(self, ratio, start=START) -> Designed:
        """The handles searched at ``ratio`` from ``start`` (``search_rounds``), the kept design confirmed."""
        bore, end, column = self.bore(ratio), self.pulse.record_end(), self.liquid.column()

        def design(h, correction):
            return self.design(h, correction, ratio, bore)

        def search(correction, start):
            # a round on a carried cut pin searches on the grid that pin was cut on and its score is read on:
            # the search grid reads a pin cut at the design grid wrongly (fitted to that grid's waves)
            grid = self.search_cells if correction is None else self.cells

            def objective(h):
                if any(not lo <= x <= hi for x, (lo, hi) in zip(h, BOX)):
                    return 100.0
                d = design(h, correction)
                try:
                    run = simulate_column(dashpot_lumped(d), end, LUMPED_SAMPLES, grid, column)
                except (RuntimeError, ValueError):    # the piston reached the floor; a striker lighter than its oil
                    return 50.0
                return design_objective(d, run, self.pulse, self.liquid, self.steel, self.rule)
            res = minimize(objective, np.array(start), method="Nelder-Mead",
                           options={"xatol": 1e-3, "fatol": 1e-4, "maxfev": self.max_evaluations})
            res.cells = grid
            return res
        t0 = time.perf_counter()
        d, handles, correction, fun, rounds = search_rounds(search, design, self.cut, self.rounds, start)
        self.search_wall += time.perf_counter() - t0
        self.evaluations += sum(r["evaluations"] for r in rounds)
        return Designed(self.confirm(d), handles, correction, bore, fun, rounds, "searched")

    def reused(self, found: Designed, ratio) -> Designed:
        """The ``found`` design's handles and pin correction at ``ratio`` (the closed form's bore for it),
        its pin cut and confirmed; its score the search's objective on its column at the design grid, its
        rounds the search's that found the handles."""
        bore = self.bore(ratio)
        out = self.confirm(self.cut(self.design(found.handles, found.correction, ratio, bore)))
        run = out["runs"]["column"]
        score = (design_objective(out["design"], run, self.pulse, self.liquid, self.steel, self.rule)
                 if run is not None else math.inf)
        return Designed(out, found.handles, found.correction, bore, score, found.rounds, "handles reused")


def search_rounds(search, design, cut, rounds: int, start=START) -> tuple:
    """The handles searched with the pin they get: round 0 searches (``search(correction, start)``, a
    Nelder-Mead result) on the quasi-steady pin, and its design's pin is cut (``cut(design)``, at the
    design grid); each next round searches from the last one's handles on the quasi-steady pin times the
    correction that cut found (``pin_correction``), and cuts its own design's pin from there (the first
    round from ``start``: ``START``, or the handles found at another striker).  At most
    ``rounds``; they stop once no handle moved by more than ``HANDLES_SETTLED`` of itself, or the round's
    score by no more than ``SCORE_SETTLED`` of the last round's (the handles may still wander along a
    valley of the score, which is what the rounds keep).  Of the
    rounds' cut designs the one of the least score (the cut's, the search's objective at the design grid)
    is kept: round 0 is the handles searched on the quasi-steady pin and cut after, so the kept design
    is never worse than that.  Returns the kept cut design, its handles, the correction that reproduces
    its cut pin on them, its score, and each round's record (handles, search objective, its grid if the
    search names one, runs, the cut's score, why the cut stopped, ``moved``: its largest handle's move
    as a share of its start, ``score_change``: its cut score over the last round's less 1,
    ``search_converged``: its search's own convergence (Nelder-Mead's tolerances met before its run
    budget; None where the search does not say), and ``settled``: what settled after it, "handles" or
    "score", or None).  Rounds whose searches end on their budget are restarts of one unfinished descent:
    the last round's move and score change say how far from settled the kept design is."""
    correction, kept, history = None, None, []
    for k in range(rounds):
        res = search(correction, start)
        h = tuple(res.x)
        cut_d = cut(design(h, correction))
        steps, best = cut_d.get("pin_cut", {}).get("steps", []), cut_d.get("pin_cut", {}).get("best")
        score = steps[best]["score"] if best is not None else float(res.fun)
        moved = float(np.max(np.abs(res.x / np.array(start) - 1.0)))
        converged = getattr(res, "success", None)
        change = None if k == 0 else float(score / history[-1]["cut_score"] - 1.0)
        settled = (None if k == 0 else "handles" if moved <= HANDLES_SETTLED
                   else "score" if abs(change) <= SCORE_SETTLED else None)
        history.append({"handles": dict(zip(HANDLES, map(float, h))), "objective": float(res.fun),
                        "cells": getattr(res, "cells", None), "evaluations": int(res.nfev),
                        "moved": moved, "score_change": change,
                        "search_converged": None if converged is None else bool(converged),
                        "carried": correction is not None, "cut_score": score,
                        "cut_stop": cut_d.get("pin_cut", {}).get("stop"), "settled": settled})
        if "pin_cut" in cut_d:             # no cut (no pin iterations): the quasi-steady pin as it is
            correction = pin_correction(cut_d, design(h, None))
        if kept is None or score < kept[3]:
            kept = (cut_d, h, correction, score)
        if settled:
            break
        start = h
    return (*kept, history)


def carried_pin(d: dict, correction) -> dict:
    """The design ``d`` with its quasi-steady pin times ``correction`` (``pin_correction``, one factor a
    pin point: the points are at the same shares of every design's stroke), within the cut's bounds
    (``pin_cut.pin_bounds``); ``d`` itself with None.  The correction carries a cut pin's shape to nearby
    handles: an approximation the search's next round and the final cut at the chosen handles correct."""
    if correction is None:
        return d
    a_min, a_max = pin_bounds(d)
    pin = np.array(d["pin"], dtype=float)
    a = np.clip(np.clip(pin[:, 1], a_min, a_max) * correction, a_min, a_max)
    return {**d, "pin": [[float(x), float(v)] for x, v in zip(pin[:, 0], a)]}


def pin_correction(cut_d: dict, d: dict) -> np.ndarray:
    """The cut pin of ``cut_d`` over the quasi-steady pin of ``d`` (the same handles, within the cut's
    bounds), point by point."""
    a_min, a_max = pin_bounds(d)
    return np.array(cut_d["pin"])[:, 1] / np.clip(np.array(d["pin"])[:, 1], a_min, a_max)


def design_objective(d: dict, run, pulse: PulseSpec, liquid: DesignLiquid, steel: str = HOUSING_STEEL,
                     rule: str = WALL_RULE) -> float:
    """The search's objective of a design ``d`` on its column ``run``: the band's (narrowed by the design
    margin), every vetoing check of the column's that fails, the housing beyond the practical wall ratio
    and the metering pin's von Mises stress over the steel's S (``housing.fixture_mass``'s
    ``pin_stress_ratio``, which the verdict's "the pin does not hold it" reads), each by its log ratio
    times ``PENALTY``."""
    _, band = pulse.band(run.t, run.acceleration, DESIGN_MARGIN)
    weight = weigh(d, run, steel, rule)
    beyond = (housing_ratio(weight), weight["pin_stress_ratio"])
    return (_objective_of(pulse, band, dashpot_limits(dashpot_lumped(d), run, liquid))
            + PENALTY * sum(math.log(max(ratio, 1.0)) for ratio in beyond))


def _cut(d: dict, pulse: PulseSpec, liquid: DesignLiquid, cells: int, iterations: int, steel: str, rule: str) -> dict:
    """The design with its pin cut on the column (``pin_cut.cut_pin``) at ``cells``, the best iterate by
    the search's own objective (``design_objective``: the band, the checks, the housing and the pin, not the
    force's match alone: a pin that flattens the force by raising the floor's pressure beyond what a
    housing holds is no better design), among the iterates inside every vetoing check of the column's if
    any is (the designer does not cut a pin into a region where its model is invalid); ``d`` itself with
    no ``iterations``."""
    if not iterations:
        return d

    def score(trial, run):
        # an iterate outside a vetoing check of the column's is never kept over one inside them all
        inside = column_holds(dashpot_limits(dashpot_lumped(trial), run, liquid))
        return design_objective(trial, run, pulse, liquid, steel, rule) + (0.0 if inside else OUTSIDE_SCORE)
    return cut_pin(d, pulse, liquid, cells, iterations, score=score)[0]


def _check_article(out: dict, article: Article):
    """The article's peak base stress on the design's column run into ``out["article_base"]``, and the
    verdict "the article yields" where every other check holds and it does not ("outside the laws'
    ranges" where the estimate is outside its own)."""
    run = out["runs"]["column"]
    if run is None:
        out["article_base"] = None
        return
    out["article_base"] = base_stress(run.t, run.acceleration, out["design"]["article_mass"], article,
                                      out["design"]["bore_radius"])
    if out["verdict"] == "inside":
        # an estimate outside its own range checks nothing: the design is outside a law's range
        base = out["article_base"]
        out["verdict"] = ("outside the laws' ranges" if not base["in_range"] else
                          "the article yields" if not base["holds"] else "inside")


def confirm(d: dict, pulse: PulseSpec, liquid: DesignLiquid, search_cells: int = SEARCH_CELLS,
            cells: int = CELLS, steel: str = HOUSING_STEEL, rule: str = WALL_RULE) -> dict:
    """A design on the column at ``cells`` and ``search_cells`` and on the lumped model, each with its
    pulse, band check and validity checks, the fixture weighed on the column's pressures, the striker
    against what carries that housing (``striker_report``), and the jet's load per shot on its receiver
    (``jet_load``, on the column at ``cells``; reported, not a verdict's)."""
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
        if name != "lumped":             # the column's accounts and the dashpot's energy balance
            models[name]["accounts"] = run.summary
    column = runs["column"]
    weight = weigh(d, column, steel, rule) if column is not None else None
    col = models.get("column")
    verdict = ("not run" if col is None else "outside the laws' ranges" if not col["holds"]
               else "no housing within Y_max" if not weight["housing_holds"]
               else "the pin does not hold it" if not weight["pin_holds"]
               else "fails the band" if not col["band_passed"] else "inside")
    return {"design": d, "runs": runs, "models": models, "fixture": weight, "walls": walls, "verdict": verdict,
            "lumped_agrees": _lumped_agrees(models),
            "jet": jet_load(lumped_design, column, liquid.column()) if column is not None else None,
            "striker": striker_report(d, pulse, weight) if weight is not None else None}


def weigh(d: dict, run, steel: str = HOUSING_STEEL, rule: str = WALL_RULE) -> dict:
    """The fixture's mass (``housing.fixture_mass``) on a column ``run``'s pressures: the wall sized for
    the worse of its slices at the piston's face and at the floor (``housing.wall_factor``), the floor
    for its own."""
    return fixture_mass(d, run.t, np.vstack((run.pressure, run.floor_pressure)), run.floor_pressure, steel, rule)


def housing_ratio(weight: dict) -> float:
    """The wall's peak pressure times its dynamic factor over the most a wall holds at the practical wall
    ratio (``weight``: ``weigh``'s fixture): above 1 no housing within Y_max holds the design."""
    return weight["peak_pressure"] * weight["dynamic_factor"] / weight["holdable_pressure"]


# the closed-form striker's fixed point with its housing (``carried_ratio``, the search's start): at most
# this many column runs
STRIKER_ITERATIONS = 4


def carried_ratio(pulse: PulseSpec, article_mass: float, seat_mass: float, liquid: DesignLiquid,
                  least_ratio: float = STRIKER_RATIO, cells: int = SEARCH_CELLS, steel: str = HOUSING_STEEL,
                  rule: str = WALL_RULE, law: OrificeLaw = AREA_RATIO) -> float:
    """The striker over the payload that carries the housing its own design needs, never below
    ``least_ratio``: ``dashpot_design.striker_carrying`` (the pressurised housing, its liquid and the
    striker's structure; the closed form's estimate, without its pin) over the payload, the housing
    weighed on the column's run (``cells``) of the closed-form design at the bore A0 for that striker
    (beyond the practical wall ratio, the heaviest housing a monobloc gives: the design is then outside,
    and the striker its best case).  The closed form's fixed point (``fixed_point.striker_fixed_point``,
    ``STRIKER_ITERATIONS`` runs at most, to ``STRIKER_TOLERANCE``): the start of the search, whose found
    design then has its own (``design_on_column``).  A design whose piston reaches the floor, or whose
    housing no finite striker carries, keeps the striker it was made at."""
    end, column = pulse.record_end(), liquid.column()

    def needed_at(ratio):
        d = _design(pulse, article_mass, seat_mass, liquid,
                    closed_form_bore(pulse, article_mass, seat_mass, liquid, ratio, law), START, ratio, law)
        try:
            run = simulate_column(dashpot_lumped(d), end, LUMPED_SAMPLES, cells, column)
        except (RuntimeError, ValueError):        # the piston reached the floor: keep this striker
            return ratio, None
        w = weigh(d, run, steel, rule)
        needed = striker_carrying(w["housing_carried"], w["liquid"]) / d["payload_mass"]
        return (needed if math.isfinite(needed) else ratio), None
    # the striker the last design's housing asks (the search's start: one step of the iteration past the
    # trial that converged)
    return max(least_ratio, striker_fixed_point(needed_at, least_ratio, most=STRIKER_ITERATIONS - 1).needed)


def striker_report(d: dict, pulse: PulseSpec, weight: dict) -> dict:
    """The design's striker [kg] against the least that carries its housing and liquid [kg], its closing
    speed and the least closing speed the band takes (its velocity change at the band's floor, by the
    collision law at that striker: dV (1 + m / M)) [m/s]."""
    m, M = d["payload_mass"], d["striker_mass"]
    carrying = carried_by(weight)
    return {"mass": M, "carrying": carrying, "carries": bool(M >= carrying * (1.0 - STRIKER_TOLERANCE)),
            "ratio": M / m, "closing_speed": d["striker_speed"],
            "least_closing_speed": striker_speed(m, M, pulse.least_velocity_change())}


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

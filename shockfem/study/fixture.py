"""The fixture study (the white paper's task 2): ``shockfem study fixture``.

From a striking mass to the pulse on the unit under test.  Sections, each a table and where useful
a figure in ``report.md`` (numbers also in ``results.json``):

1. What the specification means: for articles of 10, 12, 50 and 100 lb, the velocity change,
   stroke, force and energy of each pulse shape at 10,000 g for 5 ms (``programmer.requirement``);
   which shape gives the white paper's "delta-V ~ 500 m/s".
2. What it asks of the machine: the striking mass and speed that give the payload (article and
   fixture) that velocity change through a programmer that stops them together (the amplifier's
   rigid collision law), and the energy the programmer must take up; the launched chain that
   delivers that striking mass from the white paper's 300 ft/s first stage (``amplifier.gain``).
3. The concepts as finite-element runs, striking mass -> programmer -> fixture -> article (the
   catalogue's ogive penetrator at 12 lb), each sized by ``programmer.concepts`` (the starting point
   ``shockfem programmer`` gives): the article's pulse against the specification's band, the
   fixture's mass, the stroke used, the energy taken up and the apparent restitution, the peak
   stresses against yield, and what each run cost.

Sizes: ``smoke`` (under a minute, for tests: coarse meshes), ``default``.
"""
from __future__ import annotations

import json
import math
import os
import time
from dataclasses import dataclass
from typing import Callable

import numpy as np
from scipy.optimize import brentq, minimize

from ..amplifier.gain import collide, design
from ..amplifier.interfaces import reduced_mass
from ..errors import ModelError, UnstableRun
from ..output.figures import pyplot
from ..output.history import read_history
from ..output.render import render_state
from ..parts.catalog import PARTS
from ..metrics import shapes
from ..metrics.filters import cfc_filter
from ..metrics.pulse import pulse_metrics
from ..metrics.shapes import TOLERANCE
from ..programmer.concepts import crushable_pad, least_throttling_pressure, metering_pin_area
from ..programmer.lumped_dashpot import LumpedDashpot, simulate
from ..programmer.requirement import SHAPES, requirement
from ..runner import run_scene
from ..scene import resolve
from ..scene.library import LIBRARY
from ..units import FT, G0, LB, to_si
from .report import Report

PEAK, DURATION = 10_000 * G0, 5e-3          # the specification: 10,000 g for 5 ms
ARTICLES_LB = (10.0, 12.0, 50.0, 100.0)
ARTICLE_LB = 12.0                            # the article of the finite-element runs
WHITE_PAPER_DV = 1650 * FT                   # "a delta V of 1650 fps (~500 m/s)"
# the article: the catalogue's solid ogive penetrator of 60 mm calibre, its length set by its mass
ARTICLE = {"library": "steel_4340", "radius": 0.030, "crh": 3.0, "meplat_radius": 0.003}
# striking mass over payload for the runs: heavy enough that the payload's velocity change costs the
# striker only a tenth of its speed
STRIKER_RATIO = 10.0
STRIKER_RATIOS = (2.0, 5.0, 10.0, 20.0)
CHAIN_LAUNCH = 300 * FT                      # the white paper's first-stage speed
CHAIN_RESTITUTION = 0.9
CHAIN_MASSES = 5
# crushable concept: the foam, and the spreader plate that carries its crush stress onto the article's
# base.  The plate must itself reach 10,000 g on the foam's stress: its areal mass w leaves
# sigma_p - w A for the article, so a steel plate thicker than sigma_p / (rho A) (4.4 mm on this
# foam) cannot be driven at all.  The runs take a stiff sandwich spreader of 10 kg/m^2 as rigid.
FOAM = "polyurethane_foam"
CARRIER_STEEL = "high_strength_steel"           # the fixtures' metal parts
SPREADER = {"areal_mass": 10.0, "thickness": 0.02}
# dashpot concept: the housing and its liquid ride on the striker (a fixture carrying the stroke would
# need a member longer than the stroke to reach 10,000 g itself: rho L A_g is 1.15 GPa for 1.5 m of
# steel); the article and a light piston enter its bore, which the article's calibre sets.
OIL = {"density": 870.0, "bulk_modulus": 1.5e9, "discharge": 0.7}
DASHPOT = {"clearance": 0.002, "piston_thickness": 0.015, "pin_points": 200, "column_over_stroke": 1.3}
SIZES = {
    # meshes: the article's element sizes of section 5 (the chosen design's speed against error)
    "smoke": {"h_article": 0.006, "h_carrier": 0.012, "h_pad": 0.03, "end_margin": 1.3, "meshes": (0.006, 0.005)},
    "default": {"h_article": 0.003, "h_carrier": 0.006, "h_pad": 0.012, "end_margin": 1.3,
                "meshes": (0.006, 0.003, 0.0015)},
}


# ------------------------------------------------------------------------------------------------ 1
@dataclass
class Context:
    """What the sections share: the size's settings, where runs go, the progress echo, and the pulse
    shape section 1 finds the specification needs."""
    cfg: dict
    out_dir: str
    echo: Callable
    shape: str = "rectangle"
    dashpot_run: object = None          # section 3's dashpot design and its run, for section 4
    chosen: object = None               # section 4's design and its finite-element run, for section 5


def specification(rep: Report, ctx: Context):
    """The specification's velocity change, stroke, force and energy per article and shape; sets
    ``ctx.shape`` to the shape that gives the white paper's velocity change."""
    rep.heading("1. What 10,000 g for 5 ms means")
    rows = []
    for lb in ARTICLES_LB:
        for shape in SHAPES:
            r = requirement(shape, PEAK, DURATION, lb * LB)
            rows.append([f"{lb:g}", shape, r.velocity_change, r.stroke, r.force / 1e6, r.energy / 1e6])
    rep.table("specification", ["article [lb]", "shape", "velocity change [m/s]", "stroke [m]", "peak force [MN]",
                                "energy [MJ]"], rows, ["{}", "{}", "{:.1f}", "{:.3f}", "{:.4g}", "{:.4g}"])
    dv = {shape: requirement(shape, PEAK, DURATION, 1.0).velocity_change for shape in SHAPES}
    meets = min(dv, key=lambda s: abs(dv[s] - WHITE_PAPER_DV))
    rep.value("white_paper_velocity_change_m_s", WHITE_PAPER_DV)
    rep.value("shape_meeting_white_paper", meets)
    rep.text(f"The stroke is the relative travel that brings the relative velocity to zero, the pulse's first "
             f"moment (no rebound). The white paper's \"delta V of 1650 fps (~500 m/s)\" ({WHITE_PAPER_DV:.1f} m/s) "
             f"is given only by the {meets} ({dv[meets]:.1f} m/s); a half-sine of the same peak and duration gives "
             f"{dv['half-sine']:.1f} m/s and a sawtooth {dv['terminal-peak sawtooth']:.1f} m/s. The rest of the "
             f"study designs for the {meets}: {requirement(meets, PEAK, DURATION, 1.0).stroke:.3f} m of stroke "
             "whatever the article weighs.")
    ctx.shape = meets


# ------------------------------------------------------------------------------------------------ 2
def striker_speed(payload: float, striker: float, dv: float, e: float = 0.0) -> float:
    """The striking speed that gives a payload at rest the velocity change ``dv`` (the rigid collision
    law of the amplifier, restitution ``e``: 0 for a programmer that stops the two together)."""
    return brentq(lambda v: collide(striker, v, payload, 0.0, e)[1] - dv, 0.0, 100.0 * dv)


def machine(rep: Report, ctx: Context):
    """The striking mass and speed the specification asks of the machine, and the chain that delivers it."""
    rep.heading("2. What it asks of the machine")
    dv = requirement(ctx.shape, PEAK, DURATION, 1.0).velocity_change
    rows = []
    for lb in ARTICLES_LB:
        for ratio in STRIKER_RATIOS:
            payload = lb * LB
            M = ratio * payload
            V = striker_speed(payload, M, dv)
            v_after = collide(M, V, payload, 0.0, 0.0)[0]
            absorbed = 0.5 * M * V * V - 0.5 * (M + payload) * v_after ** 2
            rows.append([f"{lb:g}", ratio, M / LB, V, V / FT, absorbed / 1e6])
    rep.table("striking_mass", ["payload [lb]", "striker / payload [-]", "striker [lb]", "striker speed [m/s]",
                                "striker speed [ft/s]", "programmer energy [MJ]"], rows,
              ["{}", "{:g}", "{:.4g}", "{:.1f}", "{:.0f}", "{:.4g}"])
    rep.text(f"The payload is the article and whatever moves with it (the fixture): its velocity change of "
             f"{dv:.1f} m/s comes from a striking mass M at V through a programmer that leaves the two together "
             "(restitution 0): V = dV (1 + m / M). The programmer takes up the relative kinetic energy, "
             "m M / (m + M) V^2 / 2, more than the payload's own energy at dV by the factor (1 + m / M) - and "
             "a striker of the payload's own mass doubles it.")
    # the launched chain that brings that striking mass to its speed (its last mass is the striker)
    payload = ARTICLE_LB * LB
    M = STRIKER_RATIO * payload
    V = striker_speed(payload, M, dv)
    try:
        d = design("launched-chain", M, V, CHAIN_LAUNCH, CHAIN_RESTITUTION, CHAIN_MASSES)
        rep.value("chain_masses_lb", [m / LB for m in d.masses])
        rep.text(f"For the {ARTICLE_LB:g} lb article with a striker of {STRIKER_RATIO:g} times it ({M / LB:.0f} lb "
                 f"at {V:.1f} m/s, {V / FT:.0f} ft/s), a launched chain of {CHAIN_MASSES} masses at e = "
                 f"{CHAIN_RESTITUTION:g} from {CHAIN_LAUNCH / FT:.0f} ft/s needs masses of "
                 + ", ".join(f"{m / LB:.0f}" for m in d.masses) + " lb (the last is the striker; "
                 "`docs/amplifier.md`).")
    except ValueError as exc:
        rep.text(f"No {CHAIN_MASSES}-mass chain at e = {CHAIN_RESTITUTION:g} from {CHAIN_LAUNCH / FT:.0f} ft/s "
                 f"reaches {V:.1f} m/s with a {M / LB:.0f} lb striker: {exc}")


# ------------------------------------------------------------------------------------------------ 3
def article_length(radius: float, crh: float, mass: float, density: float) -> float:
    """The length of the catalogue's solid ogive penetrator of ``radius`` that weighs ``mass``."""
    part = PARTS["projectile"]

    def volume(length):
        return part.volume({"radius": radius, "length": length, "crh": crh, "meplat_radius": ARTICLE["meplat_radius"],
                            "cavity_radius": 0.0, "cavity_length": 0.0, "base_thickness": 0.0}, 3)
    nose = radius * math.sqrt(4 * crh - 1)                   # a tangent ogive's length
    return brentq(lambda L: volume(L) * density - mass, 1.01 * nose, 100 * radius)


def _spec_shape(shape: str) -> str:
    """The shape the shock metrics check against: a rectangle as MIL-STD-810's trapezoid (10% ramps)."""
    return "trapezoid" if shape == "rectangle" else shape


def _shock(name: str, shape: str) -> dict:
    return {"test_articles": [name], "axis": "z", "cfc": 1000,
            "spec": {"shape": _spec_shape(shape), "peak": f"{PEAK / G0:.0f} gee", "duration": f"{DURATION * 1e3:g} ms"}}


def crushable_design(shape: str) -> dict:
    """The foam pad for the specification's force on the article and the spreader together (the
    spreader's area is the pad's: A = m A_g / (sigma_p - w A_g)), its thickness for the relative
    stroke against a striker of ``STRIKER_RATIO`` times the payload, by the closed forms of
    ``programmer.concepts.crushable_pad`` and ``fixtures.md``."""
    foam = LIBRARY[FOAM]
    plateau = to_si(foam["crush_curve"][0][1], "pressure")
    densification = float(foam["crush_curve"][1][0])
    rho_foam = to_si(foam["density"], "density")
    m_article = ARTICLE_LB * LB
    w = SPREADER["areal_mass"]
    area = m_article * PEAK / (plateau - w * PEAK)
    m_spreader = w * area
    req = requirement(shape, PEAK, DURATION, m_article + m_spreader)
    alone = crushable_pad(requirement(shape, PEAK, DURATION, m_article), plateau, densification, rho_foam)
    payload = m_article + m_spreader
    M = STRIKER_RATIO * payload
    V = striker_speed(payload, M, req.velocity_change)
    reduced = reduced_mass(payload, M)
    stroke = reduced * V * V / (2 * plateau * area)          # the relative stroke of striker and payload
    thickness = stroke / densification
    return {"plateau": plateau, "densification": densification, "area": area, "radius": math.sqrt(area / math.pi),
            "pad_thickness": thickness, "pad_mass": rho_foam * area * thickness, "spreader_mass": m_spreader,
            "article_mass": m_article, "striker_mass": M, "striker_speed": V, "stroke_design": stroke,
            "steel_plate_limit": plateau / (to_si(LIBRARY[CARRIER_STEEL]["density"], "density") * PEAK),
            "article_alone_area": dict((label, value) for label, value, _ in alone.sizes)["area"]}


def crushable_scene(d: dict, pad_on: str, shape: str, cfg: dict) -> dict:
    """Striker -> foam pad -> spreader -> article (nose down, its base under the spreader), all moving
    down (-z).  ``pad_on`` = "fixture": the pad rests on the spreader and the striker meets its far
    face; "striker": the pad rides on the striker's face and meets the spreader."""
    m_article = d["article_mass"]
    L_article = article_length(ARTICLE["radius"], ARTICLE["crh"], m_article,
                               to_si(LIBRARY[ARTICLE["library"]]["density"], "density"))
    R, t_s, L_striker = d["radius"], SPREADER["thickness"], 0.1
    gap = 0.002
    z_spreader = L_article
    z_pad = z_spreader + t_s + (gap if pad_on == "striker" else 0.0)
    z_striker = z_pad + d["pad_thickness"] + (gap if pad_on == "fixture" else 0.0)
    V = d["striker_speed"]
    end = cfg["end_margin"] * DURATION
    pad_contact = ({"name": "strike", "a": "striker.bottom", "b": "pad.top", "penalty_scale": 1.0}
                   if pad_on == "fixture" else
                   {"name": "strike", "a": "pad.bottom", "b": "spreader.top", "penalty_scale": 1.0})
    held = ({"name": "pad_on_spreader", "a": "pad.bottom", "b": "spreader.top", "penalty_scale": 1.0}
            if pad_on == "fixture" else
            {"name": "pad_on_striker", "a": "striker.bottom", "b": "pad.top", "penalty_scale": 1.0})
    return {"scene": {"name": f"fixture_crushable_on_{pad_on}", "kinematics": "axisymmetric", "end_time": end},
            "materials": {"article_steel": {"library": ARTICLE["library"]}, "foam": {"library": FOAM},
                          "spreader": {"density": d["spreader_mass"] / (math.pi * R * R * t_s),
                                       "youngs_modulus": 70e9, "poisson_ratio": 0.3},
                          "striker": {"density": d["striker_mass"] / (math.pi * R * R * L_striker),
                                      "youngs_modulus": 210e9, "poisson_ratio": 0.3}},
            "bodies": [
                {"name": "article", "material": "article_steel", "shape": "projectile", "radius": ARTICLE["radius"],
                 "length": L_article, "crh": ARTICLE["crh"], "meplat_radius": ARTICLE["meplat_radius"],
                 "element_size": cfg["h_article"],
                 "refine": [{"region": "nose", "size": cfg["h_article"] / 2, "distance": 4 * cfg["h_article"]}]},
                {"name": "spreader", "material": "spreader", "shape": "plate", "radius": R, "thickness": t_s,
                 "position": [0.0, z_spreader], "rigid": True, "element_size": cfg["h_pad"]},
                {"name": "pad", "material": "foam", "shape": "cylinder", "radius": R, "length": d["pad_thickness"],
                 "position": [0.0, z_pad], "element_size": cfg["h_pad"],
                 "velocity": -V if pad_on == "striker" else 0.0},
                {"name": "striker", "material": "striker", "shape": "cylinder", "radius": R, "length": L_striker,
                 "position": [0.0, z_striker], "velocity": -V, "rigid": True, "element_size": cfg["h_pad"]}],
            "contact": [pad_contact, held,
                        {"name": "seat", "a": "spreader.bottom", "b": "article.base", "penalty_scale": 1.0}],
            "shock": _shock("article", shape),
            "outputs": {"field_interval": end / 20, "history_interval": 1e-5}}


# the dashpot's design handles, as factors on the closed-form design: the pin's opening, the liquid
# column over the stroke, the force the pin is cut for over m A_g, the striker's speed
DASHPOT_HANDLES = ("pin_scale", "column_over_stroke", "force_factor", "speed_factor")
DASHPOT_START = (1.0, DASHPOT["column_over_stroke"], 1.0, 1.0)
DESIGN_MARGIN = 0.03             # the lumped design aims this share of the peak inside the band


def dashpot_design(shape: str, handles=DASHPOT_START) -> dict:
    """The fluid dashpot for the specification: a bore just wider than the article, a piston the article
    stands on, the metering pin that holds the force m A_g on article and piston over the relative stroke
    against a striker of ``STRIKER_RATIO`` times the payload (``programmer.concepts.metering_pin_area``
    with the reduced mass), its opening never wider than the bore.  ``handles`` (``DASHPOT_HANDLES``)
    scale that closed-form design; the start is the closed form itself."""
    pin_scale, column_over_stroke, force_factor, speed_factor = handles
    m_article = ARTICLE_LB * LB
    r_bore = ARTICLE["radius"] + DASHPOT["clearance"]
    area = math.pi * r_bore ** 2
    m_piston = to_si(LIBRARY[CARRIER_STEEL]["density"], "density") * area * DASHPOT["piston_thickness"]
    payload = m_article + m_piston
    req = requirement(shape, PEAK, DURATION, payload)
    M = STRIKER_RATIO * payload
    V = speed_factor * striker_speed(payload, M, req.velocity_change)
    reduced = reduced_mass(payload, M)
    force = force_factor * payload * PEAK
    stroke = reduced * V * V / (2 * force)
    rho, cd = OIL["density"], OIL["discharge"]
    strokes = np.linspace(0.0, stroke, DASHPOT["pin_points"])
    pin = [min(pin_scale * metering_pin_area(x, area, force, reduced, V, rho, cd), area) for x in strokes]
    p_least = least_throttling_pressure(V, rho, cd)
    return {"handles": dict(zip(DASHPOT_HANDLES, map(float, handles))),
            "bore_radius": r_bore, "piston_area": area, "piston_mass": m_piston, "article_mass": m_article,
            "striker_mass": M, "striker_speed": V, "force": force, "design_pressure": force / area,
            "least_pressure": p_least, "initial_overshoot": p_least * area / force - 1.0, "stroke_design": stroke,
            "column": column_over_stroke * stroke, "pin": [[float(x), float(a)] for x, a in zip(strokes, pin)],
            "liquid_mass": rho * area * column_over_stroke * stroke}


def dashpot_lumped(d: dict) -> LumpedDashpot:
    """The lumped model (``programmer.lumped_dashpot``) of a dashpot design."""
    return LumpedDashpot(d["striker_mass"], d["article_mass"] + d["piston_mass"], d["striker_speed"],
                         d["piston_area"], d["column"], tuple(map(tuple, d["pin"])), OIL["density"],
                         OIL["bulk_modulus"], OIL["discharge"])


def band_of(t: np.ndarray, a: np.ndarray, shape: str, margin: float = 0.0):
    """The pulse metrics of a payload acceleration record ``a`` starting at first contact, and its check
    against the specification's band (``metrics.shapes``; the rectangle as MIL-STD-810's trapezoid),
    the record padded with rest before contact so that the band's window is covered."""
    before = TOLERANCE["before"] * DURATION * 1.2
    n = max(int(before / (t[1] - t[0])), 2)
    t = np.concatenate([t[0] - before + np.arange(n) * before / n, t])
    a = np.concatenate([np.zeros(n), a])
    pulse = pulse_metrics(t, a)
    ideal = _placed_ideal(t, a, pulse, shape)
    return pulse, shapes.band_check(t, pulse.sign * a, ideal, margin)


def _placed_ideal(t, a, pulse, shape: str):
    """The specified pulse (the rectangle as MIL-STD-810's trapezoid) placed on a measured one."""
    return shapes.place(shapes.specified(_spec_shape(shape), PEAK, DURATION), t, pulse.sign * a, pulse)


def lumped_end_time() -> float:
    """The record a band check needs after first contact: the pulse and the window after it."""
    return DURATION * (1.0 + TOLERANCE["after"]) * 1.2


def design_dashpot(shape: str, echo) -> tuple[dict, object, int]:
    """The dashpot's handles iterated on the lumped model (Nelder-Mead from the closed form) to a pulse
    inside the band narrowed by ``DESIGN_MARGIN`` (so that the finite-element run, a little off the
    lumped one, still lands inside): the objective is the narrowed band's worst excess and the velocity
    change beyond its tolerance, with the velocity-change error and the largest deviation from the ideal
    as a small tie-breaker toward the band's middle.  Returns (design, lumped run, evaluations)."""
    end = lumped_end_time()

    def objective(h):
        if h[0] <= 0.05 or h[1] <= 1.02 or h[2] <= 0.3 or h[3] <= 0.5:
            return 10.0
        run = simulate(dashpot_lumped(dashpot_design(shape, h)), end, 3000)
        _, band = band_of(run.t, run.acceleration, shape, DESIGN_MARGIN)
        allowed = TOLERANCE["velocity_change"] - DESIGN_MARGIN
        return (10.0 * (band.worst_excess + max(0.0, abs(band.velocity_change_error) - allowed))
                + abs(band.velocity_change_error) + 0.1 * band.worst_deviation)
    res = minimize(objective, DASHPOT_START, method="Nelder-Mead",
                   options={"xatol": 1e-3, "fatol": 1e-5, "maxfev": 400})
    echo(f"  dashpot design: {res.nfev} lumped runs")
    d = dashpot_design(shape, tuple(res.x))
    return d, simulate(dashpot_lumped(d), end, 3000), int(res.nfev)


def dashpot_scene(d: dict, shape: str, cfg: dict, end: float | None = None) -> dict:
    """Striker-borne housing (rigid, its bore full of oil) moving up (+z) onto a piston that carries the
    article, turned end over end to stand on its base; the liquid between the bore's floor and the piston
    throttles through the metering pin."""
    L_article = article_length(ARTICLE["radius"], ARTICLE["crh"], d["article_mass"],
                               to_si(LIBRARY[ARTICLE["library"]]["density"], "density"))
    floor, t_p, column = 0.05, DASHPOT["piston_thickness"], d["column"]
    z_piston = floor + column
    z_article = z_piston + t_p + L_article               # its position: the nose end, turned end over end
    depth = column + t_p + L_article + 0.02
    R_h = 2.0 * d["bore_radius"]
    housing_volume = math.pi * (R_h ** 2 * (floor + depth) - d["bore_radius"] ** 2 * depth)
    end = end or cfg["end_margin"] * DURATION
    h = cfg["h_article"]
    return {"scene": {"name": "fixture_dashpot", "kinematics": "axisymmetric", "end_time": end},
            "materials": {"article_steel": {"library": ARTICLE["library"]}, "steel": {"library": CARRIER_STEEL},
                          "striker": {"density": d["striker_mass"] / housing_volume, "youngs_modulus": 210e9,
                                      "poisson_ratio": 0.3}},
            "bodies": [
                {"name": "housing", "material": "striker", "shape": "carrier", "radius": R_h, "length": floor + depth,
                 "seat_radius": d["bore_radius"], "seat_depth": depth, "velocity": d["striker_speed"], "rigid": True,
                 "element_size": cfg["h_pad"]},
                {"name": "piston", "material": "steel", "shape": "cylinder", "radius": d["bore_radius"], "length": t_p,
                 "position": [0.0, z_piston], "element_size": h},
                {"name": "article", "material": "article_steel", "shape": "projectile", "radius": ARTICLE["radius"],
                 "length": L_article, "crh": ARTICLE["crh"], "meplat_radius": ARTICLE["meplat_radius"],
                 "position": [0.0, z_article], "orientation": {"direction": [0, -1]}, "element_size": h,
                 "refine": [{"region": "nose", "size": h / 2, "distance": 4 * h}]}],
            "cavity": [{"name": "oil", "walls": ["housing.seat_floor", "piston.bottom"],
                        "volume": d["piston_area"] * column,
                        "liquid": {"density": OIL["density"], "bulk_modulus": OIL["bulk_modulus"]},
                        "orifice": {"area_curve": d["pin"], "piston_area": d["piston_area"],
                                    "discharge": OIL["discharge"]}}],
            "contact": [{"name": "seat", "a": "piston.top", "b": "article.base", "penalty_scale": 1.0}],
            "shock": _shock("article", shape),
            "outputs": {"field_interval": end / 20, "history_interval": 1e-5}}


@dataclass(frozen=True)
class ConceptRun:
    """A concept's finished run, read back from its run directory."""
    path: str
    summary: dict                 # summary.json
    history: dict                 # history.csv columns by name (SI)


def _run_concept(name: str, raw: dict, out_dir: str, echo) -> tuple[ConceptRun | None, float, str]:
    """Run a concept's scene into ``out_dir/name`` (the run directory of ``shockfem run``: XDMF fields,
    histories, summary); returns (the run or None, wall time, status)."""
    t0 = time.perf_counter()
    path = os.path.join(out_dir, name)
    try:
        finished = run_scene(resolve(raw), path, progress=False, quiet=True)
    except UnstableRun as exc:
        echo(f"  {name}: unstable: {exc}")
        return None, time.perf_counter() - t0, "unstable"
    except ModelError as exc:                 # a mesh gmsh cannot make: the study goes on without the run
        echo(f"  {name}: not run: {exc}")
        return None, time.perf_counter() - t0, "not meshed"
    # the final shape and its stress field, as a picture beside the run's XDMF
    model = finished.solver.model
    deformable = [i for i in range(len(model.body_mass)) if i not in {rb.index for rb in model.rigid}]
    render_state(finished.solver, os.path.join(path, "final_shape.png"), "von_mises",
                 f"{name}: von Mises stress at t = {finished.solver.t * 1e3:.3g} ms (deformed; rigid bodies "
                 "not shown)", bodies=deformable)
    with open(os.path.join(path, "summary.json")) as fh:
        summary = json.load(fh)
    result = ConceptRun(path, summary, read_history(os.path.join(path, "history.csv"))[0])
    return result, time.perf_counter() - t0, summary["status"]


def concepts(rep: Report, ctx: Context):
    """Each concept sized by its closed form and run: the crushable pad, on the fixture and on the striker."""
    rep.heading("3. The concepts as finite-element runs")
    shape, cfg, out_dir, echo = ctx.shape, ctx.cfg, ctx.out_dir, ctx.echo
    d = crushable_design(shape)
    rep.value("crushable_design", d)
    rep.text(f"**Crushable pad** ({FOAM}, plateau {d['plateau'] / 1e6:.3g} MPa). The pad must push the article "
             f"through a spreader, and the spreader must itself reach 10,000 g on the foam's stress: a plate of "
             f"areal mass w leaves sigma_p - w A_g for the article, so a steel plate thicker than "
             f"{d['steel_plate_limit'] * 1e3:.1f} mm cannot be driven at all, and a steel plate this thin cannot "
             f"carry the article's reaction. The runs take a stiff sandwich spreader of {SPREADER['areal_mass']:g} "
             f"kg/m^2 as rigid (its bending left out): area m A_g / (sigma_p - w A_g) = {d['area']:.4f} m^2 (radius "
             f"{d['radius'] * 1e3:.0f} mm; the article alone would need {d['article_alone_area']:.4f} m^2, `shockfem programmer`'s sizing), spreader "
             f"{d['spreader_mass']:.2f} kg. With a striker of {STRIKER_RATIO:g} times the payload "
             f"({d['striker_mass']:.0f} kg at {d['striker_speed']:.1f} m/s) the relative stroke is "
             f"{d['stroke_design']:.3f} m: a pad {d['pad_thickness']:.3f} m thick at densification "
             f"{d['densification']:g}, weighing {d['pad_mass']:.1f} kg. The closed form leaves out the pad's own "
             "inertia and the crush front's momentum (rho v^2 / eps_d at the face the foam meets at speed); "
             "the runs have both, with the pad on the fixture (the striker meets its far face) and on the "
             "striker (it meets the spreader).")
    rows = []
    for pad_on in ("fixture", "striker"):
        echo(f"  crushable pad on the {pad_on}")
        raw = crushable_scene(d, pad_on, shape, cfg)
        result, wall, status = _run_concept(f"crushable_on_{pad_on}", raw, out_dir, echo)
        fixture = ["spreader", "pad"] if pad_on == "fixture" else ["spreader"]
        rows.append(_concept_row(f"crushable, pad on the {pad_on}", result, wall, status, d, fixture))
        if result is not None:
            _pulse_figure(rep, result, f"crushable, pad on the {pad_on}")
    _concept_table(rep, "crushable", rows)

    d = dashpot_design(shape)
    rep.value("dashpot_design", {k: v for k, v in d.items() if k != "pin"})
    rep.text(f"**Fluid dashpot.** The stroke must ride on the striker: a fixture member as long as the stroke "
             f"would itself need rho L A_g of stress to reach 10,000 g (1.15 GPa for 1.5 m of steel). So the striker "
             f"carries a housing whose bore, {d['bore_radius'] * 1e3:.0f} mm in radius (the article's calibre and a "
             f"{DASHPOT['clearance'] * 1e3:g} mm clearance), holds {d['liquid_mass']:.1f} kg of oil (K "
             f"{OIL['bulk_modulus'] / 1e9:g} GPa, Cd {OIL['discharge']:g}); the article, turned end over end, stands "
             f"on a {DASHPOT['piston_thickness'] * 1e3:g} mm piston ({d['piston_mass']:.2f} kg) at the liquid's top "
             f"and enters the bore as the housing closes. Holding m A_g = {d['force'] / 1e6:.4g} MN on the "
             f"{d['piston_area'] * 1e4:.2f} cm^2 piston takes {d['design_pressure'] / 1e6:.0f} MPa; but at the "
             f"striker's {d['striker_speed']:.1f} m/s no orifice throttles below rho V^2 / (2 Cd^2) = "
             f"{d['least_pressure'] / 1e6:.0f} MPa: by the incompressible law the pulse would start "
             f"{d['initial_overshoot']:.0%} over the peak. The metering pin (`shockfem programmer`'s closed form with the reduced mass of striker and "
             f"payload, {DASHPOT['pin_points']} points over the {d['stroke_design']:.3f} m relative stroke) opens no "
             f"wider than the bore; the liquid column is {d['column']:.3f} m ({DASHPOT['column_over_stroke']:g} "
             "times the stroke: the oil compresses by p / K before it flows).")
    echo("  fluid dashpot")
    result, wall, status = _run_concept("dashpot", dashpot_scene(d, shape, cfg), out_dir, echo)
    ctx.dashpot_run = (d, result, wall)
    rows = [_concept_row("fluid dashpot, metering pin", result, wall, status, d, ["piston"], striker="housing")]
    if result is not None:
        _pulse_figure(rep, result, "fluid dashpot")
        oil = result.summary["cavities"]["oil"]
        pulse = result.summary["shock"]["channels"]["article"]["pulse"]
        rep.value("dashpot_peak_pressure_Pa", oil["max_pressure"])
        rep.text(f"The run: the oil does not jump to {d['least_pressure'] / 1e6:.0f} MPa; compressible, it is a spring "
                 f"K A^2 / V that the striker first winds up, and the pressure rises over "
                 f"{pulse['rise_time'] * 1e3:.2f} ms to {oil['max_pressure'] / 1e6:.0f} MPa, so the pulse is rounded "
                 f"({result.summary['shock']['channels']['article']['shape']['classified']}) rather than initial-peak. "
                 f"The orifice throttled {oil['energy_throttled'] / 1e6:.3f} MJ of the {oil['energy_taken'] / 1e6:.3f} "
                 f"MJ the liquid took; {oil['mass_out']:.2f} kg of oil left through it.")
    _concept_table(rep, "dashpot", rows)


CONCEPT_HEADER = ["concept", "status", "fixture mass [kg]", "peak [g]", "duration [ms]", "velocity change [m/s]",
                  "shape", "band", "worst excess [-]", "apparent restitution [-]", "energy taken up [MJ]",
                  "article von Mises / yield [-]", "energy balance [-]", "elements", "wall [s]"]
CONCEPT_FORMATS = ["{}", "{}", "{:.2f}", "{:.0f}", "{:.3f}", "{:.1f}", "{}", "{}", "{:.3f}", "{:.3f}", "{:.4g}",
                   "{:.3f}", "{:.1e}", "{}", "{:.1f}"]


def _concept_row(concept: str, result, wall: float, status: str, d: dict, fixture_bodies: list[str],
                 striker: str = "striker") -> list:
    """One concept run's line: the article's pulse against the band, the fixture's mass, the energy
    the programmer took up, the striker's apparent restitution on the payload, the article's peak
    stress over its yield, the energy balance and the cost."""
    if result is None:
        return [concept, status] + [float("nan")] * (len(CONCEPT_HEADER) - 4) + [0, wall]
    s = result.summary
    channel = s["shock"]["channels"]["article"]
    pulse, tol = channel["pulse"], channel["tolerance"]
    bodies = s["bodies"]
    # speeds along the push, whichever way the scene points it
    sense = math.copysign(1.0, bodies[striker]["velocity_final"][-1] or 1.0)
    V = d["striker_speed"]
    v_striker = sense * bodies[striker]["velocity_final"][-1]
    v_article = sense * bodies["article"]["velocity_final"][-1]
    e = s["energy"]
    yield_article = to_si(LIBRARY[ARTICLE["library"]]["hardening_curve"][0][1], "pressure")
    return [concept, s["status"], sum(bodies[b]["mass"] for b in fixture_bodies), pulse["peak_g"],
            pulse["duration"] * 1e3, pulse["sign"] * pulse["velocity_change"], channel["shape"]["classified"],
            "pass" if tol["passed"] else "fail", tol["worst_excess"], (v_article - v_striker) / V,
            (e["initial_total"] - e["kinetic"]) / 1e6, bodies["article"]["max_von_mises"] / yield_article,
            e["balance_error"], s["elements"], wall]


def _concept_table(rep: Report, name: str, rows: list[list]):
    rep.table(f"concepts_{name}", CONCEPT_HEADER, rows, CONCEPT_FORMATS)


def _pulse_figure(rep: Report, result, concept: str):
    plt = pyplot()
    h = result.history
    t = h["time"]
    fig, ax = plt.subplots(figsize=(7, 3.5))
    sign = result.summary["shock"]["channels"]["article"]["pulse"]["sign"]      # along the push
    ax.plot(t * 1e3, sign * h["article.a_z"] / G0, label="article (unfiltered)")
    ax.axhline(PEAK / G0, color="k", lw=0.8, ls="--", label="10,000 g")
    ax.set_xlabel("time [ms]")
    ax.set_ylabel("acceleration [g]")
    ax.legend()
    name = "pulse_" + "".join(c if c.isalnum() else "_" for c in concept).strip("_") + ".png"
    rep.figure(name, f"{concept}: the article's acceleration (rigid-body mean, along the push)", fig)


def fe_pulse(result) -> tuple[np.ndarray, np.ndarray]:
    """A run's article acceleration along the push, CFC 1000 filtered as the shock metrics filter it."""
    h = result.history
    t = h["time"]
    sign = result.summary["shock"]["channels"]["article"]["pulse"]["sign"]
    return t, cfc_filter(sign * h["article.a_z"], float(t[1] - t[0]), 1000)


def _pulse_row(model: str, t, a, shape: str, wall: float, extra=()) -> list:
    pulse, band = band_of(t, a, shape)
    return [model, pulse.peak / G0, pulse.duration * 1e3, pulse.velocity_change, "pass" if band.passed else "fail",
            band.worst_excess, band.velocity_change_error, *extra, wall]


PULSE_HEADER = ["model", "peak [g]", "duration [ms]", "velocity change [m/s]", "band", "worst excess [-]",
                "velocity change error [-]"]
PULSE_FORMATS = ["{}", "{:.0f}", "{:.3f}", "{:.1f}", "{}", "{:.3f}", "{:+.3f}"]


def designing(rep: Report, ctx: Context):
    """The dashpot iterated to the specification on its lumped model, whose agreement with the
    finite-element run is shown first, then the design confirmed by finite elements."""
    rep.heading("4. Designing to the specification: the dashpot")
    d0, fe0, wall0 = ctx.dashpot_run
    shape = ctx.shape
    t_start = time.perf_counter()
    run0 = simulate(dashpot_lumped(d0), ctx.cfg["end_margin"] * DURATION, 3000)
    lumped_wall = time.perf_counter() - t_start
    rows = [_pulse_row("lumped (programmer.lumped_dashpot)", run0.t, run0.acceleration, shape, lumped_wall,
                       [float(run0.pressure.max()) / 1e6])]
    if fe0 is not None:
        t, a = fe_pulse(fe0)
        rows.append(_pulse_row("finite elements (section 3)", t, a, shape, wall0,
                               [fe0.summary["cavities"]["oil"]["max_pressure"] / 1e6]))
    rep.table("dashpot_lumped_vs_fe", PULSE_HEADER + ["peak pressure [MPa]", "wall [s]"], rows,
              PULSE_FORMATS + ["{:.1f}", "{:.2f}"])
    rep.text("The closed-form design of section 3 in the lumped model (two rigid masses and the lumped "
             "liquid, the same liquid and orifice laws as the cavity, `fluid/liquid.py`) and in the finite-"
             "element run, both checked here against the band the same way (`band_of`: the finite-element "
             "record CFC 1000 filtered, each record padded with rest before contact to cover the band's window).")
    ctx.echo("  dashpot: iterating on the lumped model")
    t_start = time.perf_counter()
    d, run, evaluations = design_dashpot(shape, ctx.echo)
    design_wall = time.perf_counter() - t_start
    rep.value("dashpot_chosen_handles", d["handles"])
    rep.value("dashpot_chosen_design", {k: v for k, v in d.items() if k not in ("pin", "handles")})
    ctx.echo("  dashpot: the design in finite elements")
    end = lumped_end_time()
    fe, wall, status = _run_concept("dashpot_design", dashpot_scene(d, shape, ctx.cfg, end), ctx.out_dir, ctx.echo)
    ctx.chosen = (d, fe, wall)
    rows = [_pulse_row("lumped, iterated", run.t, run.acceleration, shape, design_wall,
                       [float(run.pressure.max()) / 1e6, "-", "-"])]
    if fe is not None:
        t, a = fe_pulse(fe)
        rows.append(_pulse_row("finite elements, the iterated design", t, a, shape, wall,
                               [fe.summary["cavities"]["oil"]["max_pressure"] / 1e6,
                                fe.summary["energy"]["balance_error"], status]))
    rep.table("dashpot_design", PULSE_HEADER + ["peak pressure [MPa]", "energy balance [-]", "status",
                                                "wall [s] (lumped: the whole iteration)"],
              rows, PULSE_FORMATS + ["{:.1f}", "{:.1e}", "{}", "{:.1f}"])
    h = d["handles"]
    payload = d["article_mass"] + d["piston_mass"]
    rep.text(f"Nelder-Mead on the four handles from the closed form (1, {DASHPOT['column_over_stroke']:g}, 1, 1) took "
             f"{evaluations} lumped runs, aiming {DESIGN_MARGIN:.0%} of the peak inside the band: pin opening x {h['pin_scale']:.3f}, liquid column {h['column_over_stroke']:.3f} "
             f"times the stroke ({d['column']:.3f} m), the pin cut for {h['force_factor']:.3f} m A_g "
             f"({d['force'] / 1e6:.4g} MN, {d['design_pressure'] / 1e6:.0f} MPa on the piston), the striker at "
             f"{h['speed_factor']:.3f} of the closed form's speed ({d['striker_speed']:.1f} m/s, "
             f"{d['striker_speed'] / FT:.0f} ft/s). The fixture is the {d['piston_mass']:.2f} kg piston: the payload "
             f"the launcher and amplifier must deliver is the article and the piston, {payload:.2f} kg "
             f"({payload / LB:.2f} lb), struck by {d['striker_mass']:.1f} kg carrying {d['liquid_mass']:.1f} kg of oil.")
    if fe is not None:
        _design_figure(rep, run, fe, shape)
        rep.figure("dashpot_design/final_shape.png", "the iterated dashpot at the end of its run: piston and "
                   "article, deformed, von Mises stress (the rigid housing is not shown); "
                   "`dashpot_design/fields.xdmf` and `final_shape.xdmf` open in ParaView")


def _design_figure(rep: Report, run, fe, shape: str):
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7, 3.5))
    t, a = fe_pulse(fe)
    ideal = _placed_ideal(t, a, pulse_metrics(t, a), shape)
    lower, upper, monitored = shapes.tolerance_band(ideal, t)
    ax.fill_between(t[monitored] * 1e3, lower[monitored] / G0, upper[monitored] / G0, color="0.85",
                    label="tolerance band (MIL-STD-810 trapezoid, as read)")
    ax.plot(t * 1e3, ideal(t) / G0, "k:", lw=0.8, label="specified pulse")
    ax.plot(t * 1e3, a / G0, label="finite elements (CFC 1000)")
    ax.plot(run.t * 1e3, run.acceleration / G0, "--", label="lumped")
    ax.set_xlabel("time [ms]")
    ax.set_ylabel("acceleration [g]")
    ax.legend()
    rep.figure("dashpot_design.png", "the iterated dashpot: the article's pulse, lumped and finite elements, in "
               "the specification's band", fig)


def speed_against_error(rep: Report, ctx: Context):
    """The chosen design at several axisymmetric meshes of the article and piston: the pulse, the
    article's peak stress and what each run cost; differences from the finest mesh."""
    rep.heading("5. Speed against error: the chosen design")
    d, fe_design, wall_design = ctx.chosen
    end = lumped_end_time()
    rows = []
    for h in ctx.cfg["meshes"]:
        if h == ctx.cfg["h_article"] and fe_design is not None:
            fe, wall, status = fe_design, wall_design, "completed"     # section 4's run is this mesh
        else:
            ctx.echo(f"  the chosen design, article mesh {h * 1e3:g} mm")
            fe, wall, status = _run_concept(f"dashpot_design_h{h * 1e3:g}mm", dashpot_scene(d, ctx.shape, {**ctx.cfg,
                                       "h_article": h}, end), ctx.out_dir, ctx.echo)
        if fe is None:
            rows.append([h * 1e3, status] + [float("nan")] * 7)
            continue
        t, a = fe_pulse(fe)
        pulse, band = band_of(t, a, ctx.shape)
        s = fe.summary
        rows.append([h * 1e3, s["status"], pulse.peak / G0, pulse.velocity_change,
                     s["bodies"]["article"]["max_von_mises"] / 1e6, s["elements"], s["steps"], wall,
                     s["element_cycles_per_s"]])
    done = [r for r in rows if r[1] == "completed"]
    finest = min(done, key=lambda r: r[0]) if done else None
    for r in rows:
        r += [r[2] / finest[2] - 1 if finest and r[1] == "completed" else float("nan"),
              r[4] / finest[4] - 1 if finest and r[1] == "completed" else float("nan")]
    rep.table("speed_against_error", ["article element [mm]", "status", "peak [g]", "velocity change [m/s]",
                                      "article peak von Mises [MPa]", "elements", "steps", "wall [s]",
                                      "element-cycles/s", "peak vs finest [-]", "stress vs finest [-]"], rows,
              ["{:g}", "{}", "{:.1f}", "{:.2f}", "{:.1f}", "{}", "{}", "{:.1f}", "{:.3g}", "{:+.2e}", "{:+.2e}"])
    base = d["article_mass"] * PEAK / (math.pi * ARTICLE["radius"] ** 2)
    by_size = sorted(done, key=lambda r: -r[0])                       # coarse to fine
    peaks = [r[2] for r in by_size]
    stresses = [r[4] for r in by_size]
    spread = (max(peaks) - min(peaks)) / min(peaks) if peaks else float("nan")
    rising = len(stresses) > 1 and all(b > a for a, b in zip(stresses, stresses[1:]))
    stress_reading = (f"rises with every refinement ({' -> '.join(f'{x:.0f}' for x in stresses)} MPa): read it as a "
                      "pointer to a corner where the elastic stress is singular, not as a converged number"
                      if rising else
                      f"is {' -> '.join(f'{x:.0f}' for x in stresses)} MPa from the coarsest mesh to the finest")
    rep.text("Axisymmetric meshes of the article and the piston (the housing is rigid); the 15 ms record covers the "
             f"band's window. The peak acceleration differs by {spread:.1e} of itself across the meshes (the pulse "
             "is the lumped liquid's). The article's peak von Mises stress, the largest cell value over the run, "
             f"{stress_reading}; the article's own 10,000 g load over its base, m A_g / (pi R^2), is "
             f"{base / 1e6:.0f} MPa. The 3D run of the design (and its tail-slap variants) is still to come.")


SECTIONS = (("what the specification means", specification), ("what it asks of the machine", machine),
            ("the concepts as finite-element runs", concepts), ("designing to the specification", designing),
            ("speed against error", speed_against_error))


def run_study(size: str = "default", out_dir: str = "results/fixture", echo=print) -> str:
    """Run the study's sections in order into ``out_dir``; returns the report's path."""
    started = time.perf_counter()
    rep = Report(out_dir, "Fixture study (white paper task 2)")
    rep.text(f"`shockfem study fixture --size {size}`; every number below was computed by this run. The closed "
             "forms: `../shared/references/fixtures.md`, `docs/programmers.md`; the study: `docs/fixture.md`.")
    ctx = Context(SIZES[size], out_dir, echo)
    for k, (title, section) in enumerate(SECTIONS, 1):
        echo(f"{k}/{len(SECTIONS)} {title}")
        section(rep, ctx)
    return rep.finish(started, echo)

"""What the penetration study's sections share: the projectile (the fixture study's 12 lb article, solid,
or cased with a payload), the targets, the run sizes, the scene of a shot and the closed form it is
compared with."""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Callable

import numpy as np
from scipy.optimize import brentq

from ...parts.catalog import PARTS, ogive
from ...penetration.forrestal import depth_of, speed_at_depth
from ...scene.library import LIBRARY, property_si
from ...scene.orientation import axis_angle
from ...target.concrete import nose_factor, strength_factor
from ...units import FT, LB, to_si
from ..fixture.common import ARTICLE, ARTICLE_LB, article_dims, article_length

SPEED = 1600 * FT                       # the white paper's impact speed, 487.7 m/s
KSI = to_si("1 ksi", "pressure")
TARGETS = {"5 ksi": 5 * KSI, "10 ksi": 10 * KSI}     # the white paper's concrete and a stronger one
DENSITY = 2300.0                         # the concrete's [kg/m^3]
FRICTION = 0.4                           # the white paper's mu of the resisting torque mu F a / 2
STATIONS = 5                             # points on the axis, base (0) to nose tip (4), for its bending
END_MARGIN = 1.2                         # runs go on this share of the closed form's stopping time
# the white paper's projectile is elastic: the run's 4340 keeps its E, nu and rho, and the stresses are
# read against its yield
MATERIAL = {k: LIBRARY[ARTICLE["library"]][k] for k in ("density", "youngs_modulus", "poisson_ratio")}

# the cased article: the same outer ogive with a cavity in its shank holding an aluminium payload, its
# length set so that case and payload weigh the solid article's 12 lb (the same shot for Forrestal)
CASE = {"wall": 0.012, "base_thickness": 0.015, "cavity_start": 0.010, "clearance": 0.001, "gap": 1e-4,
        "payload": "aluminium_6061_t6"}

SIZES = {
    # element sizes of the projectile (axisymmetric quads, 3D tetrahedra) and the elements round its
    # circumference in the design's 3D runs (gmsh's curvature sizing: at 24 the tetrahedra are about 8 mm
    # at the shank and 1.6 mm at the meplat whatever the element size; smoke takes 12, five times faster;
    # section 3's pulses keep 24: at 12 the sections read the slow pulse's bending 10% under its inertia
    # relief, two or three tetrahedra across a radius), the slabs its stress along the
    # body is read on (``outputs.sections``), the centre points of the design (one: a simulation repeats
    # itself), its fold-over half, the history's sampling, the share of each event run (smoke:
    # ``event_end`` keeps it past the crater), and the force pulses' durations over the article's first
    # axial and bending periods (section 3)
    "smoke": {"h_axi": 0.006, "h_3d": 0.02, "curve_elements": 12, "sections": 9, "centre_points": 1,
              "fold_over": False,
              "history": 1e-5, "end_fraction": 0.12, "duration_ratios": (0.5, 1.0, 4.0),
              "bending_ratios": (0.5, 4.0)},
    "default": {"h_axi": 0.003, "h_3d": 0.01, "curve_elements": 24, "sections": 21, "centre_points": 1,
                "fold_over": True,
                "history": 5e-6, "end_fraction": 1.0,
                "duration_ratios": (0.25, 0.5, 0.8, 1.0, 1.5, 2.0, 3.0, 4.0, 8.0),
                "bending_ratios": (0.25, 0.5, 1.0, 2.0, 4.0, 8.0)},
}


@dataclass
class Context:
    cfg: dict
    out_dir: str
    echo: Callable
    shots: dict = field(default_factory=dict)      # section 1's runs by target name


def projectile_mass() -> float:
    """The article's mass [kg] (12 lb: its length is set for it, ``article_length``)."""
    return ARTICLE_LB * LB


def closed_form(fc: float, speed: float) -> dict:
    """Forrestal's rigid projectile for the study's article: depth, the crater's exit speed, the time to
    stop and the largest deceleration (at the tunnel's entry, where S f'c + N rho V1^2 peaks)."""
    m, a = projectile_mass(), ARTICLE["radius"]
    strength, N = strength_factor(fc) * fc, nose_factor(ARTICLE["crh"])
    P = depth_of(m, a, strength, DENSITY, N, speed, 4 * a)
    z = np.linspace(0.0, P, 4001)
    v = np.array([speed_at_depth(zi, m, a, strength, DENSITY, N, speed, 4 * a) for zi in z])
    # time = integral of dz / V; the last stretch, where V -> 0, by the deceleration's finite value there
    moving = v > 1e-3 * speed
    t = np.concatenate([[0.0], np.cumsum(np.diff(z[moving]) / (0.5 * (v[moving][1:] + v[moving][:-1])))])
    stop = t[-1] + v[moving][-1] / (math.pi * a * a * strength / m)
    v1 = speed_at_depth(4 * a, m, a, strength, DENSITY, N, speed, 4 * a)
    peak = math.pi * a * a * (strength + N * DENSITY * v1 * v1) / m
    return {"depth": P, "v1": v1, "duration": stop, "peak": peak, "z": z, "v": v, "strength": strength, "N": N}


def event_end(fc: float, speed: float, cfg: dict) -> float:
    """How long a shot runs: past the closed form's stopping time by END_MARGIN, or the size's share of that
    (smoke), but never short of twice the crater's transit 4a / V, so that the tunnel's force is reached."""
    full = END_MARGIN * closed_form(fc, speed)["duration"]
    return max(full * cfg.get("end_fraction", 1.0), 2 * 4 * ARTICLE["radius"] / speed)


def shot_scene(name: str, kinematics: str, h: float, fc: float, speed: float, end_time: float,
               history: float, yaw_deg: float = 0.0, spin: float = 0.0, friction: float = FRICTION,
               sections: int = 21, curve_elements: int = 24) -> dict:
    """The article nose first at ``speed`` into concrete of strength ``fc``: the tip 0.1 mm above the
    face, yawed ``yaw_deg`` (the axis turned about x, the velocity along -z), spinning ``spin`` [rad/s]
    about its axis; stations on its axis record its bending, and ``sections`` slabs along it its axial
    and bending stress."""
    L = article_length()
    dims = {k: v for k, v in article_dims(L).items() if k in ("radius", "length", "crh", "meplat_radius")}
    three_d = kinematics == "3d"
    tip = [0.0, 0.0, 1e-4] if three_d else [0.0, 1e-4]
    body = {"name": "projectile", "material": "steel", "shape": "projectile", "element_size": h,
            "position": tip, "velocity": [0.0, 0.0, -speed] if three_d else [0.0, -speed], **dims}
    turn = axis_angle([1.0, 0.0, 0.0], math.radians(yaw_deg))
    if three_d:
        body["orientation"] = {"axis": [1.0, 0.0, 0.0], "angle": f"{yaw_deg} deg"}
        if spin:
            body["spin"] = spin
    stations = []
    for k in range(STATIONS):
        along = L * (1 - k / (STATIONS - 1))                   # base (k = 0) to nose tip
        p = np.array(tip) + (turn @ [0.0, 0.0, along] if three_d else np.array([0.0, along]))
        # a cross-section's mean motion, not a node's: a spinning node off the axis circles it
        stations.append({"name": f"station{k}", "body": "projectile", "at": [float(c) for c in p], "section": h})
    normal = [0.0, 0.0, 1.0] if three_d else [0.0, 1.0]
    return {"scene": {"name": name, "kinematics": kinematics, "element": "tet" if three_d else "quad",
                      "end_time": end_time, "curve_elements": curve_elements},
            "materials": {"steel": dict(MATERIAL)},
            "bodies": [body],
            "penetration": {"nose": "projectile.nose", "face": {"point": [0.0] * len(normal), "normal": normal},
                            "compressive_strength": fc, "density": DENSITY,
                            "friction": friction if three_d else 0.0},
            "shock": {"test_articles": ["projectile"], "axis": "z", "cfc": 1000, "accelerometers": stations},
            "outputs": {"history_interval": history, "field_interval": end_time / 10,
                        "sections": [{"body": "projectile", "count": sections}]}}


def cased_article() -> dict:
    """The cased article's dimensions: the projectile part with its cavity (starting ``cavity_start``
    behind the nose, ``wall`` thick, closed by ``base_thickness``) and the payload cylinder in it (the
    cavity less ``clearance`` on the radius and at its top, ``gap`` above its floor), the length at which
    the two weigh the solid article's mass."""
    R = ARTICLE["radius"]
    _, nose = ogive(article_dims())
    steel = property_si(ARTICLE["library"], "density", "density")
    fill = property_si(CASE["payload"], "density", "density")
    rc, z0 = R - CASE["wall"], nose + CASE["cavity_start"]

    def dims(L):
        lc = L - CASE["base_thickness"] - z0
        case = {**article_dims(L), "cavity_radius": rc, "cavity_length": lc, "base_thickness": CASE["base_thickness"]}
        payload = {"radius": rc - CASE["clearance"], "length": lc - CASE["clearance"] - CASE["gap"],
                   "floor": z0 + CASE["gap"]}
        return case, payload

    def mass(L):
        case, payload = dims(L)
        return (PARTS["projectile"].volume(case, 3) * steel
                + math.pi * payload["radius"] ** 2 * payload["length"] * fill)
    L = brentq(lambda L: mass(L) - projectile_mass(), z0 + CASE["base_thickness"] + 0.02, 20 * R)
    case, payload = dims(L)
    return {"case": case, "payload": payload, "length": L, "payload_mass": math.pi * payload["radius"] ** 2
            * payload["length"] * fill, "case_mass": projectile_mass() - math.pi * payload["radius"] ** 2
            * payload["length"] * fill}


def cased_shot_scene(name: str, h: float, fc: float, speed: float, end_time: float, history: float,
                     sections: int) -> dict:
    """The cased article with its payload (``cased_article``), axisymmetric, nose first into concrete:
    the payload rides in the cavity (contact), and the crater law takes both masses (``carries``)."""
    c = cased_article()
    raw = shot_scene(name, "axisymmetric", h, fc, speed, end_time, history, sections=sections)
    body = raw["bodies"][0]
    body.update({k: c["case"][k] for k in ("length", "cavity_radius", "cavity_length", "base_thickness")})
    p = c["payload"]
    tip = body["position"]
    raw["materials"]["payload"] = {"library": CASE["payload"]}
    raw["bodies"].append({"name": "payload", "material": "payload", "shape": "cylinder", "radius": p["radius"],
                          "length": p["length"], "element_size": h, "position": [0.0, tip[1] + p["floor"]],
                          "velocity": list(body["velocity"])})
    raw["contact"] = [{"name": "payload_in_cavity", "a": "payload", "b": "projectile.cavity"}]
    raw["penetration"]["carries"] = ["payload"]
    raw["shock"]["test_articles"] = ["projectile", "payload"]
    raw["shock"]["accelerometers"] = []
    return raw

"""What the penetration study's sections share: the projectile (the fixture study's 12 lb article), the
targets, the run sizes, the scene of a shot and the closed form it is compared with."""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Callable

import numpy as np

from ...penetration.forrestal import depth_of, speed_at_depth
from ...scene.library import LIBRARY
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

SIZES = {
    # element sizes of the projectile (axisymmetric quads, 3D tetrahedra), the centre points of the
    # design (one: a simulation repeats itself), the history's sampling, and the share of each event run
    # (smoke: ``event_end`` keeps it past the crater), and the force pulses' durations over the article's
    # first axial period (section 3)
    "smoke": {"h_axi": 0.006, "h_3d": 0.02, "centre_points": 1, "history": 1e-5, "end_fraction": 0.12,
              "duration_ratios": (0.5, 1.0, 4.0)},
    "default": {"h_axi": 0.003, "h_3d": 0.01, "centre_points": 1, "history": 5e-6, "end_fraction": 1.0,
                "duration_ratios": (0.25, 0.5, 0.8, 1.0, 1.5, 2.0, 3.0, 4.0, 8.0)},
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
               history: float, yaw_deg: float = 0.0, spin: float = 0.0, friction: float = FRICTION) -> dict:
    """The article nose first at ``speed`` into concrete of strength ``fc``: the tip 0.1 mm above the
    face, yawed ``yaw_deg`` (the axis turned about x, the velocity along -z), spinning ``spin`` [rad/s]
    about its axis; stations on its axis record its bending."""
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
                      "end_time": end_time},
            "materials": {"steel": dict(MATERIAL)},
            "bodies": [body],
            "penetration": {"nose": "projectile.nose", "face": {"point": [0.0] * len(normal), "normal": normal},
                            "compressive_strength": fc, "density": DENSITY,
                            "friction": friction if three_d else 0.0},
            "shock": {"test_articles": ["projectile"], "axis": "z", "cfc": 1000, "accelerometers": stations},
            "outputs": {"history_interval": history, "field_interval": end_time / 10}}

"""Verification of the concrete-penetration law (``penetration/forrestal.py``).

The depth of penetration in closed form against the published data point of
``../shared/references/README.md`` (Forrestal et al. 1994: a 0.906 kg ogive of 26.9 mm diameter,
CRH 2, into concrete of f'c = 35.2 MPa at 277 m/s: measured 173 mm, the model's 167 mm), and the
closed form's tunnel depth against the equation of motion m V dV/dz = -pi a^2 (S f'c + N rho V^2)
integrated numerically from the crater's exit speed V1 to rest.  The concrete's density is not in
the reference; 2300 kg/m^3 is taken (the depth moves by 0.2% between 2200 and 2500).
"""
from __future__ import annotations

import math
import time

from scipy.integrate import solve_ivp

from ..penetration.forrestal import depth, tunnel_entry_speed_squared, tunnel_force
from .checks import check

SHOT = {"mass": 0.906, "radius": 0.0269 / 2, "crh": 2.0, "fc": 35.2e6, "density": 2300.0, "speed": 277.0}
MEASURED_DEPTH, MODEL_DEPTH = 0.173, 0.167


def forrestal(size, workdir):
    """Depth against the published model and measurement; the closed form against its ODE."""
    s = SHOT
    t0 = time.perf_counter()
    P = depth(s["mass"], s["radius"], s["fc"], s["density"], s["speed"], s["crh"])
    wall = time.perf_counter() - t0
    out = [check("forrestal.depth_vs_published_model [m]", MODEL_DEPTH, P, 0.015, wall, 0),
           check("forrestal.depth_vs_measured [m]", MEASURED_DEPTH, P, 0.05, wall, 0)]
    # the tunnel: m V dV/dz = -F(V) integrated from V1 (the crater's exit speed) to rest
    t0 = time.perf_counter()
    a, m = s["radius"], s["mass"]
    v1 = math.sqrt(tunnel_entry_speed_squared(m, a, s["fc"], s["density"], s["speed"], s["crh"]))

    def slowing(z, y):            # y = V^2 / 2: d(V^2/2)/dz = -F(V) / m
        return [-tunnel_force(a, s["fc"], s["density"], math.sqrt(max(2 * y[0], 0.0)), s["crh"]) / m]

    def stopped(z, y):
        return y[0]
    stopped.terminal = True
    sol = solve_ivp(slowing, (0.0, 10.0), [0.5 * v1 * v1], events=stopped, rtol=1e-11, atol=1e-12)
    out.append(check("forrestal.tunnel_depth_vs_ode [m]", sol.t_events[0][0] + 4 * a, P, 1e-7,
                     time.perf_counter() - t0, 0))
    return out

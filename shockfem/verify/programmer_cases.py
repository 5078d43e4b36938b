"""Verification of the pulse programmers' physics and of their sizing tool (``shockfem programmer``).

Sizing (``programmer_sizing``): the requirement of each shape against the closed forms of
``fixtures.md`` (10,000 g for 5 ms); the metering pin and the fixed orifice of the dashpot
integrated as an ODE, m dv/dt = -k(x) v^2 with k = rho A^3 / (2 Cd^2 a(x)^2), against the constant
force they are sized for and the exact a(t) = a0 / (1 + a0 t / V0)^2; the split cone's
restitution against the table of ``fixtures.md``.

Crushable pad: a rigid mass m at v0 lands on a pad of crushable foam (area A, nu = 0, a flat
crush stress sigma_c up to densification), standing on a fixed base.  While the pad crushes it
pushes back with sigma_c A, so the mass decelerates at the constant a = sigma_c A / m (a
rectangular pulse) and stops in v0 / a.  The pad first compresses elastically by
delta_e = sigma_c H / E and keeps that strain energy, F delta_e / 2 with F = sigma_c A, so that the
energy balance F s_crush + F delta_e / 2 = m v0^2 / 2 gives the stroke (the striker's travel) and the
plastic work

    stroke = v0^2 / (2 a) + delta_e / 2,     W_p = m v0^2 / 2 - F delta_e / 2

(the elastic terms are 1% of each here).  Departures from these closed forms, bounded by the
tolerances: the pad's own mass (0.2% of the striker's), the elastic rise of the contact force over
a few wave transits of the pad (tens of microseconds of a 5 ms pulse), the penalty's give, and the
crush front stepping from element to element as each densifies.
"""
from __future__ import annotations

import math
import time

import numpy as np
from scipy.integrate import solve_ivp

from ..programmer.concepts import orifice_dashpot, split_cone
from ..programmer.requirement import requirement
from ..units import G0
from .checks import SIZES, check, element_count
from .scenes import STEEL, solve

PAD = {"radius": 0.05, "thickness": 0.04, "crush": 1e6, "density": 50.0, "modulus": 150e6}
DROP = {"mass": 8.0, "speed": 5.0}


def _pad_scene(size):
    R, H, sc, rho = PAD["radius"], PAD["thickness"], PAD["crush"], PAD["density"]
    m, v0 = DROP["mass"], DROP["speed"]
    a = sc * math.pi * R ** 2 / m
    t_stop = v0 / a
    h = 0.002 * SIZES[size]
    striker_length = 0.02
    return {"scene": {"name": "crushable_pad", "kinematics": "axisymmetric", "end_time": 1.3 * t_stop},
            "materials": {
                # flat plateau to 60% volumetric strain, densified by 80%; E = the densification slope
                "foam": {"density": rho, "youngs_modulus": PAD["modulus"], "tension_cutoff": 0.1 * sc,
                         "crush_curve": [[0.0, sc], [0.6, sc], [0.8, 30 * sc]]},
                "striker": {"density": m / (math.pi * R ** 2 * striker_length), "youngs_modulus": 210e9}},
            "bodies": [{"name": "pad", "material": "foam", "shape": "cylinder", "radius": R, "length": H,
                        "element_size": h},
                       {"name": "striker", "material": "striker", "shape": "cylinder", "radius": R,
                        "length": striker_length, "element_size": 2 * h, "position": [0.0, H],
                        "velocity": [0.0, -v0], "rigid": True}],
            "boundary": [{"region": "pad.bottom", "type": "fixed"}],
            "contact": [{"name": "landing", "a": "striker.bottom", "b": "pad.top", "penalty_scale": 1.0}],
            "outputs": {"field_interval": 1.3 * t_stop, "history_interval": t_stop / 200}}


def crushable_pad(size, workdir):
    """A rigid mass dropped on a crushable pad: rectangular pulse a = sigma_c A / m, stroke
    v0^2 / (2 a), the kinetic energy absorbed as the pad's plastic work (module docstring)."""
    R, H, sc, E = PAD["radius"], PAD["thickness"], PAD["crush"], PAD["modulus"]
    m, v0 = DROP["mass"], DROP["speed"]
    F = sc * math.pi * R ** 2
    a = F / m
    t_stop = v0 / a
    delta_e = sc * H / E
    samples = []

    def probe(s):
        v, _ = s.body_means()
        samples.append((s.t, v[1, 1]))

    solver, wall = solve(_pad_scene(size), cache_dir=workdir, probe=probe)
    t, vz = np.array(samples).T
    sel = (t > 0.2 * t_stop) & (t < 0.8 * t_stop)
    decel = np.polyfit(t[sel], vz[sel], 1)[0]          # the striker moves down (vz < 0) and slows
    stop = int(np.argmax(vz >= 0.0))
    # the stroke: the striker's travel until it stops (trapezoidal integral of its velocity)
    stroke = -np.trapz(vz[:stop + 1], t[:stop + 1])
    e = solver.energy
    kinetic = 0.5 * m * v0 ** 2
    n = element_count(solver)
    return [
        # 3%: the acceptance bound; the crush front's steps from element to element and the elastic rise
        check("crushable_pad.deceleration [m/s^2]", a, decel, 0.03, wall, n),
        check("crushable_pad.stop_time [s]", t_stop, t[stop], 0.03, wall, n),
        check("crushable_pad.stroke [m]", v0 ** 2 / (2 * a) + 0.5 * delta_e, stroke, 0.03, wall, n),
        check("crushable_pad.plastic_work [J]", kinetic - 0.5 * F * delta_e, e.plastic, 0.03, wall, n),
        check("crushable_pad.energy_balance [-, abs]", 0.0, e.balance_error, 0.01, wall, n, absolute=True),
    ]


# fixtures.md, "What the specification asks": velocity change and stroke as multiples of A T and A T^2
# (490.3 m/s and 1.226 m, 312.2 m/s and 0.780 m, 245.2 m/s and 0.817 m at 10,000 g for 5 ms)
SPEC_TABLE = {"rectangle": (1.0, 0.5), "half-sine": (2 / math.pi, 1 / math.pi), "terminal-peak sawtooth": (0.5, 1 / 3)}
# fixtures.md, split cone: (half-angle [deg], mu) -> restitution of an elastic ring
CONE_TABLE = {(7, 0.05): 0.645, (7, 0.1): 0.316, (15, 0.05): 0.817, (15, 0.1): 0.658, (15, 0.2): 0.361}
OIL = {"density": 870.0, "discharge": 0.7, "bulk_modulus": 1.5e9, "heat_capacity": 1900.0}


def _dashpot_decelerations(req, piston_area, orifice_area):
    """The orifice law integrated until the article is (almost) at rest: (t, x, v, a) of
    m dv/dt = -k(x) v^2, k = rho A^3 / (2 Cd^2 a(x)^2)."""
    def k(x):
        return OIL["density"] * piston_area ** 3 / (2 * OIL["discharge"] ** 2 * orifice_area(x) ** 2)

    def stop(t, y):
        return y[1] - 1e-3 * req.velocity_change
    stop.terminal = True
    sol = solve_ivp(lambda t, y: (y[1], -k(y[0]) * y[1] ** 2 / req.mass), (0.0, 10 * req.duration),
                    (0.0, req.velocity_change), rtol=1e-10, atol=1e-12, events=stop, dense_output=True)
    t = np.linspace(0.0, sol.t[-1], 2001)
    x, v = sol.sol(t)
    return t, x, v, k(x) * v ** 2 / req.mass


def programmer_sizing(size, workdir):
    """The sizing tool's closed forms: each shape's velocity change and stroke (fixtures.md's table),
    the metering pin's constant force and the fixed orifice's exact deceleration (ODE), the split
    cone's restitution (fixtures.md's table); the size does not apply."""
    out = []
    peak, T, m = 1e4 * G0, 5e-3, 5.443
    for shape, (dv, stroke) in SPEC_TABLE.items():
        t0 = time.perf_counter()
        req = requirement(shape, peak, T, m)
        wall = time.perf_counter() - t0
        # the stroke is the first moment of the ideal pulse at 400,000 midpoints: 1e-9 or better
        out += [check(f"sizing.{shape}.velocity_change [m/s]", dv * peak * T, req.velocity_change, 1e-12, wall, 0),
                check(f"sizing.{shape}.stroke [m]", stroke * peak * T ** 2, req.stroke, 1e-9, wall, 0)]
    t0 = time.perf_counter()
    req = requirement("rectangle", peak, T, m)
    dashpot = orifice_dashpot(req, OIL["density"], OIL["discharge"], OIL["bulk_modulus"], 400e6, OIL["heat_capacity"])
    sizes = {label: value for label, value, _ in dashpot.sizes}
    A, F, V0 = sizes["piston area"], req.force, req.velocity_change

    def pin(x):       # fixtures.md's metering pin for the constant force F
        return (A ** 1.5 / OIL["discharge"] * np.sqrt(OIL["density"] / (2 * F))
                * np.sqrt(np.maximum(V0 ** 2 - 2 * F * x / m, 1e-12)))
    t, x, v, a = _dashpot_decelerations(req, A, pin)
    middle = (x > 0.1 * x[-1]) & (x < 0.9 * x[-1])
    wall = time.perf_counter() - t0
    out += [check("sizing.metering_pin.force_flatness [-, abs]", 0.0, np.abs(a[middle] / peak - 1).max(), 1e-6, wall,
                  0, absolute=True),
            check("sizing.metering_pin.stroke [m]", sizes["stroke (constant force)"], x[-1], 1e-3, wall, 0)]
    t0 = time.perf_counter()
    a_fixed = math.pi / 4 * sizes["fixed orifice giving the peak at V0: diameter"] ** 2
    t, x, v, a = _dashpot_decelerations(req, A, lambda x: a_fixed)
    exact = peak / (1 + peak * t / V0) ** 2
    early = t <= T
    v_T = np.interp(T, t, v)
    wall = time.perf_counter() - t0
    out += [check("sizing.fixed_orifice.deceleration [-, abs]", 0.0, np.abs(a[early] / exact[early] - 1).max(), 1e-6,
                  wall, 0, absolute=True),
            check("sizing.fixed_orifice.speed_after_T [m/s]", sizes["fixed orifice: speed left after the duration"], v_T,
                  1e-6, wall, 0)]
    for (alpha, mu), e in CONE_TABLE.items():
        t0 = time.perf_counter()
        cone = split_cone(req, math.radians(alpha), mu, 250e6, 210e9, 0.2, 7850.0)
        got = {label: value for label, value, _ in cone.sizes}["restitution of an elastic ring"]
        out.append(check(f"sizing.cone.alpha_{alpha}.mu_{mu:g}.restitution [-]", e, got, 0.0005 / e,
                         time.perf_counter() - t0, 0))
    return out



RUBBER_PAD = {"modulus": 10e6, "thickness": 0.01, "radius": 0.03, "speed": 20.0, "plate_radius": 0.05,
              "striker_length": 0.005}


def _rubber_pad_scene(size, end_time=3e-3, law="neo-hookean"):
    R, H, v0, Rp = RUBBER_PAD["radius"], RUBBER_PAD["thickness"], RUBBER_PAD["speed"], RUBBER_PAD["plate_radius"]
    h = 0.001 * SIZES[size]
    rubber = {"density": 1100.0, "youngs_modulus": RUBBER_PAD["modulus"], "poisson_ratio": 0.495}
    if law == "neo-hookean":
        rubber["hyperelastic"] = "neo-hookean"
    return {"scene": {"name": "rubber_pad", "kinematics": "axisymmetric", "end_time": end_time},
            "materials": {"steel": dict(STEEL), "rubber": rubber},
            "bodies": [{"name": "base", "material": "steel", "shape": "cylinder", "radius": Rp, "length": 0.02,
                        "element_size": 2 * h},
                       {"name": "pad", "material": "rubber", "shape": "cylinder", "radius": R, "length": H,
                        "element_size": h, "position": [0.0, 0.02]},
                       {"name": "striker", "material": "steel", "shape": "cylinder", "radius": Rp,
                        "length": RUBBER_PAD["striker_length"],
                        "element_size": 2 * h, "position": [0.0, 0.02 + H], "velocity": -v0}],
            "boundary": [{"region": "base.bottom", "type": "fixed"}],
            "contact": [{"name": "strike", "a": "striker.bottom", "b": "pad.top"},
                        {"name": "seat", "a": "pad.bottom", "b": "base.top"}],
            "outputs": {"field_interval": end_time, "history_interval": end_time / 300}}


def rubber_pad(size, workdir):
    """A 20 m/s steel striker onto a 10 mm Neo-Hookean rubber pad (E 10 MPa, nu 0.495) on a steel base:
    the striker is stopped and thrown back, the contact opens (the run goes through the rebound), and
    the energy balance stays within 1% (the acceptance bound).  The rubber gives the strike back
    elastically, so the striker leaves with most of its speed: less than it came with (no energy
    gained), more than half of it (the losses, bulk viscosity and contact damping, are small).
    The plates are wider than the pad (50 mm against 30 mm) so that the bulging rubber stays between
    them, and the striker is a 5 mm disc, so that the pad is squeezed to about half its thickness."""
    v0 = RUBBER_PAD["speed"]
    solver, wall = solve(_rubber_pad_scene(size), cache_dir=workdir)
    pair = solver.contacts[0]
    v, _ = solver.body_means()
    n = element_count(solver)
    opened = bool(pair.intervals) and pair.intervals[-1][1] is not None
    rebound = v[2, 1]
    return [
        check("rubber_pad.contact_opened [-, abs]", 1.0, float(opened), 0.0, wall, n, absolute=True),
        check("rubber_pad.energy_balance [-, abs]", 0.0, solver.energy.balance_error, 0.01, wall, n, absolute=True),
        check("rubber_pad.no_energy_gained [m/s, abs]", 0.0, max(0.0, rebound - v0), 0.0, wall, n, absolute=True),
        check("rubber_pad.mostly_elastic [m/s, abs]", 0.0, max(0.0, 0.5 * v0 - rebound), 0.0, wall, n, absolute=True),
    ]

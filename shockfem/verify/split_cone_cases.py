"""Verification of the split cone's physics: the clamp ring's shrink-fit preload and the wedge
action of a cone with friction.

Shrink fit: a steel ring shrunk onto a solid shaft of its length with a radial interference; the
contact's interference option pushes the initial overlap out, and the mean contact pressure must be
Lame's (``fixtures.md``).

Wedge (cone) friction, in plane strain: a soft block is pushed slowly between two rigid walls
inclined at the half-angle alpha to the push axis (the section of a rigid cone), friction mu
(phi = atan mu), then drawn back.  While it slides in, the walls push back with an axial to
radial (here: lateral) force ratio tan(alpha + phi); while it slides out, tan(alpha - phi)
(``fixtures.md``).  From the two ratios, a mass striking an elastic ring through such a cone
rebounds with e = sqrt(tan(alpha - phi) / tan(alpha + phi)); that e is compared with the table of
``fixtures.md``.  The push takes 10 ms, 25 periods of the block's lowest mode, so that the block
slides steadily (a faster push makes it stick and slip on the way out).
"""
from __future__ import annotations

import math

import numpy as np

from .checks import SIZES, check, element_count
from .scenes import STEEL, solve

SHRINK = {"shaft_radius": 0.02, "ring_outer": 0.04, "length": 0.02, "interference": 2e-5, "ramp": 2e-4}


def _shrink_fit_scene(size):
    b, c, L, delta = SHRINK["shaft_radius"], SHRINK["ring_outer"], SHRINK["length"], SHRINK["interference"]
    h = 0.001 * SIZES[size]
    end = 1.5 * SHRINK["ramp"]
    return {"scene": {"name": "shrink_fit", "kinematics": "axisymmetric", "end_time": end},
            "materials": {"steel": dict(STEEL)},
            "bodies": [{"name": "shaft", "material": "steel", "shape": "cylinder", "radius": b, "length": L,
                        "element_size": h},
                       {"name": "ring", "material": "steel", "shape": "clamp_ring", "fits": "shaft",
                        "interference": delta, "thickness": c - b + delta, "length": L, "element_size": h}],
            "contact": [{"name": "fit", "a": "ring.inner", "b": "shaft.side", "interference": SHRINK["ramp"],
                         "penalty_scale": 10.0}],
            "outputs": {"field_interval": end, "history_interval": end / 100}}


def lame_shrink_fit(delta, a, b, c, E_in, nu_in, E_out, nu_out):
    """The contact pressure of a ring (radii b, c) shrunk with radial interference delta onto a cylinder
    (radii a, b; a = 0 solid), both open-ended: Lame's thick cylinders (fixtures.md)."""
    return delta / (b * ((c * c + b * b) / (c * c - b * b) / E_out + nu_out / E_out
                         + (b * b + a * a) / (b * b - a * a) / E_in - nu_in / E_in))


def shrink_fit(size, workdir):
    """A steel ring shrunk onto a solid steel shaft of its length, radial interference 0.02 mm: the
    contact's interference option pushes the initial overlap out over 200 us, and the mean contact
    pressure (after the ramp, settled, and as the pair's summary reports it at its largest load) matches
    Lame's shrink-fit pressure (3%, the acceptance bound;
    the penalty's own give, p h / (10 K) of the 0.02 mm, is 0.2% of it here)."""
    samples = []

    def probe(s):
        pair = s.contacts[0]
        samples.append((s.t, pair._pressure()["mean_pressure"] if pair.active else 0.0))
    solver, wall = solve(_shrink_fit_scene(size), cache_dir=workdir, probe=probe)
    t, p = np.array(samples).T
    settled = p[t > SHRINK["ramp"] * 1.1].mean()
    E, nu = STEEL["youngs_modulus"], STEEL["poisson_ratio"]
    exact = lame_shrink_fit(SHRINK["interference"], 0.0, SHRINK["shaft_radius"], SHRINK["ring_outer"], E, nu, E, nu)
    pair = solver.contacts[0]
    n = element_count(solver)
    return [
        check("shrink_fit.preload_pressure [Pa]", exact, pair.preload["mean_pressure"], 0.03, wall, n),
        check("shrink_fit.settled_pressure [Pa]", exact, settled, 0.03, wall, n),
        # the pressure the pair reports in its summary: over the loaded area, when the load was largest
        check("shrink_fit.pressure_at_max_force [Pa]", exact, pair.pressure_at_max_force, 0.03, wall, n),
        check("shrink_fit.energy_balance [-, abs]", 0.0, solver.energy.balance_error, 0.01, wall, n, absolute=True),
    ]


# fixtures.md's split cone table: (alpha [deg], mu) -> the restitution of an elastic ring
WEDGES = {(7.0, 0.05): 0.645, (15.0, 0.1): 0.658, (15.0, 0.2): 0.361}
WEDGE = {"width": 0.02, "height": 0.02, "depth": 5e-4, "push_time": 1e-2}


def _wedge_scene(alpha, mu, size):
    w, hgt, T = WEDGE["width"], WEDGE["height"], WEDGE["push_time"]
    v = WEDGE["depth"] / T
    c, s = math.cos(alpha), math.sin(alpha)
    # the top is driven down at v, then back up at v, with 5% ramps; held laterally
    push = [[0.0, 0.0], [0.05 * T, -v], [0.95 * T, -v], [1.05 * T, v], [1.95 * T, v], [2 * T, 0.0]]
    return {"scene": {"name": "wedge", "kinematics": "plane-strain", "end_time": 2 * T, "thickness": 0.01},
            "materials": {"soft": {"density": 1000.0, "youngs_modulus": 10e6, "poisson_ratio": 0.3}},
            "bodies": [{"name": "block", "material": "soft", "shape": "box", "size": [w, hgt],
                        "element_size": 0.001 * SIZES[size], "position": [-w / 2, 0.0]}],
            "boundary": [{"region": "block.top", "type": "velocity", "direction": "y", "history": push},
                         {"region": "block.top", "type": "velocity", "direction": "x", "value": 0.0}],
            "contact": [{"name": side, "a": "block", "friction": mu, "penalty_scale": 1.0,
                         "wall": {"point": [sign * w / 2, 0.0], "normal": [-sign * c, s]}}
                        for side, sign in (("right", 1.0), ("left", -1.0))],
            "damping": {"ratio": 0.05, "frequency": "2 kHz"},
            "outputs": {"field_interval": 2 * T, "history_interval": T / 100}}


def cone_friction(size, workdir):
    """A block pushed into and drawn out of a rigid V of half-angle alpha with friction mu: axial over
    lateral wall force tan(alpha + phi) sliding in, tan(alpha - phi) sliding out (5%, the acceptance
    bound), and the elastic ring's restitution those ratios give against fixtures.md's table."""
    out = []
    T = WEDGE["push_time"]
    for (degrees, mu), e_table in WEDGES.items():
        alpha, phi = math.radians(degrees), math.atan(mu)
        rows = []

        def probe(s):
            F = s.contacts[0].force_a + s.contacts[0].friction_a          # the right wall's push on the block
            rows.append((s.t, F[0], F[1]))
        solver, wall = solve(_wedge_scene(alpha, mu, size), cache_dir=workdir, probe=probe)
        t, fx, fy = np.array(rows).T
        # steady sliding: the middle of each stroke, away from the turn where the friction reverses
        ratio_in = np.mean(fy[(t > 0.3 * T) & (t < 0.9 * T)] / -fx[(t > 0.3 * T) & (t < 0.9 * T)])
        ratio_out = np.mean(fy[(t > 1.3 * T) & (t < 1.9 * T)] / -fx[(t > 1.3 * T) & (t < 1.9 * T)])
        n = element_count(solver)
        tag = f"cone.alpha_{degrees:g}.mu_{mu:g}"
        out += [check(f"{tag}.loading_ratio [-]", math.tan(alpha + phi), ratio_in, 0.05, wall, n),
                check(f"{tag}.unloading_ratio [-]", math.tan(alpha - phi), ratio_out, 0.05, wall, n),
                # the table's three digits: half a unit of the last one
                check(f"{tag}.ring_restitution [-, vs fixtures.md]", e_table, math.sqrt(ratio_out / ratio_in),
                      0.0005 / e_table, wall, n),
                check(f"{tag}.energy_balance [-, abs]", 0.0, solver.energy.balance_error, 0.01, wall, n,
                      absolute=True)]
    return out


CONE = {"half_angle": 7.0, "friction": 0.1, "outer_radius": 0.04, "length": 0.04, "exit_radius": 0.02,
        "plug_length": 0.02, "plug_bottom": 0.01, "gap": 2e-6, "push": 2e-4, "push_time": 4e-4}


def _cone_scene(name, alpha, mu, size, workdir, end_time, plug_material, plug_rigid=False, ring_held=False):
    """The ring of ``CONE`` (a one-segment ``split_cone``: a ring with a conical bore of half-angle
    alpha) standing on a frictionless base, and a ``cone_plug`` of the same half-angle sitting in its
    bore ``gap`` short of touching.  ``ring_held``: every boundary node of the ring is held axially too,
    so that the ring can only breathe radially."""
    c = CONE
    h = 0.001 * SIZES[size]
    entry = c["exit_radius"] + c["length"] * math.tan(alpha)
    z0, hp = c["plug_bottom"], c["plug_length"]
    r_b = c["exit_radius"] + z0 * math.tan(alpha) - c["gap"]
    r_t = r_b + hp * math.tan(alpha)
    held = ["bottom", "side", "top", "bore"] if ring_held else ["bottom"]
    return {"scene": {"name": name, "kinematics": "axisymmetric", "end_time": end_time},
            "materials": {"steel": dict(STEEL), "plug": plug_material},
            "bodies": [{"name": "cone", "material": "steel", "shape": "split_cone", "outer_radius": c["outer_radius"],
                        "length": c["length"], "entry_radius": entry, "exit_radius": c["exit_radius"],
                        "segments": 1, "element_size": h},
                       {"name": "plug", "material": "plug", "shape": "cone_plug", "bottom_radius": r_b,
                        "top_radius": r_t, "length": hp, "element_size": h, "rigid": plug_rigid,
                        "position": [0.0, z0]}],
            "boundary": [{"region": f"cone.{region}", "type": "velocity", "direction": "z", "value": 0.0}
                         for region in held],
            "contact": [{"name": "wedge", "a": "plug.side", "b": "cone.bore", "friction": mu, "penalty_scale": 10.0}],
            "outputs": {"field_interval": end_time, "history_interval": end_time / 100}}


def cone_push(size, workdir):
    """A steel ``cone_plug`` (axisymmetric) pushed 0.2 mm into the 7 degree conical
    bore of an elastic steel ring (friction 0.1; the ring stands on a frictionless base) over 0.4 ms,
    twelve periods of the ring's breathing, then drawn back: the ring pushes back on the plug with
    axial over radial force tan(alpha + phi) while it slides in and tan(alpha - phi) while it slides
    out (5%, the acceptance bound)."""
    c = CONE
    alpha, mu = math.radians(c["half_angle"]), c["friction"]
    phi = math.atan(mu)
    T, v = c["push_time"], c["push"] / c["push_time"]
    push = [[0.0, 0.0], [0.05 * T, -v], [0.95 * T, -v], [1.05 * T, v], [1.95 * T, v], [2 * T, 0.0]]
    raw = _cone_scene("cone_push", alpha, mu, size, workdir, 2 * T, dict(STEEL))
    raw["boundary"].append({"region": "plug.top", "type": "velocity", "direction": "z", "history": push})
    raw["damping"] = {"ratio": 0.05, "frequency": "20 kHz"}
    rows = []

    def probe(s):
        pair = s.contacts[0]
        F = pair.force_a + pair.friction_a                    # the ring's push on the plug
        rows.append((s.t, F[0], F[1]))
    solver, wall = solve(raw, cache_dir=workdir, probe=probe)
    t, fr, fz = np.array(rows).T
    load = (t > 0.3 * T) & (t < 0.9 * T)
    unload = (t > 1.3 * T) & (t < 1.9 * T)
    ratio_in = float(fz[load].sum() / -fr[load].sum())
    ratio_out = float(fz[unload].sum() / -fr[unload].sum())
    n = element_count(solver)
    return [check("cone_push.loading_ratio [-]", math.tan(alpha + phi), ratio_in, 0.05, wall, n),
            check("cone_push.unloading_ratio [-]", math.tan(alpha - phi), ratio_out, 0.05, wall, n),
            check("cone_push.energy_balance [-, abs]", 0.0, solver.energy.balance_error, 0.01, wall, n, absolute=True)]


# the drop: a 2.2 kg rigid plug at 0.5 m/s (density ten times steel's, to make the contact last many
# periods of the ring's breathing, as a heavy striker on a light ring does)
REBOUND = {"speed": 0.5, "plug_density": 78000.0, "end_time": 6e-4}


def cone_rebound(size, workdir):
    """A rigid conical plug dropped into the conical bore of an elastic steel ring held axially (its
    boundary nodes move only radially): the only spring is then the ring's radial give, as in
    fixtures.md's lumped model, and the plug rebounds with e = sqrt(tan(alpha - phi) /
    tan(alpha + phi)) (5%, the acceptance bound for the cone) for the 7 and 15 degree entries of the
    table.  The loop: sliding in, the wedge stores k_r u^2 / 2 through an axial stiffness k_r tan(alpha)
    tan(alpha + phi); at the turn the friction reverses with the plug stuck; sliding out, the ring
    gives back through k_r tan(alpha) tan(alpha - phi).  An elastic plug in a ring free to compress
    axially rebounds faster (docs/programmers.md): those compliances give their energy back whole."""
    out = []
    for degrees, mu in ((7.0, 0.1), (7.0, 0.05), (15.0, 0.1), (15.0, 0.2)):
        alpha, phi = math.radians(degrees), math.atan(mu)
        plug = {**STEEL, "density": REBOUND["plug_density"]}
        raw = _cone_scene("cone_rebound", alpha, mu, size, workdir, REBOUND["end_time"], plug,
                          plug_rigid=True, ring_held=True)
        raw["bodies"][1]["velocity"] = -REBOUND["speed"]
        solver, wall = solve(raw, cache_dir=workdir)
        v_plug = solver.body_means()[0][1, 1]
        n = element_count(solver)
        tag = f"cone_rebound.alpha_{degrees:g}.mu_{mu:g}"
        out += [check(f"{tag}.restitution [-]", math.sqrt(math.tan(alpha - phi) / math.tan(alpha + phi)),
                      v_plug / REBOUND["speed"], 0.05, wall, n),
                check(f"{tag}.energy_balance [-, abs]", 0.0, solver.energy.balance_error, 0.01, wall, n,
                      absolute=True)]
    return out

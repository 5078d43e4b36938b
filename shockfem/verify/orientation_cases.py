"""Verification of oriented bodies (3D): a scene turned as a whole gives the turned results.

* The 3D rod-on-rod impact (``contact_cases``) run twice: along z, and with both rods turned by
  ``orientation = {direction = d}``, placed along d and launched with a single speed (which follows
  the body's axis).  Contact time, plateau force and the final velocities along d must agree with
  the unturned run.  Not to round-off: two flat faces meet at every node on the same step, so which
  nodes switch on a step earlier is decided by round-off, and a 90 degree turn about x (exact but for
  cos 90 deg = 6e-17) already moves the peak force by 1.6% and the contact time by 6e-6.  The bounds
  (1% of force and time, 1e-3 of the speed) are far inside what a wrong turn would do: a striker
  misplaced or launched off its axis misses, or strikes at an angle.
* A spinning cylinder turned to d: its angular momentum points along d with the magnitude I_axis w
  (I_axis from the lumped masses), and free flight keeps it (1e-9).
"""
from __future__ import annotations

import numpy as np

from .checks import SIZES, check, element_count
from .scenes import STEEL, solve, steel_c0

DIRECTION = (1.0, 2.0, 2.0)           # |d| = 3: an axis turned off all three axes
RADIUS, LENGTH, SPEED = 0.005, 0.1, 1.0
# the rods start 10 um apart: faces that start touching leave which nodes begin inside the other
# surface to round-off, and with it the contact's start
GAP = 1e-5


def _unit(v):
    v = np.asarray(v, dtype=float)
    return v / np.linalg.norm(v)


def _pair_scene(h, direction=None):
    d = _unit(direction) if direction is not None else np.array([0.0, 0.0, 1.0])
    t_contact = 2 * LENGTH / steel_c0()
    end = GAP / SPEED + 1.4 * t_contact

    def rod(name, start, speed):
        body = {"name": name, "material": "steel", "shape": "cylinder", "radius": RADIUS, "length": LENGTH,
                "element_size": h, "position": list(start * d), "velocity": speed}
        if direction is not None:
            body["orientation"] = {"direction": list(direction)}
        return body
    return {"scene": {"name": "oriented_rods", "kinematics": "3d", "element": "hex", "end_time": end},
            "materials": {"steel": dict(STEEL)},
            "bodies": [rod("striker", LENGTH + GAP, -SPEED), rod("target", 0.0, 0.0)],
            "contact": [{"name": "impact", "a": "striker.bottom", "b": "target.top"}],
            "outputs": {"field_interval": end, "history_interval": t_contact / 50}}


def _pair_run(h, workdir, direction=None):
    d = _unit(direction) if direction is not None else np.array([0.0, 0.0, 1.0])
    forces = []
    solver, wall = solve(_pair_scene(h, direction), cache_dir=workdir,
                         probe=lambda s: forces.append((s.t, float(np.linalg.norm(s.contacts[0].force_a)))))
    pair = solver.contacts[0]
    closed = [iv for iv in pair.intervals if iv[1] is not None]
    start, duration = pair.intervals[0][0], closed[-1][1] - pair.intervals[0][0]
    t, F = np.array(forces).T
    v, _ = solver.body_means()
    return {"contact_time": duration,
            "plateau_force": F[(t > start + 0.25 * duration) & (t < start + 0.75 * duration)].mean(),
            "striker_velocity": float(v[0] @ d), "target_velocity": float(v[1] @ d),
            "off_axis_velocity": float(np.linalg.norm(v - np.outer(v @ d, d))),
            "wall": wall, "elements": element_count(solver)}


def _angular_momentum(solver):
    m = solver.model.mass
    x, v = solver.x, solver.v + 0.5 * solver.dt * solver.a
    centre = (m[:, None] * x).sum(axis=0) / m.sum()
    return (m[:, None] * np.cross(x - centre, v)).sum(axis=0), centre


def oriented_body(size, workdir):
    """A turned scene gives the turned results: the 3D rod-on-rod impact along a skew axis against
    the same along z; a turned spinning cylinder's angular momentum along its axis, kept in flight."""
    h = 0.001 * SIZES[size]
    straight = _pair_run(h, workdir)
    turned = _pair_run(h, workdir, DIRECTION)
    wall, n = turned["wall"], turned["elements"]
    out = [check(f"oriented.rods.{key} [vs along z]", straight[key], turned[key], 0.01, wall, n)
           for key in ("contact_time", "plateau_force")]
    out += [check(f"oriented.rods.{key} [m/s, abs, vs along z]", straight[key], turned[key], 1e-3 * SPEED, wall, n,
                  absolute=True) for key in ("striker_velocity", "target_velocity")]
    # the unturned rods drift sideways at 3e-5 m/s too (their hex mesh is not quite symmetric)
    out.append(check("oriented.rods.off_axis_velocity [m/s, abs]", 0.0, turned["off_axis_velocity"], 1e-4 * SPEED,
                     wall, n, absolute=True))
    # a spinning cylinder turned to d, in free flight
    omega = 500.0
    d = _unit(DIRECTION)
    raw = {"scene": {"name": "oriented_spin", "kinematics": "3d", "element": "hex", "end_time": 2e-4},
           "materials": {"steel": dict(STEEL)},
           "bodies": [{"name": "rotor", "material": "steel", "shape": "cylinder", "radius": 0.02, "length": 0.02,
                       "element_size": 0.004 * SIZES[size], "position": [0.0, 0.0, 0.0], "spin": f"{omega} rad/s",
                       "orientation": {"direction": list(DIRECTION)}}],
           "outputs": {"field_interval": 2e-4, "history_interval": 2e-5}}
    start = {}

    def probe(s):
        if not start:
            start["L"], start["centre"] = _angular_momentum(s)
    solver, wall = solve(raw, cache_dir=workdir, probe=probe)
    L0, centre = start["L"], start["centre"]
    m = solver.model.mass
    rel = solver.model.X0 - centre
    axial = rel @ d
    inertia = float((m * ((rel ** 2).sum(axis=1) - axial ** 2)).sum())
    L1, _ = _angular_momentum(solver)
    n = element_count(solver)
    out += [check("oriented.spin.angular_momentum [N m s]", inertia * omega, float(L0 @ d), 1e-12, wall, n),
            check("oriented.spin.off_axis [-, abs]", 0.0, float(np.linalg.norm(np.cross(L0, d)) / np.linalg.norm(L0)),
                  1e-12, wall, n, absolute=True),
            # the explicit loop keeps angular momentum to round-off when no force acts from outside
            check("oriented.spin.kept_in_flight [-, abs]", 0.0, float(np.linalg.norm(L1 - L0) / np.linalg.norm(L0)),
                  1e-9, wall, n, absolute=True)]
    return out

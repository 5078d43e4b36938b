"""Verification of contact: elastic rods striking each other and a rigid wall (1D wave theory).

Two rods of the same material and section, striker L1 at v onto a target at rest: contact lasts
2 L1 / c0, the interface stress is rho c0 v / 2, the striker ends at rest and the target at v
(restitution 1).  A rod striking a rigid wall rebounds at v after 2 L / c0.  The rods are
slender (L = 20 D) so that 1D theory holds; their lateral ringing is physics, not error.
"""
from __future__ import annotations

import numpy as np

from .cases import SIZES, _elements, check
from .scenes import STEEL, solve, steel_c0

RADIUS, LENGTH, SPEED = 0.0025, 0.1, 1.0


def _rod(name, z0, velocity, h):
    return {"name": name, "material": "steel", "shape": "cylinder", "radius": RADIUS, "length": LENGTH,
            "element_size": h, "position": [0.0, z0], "velocity": [0.0, velocity]}


def _scene(name, bodies, contact, end_time):
    return {"scene": {"name": name, "kinematics": "axisymmetric", "end_time": end_time},
            "materials": {"steel": dict(STEEL)}, "bodies": bodies, "contact": [contact],
            "outputs": {"field_interval": end_time, "history_interval": end_time / 100}}


def _contact_time(pair) -> float:
    """From the first closing to the last opening of the pair (the whole time the rods touch)."""
    closed = [iv for iv in pair.intervals if iv[1] is not None]
    return closed[-1][1] - pair.intervals[0][0] if closed else float("nan")


def rod_on_rod(size, workdir):
    """Identical rods: contact time 2L/c0, plateau force rho c0 v / 2 A, velocities exchanged, e = 1."""
    h = 0.00025 * SIZES[size]
    c0, rho = steel_c0(), STEEL["density"]
    t_contact = 2 * LENGTH / c0
    raw = _scene("rod_on_rod", [_rod("striker", LENGTH, -SPEED, h), _rod("target", 0.0, 0.0, h)],
                 {"name": "impact", "a": "striker.bottom", "b": "target.top"}, 1.4 * t_contact)
    forces = []
    solver, wall = solve(raw, cache_dir=workdir, probe=lambda s: forces.append(
        (s.t, s.contacts[0].force_a[1]) if s.contacts else (s.t, 0.0)))
    pair = solver.contacts[0]
    v, _ = solver.body_means()
    t, F = np.array(forces).T
    plateau = F[(t > 0.25 * t_contact) & (t < 0.75 * t_contact)].mean()
    n = _elements(solver)
    return [
        check("rod_on_rod.contact_time [s]", t_contact, _contact_time(pair), 0.02, wall, n),
        check("rod_on_rod.plateau_force [N]", rho * c0 * SPEED / 2 * np.pi * RADIUS ** 2, plateau, 0.03, wall, n),
        check("rod_on_rod.striker_velocity [m/s, abs]", 0.0, v[0, 1], 0.02 * SPEED, wall, n, absolute=True),
        check("rod_on_rod.target_velocity [m/s]", -SPEED, v[1, 1], 0.02, wall, n),
        check("rod_on_rod.restitution [-]", 1.0, pair.restitution() or 0.0, 0.02, wall, n),
        check("rod_on_rod.energy_balance [-, abs]", 0.0, solver.energy.balance_error, 0.01, wall, n,
              absolute=True),
    ]


def rod_on_wall(size, workdir):
    """A rod striking a rigid wall: rebound at the impact speed after 2L/c0, no energy gained."""
    h = 0.00025 * SIZES[size]
    c0 = steel_c0()
    t_contact = 2 * LENGTH / c0
    raw = _scene("rod_on_wall", [_rod("rod", 0.0, -SPEED, h)],
                 {"name": "wall", "a": "rod.bottom", "wall": {"point": [0.0, 0.0], "normal": [0.0, 1.0]},
                  "penalty_scale": 1.0},
                 1.4 * t_contact)
    solver, wall = solve(raw, cache_dir=workdir)
    pair = solver.contacts[0]
    v, _ = solver.body_means()
    e = solver.energy
    n = _elements(solver)
    return [
        check("rod_on_wall.contact_time [s]", t_contact, _contact_time(pair), 0.02, wall, n),
        check("rod_on_wall.rebound_velocity [m/s]", SPEED, v[0, 1], 0.02, wall, n),
        # no energy gained: what is left in the rod never exceeds what it came with
        check("rod_on_wall.energy_gain [-, abs]", 0.0, max(0.0, (e.kinetic + e.internal) / e.initial - 1), 1e-3,
              wall, n, absolute=True),
    ]

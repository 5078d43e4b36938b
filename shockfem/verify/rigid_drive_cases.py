"""Verification of driven rigid bodies (a ``[[boundary]]`` naming a rigid body: its centre's velocity
prescribed along one direction, the others free).

* A rigid punch driven at a constant speed v onto the end of an elastic rod at rest (axisymmetric): 1D
  wave theory puts a stress rho c0 v behind the front, so the drive pushes with rho c0 v A while the wave
  runs, and its work rho c0 A v^2 t is what the rod takes up, half as kinetic and half as strain energy.
* A rigid cylinder in 3D, spinning about its axis, pulled by gravity across and driven along its axis by a
  ramp to V: its free direction falls as v0 - g t and its spin is kept (no torque), both exact; the drive
  puts in 1/2 M V^2 exactly (the impulse M (v - v_free) times the mean velocity telescopes to the kinetic
  energy change), and its reaction is M a of the ramp.
"""
from __future__ import annotations

import math

import numpy as np
from mpi4py import MPI

from .checks import SIZES, check, element_count
from .scenes import STEEL, solve, steel_c0

# the punch case: a steel rod R 2.5 mm, L 100 mm (L = 20 D, slender: 1D theory holds) struck at 1 m/s
PUNCH = {"radius": 0.0025, "length": 0.1, "punch_length": 0.01, "speed": 1.0}
# the free-direction case: a rigid steel cylinder R 10 mm, L 40 mm spinning at 50 rad/s, launched across
# at 2 m/s under g = 9.81 m/s^2 and driven along its axis from rest to 3 m/s over half of 10 ms
FREE = {"radius": 0.01, "length": 0.04, "spin": 50.0, "across": 2.0, "g": 9.81, "speed": 3.0, "end_time": 0.01}


# the imported deck's case (``lsdyna_cases``, studies/lsdyna/rigid_punch.k): a rigid steel punch R 10 mm,
# 10 mm long, 0.05 mm above a steel rod R 10 mm, 60 mm long, driven down by a ramp to 5 m/s over 10 us
PUNCH_DECK = {"radius": 0.01, "length": 0.06, "punch_length": 0.01, "gap": 5e-5, "speed": 5.0, "ramp": 1e-5,
              "end_time": 4e-5}


def punch_deck_scene(h: float) -> dict:
    """The rigid punch of ``PUNCH_DECK`` in 3D at element size ``h`` [m], as a raw scene (the TOML form of
    ``studies/lsdyna/rigid_punch.k``)."""
    p = PUNCH_DECK
    T = p["end_time"]
    cylinder = {"material": "steel", "shape": "cylinder", "radius": p["radius"], "element_size": h}
    return {"scene": {"name": "rigid_punch", "kinematics": "3d", "end_time": T},
            "materials": {"steel": dict(STEEL)},
            "bodies": [{"name": "rod", **cylinder, "length": p["length"], "position": [0.0, 0.0, 0.0]},
                       {"name": "punch", **cylinder, "length": p["punch_length"], "rigid": True,
                        "position": [0.0, 0.0, p["length"] + p["gap"]]}],
            "boundary": [{"region": "punch", "type": "velocity", "direction": "z",
                          "history": [[0.0, 0.0], [p["ramp"], -p["speed"]], [T, -p["speed"]]]}],
            "contact": [{"name": "face", "a": "punch.bottom", "b": "rod.top"}],
            "outputs": {"field_interval": T, "history_interval": T / 100}}


def _punch_scene(size) -> dict:
    p = PUNCH
    h = 0.00025 * SIZES[size]
    end_time = 0.8 * p["length"] / steel_c0()       # the front stops short of the rod's far end
    v = -p["speed"]
    return {"scene": {"name": "rigid_punch", "kinematics": "axisymmetric", "end_time": end_time},
            "materials": {"steel": dict(STEEL)},
            "bodies": [{"name": "rod", "material": "steel", "shape": "cylinder", "radius": p["radius"],
                        "length": p["length"], "element_size": h},
                       {"name": "punch", "material": "steel", "shape": "cylinder", "radius": p["radius"],
                        "length": p["punch_length"], "element_size": h, "position": [0.0, p["length"]],
                        "velocity": v, "rigid": True}],
            "boundary": [{"region": "punch", "type": "velocity", "direction": "z", "value": v}],
            "contact": [{"name": "face", "a": "punch.bottom", "b": "rod.top", "penalty_scale": 1.0}],
            "outputs": {"field_interval": end_time, "history_interval": end_time / 100}}


def _rod_stress_plateau(solver, low: float, high: float) -> float:
    """The mean axial stress of the rod's cells whose centres lie in low < z < high [Pa]."""
    m = solver.model
    cells = m.kernel_cells
    zc = solver.x[m.dofmap[cells]].mean(axis=1)[:, -1]
    szz = solver.sigma[cells, :, 1].mean(axis=1)
    sel = (zc > low) & (zc < high)
    comm = m.comm
    return comm.allreduce(float(szz[sel].sum()), op=MPI.SUM) / comm.allreduce(int(sel.sum()), op=MPI.SUM)


def rigid_punch(size, workdir):
    """A rigid punch driven at a constant speed into an elastic rod: rho c0 v at the contact, and the drive's
    work the rod's energy (module docstring)."""
    p = PUNCH
    raw = _punch_scene(size)
    rows = []

    def probe(s):
        rows.append((s.t, s.reactions()[-1][1], s.rigid_states[0].velocity[1]))
    solver, wall = solve(raw, cache_dir=workdir, probe=probe)
    t, force, speed = np.array(rows).T
    c0, rho, v = steel_c0(), STEEL["density"], p["speed"]
    area = math.pi * p["radius"] ** 2
    t_end = solver.t
    # the plateau once the penalty has taken up the load (a few cells' transit) and before the end
    plateau = float(-force[(t > 0.25 * t_end) & (t < 0.95 * t_end)].mean())
    stress = _rod_stress_plateau(solver, p["length"] - 0.6 * c0 * t_end, p["length"] - 0.1 * c0 * t_end)
    e = solver.energy
    # the reported reaction times the prescribed velocity, integrated over the run (trapezoid on the steps)
    power = force * -v
    reported_work = float(np.sum(0.5 * (power[1:] + power[:-1]) * np.diff(t)))
    taken = e.kinetic - e.initial + e.internal + e.hourglass + e.contact + e.bulk_viscosity + e.damping
    n = element_count(solver)
    return [
        # 1D theory: a slender rod (R / L = 1/40) carries rho c0 v behind the front to well under 1%; the
        # penalty's rise and the front's ringing: measured +0.22% (force) and -0.11% (stress) at coarse size,
        # +0.21% and -0.44% at the default
        check("rigid_punch.drive_force [N]", rho * c0 * v * area, plateau, 0.02, wall, n),
        check("rigid_punch.rod_stress [Pa]", -rho * c0 * v, stress, 0.02, wall, n),
        # the drive's work against 1D theory's rho c0 A v^2 t: short by the penalty's rise at the start
        # (-0.43% at coarse size, -0.21% at the default)
        check("rigid_punch.drive_work [J]", rho * c0 * area * v ** 2 * t_end, e.external, 0.02, wall, n),
        # the energy account: the drive's work is what the rod and the contact took up (the balance)
        check("rigid_punch.work_vs_energy_taken [-]", taken, e.external, 0.01, wall, n),
        # the reaction the history reports, times the speed, integrated: the work the account counts, to the
        # trapezoid's error on the sampled force (every step here)
        check("rigid_punch.reported_reaction_work [J]", e.external, reported_work, 0.01, wall, n),
        # the punch keeps its prescribed speed to round-off
        check("rigid_punch.speed [m/s, abs]", 0.0, float(np.abs(speed[1:] + v).max()), 1e-12, wall, n,
              absolute=True),
    ]


def _free_scene(size) -> dict:
    f = FREE
    T = f["end_time"]
    return {"scene": {"name": "rigid_drive_free", "kinematics": "3d", "end_time": T, "max_time_step": T / 400,
                      "gravity": [-f["g"], 0.0, 0.0]},
            "materials": {"steel": dict(STEEL)},
            "bodies": [{"name": "block", "material": "steel", "shape": "cylinder", "radius": f["radius"],
                        "length": f["length"], "element_size": 0.005 * SIZES[size], "rigid": True,
                        "velocity": [f["across"], 0.0, 0.0], "spin": f["spin"]}],
            "boundary": [{"region": "block", "type": "velocity", "direction": "z",
                          "history": [[0.0, 0.0], [0.5 * T, f["speed"]], [T, f["speed"]]]}],
            "outputs": {"field_interval": T, "history_interval": T / 100}}


def rigid_drive_free(size, workdir):
    """A rigid cylinder driven along its axis, free across and free to turn (module docstring)."""
    f = FREE
    T = f["end_time"]
    reactions = []

    def probe(s):
        if 0.1 * T < s.t < 0.4 * T:
            reactions.append(s.reactions()[-1])
    solver, wall = solve(_free_scene(size), cache_dir=workdir, probe=probe)
    rb, rs = solver.model.rigid[0], solver.rigid_states[0]
    v, _ = solver.body_means()
    e = solver.energy
    gravity_work = rb.mass * -f["g"] * (rs.center[0] - rb.center0[0])
    omega = np.linalg.solve(rs.rotation @ rb.inertia0 @ rs.rotation.T, rs.momentum_angular)
    ramp = rb.mass * f["speed"] / (0.5 * T)
    n = element_count(solver)
    R = np.array(reactions)
    # each check is exact in the central difference (constant forces, a piecewise-linear drive): round-off
    return [
        check("rigid_drive_free.driven_speed [m/s]", f["speed"], v[0, 2], 1e-12, wall, n),
        check("rigid_drive_free.free_speed [m/s]", f["across"] - f["g"] * T, v[0, 0], 1e-9, wall, n),
        check("rigid_drive_free.spin [rad/s]", f["spin"], omega[2], 1e-9, wall, n),
        check("rigid_drive_free.drive_work [J]", 0.5 * rb.mass * f["speed"] ** 2, e.external - gravity_work, 1e-9,
              wall, n),
        check("rigid_drive_free.reaction [N]", ramp, float(R[:, 2].mean()), 1e-9, wall, n),
        check("rigid_drive_free.reaction_free_directions [N, abs]", 0.0, float(np.abs(R[:, :2]).max()), 1e-9,
              wall, n, absolute=True),
        check("rigid_drive_free.energy_balance [-, abs]", 0.0, e.balance_error, 1e-9, wall, n, absolute=True),
    ]

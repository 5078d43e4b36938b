"""Hard cases (``shockfem verify hard``): impacts that break explicit codes, each run as a user would set
it up (``run_scene``: the checks, the warnings, the stop on instability). Each must complete with its
energy balance within 1% and its conservation law, or stop with a diagnosis: a run that stops says why,
and the case reports that stop as its result (a check that fails) rather than a traceback.

* ``hard_fast_steel``: two equal elastic-plastic 4340 rods meeting at 500 m/s each way (1000 m/s closing,
  axisymmetric, fully integrated quads): far past yield at the face (plastic strain 3.6). One-point quads
  put five times the internal energy into hourglass control here (the run warns of it, so this case
  integrates fully); the default penalty lets the faces 50% of an element into each other, which the run
  warns of and this case expects: a stiffer penalty (2x, 3x, 5x) broke the energy balance (3%) or stopped
  the run as unstable, a limit of the contact's share of the stable step at this closing speed. Momentum
  along the axis is conserved (zero: equal and opposite).
* ``hard_mass_ratio``: a steel rod 1000 times heavier than the steel disc it strikes at 10 m/s: the
  heavy body's momentum passes to a light one through a contact of very unequal stiffness. Momentum.
* ``hard_soft_pad``: a striker on a polyurethane-foam pad on a steel target (three bodies, two contacts,
  stiffness ratio about 1e4). Momentum.
* ``hard_incompressible``: a rod of nu = 0.499 (bulk modulus 170 x shear) striking a rigid wall at
  10 m/s: its time step is set by the bulk wave. The rigid wall takes momentum: the check is the
  impulse the wall gave against the rod's momentum change.
* ``hard_thin_disc``: a 0.3 mm steel disc (radius 5 mm) struck face-on by a 5 mm steel rod at 50 m/s:
  an element a few tenths of a millimetre thick sets the step. Momentum.
* ``hard_long_slide``: a steel block pressed on a rigid floor by a 1e4 m/s^2 body force, sliding at
  50 m/s with Coulomb friction mu = 0.3 for 3 ms: it slows at mu g (closed form, within 2%).
* ``hard_fast_wall``: the copper Taylor bar (R 3.2 mm, L 32.4 mm, 0.8 mm quads) at 1000 m/s onto a rigid
  wall held as a constraint (``method = "constraint"``), 20 us. On a penalty wall (``penalty_scale = 1``) this run
  completes with nodes 3.6 mm behind the wall (the penalty lets go of a node deeper than a facet size);
  the constraint puts every node that would cross the wall on it: no node of the bar behind the wall,
  and the wall's impulse is the bar's momentum change (to round-off: each impulse is m (v - v_free)).
  One-point quads: full integration inverts an element at this speed (7.6 us here, 4.6 us on the penalty wall).
"""
from __future__ import annotations

import numpy as np
from mpi4py import MPI

from ..errors import UnstableRun
from ..runner import run_scene
from ..scene import resolve
from .checks import SIZES, check
from .scenes import STEEL

FOAM = {"library": "polyurethane_foam"}
STEEL_4340 = {"library": "steel_4340"}


def _rod(name, material, radius, length, h, z, v):
    return {"name": name, "material": material, "shape": "cylinder", "radius": radius, "length": length,
            "element_size": h, "position": [0.0, z], "velocity": [0.0, v]}


def _impact(name: str, end_time: float, history: float, materials: dict, bodies: list, contacts: list,
            **scene) -> dict:
    """An axisymmetric impact scene of ``bodies`` (``_rod``) touching through ``contacts``, as raw input."""
    return {"scene": {"name": name, "kinematics": "axisymmetric", "end_time": end_time, **scene},
            "materials": materials, "bodies": bodies, "contact": contacts,
            "outputs": {"history_interval": history}}


def _face(a: str, b: str) -> dict:
    """The contact of body ``a``'s bottom on body ``b``'s top."""
    return {"name": "face", "a": f"{a}.bottom", "b": f"{b}.top"}


def _run_result(raw: dict, workdir: str):
    """The run through ``run_scene``: (its ``RunResult``, None) or (None, the diagnosis)."""
    try:
        return run_scene(resolve(raw), workdir, progress=False, quiet=True, write_fields=False), None
    except UnstableRun as e:
        return None, e.diagnosis


def _run(raw: dict, workdir: str):
    """The run through ``run_scene``: (summary, history columns, None) or (None, None, the diagnosis)."""
    result, stop = _run_result(raw, workdir)
    if result is None:
        return None, None, stop
    h = {name: result.history.column(name) for name, _ in result.history.columns}
    return result.summary, h, None


def _stopped(case: str, diagnosis: str) -> list[dict]:
    """A run that stopped: one failing check that carries the diagnosis."""
    c = check(f"{case}.completed [-]", 1.0, 0.0, 0.0, 0.0, 0)
    c["note"] = f"stopped: {diagnosis}"
    return [c]


def _momentum(h: dict, masses: dict[str, float], axis: str = "z") -> np.ndarray:
    return sum(m * h[f"{b}.v_{axis}"] for b, m in masses.items())


def _conserved(case: str, raw: dict, workdir: str, scale_speed: float, expected: tuple[str, ...] = ()) -> list[dict]:
    """Energy balance within 1% and the bodies' total momentum along the axis kept (within 0.5% of the
    largest body's momentum at ``scale_speed``), and no warning but those ``expected`` (by their start)."""
    s, h, stop = _run(raw, workdir)
    if s is None:
        return _stopped(case, stop)
    masses = {b: s["bodies"][b]["mass"] for b in s["bodies"]}
    p = _momentum(h, masses)
    scale = max(masses.values()) * scale_speed
    wall, n = s["wall_time_s"], s["elements"]
    checks = [check(f"{case}.momentum_drift [-, abs, of the heaviest body's]", 0.0,
                    float(np.abs(p - p[0]).max()) / scale, 0.005, wall, n, absolute=True),
              check(f"{case}.energy_balance [-, abs]", 0.0, s["energy"]["balance_error"], 0.01, wall, n, absolute=True)]
    unexpected = [w for w in s.get("warnings", []) if not w.startswith(expected)]
    checks.append(check(f"{case}.unexpected_warnings [-]", 0.0, float(len(unexpected)), 0.0, wall, n, absolute=True))
    checks[-1]["note"] = _what_happened(s)
    return checks


def _what_happened(s: dict) -> str:
    """The run's extremes and warnings, for the report beside its checks."""
    strain = max(b["max_plastic_strain"] for b in s["bodies"].values())
    words = [f"{s['steps']} steps, largest plastic strain {strain:.3g}, plastic work "
             f"{s['energy']['plastic'] / max(s['energy']['initial_total'], 1e-300):.1%} of the initial energy"]
    return "; ".join(words + [f"warning: {w}" for w in s.get("warnings", [])])


def hard_fast_steel(size, workdir):
    """Two 4340 rods meeting at 500 m/s each way: momentum and energy through heavy plasticity."""
    h = 0.5e-3 * SIZES[size]
    raw = _impact("hard_fast_steel", 1.5e-5, 1e-7, {"steel": STEEL_4340},
                  [_rod("upper", "steel", 0.005, 0.02, h, 0.02 + 1e-5, -500.0),
                   _rod("lower", "steel", 0.005, 0.02, h, 0.0, 500.0)], [_face("upper", "lower")], integration="full")
    return _conserved("hard_fast_steel", raw, workdir, 500.0, expected=("contact face:",))


def hard_mass_ratio(size, workdir):
    """A rod 1000 times heavier than the disc it strikes: momentum through unequal bodies."""
    h = 1e-3 * SIZES[size]
    # rod R 10 mm x 100 mm (0.247 kg) on a disc R 5 mm x 0.4 mm (0.247 g)
    raw = _impact("hard_mass_ratio", 2e-5, 1e-7, {"steel": dict(STEEL)},
                  [_rod("heavy", "steel", 0.01, 0.1, h, 0.4e-3 + 1e-5, -10.0),
                   _rod("light", "steel", 0.005, 0.4e-3, 0.2e-3, 0.0, 0.0)], [_face("heavy", "light")])
    return _conserved("hard_mass_ratio", raw, workdir, 10.0)


def hard_soft_pad(size, workdir):
    """A striker on a foam pad on a steel target: momentum through a soft layer."""
    h = 1e-3 * SIZES[size]
    raw = _impact("hard_soft_pad", 4e-4, 1e-6, {"steel": dict(STEEL), "foam": FOAM},
                  [_rod("striker", "steel", 0.01, 0.05, h, 0.06 + 2e-5, -20.0),
                   _rod("pad", "foam", 0.01, 0.01, h, 0.05 + 1e-5, 0.0),
                   _rod("target", "steel", 0.01, 0.05, h, 0.0, 0.0)],
                  [dict(_face("striker", "pad"), name="upper"), dict(_face("pad", "target"), name="lower")])
    return _conserved("hard_soft_pad", raw, workdir, 20.0)


def hard_thin_disc(size, workdir):
    """A 0.3 mm disc struck face-on at 50 m/s by a rod: a fraction of a millimetre sets the step."""
    h = 1e-3 * SIZES[size]
    raw = _impact("hard_thin_disc", 3e-5, 1e-7, {"steel": dict(STEEL)},
                  [_rod("rod", "steel", 0.005, 0.05, h, 0.3e-3 + 1e-5, -50.0),
                   _rod("disc", "steel", 0.005, 0.3e-3, 0.15e-3, 0.0, 0.0)], [_face("rod", "disc")])
    return _conserved("hard_thin_disc", raw, workdir, 50.0)


def hard_incompressible(size, workdir):
    """A nu = 0.499 rod on a rigid wall at 10 m/s: the wall's impulse is the rod's momentum change."""
    h = 1e-3 * SIZES[size]
    rubbery = dict(STEEL, poisson_ratio=0.499)
    raw = _impact("hard_incompressible", 1e-4, 2e-7, {"nearly_incompressible": rubbery},
                  [_rod("rod", "nearly_incompressible", 0.005, 0.1, h, 1e-5, -10.0)],
                  [{"name": "wall", "a": "rod.bottom", "wall": {"point": [0.0, 0.0], "normal": [0.0, 1.0]}}])
    s, hist, stop = _run(raw, workdir)
    if s is None:
        return _stopped("hard_incompressible", stop)
    m = s["bodies"]["rod"]["mass"]
    change = m * (hist["rod.v_z"][-1] - hist["rod.v_z"][0])
    impulse = s["contacts"]["wall"]["impulse_on_a"][-1]
    wall, n = s["wall_time_s"], s["elements"]
    # the impulse is integrated as the central-difference update applies the force (``ContactPair.account``):
    # equal to round-off (3e-15 measured; 1e-9 leaves room for a longer sum, and catches a half step's force)
    return [check("hard_incompressible.wall_impulse_vs_momentum_change [N s]", change, impulse, 1e-9, wall, n),
            check("hard_incompressible.energy_balance [-, abs]", 0.0, s["energy"]["balance_error"], 0.01, wall, n,
                  absolute=True)]


def hard_fast_wall(size, workdir):
    """The copper Taylor bar at 1000 m/s on a constraint wall: no node behind it, impulse = momentum change."""
    h = 0.8e-3 * SIZES[size]
    raw = _impact("hard_fast_wall", 2e-5, 1e-7, {"copper": {"library": "copper"}},
                  [_rod("bar", "copper", 0.0032, 0.0324, h, 0.0, -1000.0)],
                  [{"name": "wall", "a": "bar.bottom", "wall": {"point": [0.0, 0.0], "normal": [0.0, 1.0]},
                    "method": "constraint"}])
    result, stop = _run_result(raw, workdir)
    if result is None:
        return _stopped("hard_fast_wall", stop)
    s, solver = result.summary, result.solver
    v = result.history.column("bar.v_z")
    change = s["bodies"]["bar"]["mass"] * (v[-1] - v[0])
    impulse = s["contacts"]["wall"]["impulse_on_a"][-1]
    behind = max(0.0, -float(solver.comm.allreduce(solver.x[:, 1].min(), op=MPI.MIN)))
    wall, n = s["wall_time_s"], s["elements"]
    checks = [check("hard_fast_wall.deepest_node_behind_the_wall [m, abs]", 0.0, behind, 1e-12, wall, n,
                    absolute=True),
              # each impulse is m (v - v_free) summed as applied: equal to round-off (1e-9 catches a half step)
              check("hard_fast_wall.wall_impulse_vs_momentum_change [N s]", change, impulse, 1e-9, wall, n),
              check("hard_fast_wall.energy_balance [-, abs]", 0.0, s["energy"]["balance_error"], 0.01, wall, n,
                    absolute=True)]
    checks[-1]["note"] = _what_happened(s)
    return checks


SLIDE = (0.3, 1e4, 50.0, 3e-3)          # mu, the pressing body force [m/s^2], speed [m/s], time [s]


def hard_long_slide(size, workdir):
    """A pressed steel block sliding 3 ms with friction: it slows at mu g."""
    mu, g, v0, end = SLIDE
    h = 2e-3 * SIZES[size]
    raw = {"scene": {"name": "hard_long_slide", "kinematics": "3d", "element": "hex", "end_time": end,
                     "gravity": [0.0, 0.0, -g]},
           "materials": {"steel": dict(STEEL)},
           "bodies": [{"name": "block", "material": "steel", "shape": "box", "size": [0.02, 0.02, 0.01],
                       "element_size": h, "position": [0.0, 0.0, 0.0], "velocity": [v0, 0.0, 0.0]}],
           "contact": [{"name": "floor", "a": "block.bottom", "wall": {"point": [0.0, 0.0, 0.0],
                                                                     "normal": [0.0, 0.0, 1.0]}, "friction": mu}],
           "outputs": {"history_interval": end / 300}}
    s, hist, stop = _run(raw, workdir)
    if s is None:
        return _stopped("hard_long_slide", stop)
    t, v = hist["time"], hist["block.v_x"]
    late = t > 0.2 * end                # clear of the block settling on the floor under its load
    decel = -np.polyfit(t[late], v[late], 1)[0]
    wall, n = s["wall_time_s"], s["elements"]
    return [check("hard_long_slide.deceleration [m/s^2]", mu * g, decel, 0.02, wall, n),
            check("hard_long_slide.energy_balance [-, abs]", 0.0, s["energy"]["balance_error"], 0.01, wall, n,
                  absolute=True)]


HARD = {"hard_fast_steel": hard_fast_steel, "hard_mass_ratio": hard_mass_ratio, "hard_soft_pad": hard_soft_pad,
        "hard_incompressible": hard_incompressible, "hard_thin_disc": hard_thin_disc,
        "hard_long_slide": hard_long_slide, "hard_fast_wall": hard_fast_wall}

"""A mass-chain scene, run at the fidelity its question needs.

A chain scene is a scene file with a ``[chain]`` table instead of ``[scene]``: the bodies are
listed in chain order (the first is launched, or sits on the anvil; the last is the test
article), without positions or velocities, which the chain sets:

    [chain]
    name = "three_mass"
    architecture = "launched-chain"   # or "stack-on-anvil"
    launch_speed = "10 m/s"           # of the first body, or of the whole stack
    fidelity = "1d"                   # rigid | 1d | axisymmetric | 3d (default rigid)
    gap = "1 mm"                      # launched chain: between neighbours (or a list, one per
                                      #   interface); stack: to the anvil
    restitution = 0.9                 # the rigid model's, every interface (or a list)
    damping = 0.02                    # structural damping ratio of every body (1d and finite elements)
    damping_type = "band"             # held from each body's first mode c0 / 2L to damping_band times
                                      #   it; or "stiffness": at the first mode, growing with frequency
    damping_band = 20                 # the band's high over low frequency
    end_time = "2 ms"                 # default: the last first-pass collision of a rigid chain
                                      #   at e = 0.2, plus three transits of the longest body
    pad_stiffness = "1.4 GN/m"        # optional: an elastic pad on every struck face (or a list,
                                      #   one per interface, 0 for none), met after the gap
    pad_thickness = "60 mm"           # its free thickness (or a list): the faces meet when it is
                                      #   crushed through (finite elements)
    pad_damping = 0.02                # the pads' damping ratio on the two bodies' reduced mass

    [launcher]                        # instead of launch_speed: the gas gun that fires the first
    bore = "12 in"                    #   body (or the whole stack), as in a launcher scene
    length = "6 ft"                   #   (shockfem/launcher/scene.py) without projectile_mass,
    reservoir_pressure = "2000 psi"   #   which the chain gives it; its muzzle velocity is the
    reservoir_volume = "20 ft**3"     #   launch speed, so the test article's speed follows from
                                      #   the tank pressure in one run

A pad sits on the struck face; the striker meets it after the gap.  ``rigid`` gives the
interface the restitution of rigid bodies on a spring-dashpot that never pulls
(``rigid.pad_restitution``);
``1d`` an interface spring (no thickness: it never bottoms); the finite elements a
compression-only spring and dashpot between the two faces, set the gap plus the pad's thickness
apart, that engages when the gap has closed, with the faces' contact as the stop should the pad
be crushed through.

Every fidelity writes the same ``summary.json`` (key ``chain``): which model ran, its wall
time, the stage table (``metrics/stages.py``), the gain, the pulse on the test article where
the fidelity has one, and the peak interface stress against each material's yield stress.

* ``rigid``: ``rigid.py``, restitution as given; interface stress from the 1D impedance
  estimate F = dv Z_a Z_b / (Z_a + Z_b), Z = rho c0 A, over the smaller face.
* ``1d``: ``bars.py``, each body a uniform bar of its length and its volume / length section;
  restitution emerges from the waves; interface stress from the low-passed contact force.
* ``axisymmetric`` / ``3d``: the finite-element solver (``runner.py``) on the bodies stacked along
  z, contact between neighbours, the same damping (each body's own, over its own band);
  von Mises peaks against yield.
"""
from __future__ import annotations

import json
import math
import os
import time
from dataclasses import dataclass

import numpy as np

from ..parts.catalog import PARTS
from ..metrics.stages import stage_table
from ..output.rundir import write_json_atomic
from ..scene import SceneError, resolve
from ..scene.checker import Checker
from ..units import G0
from . import rigid
from .interfaces import flat_face_stress, pad_dashpot, pad_peak_force, reduced_mass
from .bars import Bar, Interface, run_bars
from .gain import ARCHITECTURES

FIDELITIES = ("rigid", "1d", "axisymmetric", "3d")
CHAIN_FIELDS = ("name", "architecture", "launch_speed", "fidelity", "gap", "restitution", "damping", "damping_type",
                "damping_band", "end_time", "pad_stiffness", "pad_thickness", "pad_damping")
# The chain's structural damping: a band over each body's first DAMPING_BAND free-free modes, where a
# sharp impact puts its energy (``verify band_damping_modes`` checks 2% over 1:20), or stiffness-
# proportional at the first mode (LS-DYNA's *DAMPING_PART_STIFFNESS; overdamps the modes above).
DAMPING_TYPES = ("band", "stiffness")
DAMPING_BAND = 20.0
# The default end time follows a rigid chain this lossy, so a slower real chain still finishes.
TIMING_RESTITUTION = 0.2
# FE gaps in a stack shrink up the stack (the closed form's strike order) but stay resolvable.
STACK_SHRINK = 0.1


@dataclass
class ChainSpec:
    name: str
    architecture: str
    launch_speed: float
    fidelity: str
    gap: float
    restitution: tuple[float, ...]
    damping: float
    end_time: float | None
    pad_stiffness: tuple[float, ...] = ()   # per interface [N/m], 0: none
    pad_thickness: tuple[float, ...] = ()   # per interface [m]
    pad_damping: float = 0.02
    gaps: tuple[float, ...] = ()      # per interface of a launched chain, when given as a list [m]
    damping_type: str = "band"        # DAMPING_TYPES
    damping_band: float = DAMPING_BAND     # the band's high over low frequency
    launcher: dict | None = None      # the shot's summary and sizing when a [launcher] fired the chain
    shot: object = None               # and the shot itself (its histories)

    def pad(self, k: int) -> float:
        """Stiffness of interface k's pad [N/m] (0: plain contact)."""
        return self.pad_stiffness[k] if self.pad_stiffness else 0.0

    def pad_space(self, k: int) -> float:
        """The pad's thickness at interface k [m] (0: no pad)."""
        return self.pad_thickness[k] if self.pad(k) else 0.0

    def interface_gap(self, k: int) -> float:
        """Gap between bodies k and k + 1 [m]: ``gap`` (or its k-th value) in a launched chain; in a
        stack ``gap`` is the anvil's and the others shrink up the stack by STACK_SHRINK."""
        if self.architecture == "stack-on-anvil":
            return self.gap * STACK_SHRINK ** (k + 1)
        return self.gaps[k] if self.gaps else self.gap

    def rigid_restitution(self) -> tuple[float, ...]:
        """The rigid model's restitution per interface: as given, or its pad's."""
        return tuple(rigid.pad_restitution(self.pad_damping) if self.pad(k) else e
                     for k, e in enumerate(self.restitution))


def _spec(raw: dict, n: int, ck: Checker) -> ChainSpec:
    """The [chain] table of a chain of ``n`` bodies, read through the scene checker ``ck``."""
    c = ck.table(raw, "chain", "chain")
    ck.unknown(c, CHAIN_FIELDS, "chain")
    arch = ck.choice(c, "architecture", "chain", ARCHITECTURES, "launched-chain")
    fidelity = ck.choice(c, "fidelity", "chain", FIDELITIES, "rigid")
    interfaces = max(n - 1, 0)

    def per_interface(key, default, read):
        """One value for every interface, or a list of one per interface, each read by ``read(d, key)``."""
        given = c.get(key, default)
        values = given if isinstance(given, list) else [given] * interfaces
        if len(values) != interfaces:
            ck.fail(f"chain.{key}", f"one value or a list of {interfaces} (one per interface), got {given!r}")
            return (read({key: default}, key),) * interfaces
        return tuple(read({key: v}, key) for v in values)

    e = per_interface("restitution", 0.9, lambda d, k: ck.number(d, k, "chain", 0.9, 0.0, 1.0,
                                                                  "a coefficient of restitution", low_open=True))
    damping = ck.number(c, "damping", "chain", 0.02, 0.0, 0.5, "a damping ratio", high_open=True)
    damping_type = ck.choice(c, "damping_type", "chain", DAMPING_TYPES, "band")
    damping_band = ck.number(c, "damping_band", "chain", DAMPING_BAND, 1.0, 1000.0, "a frequency ratio",
                             low_open=True)
    if "launcher" in raw and "launch_speed" in c:
        ck.fail("chain.launch_speed", f"the [launcher] sets the launch speed; give one or the other, got "
                                      f"{c['launch_speed']}")
    speed = ck.quantity(c, "launch_speed", "chain", "velocity", 1.0 if "launcher" in raw else None, positive=True)
    pads = (per_interface("pad_stiffness", 0.0, lambda d, k: ck.quantity(d, k, "chain", "stiffness", 0.0,
                                                                          nonnegative=True))
            if "pad_stiffness" in c else ())
    thickness: tuple[float, ...] = ()
    if any(pads):
        if "pad_thickness" not in c:
            ck.fail("chain.pad_thickness", "missing (the pads' free thickness, e.g. \"50 mm\"; more than their "
                                           "compression, or the faces meet)")
        else:
            thickness = per_interface("pad_thickness", 0.0, lambda d, k: ck.quantity(d, k, "chain", "length", 0.0,
                                                                                      nonnegative=True))
            if any(k and not t for k, t in zip(pads, thickness)):
                ck.fail("chain.pad_thickness", f"every pad needs a thickness > 0, got {c['pad_thickness']!r}")
    pad_damping = ck.number(c, "pad_damping", "chain", 0.02, 0.0, 1.0, "a damping ratio", high_open=True)
    gaps: tuple[float, ...] = ()
    if isinstance(c.get("gap"), list):
        if arch != "launched-chain":
            ck.fail("chain.gap", f"a stack has one gap (to the anvil; the others shrink up the stack), got {c['gap']!r}")
        else:
            gaps = per_interface("gap", 1e-3, lambda d, k: ck.quantity(d, k, "chain", "length", 1e-3, positive=True))
    gap = gaps[0] if gaps else ck.quantity(c if not isinstance(c.get("gap"), list) else {}, "gap", "chain", "length",
                                           1e-3, positive=True)
    return ChainSpec(str(c.get("name", "chain")), arch, speed, fidelity, gap, e, damping,
                     ck.quantity(c, "end_time", "chain", "time", 0.0, nonnegative=True) or None,
                     pads if thickness else (), thickness, pad_damping, gaps, damping_type, damping_band)


def _height(body) -> float:
    """Extent of a catalogued part along its axis [m]."""
    zs = [p[1] for seg in PARTS[body.shape].profile(body.dims).segments() for p in (seg.start, seg.end)]
    return max(zs) - min(zs)


def fe_scene(raw: dict, spec: ChainSpec, kinematics: str, heights: list[float] | None = None,
             end_time: float = 1.0, frequencies: list[float] | None = None,
             masses: list[float] | None = None) -> dict:
    """The chain as an ordinary raw scene: bodies stacked along z, contact between neighbours;
    each body damped (``spec.damping`` of critical) over its own band from its first frequency in
    ``frequencies`` [Hz] (or stiffness-proportional at it) unless it has a damping of its own; the pads (with the
    bodies' ``masses`` for their dashpots) as compression-only springs across the gaps.

    Launched chain: the test article stands on z = 0, each heavier body above the next with the
    gap, the first moving down at the launch speed.  Stack on anvil: the first body above a rigid
    plane at z = 0 by the gap, the others above it with gaps shrinking up the stack, all falling."""
    bodies = [dict(b) for b in raw["bodies"]]
    n = len(bodies)
    gdim = 3 if kinematics == "3d" else 2
    heights = heights or [0.0] * n
    z = [0.0] * n
    if spec.architecture == "launched-chain":
        for k in range(n - 2, -1, -1):
            z[k] = z[k + 1] + heights[k + 1] + spec.interface_gap(k) + spec.pad_space(k)
        speeds = [-spec.launch_speed] + [0.0] * (n - 1)
    else:
        z[0] = spec.gap
        for k in range(1, n):
            z[k] = z[k - 1] + heights[k - 1] + spec.interface_gap(k - 1) + spec.pad_space(k - 1)
        speeds = [-spec.launch_speed] * n
    for b, zk, vk in zip(bodies, z, speeds):
        b["position"] = [0.0] * (gdim - 1) + [zk]
        b["velocity"] = [0.0] * (gdim - 1) + [vk]
    contacts = [{"name": f"{bodies[k]['name']}_{bodies[k + 1]['name']}", "a": f"{bodies[k]['name']}.bottom",
                 "b": f"{bodies[k + 1]['name']}.top"} for k in range(n - 1)]
    if spec.architecture == "stack-on-anvil":
        contacts = [{"name": f"anvil_{bodies[0]['name']}", "a": f"{bodies[0]['name']}.bottom",
                     "wall": {"point": [0.0] * gdim, "normal": [0.0] * (gdim - 1) + [1.0]}}] + \
                   [{"name": f"{bodies[k]['name']}_{bodies[k + 1]['name']}", "a": f"{bodies[k + 1]['name']}.bottom",
                     "b": f"{bodies[k]['name']}.top"} for k in range(n - 1)]
    out = {"scene": {"name": spec.name, "kinematics": kinematics, "end_time": end_time,
                     "element": "hex" if gdim == 3 else "quad"},
           "materials": raw.get("materials", {}), "bodies": bodies, "contact": contacts,
           "shock": {"test_articles": [bodies[-1]["name"]], "cfc": "none", **raw.get("shock", {})}}
    if "outputs" in raw:          # the field and history cadence of the finite-element runs
        out["outputs"] = raw["outputs"]
    if spec.damping and frequencies:
        for b, f in zip(bodies, frequencies):
            b.setdefault("damping", structural_damping(spec, f))
    if masses and any(spec.pad_stiffness):
        pairs = [c for c in contacts if "b" in c]          # the body-body interfaces, k = 0 .. n - 2
        # the spring's extension is the change of the faces' distance: nothing until the gap has
        # closed, then k per metre of the pad's compression (extrapolated beyond the table)
        out["spring"] = [{"name": _pad_name(c["name"]), "a": c["a"], "b": c["b"],
                          "curve": [[-gap - spec.pad_space(k), -spec.pad(k) * spec.pad_space(k)], [-gap, 0.0],
                                    [0.0, 0.0]],
                          "damping": pad_dashpot(spec.pad_damping, spec.pad(k), masses[k], masses[k + 1]),
                          "compression_only": True}
                         for k, c in enumerate(pairs) if spec.pad(k) for gap in [spec.interface_gap(k)]]
    return out


def structural_damping(spec: ChainSpec, first: float) -> dict:
    """The damping table of a chain body whose first free-free frequency is ``first`` [Hz]."""
    if spec.damping_type == "band":
        return {"type": "band", "ratio": spec.damping, "low": first, "high": spec.damping_band * first}
    return {"type": "stiffness", "ratio": spec.damping, "frequency": first}


def _damping_words(spec: ChainSpec) -> str:
    return (f"band over each body's first mode to {spec.damping_band:g} times it" if spec.damping_type == "band"
            else "stiffness-proportional at each body's first mode")


def _pad_name(interface: str) -> str:
    return f"pad_{interface}"


def first_frequencies(scene, heights: list[float]) -> list[float]:
    """Each body's first free-free longitudinal frequency as a bar, c0 / 2L [Hz]: where each body's
    structural damping starts (band) or is set (stiffness-proportional, which grows with frequency), so
    that a small stiff body is damped as much as a large one at its own first mode."""
    return [scene.material_of(b).c_bar / (2 * h) for b, h in zip(scene.bodies, heights)]


def resolve_chain(raw: dict, fidelity: str | None = None):
    """Check a chain scene; returns (spec, scene) with the scene resolved for the fidelity's
    kinematics (axisymmetric for rigid and 1d, whose bodies are parts of revolution)."""
    ck = Checker()
    bodies = raw.get("bodies")
    if not isinstance(bodies, list) or len(bodies) < 2:
        raise SceneError([f"bodies: a chain needs at least two [[bodies]] in chain order, got {bodies!r}"])
    ck.unknown(raw, ("chain", "materials", "bodies", "shock", "launcher", "outputs"), "")
    for i, b in enumerate(bodies):
        if not isinstance(b, dict):
            ck.fail(f"bodies[{i}]", f"must be a table, got {b!r}")
        elif not (isinstance(b.get("name"), str) and b["name"].isidentifier()):
            ck.fail(f"bodies[{i}].name", f"a chain body needs a name made of letters, digits and _, got "
                                         f"{b.get('name')!r}")
        for k in ("position", "velocity"):
            if isinstance(b, dict) and k in b:
                ck.fail(f"bodies[{i}].{k}", f"the chain sets it (launch_speed, gap); remove it, got {b[k]!r}")
        if isinstance(b, dict) and not (isinstance(b.get("shape"), str) and b["shape"] in PARTS):
            ck.fail(f"bodies[{i}].shape", f"a chain body is a part of revolution ({', '.join(PARTS)}), "
                                          f"got {b.get('shape')!r}")
    spec = _spec(raw, len(bodies), ck)
    if fidelity is not None:
        spec.fidelity = ck.choice({"--fidelity": fidelity}, "--fidelity", "", FIDELITIES)
    kinematics = spec.fidelity if spec.fidelity in ("axisymmetric", "3d") else "axisymmetric"
    scene = None
    if all(isinstance(b, dict) and isinstance(b.get("name"), str) for b in bodies):
        try:   # positions, velocities and contacts are generated: the rest is the user's, checked as a scene's
            scene = resolve(fe_scene(raw, spec, kinematics))
        except SceneError as e:
            ck.problems += e.problems
    ck.done()
    heights = [_height(b) for b in scene.bodies]
    if "launcher" in raw:
        _fire_launcher(raw, spec, _masses(scene))
    scene_raw = fe_scene(raw, spec, kinematics, heights, end_time=spec.end_time or 1.0,
                         frequencies=first_frequencies(scene, heights), masses=_masses(scene))
    return spec, resolve(scene_raw), heights


def _fire_launcher(raw: dict, spec: ChainSpec, masses: list[float]):
    """Fire the scene's gas gun with the first body (launched chain) or the whole stack as its
    projectile; its muzzle velocity becomes the chain's launch speed."""
    from ..launcher.gun import fire
    from ..launcher.output import sizing
    from ..launcher.scene import resolve_launcher
    launched = masses[0] if spec.architecture == "launched-chain" else sum(masses)
    name, gun, options = resolve_launcher(raw, projectile_mass=launched)
    shot = fire(gun)
    if not shot.left_barrel or shot.muzzle_velocity <= 0:
        raise SceneError([f"launcher: the gun does not fire the {launched:.5g} kg "
                          f"{'first body' if spec.architecture == 'launched-chain' else 'stack'}: {shot.note}"])
    try:
        size = sizing(gun, options)
    except ValueError as e:
        raise SceneError([f"launcher: ASME sizing: {e}"]) from None
    spec.launch_speed = shot.muzzle_velocity
    spec.launcher = {"name": name, **shot.summary(), "sizing": size}
    spec.shot = shot


def _masses(scene) -> list[float]:
    return [scene.material_of(b).rho * PARTS[b.shape].volume(b.dims, 3) for b in scene.bodies]


def _impedance_stress(scene, heights, stages, spec, masses) -> dict:
    """Rigid fidelity: the elastic interface stress of each collision from 1D impedances, or
    on a pad the peak force of rigid bodies on an undamped spring, dv sqrt(k M*)."""
    out = {}
    names = [b.name for b in scene.bodies]
    for s in stages:
        if s.struck == "wall":          # a rigid anvil: Z_b infinite, the stress is rho c0 dv
            mat = scene.material_of(scene.body(s.striker))
            out[s.pair] = abs(s.striker_before - s.struck_before) * mat.rho * mat.c_bar
            continue
        a, b = scene.body(s.striker), scene.body(s.struck)
        za, zb = [scene.material_of(x).rho * scene.material_of(x).c_bar * PARTS[x.shape].volume(x.dims, 3) / h
                  for x, h in ((a, heights[names.index(a.name)]), (b, heights[names.index(b.name)]))]
        area = min(PARTS[x.shape].volume(x.dims, 3) / heights[names.index(x.name)] for x in (a, b))
        k = min(names.index(a.name), names.index(b.name))
        dv = abs(s.striker_before - s.struck_before)
        out[s.pair] = (pad_peak_force(dv, spec.pad(k), reduced_mass(masses[k], masses[k + 1])) / area
                       if spec.pad(k) else flat_face_stress(dv, za, zb, area))
    return out


def _yield_of(key: str, yields: dict) -> float | None:
    """The lower yield stress of the bodies a peak-stress key names: a body, or an interface
    ``a_b`` (``anvil_b``); None when none of them yields (elastic materials)."""
    ys = [y for b, y in yields.items() if y and (b == key or b in key.split("_"))]
    return min(ys) if ys else None


def default_end_time(raw: dict) -> float:
    """The end time a chain scene runs to when it does not give one (``_default_end``)."""
    spec, scene, heights = resolve_chain(raw)
    return _default_end(spec, _masses(scene), heights, scene)


def parting_end_time(raw: dict) -> float:
    """An end time long enough for a lossy chain to part, for studies that read its final speeds: the
    default's rigid timing at e = 0.2, tripled (flat steel faces restitute less than that, and a stage
    that yields keeps pushing the next body after the default end)."""
    return 3 * default_end_time(raw)


def _default_end(spec, masses, heights, scene) -> float:
    """The last first-pass collision of a rigid chain with restitution 0.2 (real chains are
    slower than the assumed restitution makes them), plus three transits of the longest body."""
    import dataclasses
    transit = max(h / scene.material_of(b).c_bar for h, b in zip(heights, scene.bodies))
    timing = dataclasses.replace(spec, restitution=tuple(min(e, TIMING_RESTITUTION) for e in spec.restitution))
    r = _run_rigid_model(timing, masses, heights)
    last = max((c.time for c in r.collisions), default=0.0)
    # a pad's contact lasts half its period on the two masses, pi sqrt(M* / k)
    pads = sum(math.pi * math.sqrt(reduced_mass(masses[k], masses[k + 1]) / spec.pad(k))
               for k in range(len(masses) - 1) if spec.pad(k))
    return last + 3 * transit + max(spec.gaps or (spec.gap,)) / spec.launch_speed + 1.5 * pads


def _run_rigid_model(spec, masses, heights):
    if spec.architecture == "launched-chain":
        v = [spec.launch_speed] + [0.0] * (len(masses) - 1)
        return rigid.run_chain(masses, v, heights, [spec.interface_gap(k) for k in range(len(masses) - 1)],
                               spec.rigid_restitution())
    return rigid.run_chain(masses, [-spec.launch_speed] * len(masses), heights,
                           [spec.interface_gap(k) for k in range(len(masses) - 1)],
                           spec.rigid_restitution(), anvil=spec.restitution[0], anvil_gap=spec.gap)


def _rigid_history(result, names, interface_names) -> dict:
    """A history of the rigid model: velocities stepping at each collision, impulses as forces
    over one sample, in a run's column names (so the same stage table reads it)."""
    times = sorted({0.0} | {c.time for c in result.collisions})
    t = []
    for tc in times:
        t += [tc - 1e-12, tc + 1e-12] if tc > 0 else [0.0]
    t.append((times[-1] if times else 0.0) * 1.1 + 1e-9)
    t = np.array(t)
    v = np.tile(result.initial, (len(t), 1))
    f = np.zeros((len(t), len(interface_names)))
    for c in result.collisions:
        after = t > c.time
        if c.left >= 0:
            v[after, c.left] = c.after[0]
        v[after, c.right] = c.after[1]
        j = 0 if c.left < 0 else c.left + (1 if len(interface_names) == len(names) else 0)
        i = int(np.searchsorted(t, c.time))      # the sample just after the collision
        f[i - 1, j] = 1.0                         # the force on the sample just before it
    h = {"time": t, "energy.kinetic": 0.5 * (v ** 2) @ result.masses, "energy.internal": np.zeros(len(t))}
    for k, n in enumerate(names):
        h[f"{n}.v_z"] = v[:, k]
    for j, n in enumerate(interface_names):
        h[f"contact.{n}.normal_z"] = f[:, j]
    return h


def run_chain_scene(raw: dict, out_dir: str, fidelity: str | None = None, progress: bool = True,
                    echo=print, resume: bool = False) -> dict:
    """Run a chain scene at its fidelity (or ``fidelity``); writes ``out_dir/summary.json``.  ``resume``:
    continue its finite-element run from the checkpoint in ``out_dir`` (``runner.resume_run``)."""
    spec, scene, heights = resolve_chain(raw, fidelity)
    masses = _masses(scene)
    names = [b.name for b in scene.bodies]
    os.makedirs(out_dir, exist_ok=True)
    end_time = spec.end_time or _default_end(spec, masses, heights, scene)
    launch = spec.launch_speed
    stack = spec.architecture == "stack-on-anvil"
    if stack:
        contacts = [{"name": f"anvil_{names[0]}", "a": names[0], "b": None, "wall_velocity": 0.0}]
        contacts += [{"name": f"{names[k]}_{names[k + 1]}", "a": names[k + 1], "b": names[k]}
                     for k in range(len(names) - 1)]
    else:
        contacts = [{"name": f"{names[k]}_{names[k + 1]}", "a": names[k], "b": names[k + 1]}
                    for k in range(len(names) - 1)]
    iface_names = [c["name"] for c in contacts]
    t0 = time.perf_counter()
    pulse = None
    if spec.fidelity == "rigid":
        result = _run_rigid_model(spec, masses, heights)
        wall = time.perf_counter() - t0
        h = _rigid_history(result, names, iface_names)
        padded = (f" (pads: rigid bodies on a spring-dashpot that never pulls, zeta = {spec.pad_damping:g})"
                  if any(spec.pad_stiffness) else "")
        model = (f"rigid: event-driven rigid-body collisions, restitution "
                 f"{[round(e, 6) for e in spec.rigid_restitution()]}{padded}; "
                 f"{len(result.collisions)} collisions ({result.stopped})")
        stages = stage_table(h, dict(zip(names, masses)), contacts, "z", ("z",))
        stress = _impedance_stress(scene, heights, stages, spec, masses)
        stress_kind = ("elastic 1D impedance estimate dv Z_a Z_b / (Z_a + Z_b) over the smaller face; "
                       "on a pad dv sqrt(k M*) over it")
    elif spec.fidelity == "1d":
        bars = []
        for b, hgt in zip(scene.bodies, heights):
            mat = scene.material_of(b)
            pl = mat.plasticity
            sy = pl.yield_stress if pl else math.inf
            H = (pl.curve[-1][1] - pl.curve[0][1]) / (pl.curve[-1][0] - pl.curve[0][0]) if pl else 0.0
            v0 = (-launch if stack else (launch if b is scene.bodies[0] else 0.0))
            bars.append(Bar(b.name, hgt, PARTS[b.shape].volume(b.dims, 3) / hgt, mat.rho, mat.E, v0,
                            yield_stress=sy, hardening=H))
        gaps = [Interface(iface_names[k + 1 if stack else k], spec.interface_gap(k),
                          spec.pad(k) or None, spec.pad_damping if spec.pad(k) else 0.0)
                for k in range(len(bars) - 1)]
        r = run_bars(bars, gaps, end_time, damping_ratio=[b.damping.ratio if b.damping else 0.0 for b in scene.bodies],
                     damping_frequency=[b.damping.frequency if b.damping else 0.0 for b in scene.bodies],
                     damping_band=[(b.damping.low, b.damping.high) if b.damping and b.damping.kind == "band" else None
                                   for b in scene.bodies],
                     damping_reference=[b.damping.reference_frequency if b.damping and b.damping.kind == "band"
                                        else None for b in scene.bodies],
                     anvil_gap=spec.gap if stack else None)
        wall = r.wall_time_s
        h = r.history
        if stack:           # the anvil's force is not recorded; its impulse shows in body 1's velocity
            h[f"contact.{iface_names[0]}.normal_z"] = np.zeros(len(h["time"]))
        model = (f"1d: {sum(1 for _ in bars)} elastic{'-plastic' if any(b.yield_stress < math.inf for b in bars) else ''}"
                 f" bars, kinematic contact, structural damping {spec.damping:g} ({_damping_words(spec)}); {r.steps} steps, "
                 f"{r.element_cycles_per_s:.3g} element-cycles/s, energy balance {r.energy_balance_error:.1e}")
        stages = stage_table(h, r.masses, contacts, "z", ("z",))
        stress = dict(r.interface_stress)
        stress_kind = "peak contact force (low-passed over 4 element transits) over the smaller face"
    else:
        from ..runner import resume_run, run_scene
        scene = resolve(fe_scene(raw, spec, spec.fidelity, heights, end_time,
                                 frequencies=first_frequencies(scene, heights), masses=masses))
        if resume:
            res = resume_run(out_dir, progress=progress, quiet=not progress, scene=scene)
        else:
            res = run_scene(scene, out_dir, progress=progress, write_fields=True, quiet=not progress,
                            origin={"chain": raw, "fidelity": spec.fidelity})
        wall = res.summary["wall_time_s"]
        from ..output.history_file import read_history_csv
        h = read_history_csv(os.path.join(out_dir, "history.csv"))
        for c in scene.contacts:        # an interface's force: its contact's and its pad's
            pad = f"spring.{_pad_name(c.name)}.force_z"
            if pad in h:
                h[f"contact.{c.name}.normal_z"] = h[f"contact.{c.name}.normal_z"] + h[pad]
        model = "finite elements (" + spec.fidelity + "): " + "; ".join(m.strip() for m in res.summary["models"])
        fe_contacts = [{"name": c.name, "a": c.a, "b": c.b,
                        "wall_velocity": c.rigid.velocity[-1] if c.rigid else 0.0} for c in scene.contacts]
        stages = stage_table(h, {b: res.summary["bodies"][b]["mass"] for b in names}, fe_contacts, "z", ("z",))
        stress = {b: res.summary["bodies"][b]["max_von_mises"] for b in names}
        stress_kind = "largest von Mises stress in each body"
        pulse = (res.summary.get("shock") or {}).get("channels", {}).get(names[-1])
    last = names[-1]
    # the test article's speed when the record ends (it may have been struck more than once, or
    # pushed by a train of bodies that have not parted); whether any contact is still closed then
    final_speed = abs(float(h[f"{last}.v_z"][-1]))
    still_closed = any(s.end >= h["time"][-1] - 1e-12 for s in stages)
    summary_path = os.path.join(out_dir, "summary.json")
    # a finite-element run's summary gets the chain's results beside its own; the rigid and 1d models
    # write one of their own (a batch of chain runs reads each case's status from it)
    if spec.fidelity in ("rigid", "1d"):
        base = {"status": "completed", "wall_time_s": wall}
    else:
        with open(summary_path) as fh:
            base = json.load(fh)
    yields = {b.name: (scene.material_of(b).plasticity.yield_stress if scene.material_of(b).plasticity else None)
              for b in scene.bodies}
    chain = {
        "fidelity": spec.fidelity, "model": model, "architecture": spec.architecture,
        "launch_speed": launch, "wall_time_s": wall, "end_time": end_time,
        "masses": dict(zip(names, masses)), "lengths": dict(zip(names, heights)),
        "stages": [s.as_dict() for s in stages],
        "test_article_speed": final_speed, "gain": final_speed / launch,
        "contact_at_end": still_closed,
        "peak_stress": stress, "peak_stress_kind": stress_kind, "yield_stress": yields,
        "stress_over_yield": {k: v / _yield_of(k, yields) for k, v in stress.items() if _yield_of(k, yields)},
        "test_article_pulse": pulse,
        "launcher": spec.launcher,
    }
    write_json_atomic(summary_path, {**base, "chain": chain})
    if spec.launcher:
        from ..launcher.output import write_shot
        write_shot(os.path.join(out_dir, "launcher"), spec.shot, spec.launcher["sizing"])
        L = spec.launcher
        echo(f"launcher '{L['name']}': {L['model']}\n  fires {L['gun']['projectile_mass']:.5g} kg at "
             f"{launch:.5g} m/s from {L['gun']['reservoir_pressure'] / 1e6:.4g} MPa "
             f"(peak {L['peak_acceleration'] / G0:.4g} g, efficiency {L['efficiency']:.1%}); "
             f"barrel and tank {L['sizing']['total_weight']:.4g} kg")
    # a finite-element run with its progress shown has printed its model and its directory already
    runner_printed = spec.fidelity in ("axisymmetric", "3d") and progress
    echo(f"chain '{spec.name}', {spec.architecture}, fidelity {spec.fidelity}:"
         + (" (the model is the run's, above)" if runner_printed else "\n    " + model.replace("; ", "\n    ")))
    for s in stages:
        echo(f"  {s.pair:24s} {s.striker} {s.striker_before:+.4g} -> {s.striker_after:+.4g} m/s, {s.struck} "
             f"{s.struck_before:+.4g} -> {s.struck_after:+.4g} m/s, e = {s.restitution:.4f}")
    echo(f"  test article {last}: {final_speed:.5g} m/s at the end, gain {chain['gain']:.4f}; wall time {wall:.3g} s"
         + ("; NOTE: bodies still in contact when the run ended (set chain.end_time longer)" if still_closed else ""))
    for k, v in stress.items():
        y = _yield_of(k, yields)
        against = f", {v / y:.0%} of yield {y / 1e6:.4g} MPa" if y else ", elastic material (no yield given)"
        echo(f"  peak stress {k}: {v / 1e6:.4g} MPa{against} ({stress_kind})")
    if not runner_printed:
        echo(f"results in {out_dir}")
    return chain

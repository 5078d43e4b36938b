"""The preload stage (``[scene.preload]``): the assembly settles under its interference fits before the event.

An interference pushed out over its contact's ``interference`` time is a load: on bodies that nothing
else holds (the hoop-free segments of a split cone, say) it is a blow, and the event would start from
the motion it leaves.  The stage runs the solver from the scene's state with

* the event's bodies, those given an initial velocity or spin, held at rest (their velocities zeroed
  every step): they neither move nor load anything while the assembly settles;
* mass-proportional damping alpha = 4 pi f (critical at f, the assembly's lowest mode: ``frequency``, or
  c0 / 2L of the body with the lowest such estimate, c0 its bar speed and L its largest extent, in
  axisymmetry at least pi r_max for a ring's breathing), taken
  implicitly by the velocity update as the scene's own mass damping is (``nodal.update_velocity``:
  unconditionally stable, its work counted as damping), for the stage only.  Every mode then decays at
  least as fast as f's critically damped one (a mode of frequency f_k > f at alpha / 2; one below f,
  overdamped, at 2 pi f_k^2 / (2 f)), so the stage settles in a few periods of f whatever the mesh
  (dynamic relaxation, Underwood 1983, in Belytschko & Hughes, *Computational Methods for Transient
  Analysis*, ch. 5).  Kinetic damping (velocities zeroed at each peak of the kinetic energy) was tried
  first: under the penalty springs of a shrink fit, whose stable step alternates with the contact's, its
  resets grew the highest mode 40-fold a cycle.

It ends when every interference has come on and the kinetic energy is below ``kinetic_energy_ratio`` of the
elements' stored energy, or at ``duration``.  The event then starts from the settled
state with its own clock (t = 0) and the scene's initial velocities; its energy account goes on from the
stage's (what the stage's damping took is in ``damping``), so the balance holds from the stage's start through the
event.  Range of validity: a static preload (interference, gravity); a stage that ends unsettled says so in
the log and in ``summary.json`` (``preload.settled``).
"""
from __future__ import annotations

import math

import numpy as np
from mpi4py import MPI

from ..materials import layout


def _held_nodes(model) -> tuple[np.ndarray, list[int]]:
    """The nodes of the event's bodies (an initial velocity or spin) and the indices of their rigid states."""
    moving = [i for i, b in enumerate(model.bodies) if any(v != 0.0 for v in b.velocity) or b.spin]
    nodes = np.flatnonzero(np.isin(model.node_body, moving))
    rigid = [k for k, rb in enumerate(model.rigid) if rb.index in moving]
    return nodes, rigid


def _hold(solver, nodes: np.ndarray, rigid: list[int]) -> float:
    """Zero the held bodies' velocities; returns the kinetic energy they had (on this rank's owned nodes)."""
    owned = nodes[nodes < solver.model.num_owned]
    taken = 0.5 * float(np.dot(solver.model.mass[owned], (solver.v[owned] ** 2).sum(axis=1)))
    solver.v[nodes] = 0.0
    for k in rigid:
        solver.rigid_states[k].velocity[:] = 0.0
        solver.rigid_states[k].momentum_angular[:] = 0.0
    return taken


def stage_frequency(model, spec) -> float:
    """The frequency [Hz] the stage damps critically: ``spec.frequency``, else the lowest c0 / 2L over the
    deformable bodies (L the largest extent of a body's nodes, in axisymmetry at least pi r_max, c0 =
    sqrt(E / rho) its bar speed)."""
    if spec.frequency > 0.0:
        return spec.frequency
    lowest = math.inf
    for i, body in enumerate(model.bodies):
        if body.rigid:
            continue
        x = model.X0[model.node_body == i]
        local = (x.min(axis=0), x.max(axis=0)) if len(x) else (np.full(model.gdim, np.inf), np.full(model.gdim, -np.inf))
        lo = model.comm.allreduce(local[0], op=MPI.MIN)
        hi = model.comm.allreduce(local[1], op=MPI.MAX)
        extent = float((hi - lo).max())
        if model.axisymmetric:
            # a ring's breathing mode, c0 / (2 pi r): c0 / 2L with L = pi r
            extent = max(extent, math.pi * float(hi[0]))
        lam, mu, rho = (model.params[i, k] for k in (layout.P_LAMBDA, layout.P_MU, layout.P_RHO))
        young = mu * (3.0 * lam + 2.0 * mu) / (lam + mu)
        if extent > 0.0:
            lowest = min(lowest, math.sqrt(young / rho) / (2.0 * extent))
    return lowest if math.isfinite(lowest) else 0.0


def settle(solver, spec, log=print) -> dict:
    """Run the preload stage ``spec`` (a scene ``Preload``) on ``solver`` from its initial state and start
    the event from the settled state (module docstring).  Returns the stage's report for ``summary.json``."""
    nodes, rigid = _held_nodes(solver.model)
    e = solver.energy
    _hold(solver, nodes, rigid)
    # the stage starts at rest: the event's kinetic energy comes in when it starts
    e.initial = e.kinetic = 0.0
    ramp = max((c.spec.interference_time for c in solver.contacts), default=0.0)
    frequency = stage_frequency(solver.model, spec)
    alpha = 4.0 * math.pi * frequency                 # zeta = alpha / (2 omega) = 1 at the stage's frequency
    scene_alpha = solver.model.alpha
    solver.model.alpha = scene_alpha + alpha
    settled, kinetic, stored = False, 0.0, 0.0
    try:
        for step in solver.steps(spec.duration):
            taken = _hold(solver, nodes, rigid)
            e.damping += solver.comm.allreduce(taken) if solver.parallel else taken
            kinetic, stored = e.kinetic, e.internal
            if solver.t >= ramp and kinetic <= spec.kinetic_energy_ratio * max(stored, 1e-300):
                settled = True
                break
    finally:
        solver.model.alpha = scene_alpha
    stage_time, steps = solver.t, solver.step
    # the event from the settled state: its clock, its initial velocities
    e.damping += e.kinetic
    solver.start_event()
    e.initial = e.kinetic
    report = {"settled": settled, "time": stage_time, "steps": steps, "frequency": frequency, "alpha": alpha,
              "kinetic_energy": kinetic, "stored_energy": stored, "held_bodies":
              [solver.model.bodies[i].name for i in sorted(set(solver.model.node_body[nodes].tolist()))],
              "kinetic_energy_ratio": spec.kinetic_energy_ratio, "units": "s, Hz, 1/s, J"}
    said = (f"preload stage: {'settled' if settled else 'NOT settled'} in {stage_time:.4g} s ({steps} steps, mass "
            f"damping {alpha:.4g} 1/s, critical at {frequency:.4g} Hz; kinetic energy {kinetic:.3g} J against "
            f"{stored:.4g} J stored); the event starts from it at t = 0")
    log(said if settled else "WARNING: " + said + f": lengthen scene.preload.duration ({spec.duration:.4g} s)")
    # kept with the solver's state, so that a run resumed from a checkpoint of its event still reports it
    solver.preload_report = report
    return report

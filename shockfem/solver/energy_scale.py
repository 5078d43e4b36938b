"""The energy a run will put in play, known before its first step: the scale of its energy checks.

A run that starts at rest has no energy at t = 0; its drive or its preload brings energy in over the
first steps.  Measured against the energy in play so far, the balance's start-up error (the half-step
account of a force that switches on, of the order of the first steps' work) reads as tens of percent,
though it stays flat at a few nJ while the run takes up joules.  Against the energy the run will
take up, known at t = 0, it reads as what it is.  Each term below is an order of magnitude (within a few
times of the energy the run takes up), never a bound:

* the initial kinetic energy (the account's own ``initial``);
* a prescribed velocity (of a region, or of a rigid body's centre): the kinetic energy of the body it
  drives at the history's largest speed, 0.5 M v_max^2 (a body pushed from rest at v takes up at least that much before it is brought to speed);
* a contact's interference (pushed out as a preload): the elastic energy of the fit,
  0.5 sum_i A_i d_i^2 / (L_a / K_a + L_b / K_b), each node's overlap d_i over its area A_i squeezed into
  the two bodies in series, each a spring of bulk modulus K over its size L (the smallest side of its box).
  For a steel ring of 20 mm wall on a 20 mm steel shaft at 0.02 mm this gives 2.2 J against Lame's
  0.5 p delta A = 2.0 J.

Loads given as forces are not in it: their work depends on how far the body moves, which only the run
tells.
"""
from __future__ import annotations

import numpy as np
from mpi4py import MPI

from ..model import Model


def drive_energy(model: Model) -> float:
    """0.5 M v_max^2 summed over the bodies a prescribed velocity drives [J] (M the body's mass, v_max
    the largest speed any of its prescribed-velocity conditions reaches).  Collective."""
    gdim = model.gdim
    v_max = np.zeros(len(model.bodies))
    for c in model.constraints:
        speed = float(np.abs(c.values).max(initial=0.0))
        if speed == 0.0 or not len(c.dofs):
            continue
        bodies = np.unique(model.node_body[c.dofs // gdim])
        v_max[bodies[bodies >= 0]] = np.maximum(v_max[bodies[bodies >= 0]], speed)
    if model.comm.size > 1:
        model.comm.Allreduce(MPI.IN_PLACE, v_max, op=MPI.MAX)
    for rb in model.rigid:          # a driven rigid body (the same on every rank)
        for drive in rb.drives:
            v_max[rb.index] = max(v_max[rb.index], float(np.abs(drive.values).max(initial=0.0)))
    return float(0.5 * np.sum(model.body_mass * v_max ** 2))


def body_sizes(model: Model) -> np.ndarray:
    """Each body's smallest side of its bounding box at t = 0 [m].  Collective."""
    n = len(model.bodies)
    low = np.full((n, model.gdim), np.inf)
    high = np.full((n, model.gdim), -np.inf)
    for i in range(n):
        x = model.X0[model.node_body == i]
        if len(x):
            low[i], high[i] = x.min(axis=0), x.max(axis=0)
    if model.comm.size > 1:
        model.comm.Allreduce(MPI.IN_PLACE, low, op=MPI.MIN)
        model.comm.Allreduce(MPI.IN_PLACE, high, op=MPI.MAX)
    return np.where(np.isfinite(high - low), high - low, 0.0).min(axis=1)


def interference_energy(model: Model, contacts) -> float:
    """The elastic energy the contacts' interferences will store (module docstring) [J].  Collective."""
    sizes = None
    total = 0.0
    for pair in contacts:
        areas, depths = pair.interference_overlaps()
        fit = float(np.sum(areas * depths ** 2))
        if model.comm.size > 1:
            fit = model.comm.allreduce(fit, op=MPI.SUM)
        if fit == 0.0:
            continue
        sizes = body_sizes(model) if sizes is None else sizes
        # each side a spring L / K per unit area in series; a rigid side is not one
        compliance = sum(sizes[s.body] / float(np.mean(s.bulk)) for s in pair.surfaces()
                         if not model.bodies[s.body].rigid)
        if compliance > 0.0:
            total += 0.5 * fit / compliance
    return total


def energy_scale(model: Model, contacts, initial_kinetic: float) -> float:
    """The energy the run will put in play, known at t = 0 (module docstring) [J].  Collective."""
    return max(initial_kinetic, drive_energy(model), interference_energy(model, contacts))

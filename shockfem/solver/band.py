"""Band (frequency-range) damping in the time loop: Maxwell terms on the nodal internal force.

Each body with ``damping.type = "band"`` gets the Maxwell terms of ``materials/band_damping.py``
(their relaxation times and weights fitted to its ratio and band).  They act on the body's own
deformation through the internal force: for a linear body f_int = K u, so driving each term with
the increment of f_int over the step,

    r_k(n+1) = exp(-dt / tau_k) r_k(n) + g_k (tau_k / dt)(1 - exp(-dt / tau_k)) (f_int(n+1) - f_int(n)),

gives the force r_k = g_k K q_k of a spring g_k K in series with a dashpot g_k tau_k K, q_k the
spring's stretch, filtered from the displacement increments alike; the nodes feel f_int + sum_k r_k.
No element pass is needed, a rigid-body translation (f_int unchanged) is never damped, and where
the material yields the terms follow its tangent stiffness (the plastic increments of f_int are small).
The terms see the whole internal force: the hourglass forces of one-point elements and the bulk
viscosity's are damped and stiffened alike (by the same few percent as the elastic forces).
Energy: the terms' work sum_k r_k . du over the step (trapezoidal, as the solver's internal work)
less the change of what their springs store, 0.5 sum_k q_k . r_k, is what their dashpots
dissipated: the damping energy.  Far above the band each term is a spring in parallel with K: the
stable step is shortened by ``BandTerms.step_factor``.
"""
from __future__ import annotations

import numpy as np
from numba import njit

from ..materials.band_damping import BandTerms, decay_and_gain, fit_band, maxwell_update


@njit(cache=True, fastmath=True)
def add_band_forces(f_int, u, nodes, num_owned, f_prev, u_prev, r, q, decay, gain, weight):
    """Advance the Maxwell terms ``r``, ``q`` (len(nodes), gdim, terms) of ``nodes`` over a step with the
    new ``f_int`` and ``u`` (their values a step earlier in ``f_prev``, ``u_prev``, updated here) and add
    sum_k r_k to ``f_int``.  Returns the terms' work over the step, 0.5 (R_n + R_n+1) . du, and what their
    springs store after it, 0.5 sum_k q_k . r_k [J], over the owned nodes (module docstring)."""
    terms = decay.shape[0]
    gdim = f_int.shape[1]
    work = 0.0
    stored = 0.0
    for j in range(nodes.shape[0]):
        n = nodes[j]
        owned = 1.0 if n < num_owned else 0.0
        for i in range(gdim):
            df = f_int[n, i] - f_prev[j, i]
            du = u[n, i] - u_prev[j, i]
            f_prev[j, i] = f_int[n, i]
            u_prev[j, i] = u[n, i]
            before = 0.0
            after = 0.0
            kept = 0.0
            for k in range(terms):
                before += r[j, i, k]
                rk, qk = maxwell_update(r[j, i, k], q[j, i, k], df, du, decay[k], gain[k], weight[k])
                r[j, i, k] = rk
                q[j, i, k] = qk
                after += rk
                kept += qk * rk
            f_int[n, i] += after
            work += owned * 0.5 * (before + after) * du
            stored += owned * 0.5 * kept
    return work, stored


class BandGroup:
    """The nodes of the bodies that share one band damping, with their terms' state."""

    def __init__(self, terms: BandTerms, nodes: np.ndarray, f_int: np.ndarray, u: np.ndarray):
        self.terms = terms
        self.nodes = nodes.astype(np.int64)
        self.tau = np.array(terms.tau)
        self.weight = np.array(terms.weight)
        # the terms innermost: a node's terms are updated together, from one cache line
        shape = (len(nodes), f_int.shape[1], len(terms.tau))
        self.r = np.zeros(shape)
        self.q = np.zeros(shape)
        self.f_prev = f_int[nodes].copy()
        self.u_prev = u[nodes].copy()
        self.stored = 0.0                  # what the terms' springs hold on this rank's owned nodes [J]

    def step(self, f_int: np.ndarray, u: np.ndarray, dt: float, num_owned: int) -> float:
        """Add the terms' forces to ``f_int`` after a step ``dt``; returns what they dissipated [J]."""
        decay, gain = decay_and_gain(self.tau, dt)
        work, stored = add_band_forces(f_int, u, self.nodes, num_owned, self.f_prev, self.u_prev, self.r, self.q,
                                       decay, gain, self.weight)
        dissipated = work - (stored - self.stored)
        self.stored = stored
        return dissipated


class BandDamping:
    """Every band-damped body of a model: ``step`` after each internal force, ``step_factor`` on the
    stable step.  None of it when no body has a band (``of``)."""

    def __init__(self, groups: list[BandGroup]):
        self.groups = groups

    @classmethod
    def of(cls, model, f_int: np.ndarray, u: np.ndarray) -> "BandDamping | None":
        bands: dict = {}
        for i, (body, d) in enumerate(zip(model.bodies, model.body_damping)):
            if d is not None and d.kind == "band" and not body.rigid:
                bands.setdefault((d.ratio, d.low, d.high), []).append(i)
        if not bands:
            return None
        groups = [BandGroup(fit_band(*key), np.flatnonzero(np.isin(model.node_body, ids)), f_int, u)
                  for key, ids in bands.items()]
        return cls(groups)

    @property
    def step_factor(self) -> float:
        """The smallest share of the stable step the groups leave (applied to the whole mesh)."""
        return min(g.terms.step_factor for g in self.groups)

    @property
    def stored(self) -> float:
        """What the terms' springs hold on this rank [J] (part of the stored energy)."""
        return sum(g.stored for g in self.groups)

    def step(self, f_int: np.ndarray, u: np.ndarray, dt: float, num_owned: int) -> float:
        """Add every group's forces to ``f_int``; returns what they dissipated over the step on this rank [J]."""
        return sum(g.step(f_int, u, dt, num_owned) for g in self.groups)

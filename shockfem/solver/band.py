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
A rigid rotation turns a stressed body's nodal forces without deforming it: in 3D and plane strain the
terms therefore live in each body's co-rotating frame (its best-fit rotation R about its centre of
mass, Kabsch's least squares, every step), driven by R^T f_int and by the deformation
R^T (x - c) - (X - c0), their force turned back by R (``BandGroup``): a spinning body is not damped.
Within a body the frame is one rotation: parts of a body turning against each other (a flexible arm)
still drive the terms by their relative rotation.
Yielding: the terms act beside the material, so what they took up during a cell's elastic rise is carried
past its yield surface while they relax.  The 1D bars (``amplifier/bars.py``) hold their terms per element
and let them go where an element yields; here the terms are nodal forces, the divergence of the cells'
Maxwell stresses, and cannot be let go cell by cell: releasing them at the nodes of the cells that yielded
in a step made two steel rods yielding at 300 MPa (20 m/s, 2% over [f1, 20 f1]) rebound at 0.576 against
0.522 kept and 0.498 undamped.  Holding the terms per cell, in the element pass, is the way to it.
The terms see the whole internal force: the hourglass forces of one-point elements and the bulk
viscosity's are damped and stiffened alike (by the same few percent as the elastic forces).
Energy: the terms' work sum_k r_k . du over the step (trapezoidal, as the solver's internal work)
less the change of what their springs store, 0.5 sum_k q_k . r_k, is what their dashpots
dissipated: the damping energy.  Far above the band each term is a spring in parallel with K: the
stable step is shortened by ``BandTerms.step_factor``.
"""
from __future__ import annotations

import numpy as np
from mpi4py import MPI
from numba import njit

from ..materials.band_damping import BandTerms, decay_and_gain, fit_band, maxwell_update


@njit(cache=True, fastmath=True)
def add_band_forces(f_int, u, X, nodes, slot, rot, rot_prev, centre, centre0, rotating, num_owned,
                    f_prev, d_prev, u_prev, r, q, decay, gain, weight):
    """Advance the Maxwell terms ``r``, ``q`` (len(nodes), gdim, terms) of ``nodes`` over a step with the
    new ``f_int`` and ``u`` and add their forces to ``f_int``.  With ``rotating``, node j's body (``slot[j]``)
    turned by ``rot`` (gdim, gdim) about its centre ``centre`` from ``centre0`` (``body_frames``): the terms
    see the force R^T f and the deformation R^T (x - c) - (X - c0) in the body's frame; without, the global
    force and ``u``.  ``f_prev``, ``d_prev`` (the frame's values a step earlier) and ``u_prev`` are updated
    here; ``rot_prev`` is the frame a step earlier.  Returns the terms' work over the step,
    0.5 (R_n r_n + R_n+1 r_n+1) . du (du the global displacement increment, as the solver's internal work),
    and what their springs store after it, 0.5 sum_k q_k . r_k [J], over the owned nodes."""
    terms = decay.shape[0]
    gdim = f_int.shape[1]
    work = 0.0
    stored = 0.0
    fb = np.empty(gdim)
    db = np.empty(gdim)
    before = np.empty(gdim)
    after = np.empty(gdim)
    for j in range(nodes.shape[0]):
        n = nodes[j]
        b = slot[j]
        owned = 1.0 if n < num_owned else 0.0
        for i in range(gdim):
            if rotating:
                fi = 0.0
                di = 0.0
                for k in range(gdim):
                    fi += rot[b, k, i] * f_int[n, k]
                    di += rot[b, k, i] * (X[n, k] + u[n, k] - centre[b, k])
                fb[i] = fi
                db[i] = di - (X[n, i] - centre0[b, i])
            else:
                fb[i] = f_int[n, i]
                db[i] = u[n, i]
        for i in range(gdim):
            df = fb[i] - f_prev[j, i]
            dd = db[i] - d_prev[j, i]
            f_prev[j, i] = fb[i]
            d_prev[j, i] = db[i]
            before[i] = 0.0
            after[i] = 0.0
            kept = 0.0
            for k in range(terms):
                before[i] += r[j, i, k]
                rk, qk = maxwell_update(r[j, i, k], q[j, i, k], df, dd, decay[k], gain[k], weight[k])
                r[j, i, k] = rk
                q[j, i, k] = qk
                after[i] += rk
                kept += qk * rk
            stored += owned * 0.5 * kept
        for i in range(gdim):
            if rotating:
                a = 0.0
                p = 0.0
                for k in range(gdim):
                    a += rot[b, i, k] * after[k]
                    p += rot_prev[b, i, k] * before[k]
            else:
                a = after[i]
                p = before[i]
            f_int[n, i] += a
            work += owned * 0.5 * (p + a) * (u[n, i] - u_prev[j, i])
            u_prev[j, i] = u[n, i]
    return work, stored


def best_rotation(h: np.ndarray) -> np.ndarray:
    """The rotation R that maximises tr(R H) for the covariance H = sum m (X - c0)(x - c)^T: the least-squares
    rigid rotation taking the reference onto the current positions (Kabsch 1976, Acta Cryst. A32, 922)."""
    if h.shape[0] == 2:
        # tr(R H) = cos(t) (H00 + H11) + sin(t) (H01 - H10)
        t = np.arctan2(h[0, 1] - h[1, 0], h[0, 0] + h[1, 1])
        c, s = np.cos(t), np.sin(t)
        return np.array([[c, -s], [s, c]])
    left, _, right_t = np.linalg.svd(h)
    d = np.sign(np.linalg.det(right_t.T @ left.T)) or 1.0
    return right_t.T @ np.diag([1.0, 1.0, d]) @ left.T


class BandGroup:
    """The nodes of the bodies that share one band damping, with their terms' state.

    A body's rigid rotation turns its nodal forces: driven by them in the global frame, the terms of a
    stressed spinning body would see a force that changes while the body does not deform, and damp the
    spin (a free steel rotor of 20 mm at 2000 rad/s, with 2% over 100 Hz to 2 kHz, lost 35% of its kinetic
    energy in a revolution).  So in 3D and plane strain each body's terms live in its co-rotating frame:
    its best-fit rotation R about its centre of mass from the reference positions (``best_rotation``,
    every step), the terms driven by R^T f_int and by the deformation R^T (x - c) - (X - c0), their force
    turned back by R.  In an axisymmetric model a body has no rigid rotation (and a translation along the
    axis leaves f_int unchanged): the terms stay in the global frame.
    """

    NOT_STATE = ("comm", "X", "mass", "_owned_frames")

    def __init__(self, terms: BandTerms, nodes: np.ndarray, slot: np.ndarray, model, f_int: np.ndarray,
                 u: np.ndarray):
        self.terms = terms
        self.nodes = nodes.astype(np.int64)
        self.slot = slot.astype(np.int64)
        self.tau = np.array(terms.tau)
        self.weight = np.array(terms.weight)
        self.X = model.X0
        self.mass = model.mass
        self.comm = model.comm
        self.num_owned = model.num_owned
        self.rotating = not model.axisymmetric
        gdim = f_int.shape[1]
        bodies = int(self.slot.max()) + 1 if len(self.slot) else 1
        # the terms innermost: a node's terms are updated together, from one cache line
        shape = (len(nodes), gdim, len(terms.tau))
        self.r = np.zeros(shape)
        self.q = np.zeros(shape)
        self.centre0 = np.zeros((bodies, gdim))
        self.sums = np.zeros((bodies, 1 + gdim + gdim * gdim))
        self.rot = np.tile(np.eye(gdim), (bodies, 1, 1))
        self.centre = np.zeros((bodies, gdim))
        if self.rotating:
            self._owned_frames = self._frame_parts(np.zeros(bodies))
            self.centre0[:] = self._frames(np.zeros_like(u))[1]      # the reference centres of mass
            self._owned_frames = self._frame_parts(self.centre0)
            self.rot[:], self.centre[:] = self._frames(u)
        self.rot_prev = self.rot.copy()
        self.f_prev = np.zeros((len(nodes), gdim))
        self.d_prev = np.zeros((len(nodes), gdim))
        self.u_prev = u[nodes].copy()
        self._into_frame(f_int, u)
        self.stored = 0.0                  # what the terms' springs hold on this rank's owned nodes [J]

    def _frame_parts(self, centre0: np.ndarray) -> list:
        """Per body slot: its owned nodes, their masses and m (X - c0) (constant: the covariance's left side)."""
        parts = []
        for b in range(self.rot.shape[0]):
            own = self.nodes[(self.slot == b) & (self.nodes < self.num_owned)]
            m = self.mass[own]
            parts.append((own, m, m[:, None] * (self.X[own] - np.atleast_1d(centre0[b]))))
        return parts

    def _frames(self, u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Each body's best-fit rotation and centre of mass at displacement ``u``: from the owned nodes'
        sums M, sum m (x - c0) and the covariance sum m (X - c0)(x - c0)^T (= sum m (X - c0)(x - c)^T, since
        sum m (X - c0) = 0), reduced over the ranks.  Collective."""
        gdim = u.shape[1]
        for b, (own, m, weighted) in enumerate(self._owned_frames):
            x = self.X[own] + u[own] - self.centre0[b]
            self.sums[b, 0] = m.sum()
            self.sums[b, 1:1 + gdim] = m @ x
            self.sums[b, 1 + gdim:] = (weighted.T @ x).ravel()
        sums = self.comm.allreduce(self.sums, op=MPI.SUM) if self.comm.size > 1 else self.sums
        mass = np.maximum(sums[:, 0], 1e-300)
        centre = self.centre0 + sums[:, 1:1 + gdim] / mass[:, None]
        rot = np.array([best_rotation(h.reshape(gdim, gdim)) for h in sums[:, 1 + gdim:]])
        return rot, centre

    def _into_frame(self, f_int: np.ndarray, u: np.ndarray) -> None:
        """Start the terms from the current force and deformation (nothing stored, nothing moved)."""
        if self.rotating:
            for b in range(self.rot.shape[0]):
                mine = self.slot == b
                n = self.nodes[mine]
                self.f_prev[mine] = f_int[n] @ self.rot[b]
                self.d_prev[mine] = (self.X[n] + u[n] - self.centre[b]) @ self.rot[b] - (self.X[n] - self.centre0[b])
        else:
            self.f_prev[:] = f_int[self.nodes]
            self.d_prev[:] = u[self.nodes]

    def step(self, f_int: np.ndarray, u: np.ndarray, dt: float, num_owned: int) -> float:
        """Add the terms' forces to ``f_int`` after a step ``dt``; returns what they dissipated [J].  Collective
        in 3D and plane strain (the bodies' frames)."""
        decay, gain = decay_and_gain(self.tau, dt)
        if self.rotating:
            self.rot_prev[:] = self.rot
            self.rot[:], self.centre[:] = self._frames(u)
        work, stored = add_band_forces(f_int, u, self.X, self.nodes, self.slot, self.rot, self.rot_prev,
                                       self.centre, self.centre0, self.rotating, num_owned, self.f_prev,
                                       self.d_prev, self.u_prev, self.r, self.q, decay, gain, self.weight)
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
        groups = []
        for key, ids in bands.items():
            nodes = np.flatnonzero(np.isin(model.node_body, ids))
            # each node's body as a slot of the group (its own frame, BandGroup)
            slot = np.searchsorted(np.array(ids), model.node_body[nodes])
            groups.append(BandGroup(fit_band(*key), nodes, slot, model, f_int, u))
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

"""Contact pairs at run time: search, penalty forces, and what each pair reports.

A pair is two surfaces (two-pass: the nodes of each against the segments of the other, so
neither side is privileged) or one surface against a rigid plane.  The search finds, for
every slave node, the master segments within reach (a KD-tree on segment midpoints) and is
refreshed only when some node of the pair has travelled half the search margin since the
last search; while the bounding boxes of the two surfaces are further apart than the margin
the pair costs nothing but the box test.  Penetrations present at the start are reported
and not pushed out: each slave node's initial penetration is its zero (LS-DYNA's IGNORE=1),
released as the node comes out.
"""
from __future__ import annotations

import math

import numpy as np
from scipy.spatial import cKDTree

from ..errors import ModelError
from ..model import Model
from ..scene.schema import Contact
from ..solver.kernels import P_LAMBDA, P_MU
from . import kernels
from .surfaces import Surface, build_surface

TWO_PI = 2.0 * math.pi


def _cell_volumes(model: Model, cells: np.ndarray) -> np.ndarray:
    """Volumes of 2D cells in the reference configuration, with the 2 pi r or thickness weight."""
    X = model.X0
    nodes = model.dofmap[cells]
    if nodes.shape[1] == 4:
        nodes = nodes[:, [0, 1, 3, 2]]           # tensor order -> around
    p = X[nodes]
    x, y = p[..., 0], p[..., 1]
    area = 0.5 * np.abs(np.sum(x * np.roll(y, -1, axis=1) - np.roll(x, -1, axis=1) * y, axis=1))
    return area * _weight(model, p[..., 0].mean(axis=1))


def _weight(model: Model, r: np.ndarray) -> np.ndarray:
    return TWO_PI * r if model.scene.kinematics == "axisymmetric" else np.full_like(r, model.scene.thickness)


def _bulk_modulus(model: Model, cells: np.ndarray) -> np.ndarray:
    p = model.params[model.cell_material[cells]]
    return p[:, P_LAMBDA] + 2.0 * p[:, P_MU] / 3.0


def segment_lengths(X: np.ndarray, surface: Surface) -> np.ndarray:
    return np.linalg.norm(X[surface.segments[:, 1]] - X[surface.segments[:, 0]], axis=1)


def _segment_areas(model: Model, surface: Surface) -> np.ndarray:
    """Areas of 2D segments in the reference configuration: length x (2 pi r at the midpoint, or thickness)."""
    X = model.X0
    r_mid = 0.5 * (X[surface.segments[:, 0], 0] + X[surface.segments[:, 1], 0])
    return segment_lengths(X, surface) * _weight(model, r_mid)


def segment_stiffness(model: Model, surface: Surface, scale: float) -> np.ndarray:
    """LS-DYNA's penalty for solids, k = scale K A^2 / V, per segment (A its area, V its cell's volume)."""
    return (scale * _bulk_modulus(model, surface.cells) * _segment_areas(model, surface) ** 2
            / _cell_volumes(model, surface.cells))


def node_stiffness(model: Model, surface: Surface, scale: float) -> np.ndarray:
    """Per surface node: k = scale K A_i^2 / V_i with A_i half the area of its segments, and K and V_i
    the means over the cells of those segments (for a node against a rigid wall)."""
    per_node = len(surface.segments[0])
    node = np.searchsorted(surface.nodes, surface.segments.ravel())     # nodes is sorted and unique

    def node_sum(per_segment):
        out = np.zeros(len(surface.nodes))
        np.add.at(out, node, np.repeat(per_segment, per_node))
        return out
    count = node_sum(np.ones(len(surface.segments)))
    A = node_sum(_segment_areas(model, surface) / per_node)
    K = node_sum(_bulk_modulus(model, surface.cells)) / count
    V = node_sum(_cell_volumes(model, surface.cells)) / count
    return scale * K * A ** 2 / V


class _Pass:
    """Slave nodes of one surface against the segments of another."""

    def __init__(self, slave: Surface, master: Surface, stiffness: np.ndarray):
        self.slaves = slave.nodes
        self.master = master
        self.stiffness = stiffness
        self.gap = np.zeros(len(self.slaves))
        self.offset = np.zeros(len(self.slaves))
        self.cand_ptr = np.zeros(len(self.slaves) + 1, dtype=np.int64)
        self.cand_seg = np.zeros(0, dtype=np.int64)

    def search(self, x: np.ndarray, reach: float):
        mid = 0.5 * (x[self.master.segments[:, 0]] + x[self.master.segments[:, 1]])
        hits = cKDTree(mid).query_ball_point(x[self.slaves], reach)
        self.cand_ptr = np.concatenate([[0], np.cumsum([len(h) for h in hits])]).astype(np.int64)
        self.cand_seg = np.array([j for h in hits for j in h], dtype=np.int64)


class ContactPair:
    def __init__(self, model: Model, spec: Contact):
        if model.gdim != 2:
            raise ModelError(f"contact '{spec.name}': this version has contact in axisymmetric and plane "
                             f"strain scenes; 3D contact is not built yet (use a 2D scene)")
        if model.comm.size > 1:
            raise ModelError(f"contact '{spec.name}': contact runs on one process in this version; run "
                             f"without mpirun")
        self.model = model
        self.spec = spec
        self.name = spec.name
        gdim = model.gdim
        self.a = build_surface(model, spec.a)
        self.b = build_surface(model, spec.b) if spec.b else None
        seg_scale = 0.1 if spec.penalty == "soft" else spec.penalty_scale
        self.soft_scale = spec.penalty_scale if spec.penalty == "soft" else 0.0
        if self.b is None:
            w = spec.wall
            self.point = np.array(w.point, dtype=float)
            self.normal = np.array(w.normal, dtype=float)
            self.wall_velocity = np.array(w.velocity, dtype=float)
            self.wall_stiffness = node_stiffness(model, self.a, seg_scale)
            self.wall_gap = np.zeros(len(self.a.nodes))
            self.wall_offset = np.zeros(len(self.a.nodes))
            self.passes = []
            self.nodes = self.a.nodes
        else:
            self.passes = [_Pass(self.a, self.b, segment_stiffness(model, self.b, seg_scale)),
                           _Pass(self.b, self.a, segment_stiffness(model, self.a, seg_scale))]
            self.nodes = np.union1d(self.a.nodes, self.b.nodes)
        seg_len = np.concatenate([segment_lengths(model.X0, s) for s in (self.a, self.b) if s is not None])
        # a node counts as penetrating only within `depth` of the surface (half the thinnest element
        # is a safe bound for a single step's travel); the search reaches a segment length beyond that
        self.depth = 0.5 * float(seg_len.min()) if self.b is not None else float(seg_len.max())
        self.margin = float(seg_len.max())
        self.reach = 0.5 * float(seg_len.max()) + self.margin
        self.x_search = None
        self.f = np.zeros((len(model.X0), gdim))
        self._f_old = np.zeros((len(self.nodes), gdim))
        self.work = 0.0                      # work done by the contact forces on the bodies [J]
        self.impulse = np.zeros(gdim)        # of the force on surface a [N s]
        self.force_a = np.zeros(gdim)        # current force on surface a [N]
        self.max_force = 0.0
        self.max_penetration = 0.0
        self.active = 0
        self.intervals: list[list[float]] = []
        self.searches = 0
        self.initial_overlap = (0, 0.0)      # (nodes, deepest [m]) at t = 0
        self.v_before = self.v_after = None  # body mean velocities around contact (for restitution)

    # --------------------------------------------------------------- search
    def _boxes_apart(self, x: np.ndarray) -> bool:
        if self.b is None:
            g = (x[self.a.nodes] - self.point) @ self.normal
            return bool(g.min() > self.margin)
        pa, pb = x[self.a.nodes], x[self.b.nodes]
        gap = np.maximum(pa.min(axis=0) - pb.max(axis=0), pb.min(axis=0) - pa.max(axis=0))
        return bool(gap.max() > self.margin)

    def _refresh(self, x: np.ndarray):
        if self.x_search is not None:
            travel = np.abs(x[self.nodes] - self.x_search).max()
            if travel < 0.25 * self.margin:
                return
        for p in self.passes:
            p.search(x, self.reach)
        self.x_search = x[self.nodes].copy()
        self.searches += 1

    # --------------------------------------------------------------- forces
    def compute(self, x: np.ndarray, v: np.ndarray, mass: np.ndarray, dt: float, t: float) -> float:
        """Contact forces at the current positions into ``self.f``; returns the step limit (inf if none)."""
        f = self.f
        f[self.nodes] = 0.0
        active = 0
        dt_limit = np.inf
        deepest = 0.0
        if not self._boxes_apart(x):
            zeta = self.spec.damping
            if self.b is None:
                active, dt_limit = kernels.node_to_plane(
                    self.a.nodes, self.wall_stiffness, self.point + t * self.wall_velocity, self.normal,
                    self.wall_velocity, x, v, mass, zeta, self.soft_scale, dt, self.depth, f, self.wall_gap,
                    self.wall_offset)
                deepest = -self.wall_gap.min()
            else:
                self._refresh(x)
                for p in self.passes:
                    n, dl = kernels.node_to_segment_2d(p.slaves, p.master.segments, p.stiffness, p.cand_ptr,
                                                       p.cand_seg, x, v, mass, zeta, self.soft_scale, dt,
                                                       self.depth, f, p.gap, p.offset)
                    active += n
                    dt_limit = min(dt_limit, dl)
                    deepest = max(deepest, -p.gap.min())
        self.active = active
        dt_limit = dt_limit if active else np.inf
        self.max_penetration = max(self.max_penetration, deepest)
        self.force_a = f[self.a.nodes].sum(axis=0)
        return dt_limit

    def account(self, dt: float, v_half: np.ndarray, t: float, body_velocities):
        """After a step of size dt ending at t: work, impulse, intervals, restitution velocities."""
        f_new = self.f[self.nodes]
        self.work += 0.5 * dt * float(np.sum((self._f_old + f_new) * v_half[self.nodes]))
        self._f_old = f_new.copy()
        self.impulse += dt * self.force_a
        self.max_force = max(self.max_force, float(np.linalg.norm(self.force_a)))
        closed = self.active > 0
        if closed and (not self.intervals or self.intervals[-1][1] is not None):
            self.intervals.append([t, None])
            if self.v_before is None:
                self.v_before = body_velocities()
        elif not closed and self.intervals and self.intervals[-1][1] is None:
            self.intervals[-1][1] = t
            self.v_after = body_velocities()

    def start(self, x: np.ndarray, v: np.ndarray, mass: np.ndarray) -> tuple[int, float]:
        """At t = 0: take every initial penetration as its node's zero; returns (nodes, deepest [m])."""
        if self._boxes_apart(x):
            return self.initial_overlap
        if self.b is None:
            self.wall_offset[:] = np.minimum((x[self.a.nodes] - self.point) @ self.normal, 0.0)
            self.wall_offset[self.wall_offset <= -self.depth] = 0.0
            offsets = [self.wall_offset]
        else:
            self._refresh(x)
            for p in self.passes:
                p.offset[:] = -1e300          # accept any initial penetration as the zero
                kernels.node_to_segment_2d(p.slaves, p.master.segments, p.stiffness, p.cand_ptr, p.cand_seg,
                                           x, v, mass, 0.0, 0.0, 0.0, self.depth, self.f, p.gap, p.offset)
                p.offset[:] = np.minimum(p.gap, 0.0)
            self.f[self.nodes] = 0.0
            offsets = [p.offset for p in self.passes]
        tiny = -1e-6 * self.depth                 # round-off of coincident meshes is no overlap
        for o in offsets:
            o[o > tiny] = 0.0
        nodes = sum(int((o < 0).sum()) for o in offsets)
        deepest = max(float(-o.min()) for o in offsets) if nodes else 0.0
        self.initial_overlap = (nodes, deepest)
        return self.initial_overlap

    def restitution(self) -> float | None:
        """e = -(v_a' - v_b') . n / ((v_a - v_b) . n), n the direction of the impulse on a;
        from the body mean velocities before first contact and after final separation."""
        if self.v_before is None:
            return None
        after = self.v_after if (self.intervals and self.intervals[-1][1] is not None) else None
        if after is None:
            return None
        n = self.impulse / max(np.linalg.norm(self.impulse), 1e-300)
        ia = self.a.body

        def rel(vel):
            vb = vel[self.b.body] if self.b is not None else self.wall_velocity
            return float(np.dot(vel[ia] - vb, n))
        before = rel(self.v_before)
        return -rel(after) / before if before != 0 else None

    def summary(self) -> dict:
        return {"surfaces": [self.spec.a, self.spec.b or "wall"],
                "penalty": self.spec.penalty, "damping_ratio": self.spec.damping,
                "impulse_on_a": self.impulse.tolist(), "max_normal_force": self.max_force,
                "friction_force_max": 0.0,
                "contact_energy": -self.work, "max_penetration": self.max_penetration,
                "intervals": self.intervals, "restitution": self.restitution(),
                "initial_overlap": {"nodes": self.initial_overlap[0], "deepest": self.initial_overlap[1]},
                "searches": self.searches}

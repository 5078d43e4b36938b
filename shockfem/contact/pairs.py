"""Contact pairs at run time: search, penalty and friction forces, and what each pair reports.

A pair is two surfaces (two-pass: the nodes of each against the facets of the other, so
neither side is privileged) or one surface against a rigid analytic surface (plane or
cylinder).  Every rank holds the pair's surfaces whole and works on compact copies of their
nodes (``surfaces.NodeExchange``), so a pair computes the same forces on one process or many.

The search finds, for every slave node, the master facets within reach (a KD-tree on facet
centres) and is refreshed only when some node of the pair has travelled a quarter of the
search margin since the last search; while the bounding boxes of the two surfaces are further
apart than the margin the pair costs nothing but the box test.  Penetrations present at the
start are reported and not pushed out: each slave node's initial penetration is its zero
(LS-DYNA's IGNORE=1), released as the node comes out.
"""
from __future__ import annotations

import numpy as np
from mpi4py import MPI
from scipy.spatial import cKDTree

from ..errors import ModelError
from ..model import Model
from ..scene.specs import Contact
from . import kernels
from .surfaces import NodeExchange, Surface, build_surface


def facet_stiffness(surface: Surface, scale: float, bulk: np.ndarray | float | None = None) -> np.ndarray:
    """LS-DYNA's penalty for solids, k = scale K A^2 / V, per facet (A its area, V its cell's volume,
    K the bulk modulus behind it unless ``bulk`` is given)."""
    return scale * (surface.bulk if bulk is None else bulk) * surface.area ** 2 / surface.volume


def master_stiffness(master: Surface, slave: Surface, scale: float, rigid: bool) -> np.ndarray:
    """The penalty of the master facets a slave surface's nodes are pushed out of.  A rigid body has
    no stiffness of its own (its modulus is a placeholder): its facets take the slave side's bulk
    modulus, as a rigid wall takes the stiffness of the nodes it stops.  Otherwise a steel striker's
    facets would hold a foam pad's light nodes with steel's stiffness, and their stable step would
    fall a hundredfold."""
    return facet_stiffness(master, scale, float(np.mean(slave.bulk)) if rigid else None)


def _node_sum(facets: np.ndarray, nodes: np.ndarray, per_facet: np.ndarray) -> np.ndarray:
    """Per surface node (``nodes``, sorted, numbering as ``facets``): the sum of ``per_facet`` over the
    facets it belongs to."""
    out = np.zeros(len(nodes))
    np.add.at(out, np.searchsorted(nodes, facets.ravel()), np.repeat(per_facet, facets.shape[1]))
    return out


def node_areas(surface: Surface, facets: np.ndarray, nodes: np.ndarray) -> np.ndarray:
    """Each surface node's share of the area of its facets (in axisymmetry the swept area)."""
    return _node_sum(facets, nodes, surface.area / facets.shape[1])


def node_stiffness(surface: Surface, facets: np.ndarray, nodes: np.ndarray, scale: float) -> np.ndarray:
    """Per surface node (``nodes``, sorted, numbering as ``facets``): k = scale K A_i^2 / V_i with
    A_i its share of the area of its facets, and K and V_i the means over the cells of those facets
    (for a node against a rigid surface)."""
    count = _node_sum(facets, nodes, np.ones(len(facets)))
    A = node_areas(surface, facets, nodes)
    K = _node_sum(facets, nodes, surface.bulk) / count
    V = _node_sum(facets, nodes, surface.volume) / count
    return scale * K * A ** 2 / V


class _Pass:
    """Slave nodes of one surface against the facets of another (compact node numbers).

    Under MPI every rank holds both surfaces whole (gathered each step) and the pair's whole state, and
    takes its own slaves (``rows``: those whose node it owns) through the costly half of the pass, the
    search of each slave's facet (``find``: ``kernels.closest_facets``); the ranks then share what each
    found (``share_closest``: two numbers a slave) and every rank runs the springs of all slaves in slave
    order (``respond``: ``kernels.facet_responses``), so that forces, friction histories and the step
    limit are summed as in one process: the same bits on any number of ranks."""

    def __init__(self, slaves: np.ndarray, facets: np.ndarray, stiffness: np.ndarray, rows: np.ndarray, comm):
        self.slaves = slaves
        self.facets = facets
        self.stiffness = stiffness
        self.rows = rows
        self.gap = np.zeros(len(slaves))
        self.offset = np.zeros(len(slaves))
        self.ft = np.zeros((len(slaves), 3))          # tangential (friction) force history
        self.cand_ptr = np.zeros(len(slaves) + 1, dtype=np.int64)
        self.cand_seg = np.zeros(0, dtype=np.int64)
        self.near = np.zeros(0, dtype=np.int64)       # the facets the candidate lists hold
        self.best = np.full(len(slaves), -1, dtype=np.int64)    # each slave's facet (-1: none), its gap
        self.best_g = np.zeros(len(slaves))
        self.comm = comm if comm.size > 1 else None
        if self.comm is not None:
            self.counts = np.array(comm.allgather(len(rows)))
            self.order = np.concatenate(comm.allgather(rows))      # rank by rank
            self.offsets = np.concatenate([[0], np.cumsum(self.counts)])

    def search(self, x: np.ndarray, reach: float):
        centre = x[self.facets].mean(axis=1)
        hits = cKDTree(centre).query_ball_point(x[self.slaves[self.rows]], reach)
        counts = np.zeros(len(self.slaves), dtype=np.int64)
        counts[self.rows] = [len(h) for h in hits]
        self.cand_ptr = np.concatenate([[0], np.cumsum(counts)]).astype(np.int64)
        # ``rows`` is sorted, so its lists follow one another as the pointers say
        self.cand_seg = np.array([j for h in hits for j in h], dtype=np.int64)
        self.near = kernels.candidate_facets(self.cand_seg)

    def find(self, x: np.ndarray, depth: float):
        """Each of this rank's slaves' facet and gap (``best``, ``best_g``; the other ranks' slaves come
        from ``share_closest``)."""
        kernels.closest_facets(self.slaves, self.rows, self.facets, self.near, self.cand_ptr, self.cand_seg, x,
                               depth, self.best, self.best_g)

    def respond(self, x, v, mass, zeta, soft_scale, dt, depth, friction, f, ff, stiff):
        """The springs of every slave on the facet found for it; the number active."""
        return kernels.facet_responses(self.slaves, self.facets, self.stiffness, self.best, self.best_g, x, v, mass,
                                       zeta, soft_scale, dt, friction, f, ff, self.ft, self.gap, self.offset, stiff)


def share_closest(passes: list, comm):
    """Every rank's slaves' facets and gaps (``_Pass.find``) to every rank, the passes' together in one
    exchange (a facet number is exact as a double): each rank finds its own slaves of every pass before
    any waits, so that a partition that gives one rank surface a and the other surface b keeps both
    busy.  Collective."""
    mine = np.concatenate([np.column_stack([p.best[p.rows], p.best_g[p.rows]]) for p in passes])
    counts = sum(p.counts for p in passes)
    every = np.empty((sum(len(p.slaves) for p in passes), 2))
    comm.Allgatherv(mine, [every, counts * 2, None, MPI.DOUBLE])
    # rank by rank, each pass's rows in turn
    start = 0
    for r in range(comm.size):
        for p in passes:
            n = p.counts[r]
            rows = p.order[p.offsets[r]:p.offsets[r] + n]
            p.best[rows] = every[start:start + n, 0].astype(np.int64)
            p.best_g[rows] = every[start:start + n, 1]
            start += n


class _RigidPass:
    """Nodes of a surface against a rigid plane or cylinder."""

    def __init__(self, model: Model, spec: Contact, slaves: np.ndarray, stiffness: np.ndarray):
        r = spec.rigid
        gdim = model.gdim
        self.slaves = slaves
        self.stiffness = stiffness
        self.kind = {"plane": kernels.PLANE, "cylinder": kernels.CYLINDER, "tunnel": kernels.TUNNEL}[r.kind]
        self.point = np.array(r.point, dtype=float)
        self.direction = np.array(r.direction, dtype=float)
        self.radius = r.radius
        self.inside = r.inside
        self.velocity = np.array(r.velocity, dtype=float)
        self.gap = np.zeros(len(slaves))
        self.offset = np.zeros(len(slaves))
        self.ft = np.zeros((len(slaves), 3))
        self.t = 0.0
        assert len(self.point) == gdim

    def gaps(self, x: np.ndarray) -> np.ndarray:
        p = x[self.slaves] - (self.point + self.t * self.velocity)
        if self.kind == kernels.PLANE:
            return p @ self.direction
        along = p @ self.direction
        dist = np.linalg.norm(p - np.outer(along, self.direction), axis=1)
        gap = self.radius - dist if self.inside else dist - self.radius
        return np.where(along >= 0.0, gap, np.inf) if self.kind == kernels.TUNNEL else gap

    def find(self, x: np.ndarray, depth: float):
        """Nothing to search: the surface is analytic (``respond`` does it all, on every rank)."""

    def respond(self, x, v, mass, zeta, soft_scale, dt, depth, friction, f, ff, stiff):
        return kernels.node_to_rigid(self.slaves, self.stiffness, self.kind, self.point + self.t * self.velocity,
                                     self.direction, self.radius, self.inside, self.velocity, x, v, mass, zeta,
                                     soft_scale, dt, depth, friction, f, ff, self.ft, self.gap, self.offset, stiff)


class ContactPair:
    def __init__(self, model: Model, spec: Contact):
        self.model = model
        self.spec = spec
        self.name = spec.name
        gdim = model.gdim
        self.a = build_surface(model, spec.a)
        self.b = build_surface(model, spec.b) if spec.b else None
        surfaces = [s for s in (self.a, self.b) if s is not None]
        for s in surfaces:
            if not len(s.facets):
                raise ModelError(f"contact '{spec.name}': surface '{s.name}' has no boundary facets; check the "
                                 f"region (a facet belongs to one region only)")
        self.global_nodes = np.unique(np.concatenate([s.facets.ravel() for s in surfaces]))
        self.exchange = NodeExchange(model, self.global_nodes)
        compact = [np.searchsorted(self.global_nodes, s.facets) for s in surfaces]
        self.nodes_a = np.unique(compact[0])
        self.area_a = node_areas(self.a, compact[0], self.nodes_a)      # for contact pressures on a
        self.mass = self.exchange.gather(model.mass[:, None])[:, 0]
        seg_scale = 0.1 if spec.penalty == "soft" else spec.penalty_scale
        self.soft_scale = spec.penalty_scale if spec.penalty == "soft" else 0.0
        self.friction = np.array(spec.friction, dtype=float)
        sizes = np.concatenate([s.size for s in surfaces])
        self.parallel = model.comm.size > 1
        if self.b is None:
            self.passes = [_RigidPass(model, spec, self.nodes_a,
                                      node_stiffness(self.a, compact[0], self.nodes_a, seg_scale))]
            # a node is caught by a rigid surface up to a facet size behind it
            self.depth = float(sizes.max())
        else:
            rigid = [model.bodies[s.body].rigid for s in (self.a, self.b)]
            # under MPI a rank searches for the slaves it owns (``_Pass``)
            owned = np.zeros(len(self.global_nodes), dtype=bool)
            owned[self.exchange.slot] = True
            slaves_b = np.unique(compact[1])
            self.passes = [_Pass(slaves, facets, master_stiffness(master, slave, seg_scale, rigid_master),
                                 np.flatnonzero(owned[slaves]), model.comm)
                           for slaves, facets, master, slave, rigid_master in
                           ((self.nodes_a, compact[1], self.b, self.a, rigid[1]),
                            (slaves_b, compact[0], self.a, self.b, rigid[0]))]
            # a node counts as penetrating only within `depth` of the surface (half the smallest facet
            # is a safe bound for a single step's travel); the search reaches a facet size beyond that
            self.depth = 0.5 * float(sizes.min())
        self.margin = float(sizes.max())
        self.smallest_facet = float(sizes.min())
        self.reach = 0.5 * float(sizes.max()) + self.margin
        n = len(self.global_nodes)
        self.x = np.zeros((n, gdim))
        self.v = np.zeros((n, gdim))
        self.x_search = None
        self.f = np.zeros((n, gdim))              # normal forces on the compact nodes [N]
        self.ff = np.zeros((n, gdim))             # friction forces [N]
        self.stiff = np.zeros(n)                  # row sums of the active springs' stiffness [N/m]
        # on a, this step: |force|, |friction|, largest node pressure, summed |f_i|, loaded area (``account``)
        self._step_sizes = np.zeros(5)
        self._f_old = np.zeros((n, gdim))
        self._ff_old = np.zeros((n, gdim))
        self.work = 0.0                      # work done by the normal contact forces on the bodies [J]
        self.friction_work = 0.0             # work done by the friction forces [J] (<= 0: dissipated)
        self.impulse = np.zeros(gdim)        # of the force on surface a [N s]
        self.force_a = np.zeros(gdim)        # current normal force on surface a [N]
        self.friction_a = np.zeros(gdim)     # current friction force on surface a [N]
        self.max_force = 0.0
        self.max_friction = 0.0
        self.max_pressure = 0.0              # the largest node pressure on a, |f_i| / A_i [Pa]
        self.pressure_at_max_force = 0.0     # the mean pressure over a's loaded area then [Pa]
        self.max_penetration = 0.0
        self.active = 0
        self.intervals: list[list[float]] = []
        self.searches = 0
        self.initial_overlap = (0, 0.0)      # (nodes, deepest [m]) at t = 0
        self._offset0 = None                 # the initial penetrations an interference ramp pushes out
        self.preload = None                  # at the end of that ramp: force on a, pressure, area
        self.v_before = self.v_after = None  # body mean velocities around contact (for restitution)

    # --------------------------------------------------------------- search
    def _boxes_apart(self) -> bool:
        x = self.x
        if self.b is None:
            return bool(self.passes[0].gaps(x).min() > self.margin)
        return kernels.boxes_gap(x, self.passes[0].slaves, self.passes[1].slaves) > self.margin

    def _refresh(self):
        if self.b is None:
            return
        if self.x_search is not None and kernels.travel(self.x, self.x_search) < 0.25 * self.margin:
            return
        for p in self.passes:
            p.search(self.x, self.reach)
        self.x_search = self.x.copy()
        self.searches += 1

    # --------------------------------------------------------------- forces
    def _find(self):
        """Every pass's search of its slaves' facets (under MPI each rank its own, then shared).
        Collective under MPI."""
        for p in self.passes:
            p.find(self.x, self.depth)
        if self.parallel and self.b is not None:      # a rigid surface's pass searches nothing
            share_closest(self.passes, self.model.comm)

    def compute(self, x: np.ndarray, v: np.ndarray, dt: float, t: float) -> float:
        """Contact forces at the current positions (collective: gathers the surface nodes).

        ``v`` is v_{n+1/2} of the step of size ``dt`` just taken: the work of the contact forces
        over that step is counted here, trapezoidally, as the solver counts it.  Returns the
        step limit of the active penalty springs (inf if none)."""
        self.exchange.gather(x, self.x)
        self.exchange.gather(v, self.v)
        self.f[:] = 0.0
        self.ff[:] = 0.0
        self.stiff[:] = 0.0
        active = 0
        deepest = 0.0
        for p in self.passes:
            if isinstance(p, _RigidPass):
                p.t = t
        if self._offset0 is not None:
            self._push_out_overlaps(t)
        if not self._boxes_apart():                 # the same answer on every rank: each holds all of x
            self._refresh()
            self._find()
            for p in self.passes:
                active += p.respond(self.x, self.v, self.mass, self.spec.damping, self.soft_scale, dt, self.depth,
                                    self.friction, self.f, self.ff, self.stiff)
                deepest = max(deepest, -p.gap.min())
        else:
            for p in self.passes:
                p.ft[:] = 0.0
        self.active = active
        self.max_penetration = max(self.max_penetration, deepest)
        self.force_a, self.friction_a, work, friction_work, omega2, self._step_sizes = kernels.totals(
            self.f, self.ff, self._f_old, self._ff_old, self.v, self.stiff, self.mass, self.nodes_a, self.area_a)
        if self._offset0 is not None and self.preload is None and t >= self.spec.interference_time:
            self.preload = self._pressure()
        self.work += 0.5 * dt * work
        self.friction_work += 0.5 * dt * friction_work
        return self._stable_step(omega2) if omega2 > 0.0 else np.inf     # active or arriving springs

    def _push_out_overlaps(self, t: float):
        """LS-DYNA's interference option: the penetration each node started with counts in full after
        the interference time, growing smoothly (3 s^2 - 2 s^3 of s = t / T) from nothing, so that a
        shrink fit settles into its preload instead of being struck by it."""
        s = min(t / self.spec.interference_time, 1.0)
        left = 1.0 - s * s * (3.0 - 2.0 * s)
        for p, o0 in zip(self.passes, self._offset0):
            np.maximum(p.offset, left * o0, out=p.offset)
        if s >= 1.0 and self.preload is not None:
            self._offset0 = None

    def _pressure(self) -> dict:
        """The normal force on surface a, its nodes' normal forces summed by magnitude over a's area
        (a mean contact pressure; in axisymmetry the area is the swept one, 2 pi r per unit length)."""
        load = float(np.linalg.norm(self.f[self.nodes_a], axis=1).sum())
        area = float(self.a.area.sum())
        return {"time": self.spec.interference_time, "force_on_a": self.force_a.tolist(), "normal_load": load,
                "area": area, "mean_pressure": load / area}

    def _stable_step(self, omega2: float) -> float:
        """2 / omega of the active springs alone, omega^2 <= max_i stiff_i / m_i (Gershgorin, ``omega2``),
        shortened by the contact damping: (2 / omega)(sqrt(1 + zeta^2) - zeta) (Belytschko et al., eq. 6.2.28)."""
        zeta = self.spec.damping
        return 2.0 / np.sqrt(omega2) * (np.sqrt(1.0 + zeta * zeta) - zeta)

    def add_forces(self, f: np.ndarray):
        """Add this pair's forces on the nodes this rank owns into the solver's array ``f``."""
        self.exchange.add_to(self.f, f)
        self.exchange.add_to(self.ff, f)

    def account(self, dt: float, t: float, body_velocities):
        """After a step ending at t: impulse, peak forces, open/closed intervals, restitution velocities.
        Collective when contact opens or closes (``body_velocities`` reduces over ranks)."""
        self.impulse += dt * (self.force_a + self.friction_a)
        force, friction, pressure, load, loaded_area = self._step_sizes.tolist()
        if self.active > 0:
            self.max_pressure = max(self.max_pressure, pressure)
            if force > self.max_force and loaded_area > 0:
                self.pressure_at_max_force = load / loaded_area
        self.max_force = max(self.max_force, force)
        self.max_friction = max(self.max_friction, friction)
        closed = self.active > 0
        if closed and (not self.intervals or self.intervals[-1][1] is not None):
            self.intervals.append([t, None])
            if self.v_before is None:
                # the mean velocities at t_{n+1} already hold half of this step's impulse (and all
                # of any earlier one): take back what this pair has transferred
                transferred = self.impulse - 0.5 * dt * (self.force_a + self.friction_a)
                self.v_before = body_velocities().copy()
                masses = self.model.body_mass
                self.v_before[self.a.body] -= transferred / masses[self.a.body]
                if self.b is not None:
                    self.v_before[self.b.body] += transferred / masses[self.b.body]
        elif not closed and self.intervals and self.intervals[-1][1] is None:
            self.intervals[-1][1] = t
            self.v_after = body_velocities()

    def start(self, x: np.ndarray, v: np.ndarray) -> tuple[int, float]:
        """At t = 0: take every initial penetration as its node's zero; returns (nodes, deepest [m])."""
        self.exchange.gather(x, self.x)
        self.exchange.gather(v, self.v)
        if self._boxes_apart():
            return self.initial_overlap
        self._refresh()
        no_friction = np.zeros(3)
        self._find()
        for p in self.passes:
            p.offset[:] = -1e300          # accept any initial penetration as the zero
            p.respond(self.x, self.v, self.mass, 0.0, 0.0, 0.0, self.depth, no_friction, self.f, self.ff, self.stiff)
            p.offset[:] = np.minimum(p.gap, 0.0)
        self.f[:] = 0.0
        self.ff[:] = 0.0
        self.stiff[:] = 0.0
        tiny = -1e-6 * self.depth                 # round-off of coincident meshes is no overlap
        offsets = [p.offset for p in self.passes]
        for o in offsets:
            o[o > tiny] = 0.0
        nodes = sum(int((o < 0).sum()) for o in offsets)
        deepest = max(float(-o.min()) for o in offsets) if nodes else 0.0
        self.initial_overlap = (nodes, deepest)
        if nodes and self.spec.interference_time > 0.0:
            self._offset0 = [o.copy() for o in offsets]
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
            vb = vel[self.b.body] if self.b is not None else np.array(self.spec.rigid.velocity)
            return float(np.dot(vel[ia] - vb, n))
        before = rel(self.v_before)
        return -rel(after) / before if before != 0 else None

    def summary(self) -> dict:
        return {"surfaces": [self.spec.a, self.spec.b or self.spec.rigid.kind],
                "penalty": self.spec.penalty, "damping_ratio": self.spec.damping,
                "friction": {"static": self.spec.friction[0], "dynamic": self.spec.friction[1],
                             "decay": self.spec.friction[2]},
                "impulse_on_a": self.impulse.tolist(), "max_normal_force": self.max_force,
                "max_friction_force": self.max_friction,
                "max_pressure": self.max_pressure, "pressure_at_max_force": self.pressure_at_max_force,
                "contact_energy": -(self.work + self.friction_work),
                "friction_work": self.friction_work, "max_penetration": self.max_penetration,
                "smallest_facet": self.smallest_facet,
                "intervals": self.intervals, "restitution": self.restitution(),
                "initial_overlap": {"nodes": self.initial_overlap[0], "deepest": self.initial_overlap[1]},
                "interference_preload": self.preload,
                "searches": self.searches}

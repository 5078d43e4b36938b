"""Contact pairs at run time: search, penalty and friction forces, and what each pair reports.

A pair is two surfaces (two-pass: the nodes of each against the facets of the other, so
neither side is privileged) or one surface against a rigid analytic surface (plane or
cylinder).  The pair works on compact arrays of its surfaces' nodes (``surfaces.NodeExchange``).
Every rank knows the surfaces' facets, but under MPI it holds positions only of the nodes it owns
and of a halo of other ranks' nodes near its own slaves (``halo.SurfaceHalo``); it searches and
responds for its own slaves, and adds to its own nodes every spring that acts on them in the pair's
slave order, so a pair computes the same forces, to the bit, on one process or many.

The search finds, for every slave node, the master facets within reach (a KD-tree on facet
centres) and is refreshed only when some node of the pair has travelled a quarter of the
search margin since the last search; while the bounding boxes of the two surfaces are further
apart than the margin the pair costs nothing but the box test.  Penetrations present at the
start are reported and not pushed out: each slave node's initial penetration is its zero
(LS-DYNA's IGNORE=1), released as the node comes out.
"""
from __future__ import annotations

import math

import numpy as np
from mpi4py import MPI

from ..errors import ModelError
from ..forces.source import ForceSource
from ..model import Model
from ..scene.specs import Contact
from . import kernels, pair_step
from .halo import SurfaceHalo
from .surfaces import NodeExchange, Surface, build_surface, reference_key


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


def _reference_order(model: Model, global_nodes: np.ndarray) -> np.ndarray:
    """Surface nodes (global numbers) in the order of their reference positions (x first, rounded:
    ``surfaces.reference_key``; then the body, for nodes of two bodies that start at one point), which no
    partition changes: the pair's slave order, in which its forces are summed, is then the same on any
    number of ranks.  Collective."""
    exchange = NodeExchange(model, global_nodes)
    X = reference_key(exchange.gather(model.X0))
    body = exchange.gather(model.node_body[:, None].astype(float))[:, 0]
    return global_nodes[np.lexsort((body,) + tuple(X.T[::-1]))]


class _Pass:
    """Slave nodes of one surface against the facets of another (compact node numbers).

    Every rank holds the pass's slave arrays whole but works on its own slaves (``rows``: those whose
    node it owns): the search of each one's facet (``find``: ``kernels.closest_facets``) and its spring
    (``respond``: ``kernels.facet_springs``, a record each; the pair adds them to the nodes)."""

    def __init__(self, slaves: np.ndarray, facets: np.ndarray, stiffness: np.ndarray, rows: np.ndarray, key0: int):
        self.slaves = slaves
        self.facets = facets
        self.stiffness = stiffness
        self.rows = rows
        self.key0 = key0                              # this pass's slaves' place in the pair's slave order
        self.gap = np.zeros(len(slaves))
        self.offset = np.zeros(len(slaves))
        self.ft = np.zeros((len(slaves), 3))          # tangential (friction) force history
        self.cand_ptr = np.zeros(len(slaves) + 1, dtype=np.int64)
        self.cand_seg = np.zeros(0, dtype=np.int64)
        self.near = np.zeros(0, dtype=np.int64)       # the facets the candidate lists hold
        self.best = np.full(len(slaves), -1, dtype=np.int64)    # each slave's facet (-1: none), its gap
        self.best_g = np.zeros(len(slaves))
        self.own = slaves[rows]                       # this rank's slave nodes
        self.records = np.zeros((len(rows), kernels.record_width(facets.shape[1])))
        self.count = 0                                # records written this step

    def search(self, x: np.ndarray, reach: float, known: np.ndarray | None = None):
        """Each of this rank's slaves' candidate facets: those whose centre is within ``reach`` of it, among
        the facets whose nodes this rank knows (``known``; all in one process), in facet order."""
        usable = np.arange(len(self.facets)) if known is None else np.flatnonzero(known[self.facets].all(axis=1))
        counts = np.zeros(len(self.slaves), dtype=np.int64)
        hits = []
        if len(self.rows) and len(usable):
            from scipy.spatial import cKDTree       # here: scipy.spatial's import takes 0.11 s, and only facet pairs search
            centre = x[self.facets[usable]].mean(axis=1)
            hits = cKDTree(centre).query_ball_point(x[self.slaves[self.rows]], reach)
            counts[self.rows] = [len(h) for h in hits]
        self.cand_ptr = np.concatenate([[0], np.cumsum(counts)]).astype(np.int64)
        # ``rows`` is sorted, so its lists follow one another as the pointers say; each list is sorted,
        # and ``usable`` is, so the candidates come in facet order on any number of ranks
        self.cand_seg = usable[np.array([j for h in hits for j in h], dtype=np.int64)]
        self.near = kernels.candidate_facets(self.cand_seg)

    def find(self, x: np.ndarray, depth: float):
        """Each of this rank's slaves' facet and gap (``best``, ``best_g``)."""
        kernels.closest_facets(self.slaves, self.rows, self.facets, self.near, self.cand_ptr, self.cand_seg, x,
                               depth, self.best, self.best_g)

    def step_arrays(self) -> tuple:
        """The pass's arguments of ``pair_step.close_step``, in its order."""
        return (self.slaves, self.rows, self.facets, self.near, self.cand_ptr, self.cand_seg, self.stiffness, self.best,
                self.best_g, self.ft, self.gap, self.offset, self.key0, self.records)

    def respond(self, x, v, mass, zeta, soft_scale, dt, depth, friction, f, ff, stiff):
        """The springs of this rank's slaves on the facets found for them, as records (``records[:count]``);
        the number active.  (``f``, ``ff``, ``stiff`` are the pair's: it adds the records to them.)"""
        active, self.count = kernels.facet_springs(self.slaves, self.rows, self.facets, self.stiffness, self.best,
                                                   self.best_g, x, v, mass, zeta, soft_scale, dt, friction, self.ft,
                                                   self.gap, self.offset, self.key0, self.records)
        return active


class _RigidPass:
    """Nodes of a surface against a rigid plane or cylinder (each rank its own: ``rows``)."""

    def __init__(self, model: Model, spec: Contact, slaves: np.ndarray, stiffness: np.ndarray, rows: np.ndarray):
        r = spec.rigid
        gdim = model.gdim
        self.slaves = slaves
        self.rows = rows
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
        self._gaps = np.empty(len(rows))
        self.t = 0.0
        assert len(self.point) == gdim

    def point_at(self, t: float) -> np.ndarray:
        """The rigid surface's point at time ``t`` (it moves at ``velocity``)."""
        return self.point + t * self.velocity

    def gaps(self, x: np.ndarray) -> np.ndarray:
        """The gaps of this rank's slaves (``kernels.rigid_gaps``; a tunnel's nodes not yet in it: inf)."""
        return kernels.rigid_gaps(self.slaves, self.rows, self.kind, self.point_at(self.t),
                                  self.direction, self.radius, self.inside, x, self._gaps)

    def find(self, x: np.ndarray, depth: float):
        """Nothing to search: the surface is analytic (``respond`` does it all)."""

    def step_arrays(self) -> tuple:
        """What ``pair_step.rigid_step`` takes of this pass, in its order."""
        return (self.slaves, self.rows, self.stiffness, self.kind, self.point_at(self.t),
                self.direction, self.radius, self.inside, self.velocity, self._gaps, self.ft, self.gap, self.offset)

    def respond(self, x, v, mass, zeta, soft_scale, dt, depth, friction, f, ff, stiff):
        """This rank's slaves' springs, added to ``f``, ``ff``, ``stiff``; the number active."""
        return kernels.node_to_rigid(self.slaves, self.rows, self.stiffness, self.kind, self.point_at(self.t),
                                     self.direction, self.radius, self.inside, self.velocity, x, v, mass, zeta,
                                     soft_scale, dt, depth, friction, f, ff, self.ft, self.gap, self.offset, stiff)


class ContactPair(ForceSource):
    """A contact pair as a force source (``forces/source.py``); a constraint wall holds its nodes instead."""

    kind = "contact"

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
        self.global_nodes = _reference_order(model, np.unique(np.concatenate([s.facets.ravel() for s in surfaces])))
        self.exchange = NodeExchange(model, self.global_nodes)
        by_number = np.argsort(self.global_nodes)
        compact = [by_number[np.searchsorted(self.global_nodes, s.facets, sorter=by_number)] for s in surfaces]
        self.nodes_a = np.unique(compact[0])
        self.area_a = node_areas(self.a, compact[0], self.nodes_a)      # for contact pressures on a
        self.mass = self.exchange.gather(model.mass[:, None])[:, 0]
        seg_scale = 0.1 if spec.penalty == "soft" else spec.penalty_scale
        self.soft_scale = spec.penalty_scale if spec.penalty == "soft" else 0.0
        self.friction = np.array(spec.friction, dtype=float)
        self.has_friction = bool(self.friction[0] > 0.0 or self.friction[1] > 0.0)
        sizes = np.concatenate([s.size for s in surfaces])
        self.parallel = model.comm.size > 1
        # a rank works on the nodes it owns (all of them in one process) and, under MPI, on a halo of the
        # other ranks' nodes that its slaves' facets hold (``halo.SurfaceHalo``)
        self.owned = np.zeros(len(self.global_nodes), dtype=bool)
        self.owned[self.exchange.slot] = True
        self.own_nodes = np.flatnonzero(self.owned)
        own_a = self.owned[self.nodes_a]
        self.own_a, self.own_area_a = self.nodes_a[own_a], self.area_a[own_a]
        self.halo = SurfaceHalo(model.comm, self.exchange.owners(), gdim) if self.parallel and spec.b else None
        # in one process: a two-surface pair's step in two compiled calls, a rigid pair's in one
        # (``_step_in_one_process``)
        self.one_process = not self.parallel
        if self.b is None:
            self.passes = [_RigidPass(model, spec, self.nodes_a,
                                      node_stiffness(self.a, compact[0], self.nodes_a, seg_scale),
                                      np.flatnonzero(own_a))]
            # a node is caught by a rigid surface up to a facet size behind it
            self.depth = float(sizes.max())
        else:
            rigid = [model.bodies[s.body].rigid for s in (self.a, self.b)]
            slaves_b = np.unique(compact[1])
            self.passes = [_Pass(slaves, facets, master_stiffness(master, slave, seg_scale, rigid_master),
                                 np.flatnonzero(self.owned[slaves]), key0)
                           for slaves, facets, master, slave, rigid_master, key0 in
                           ((self.nodes_a, compact[1], self.b, self.a, rigid[1], 0),
                            (slaves_b, compact[0], self.a, self.b, rigid[0], len(self.nodes_a)))]
            self.master_nodes = [slaves_b, self.nodes_a]      # the nodes of each pass's master facets
            # a node counts as penetrating only within `depth` of the surface (half the smallest facet
            # is a safe bound for a single step's travel); the search reaches a facet size beyond that
            self.depth = 0.5 * float(sizes.min())
        self.margin = float(sizes.max())
        self.smallest_facet = float(sizes.min())
        self.reach = 0.5 * float(sizes.max()) + self.margin
        n = len(self.global_nodes)
        self.x = np.zeros((n, gdim))
        self.v = np.zeros((n, gdim))
        self.x_search = np.zeros((n, gdim))        # the positions at the last search (``searches`` > 0)
        self._least = np.zeros(4 * gdim + 1)        # what ``_survey`` reduces
        self.f = np.zeros((n, gdim))              # normal forces on the compact nodes [N]
        self.ff = np.zeros((n, gdim))             # friction forces [N]
        self.stiff = np.zeros(n)                  # row sums of the active springs' stiffness [N/m]
        # on a, this step: |force|, |friction|, largest node pressure, summed |f_i|, loaded area (``account``)
        self._step_sizes = (0.0, 0.0, 0.0, 0.0, 0.0)
        self._f_old = np.zeros((n, gdim))
        self._ff_old = np.zeros((n, gdim))
        self.work = 0.0                      # work done by the normal contact forces on the bodies [J]
        self.friction_work = 0.0             # work done by the friction forces [J] (<= 0: dissipated)
        self.impulse = np.zeros(gdim)        # of the force on surface a to t [N s] (``account``)
        self._load_before = np.zeros(gdim)   # the force on a (normal and friction) at the step's start [N]
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
        # a constraint wall (``hold``): surface a's nodes this rank owns, their masses and areas
        self.constraint = spec.method == "constraint"
        self.holds_motion = self.constraint
        self._said_preload = False
        if self.constraint:
            if model.bodies[self.a.body].rigid:
                raise ModelError(f"contact '{spec.name}': method = \"constraint\" holds a deformable body's "
                                 f"nodes on the wall; '{model.bodies[self.a.body].name}' is rigid: leave method "
                                 f"at \"penalty\"")
            of_a = np.isin(self.exchange.slot, self.nodes_a)
            self.wall_nodes = self.exchange.local[of_a]
            self.wall_mass = model.mass[self.wall_nodes]
            self.wall_area = self.area_a[np.searchsorted(self.nodes_a, self.exchange.slot[of_a])]
            self._wall_impulse = np.zeros(gdim)
            self._wall_before = np.zeros((len(self.wall_nodes), gdim))     # their v_{n-1/2} (``take_velocities``)

    # --------------------------------------------------------------- search
    def _gather(self, x: np.ndarray, v: np.ndarray):
        """This rank's own surface nodes' positions and velocities into the compact arrays."""
        self.exchange.gather_own(x, self.x)
        self.exchange.gather_own(v, self.v)

    def _survey(self) -> tuple[bool, bool]:
        """(the two surfaces' bounding boxes are further apart than the margin, a search is due: some node
        has travelled a quarter of the margin since the last one), the same on every rank (one reduction
        of the ranks' boxes and travels: minima and maxima are exact).  Collective under MPI."""
        if self.b is None:
            gaps = self.passes[0].gaps(self.x)
            nearest = np.array([gaps.min() if len(gaps) else np.inf])
            if self.parallel:
                self.model.comm.Allreduce(MPI.IN_PLACE, nearest, op=MPI.MIN)
            return bool(nearest[0] > self.margin), False
        least = self._least
        kernels.survey(self.x, self.passes[0].own, self.passes[1].own, self.x_search, self.own_nodes,
                       self.searches > 0, least)
        if self.parallel:
            self.model.comm.Allreduce(MPI.IN_PLACE, least, op=MPI.MIN)
        return kernels.verdict(least, self.margin)

    def _search(self):
        """Each pass's candidate facets for this rank's slaves; under MPI first the near nodes of the other
        ranks, and after it the halo of the candidates' nodes (``halo.SurfaceHalo``).  Collective under MPI."""
        known = None
        if self.halo is not None:
            # a facet whose centre is within reach of a slave has its nodes within a facet size more
            widen = 1.01 * (self.reach + self.margin)
            boxes = []
            for p in self.passes:
                lo, hi = kernels.extent(self.x, p.own)
                boxes.append((lo - widen, hi + widen))
            known = self.halo.find_near(self.x, boxes, self.master_nodes)
        for p in self.passes:
            p.search(self.x, self.reach, known)
        if self.halo is not None:
            self.halo.ask_for(np.unique(np.concatenate([p.facets[p.near].ravel() for p in self.passes])))
        self.x_search[:] = self.x
        self.searches += 1

    # --------------------------------------------------------------- forces
    def _springs(self, search_due: bool, zeta: float, soft_scale: float, dt: float, friction: np.ndarray) -> int:
        """Search if due, find each of this rank's slaves' facet, and respond; a facet pass's springs are
        added to the nodes here (under MPI the records of all ranks that act on this rank's nodes, in the
        pair's slave order).  Returns the number of active slaves of this rank.  Collective under MPI."""
        if self.b is not None and search_due:
            self._search()
        if self.halo is not None:
            self.halo.update(self.x, self.v)
        active = 0
        for p in self.passes:
            p.find(self.x, self.depth)
            active += p.respond(self.x, self.v, self.mass, zeta, soft_scale, dt, self.depth, friction, self.f,
                                self.ff, self.stiff)
        if self.b is None:
            return active
        nf = self.passes[0].facets.shape[1]
        if self.halo is None:             # in one process the passes' records are in slave order already
            for p in self.passes:
                kernels.add_springs(p.records[:p.count], self.owned, nf, self.has_friction, self.f, self.ff,
                                    self.stiff)
        else:
            records = self.halo.spread(np.concatenate([p.records[:p.count] for p in self.passes]), nf)
            kernels.add_springs(records, self.owned, nf, self.has_friction, self.f, self.ff, self.stiff)
        return active

    def take_velocities(self, v: np.ndarray):
        """A constraint wall's nodes' velocities before the step's update (v_{n-1/2}), for ``hold``'s work."""
        np.take(v, self.wall_nodes, axis=0, out=self._wall_before)

    def hold(self, x: np.ndarray, v: np.ndarray, dt: float, dt_avg: float, t_end: float) -> float:
        """A constraint wall's step (``kernels.hold_on_plane``): the nodes of surface a that would cross the
        wall by ``t_end`` put on it, ``v`` (v_{n+1/2}, before the position update) changed in place.  The
        impulse goes into the pair's impulse as it is, and its mean force over the step (impulse /
        ``dt_avg``) is the force on a the history records.  Returns the work of the wall on the bodies
        [J].  Collective under MPI."""
        rigid = self.passes[0]
        work, held, total, largest, loaded = kernels.hold_on_plane(
            x, v, self._wall_before, self.wall_nodes, self.wall_mass, self.wall_area,
            rigid.point_at(t_end),
            rigid.direction, dt, self._wall_impulse)
        sums = np.concatenate([[work, held, total, loaded], self._wall_impulse])
        if self.parallel:
            self.model.comm.Allreduce(MPI.IN_PLACE, sums, op=MPI.SUM)
            largest = self.model.comm.allreduce(largest, op=MPI.MAX)
        work, held, total, loaded = sums[:4].tolist()
        self.impulse += sums[4:]
        self.force_a = sums[4:] / dt_avg
        self.active = int(held)
        self.work += work
        self._step_sizes = (float(np.linalg.norm(self.force_a)), 0.0, largest / dt_avg, total / dt_avg, loaded)
        return work

    def compute(self, x: np.ndarray, v: np.ndarray, dt: float, t: float) -> float:
        """Contact forces at the current positions on this rank's nodes (collective under MPI).

        ``v`` is v_{n+1/2} of the step of size ``dt`` just taken: the work of the contact forces
        over that step is counted here, trapezoidally, as the solver counts it.  Returns the
        step limit of the active penalty springs (inf if none; a constraint wall has none, and no
        forces: ``hold`` does its work)."""
        if self.constraint:
            return np.inf
        sums, peaks = self._step_in_one_process(x, v, dt, t) if self.one_process else self._step(x, v, dt, t)
        g = self.x.shape[1]
        self._load_before = self.force_a + self.friction_a
        self.force_a, self.friction_a = sums[:g], sums[g:2 * g]
        work, friction_work, load, loaded_area, active = sums[2 * g:].tolist()
        omega2, max_pressure, deepest = peaks.tolist()
        self._step_sizes = (math.sqrt(sum(c * c for c in self.force_a.tolist())),
                            math.sqrt(sum(c * c for c in self.friction_a.tolist())), max_pressure, load, loaded_area)
        self.active = int(active)
        self.max_penetration = max(self.max_penetration, deepest)
        if self._offset0 is not None and self.preload is None and t >= self.spec.interference_time:
            self.preload = self._pressure()
        self.work += 0.5 * dt * work
        self.friction_work += 0.5 * dt * friction_work
        return self._stable_step(omega2) if omega2 > 0.0 else np.inf     # active or arriving springs

    def _step(self, x: np.ndarray, v: np.ndarray, dt: float, t: float) -> tuple[np.ndarray, np.ndarray]:
        """The step's forces on the compact nodes and the totals ``kernels.totals`` returns, reduced over the
        ranks: a pair under MPI (``_step_in_one_process`` does the same in one process).  Collective under
        MPI."""
        self._gather(x, v)
        kernels.clear(self.own_nodes, self.f, self.ff, self.stiff)
        active = 0
        deepest = 0.0
        for p in self.passes:
            if isinstance(p, _RigidPass):
                p.t = t
        if self._offset0 is not None:
            self._push_out_overlaps(t)
        apart, search_due = self._survey()          # the same answer on every rank
        if not apart:
            active = self._springs(search_due, self.spec.damping, self.soft_scale, dt, self.friction)
            for p in self.passes:
                deepest = max(deepest, -p.gap.min())
        else:
            for p in self.passes:
                p.ft[:] = 0.0
        sums, peaks = kernels.totals(self.f, self.ff, self._f_old, self._ff_old, self.v, self.stiff, self.mass,
                                     self.own_a, self.own_area_a, self.own_nodes, active, deepest)
        if self.parallel:
            self.model.comm.Allreduce(MPI.IN_PLACE, sums, op=MPI.SUM)
            self.model.comm.Allreduce(MPI.IN_PLACE, peaks, op=MPI.MAX)
        return sums, peaks

    def _step_in_one_process(self, x: np.ndarray, v: np.ndarray, dt: float, t: float) -> tuple[np.ndarray, np.ndarray]:
        """``_step`` in one process (``pair_step``): for two surfaces in two compiled calls with a search
        between them when one is due, against a rigid surface in one.  The same kernels in the same order,
        so the same forces to the bit.  (The initial overlaps' push-out, which ``_step`` does after the
        gather, changes only the offsets, which neither the gather nor the box test reads.)"""
        if self._offset0 is not None:
            self._push_out_overlaps(t)
        if self.b is None:
            r = self.passes[0]
            r.t = t
            return pair_step.rigid_step(x, v, self.exchange.local, self.exchange.slot, self.x, self.v, self.own_nodes,
                                        self.f, self.ff, self.stiff, self.margin, dt, *r.step_arrays(), self.mass,
                                        self.spec.damping, self.soft_scale, self.depth, self.friction, self._f_old,
                                        self._ff_old, self.own_a, self.own_area_a)
        p, q = self.passes
        apart, search_due = pair_step.open_step(x, v, self.exchange.local, self.exchange.slot, self.x, self.v,
                                                self.own_nodes, self.f, self.ff, self.stiff, p.own, q.own,
                                                self.x_search, self.searches > 0, self._least, self.margin)
        if not apart and search_due:
            self._search()
        sums, peaks, p.count, q.count = pair_step.close_step(
            apart, dt, *p.step_arrays(), *q.step_arrays(), self.x, self.v, self.mass, self.spec.damping,
            self.soft_scale, self.depth, self.friction, self.owned, self.has_friction, self.f, self.ff, self.stiff,
            self._f_old, self._ff_old, self.own_a, self.own_area_a, self.own_nodes)
        return sums, peaks

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
        (a mean contact pressure; in axisymmetry the area is the swept one, 2 pi r per unit length).
        Collective under MPI."""
        load = float(np.linalg.norm(self.f[self.own_a], axis=1).sum())
        if self.parallel:
            load = self.model.comm.allreduce(load, op=MPI.SUM)
        area = float(self.a.area.sum())
        return {"time": self.spec.interference_time, "force_on_a": self.force_a.tolist(), "normal_load": load,
                "area": area, "mean_pressure": load / area}

    def _stable_step(self, omega2: float) -> float:
        """2 / omega of the active springs alone, omega^2 <= max_i stiff_i / m_i (Gershgorin, ``omega2``),
        shortened by the contact damping: (2 / omega)(sqrt(1 + zeta^2) - zeta) (Belytschko et al., eq. 6.2.28)."""
        zeta = self.spec.damping
        return 2.0 / math.sqrt(omega2) * (math.sqrt(1.0 + zeta * zeta) - zeta)

    def add_forces(self, f: np.ndarray):
        """Add this pair's forces on the nodes this rank owns into the solver's array ``f``."""
        self.exchange.add_to(self.f, f)
        self.exchange.add_to(self.ff, f)

    def account(self, dt: float, t: float, body_velocities):
        """After a step ending at t: impulse, peak forces, open/closed intervals, restitution velocities.
        Collective when contact opens or closes (``body_velocities`` reduces over ranks).

        The impulse is the force's trapezoidal integral, dt (f_n + f_n+1) / 2: what the central-difference
        update puts into the bodies' mean velocities at t (v_n+1/2 takes a_n over (dt_n-1 + dt_n) / 2, and
        v(t_n+1) = v_n+1/2 + dt_n a_n+1 / 2), so a body that only this pair pushes changes its momentum by
        exactly the impulse (dt f_n+1 differed by half a step's force at the end, 1e-3 of a Taylor bar's)."""
        if not self.constraint:          # a constraint wall adds its impulses as they are (``hold``)
            self.impulse += 0.5 * dt * (self._load_before + self.force_a + self.friction_a)
        force, friction, pressure, load, loaded_area = self._step_sizes
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
                # the mean velocities at t_{n+1} hold all the impulse so far: take back what this pair
                # has transferred
                transferred = self.impulse
                self.v_before = body_velocities().copy()
                masses = self.model.body_mass
                self.v_before[self.a.body] -= transferred / masses[self.a.body]
                if self.b is not None:
                    self.v_before[self.b.body] += transferred / masses[self.b.body]
        elif not closed and self.intervals and self.intervals[-1][1] is None:
            self.intervals[-1][1] = t
            self.v_after = body_velocities()

    def start(self, x: np.ndarray, v: np.ndarray) -> tuple[int, float]:
        """At t = 0: take every initial penetration as its node's zero; returns (nodes, deepest [m]).
        A constraint wall refuses nodes that start behind it.  Collective under MPI."""
        self._gather(x, v)
        if self.constraint:
            gaps = self.passes[0].gaps(self.x)
            deepest = float(max(-gaps.min(), 0.0)) if len(gaps) else 0.0
            if self.parallel:
                deepest = self.model.comm.allreduce(deepest, op=MPI.MAX)
            if deepest > 1e-6 * self.smallest_facet:
                raise ModelError(f"contact '{self.name}': surface '{self.spec.a}' starts up to {deepest * 1e3:.4g} mm "
                                 f"behind the constraint wall, which would put those nodes on it in the first "
                                 f"step: move the wall's point or the body")
            return self.initial_overlap
        apart, search_due = self._survey()
        if apart:
            return self.initial_overlap
        for p in self.passes:
            p.offset[:] = -1e300          # accept any initial penetration as the zero
        self._springs(search_due, 0.0, 0.0, 0.0, np.zeros(3))
        tiny = -1e-6 * self.depth                 # round-off of coincident meshes is no overlap
        offsets = []
        for p in self.passes:
            p.offset[:] = np.minimum(p.gap, 0.0)
            p.offset[p.offset > tiny] = 0.0
            offsets.append(p.offset)
        kernels.clear(self.own_nodes, self.f, self.ff, self.stiff)
        found = np.array([sum(float((o < 0).sum()) for o in offsets)])
        deepest = np.array([max(float(-o.min()) for o in offsets)])
        if self.parallel:
            self.model.comm.Allreduce(MPI.IN_PLACE, found, op=MPI.SUM)
            self.model.comm.Allreduce(MPI.IN_PLACE, deepest, op=MPI.MAX)
        nodes = int(found[0])
        self.initial_overlap = (nodes, float(deepest[0]) if nodes else 0.0)
        if nodes and self.spec.interference_time > 0.0:
            self._offset0 = [o.copy() for o in offsets]
        return self.initial_overlap

    # ------------------------------------------------------ force source
    def rows(self) -> np.ndarray:
        return self.exchange.local

    def begin(self, x: np.ndarray, v: np.ndarray) -> list[str]:
        nodes, deepest = self.start(x, v)
        if not nodes:
            return []
        said = f"contact '{self.name}': {nodes} nodes start inside the other surface (deepest {deepest * 1e3:.4g} mm)"
        if self.spec.interference_time > 0.0:
            return [f"{said}; the overlap is pushed out over {self.spec.interference_time:.4g} s (interference): "
                    f"a preload"]
        return [f"{said}; each keeps its initial penetration as its zero (give the contact an interference time "
                f"to push it out as a preload)"]

    def apply(self, x: np.ndarray, u: np.ndarray, v: np.ndarray, dt: float, t: float, f: np.ndarray) -> float:
        limit = self.compute(x, v, dt, t)
        self.add_forces(f)
        return limit

    def said(self, t: float) -> list[str]:
        if self.preload is None or self._said_preload:
            return []
        self._said_preload = True
        return [f"t = {t:.6g} s: contact '{self.name}' has pushed its initial overlap out: preload "
                f"{self.preload['normal_load']:.5g} N, mean contact pressure "
                f"{self.preload['mean_pressure'] / 1e6:.5g} MPa over {self.preload['area']:.4g} m^2"]

    def energy(self) -> float:
        return -(self.work + self.friction_work)

    def columns(self, axes) -> list[tuple[str, str]]:
        # the forces on surface a: normal (penalty and contact damping) and friction, as vectors
        return ([(f"contact.{self.name}.normal_{a}", "N") for a in axes]
                + [(f"contact.{self.name}.friction_{a}", "N") for a in axes])

    def history(self) -> list[float]:
        return [*self.force_a, *self.friction_a]

    # ------------------------------------------------------------ results
    def surfaces(self) -> list:
        """The pair's surfaces (one against a rigid wall)."""
        return [s for s in (self.a, self.b) if s is not None]

    def interference_overlaps(self) -> tuple[np.ndarray, np.ndarray]:
        """The area [m^2] and initial overlap [m] of each node of surface a this rank owns that starts
        inside the other surface, when an interference pushes the overlaps out (empty otherwise)."""
        if self._offset0 is None:
            return np.zeros(0), np.zeros(0)
        depth = -self._offset0[0][self.passes[0].rows]
        inside = depth > 0.0
        return self.own_area_a[inside], depth[inside]

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
        return {"surfaces": [self.spec.a, self.spec.b or self.spec.rigid.kind], "method": self.spec.method,
                "penalty": self.spec.penalty, "damping_ratio": self.spec.damping,
                "friction": {"static": self.spec.friction[0], "dynamic": self.spec.friction[1],
                             "decay": self.spec.friction[2]},
                "impulse_on_a": self.impulse.tolist(), "max_normal_force": self.max_force,
                "max_friction_force": self.max_friction,
                "max_pressure": self.max_pressure, "pressure_at_max_force": self.pressure_at_max_force,
                "contact_energy": self.energy(),
                "friction_work": self.friction_work, "max_penetration": self.max_penetration,
                "smallest_facet": self.smallest_facet,
                "intervals": self.intervals, "restitution": self.restitution(),
                "initial_overlap": {"nodes": self.initial_overlap[0], "deepest": self.initial_overlap[1]},
                "interference_preload": self.preload,
                "searches": self.searches}

"""Central-difference (leapfrog) time integration as a generator of steps.

    a_n        = M^-1 (f_ext_n - f_int_n)                       lumped (diagonal) mass
    v_{n+1/2}  = v_{n-1/2} + (dt_{n-1/2} + dt_{n+1/2}) / 2 a_n  variable step
    x_{n+1}    = x_n + dt_{n+1/2} v_{n+1/2}                     updated Lagrangian

(Belytschko, Liu & Moran, *Nonlinear Finite Elements*, Box 6.1.)  Each ``next()`` of
``ExplicitSolver.steps()`` advances one step in named phases (velocity, constraints,
position, internal force, loads, acceleration, energy) and yields a read-only ``Step`` record
(step, time, dt, stable step, a copy of the energies, the solver's messages), so that a progress
bar, monitors and the API's ``on_step`` see the run without being able to change it; history
recorders and field writers read the fields from the solver they were built on.

Energy bookkeeping (every step, summed over owned nodes and reduced over ranks):
kinetic ``0.5 m v^2``; internal work ``int f_int . du`` (trapezoidal), of which the
stiffness-proportional damping part is counted separately; mass-damping dissipation;
external work of loads and of prescribed velocities (reactions).  The balance
``kinetic + internal + damping - external - initial kinetic`` is zero for an exact
integrator; its size relative to the largest energy in play is ``balance_error``.
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, field, replace

import numpy as np
from dolfinx import fem
from mpi4py import MPI

from .. import compat
from ..errors import UnstableRun
from ..model import Model
from ..forces import registry
from ..elements import kernels
from ..elements.blocks import no_peak
from ..materials.layout import STATE_SIZE
from ..materials.objective import rotation_of_angular_velocity
from ..materials.update import is_elastic_only
from . import guards, nodal
from .band import BandDamping
from .energy_scale import energy_scale


# A lumped oscillator (a discrete spring, a liquid against a rigid body) is the model itself, not a mesh
# mode whose error is the mesh's: its period must be resolved, not just kept stable.  The central
# difference shortens a period by (omega dt)^2 / 24 (omega_h dt = 2 arcsin(omega dt / 2); Hughes, *The
# Finite Element Method*, 9.3): at 20 steps a period, omega dt = 0.31 and the period is 0.4% short; at the
# stable step 2 / omega with the safety factor 0.9 (3.5 steps a period) it is 20% short.
LUMPED_STEPS_PER_PERIOD = 20


@dataclass
class Energies:
    kinetic: float = 0.0
    internal: float = 0.0          # stored (elastic) energy = internal work less all the parts below
    damping: float = 0.0           # dissipated by Rayleigh damping (mass and stiffness parts) and band damping
    hourglass: float = 0.0         # work of the hourglass forces (one-point elements)
    plastic: float = 0.0           # plastic work int sigma : d eps_p dV
    bulk_viscosity: float = 0.0    # dissipated by the artificial bulk viscosity
    contact: float = 0.0           # taken up by contact (penalty, contact damping, friction), discrete
                                   # springs, liquid cavities and a penetrated target = -their work on
                                   # the bodies
    external: float = 0.0          # work of loads and prescribed velocities
    initial: float = 0.0           # kinetic energy at t = 0
    peak: float = 0.0              # largest energy in play so far (the balance reference)
    scale: float = 0.0             # the energy the run will put in play, known at t = 0 (``energy_scale``)

    @property
    def balance(self) -> float:
        return (self.kinetic + self.internal + self.damping + self.hourglass + self.plastic
                + self.bulk_viscosity + self.contact - self.external - self.initial)

    @property
    def largest(self) -> float:
        """The largest energy in play so far, or the energy the run will put in play (``energy_scale``) if
        that is larger: the scale of the energy checks."""
        return max(self.peak, self.initial, self.scale)

    @property
    def balance_error(self) -> float:
        """|balance| as a fraction of the largest energy in play."""
        return abs(self.balance) / max(self.largest, 1e-300)


@dataclass(frozen=True)
class Step:
    """What the time loop yields after every step: numbers, not the solver (which keeps the state)."""
    step: int                  # steps taken so far
    t: float                   # time reached [s]
    dt: float                  # the step just taken [s]
    dt_stable: float           # the elements' stable step at t, before the safety factor [s]
    energy: Energies           # a copy of the energy account at t [J]
    messages: tuple = ()       # what the solver had to say during this step


@dataclass
class RigidState:
    center: np.ndarray
    velocity: np.ndarray
    momentum_angular: np.ndarray = field(default_factory=lambda: np.zeros(3))
    rotation: np.ndarray = field(default_factory=lambda: np.eye(3))
    force: np.ndarray = field(default_factory=lambda: np.zeros(3))    # resultant at t_n [N]
    torque: np.ndarray = field(default_factory=lambda: np.zeros(3))   # about the centre, 3D [N m]


@dataclass
class PhaseTimes:
    """Wall time spent in each phase of the step [s] (for ``shockfem bench``): the nodal update (velocity,
    constraints, position), the internal force (the element pass), contact (and loads, springs, liquids,
    target), and the rest (acceleration, energy bookkeeping, contact accounting)."""
    internal_force: float = 0.0
    update: float = 0.0
    contact: float = 0.0
    energy: float = 0.0
    total: float = 0.0


class ExplicitSolver:
    """Holds the state of a run and advances it; see the module docstring."""

    def __init__(self, model: Model, initial_velocity=None):
        """``initial_velocity(x) -> v``, arrays (nodes, gdim), replaces the scene's body velocities."""
        self.model = model
        self.comm = model.comm
        self.parallel = self.comm.size > 1
        self._nodal_fields()
        self._force_sources()
        self._element_state()
        self._masses()
        self._constraints()
        self._counters()
        self._start(initial_velocity)

    # ----------------------------------------------------------------- set-up
    def _nodal_fields(self):
        """Positions, velocities, displacements, accelerations and forces per node (gdim columns); the
        velocity, internal force and displacement are views of dolfinx functions (for ghost updates and
        output)."""
        m = self.model
        gdim = m.gdim
        self._v_fn = fem.Function(m.V, name="velocity")
        self._f_fn = fem.Function(m.V, name="internal_force")
        self.u_fn = fem.Function(m.V, name="displacement")
        self.v = self._v_fn.x.array.reshape(-1, gdim)
        self.f_int = self._f_fn.x.array.reshape(-1, gdim)
        self.u = self.u_fn.x.array.reshape(-1, gdim)
        self.x = m.X0.copy()
        self.a = np.zeros_like(self.x)
        self.f_ext = np.zeros_like(self.x)
        self.f_con = np.zeros_like(self.x)

    def _force_sources(self):
        """The force sources (``forces/registry.py``) and gravity."""
        m = self.model
        self.dt_contact = np.inf       # smallest stable step of the force sources' stiffness
        self._said_contact_dt = False
        self._said_accuracy_step = False
        self.log_messages: list[str] = []
        # contact pairs, springs, liquid cavities, a target: everything that pushes besides the elements
        self.sources = registry.build(m)
        self._walls = [source for source in self.sources if source.holds_motion]     # held in ``advance``
        self._contact_rows = self._rows_with_contact_forces()
        self.f_gravity = (m.mass[:, None] * np.asarray(m.gravity)[None, :] if m.gravity
                          else None)
        # whether f_ext or f_con can be non-zero; if not, the nodal passes leave them unread
        self.forces_applied = bool(m.loads or self.f_gravity is not None or self.sources)

    def _element_state(self):
        """Stresses and point state, the element pass, hourglass resultants and the per-body works."""
        m = self.model
        gdim = m.gdim
        self.sigma = np.zeros((len(m.dofmap), m.num_quadrature_points, 6))
        # state per point (plastic strain, its rate, back stress, slot closure); a stub if no body needs one
        self.plastic_state = np.zeros((len(m.dofmap), m.num_quadrature_points, STATE_SIZE)
                                      if m.point_state else (1, 1, STATE_SIZE))
        # the element kernels' copies without law calls when every material is elastic (elements/)
        elastic_only = is_elastic_only(m.params)
        self._element_pass = kernels.element_pass(m.cell_kind, m.one_point, elastic_only)
        # stiffness-form hourglass resultants of one-point cells (2 per quad, 4 x 3 per hex; none at Gauss points)
        self.hourglass = np.zeros((len(m.dofmap), (2 if gdim == 2 else 12) if m.one_point else 0))
        # per row of params, the peak von Mises stress the pass has seen, with when and where (``blocks``)
        self.peak = no_peak(len(m.params))
        # per row of params, this rank's share: the stresses' work (stored and plastic energy), the hourglass
        # work and the plastic work [J], summed per body (``_row_body``) for per-body energies and warnings
        self.body_energy = np.zeros((len(m.params), 3))
        self._row_body = m.row_body

    def _masses(self):
        """Owned nodes, the inverse masses and the masses of the kinetic energy, per node and per dof."""
        m = self.model
        gdim = m.gdim
        self.owned = np.zeros(len(self.x), dtype=bool)
        self.owned[:m.num_owned] = True
        self.inv_mass = np.where(m.mass > 0, 1.0 / np.where(m.mass > 0, m.mass, 1.0), 0.0)
        # the nodal kinetic energy leaves rigid bodies out: theirs is their own (``_rigid_loads``)
        self.kinetic_mass = m.mass.copy()
        for rb in m.rigid:
            self.kinetic_mass[rb.nodes] = 0.0
        # the same per dof, shaped as the velocity, for the nodal passes (``nodal``: they vectorise so)
        self._mass_dofs = np.repeat(m.mass[:, None], gdim, axis=1)
        self._inv_mass_dofs = np.repeat(self.inv_mass[:, None], gdim, axis=1)
        self._kinetic_mass_dofs = np.repeat(self.kinetic_mass[:, None], gdim, axis=1)

    def _constraints(self):
        """The constrained dofs, their masses, and where each constraint's dofs sit among them."""
        m = self.model
        gdim = m.gdim
        self._constrained_dofs = (np.unique(np.concatenate([c.dofs for c in m.constraints]))
                                  if m.constraints else np.zeros(0, dtype=np.int64))
        self.constrained = np.zeros(self.x.shape, dtype=np.bool_)
        self.constrained.reshape(-1)[self._constrained_dofs] = True
        # for the reactions' work: the mass behind each constrained dof, and which dofs this rank owns
        self._constrained_mass = self._mass_dofs.reshape(-1)[self._constrained_dofs]
        self._constrained_owned = self._constrained_dofs < m.num_owned * gdim
        # where each constraint's dofs sit among them (``advance``, ``_prescribed_motion``)
        self._constraint_positions = [np.searchsorted(self._constrained_dofs, c.dofs) for c in m.constraints]
        # a step's scratch (``advance``): the constrained dofs' velocities before it and their prescribed ones
        self._constrained_before = np.zeros(len(self._constrained_dofs))
        self._constrained_held = np.zeros(len(self._constrained_dofs))
        # fixed, symmetry and axis conditions (and constant driven ends) hold the same velocity at every t:
        # filled once, and their rate is zero (``advance``, ``_prescribed_motion`` evaluated them every step,
        # ~10 us a step on a 3,200-cell contact run with a history row every step)
        self._prescribed_constant = all(len(c.values) == 1 for c in m.constraints)
        if self._prescribed_constant:
            self._prescribed_velocities(0.0, self._constrained_held)
            # ``_prescribed_motion``'s velocity and rate, once: (c - c) / (after - before) is 0 exactly
            self._prescribed = (self._constrained_held.copy(), np.zeros(len(self._constrained_dofs)))

    def _counters(self):
        """Time, step, the stable step, the energy account and the scratch of the step's reductions."""
        m = self.model
        gdim = m.gdim
        self.t = 0.0
        self.step = 0
        self.dt = 0.0                 # last step taken, t_n - t_{n-1}
        self.dt_stable = np.inf       # critical step of the current configuration (no safety factor)
        self.critical_cell = -1       # the cell that sets it (on the rank that holds it; -1 elsewhere)
        self.energy = Energies()
        self.times = PhaseTimes()
        self.rigid_states = [RigidState(rb.center0.copy(), np.zeros(gdim)) for rb in m.rigid]
        self._prescribed_at = -1        # the step ``_prescribed_motion`` was last evaluated at
        self._body_sums_at = None       # (step, t) ``_body_sums`` was last evaluated at
        self._step_largest = np.zeros(2)    # the buffers of a step's two reductions over the ranks
        self._step_sums = np.zeros(15)
        self._reaction_dofs = None      # ``reactions``' held dofs by region, made at its first call

    def _start(self, initial_velocity):
        """The state at t = 0: the velocities, every force and the accelerations, the sources' first words,
        the initial kinetic energy and the stable step the collapse is measured against."""
        self._set_initial_velocity()
        if initial_velocity is not None:
            self.v[:] = initial_velocity(self.x)
        self._internal_force(0.0)
        # band-damped bodies' Maxwell terms, driven by the internal force from here on (None if no band)
        self.band = BandDamping.of(self.model, self.f_int, self.u)
        self._external_force(0.0)
        for source in self.sources:
            self.log_messages += source.begin(self.x, self.v)
        self._contact_forces(0.0)
        self._acceleration()
        self._rigid_loads(0.0)
        self.energy.initial = self.energy.kinetic = self._kinetic_energy(self.v)
        self.energy.peak = self.energy.initial
        self.energy.scale = energy_scale(self.model, self.contacts, self.energy.initial)
        self.dt_first = self.dt_stable    # the reference of a collapsing step (``steps``)

    def start_event(self):
        """After a preload stage (``solver/preload.py``): the clock back to t = 0, the scene's initial
        velocities on the settled state (a step of 0 before the first, as at the start), their kinetic energy."""
        self.t, self.dt = 0.0, 0.0
        self._set_initial_velocity()
        self.energy.kinetic = self._kinetic_energy(self.v)

    def _set_initial_velocity(self):
        m = self.model
        for i, body in enumerate(m.bodies):
            nodes = m.node_body == i
            self.v[nodes] = np.asarray(body.velocity)
            if body.spin and m.gdim == 3:
                # spin about the body's own axis (turned with it) through its position
                rel = self.x[nodes] - np.asarray(body.position)
                self.v[nodes] += np.cross(body.spin * np.asarray(body.axis), rel)
        for k, (rb, rs) in enumerate(zip(m.rigid, self.rigid_states)):
            body = m.bodies[rb.index]
            rs.velocity = np.asarray(body.velocity, dtype=float)
            if m.gdim == 3 and body.spin:
                omega = body.spin * np.asarray(body.axis)
                rs.momentum_angular = rb.inertia0 @ omega
                # rigid-body spin about the axis through the centre of mass parallel to the body's own
                self.v[rb.nodes] = rs.velocity + np.cross(omega, rb.rel0)

    # ---------------------------------------------------------------- phases
    def _sum(self, local: float) -> float:
        return self.comm.allreduce(local, op=MPI.SUM) if self.parallel else local

    def _kinetic_energy(self, v: np.ndarray) -> float:
        o = self.owned
        return self._sum(0.5 * float(np.dot(self.model.mass[o], (v[o] ** 2).sum(axis=1))))

    def _internal_force(self, dt: float) -> tuple[float, float, float, float]:
        """f_int at t_{n+1} (stresses updated over the step); returns this rank's powers of damping,
        hourglass control and bulk viscosity [W] and plastic work of the step [J] (``advance`` sums them
        over the ranks with the step's other sums).  Collective: the stable step and an inverted cell are
        reduced here."""
        m = self.model
        self.f_int[:] = 0.0
        try:
            dt_stable, critical, damping_power, viscosity_power, plastic_work, hourglass_power, bad = self._element_pass(
                m.kernel_cells, m.dofmap, m.cell_material, m.cell_sign, self.x, self.v, self.t, dt, m.N, m.dN, m.wq,
                m.kinematics, m.thickness, m.cell_kind, True, m.hourglass_form, m.hourglass_coefficient, m.params,
                m.curves, self.plastic_state, self.sigma, self.hourglass, self.f_int, self.body_energy, self.peak)
        except ZeroDivisionError:
            # a kernel divided by a zero that a non-finite state made (numba's Python error model): the
            # state, not the element, is at fault; name the first non-finite node
            self._check_finite(self._first_non_finite())
            raise
        if self.parallel:
            compat.reverse_add(self._f_fn)
            # one buffer reduction for both (every reduction is a point where the ranks wait for each other,
            # and mpi4py's pickled one of a small array costs ten times a buffer's): the smallest stable step,
            # as the largest -dt, and the highest inverted cell
            largest = self._step_largest
            largest[0], largest[1] = -dt_stable, bad
            self.comm.Allreduce(MPI.IN_PLACE, largest, op=MPI.MAX)
            dt_local = dt_stable
            dt_stable = -float(largest[0])
            critical = critical if dt_local == dt_stable else -1
            if largest[1] >= 0:         # some rank's cell inverted: every rank stops with that rank's words
                self._stop_on_every_rank(self._inverted(bad) if bad >= 0 else None)
        if bad >= 0:
            raise self._inverted(bad)
        if np.isfinite(dt_stable) and dt_stable < 1e300:
            self.dt_stable = dt_stable
            self.critical_cell = critical
        return damping_power, hourglass_power, viscosity_power, plastic_work

    def _external_force(self, t: float):
        if not self.model.loads and self.f_gravity is None:
            return                      # f_ext stays zero
        self.f_ext[:] = 0.0 if self.f_gravity is None else self.f_gravity
        flat = self.f_ext.reshape(-1)
        for load in self.model.loads:
            flat[load.dofs] += load.value(t) * load.shares

    def _contact_forces(self, dt: float):
        """The force sources' forces at t_{n+1} into f_con (v is v_{n+1/2}; ``forces/source.py``)."""
        if not self.sources:
            return
        # only the rows the sources write: a large mesh touches in a small face, and zeroing the whole array
        # was most of a step's contact time (0.45 of 0.95 ms at 205k nodes)
        self.f_con[self._contact_rows] = 0.0
        limit = np.inf
        for source in self.sources:
            limit = min(limit, source.apply(self.x, self.u, self.v, dt, self.t, self.f_con))
            self.log_messages += source.said(self.t)
        if np.isfinite(limit) and not self._said_contact_dt:
            self._said_contact_dt = True
            combined = 1.0 / np.sqrt(1.0 / self.dt_stable ** 2 + 1.0 / limit ** 2)
            self.log_messages.append(f"t = {self.t:.6g} s: contact, discrete springs and liquids lower the stable "
                                     f"step from {self.dt_stable:.4g} s to {combined:.4g} s while they act "
                                     f"(before the safety factor)")
        self.dt_contact = limit

    def _rows_with_contact_forces(self) -> np.ndarray:
        """The local nodes whose ``f_con`` a force source can write (each adds to its own nodes only:
        ``ForceSource.rows``); every other row stays zero from the start."""
        rows = [source.rows() for source in self.sources]
        return np.unique(np.concatenate(rows)).astype(np.int64) if rows else np.zeros(0, dtype=np.int64)

    def _acceleration(self):
        np.multiply(self.f_ext + self.f_con - self.f_int, self.inv_mass[:, None], out=self.a)

    # ------------------------------------------------------------ diagnosis
    def body_of_cell(self, cell: int) -> str:
        b = self.model.cell_body[cell] if 0 <= cell < len(self.model.cell_body) else -1
        return self.model.bodies[b].name if b >= 0 else "?"

    def _diagnose_cell(self, cell: int, what: str) -> str:
        tdim = self.model.meshed.mesh.topology.dim
        first = self.model.meshed.mesh.topology.index_map(tdim).local_range[0]
        centre = self.x[self.model.dofmap[cell]].mean(axis=0) if cell < len(self.model.dofmap) else None
        where = f" at x = {np.array2string(centre, precision=4)} m" if centre is not None else ""
        return (f"{what}: body '{self.body_of_cell(cell)}', element {first + cell}{where}, "
                f"t = {self.t:.6g} s (step {self.step}). Check the impact speed against the material, "
                f"refine the mesh there, or lower scene.safety_factor.")

    def _first_non_finite(self) -> int:
        """The first node of this rank whose position or velocity is not finite, or -1 (local: called
        where a kernel failed on this rank alone)."""
        bad = ~(np.isfinite(self.x).all(axis=1) & np.isfinite(self.v).all(axis=1))
        return int(np.argmax(bad)) if bad.any() else -1

    def _inverted(self, cell: int) -> UnstableRun:
        return UnstableRun(self._diagnose_cell(cell, "non-positive element volume (the element inverted)"),
                           self.t, self.body_of_cell(cell), cell)

    def _check_finite(self, node: int):
        error = self._not_finite(node)
        if error is not None:
            raise error

    def _not_finite(self, node: int) -> UnstableRun | None:
        """The stop for a non-finite state at this rank's ``node`` (None if ``node`` is -1)."""
        if node >= 0:
            body = self.model.bodies[self.model.node_body[node]].name
            return UnstableRun(f"the solution is not finite (NaN/Inf): body '{body}', node {node} at "
                               f"x = {np.array2string(self.x[node], precision=4)} m, t = {self.t:.6g} s "
                               f"(step {self.step}). The step {self.dt:.3g} s may exceed the stable step "
                               f"{self.dt_stable:.3g} s: lower scene.safety_factor.", self.t, body)
        return None

    def _stop_on_every_rank(self, mine: UnstableRun | None):
        """Raise on every rank the stop of the first rank that has one (``mine``: this rank's, or None), so
        that the diagnosis names the node or cell on the rank that holds it.  Collective: called once the
        ranks' reduction says that some rank has one."""
        said = None if mine is None else (mine.diagnosis, mine.body, mine.element)
        diagnosis, body, element = next(d for d in self.comm.allgather(said) if d is not None)
        raise UnstableRun(diagnosis, self.t, body, element)

    # ------------------------------------------------------------ the step
    def stable_step(self) -> float:
        """safety x the critical step; active contact springs add to the highest frequency of the nodes
        they join (omega^2 <= omega_elements^2 + omega_contact^2, Gershgorin), so the steps combine."""
        dt = self.dt_stable * (self.band.step_factor if self.band else 1.0)
        if math.isfinite(self.dt_contact):
            dt = 1.0 / math.sqrt(1.0 / dt ** 2 + 1.0 / self.dt_contact ** 2)
        return self.model.safety_factor * dt

    def accuracy_step(self) -> float:
        """The step's bound for accuracy [s]: 1 / ``LUMPED_STEPS_PER_PERIOD`` of the shortest period a force
        source sets (``ForceSource.period``: a discrete spring's, a liquid's against rigid bodies), and the
        scene's ``max_time_step``; inf if none.  Said once in the log when it sets the step."""
        shortest = min(self.sources, key=lambda s: s.period, default=None)
        period, source = (shortest.period, shortest.oscillator) if shortest else (math.inf, "")
        bound = period / LUMPED_STEPS_PER_PERIOD
        if 0.0 < self.model.max_time_step < bound:
            bound, source = self.model.max_time_step, "scene.max_time_step"
        if bound < self.stable_step() and not self._said_accuracy_step:
            self._said_accuracy_step = True
            why = (f"1/{LUMPED_STEPS_PER_PERIOD} of the period {period:.4g} s of {source}"
                   if source != "scene.max_time_step" else source)
            self.log_messages.append(f"t = {self.t:.6g} s: the step is bounded to {bound:.4g} s for accuracy "
                                     f"({why}), below the stable step {self.stable_step():.4g} s")
        return bound

    def advance(self, dt: float):
        """One central-difference step of size ``dt`` (t_n -> t_{n+1})."""
        m = self.model
        e = self.energy
        t0 = time.perf_counter()
        dt_avg = 0.5 * (self.dt + dt)
        if m.constraints:
            nodal.take_dofs(self.v, self._constrained_dofs, self._constrained_before)
        for wall in self._walls:
            wall.take_velocities(self.v)

        # velocity v_{n+1/2}; mass-proportional damping taken implicitly (its work on this rank)
        damping_work = nodal.update_velocity(self.v, self.a, dt_avg, m.alpha, self._mass_dofs, m.num_owned)

        # rigid bodies: velocities that carry their nodes to the rigid-body positions at t_{n+1}; the work of
        # their drives (the same on every rank: the bodies' states are)
        drive_work = 0.0
        for rb, rs in zip(m.rigid, self.rigid_states):
            drive_work += self._advance_rigid(rb, rs, dt, dt_avg)

        # prescribed velocities (and fixed / symmetry / axis constraints); the reactions' work is
        # m (v - v_free) . v_n over the constrained dofs
        reaction_work = 0.0
        if m.constraints:
            held = (self._constrained_held if self._prescribed_constant
                    else self._prescribed_velocities(self.t + 0.5 * dt, self._constrained_held))
            reaction_work = nodal.hold_dofs(self.v, self._constrained_dofs, held, self._constrained_mass,
                                            self._constrained_owned, self._constrained_before)
        # constraint walls: the nodes that would cross one by t_{n+1} put on it (its work, taken up by contact)
        wall_work = 0.0
        for wall in self._walls:
            wall_work += wall.hold(self.x, self.v, dt, dt_avg, self.t + dt)
        if self.parallel:
            self._v_fn.x.scatter_forward()

        # position, and the first halves of the work increments (forces at t_n)
        w_int, w_ext, w_con = nodal.update_position(self.x, self.u, self.v, dt, self.f_int, self.f_ext,
                                                    self.f_con, self.forces_applied, m.num_owned)
        self.t += dt
        self.dt = dt
        self.step += 1
        t1 = time.perf_counter()

        # internal and external forces at t_{n+1}
        damping_power, hourglass_power, viscosity_power, plastic_work = self._internal_force(dt)
        # band damping's Maxwell terms on the new internal force (what their dashpots took on this rank)
        band_loss = self.band.step(self.f_int, self.u, dt, m.num_owned) if self.band else 0.0
        t2 = time.perf_counter()
        self._external_force(self.t)
        self._contact_forces(dt)
        t_contact = time.perf_counter()

        # acceleration a_{n+1}, second halves of the work increments, kinetic energy
        w_int2, w_ext2, w_con2, kinetic, bad = nodal.finish_step(
            self.a, self.v, self.f_int, self.f_ext, self.f_con, self.forces_applied, self._inv_mass_dofs,
            self._kinetic_mass_dofs, self.constrained,
            dt, m.num_owned)
        if self.parallel:
            # the step's sums over the ranks in one buffer reduction, a non-finite node counted with them
            sums = self._step_sums
            sums[:] = (damping_work, reaction_work, damping_power, hourglass_power, viscosity_power,
                       plastic_work, band_loss, w_int, w_ext, w_con, w_int2, w_ext2, w_con2, kinetic, bad >= 0)
            self.comm.Allreduce(MPI.IN_PLACE, sums, op=MPI.SUM)
            (damping_work, reaction_work, damping_power, hourglass_power, viscosity_power, plastic_work, band_loss,
             w_int, w_ext, w_con, w_int2, w_ext2, w_con2, kinetic, non_finite) = sums.tolist()
            if non_finite:
                self._stop_on_every_rank(self._not_finite(bad))
        else:
            self._check_finite(bad)
        if m.rigid:
            kinetic += self._rigid_loads(dt)
        e.damping += damping_work
        e.damping += dt * damping_power + band_loss
        e.hourglass += dt * hourglass_power
        e.bulk_viscosity += dt * viscosity_power
        e.plastic += plastic_work
        e.internal += (w_int + w_int2 - dt * (damping_power + hourglass_power + viscosity_power) - plastic_work
                       - band_loss)
        e.external += w_ext + w_ext2 + reaction_work + drive_work
        e.contact -= w_con + w_con2 + wall_work
        for source in self.sources:
            source.account(dt, self.t, lambda: self.body_means()[0])
        e.kinetic = kinetic
        e.peak = max(e.peak, e.kinetic, abs(e.internal), abs(e.external), e.damping, abs(e.hourglass),
                     abs(e.contact), e.plastic, e.bulk_viscosity)
        t3 = time.perf_counter()
        self.times.update += t1 - t0
        self.times.internal_force += t2 - t1
        self.times.contact += t_contact - t2
        self.times.energy += t3 - t_contact
        self.times.total += t3 - t0

    def _advance_rigid(self, rb, rs: RigidState, dt: float, dt_avg: float) -> float:
        """Move a rigid body by its resultant force and torque at t_n (``_rigid_loads``), its driven directions
        at their prescribed velocity at t_{n+1/2}; returns the drives' work over the step [J]: the impulse
        M (v - v_free) times the mean velocity (v_{n-1/2} + v_{n+1/2}) / 2, as a held dof's
        (``nodal.hold_dofs``), and a held turn's likewise."""
        m = self.model
        before = rs.velocity
        rs.velocity = rs.velocity + dt_avg * rs.force / rb.mass
        work = 0.0
        for drive in rb.drives:
            free, new = rs.velocity[drive.component], drive.value(self.t + 0.5 * dt)
            rs.velocity[drive.component] = new
            work += rb.mass * (new - free) * 0.5 * (before[drive.component] + new)
        center_new = rs.center + dt * rs.velocity
        if m.gdim == 3:
            inertia = rs.rotation @ rb.inertia0 @ rs.rotation.T
            if rb.held_turn:        # the torque impulse that stops it, times its mean angular velocity
                turning = np.linalg.solve(inertia, rs.momentum_angular) if rb.mass > 0 else np.zeros(3)
                work -= float((rs.momentum_angular + dt_avg * rs.torque) @ turning) * 0.5
                rs.momentum_angular = np.zeros(3)
            else:
                rs.momentum_angular = rs.momentum_angular + dt_avg * rs.torque
            omega = np.linalg.solve(inertia, rs.momentum_angular) if rb.mass > 0 else np.zeros(3)
            rs.rotation = rotation_of_angular_velocity(omega, dt) @ rs.rotation
            x_new = center_new + rb.rel0 @ rs.rotation.T
            self.v[rb.nodes] = (x_new - self.x[rb.nodes]) / dt
        else:
            nodal.translate_rigid(self.x, self.v, rb.nodes, rs.velocity, dt)
        rs.center = center_new
        return work

    def _rigid_center_velocity(self, rb, rs: RigidState, dt: float) -> np.ndarray:
        """A rigid body's centre velocity at t_{n+1} as the kinetic energy counts it: v_{n+1/2} + dt/2 F / M,
        a driven direction at its v_{n+1/2} (as ``nodal.finish_step`` counts a held dof: the drive's work
        is counted to the half step)."""
        v_c = rs.velocity + 0.5 * dt * rs.force / rb.mass
        for drive in rb.drives:
            v_c[drive.component] = rs.velocity[drive.component]
        return v_c

    def _rigid_loads(self, dt: float) -> float:
        """The resultant force (and torque, 3D) on every rigid body at t_{n+1}, kept for its next
        advance, and the bodies' kinetic energy at t_{n+1}: 1/2 M |v_c|^2 (+ 1/2 omega . L), with
        v_c = v_c,n+1/2 + dt/2 F / M and L likewise.  The nodes' own f / m would miss it: a load spread
        unevenly over a rigid surface (a nose in a target) gives each node a different acceleration,
        so those nodes are left out of the nodal sum.  Collective; the same value on every rank."""
        m = self.model
        kinetic = 0.0
        for rb, rs in zip(m.rigid, self.rigid_states):
            force, torque = np.empty(m.gdim), np.empty(3)
            nodal.rigid_resultant(self.f_ext, self.f_con, self.f_int, self.x, rs.center, rb.nodes, rb.num_owned,
                                  force, torque)
            rs.force = self._sum(force)
            if m.axisymmetric:
                rs.force[0] = 0.0   # a ring's radial forces cancel: an axisymmetric rigid body moves along z
            v_c = self._rigid_center_velocity(rb, rs, dt)
            kinetic += 0.5 * rb.mass * float(v_c @ v_c)
            if m.gdim == 3 and not rb.held_turn:
                rs.torque = self._sum(torque)
                momentum = rs.momentum_angular + 0.5 * dt * rs.torque
                inertia = rs.rotation @ rb.inertia0 @ rs.rotation.T
                kinetic += 0.5 * float(np.linalg.solve(inertia, momentum) @ momentum) if rb.mass > 0 else 0.0
        return kinetic

    def steps(self, end_time: float):
        """Yield a ``Step`` after every step until ``end_time`` (from wherever the solver stands: a run
        restored from a checkpoint goes on from there); stop with a diagnosis when the elements' stable step
        collapses or their stored energy goes negative (``guards.step_collapse``, ``guards.energy_created``)."""
        said = len(self.log_messages)
        while self.t < end_time * (1 - 1e-12):
            guards.step_collapse(self)
            dt = min(self.stable_step(), self.accuracy_step(), end_time - self.t)
            self.advance(dt)
            guards.energy_created(self)
            yield Step(self.step, self.t, dt, self.dt_stable, replace(self.energy), tuple(self.log_messages[said:]))
            said = len(self.log_messages)

    def critical_cell_said(self) -> str:
        """", body 'B' element N at x = ..." of the cell that sets the stable step (the most crushed), or "".
        Collective: the rank holding it tells the others."""
        cell = self.critical_cell
        if self.parallel:
            holders = self.comm.allgather(self._diagnose_cell(cell, "") if cell >= 0 else None)
            return next((h for h in holders if h), "")
        return self._diagnose_cell(cell, "") if cell >= 0 else ""

    # ------------------------------------------------------------ results
    def _sources_of(self, kind: str) -> list:
        return [source for source in self.sources if source.kind == kind]

    @property
    def contacts(self) -> list:
        """The contact pairs among the force sources."""
        return self._sources_of("contact")

    @property
    def springs(self) -> list:
        """The discrete springs among the force sources."""
        return self._sources_of("spring")

    @property
    def cavities(self) -> list:
        """The liquid cavities among the force sources."""
        return self._sources_of("cavity")

    @property
    def target(self):
        """The penetrated target among the force sources, or None."""
        return next(iter(self._sources_of("penetration")), None)

    def body_energies(self) -> dict[str, np.ndarray]:
        """Per body [J]: ``kinetic`` at t_n (a rigid body's own, with its spin in 3D); ``internal``, the
        work of the stresses, stored and plastic energy ((sigma_n + sigma_n+1)/2 : d integrated cell by
        cell, so its sum agrees with the nodal account's ``internal + plastic`` to the time step's order,
        not to round-off); ``plastic``, the plastic work in it; ``hourglass``, the hourglass forces' work.
        Collective."""
        m = self.model
        _, _, kinetic, work = self._body_sums()
        kinetic = kinetic.copy()
        for rb, rs in zip(m.rigid, self.rigid_states):     # at t_n, as ``_rigid_loads`` takes it
            v_c = self._rigid_center_velocity(rb, rs, self.dt)
            kinetic[rb.index] += 0.5 * rb.mass * float(v_c @ v_c)
            if m.gdim == 3 and not rb.held_turn:
                momentum = rs.momentum_angular + 0.5 * self.dt * rs.torque
                inertia = rs.rotation @ rb.inertia0 @ rs.rotation.T
                kinetic[rb.index] += 0.5 * float(np.linalg.solve(inertia, momentum) @ momentum)
        return {"kinetic": kinetic, "internal": work[:, 0].copy(), "hourglass": work[:, 1].copy(),
                "plastic": work[:, 2].copy()}

    def motion(self, nodes=slice(None)) -> tuple[np.ndarray, np.ndarray]:
        """Velocity and acceleration of ``nodes`` (all by default) at t [m/s, m/s^2]: v_{n+1/2} + dt/2 a_{n+1}
        and a_{n+1} (with the mass damping's -alpha v) where the dof is free; where a velocity is prescribed (fixed, symmetry, the axis, a
        driven end), that velocity at t and its rate: there M^-1 f is the push the constraint cancels,
        not the motion (a bar driven at a constant speed would show its wave front's force as acceleration)."""
        v = self.v[nodes] + 0.5 * self.dt * self.a[nodes]
        a = self.a[nodes].copy()
        if self.model.alpha:
            a -= self.model.alpha * v       # mass-proportional damping: a force the solver applies implicitly
        if self.model.constraints:
            prescribed_v, prescribed_a = self._prescribed_motion()
            held = self.constrained[nodes]
            # the held entries' flat dofs, and where each sits among the constrained dofs
            flat = (np.arange(len(self.v))[nodes][:, None] * self.model.gdim + np.arange(self.model.gdim))[held]
            at = np.searchsorted(self._constrained_dofs, flat)
            v[held] = prescribed_v[at]
            a[held] = prescribed_a[at]
        return v, a

    def reaction_regions(self) -> list[tuple[str, list[int]]]:
        """The supports whose reactions ``reactions`` gives: every region with a fixed, symmetry or
        prescribed-velocity condition (the axis of an axisymmetric mesh left out), with the components
        it holds, then every driven rigid body, named by the body, with its driven components.  The same on
        every rank."""
        held: dict[str, set] = {}
        for con in self.model.constraints:
            if con.region != "axis":
                held.setdefault(con.region, set()).update((con.dofs % self.model.gdim).tolist())
        if self.parallel:
            merged = {}
            for part in self.comm.allgather(held):
                for region, comps in part.items():
                    merged.setdefault(region, set()).update(comps)
            held = merged
        driven = [(rb.name, sorted(d.component for d in rb.drives)) for rb in self.model.rigid if rb.drives]
        return [(region, sorted(held[region])) for region in sorted(held)] + driven

    def reactions(self) -> list[np.ndarray]:
        """The force each support (``reaction_regions``) applies to the body at t [N], (gdim,) each: over
        its held dofs, m a_prescribed + alpha m v_prescribed - (f_ext + f_con - f_int), what the
        condition adds to the forces for the dofs to follow it (the mass damping's force included; a dof
        held by two regions counts in each).  Collective."""
        m = self.model
        if self._reaction_dofs is None:     # each region's owned held dofs, once
            owned = m.num_owned * m.gdim
            self._reaction_dofs = []
            for region, _ in self.reaction_regions():
                if "." not in region:       # a driven rigid body (``_drive_reactions``)
                    continue
                dofs = np.unique(np.concatenate([c.dofs for c in m.constraints if c.region == region]))
                dofs = dofs[dofs < owned]
                # with where each sits among the constrained dofs (``_prescribed_motion``'s order)
                self._reaction_dofs.append((dofs, np.searchsorted(self._constrained_dofs, dofs)))
        if not self._reaction_dofs:
            return self._drive_reactions()
        prescribed_v, prescribed_a = self._prescribed_motion()
        forces = (self.f_ext.reshape(-1), self.f_con.reshape(-1), self.f_int.reshape(-1))
        out = np.zeros((len(self._reaction_dofs), m.gdim))
        for k, (dofs, at) in enumerate(self._reaction_dofs):
            v, a = prescribed_v[at], prescribed_a[at]
            push = (m.mass[dofs // m.gdim] * (a + m.alpha * v)
                    - (forces[0][dofs] + forces[1][dofs] - forces[2][dofs]))
            np.add.at(out[k], dofs % m.gdim, push)
        if self.parallel:
            self.comm.Allreduce(MPI.IN_PLACE, out, op=MPI.SUM)
        return list(out) + self._drive_reactions()

    def _drive_reactions(self) -> list[np.ndarray]:
        """The force each driven rigid body's drive applies to it at t [N], (gdim,) each (zero along its free
        directions): M a_prescribed - F along each driven one, F the resultant of every other force on it."""
        out = []
        h = 0.5 * self.dt if self.dt > 0 else 1e-9
        for rb, rs in zip(self.model.rigid, self.rigid_states):
            if rb.drives:
                force = np.zeros(self.model.gdim)
                for drive in rb.drives:
                    force[drive.component] = rb.mass * drive.rate(self.t, h) - rs.force[drive.component]
                out.append(force)
        return out

    def _prescribed_motion(self) -> tuple[np.ndarray, np.ndarray]:
        """The prescribed velocity at t and its rate (central difference over the last step: exact on the
        piecewise-linear histories) of every constrained dof (``_constrained_dofs``, in their order);
        evaluated once per step (the history asks for it several times)."""
        if not self._prescribed_constant and self._prescribed_at != self.step:
            n = len(self._constrained_dofs)
            h = 0.5 * self.dt if self.dt > 0 else 1e-9
            before, after = max(self.t - h, 0.0), self.t + h
            v = self._prescribed_velocities(self.t, np.zeros(n))
            a = ((self._prescribed_velocities(after, np.zeros(n)) - self._prescribed_velocities(before, np.zeros(n)))
                 / (after - before))
            self._prescribed, self._prescribed_at = (v, a), self.step
        return self._prescribed

    def _prescribed_velocities(self, t: float, out: np.ndarray) -> np.ndarray:
        """Every constrained dof's prescribed velocity at t into ``out`` (``_constrained_dofs``' order; of two
        constraints that share a dof, the later one's), which it returns."""
        for con, at in zip(self.model.constraints, self._constraint_positions):
            out[at] = con.value(t)
        return out

    def _body_sums(self):
        """Per body, over all ranks: the sums of m v and m a of the motion at t, of the kinetic energy as
        the nodal account takes it (``nodal.body_sums``), and the elements' works (``body_energy``'s
        internal, hourglass and plastic columns).  Once per step (the history asks for them twice), in one
        buffer reduction.  Collective."""
        m = self.model
        if self._body_sums_at != (self.step, self.t):
            v_held, a_held = self._prescribed_motion()
            mv, ma, kinetic = nodal.body_sums(self.v, self.a, self.dt, m.alpha, m.mass, self.kinetic_mass,
                                              self.constrained, m.node_body, len(m.bodies), m.num_owned,
                                              self._constrained_dofs, v_held, a_held)
            # a body's rows: its own and those of its mass-scaled cells
            work = np.zeros((len(m.bodies), 3))
            np.add.at(work, self._row_body, self.body_energy)
            if self.parallel:
                parts = (mv, ma, kinetic, work)
                sums = np.concatenate([p.reshape(-1) for p in parts])
                self.comm.Allreduce(MPI.IN_PLACE, sums, op=MPI.SUM)
                ends = np.cumsum([p.size for p in parts])[:-1]
                mv, ma, kinetic, work = (s.reshape(p.shape) for s, p in zip(np.split(sums, ends), parts))
            self._body_sums_kept = (mv, ma, kinetic, work)
            self._body_sums_at = (self.step, self.t)
        return self._body_sums_kept          # kept for the step: callers copy before changing them

    def body_means(self):
        """Mass-weighted mean velocity and acceleration of every body at t (``motion``), (bodies, gdim) each.
        Collective."""
        m = self.model
        mv, ma, _, _ = self._body_sums()
        v_mean, a_mean = mv / m.body_mass[:, None], ma / m.body_mass[:, None]
        h = 0.5 * self.dt if self.dt > 0 else 1e-9
        for rb in m.rigid:          # a driven direction moves as prescribed at t
            for drive in rb.drives:
                v_mean[rb.index, drive.component] = drive.value(self.t)
                a_mean[rb.index, drive.component] = drive.rate(self.t, h)
        if m.axisymmetric:
            # the centre of mass of a body of revolution stays on its axis: the mean of the nodes' radial
            # motion is the body breathing, not moving
            v_mean[:, 0] = a_mean[:, 0] = 0.0
        return v_mean, a_mean

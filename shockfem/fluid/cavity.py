"""A liquid-filled cavity discharging through an orifice: the fluid dashpot as a control volume.

Each step, on the walls' current positions and velocities (``Cavity.walls``: body surfaces whose
outward normals face the liquid; the cavity's other walls are held still):

    dV/dt    = -sum over wall facets of v_f . S_f       S_f the facet's outward area vector (2 pi r ds
                                                        in axisymmetry), v_f its mean velocity
    M        : the liquid's mass, less what the orifice has let out;  rho = M / V
    p        = K / n ((rho / rho0)^n - 1)               gauge pressure, Tait's law (``liquid.py``)
    mdot     = rho Cc a u_j                             the orifice jet by the scene's law (``orifice.py``:
                                                        the sharp-edged law with the velocity of approach
                                                        in the passage A, or a fixed Cd without it), taken
                                                        at the step's end (backward Euler)
    f        = -p S_f / (nodes per facet) on each wall node: the liquid pushes the walls away from it,
                                                        on the current geometry (a follower load); on the
                                                        last wall (the orifice's) p less J / A_w, the jet's
                                                        reaction J = mdot (u_j - u1) (sharp-edged law)

with a the orifice area: fixed, or a table of the stroke (displaced volume / piston area: a
metering pin).  A cavity given no volume is closed by its walls, and its volume is taken from their current
positions every step (divergence theorem).  The liquid's energy is the work the walls do on it, split into what it stores
(the compression energy of M at rho) and what the orifice throttles, the integral of p mdot / rho
(the jet's kinetic energy, turned to heat downstream), less the jet reaction's work on the orifice's
wall.  The walls' nodes see the liquid as a spring of stiffness K A^2 / V (a rigid wall: its body's
mass), which bounds the stable step.  The passage A is ``orifice.piston_area``, or the last wall's area.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from ..contact.surfaces import NodeExchange, area_vectors, build_surface, trapezoidal_work
from ..errors import ModelError
from ..forces.source import ForceSource
from ..model import Model
from ..scene.specs import Cavity
from . import liquid
from . import orifice
from .column import _interpolate
from .orifice import AREA_RATIO, OrificeLaw


def orifice_law(spec: Cavity) -> OrificeLaw:
    """The scene's orifice law (``scene/cavities.py``): the sharp-edged law with the velocity of approach and
    the jet's reaction, or a fixed Cd without either."""
    if spec.law == "fixed_cd":
        return OrificeLaw(discharge=spec.discharge, approach=False, jet=False, largest_ratio=1.0)
    return AREA_RATIO


class OrificeArea:
    """The orifice's area against the stroke [m^2]: fixed (the scene's table has one row) or a table of the
    stroke [m] (a metering pin), its ends held."""

    def __init__(self, table):
        curve = np.array(table, dtype=float)
        self.stroke, self.area = curve[:, 0], curve[:, 1]

    def __call__(self, stroke: float) -> float:
        if len(self.area) == 1:
            return float(self.area[0])
        return _interpolate(stroke, self.stroke, self.area)


class WallNodes:
    """The walls' nodes of a liquid source, compact over the ranks (``NodeExchange``): the facets of each
    wall in the walls' order (``facets``, ``wall_of_facet``), each node's moving mass (a rigid body's node
    moves with its whole body) and its rigid body's place among the walls' rigid bodies (-1: deformable);
    every step, their state (``state``) and the liquid's forces on them, from a pressure on each facet
    (``pressure``, ``push``).  Collective."""

    def __init__(self, model: Model, spec: Cavity):
        surfaces = [build_surface(model, w) for w in spec.walls]
        facets = [s.facets for s in surfaces]
        if not any(len(f) for f in facets):
            raise ModelError(f"cavity '{spec.name}': its walls {', '.join(spec.walls)} have no facets")
        width = max(f.shape[1] for f in facets)
        if any(f.shape[1] != width for f in facets):
            raise ModelError(f"cavity '{spec.name}': walls of mixed facet kinds")
        self.counts = [len(f) for f in facets]
        self.global_nodes = np.unique(np.concatenate([f.ravel() for f in facets]))
        self.exchange = NodeExchange(model, self.global_nodes)
        self.facets = np.searchsorted(self.global_nodes, np.concatenate(facets))
        self.wall_of_facet = np.repeat(np.arange(len(facets)), self.counts)
        body = self.exchange.gather(model.node_body[:, None].astype(float))[:, 0].astype(int)
        mass = self.exchange.gather(model.mass[:, None])[:, 0]
        for rb in model.rigid:
            mass[body == rb.index] = model.body_mass[rb.index]
        self.mass = mass
        rigid = np.isin(body, [rb.index for rb in model.rigid])
        rigid_bodies = np.unique(body[rigid])
        self.rigid_group = np.where(rigid, np.searchsorted(rigid_bodies, body), -1)
        self.group_area = np.zeros(len(rigid_bodies))
        self.group_mass = model.body_mass[rigid_bodies] if len(rigid_bodies) else np.zeros(0)
        # the step's state, in buffers kept for the run
        n, gdim = len(self.global_nodes), model.gdim
        self.x, self.v = np.empty((n, gdim)), np.empty((n, gdim))
        self.S = np.empty((len(self.facets), gdim))
        self.pressure = np.zeros(len(self.facets))      # on each facet, set by the source before ``push``
        self.f, self._f_old = np.zeros((n, gdim)), np.zeros((n, gdim))

    def state(self, model: Model, x_local: np.ndarray, v_local: np.ndarray):
        """The walls' nodes' positions and velocities (compact) and their facets' area vectors on those
        positions: (x, v, S).  Collective."""
        x = self.exchange.gather(x_local, out=self.x)
        v = self.exchange.gather(v_local, out=self.v)
        return x, v, area_vectors(model, x, self.facets, out=self.S)

    def push(self, f: np.ndarray, dt: float) -> float:
        """The facets' ``pressure`` as forces on the walls' nodes (``wall_forces``, on the last ``state``),
        added into the bodies' ``f``; returns their work over the step [J]."""
        work = wall_forces(self.f, self._f_old, self.facets, self.S, self.pressure, self.v, dt)
        self.exchange.add_to(self.f, f)
        return work

    def lumped_period(self, S: np.ndarray, stiffness_per_area2: float, whole: float | None = None) -> float:
        """2 pi / omega of the liquid spring on the rigid bodies among the walls, omega^2 = (K_t / V) A_g A /
        M_g (``_stable_step``'s bound for a rigid wall: A_g its area, A the walls' whole area, M_g its body's
        mass, ``group_area`` as ``_stable_step`` left it; ``whole`` if known), inf without one.  That
        oscillation is the model
        (a piston on a liquid), not a mesh mode: it bounds the step for accuracy too
        (``ExplicitSolver.accuracy_step``).  A deformable wall's node is a mesh mode, as an element's, and
        left out."""
        if not len(self.group_area):
            return math.inf
        if whole is None:
            whole = float(np.sqrt((S * S).sum(axis=1)).sum())
        omega2 = stiffness_per_area2 * whole * float(np.max(self.group_area / self.group_mass))
        return 2.0 * math.pi / math.sqrt(omega2) if omega2 > 0.0 else math.inf


class LiquidCavity(ForceSource):
    """A liquid-filled cavity as a force source (``forces/source.py``): its pressure on its walls."""

    kind = "cavity"

    @property
    def oscillator(self) -> str:
        return f"cavity '{self.name}' on its rigid walls"

    def __init__(self, model: Model, spec: Cavity):
        self.spec = spec
        self.name = spec.name
        self.model = model
        walls = WallNodes(model, spec)
        self.walls = walls
        self.global_nodes, self.exchange, self.facets = walls.global_nodes, walls.exchange, walls.facets
        self.axisymmetric = model.axisymmetric
        self.mass = walls.mass
        # the orifice's wall (the last), where the sharp-edged law's jet reaction acts
        self._orifice_wall = walls.wall_of_facet == len(spec.walls) - 1
        self.period = math.inf           # of the liquid spring on its rigid walls' bodies [s] (``apply``)
        # a cavity closed by its walls (no volume given) takes its volume from them, every step
        self.enclosed = spec.volume <= 0.0
        self.volume = self.enclosed_volume(self.exchange.gather(model.X0)) if self.enclosed else spec.volume
        if self.volume <= 0.0:
            raise ModelError(f"cavity '{spec.name}': its walls enclose no volume ({self.volume:.4g} m^3): with no "
                             f"volume given they must close the cavity, their outward normals facing the liquid")
        self.initial_volume = self.volume
        # a pre-charged cavity holds the mass that gives its initial pressure: (1 + n p0 / K)^(1/n) rho0 V
        n, K = spec.tait_exponent, spec.bulk_modulus
        self.mass_liquid = spec.density * (1.0 + n * spec.initial_pressure / K) ** (1.0 / n) * self.volume
        self.initial_stored = self.stored_energy()
        self.pressure = 0.0
        self.outflow = 0.0               # mass rate out [kg/s]
        self.out_mass = 0.0              # mass let out so far [kg]
        self.work = 0.0                  # work of the liquid on the walls [J]
        self.throttled = 0.0             # energy dissipated by the orifice [J]
        self.max_pressure = 0.0
        self._orifice = OrificeArea(spec.orifice)
        self.law = orifice_law(spec)
        self._law = self.law.code()
        # the passage the liquid approaches the orifice through: the piston's area, or the orifice wall's own
        S0 = area_vectors(model, self.exchange.gather(model.X0), self.facets)
        self.passage = spec.piston_area or float(np.linalg.norm(S0[self._orifice_wall].sum(axis=0)))
        if self.passage <= 0.0 and self._orifice.area.max() > 0.0:
            raise ModelError(f"cavity '{spec.name}': its last wall {spec.walls[-1]} has no net area (a closed "
                             f"surface) to approach the orifice through: give orifice.piston_area")
        self.jet_force = 0.0             # the jet's reaction on the orifice's wall [N]
        self.jet_work = 0.0              # its work on that wall [J]
        self.max_area_ratio = 0.0        # the largest orifice area over the passage's

    # ---------------------------------------------------------------- state
    def density_ratio(self) -> float:
        return self.mass_liquid / (self.spec.density * self.volume)

    def pressure_of(self, ratio: float) -> float:
        return liquid.pressure(ratio, self.spec.bulk_modulus, self.spec.tait_exponent)

    def stored_energy(self) -> float:
        """The compression energy of the liquid in the cavity [J]."""
        return self.mass_liquid * liquid.compression_energy(self.density_ratio(), self.spec.bulk_modulus,
                                                            self.spec.tait_exponent, self.spec.density)

    def stroke(self) -> float:
        return (self.initial_volume - self.volume) / self.spec.piston_area if self.spec.piston_area else 0.0

    def orifice_area(self) -> float:
        return self._orifice(self.stroke())

    def _mass_out(self, dt: float) -> float:
        """The mass the orifice lets out over the step, at the pressure it leaves behind
        (``liquid.outflow_over_step``: backward Euler), through the area of the step's stroke."""
        sp = self.spec
        area = self.orifice_area()
        return liquid.outflow_over_step(self.mass_liquid, self.volume, dt, area, self.passage, self._law,
                                        sp.bulk_modulus, sp.tait_exponent, sp.density)

    # ---------------------------------------------------------------- geometry
    def enclosed_volume(self, x: np.ndarray) -> float:
        """The volume the walls close, by the divergence theorem with the liquid's outward normals -S:
        V = -sum of (x_f . S_f) / d in 3D (d = 3) and plane strain (d = 2), V = -sum of z_f S_z,f in
        axisymmetry (the field (0, z), whose divergence is 1); x_f the facet's centroid."""
        return _enclosed_volume(x, self.facets, area_vectors(self.model, x, self.facets), self.axisymmetric)

    # ---------------------------------------------------------------- step
    def apply(self, x: np.ndarray, u: np.ndarray, v: np.ndarray, dt: float, t: float, f: np.ndarray) -> float:
        """Advance the liquid over the step just taken (``v`` is v_n+1/2), then its pressure's forces on
        the walls at t_n+1 into ``f``.  Returns the step limit of the liquid's stiffness.  Collective.

        Its loops are compiled (``_flux``, ``wall_forces``, ``_stable_step``): a cavity has a few
        walls' facets, and numpy's calls on them took most of a dashpot run's step."""
        x, v, S = self.walls.state(self.model, x, v)
        if dt > 0.0:
            if self.enclosed:
                self.volume = _enclosed_volume(x, self.facets, S, self.axisymmetric)
            else:
                # the outward normals face the liquid: walls moving along them shrink it
                self.volume -= dt * _flux(v, self.facets, S)
            taken = self._mass_out(dt)
            self.mass_liquid -= taken
            self.out_mass += taken
            ratio = self.density_ratio()
            self.outflow = taken / dt
            self.throttled += taken * self.pressure_of(ratio) / (self.spec.density * ratio)
        else:
            # at the start: the jet of a pre-charged cavity already flows at its pressure
            sp = self.spec
            self.outflow = liquid.orifice_mass_flow(self.density_ratio(), self.orifice_area(), self.passage, self._law,
                                                    sp.bulk_modulus, sp.tait_exponent, sp.density)
        self.pressure = self.pressure_of(self.density_ratio())
        self.max_pressure = max(self.max_pressure, self.pressure)
        self._jet(S, v, dt)
        self.work += self.walls.push(f, dt)
        # the liquid as a volume spring, K_t = dp / d(ln rho), on the walls' nodes
        K_t = self.spec.bulk_modulus * self.density_ratio() ** self.spec.tait_exponent
        w = self.walls
        limit = _stable_step(S, self.facets, w.rigid_group, w.group_area, self.mass, K_t / max(self.volume, 1e-300))
        self.period = w.lumped_period(S, K_t / max(self.volume, 1e-300))
        return limit

    def _jet(self, S: np.ndarray, v: np.ndarray, dt: float):
        """The pressure on each facet: the cavity's, less J / A_w on the orifice's wall (its area A_w), J the
        jet's reaction at this step's outflow (0 for the fixed-Cd law); and J's work on that wall over the step
        (its velocity into the liquid, the volume it sweeps over its area)."""
        on_facet = self.walls.pressure
        on_facet[:] = self.pressure
        area = self.orifice_area()
        if area > 0.0:
            self.max_area_ratio = max(self.max_area_ratio, area / self.passage)
        rho = self.spec.density * self.density_ratio()
        self.jet_force = orifice.jet_reaction(self.outflow, rho, area, self.passage, self._law)
        if self.jet_force > 0.0:
            on = self._orifice_wall
            A_w = float(np.linalg.norm(S[on].sum(axis=0)))
            on_facet[on] -= self.jet_force / A_w
            self.jet_work += dt * self.jet_force * _flux(v, self.facets[on], S[on]) / A_w

    # ------------------------------------------------------ force source
    def rows(self) -> np.ndarray:
        return self.exchange.local

    def energy(self) -> float:
        return -self.work

    def columns(self, axes) -> list[tuple[str, str]]:
        return [(f"cavity.{self.name}.pressure", "Pa"), (f"cavity.{self.name}.volume", "m^3"),
                (f"cavity.{self.name}.outflow", "kg/s"), (f"cavity.{self.name}.orifice_area", "m^2")]

    def history(self) -> list[float]:
        return [self.pressure, self.volume, self.outflow, self.orifice_area()]

    def summary(self) -> dict:
        limit = orifice.valid_area_ratio(self.law)
        return {"model": f"control volume at one pressure, {self.law.describe()}; leaves out the liquid's inertia and "
                         f"waves, cavitation below 0 gauge (model = \"column\" has them)",
                "walls": list(self.spec.walls), "volume": self.volume, "initial_volume": self.initial_volume,
                "pressure": self.pressure, "max_pressure": self.max_pressure, "mass_out": self.out_mass,
                "energy_taken": self.energy(), "energy_stored": self.stored_energy() - self.initial_stored,
                "energy_throttled": self.throttled, "jet_reaction_work": self.jet_work,
                "jet_heating": self.throttled / max(self.out_mass, 1e-300) / self.spec.heat_capacity,
                "validity": [{"name": "orifice area ratio a / A", "value": self.max_area_ratio, "limit": limit,
                              "holds": bool(self.max_area_ratio <= limit)}],
                "outside": [] if self.max_area_ratio <= limit else ["orifice area ratio a / A"]}


@njit(cache=True)
def _facet_means_dot(values, facets, S, first):
    """The sum over the facets of u_f . S_f from component ``first`` on, u_f the mean of the facet's nodes'
    ``values``."""
    nf, nn = facets.shape
    total = 0.0
    for i in range(nf):
        for j in range(first, values.shape[1]):
            c = 0.0
            for k in range(nn):
                c += values[facets[i, k], j]
            total += c / nn * S[i, j]
    return total


@njit(cache=True)
def _enclosed_volume(x, facets, S, axisymmetric):
    """``LiquidCavity.enclosed_volume``'s sum over the facets: of z_f S_z,f in axisymmetry, else of
    x_f . S_f over the dimension."""
    if axisymmetric:
        return -_facet_means_dot(x, facets, S, 1)
    return -_facet_means_dot(x, facets, S, 0) / x.shape[1]


@njit(cache=True)
def _flux(v, facets, S):
    """sum over the facets of v_f . S_f, v_f the mean of the facet's nodes' velocities [m^3/s]."""
    return _facet_means_dot(v, facets, S, 0)


@njit(cache=True)
def wall_forces(f, f_old, facets, S, pressure, v, dt):
    """The pressure's forces on the walls' nodes into ``f`` (-p_f S_f shared equally by a facet's nodes,
    ``pressure`` one per facet), and the work they did over the step, dt/2 (f_old + f) . v; ``f_old``
    becomes ``f``."""
    nf, nn = facets.shape
    f[:] = 0.0
    for k in range(nn):
        for i in range(nf):
            for j in range(f.shape[1]):
                f[facets[i, k], j] -= pressure[i] * S[i, j] / nn
    return trapezoidal_work(f, f_old, v, dt)


@njit(cache=True)
def node_areas(S, facets, rigid_group, group_area, n_nodes):
    """Each wall node's share of the walls' area (a facet's area shared equally by its nodes; a rigid wall's
    nodes move with their body: their group's whole area, summed into ``group_area``), and the walls' whole
    area."""
    nf, nn = facets.shape
    a_node = np.zeros(n_nodes)
    whole = 0.0
    for i in range(nf):
        area = 0.0
        for j in range(S.shape[1]):
            area += S[i, j] * S[i, j]
        area = math.sqrt(area)
        whole += area
        for k in range(nn):
            a_node[facets[i, k]] += area / nn
    group_area[:] = 0.0
    for a in range(n_nodes):
        if rigid_group[a] >= 0:
            group_area[rigid_group[a]] += a_node[a]
    share = np.empty(n_nodes)
    for a in range(n_nodes):
        share[a] = group_area[rigid_group[a]] if rigid_group[a] >= 0 else a_node[a]
    return share, whole


@njit(cache=True)
def _stable_step(S, facets, rigid_group, group_area, mass, stiffness_per_area2):
    """2 / omega, omega^2 <= max over nodes of (K_t / V) a_i A / m_i: the liquid as a volume spring
    (Gershgorin on -dp/dV S_i S_j); a_i the node's share of the walls' area (``node_areas``: a rigid
    wall's nodes share their group's whole area, and their body's mass), A the walls' whole area.
    ``stiffness_per_area2`` = K_t / V."""
    share, whole = node_areas(S, facets, rigid_group, group_area, len(mass))
    omega2 = 0.0
    for a in range(len(mass)):
        omega2 = max(omega2, stiffness_per_area2 * share[a] * whole / mass[a])
    return 2.0 / math.sqrt(omega2) if omega2 > 0.0 else np.inf

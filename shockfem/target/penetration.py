"""A concrete target as a load on the projectile's nose: the ``[penetration]`` of a scene.

Each step, on the nose facets' current positions and velocities (``target/concrete.py`` for the law):

    z          = the depth of the nose's deepest node below the target's face (the tip)
    crater     z < k (k = ``crater_depth``, Forrestal's 4a): every nose facet carries
               sigma_n = (S f'c + rho (V1 cos)^2) z / k, cos = v_n / |v| the facet's direction cosine,
               so that a rigid nose feels Forrestal's F = c z exactly (c and V1 from the strike speed
               and the mass of the projectile and what it carries, fixed when the tip reaches the face)
    tunnel     z >= k: sigma_n = S f'c + rho v_n^2 on the advancing facets, times the share of each
               facet beyond the face (from its nodes' depths; all of the nose once it is in)
    force      -sigma_n S_f / (nodes per facet) on each facet node, S_f the outward area vector on the
               current geometry (a follower load: a yawed or bending nose gets its lateral load)
    torque     3D, mu > 0: T = mu F a / 2 about the nose's axis against the projectile's spin (the white
               paper's friction torque), as forces along e x r on the loaded nodes, weighted by their load

a is the nose's radius from its own area (|sum of S_f| = pi a^2), its axis the direction of that sum,
and the law's nose factor is the mesh's own, N = sum of A_f (n_f . e)^3 / (pi a^2) (the ogive's
(8 psi - 1) / (24 psi^2) as the mesh resolves it).  The work of the target on the projectile is
integrated by the trapezoidal rule; the solver counts it with contact (``energy.contact``).
"""
from __future__ import annotations

import functools
import math

import numpy as np
from mpi4py import MPI
from numba import njit

from ..contact.surfaces import NodeExchange, area_vectors, build_surface, trapezoidal_work
from ..errors import ModelError
from ..forces.source import ForceSource
from ..model import Model
from ..scene.specs import Penetration
from .concrete import crater_law, normal_stress, strength_factor

# Below this sliding speed of the nose's surface on the target, a omega [m/s], the friction torque fades out
# linearly (Coulomb friction regularised, as explicit codes do): it stops a spin instead of reversing it
# every step, and the tiny twist an unspun body picks up from its faceted nose is not met by the full mu F a / 2
# flipping sign each step.
SLIP_AT_REST = 0.1
# where the nose is: the regimes of ``_nose_pressure_kernel``'s pass
_AIR, _CRATER, _TUNNEL = 0, 1, 2


class ConcreteTarget(ForceSource):
    """A penetrated concrete target as a force source (``forces/source.py``): its load on the nose."""

    kind = "penetration"
    name = "penetration"

    def __init__(self, model: Model, spec: Penetration):
        self.spec = spec
        self.model = model
        surface = build_surface(model, spec.nose)
        if not len(surface.facets):
            raise ModelError(f"penetration: the nose surface '{spec.nose}' has no facets")
        self.global_nodes = np.unique(surface.facets)
        self.exchange = NodeExchange(model, self.global_nodes)
        self.facets = np.searchsorted(self.global_nodes, surface.facets)
        # each facet's share onto its nodes as one sparse product (np.add.at over the facets was a seventh
        # of a 3D penetration run's whole step)
        self.gdim = model.gdim
        self.point = np.array(spec.point, dtype=float)
        self.normal = np.array(spec.normal, dtype=float)
        self.strength = (spec.strength_factor or strength_factor(spec.compressive_strength)) \
            * spec.compressive_strength                                                   # S f'c [Pa]
        S0 = area_vectors(model, self.exchange.gather(model.X0), self.facets)
        self.radius, axis = self._nose_axis(S0.sum(axis=0))
        self.nose_factor = self._nose_factor(S0, axis)
        self.crater_depth = spec.crater_depth if spec.crater_depth >= 0 else 4.0 * self.radius
        names = model.body_names
        self.projectile = [names.index(spec.nose.partition(".")[0])] + [names.index(b) for b in spec.carried]
        self.mass = float(sum(model.body_mass[i] for i in self.projectile))
        # this rank's owned nodes of the projectile and what it carries (for its speed and spin)
        owned = np.arange(len(model.mass)) < model.num_owned
        self.projectile_nodes = np.flatnonzero(owned & np.isin(model.node_body, self.projectile))
        # a rigid nose has no elements to set the step: the load's own resolution does (below)
        self.rigid_nose = model.bodies[self.projectile[0]].rigid
        self.facet_size = float(surface.size.min())
        self.f = np.zeros((len(self.global_nodes), self.gdim))
        self._f_old = np.zeros_like(self.f)
        # the step's scratch: the nose's positions and velocities, its nodes' depths, its area vectors
        self._x = np.empty_like(self.f)
        self._v = np.empty_like(self.f)
        self._depth = np.empty(len(self.global_nodes))
        self._S = np.empty((len(self.facets), self.gdim))
        self._arm = np.empty_like(self.f)           # the friction torque's arms
        self._total = np.empty(self.gdim)           # the sum of the nose's area vectors
        self._nose_pressure = _nose_pressure_kernel(self.facets.shape[1], self.gdim)
        self._sums = np.empty(7)                    # the projectile's mass, first moments and momentum
        self._lj = np.empty(2)                      # its angular momentum about the axis and polar moment
        self.depth = 0.0                 # the tip's depth below the face [m] (negative before it arrives)
        self.max_depth = 0.0
        self.force = np.zeros(self.gdim)  # resultant of the target's pressure on the nose [N]
        self.axial_force = 0.0           # its component against the nose's axis [N]
        self.max_axial_force = 0.0
        self.torque = 0.0                # friction torque applied about the axis [N m]
        self.spin = 0.0                  # the projectile's spin about its axis [rad/s] (while loaded)
        self.work = 0.0                  # work of the target on the projectile [J]
        self.strike_speed = None         # the projectile's speed when its tip reaches the face [m/s]
        self.strike_time = None
        self.crater_stiffness = 0.0      # Forrestal's c [N/m]
        self.tunnel_entry_speed = None   # V1 [m/s] (the crater law's)
        self.tunnel_time = None          # when the tip passed the crater's depth [s]

    # ---------------------------------------------------------------- geometry
    def _nose_axis(self, total: np.ndarray) -> tuple[float, np.ndarray]:
        """(radius a, unit axis e) of the nose from the sum of its area vectors, pi a^2 e (the nose closed by
        its base disc has none); axisymmetric: along the axis, the radial parts being rings."""
        total = total.copy()
        if self.model.axisymmetric:
            total[0] = 0.0
        area = float(np.linalg.norm(total))
        if area <= 0.0:
            raise ModelError(f"penetration: the nose surface '{self.spec.nose}' has no frontal area")
        return math.sqrt(area / math.pi), total / area

    def _nose_factor(self, S: np.ndarray, axis: np.ndarray) -> float:
        """N = sum of A_f (n_f . e)^3 over the facets facing forward, / (pi a^2)."""
        A = np.linalg.norm(S, axis=1)
        cos = np.clip(S @ axis / np.where(A > 0, A, 1.0), 0.0, None)
        return float(np.sum(A * cos ** 3) / (math.pi * self.radius ** 2))

    def _projectile_speed(self, v_local: np.ndarray) -> float:
        """|mass-weighted mean velocity| of the projectile and what it carries.  Collective."""
        m = self.model
        sel = self.projectile_nodes
        momentum = (m.mass[sel, None] * v_local[sel]).sum(axis=0)
        if m.comm.size > 1:
            momentum = m.comm.allreduce(momentum, op=MPI.SUM)
        return float(np.linalg.norm(momentum)) / self.mass

    # ---------------------------------------------------------------- step
    def compute(self, x_local: np.ndarray, v_local: np.ndarray, dt: float, t: float) -> float:
        """The target's forces on the nose at t_n+1 (``v`` is v_n+1/2).  Returns the load's step limit:
        none on a deformable nose (its velocity term is a damping far below the nodes' critical); on a
        rigid one, which has no elements to set the step, the time to travel half a facet at the strike
        speed, so that the facets enter the target over several steps each.  Collective.

        The facet loop is compiled (``_nose_pressure_kernel``): numpy's calls on a nose's few dozen facets took
        a millisecond a step, more than the elements."""
        x = self.exchange.gather(x_local, out=self._x)
        v = self.exchange.gather(v_local, out=self._v)
        depth = _depths(x, self.point, self.normal, self._depth)     # each nose node's depth below the face
        self.depth = float(depth.max())
        self.max_depth = max(self.max_depth, self.depth)
        if self.depth > 0.0 and self.strike_speed is None:
            self._strike(v_local, t)
        S = area_vectors(self.model, x, self.facets, out=self._S)
        if self.depth <= 0.0:
            regime, speed, scale = _AIR, 0.0, 0.0
        elif self.depth < self.crater_depth:
            # the crater: the tunnel law at V1 over the whole nose, scaled with depth (F = c z)
            regime, speed, scale = _CRATER, self.tunnel_entry_speed, self.depth / self.crater_depth
        else:
            if self.tunnel_time is None:
                self.tunnel_time = t
            regime, speed, scale = _TUNNEL, 0.0, 1.0
        loaded = self._nose_pressure(S, v, self.facets, depth, regime, self.strength, self.spec.density, speed,
                                     scale, self.f, self.force, self._total)
        axis = self._nose_axis(self._total)[1] if loaded else None
        self.axial_force = float(-self.force @ axis) if axis is not None else 0.0
        self.max_axial_force = max(self.max_axial_force, self.axial_force)
        if self.gdim == 3 and self.spec.friction > 0.0:
            if axis is not None:
                self._friction_torque(x, x_local, v_local, axis)
            else:
                self.torque = 0.0
        self.work += trapezoidal_work(self.f, self._f_old, v, dt)
        if not self.rigid_nose:
            return np.inf
        # at the strike speed, not the current one: the last metres per second before it stops need
        # steps as short as the first
        speed = max(float(np.sqrt((v ** 2).sum(axis=1)).max()), self.strike_speed or 0.0)
        return 0.5 * self.facet_size / speed if speed > 0.0 else np.inf

    def _strike(self, v_local: np.ndarray, t: float):
        """The tip reaches the face: fix the crater law from the projectile's speed and mass."""
        self.strike_speed = self._projectile_speed(v_local)
        self.strike_time = t
        if self.crater_depth > 0.0:
            self.crater_stiffness, v1_squared = crater_law(
                self.mass, self.radius, self.strength, self.spec.density, self.nose_factor, self.strike_speed,
                self.crater_depth)
            self.tunnel_entry_speed = math.sqrt(max(v1_squared, 0.0))
        else:
            self.tunnel_entry_speed = self.strike_speed

    def _projectile_spin(self, x_local: np.ndarray, v_local: np.ndarray, axis: np.ndarray) -> float:
        """The projectile's spin about ``axis`` [rad/s]: its angular momentum about the axis through its
        centre of mass over its polar moment, L / J (the whole body's: a nose's own nodes also twist and
        ring, and an unspun body's would read that as spin).  Collective.  The sums over the body's nodes
        are compiled (``_mass_moments``, ``_spin_moments``): numpy's cross products and temporaries on a
        few hundred nodes took 0.3 ms a step, more than the 3D elements' pass."""
        m = self.model
        sums = _mass_moments(m.mass, x_local, v_local, self.projectile_nodes, self._sums)
        if m.comm.size > 1:
            m.comm.Allreduce(MPI.IN_PLACE, sums, op=MPI.SUM)
        centre, mean_v = sums[1:4] / sums[0], sums[4:7] / sums[0]
        lj = _spin_moments(m.mass, x_local, v_local, self.projectile_nodes, centre, mean_v, axis, self._lj)
        if m.comm.size > 1:
            m.comm.Allreduce(MPI.IN_PLACE, lj, op=MPI.SUM)
        return lj[0] / max(lj[1], 1e-300)

    def _friction_torque(self, x: np.ndarray, x_local: np.ndarray, v_local: np.ndarray, axis: np.ndarray):
        """T = mu F a / 2 against the projectile's spin, as forces w_i T (e x r_i) / sum w_j |r_j|^2 on
        the nose's nodes (w their load, r their arm square to the axis through the load's centre,
        sum w_i r_i = 0): their moment about the axis is exactly T and their resultant exactly zero (an
        uneven mesh would otherwise push the nose sideways).  Collective."""
        self.spin = self._projectile_spin(x_local, v_local, axis)
        lever = _load_arms(self.f, x, axis, self._arm)
        if lever < 0.0:
            return                                  # no load on the nose
        fade = min(max(self.spin * self.radius / SLIP_AT_REST, -1.0), 1.0)
        # the torque applied: mu F a / 2 while the nose spins, none once it has stopped
        self.torque = abs(fade) * self.spec.friction * self.axial_force * self.radius / 2.0
        if lever <= 0.0 or self.torque <= 0.0:
            return
        _add_torque(self.f, self._arm, axis, math.copysign(self.torque / lever, fade))

    def add_forces(self, f: np.ndarray):
        self.exchange.add_to(self.f, f)

    # ------------------------------------------------------ force source
    def rows(self) -> np.ndarray:
        return self.exchange.local

    def apply(self, x: np.ndarray, u: np.ndarray, v: np.ndarray, dt: float, t: float, f: np.ndarray) -> float:
        limit = self.compute(x, v, dt, t)
        self.add_forces(f)
        return limit

    def energy(self) -> float:
        return -self.work

    def columns(self, axes) -> list[tuple[str, str]]:
        out = ([("penetration.depth", "m")] + [(f"penetration.force_{a}", "N") for a in axes]
               + [("penetration.axial_force", "N"), ("penetration.target_work", "J")])
        if self.gdim == 3:
            out += [("penetration.spin", "rad/s"), ("penetration.torque", "N m")]
        return out

    def history(self) -> list[float]:
        out = [self.depth, *self.force, self.axial_force, -self.work]
        return out + [self.spin, self.torque] if self.gdim == 3 else out

    def summary(self) -> dict:
        return {"nose": self.spec.nose, "radius": self.radius, "nose_factor": self.nose_factor,
                "strength": self.strength, "crater_depth": self.crater_depth, "mass": self.mass,
                "strike_speed": self.strike_speed, "strike_time": self.strike_time,
                "crater_stiffness": self.crater_stiffness, "tunnel_entry_speed": self.tunnel_entry_speed,
                "tunnel_time": self.tunnel_time, "depth": self.depth, "max_depth": self.max_depth,
                "max_axial_force": self.max_axial_force, "target_work": self.energy()}


@njit(cache=True)
def _depths(x, point, normal, out):
    """Each node's depth below the target's face, (point - x) . normal, into ``out``."""
    for a in range(x.shape[0]):
        d = 0.0
        for j in range(x.shape[1]):
            d += (point[j] - x[a, j]) * normal[j]
        out[a] = d
    return out


@functools.lru_cache(maxsize=None)
def _nose_pressure_kernel(nodes_per_facet: int, gdim: int):
    """The nose's pressure pass compiled for facets of ``nodes_per_facet`` nodes in ``gdim`` dimensions, both
    constants of the closure: the loops over a facet's nodes and over the coordinates unroll.  With them
    read from the arrays' shapes the pass took 120 us a step on a 1,536-facet nose, more than a third of
    the target's step (docs/performance.md)."""
    nn, gd = nodes_per_facet, gdim

    @njit(cache=True)
    def nose_pressure(S, v, facets, depth, regime, strength, density, entry_speed, scale, f, force, total):
        """The target's normal stress on each nose facet (the module docstring's crater and tunnel laws; none
        in the ``_AIR``) as forces -sigma_n S_f / (nodes per facet) on its nodes into ``f``, their resultant
        into ``force``, the sum of the area vectors S_f into ``total`` (the nose's axis and radius); returns
        whether any facet is loaded.  The facet's normal speed is its nodes' mean velocity along
        S_f / |S_f|; in the crater the law takes V1 (``entry_speed``) along the facet's direction cosine,
        times ``scale`` = z / k; in the tunnel each facet carries the share of it beyond the face, from its
        nodes' depths."""
        f[:] = 0.0
        force[:] = 0.0
        total[:] = 0.0
        loaded = False
        vf = np.empty(gd)
        for i in range(facets.shape[0]):
            area = 0.0
            for j in range(gd):
                area += S[i, j] * S[i, j]
                total[j] += S[i, j]
            area = math.sqrt(area)
            vn = 0.0
            speed = 0.0
            for j in range(gd):
                mean = 0.0
                for k in range(nn):
                    mean += v[facets[i, k], j]
                vf[j] = mean / nn
                vn += vf[j] * (S[i, j] / (area if area > 0.0 else 1.0))
                speed += vf[j] * vf[j]
            if regime == _AIR:
                p = 0.0
            elif regime == _CRATER:
                speed = math.sqrt(speed)
                p = normal_stress(strength, density, entry_speed * (vn / (speed if speed > 0.0 else 1.0))) * scale
            else:
                beyond = 0.0
                whole = 0.0
                for k in range(nn):
                    d = depth[facets[i, k]]
                    beyond += max(d, 0.0)
                    whole += abs(d)
                p = normal_stress(strength, density, vn) * (beyond / max(whole, 1e-300))
            loaded = loaded or p != 0.0
            for j in range(gd):
                share = -p * S[i, j] / nn
                for k in range(nn):
                    f[facets[i, k], j] += share
                force[j] += share
        for j in range(gd):
            force[j] *= nn
        return loaded

    return nose_pressure


@njit(cache=True)
def _mass_moments(mass, x, v, nodes, out):
    """Over ``nodes``: the mass, the first moments sum m x and the momentum sum m v, into ``out`` (7)."""
    out[:] = 0.0
    for a in nodes:
        out[0] += mass[a]
        for j in range(3):
            out[1 + j] += mass[a] * x[a, j]
            out[4 + j] += mass[a] * v[a, j]
    return out


@njit(cache=True)
def _spin_moments(mass, x, v, nodes, centre, mean_v, axis, out):
    """Over ``nodes``: the angular momentum about ``axis`` through ``centre`` relative to the mean velocity,
    sum m ((r x (v - mean_v)) . e), and the polar moment sum m |r|^2, r the arm square to the axis; into
    ``out`` (2)."""
    out[:] = 0.0
    for a in nodes:
        r0, r1, r2 = x[a, 0] - centre[0], x[a, 1] - centre[1], x[a, 2] - centre[2]
        along = r0 * axis[0] + r1 * axis[1] + r2 * axis[2]
        r0, r1, r2 = r0 - along * axis[0], r1 - along * axis[1], r2 - along * axis[2]
        u0, u1, u2 = v[a, 0] - mean_v[0], v[a, 1] - mean_v[1], v[a, 2] - mean_v[2]
        out[0] += mass[a] * ((r1 * u2 - r2 * u1) * axis[0] + (r2 * u0 - r0 * u2) * axis[1]
                             + (r0 * u1 - r1 * u0) * axis[2])
        out[1] += mass[a] * (r0 * r0 + r1 * r1 + r2 * r2)
    return out


@njit(cache=True)
def _load_arms(f, x, axis, arm):
    """Each nose node's arm square to ``axis`` through the centre of the nodes weighted by their load |f_i|,
    into ``arm``; returns the lever sum w_i |r_i|^2, or -1 when no node is loaded."""
    n = f.shape[0]
    total = 0.0
    c0 = c1 = c2 = 0.0
    for i in range(n):
        w = math.sqrt(f[i, 0] * f[i, 0] + f[i, 1] * f[i, 1] + f[i, 2] * f[i, 2])
        total += w
        c0 += w * x[i, 0]
        c1 += w * x[i, 1]
        c2 += w * x[i, 2]
    if total <= 0.0:
        return -1.0
    c0, c1, c2 = c0 / total, c1 / total, c2 / total
    lever = 0.0
    for i in range(n):
        r0, r1, r2 = x[i, 0] - c0, x[i, 1] - c1, x[i, 2] - c2
        along = r0 * axis[0] + r1 * axis[1] + r2 * axis[2]
        r0, r1, r2 = r0 - along * axis[0], r1 - along * axis[1], r2 - along * axis[2]
        arm[i, 0], arm[i, 1], arm[i, 2] = r0, r1, r2
        lever += math.sqrt(f[i, 0] * f[i, 0] + f[i, 1] * f[i, 1] + f[i, 2] * f[i, 2]) * (r0 * r0 + r1 * r1 + r2 * r2)
    return lever


@njit(cache=True)
def _add_torque(f, arm, axis, scale):
    """f_i -= scale |f_i| (e x r_i): the friction torque's forces, each node's weight its own load."""
    for i in range(f.shape[0]):
        w = scale * math.sqrt(f[i, 0] * f[i, 0] + f[i, 1] * f[i, 1] + f[i, 2] * f[i, 2])
        r0, r1, r2 = arm[i, 0], arm[i, 1], arm[i, 2]
        f[i, 0] -= w * (axis[1] * r2 - axis[2] * r1)
        f[i, 1] -= w * (axis[2] * r0 - axis[0] * r2)
        f[i, 2] -= w * (axis[0] * r1 - axis[1] * r0)

"""A liquid-filled cavity discharging through an orifice: the fluid dashpot as a control volume.

Each step, on the walls' current positions and velocities (``Cavity.walls``: body surfaces whose
outward normals face the liquid; the cavity's other walls are held still):

    dV/dt    = -sum over wall facets of v_f . S_f       S_f the facet's outward area vector (2 pi r ds
                                                        in axisymmetry), v_f its mean velocity
    M        : the liquid's mass, less what the orifice has let out;  rho = M / V
    p        = K / n ((rho / rho0)^n - 1)               gauge pressure, Tait's law (``liquid.py``)
    mdot     = Cd a rho min(sqrt(2 p / rho), c)         the orifice jet (``liquid.py``), taken at the
                                                        step's end (backward Euler)
    f        = -p S_f / (nodes per facet) on each wall node: the liquid pushes the walls away from it,
                                                        on the current geometry (a follower load)

with a the orifice area: fixed, or a table of the stroke (displaced volume / piston area: a
metering pin).  A cavity given no volume is closed by its walls, and its volume is taken from their current
positions every step (divergence theorem).  The liquid's energy is the work the walls do on it, split into what it stores
(the compression energy of M at rho) and what the orifice throttles, the integral of p mdot / rho
(the jet's kinetic energy, turned to heat downstream).  The walls' nodes see the liquid as a spring
of stiffness K A^2 / V (a rigid wall: its body's mass), which bounds the stable step.
"""
from __future__ import annotations

import math

import numpy as np

from ..contact.surfaces import NodeExchange, area_vectors, build_surface
from ..errors import ModelError
from ..model import Model
from ..scene.specs import Cavity
from . import liquid


class LiquidCavity:
    def __init__(self, model: Model, spec: Cavity):
        self.spec = spec
        self.name = spec.name
        self.model = model
        surfaces = [build_surface(model, w) for w in spec.walls]
        facets = [s.facets for s in surfaces]
        if not any(len(f) for f in facets):
            raise ModelError(f"cavity '{spec.name}': its walls {', '.join(spec.walls)} have no facets")
        width = max(f.shape[1] for f in facets)
        if any(f.shape[1] != width for f in facets):
            raise ModelError(f"cavity '{spec.name}': walls of mixed facet kinds")
        self.global_nodes = np.unique(np.concatenate([f.ravel() for f in facets]))
        self.exchange = NodeExchange(model, self.global_nodes)
        self.facets = np.searchsorted(self.global_nodes, np.concatenate(facets))
        self.gdim = model.gdim
        self.axisymmetric = model.axisymmetric
        # per compact node: its body, and the mass that moves with it (a rigid body moves whole)
        body = self.exchange.gather(model.node_body[:, None].astype(float))[:, 0].astype(int)
        mass = self.exchange.gather(model.mass[:, None])[:, 0]
        for rb in model.rigid:
            mass[body == rb.index] = model.body_mass[rb.index]
        self.body, self.mass = body, mass
        self.rigid = np.isin(body, [rb.index for rb in model.rigid])
        self.f = np.zeros((len(self.global_nodes), self.gdim))
        self._f_old = np.zeros_like(self.f)
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
        curve = np.array(spec.orifice, dtype=float)
        self._stroke, self._area = curve[:, 0], curve[:, 1]

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
        if len(self._area) == 1:
            return float(self._area[0])
        return float(np.interp(self.stroke(), self._stroke, self._area))

    def _mass_flow(self, mass: float) -> float:
        """The orifice's mass rate [kg/s] with ``mass`` of liquid in the current volume."""
        return liquid.orifice_mass_flow(mass / (self.spec.density * self.volume), self.orifice_area(),
                                        self.spec.discharge, self.spec.bulk_modulus, self.spec.tait_exponent,
                                        self.spec.density)

    def _mass_out(self, dt: float) -> float:
        """The mass m the orifice lets out over the step, at the pressure it leaves behind (backward
        Euler: m = dt mdot(M - m)).  One step's compression, K dV / V, can exceed the pressure itself;
        taking the outflow at the start-of-step pressure would overshoot it every step."""
        high = self.mass_liquid - self.spec.density * self.volume     # with this out, p = 0
        if high <= 0.0 or self._mass_flow(self.mass_liquid) == 0.0:
            return 0.0
        low = 0.0
        for _ in range(60):                    # bisection: g(m) = m - dt mdot(M - m) rises with m
            mid = 0.5 * (low + high)
            if mid - dt * self._mass_flow(self.mass_liquid - mid) > 0.0:
                high = mid
            else:
                low = mid
            if high - low <= 1e-13 * self.mass_liquid:
                break
        return 0.5 * (low + high)

    # ---------------------------------------------------------------- geometry
    def enclosed_volume(self, x: np.ndarray) -> float:
        """The volume the walls close, by the divergence theorem with the liquid's outward normals -S:
        V = -sum of (x_f . S_f) / d in 3D (d = 3) and plane strain (d = 2), V = -sum of z_f S_z,f in
        axisymmetry (the field (0, z), whose divergence is 1); x_f the facet's centroid."""
        S = self._area_vectors(x)
        centre = x[self.facets].mean(axis=1)
        if self.axisymmetric:
            return -float(np.dot(centre[:, 1], S[:, 1]))
        return -float(np.einsum("ij,ij->", centre, S)) / self.gdim

    def _area_vectors(self, x: np.ndarray) -> np.ndarray:
        """Outward area vector of each wall facet on the current geometry (out of its body: into the liquid)."""
        return area_vectors(self.model, x[self.facets])

    # ---------------------------------------------------------------- step
    def compute(self, x_local: np.ndarray, v_local: np.ndarray, dt: float) -> float:
        """Advance the liquid over the step just taken (``v`` is v_n+1/2), then the pressure forces on
        the walls at t_n+1.  Returns the step limit of the liquid's stiffness.  Collective."""
        x = self.exchange.gather(x_local)
        v = self.exchange.gather(v_local)
        S = self._area_vectors(x)
        nn = self.facets.shape[1]
        if dt > 0.0:
            if self.enclosed:
                self.volume = self.enclosed_volume(x)
            else:
                # the outward normals face the liquid: walls moving along them shrink it
                self.volume -= dt * float(np.einsum("ij,ij->", v[self.facets].mean(axis=1), S))
            taken = self._mass_out(dt)
            self.mass_liquid -= taken
            self.out_mass += taken
            ratio = self.density_ratio()
            self.outflow = taken / dt
            self.throttled += taken * self.pressure_of(ratio) / (self.spec.density * ratio)
        self.pressure = self.pressure_of(self.density_ratio())
        self.max_pressure = max(self.max_pressure, self.pressure)
        self.f[:] = 0.0
        share = -self.pressure * S / nn
        for k in range(nn):
            np.add.at(self.f, self.facets[:, k], share)
        self.work += 0.5 * dt * float(np.sum((self._f_old + self.f) * v))
        self._f_old[:] = self.f
        return self._stable_step(S)

    def _stable_step(self, S: np.ndarray) -> float:
        """2 / omega, omega^2 <= max over nodes of (K_t / V) a_i A / m_i: the liquid as a volume spring
        (Gershgorin on -dp/dV S_i S_j); a rigid wall's nodes move with their body's mass and area."""
        ratio = self.density_ratio()
        K_t = self.spec.bulk_modulus * ratio ** self.spec.tait_exponent
        areas = np.linalg.norm(S, axis=1)
        a_node = np.zeros(len(self.global_nodes))
        for k in range(self.facets.shape[1]):
            np.add.at(a_node, self.facets[:, k], areas / self.facets.shape[1])
        if self.rigid.any():
            for b in np.unique(self.body[self.rigid]):
                on = self.body == b
                a_node[on] = a_node[on].sum()
        omega2 = float(np.max(K_t / max(self.volume, 1e-300) * a_node * areas.sum() / self.mass))
        return 2.0 / math.sqrt(omega2) if omega2 > 0.0 else np.inf

    def add_forces(self, f: np.ndarray):
        self.exchange.add_to(self.f, f)

    def summary(self) -> dict:
        return {"walls": list(self.spec.walls), "volume": self.volume, "initial_volume": self.initial_volume,
                "pressure": self.pressure, "max_pressure": self.max_pressure, "mass_out": self.out_mass,
                "energy_taken": -self.work, "energy_stored": self.stored_energy() - self.initial_stored,
                "energy_throttled": self.throttled}

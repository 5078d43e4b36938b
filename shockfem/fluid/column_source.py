"""The liquid column of a fluid dashpot as a force source: ``column.py``'s compressible column between two
finite-element walls, the bore's floor and the piston face the orifice passes through
(``[[cavity]] model = "column"``, ``walls = [floor, piston]``).

The column's axis e is the floor's: its area vectors' sum S_F (outward from the floor's body, into the
liquid) gives e = S_F / |S_F|, fixed at the start; the piston face's must point back along -e.  Every
step, on the walls' current facets (area vectors S_f, nodes' mean velocities v_f):

    w_k  = sum_f (S_f . v_f) / sum_f (S_f . e)      a wall's axial velocity: the volume it sweeps over its
                                                    axial area, so that the column's length follows the
                                                    volume between the walls
    the column stepped on its own clock: once the steps since its last reach its own step (its Courant
    step, and a quarter of the walls' dashpot bound below), over them, with the walls at their mean
    axial velocities (v_n+1/2 averaged), in sub-steps if one step is longer; its mean forces over that
    step, F_F = -p_F A_F and F_P = p_P A_P - J (J the jet's reaction on the piston,
    ``orifice.jet_reaction``), back to the walls as follower loads, held until its next step:
    f_node = -(F_k / sum_f S_f . (-+e)) S_f / (nodes per facet)   summing to F_k e on each wall

so that the walls' work on the liquid, -(F_F w_F + F_P w_P) dt, is what the column counts (its floor's and
piston's work and the jet reaction's).  A the column's section: ``section`` (against the distance from the
floor), else ``orifice.piston_area``, else the piston face's axial area; the liquid starts at rest in the
floor's frame (it rides in the bore), at ``initial_pressure``.  The orifice's area follows the stroke,
L0 - L.

Energy: the walls' work on the liquid (``energy``, what the solver counts from the nodal forces) = the
column's stored and kinetic energy's change + what the jet carries out of it + the jet reaction's work +
the column's dissipation (its shock fronts and Rusanov's flux: the liquid's heating); the rest, the
coupling's own residual (the solver's trapezoidal work against the column's step), is in the summary.

Stable step: a wall node of mass m_i and area a_i against the liquid's impedance rho c (the wall face's
acoustic Riemann solution, a dashpot rho c a_i) is stable in the central difference below 2 m_i / (rho c a_i),
and with the dashpot's force held over the column's step (a delay tau) below tau = (pi / 2) m_i / (rho c a_i);
the liquid as a spring K A^2 / V on the walls' nodes (``cavity._stable_step``) bounds it too, and its
period on the rigid walls' bodies bounds the step for accuracy (``WallNodes.lumped_period``).  A rigid
wall's nodes move with their body (its mass, its wall's area).

Range of validity, checked every run (``validity``, flagged in summary.json's ``outside``): the orifice
law's area ratio (``orifice.valid_area_ratio``), the piston's Mach number |w_P - w_F| / c and the liquid's
in the column below ``column.MACH_LIMIT``; a column that parts (cavitation) is modelled (column
separation at the vapour pressure) and flagged.  Left out: friction on the bore, liquid returning
through the orifice, lateral flow (1D: one pressure across the bore at each station; the walls' lateral
motion and tilt do not move the liquid), the liquid's heating on its pressure.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from ..contact.surfaces import area_vectors
from ..errors import ModelError
from ..forces.source import ForceSource
from ..model import Model
from ..scene.specs import Cavity
from . import orifice
from .cavity import OrificeArea, WallNodes, node_areas, orifice_law
from .column import MACH_LIMIT, PARTED, ColumnLiquid, LiquidColumn, column_walls

# the piston face must face the floor: the cosine between its net normal and -e above this (8 degrees)
PARALLEL = 0.99
# a column given a volume: it must be its walls' within this share (the walls and the section set it)
VOLUME_AGREEMENT = 0.02
# the column's step against the dashpot's bound 2 m / (rho c a) on the walls' nodes: its forces are held over
# it, a delay, stable below (pi / 2) m / (rho c a); a quarter of the bound keeps it below a third of that
DELAY = 0.25


class ColumnSource(ForceSource):
    """A liquid column between two walls as a force source (module docstring)."""

    kind = "cavity"

    @property
    def oscillator(self) -> str:
        return f"column '{self.name}' on its rigid walls"

    def __init__(self, model: Model, spec: Cavity):
        self.spec, self.name, self.model = spec, spec.name, model
        self.walls = w = WallNodes(model, spec)
        self.exchange, self.facets = w.exchange, w.facets
        self.n_floor = w.counts[0]
        x0 = self.exchange.gather(model.X0)
        S0 = area_vectors(model, x0, self.facets)
        self.axis, s_floor, s_piston, self.wall_areas = self._axis(x0, S0)
        self.section = self._section(spec)
        self.law = orifice_law(spec)
        self.liquid = ColumnLiquid(spec.density, spec.bulk_modulus, spec.tait_exponent, spec.vapour_pressure,
                                   spec.heat_capacity)
        body = model.bodies[[b.name for b in model.bodies].index(spec.walls[0].partition(".")[0])]
        v_floor = float(np.dot(np.asarray(body.velocity, dtype=float)[:model.gdim], self.axis))
        self.column = LiquidColumn(self.liquid, s_floor, s_piston, self.section, spec.cells, self.law,
                                   spec.initial_pressure, v_floor)
        self.initial_length = s_piston - s_floor
        self._check_volume(spec)
        self._orifice = OrificeArea(spec.orifice)
        self.period = math.inf
        self.work = 0.0                  # of the liquid on the walls [J] (trapezoidal, the solver's)
        self.column_work = 0.0           # of the walls on the liquid, as the column's step counts it [J]
        self.jet_work = 0.0              # the jet reaction's part of it, J w_P [J]
        self.forces = (-spec.initial_pressure * self.column.area(0.0),
                       spec.initial_pressure * self.column.area(self.initial_length))
        self.velocities = (v_floor, v_floor)
        self.substeps = 0                # the column's steps (its Courant sub-steps)
        self.column_steps = 0            # the times it was stepped (its forces updated)
        self._held = 0.0                 # the time since its last step [s]
        self._swept = [0.0, 0.0]         # the walls' axial displacement since then [m]
        self._interval = 0.0             # its own step [s] (``_limit``)
        self._step_limit = math.inf
        self._stepped = False
        self.max = {"floor_pressure": spec.initial_pressure, "piston_pressure": spec.initial_pressure,
                    "area_ratio": 0.0, "piston_mach": 0.0, "column_mach": 0.0, "void": 0.0}

    # ---------------------------------------------------------------- set-up
    def _axis(self, x: np.ndarray, S: np.ndarray):
        """The column's axis (the floor's net normal), the walls' axial positions (their facets' centroids,
        weighted by axial area) and their axial areas at the start."""
        nf = self.n_floor
        S_floor, S_piston = S[:nf].sum(axis=0), S[nf:].sum(axis=0)
        if np.linalg.norm(S_floor) <= 0.0 or np.linalg.norm(S_piston) <= 0.0:
            raise ModelError(f"column '{self.name}': its walls {', '.join(self.spec.walls)} must each be a face "
                             f"across the bore (a closed surface has no net area)")
        axis = S_floor / np.linalg.norm(S_floor)
        if self.model.axisymmetric:
            axis = np.array([0.0, math.copysign(1.0, S_floor[1])])      # a ring's radial forces cancel
        if -float(S_piston @ axis) / np.linalg.norm(S_piston) < PARALLEL:
            raise ModelError(f"column '{self.name}': the piston face {self.spec.walls[1]} must face the floor "
                             f"{self.spec.walls[0]} across the liquid (their outward normals opposite, within "
                             f"{math.degrees(math.acos(PARALLEL)):.0f} degrees)")
        s_floor, a_floor, _ = _wall_state(x, x, self.facets[:nf], S[:nf], axis)
        s_piston, a_piston, _ = _wall_state(x, x, self.facets[nf:], S[nf:], axis)
        if s_piston <= s_floor:
            raise ModelError(f"column '{self.name}': the piston face {self.spec.walls[1]} must lie beyond the floor "
                             f"{self.spec.walls[0]} along the floor's outward normal (the liquid between them)")
        return axis, s_floor, s_piston, (a_floor, -a_piston)

    def _section(self, spec: Cavity):
        """The column's section: the scene's table, the piston's area, or the piston face's axial area."""
        if spec.section:
            return tuple(spec.section)
        return spec.piston_area or self.wall_areas[1]

    def _check_volume(self, spec: Cavity):
        if spec.volume <= 0.0:
            return
        V = float(self.column.m.sum()) / (self.liquid.density * (1.0 + spec.tait_exponent * spec.initial_pressure
                                                                  / spec.bulk_modulus) ** (1.0 / spec.tait_exponent))
        if abs(V / spec.volume - 1.0) > VOLUME_AGREEMENT:
            raise ModelError(f"cavity '{spec.name}': volume {spec.volume:.6g} m^3, but its column between "
                             f"{spec.walls[0]} and {spec.walls[1]} holds {V:.6g} m^3 (section x length): a "
                             f"column's volume is its walls'; remove volume or correct it")

    # ---------------------------------------------------------------- step
    def orifice_area(self) -> float:
        return self._orifice(self.initial_length - self.column.length())

    def apply(self, x: np.ndarray, u: np.ndarray, v: np.ndarray, dt: float, t: float, f: np.ndarray) -> float:
        """The walls' axial velocities at v_n+1/2 (their volume swept over the step); the column stepped once
        the steps since its last one reach its own step (``_interval``), on the walls' mean velocities over
        them; its mean forces of that step on the walls' facets at t_n+1, held until its next.  Returns the
        step limit (module docstring).  Collective."""
        x, v, S = self.walls.state(self.model, x, v)
        a_floor, flux_floor, a_piston, flux_piston = _walls_state(x, v, self.facets, S, self.n_floor, self.axis)
        w_f, w_p = flux_floor / a_floor, flux_piston / a_piston
        if dt > 0.0:
            self._held += dt
            self._swept[0] += dt * w_f
            self._swept[1] += dt * w_p
            # step the column now if the next step (as long as this one) would take it past its own
            if self._held + dt > self._interval:
                held = self._held
                self._advance(self._swept[0] / held, self._swept[1] / held, held)
                self._held = self._swept[0] = self._swept[1] = 0.0
                self._step_limit = self._limit(S)
        else:
            # at the start: the walls' Riemann pressures on the liquid as it stands (a step of no length)
            self.forces = self.column.step(w_f, w_p, self.orifice_area(), 0.0)
            self.velocities = (w_f, w_p)
            self._step_limit = self._limit(S)
        F_f, F_p = self.forces
        # q on each facet: -q S_f sums to F e on a wall whose axial area is sum S_f . e = a (q = -F / a)
        self.walls.pressure[:self.n_floor] = -F_f / a_floor
        self.walls.pressure[self.n_floor:] = -F_p / a_piston
        self.work += self.walls.push(f, dt)
        return self._step_limit

    def _advance(self, w_f: float, w_p: float, dt: float):
        """The column over ``dt`` in sub-steps within its Courant limit, the walls held at (w_f, w_p); its
        mean forces over the step in ``forces``, the walls' work and the validity checks' peaks."""
        col = self.column
        a = self.orifice_area()
        n = max(1, math.ceil(dt / col.stable_step(w_f, w_p)))
        h = dt / n
        F_f = F_p = 0.0
        for _ in range(n):
            f_f, f_p = col.step(w_f, w_p, a, h)
            F_f += f_f / n
            F_p += f_p / n
            self.jet_work += h * col.jet_force * w_p
            self._peaks(a, w_f, w_p)
        self.substeps += n
        self.column_steps += 1
        self.forces, self.velocities = (F_f, F_p), (w_f, w_p)
        self.column_work -= dt * (F_f * w_f + F_p * w_p)
        self._stepped = True

    def _peaks(self, a: float, w_f: float, w_p: float):
        col, peak = self.column, self.max
        c = self.liquid.sound_speed()
        peak["floor_pressure"] = max(peak["floor_pressure"], col.floor_pressure)
        peak["piston_pressure"] = max(peak["piston_pressure"], col.piston_pressure)
        if a > 0.0:
            peak["area_ratio"] = max(peak["area_ratio"], a / col.area(col.length()))
        peak["piston_mach"] = max(peak["piston_mach"], abs(w_p - w_f) / c)

    def account(self, dt: float, t: float, body_velocities) -> None:
        """After a step that stepped the column: the liquid's Mach number in it and its cavity (loops over the
        cells)."""
        if not self._stepped:
            return
        self._stepped = False
        peak, col = self.max, self.column
        w_f, w_p = self.velocities
        peak["column_mach"] = max(peak["column_mach"], col.mach(w_f, w_p))
        peak["void"] = max(peak["void"], col.void())

    def _limit(self, S: np.ndarray) -> float:
        """The step limit of the liquid on the walls' nodes: the impedance rho c and the spring K_t A^2 / V,
        combined as frequencies (Gershgorin); the accuracy period on the rigid walls' bodies into ``period``;
        the column's own step into ``_interval``: its Courant step, and a quarter of the impedance's bound,
        m_i / (2 rho c a_i), since its forces are held over it (a delay tau on the wall's dashpot rho c a_i is
        stable below (pi / 2) m_i / (rho c a_i))."""
        w, col, lq = self.walls, self.column, self.liquid
        volume, z_floor, z_end = column_walls(col.m, col.x, col.area_x, col.area_a, col._liquid)
        V = max(volume, 1e-300)
        K_t = lq.bulk_modulus * max(col.mass() / (lq.density * V), 1.0) ** lq.tait_exponent
        share, whole = node_areas(S, self.facets, w.rigid_group, w.group_area, len(w.mass))
        self.period = w.lumped_period(S, K_t / V, whole)
        limit, damper = _liquid_step_limit(share, w.mass, whole, K_t / V, max(z_floor, z_end))
        self._interval = min(col.stable_step(*self.velocities), DELAY * damper)
        return limit

    # ---------------------------------------------------------------- what the run reads
    def rows(self) -> np.ndarray:
        return self.exchange.local

    def energy(self) -> float:
        return -self.work

    def columns(self, axes) -> list[tuple[str, str]]:
        n = f"cavity.{self.name}"
        return [(f"{n}.floor_pressure", "Pa"), (f"{n}.piston_pressure", "Pa"), (f"{n}.outflow", "kg/s"),
                (f"{n}.mass_out", "kg"), (f"{n}.void", "m^3"), (f"{n}.heating", "K"), (f"{n}.orifice_area", "m^2"),
                (f"{n}.stroke", "m")]

    def history(self) -> list[float]:
        col = self.column
        return [col.floor_pressure, col.piston_pressure, col.mass_rate, float(col.accounts[2]), col.void(),
                self.heating(), self.orifice_area(), self.initial_length - col.length()]

    def heating(self) -> float:
        """The column's mean temperature rise from its own dissipation [K]."""
        return max(self.column.dissipated(), 0.0) / max(self.column.mass(), 1e-300) / self.liquid.heat_capacity

    def validity(self) -> list[dict]:
        """The run's checks against the column's and its law's ranges (module docstring)."""
        peak = self.max
        cavity = peak["void"] / (self.section_volume())
        checks = [("orifice area ratio a / A", peak["area_ratio"], orifice.valid_area_ratio(self.law)),
                  ("piston Mach number |w_P - w_F| / c", peak["piston_mach"], MACH_LIMIT),
                  ("liquid Mach number in the column", peak["column_mach"], MACH_LIMIT),
                  ("cavitation (the column's largest cavity / its volume; modelled)", cavity, PARTED)]
        return [{"name": name, "value": float(value), "limit": limit, "holds": bool(value <= limit)}
                for name, value, limit in checks]

    def section_volume(self) -> float:
        """The liquid's volume at the start [m^3]."""
        col = self.column
        return float(np.trapz(np.interp(np.linspace(0.0, self.initial_length, 201), col.area_x, col.area_a),
                              np.linspace(0.0, self.initial_length, 201)))

    def summary(self) -> dict:
        col = self.column
        acc = col.summary()
        validity = self.validity()
        taken = self.energy()
        return {"model": f"1D compressible liquid column, {self.spec.cells} finite volumes (Rusanov, MUSCL-Hancock) "
                         f"along the bore from {self.spec.walls[0]} to {self.spec.walls[1]}, cavitation at "
                         f"{self.liquid.vapour_pressure:.4g} Pa, {self.law.describe()}; leaves out friction on the "
                         f"bore, liquid returning through the orifice, lateral flow (1D: one pressure across the "
                         f"bore at each station) and the heating's effect on the pressure",
                "walls": list(self.spec.walls), "axis": [float(c) for c in self.axis], "cells": self.spec.cells,
                "initial_length": self.initial_length, "length": col.length(),
                "section_at_piston": col.area(col.length()),
                "liquid_mass": col.mass() + float(col.accounts[2]),
                "floor_pressure": col.floor_pressure, "piston_pressure": col.piston_pressure,
                "max_floor_pressure": self.max["floor_pressure"], "max_piston_pressure": self.max["piston_pressure"],
                # the control volume's name for the piston's peak, so that a reader of either finds it
                "max_pressure": self.max["piston_pressure"],
                "mass_out": float(col.accounts[2]), "max_void": self.max["void"], "void": col.void(),
                "heating": self.heating(), "jet_heating": acc["jet heating [K]"],
                "energy_taken": taken, "energy_column_change": acc["column energy change [J]"],
                "energy_out_with_jet": acc["energy out [J]"], "jet_reaction_work": self.jet_work,
                "energy_dissipated": acc["column dissipation [J]"],
                "coupling_residual": taken - self.column_work, "column_substeps": self.substeps,
                "column_updates": self.column_steps,
                "validity": validity, "outside": [c["name"] for c in validity if not c["holds"]]}


@njit(cache=True)
def _liquid_step_limit(share, mass, whole, stiffness_per_area2, z):
    """The step limit of the liquid on the walls' nodes [s], its spring (``cavity._stable_step``'s omega^2 =
    max (K_t / V) a_i A / m_i) and its dashpot (2 m_i / (rho c a_i)) combined as frequencies (Gershgorin),
    and the dashpot's alone."""
    omega2 = 0.0
    damper = np.inf
    for a in range(len(mass)):
        omega2 = max(omega2, stiffness_per_area2 * share[a] * whole / mass[a])
        damper = min(damper, 2.0 * mass[a] / (z * share[a]))
    return 1.0 / math.sqrt(omega2 / 4.0 + 1.0 / damper ** 2), damper


@njit(cache=True)
def _walls_state(x, v, facets, S, n_floor, axis):
    """``_wall_state``'s axial areas and fluxes of the floor (the first ``n_floor`` facets) and the piston."""
    _, a_floor, flux_floor = _wall_state(x, v, facets[:n_floor], S[:n_floor], axis)
    _, a_piston, flux_piston = _wall_state(x, v, facets[n_floor:], S[n_floor:], axis)
    return a_floor, flux_floor, a_piston, flux_piston


@njit(cache=True)
def _wall_state(x, v, facets, S, axis):
    """A wall's axial position (its facets' centroids along ``axis``, weighted by axial area), its axial
    area sum S_f . e, and its flux sum S_f . v_f (v_f the mean of the facet's nodes' ``v``)."""
    nf, nn = facets.shape
    position = area = flux = 0.0
    for i in range(nf):
        a = 0.0
        for j in range(S.shape[1]):
            a += S[i, j] * axis[j]
        c = 0.0
        q = 0.0
        for k in range(nn):
            for j in range(S.shape[1]):
                c += x[facets[i, k], j] * axis[j] / nn
                q += v[facets[i, k], j] * S[i, j] / nn
        position += abs(a) * c
        area += a
        flux += q
    return position / max(abs(area), 1e-300), area, flux

"""Discrete springs and dashpots between two bodies (the white paper's soft springs, elastomer pads).

Each end of a spring is a node set (a body, or a named region of one) that the spring sees
through its mass-weighted mean motion, and pushes with forces shared in proportion to nodal
mass (so the set accelerates as a whole under it, like LS-DYNA's discrete element on rigidly
averaged nodes).  With n the unit direction from end a to end b:

    extension  e = (u_b - u_a) . n,   rate  e_dot = (v_b - v_a) . n     (mean motions)
    tension    T = F(e) + c e_dot     F: k e, or a tabulated curve (linear between points,
                                      extrapolated with the end slopes)
    force on a = +T n, on b = -T n    (compression_only: T <= 0, a pad that never pulls, and
                                      zero while F(e) >= 0: the dashpot acts in contact only)

Its stable step joins the element steps like a contact spring: the two-mass oscillator of the
ends, omega^2 = k_max (1/M_a + 1/M_b), shortened by the dashpot.  That oscillator is the model, not a
mesh mode: its period 2 pi / omega bounds the step for accuracy too (``ExplicitSolver.accuracy_step``).
"""
from __future__ import annotations

import math

import numpy as np
from mpi4py import MPI

from ..errors import ModelError
from ..forces.source import ForceSource
from ..model import Model
from ..model.model import region_nodes
from ..scene.specs import Spring
from ..materials.viscosity import damped_step


def _end_nodes(model: Model, spec: str) -> np.ndarray:
    """Owned local nodes of "body" or "body.region"."""
    body_name, _, region = spec.partition(".")
    if region:
        nodes = region_nodes(model.V, model.meshed, spec)
    else:
        index = model.body_names.index(body_name)
        nodes = np.flatnonzero(model.node_body == index)
    return nodes[nodes < model.num_owned]


class DiscreteSpring(ForceSource):
    """A discrete spring (and dashpot) as a force source (``forces/source.py``)."""

    kind = "spring"

    def __init__(self, model: Model, spec: Spring):
        self.spec = spec
        self.name = spec.name
        self.comm = model.comm
        self.nodes = [_end_nodes(model, spec.a), _end_nodes(model, spec.b)]
        self.end_mass = [self._sum(model.mass[n].sum()) for n in self.nodes]
        if min(self.end_mass) <= 0:
            raise ModelError(f"spring '{spec.name}': an end has no mass (check spec.a and spec.b)")
        self.share = [model.mass[n] / M for n, M in zip(self.nodes, self.end_mass)]
        centres = self._means(model.X0)[0]
        if spec.direction is not None:
            n = np.array(spec.direction, dtype=float)
        elif model.axisymmetric:
            n = np.array([0.0, 1.0 if centres[1][1] >= centres[0][1] else -1.0])   # along the axis
        else:
            n = centres[1] - centres[0]
            if np.linalg.norm(n) == 0:
                raise ModelError(f"spring '{spec.name}': the two ends share a centre of mass; give "
                                 f"spring.direction")
            n = n / np.linalg.norm(n)
        self.direction = n
        if spec.curve:
            e, F = np.array(spec.curve).T
            self.curve = (e, F)
            k_max = float(np.max(np.abs(np.diff(F) / np.diff(e))))
        else:
            self.curve = None
            k_max = spec.stiffness
        self.k_max = k_max
        m_eff = 1.0 / (1.0 / self.end_mass[0] + 1.0 / self.end_mass[1])
        if k_max > 0:
            omega = math.sqrt(k_max / m_eff)
            self.dt_limit = damped_step(2.0 / omega, spec.damping / k_max)
            self.period = 2.0 * math.pi / omega    # of the ends' oscillation at the stiffest slope [s]
        else:
            self.dt_limit = 2.0 * m_eff / spec.damping        # a dashpot alone: explicit decay of v
            self.period = math.inf
        self.tension = 0.0
        self.extension = 0.0
        self.max_tension = 0.0
        self.min_tension = 0.0
        self.work = 0.0                     # done on the bodies [J] (minus stored and dissipated)

    def _sum(self, local):
        return self.comm.allreduce(local, op=MPI.SUM) if self.comm.size > 1 else local

    def _means(self, *fields: np.ndarray) -> np.ndarray:
        """Mass-weighted means of each field over each end, (fields, 2 ends, gdim), in one reduction."""
        local = np.array([[(self.share[k][:, None] * f[self.nodes[k]]).sum(axis=0) for k in (0, 1)]
                          for f in fields])
        return self._sum(local)

    def force_law(self, e: float) -> float:
        """Spring tension F(e) [N] at extension e [m]."""
        if self.curve is None:
            return self.spec.stiffness * e
        xs, fs = self.curve
        if e < xs[0]:
            return fs[0] + (e - xs[0]) * (fs[1] - fs[0]) / (xs[1] - xs[0])
        if e > xs[-1]:
            return fs[-1] + (e - xs[-1]) * (fs[-1] - fs[-2]) / (xs[-1] - xs[-2])
        return float(np.interp(e, xs, fs))

    def compute(self, u: np.ndarray, v: np.ndarray, dt: float, f: np.ndarray) -> float:
        """Add the spring's forces at u_{n+1} (rate from v_{n+1/2}) to ``f``; returns its step limit.
        Collective."""
        n = self.direction
        mean_u, mean_v = self._means(u, v)
        e = float((mean_u[1] - mean_u[0]) @ n)
        e_dot = float((mean_v[1] - mean_v[0]) @ n)
        F = self.force_law(e)
        T = F + self.spec.damping * e_dot
        if self.spec.compression_only:
            # a pad: pushes only while compressed, and its dashpot acts only then (not while a gap
            # in its curve closes); a dashpot alone pushes against any approach
            T = 0.0 if F >= 0.0 and self.k_max > 0 else min(T, 0.0)
        f[self.nodes[0]] += T * self.share[0][:, None] * n
        f[self.nodes[1]] -= T * self.share[1][:, None] * n
        # work on the bodies over the step, (T_n + T_{n+1})/2 against e_dot_{n+1/2} as the solver counts it
        self.work -= 0.5 * dt * (self.tension + T) * e_dot
        self.extension, self.tension = e, T
        self.max_tension = max(self.max_tension, T)
        self.min_tension = min(self.min_tension, T)
        return self.dt_limit

    # ------------------------------------------------------ force source
    def rows(self) -> np.ndarray:
        return np.concatenate(self.nodes)

    def apply(self, x: np.ndarray, u: np.ndarray, v: np.ndarray, dt: float, t: float, f: np.ndarray) -> float:
        return self.compute(u, v, dt, f)

    def energy(self) -> float:
        return -self.work

    def columns(self, axes) -> list[tuple[str, str]]:
        # the spring's force on its end a, as a vector (tension T along the unit a -> b)
        return [(f"spring.{self.name}.force_{a}", "N") for a in axes]

    def history(self) -> list[float]:
        return list(self.tension * self.direction)

    def summary(self) -> dict:
        return {"ends": [self.spec.a, self.spec.b], "direction": self.direction.tolist(),
                "extension": self.extension, "tension": self.tension, "max_tension": self.max_tension,
                "max_compression": -self.min_tension, "energy": self.energy()}

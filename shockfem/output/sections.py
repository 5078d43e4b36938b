"""The axial and bending stress along a slender body, from its element stresses.

A scene's ``outputs.sections = [{body = "projectile", count = 21}]`` cuts the body's length along its
axis (the drawn z axis turned by its orientation; 2D: y) into ``count`` equal slabs.  In each slab the
axial stress sigma_n = n . sigma . n of its cells (n the body's current axis: the chord from the first
slab's centre of mass to the last's) is fitted as a plane over the section (the L2 projection: the
solver's own stress points against the exact integrals of the cells' geometry):

    sigma_n(p) = sigma_axial + g . p,     p the cell centre's position square to the axis,

which is Euler-Bernoulli's distribution N / A + M y / I whenever the section carries it (the fit is
exact for it).  The slab's axial stress is sigma_axial (its resultant N / A) and its bending stress
|g| R, R the slab's outer radius (the outer fibre).  Axisymmetric: no bending, sigma_axial alone.

The positions p are the cells' reference (material) positions: the stress pattern rides with the
material, so a body that spins keeps its fit.  Local stresses at contacts and the wave's own
non-planar part are what the fit leaves out (the von Mises field has them).
"""
from __future__ import annotations

import numpy as np
from mpi4py import MPI
from numba import njit

from ..errors import ModelError
from ..model import kinematics as kin
from ..solver.explicit import ExplicitSolver

# the rule for the slabs' geometry, by dimension: exact for a cell's second moments, and with points fine
# enough along a cell (11 in 2D, about 6 in 3D) that a slab's share of a cell it cuts is counted to a few
# percent of that cell (a slab's area then to about 1%)
GEOMETRY_DEGREE = {2: 20, 3: 10}



class SectionStresses:
    """The stresses of one body's slabs, recorded at every history sample; keeps their extremes."""

    def __init__(self, solver: ExplicitSolver, cuts):
        m = solver.model
        self.solver, self.name, self.count = solver, cuts.body, cuts.count
        body = m.body_names.index(cuts.body)
        self.axisymmetric = m.axisymmetric
        self.cells = m.kernel_cells[m.cell_body[m.kernel_cells] == body]
        axis = np.asarray(m.bodies[body].axis, dtype=float)[:m.gdim] if m.gdim == 3 else np.array([0.0, 1.0])
        axis /= np.linalg.norm(axis)
        nodes = np.flatnonzero(m.node_body == body)
        s_nodes = m.X0[nodes] @ axis
        low, high = (float(s_nodes.min()), float(s_nodes.max())) if len(nodes) else (np.inf, -np.inf)
        if solver.parallel:
            low, high = solver.comm.allreduce(low, op=MPI.MIN), solver.comm.allreduce(high, op=MPI.MAX)
        width = (high - low) / self.count
        corners = m.X0[m.dofmap[self.cells]]                          # (cells, nn, gdim)
        centres = corners.mean(axis=1)
        self.slab = np.clip(((centres @ axis - low) / width).astype(int), 0, self.count - 1)
        self.positions = (np.arange(self.count) + 0.5) * width               # from the body's low end
        # the lateral frame square to the axis (3D: two directions; plane strain: one; axisymmetric: none)
        if self.axisymmetric:
            frame = np.zeros((0, m.gdim))
        elif m.gdim == 2:
            frame = np.array([[1.0, 0.0]])
        else:
            e1 = np.cross(axis, [1.0, 0.0, 0.0] if abs(axis[0]) < 0.9 else [0.0, 1.0, 0.0])
            e1 /= np.linalg.norm(e1)
            frame = np.array([e1, np.cross(axis, e1)])
        # the solver's own points (where the stresses live) and a rule exact for the sections' second
        # moments: the fit is the L2 projection of the stress onto planes, sum sigma_q [1, p_q] dV_q against
        # the exact integral of [1, p] [1, p]^T (cell centres alone would miss each cell's own second moment
        # and overstate the bending by the share of it, 20% with four elements across a radius)
        x_q, dv_q = _points(corners, m.N, m.dN, m.wq, m.axisymmetric)
        cell = m.meshed.mesh.topology.cell_name()
        _, w_exact, N_exact, dN_exact = kin.quadrature(cell, "3d" if m.gdim == 3 else "plane-strain",
                                                         degree=GEOMETRY_DEGREE[m.gdim])
        x_e, dv_e = _points(corners, N_exact, dN_exact, w_exact, m.axisymmetric)
        lateral_e = x_e @ frame.T                                              # (cells, q, lateral)
        p_e = lateral_e
        volume = self._sum(dv_e.sum(axis=1))
        if np.any(volume <= 0.0):
            empty = np.flatnonzero(volume <= 0.0)
            raise ModelError(f"outputs.sections of {cuts.body}: slab(s) {empty.tolist()} hold no element centre: "
                             f"lower count ({self.count}) or refine the body (slabs {width:.3g} m long)")
        centre = self._sum(np.einsum("cq,cql->cl", dv_e, p_e)) / volume[:, None]    # (slabs, lateral)
        offset = centre[self.slab][:, None, :]
        p_e = p_e - offset
        basis_e = np.concatenate([np.ones(p_e.shape[:2] + (1,)), p_e], axis=2)
        normal = self._sum(np.einsum("cq,cqk,cql->ckl", dv_e, basis_e, basis_e))
        if np.any(np.linalg.cond(normal) > 1e12):
            raise ModelError(f"outputs.sections of {cuts.body}: a slab's cells do not span its section (too few "
                             f"elements across it): lower count ({self.count}) or refine the body")
        self.solve = np.linalg.inv(normal)                                    # (slabs, k, k)
        # the sections' area and second moment of area: the slab's geometry over its length, each point of
        # the exact rule counted in the slab it lies in (a cell's centre alone would give a slab four or
        # five layers of elements by turns); 3D: the mean of the two principal second moments
        on = np.clip(((x_e @ axis - low) / width).astype(int), 0, self.count - 1).ravel()
        dv, p_flat = dv_e.ravel(), lateral_e.reshape(dv_e.size, frame.shape[0])
        self.area = self._sum(dv, on) / width
        if frame.shape[0]:
            mid = self._sum(dv[:, None] * p_flat, on) / (self.area[:, None] * width)
            spread = (p_flat - mid[on]) ** 2
            self.second_moment = self._sum(dv[:, None] * spread, on).mean(axis=1) / width
        else:
            self.second_moment = np.zeros(self.count)
        p_q = x_q @ frame.T - offset
        self.weights = dv_q[:, :, None] * np.concatenate([np.ones(p_q.shape[:2] + (1,)), p_q], axis=2)
        # the outer fibre: the largest distance of a slab's corners from its axis line
        if self.axisymmetric:
            reach = np.abs(corners[..., 0]).max(axis=1)
        else:
            lateral = corners - np.einsum("cnd,d->cn", corners, axis)[..., None] * axis
            centre_line = centre @ frame                                       # (slabs, gdim)
            reach = np.linalg.norm(lateral - centre_line[self.slab][:, None, :], axis=2).max(axis=1)
        radius = np.zeros(self.count)
        np.maximum.at(radius, self.slab, reach)
        self.radius = solver.comm.allreduce(radius, op=MPI.MAX) if solver.parallel else radius
        # the current axis: the chord between the end slabs' centres of mass (owned nodes)
        owned = nodes[nodes < m.num_owned]
        s_owned = m.X0[owned] @ axis
        self.ends = (owned[s_owned <= low + width], owned[s_owned >= high - width])
        self.reference_axis = axis
        self._moments = np.zeros((self.count, self.weights.shape[2]))
        self.axial = np.zeros(self.count)
        self.bending = np.zeros(self.count)
        self.max_tension = np.full(self.count, -np.inf)
        self.max_compression = np.full(self.count, np.inf)
        self.max_bending = np.zeros(self.count)

    def _sum(self, values: np.ndarray, slabs: np.ndarray | None = None) -> np.ndarray:
        """Per-slab sums over all ranks of per-item ``values`` lying in ``slabs`` (default: the cells'
        own slabs).  Collective."""
        out = np.zeros((self.count,) + values.shape[1:])
        np.add.at(out, self.slab if slabs is None else slabs, values)
        return self._over_ranks(out)

    def _over_ranks(self, out: np.ndarray) -> np.ndarray:
        """``out`` summed over the ranks, in place.  Collective."""
        if self.solver.parallel:
            self.solver.comm.Allreduce(MPI.IN_PLACE, out, op=MPI.SUM)     # a buffer reduction: every sample
        return out

    def current_axis(self) -> np.ndarray:
        """The unit chord from the low end's centre of mass to the high end's, now.  Collective."""
        if self.axisymmetric:
            return self.reference_axis
        s, m = self.solver, self.solver.model
        ends = []
        for nodes in self.ends:
            moment = np.append(m.mass[nodes] @ s.x[nodes], m.mass[nodes].sum())
            ends.append(s.comm.allreduce(moment, op=MPI.SUM) if s.parallel else moment)
        chord = ends[1][:-1] / ends[1][-1] - ends[0][:-1] / ends[0][-1]
        return chord / np.linalg.norm(chord)

    def record(self) -> list[float]:
        """This sample's axial stresses, then bending stresses, slab by slab [Pa].  Collective."""
        n = self.current_axis()
        n3 = np.append(n, 0.0) if len(n) == 2 else n          # axisymmetric: (0, 1, 0), sigma_n = sigma_22
        moments = self._over_ranks(_slab_moments(self.solver.sigma, self.cells, n3, self.weights, self.slab,
                                                 self._moments))
        fit = np.einsum("skl,sl->sk", self.solve, moments)
        self.axial = fit[:, 0]
        self.bending = np.linalg.norm(fit[:, 1:], axis=1) * self.radius
        np.maximum(self.max_tension, self.axial, out=self.max_tension)
        np.minimum(self.max_compression, self.axial, out=self.max_compression)
        np.maximum(self.max_bending, self.bending, out=self.max_bending)
        return list(self.axial) + list(self.bending)

    def columns(self) -> list[tuple[str, str]]:
        return ([(f"section.{self.name}.{k}.axial_stress", "Pa") for k in range(self.count)]
                + [(f"section.{self.name}.{k}.bending_stress", "Pa") for k in range(self.count)])

    def summary(self) -> dict:
        return {"position": self.positions.tolist(), "outer_radius": self.radius.tolist(),
                "area": self.area.tolist(), "second_moment_of_area": self.second_moment.tolist(),
                "max_axial_tension": self.max_tension.tolist(),
                "max_axial_compression": self.max_compression.tolist(),
                "max_bending": self.max_bending.tolist(),
                "units": "position and outer_radius m (position from the body's low end along its axis), area m^2 "
                         "(axisymmetric: the whole ring), second_moment_of_area m^4, stresses Pa"}


def _points(corners: np.ndarray, N: np.ndarray, dN: np.ndarray, w: np.ndarray, axisymmetric: bool):
    """Positions (cells, points, gdim) and volumes (cells, points) of a rule's points on the cells
    (axisymmetric: with 2 pi r)."""
    x = np.einsum("qa,cad->cqd", N, corners)
    J = np.einsum("qat,cad->cqdt", dN, corners)
    dv = np.abs(np.linalg.det(J)) * w
    return x, dv * (2 * np.pi * x[..., 0] if axisymmetric else 1.0)


@njit(cache=True)
def _slab_moments(sigma, cells, n, weights, slab, out):
    """Each slab's moments of the axial stress, sum over its cells and their points of sigma_n w_k, into
    ``out`` (slabs, k), cell by cell in order; sigma_n = n . sigma . n from the stored order 11 22 33 23 13 12
    (numpy's per-sample temporaries and ``np.add.at`` took a sixth of the penetration study's lateral-pulse
    runs)."""
    out[:] = 0.0
    for ci in range(cells.shape[0]):
        c = cells[ci]
        for q in range(weights.shape[1]):
            s = sigma[c, q]
            sigma_n = (n[0] * n[0] * s[0] + n[1] * n[1] * s[1] + n[2] * n[2] * s[2]
                       + 2.0 * (n[1] * n[2] * s[3] + n[0] * n[2] * s[4] + n[0] * n[1] * s[5]))
            for k in range(weights.shape[2]):
                out[slab[ci], k] += sigma_n * weights[ci, q, k]
    return out

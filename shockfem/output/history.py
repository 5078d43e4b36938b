"""Time histories: per-body mean velocity, acceleration and energies, the reactions of the supports,
accelerometers' displacement, velocity and acceleration, contact forces, stresses along slender bodies
(``sections``), energies; HDF5 and CSV.

Columns carry their units in the header (``bar.v_z [m/s]``).  Only rank 0 writes; a run streams the
CSV a block of rows every half second, so a killed run leaves it readable to its last samples, and
rewrites the HDF5 file whole as it goes (written beside and renamed into place, every 2 s or more seldom:
its writing kept under 2% of the wall time), so a kill leaves it whole to its last snapshot.
Whole-file snapshots rather than HDF5's own append (SWMR): a SWMR file whose writer was killed stays
marked as open, and readers refuse it until ``h5clear`` has been run on it.
Accelerometers record the *velocity* of their node: the shock metrics take acceleration as
its interval mean between samples, which cannot alias the stress waves above the sampling
rate (``metrics/signals.py``).
"""
from __future__ import annotations

import csv
import os
import time

import h5py
import numpy as np

from mpi4py import MPI

from ..errors import ModelError
from ..solver.explicit import ExplicitSolver
from .sections import SectionStresses


# each body's (``ExplicitSolver.body_energies``): internal is the work of its stresses, stored and plastic
BODY_ENERGIES = ("kinetic", "internal", "plastic", "hourglass")
ENERGY_COLUMNS = ("kinetic", "internal", "plastic", "damping", "hourglass", "bulk_viscosity", "contact",
                  "external", "balance")


# how often (wall time) the streamed CSV is flushed to disk: a kill loses at most this much of it
FLUSH_EVERY_S = 0.5
# the HDF5 snapshot: at most every SNAPSHOT_EVERY_S (a whole file each time: the CSV is the fine-grained
# stream), and at most SNAPSHOT_SHARE of the wall time spent on it
SNAPSHOT_EVERY_S = 2.0
SNAPSHOT_SHARE = 0.02


class HistoryRecorder:
    def __init__(self, solver: ExplicitSolver, csv_path: str | None = None, h5_path: str | None = None):
        """``csv_path``: stream the rows there as they are recorded (rank 0), header first; ``h5_path``:
        keep a whole snapshot of the history there as the run goes (rank 0)."""
        m = solver.model
        self.solver = solver
        axes = ("r", "z") if m.axisymmetric else "xyz"[:m.gdim]
        self.columns = [("time", "s")]
        for b in m.bodies:
            self.columns += [(f"{b.name}.v_{a}", "m/s") for a in axes]
            self.columns += [(f"{b.name}.a_{a}", "m/s^2") for a in axes]
        for b in m.bodies:
            self.columns += [(f"{b.name}.energy_{k}", "J") for k in BODY_ENERGIES]
        self.reactions = solver.reaction_regions()
        for region, components in self.reactions:
            self.columns += [(f"reaction.{region}_{axes[c]}", "N") for c in components]
        self.meters = [_Meter(solver, am) for am in m.accelerometers]
        self.notes = [meter.note for meter in self.meters]
        for am in m.accelerometers:
            # the velocity is the metrics' channel (its interval means cannot alias); the acceleration is
            # the node's own at the sample
            for quantity, unit in (("u", "m"), ("v", "m/s"), ("a", "m/s^2")):
                self.columns += [(f"accelerometer.{am.name}.{quantity}_{a}", unit) for a in axes]
        for source in solver.sources:           # contact pairs, springs, cavities, a target: each its own
            self.columns += source.columns(axes)
        self.sections = [SectionStresses(solver, cuts) for cuts in m.sections]
        for sec in self.sections:
            self.columns += sec.columns()
            self.notes.append(f"stress sections of {sec.name}: {sec.count} slabs of "
                              f"{sec.positions[0] * 2:.4g} m along its axis, axial and bending stress "
                              f"(plane fit over each section)")
        self.columns += [(f"energy.{k}", "J") for k in ENERGY_COLUMNS]
        self.columns += [("energy.balance_error", "-"), ("dt", "s")]
        # the rows so far, in an array that doubles as it fills; ``count`` of them are the history
        self._rows = np.empty((1024, len(self.columns)))
        self.count = 0
        self._streamed = 0                # rows written to the streamed CSV
        self._h5 = h5_path if solver.comm.rank == 0 else None
        self._snapshot_due = 0.0
        self._stream = None
        if csv_path and solver.comm.rank == 0:
            self._stream = open(csv_path, "w", newline="")
            self._csv = csv.writer(self._stream)
            self._csv.writerow(self._header())
            self._stream.flush()
            self._flushed = time.perf_counter()

    def resume(self, rows: np.ndarray):
        """Take the rows a checkpoint kept as the history so far (a resumed run): the streamed CSV starts
        again from them (its rows beyond the checkpoint are written again as the run goes on)."""
        rows = np.asarray(rows, dtype=float).reshape(-1, len(self.columns))
        self._rows = np.empty((max(1024, 2 * len(rows)), len(self.columns)))
        self._rows[:len(rows)] = rows
        self.count = len(rows)
        if self._stream is not None:
            self._write_stream()

    def _header(self) -> list[str]:
        return [f"{n} [{u}]" for n, u in self.columns]

    def record(self):
        """A row at the solver's time t: written into the history's array, streamed to the CSV a block at
        a time (every FLUSH_EVERY_S), and the HDF5 snapshot renewed when due.  Collective."""
        s = self.solver
        if self.count == len(self._rows):
            self._rows = np.concatenate([self._rows, np.empty_like(self._rows)])
        row = self._rows[self.count]
        row[0] = s.t
        v, a = s.body_means()
        k = 1
        gdim = v.shape[1]
        for vb, ab in zip(v, a):
            row[k:k + gdim] = vb
            row[k + gdim:k + 2 * gdim] = ab
            k += 2 * gdim
        energies = s.body_energies()
        for name in BODY_ENERGIES:          # per body, its energies in BODY_ENERGIES' order
            row[k + BODY_ENERGIES.index(name):k + len(BODY_ENERGIES) * len(v):len(BODY_ENERGIES)] = energies[name]
        k += len(BODY_ENERGIES) * len(v)
        for (region, components), force in zip(self.reactions, s.reactions()):
            row[k:k + len(components)] = force[components]
            k += len(components)
        for meter in self.meters:
            motion = meter.motion().reshape(-1)
            row[k:k + len(motion)] = motion
            k += len(motion)
        for source in s.sources:
            values = source.history()
            row[k:k + len(values)] = values
            k += len(values)
        for sec in self.sections:
            values = sec.record()
            row[k:k + len(values)] = values
            k += len(values)
        e = s.energy
        row[k:k + len(ENERGY_COLUMNS)] = [getattr(e, name) for name in ENERGY_COLUMNS]
        row[k + len(ENERGY_COLUMNS):] = e.balance_error, s.dt
        self.count += 1
        if self._stream is not None and time.perf_counter() - self._flushed > FLUSH_EVERY_S:
            self._write_stream()
        if self._h5 is not None and time.perf_counter() >= self._snapshot_due:
            self._snapshot(self._h5)

    def _write_stream(self):
        """The rows not yet streamed, to the CSV, flushed (the csv module's float repr: exact)."""
        self._csv.writerows(self._rows[self._streamed:self.count].tolist())
        self._streamed = self.count
        self._stream.flush()
        self._flushed = time.perf_counter()

    def array(self) -> np.ndarray:
        """The rows so far, (count, columns): a view of the history's own array."""
        return self._rows[:self.count]

    def column(self, name: str) -> np.ndarray:
        names = [c[0] for c in self.columns]
        return self.array()[:, names.index(name)]

    def _snapshot(self, h5_path: str):
        """The whole history as HDF5, written beside and renamed into place; the next one is due after
        SNAPSHOT_EVERY_S, or later if this one took more than SNAPSHOT_SHARE of that."""
        started = time.perf_counter()
        data = self.array()
        partial = h5_path + ".partial"
        with h5py.File(partial, "w") as f:
            for j, (name, unit) in enumerate(self.columns):
                ds = f.create_dataset(name, data=data[:, j])
                ds.attrs["unit"] = unit
        os.replace(partial, h5_path)
        took = time.perf_counter() - started
        self._snapshot_due = time.perf_counter() + max(SNAPSHOT_EVERY_S, took / SNAPSHOT_SHARE)

    def write(self, h5_path: str, csv_path: str):
        """The last HDF5 snapshot (written beside and renamed into place) and the CSV (closed if it was
        streamed, written whole if not)."""
        if self.solver.comm.rank != 0:
            return
        self._snapshot(h5_path)
        if self._stream is not None:
            self._write_stream()
            self._stream.close()
            self._stream = None
            return
        with open(csv_path, "w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow(self._header())
            w.writerows(self.array().tolist())


class _Meter:
    """An accelerometer's reading: the velocity of one node (on the rank that owns it), or the
    mass-weighted mean velocity of a section's nodes."""

    def __init__(self, solver: ExplicitSolver, meter):
        m = solver.model
        self.solver = solver
        body = m.body_names.index(meter.body)
        point = np.asarray(meter.point)
        mine = solver.owned & (m.node_body == body)
        if meter.section > 0.0:
            axis = np.asarray(m.bodies[body].axis)[:m.gdim] if m.gdim == 3 else np.eye(2)[1]
            self.nodes = np.flatnonzero(mine & (np.abs((m.X0 - point) @ axis) <= 0.5 * meter.section))
            count = solver.comm.allreduce(len(self.nodes), op=MPI.SUM) if solver.parallel else len(self.nodes)
            if count == 0:
                raise ModelError(f"accelerometer {meter.name}: no node of {meter.body} within "
                                 f"{meter.section / 2:.3g} m of the section through {meter.point}: widen its section")
            if m.gdim == 3:
                self.mass = self._centred_weights(solver, m.mass[self.nodes], m.X0[self.nodes] - point, axis)
            else:           # 2D: no spin; a section's mean is its mass-weighted mean
                total = m.mass[self.nodes].sum()
                total = solver.comm.allreduce(total, op=MPI.SUM) if solver.parallel else total
                self.mass = m.mass[self.nodes] / total
            self.owner = -1
            self.note = (f"accelerometer {meter.name}: mean of {int(count)} nodes of {meter.body} in the "
                         f"{meter.section:.3g} m section through {np.array2string(point, precision=5)} m")
            return
        candidates = np.flatnonzero(mine)
        if len(candidates):
            d = np.linalg.norm(m.X0[candidates] - point, axis=1)
            best = int(candidates[np.argmin(d)])
            local = (float(d.min()), solver.comm.rank)
        else:
            best, local = -1, (np.inf, solver.comm.rank)
        distance, self.owner = solver.comm.allreduce(local, op=MPI.MINLOC) if solver.parallel else local
        where = m.X0[best] if solver.comm.rank == self.owner else np.zeros(m.gdim)
        where = solver.comm.allreduce(where, op=MPI.SUM) if solver.parallel else where
        self.nodes = np.array([best])
        self.note = (f"accelerometer {meter.name}: node of {meter.body} at {np.array2string(where, precision=5)} m, "
                     f"{distance:.3g} m from the requested point")

    @staticmethod
    def _centred_weights(solver, mass, arm, axis):
        """Weights w_i = m_i (1 + l . r_i) / sum, r_i the nodes' arms square to the axis, l chosen so that
        sum w_i r_i = 0: the weighted section is centred on the axis, so a spin of the section about the
        axis adds nothing to its mean velocity (the plain mass centroid of a meshed slab sits a little off
        it and would circle).  Collective."""
        arm = arm - np.outer(arm @ axis, axis)
        moment = mass @ arm                                     # sum m_i r_i
        second = (mass[:, None] * arm).T @ arm                  # sum m_i r_i r_i^T
        if solver.parallel:
            moment = solver.comm.allreduce(moment, op=MPI.SUM)
            second = solver.comm.allreduce(second, op=MPI.SUM)
        # the plane square to the axis: second is singular along the axis, so solve in its range
        lam = -np.linalg.pinv(second, rcond=1e-12) @ moment
        w = mass * (1.0 + arm @ lam)
        total = solver.comm.allreduce(w.sum(), op=MPI.SUM) if solver.parallel else w.sum()
        return w / total

    def motion(self) -> np.ndarray:
        """Its displacement, velocity and acceleration at t (``ExplicitSolver.motion``), (3, gdim) on every
        rank.  Collective."""
        s = self.solver
        v, a = s.motion(self.nodes)
        u = s.x[self.nodes] - s.model.X0[self.nodes]
        if self.owner == -1:
            local = np.array([(self.mass[:, None] * q).sum(axis=0) for q in (u, v, a)])
        else:
            local = np.array([q[0] for q in (u, v, a)]) if s.comm.rank == self.owner else np.zeros((3, s.model.gdim))
        if s.parallel:
            s.comm.Allreduce(MPI.IN_PLACE, local, op=MPI.SUM)     # a buffer reduction: every sample
        return local

"""Time histories: per-body mean velocity and acceleration, accelerometer velocities, contact
forces, energies; HDF5 and CSV.

Columns carry their units in the header (``bar.v_z [m/s]``).  Only rank 0 writes.
Accelerometers record the *velocity* of their node: the shock metrics take acceleration as
its interval mean between samples, which cannot alias the stress waves above the sampling
rate (``metrics/signals.py``).
"""
from __future__ import annotations

import csv

import h5py
import numpy as np

from mpi4py import MPI

from ..solver.explicit import ExplicitSolver


ENERGY_COLUMNS = ("kinetic", "internal", "plastic", "damping", "hourglass", "bulk_viscosity", "contact",
                  "external", "balance")


class HistoryRecorder:
    def __init__(self, solver: ExplicitSolver):
        m = solver.model
        self.solver = solver
        axes = ("r", "z") if m.axisymmetric else "xyz"[:m.gdim]
        self.columns = [("time", "s")]
        for b in m.bodies:
            self.columns += [(f"{b.name}.v_{a}", "m/s") for a in axes]
            self.columns += [(f"{b.name}.a_{a}", "m/s^2") for a in axes]
        self.meters = [_place_accelerometer(solver, am) for am in m.accelerometers]
        self.notes = [note for _, _, note in self.meters]
        for am in m.accelerometers:
            self.columns += [(f"accelerometer.{am.name}.v_{a}", "m/s") for a in axes]
        for c in m.contacts:
            # the forces on surface a: normal (penalty and contact damping) and friction, as vectors
            self.columns += [(f"contact.{c.name}.normal_{a}", "N") for a in axes]
            self.columns += [(f"contact.{c.name}.friction_{a}", "N") for a in axes]
        for sp in m.springs:
            # the spring's force on its end a, as a vector (tension T along the unit a -> b)
            self.columns += [(f"spring.{sp.name}.force_{a}", "N") for a in axes]
        for cv in m.cavities:
            self.columns += [(f"cavity.{cv.name}.pressure", "Pa"), (f"cavity.{cv.name}.volume", "m^3"),
                             (f"cavity.{cv.name}.outflow", "kg/s"), (f"cavity.{cv.name}.orifice_area", "m^2")]
        if m.penetration:
            self.columns += [("penetration.depth", "m")]
            self.columns += [(f"penetration.force_{a}", "N") for a in axes]
            self.columns += [("penetration.axial_force", "N"), ("penetration.target_work", "J")]
            if m.gdim == 3:
                self.columns += [("penetration.spin", "rad/s"), ("penetration.torque", "N m")]
        self.columns += [(f"energy.{k}", "J") for k in ENERGY_COLUMNS]
        self.columns += [("energy.balance_error", "-"), ("dt", "s")]
        self.rows: list[list[float]] = []

    def record(self):
        s = self.solver
        v, a = s.body_means()
        e = s.energy
        row = [s.t]
        for vb, ab in zip(v, a):
            row += list(vb) + list(ab)
        for node, owner, _ in self.meters:
            vn = s.v[node] + 0.5 * s.dt * s.a[node] if s.comm.rank == owner else np.zeros(s.model.gdim)
            row += list(s.comm.allreduce(vn, op=MPI.SUM) if s.parallel else vn)
        for pair in s.contacts:
            row += list(pair.force_a) + list(pair.friction_a)
        for spring in s.springs:
            row += list(spring.tension * spring.direction)
        for cavity in s.cavities:
            row += [cavity.pressure, cavity.volume, cavity.outflow, cavity.orifice_area()]
        if s.target is not None:
            tg = s.target
            row += [tg.depth] + list(tg.force) + [tg.axial_force, -tg.work]
            if s.model.gdim == 3:
                row += [tg.spin, tg.torque]
        row += [getattr(e, k) for k in ENERGY_COLUMNS] + [e.balance_error, s.dt]
        self.rows.append(row)

    def array(self) -> np.ndarray:
        return np.array(self.rows) if self.rows else np.zeros((0, len(self.columns)))

    def column(self, name: str) -> np.ndarray:
        names = [c[0] for c in self.columns]
        return self.array()[:, names.index(name)]

    def write(self, h5_path: str, csv_path: str):
        if self.solver.comm.rank != 0:
            return
        data = self.array()
        with h5py.File(h5_path, "w") as f:
            for j, (name, unit) in enumerate(self.columns):
                ds = f.create_dataset(name, data=data[:, j])
                ds.attrs["unit"] = unit
        with open(csv_path, "w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow([f"{n} [{u}]" for n, u in self.columns])
            w.writerows(data.tolist())


def _place_accelerometer(solver: ExplicitSolver, meter) -> tuple[int, int, str]:
    """(local node, owning rank, note): the owned node of the accelerometer's body nearest to its point."""
    m = solver.model
    body = m.body_names.index(meter.body)
    candidates = np.flatnonzero(solver.owned & (m.node_body == body))
    point = np.asarray(meter.point)
    if len(candidates):
        d = np.linalg.norm(m.X0[candidates] - point, axis=1)
        best = int(candidates[np.argmin(d)])
        local = (float(d.min()), solver.comm.rank)
    else:
        best, local = -1, (np.inf, solver.comm.rank)
    distance, owner = solver.comm.allreduce(local, op=MPI.MINLOC) if solver.parallel else local
    where = m.X0[best] if solver.comm.rank == owner else np.zeros(m.gdim)
    where = solver.comm.allreduce(where, op=MPI.SUM) if solver.parallel else where
    note = (f"accelerometer {meter.name}: node of {meter.body} at {np.array2string(where, precision=5)} m, "
            f"{distance:.3g} m from the requested point")
    return best, owner, note


def read_history(path: str) -> tuple[dict[str, np.ndarray], dict[str, str]]:
    """(columns, units) of a ``history.csv``: arrays and units keyed by the column name, whose header
    is written as "name [unit]"."""
    with open(path) as fh:
        header = next(csv.reader(fh))
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    names, units = zip(*(h[:-1].rsplit(" [", 1) for h in header))
    return {n: data[:, j] for j, n in enumerate(names)}, dict(zip(names, units))


def read_history_csv(path: str) -> dict[str, np.ndarray]:
    """Columns of a ``history.csv`` keyed by name without the unit."""
    return read_history(path)[0]

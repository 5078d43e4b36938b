"""Each body's peak von Mises stress over the whole run, with where and when: a compiled pass every step.

Field frames are written at intervals longer than a stress wave's passage (a 70 us frame interval on a
rod struck for 100 us catches the rho c0 v / 2 front at half its height or not at all), so the peak is
taken from the stresses every step, at every integration point, instead of from the frames.  The pass
takes each body's largest squared value branch-free (it vectorises), and looks for the cell (up to the
first that holds it) only on a step that raises the peak: its cost per step is in ``docs/performance.md``.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit


@njit(cache=True, inline="always")
def von_mises2(sigma, c, q):
    """3 J2 = ((s11 - s22)^2 + (s22 - s33)^2 + (s33 - s11)^2) / 2 + 3 (s23^2 + s13^2 + s12^2), the squared von
    Mises stress at point ``q`` of cell ``c`` of ``sigma`` [..., 6] = [11, 22, 33, 23, 13, 12] [Pa^2]
    (``cell_fields.von_mises``, squared)."""
    a = sigma[c, q, 0]
    b = sigma[c, q, 1]
    d = sigma[c, q, 2]
    return (0.5 * ((a - b) * (a - b) + (b - d) * (b - d) + (d - a) * (d - a))
            + 3.0 * (sigma[c, q, 3] * sigma[c, q, 3] + sigma[c, q, 4] * sigma[c, q, 4]
                     + sigma[c, q, 5] * sigma[c, q, 5]))


@njit(cache=True, fastmath=True)
def largest_von_mises2(sigma, cells):
    """The largest squared von Mises stress over the points of ``cells`` [Pa^2].  Branch-free, so that it
    vectorises (fastmath: a run whose stresses are not finite is stopped by the solver's own check)."""
    largest = 0.0
    for k in range(len(cells)):
        for q in range(sigma.shape[1]):
            largest = max(largest, von_mises2(sigma, cells[k], q))
    return largest


@njit(cache=True)
def where_largest(sigma, cells, largest2):
    """The first cell of ``cells`` with a point at ``largest2`` (``largest_von_mises2``'s answer, to round-off:
    the vectorised pass may round differently) [Pa^2]; it stops there, so it reads half the cells on average.
    Run only on a step that raises a peak."""
    reach = largest2 * (1.0 - 1e-12)
    for k in range(len(cells)):
        for q in range(sigma.shape[1]):
            if von_mises2(sigma, cells[k], q) >= reach:
                return cells[k]
    return -1


class PeakStress:
    """The running peak of each body's von Mises stress (``largest_von_mises2`` on the solver's stresses
    after every step), and where (the cell's reference centre) and when it was reached."""

    def __init__(self, solver, state: dict | None = None):
        """``state``: what ``state()`` returned, from a checkpoint."""
        m = solver.model
        self.solver = solver
        n = len(m.bodies)
        kernel = np.asarray(m.kernel_cells, dtype=np.int64)
        # each body's owned deformable cells (a rigid body has none)
        self.cells = [kernel[m.cell_body[kernel] == b] for b in range(n)]
        self.peak = np.zeros(n)
        self.when = np.zeros(n)
        self.where = np.full(n, -1, dtype=np.int64)
        if state is not None:
            self.peak[:], self.when[:], self.where[:] = state["peak"], state["when"], state["where"]

    def update(self, t: float):
        """After a step that reached ``t`` [s]."""
        sigma = self.solver.sigma
        for b, cells in enumerate(self.cells):
            if not len(cells):
                continue
            largest2 = largest_von_mises2(sigma, cells)
            if largest2 > self.peak[b] * self.peak[b]:
                self.peak[b] = math.sqrt(largest2)
                self.when[b] = t
                self.where[b] = where_largest(sigma, cells, largest2)

    def state(self) -> dict:
        """This rank's running peaks, for a checkpoint."""
        return {"peak": self.peak.copy(), "when": self.when.copy(), "where": self.where.copy()}

    def per_body(self) -> list[dict]:
        """Each body's peak over all ranks: ``max_von_mises`` [Pa], ``time`` [s] and ``at`` (the reference
        centre of the cell [m]; None for a body that carried no stress).  Collective."""
        m = self.solver.model
        out = []
        for b in range(len(self.peak)):
            c = self.where[b]
            at = m.X0[m.dofmap[c]].mean(axis=0).tolist() if c >= 0 else None
            mine = (self.peak[b], self.when[b], at)
            best = max(m.comm.allgather(mine), key=lambda r: r[0]) if m.comm.size > 1 else mine
            out.append({"max_von_mises": float(best[0]), "time": float(best[1]) if best[2] is not None else None,
                        "at": best[2]})
        return out

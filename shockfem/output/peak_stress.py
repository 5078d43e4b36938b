"""Each body's peak von Mises stress over the whole run, with where and when: taken by the element pass.

Field frames are written at intervals longer than a stress wave's passage (a 70 us frame interval on a
rod struck for 100 us catches the rho c0 v / 2 front at half its height or not at all), so the peak is
taken from the stresses every step, at every integration point, instead of from the frames.  The element
pass, which has each cell's new stress at hand, keeps it: per row of the material parameters, the largest
squared von Mises stress so far, the time and the cell (``elements.blocks.track_peak``, the solver's
``peak``).  This module reads it per body.
"""
from __future__ import annotations

import math

import numpy as np

from ..elements.blocks import PEAK_CELL, PEAK_TIME, PEAK_VM2, no_peak
from ..model.mass_scaling import row_bodies


class PeakStress:
    """The peak of each body's von Mises stress over the run, and where (the cell's reference centre) and
    when it was reached, from the solver's ``peak`` (per row of params: a body's own row and those mass
    scaling split off it)."""

    def __init__(self, solver, state: dict | None = None):
        """``state``: what ``state()`` returned, from a checkpoint."""
        m = solver.model
        self.solver = solver
        # a row no cell of this rank's passes uses keeps ``no_peak``
        self.row_body = row_bodies(len(solver.peak), m.cell_body, m.cell_material)
        # the run's peaks from here: a checkpoint's, or none (what the solver's set-up or a preload stage's
        # settling passed through before the event is not the event's)
        solver.peak[:] = state["rows"] if state is not None else no_peak(len(solver.peak))

    def _mine(self, b: int) -> tuple[float, float, list | None]:
        """(peak [Pa], time [s], reference centre of the cell [m] or None) of body ``b`` on this rank."""
        m, peak = self.solver.model, self.solver.peak
        rows = np.flatnonzero(self.row_body == b)
        if not len(rows) or peak[rows, PEAK_CELL].max() < 0:
            return 0.0, 0.0, None
        r = rows[np.argmax(peak[rows, PEAK_VM2])]
        c = int(peak[r, PEAK_CELL])
        return math.sqrt(peak[r, PEAK_VM2]), float(peak[r, PEAK_TIME]), m.X0[m.dofmap[c]].mean(axis=0).tolist()

    def state(self) -> dict:
        """This rank's running peaks, for a checkpoint."""
        return {"rows": self.solver.peak.copy()}

    def per_body(self) -> list[dict]:
        """Each body's peak over all ranks: ``max_von_mises`` [Pa], ``time`` [s] and ``at`` (the reference
        centre of the cell [m]; None for a body that carried no stress).  Collective."""
        m = self.solver.model
        out = []
        for b in range(len(m.bodies)):
            mine = self._mine(b)
            best = max(m.comm.allgather(mine), key=lambda r: r[0]) if m.comm.size > 1 else mine
            out.append({"max_von_mises": float(best[0]), "time": float(best[1]) if best[2] is not None else None,
                        "at": best[2]})
        return out

"""Mass scaling for long events: mass added to the elements whose stable step is below a target step.

An explicit run steps at the stable step of its smallest element (h / c, times the safety factor).
A few small elements (a fillet, a thin lip, a graded mesh) can set a step far below the rest's, and a
5 ms event then takes hours.  LS-DYNA's DT2MS < 0 adds mass to just those elements: an element of
step dt_e < dt_target gets its density multiplied by f = (dt_target / dt_e)^2, which lowers its wave
speed by sqrt(f) and so lifts its step to the target.  The price is inertia that is not there: the
added mass is reported per body with its share of the body's mass, and a run whose scaling would add
more than ``scene.mass_scaling_limit`` (5% by default) of any body's mass is refused.

Done once, on the initial mesh (LS-DYNA rescales every cycle as elements deform): an element crushed
during the run still shortens the step, and the step-collapse guard stops a run that collapses.

Each scaled element's density goes to a copy of its body's parameter row (density times f, wave speed
over sqrt(f)), so the element kernels, the bulk viscosity and the hourglass control see the scaled
element without a per-cell density array; factors are rounded up to steps of 0.2% (``FACTOR_STEP``) so
that a graded mesh makes tens of rows, not one per element.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..geometry.quality import characteristic_lengths
from ..materials import layout

FACTOR_STEP = 1.002         # scaling factors are rounded up to powers of this (0.2% steps)


@dataclass
class MassScaling:
    """What the scaling did (the same on every rank for the totals)."""
    time_step: float                                   # the target [s]
    cells: dict[str, int] = field(default_factory=dict)             # scaled cells per body
    added_mass: dict[str, float] = field(default_factory=dict)      # [kg] per body
    share: dict[str, float] = field(default_factory=dict)           # added / original body mass
    largest_factor: float = 1.0                        # of any element's density

    def as_dict(self) -> dict:
        return {"time_step_s": self.time_step, "largest_density_factor": self.largest_factor,
                "bodies": {name: {"cells": self.cells[name], "added_mass_kg": self.added_mass[name],
                                  "added_share": self.share[name]} for name in self.cells}}

    def describe(self) -> str:
        scaled = [f"{name} +{self.added_mass[name]:.4g} kg ({self.share[name]:.2%}, {self.cells[name]} elements)"
                  for name in self.cells if self.cells[name]]
        what = "; ".join(scaled) if scaled else "no element is below it"
        return (f"mass scaling to a step of {self.time_step:.4g} s: {what}; the added mass is inertia the "
                f"parts do not have (waves slow by up to {math.sqrt(self.largest_factor):.3g}x in the scaled "
                f"elements), set once on the initial mesh")


def row_bodies(num_rows: int, cell_body: np.ndarray, cell_material: np.ndarray) -> np.ndarray:
    """The body of each of the ``num_rows`` rows of params: row k is body k's own, and a row ``scale_rows``
    split off a body's row for its scaled cells is that body's (read from the cells on it)."""
    rows = np.arange(num_rows)
    cells = cell_body >= 0
    rows[cell_material[cells]] = cell_body[cells]
    return rows


def element_steps(X0, dofmap, cell_name: str, wave_speed: np.ndarray, safety_factor: float) -> np.ndarray:
    """Each cell's stable step as the mesh check estimates it: safety x characteristic length / wave speed."""
    lengths = characteristic_lengths(X0[dofmap], cell_name)
    return safety_factor * lengths / wave_speed


def scale_rows(params: np.ndarray, curves: np.ndarray, cell_material: np.ndarray, steps: np.ndarray,
               target: float, scaled_cells: np.ndarray):
    """Rows for the cells of ``scaled_cells`` (bool) whose ``steps`` are below ``target``: returns
    (params, curves, cell_material, factor per cell) with the new rows appended."""
    factor = np.ones(len(cell_material))
    below = scaled_cells & (steps < target)
    if not below.any():
        return params, curves, cell_material, factor
    exact = (target / steps[below]) ** 2
    level = np.ceil(np.log(exact) / np.log(FACTOR_STEP) - 1e-9).astype(np.int64)
    factor[below] = FACTOR_STEP ** level
    keys = np.stack([cell_material[below], level], axis=1)
    unique, which = np.unique(keys, axis=0, return_inverse=True)
    new_rows = params[unique[:, 0]].copy()
    f = FACTOR_STEP ** unique[:, 1].astype(float)
    new_rows[:, layout.P_RHO] *= f
    new_rows[:, layout.P_WAVE_SPEED] /= np.sqrt(f)
    cell_material = cell_material.copy()
    cell_material[np.flatnonzero(below)] = len(params) + which.ravel()
    return (np.vstack([params, new_rows]), np.concatenate([curves, curves[unique[:, 0]]]), cell_material,
            factor)

"""The fluid dashpot as two rigid masses on a compressible liquid column: the lumped dashpot's bodies
(``lumped_dashpot.py``) with the liquid of ``fluid/column.py`` (its mass, waves, cavitation, the jet)
instead of a control volume at one pressure.

The striker (the housing, less the liquid, which the column now carries) closes at V on the payload
(piston and article, at rest); the column runs from the bore's floor to the piston, moving with the
housing at first:

    (M - m_l) x_s'' = -p_floor A,     m x_p'' = p_piston A - J,     a = a(s), s = L0 - (x_p - x_s)

integrated by symplectic Euler on the column's own step (its Courant limit).  Left out: everything
elastic in the bodies (the finite-element run has that), and what the column leaves out (its
docstring: friction on the bore, liquid returning through the orifice).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..fluid.column import ColumnLiquid, LiquidColumn
from .lumped_dashpot import LumpedDashpot

CELLS = 200                     # the column's cells (``verify liquid_column`` shows the pulse converged)


@dataclass(frozen=True)
class ColumnRun:
    t: np.ndarray                       # [s]
    acceleration: np.ndarray            # the payload's [m/s^2]
    pressure: np.ndarray                # at the piston's face [Pa]
    floor_pressure: np.ndarray          # at the bore's floor [Pa]
    stroke: np.ndarray                  # [m]
    payload_speed: np.ndarray           # [m/s]
    striker_speed: np.ndarray           # [m/s]
    cavity: np.ndarray                  # the column's void [m^3]
    summary: dict                       # the column's accounts at the end (``LiquidColumn.summary``)
    steps: int


def column_liquid(d: LumpedDashpot) -> ColumnLiquid:
    """The column's liquid with the lumped dashpot's density, modulus and Tait exponent."""
    return ColumnLiquid(density=d.density, bulk_modulus=d.bulk_modulus, tait_exponent=d.tait_exponent)


def simulate_column(d: LumpedDashpot, end_time: float, samples: int = 4000, cells: int = CELLS,
                    liquid: ColumnLiquid | None = None) -> ColumnRun:
    """The dashpot ``d`` from first contact to ``end_time`` with its liquid as a column of ``cells``
    finite volumes, sampled at ``samples`` even times (the state of the step that reaches each)."""
    liquid = liquid or column_liquid(d)
    L0, A = d.column, d.piston_area
    column = LiquidColumn(liquid, 0.0, L0, A, cells, d.orifice_law(), d.initial_pressure, d.speed)
    housing = d.striker_mass - column.mass()
    if housing <= 0.0:
        raise ValueError(f"column dashpot: the striker's {d.striker_mass:.4g} kg must outweigh its liquid's "
                         f"{column.mass():.4g} kg")
    pin = np.array(d.pin, dtype=float).reshape(-1, 2)
    t_out = np.linspace(0.0, end_time, samples)
    rows = np.zeros((samples, 7))
    v_s, v_p, t, k, steps = d.speed, 0.0, 0.0, 0, 0
    force_p = d.initial_pressure * A
    while k < samples:
        stroke = L0 - column.length()
        if t >= t_out[k]:
            rows[k] = (force_p / d.payload_mass, column.piston_pressure, column.floor_pressure, stroke, v_p, v_s,
                       column.void())
            k += 1
            continue
        if column.length() <= 1e-3 * L0:
            raise RuntimeError(f"column dashpot: the piston reached the floor at t = {t:.6g} s")
        dt = min(column.stable_step(v_s, v_p), t_out[k] - t) if t_out[k] > t else column.stable_step(v_s, v_p)
        area = float(np.interp(stroke, pin[:, 0], pin[:, 1]))
        force_f, force_p = column.step(v_s, v_p, area, dt)
        v_s += dt * force_f / housing
        v_p += dt * force_p / d.payload_mass
        t += dt
        steps += 1
    r = rows.T
    return ColumnRun(t_out, r[0], r[1], r[2], r[3], r[4], r[5], r[6], column.summary(), steps)

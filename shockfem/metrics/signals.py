"""Uniformly sampled signals from run histories.

A run records the mass-weighted mean velocity of each body at the history cadence.  Its
acceleration is taken as the *interval mean* (v_{k+1} - v_k) / dt rather than the
instantaneous nodal acceleration at the sample: the interval mean cannot alias the
stress-wave content above the sampling rate into the pulse, and it integrates back to the
velocity change exactly (the sum telescopes).
"""
from __future__ import annotations

import numpy as np


def uniform_times(t: np.ndarray, dt: float | None = None) -> np.ndarray:
    """A uniform grid over ``t[0] .. t[-1]`` with step ``dt`` (default: the median sample
    interval, so a record taken every step with a slowly varying step keeps its resolution)."""
    t = np.asarray(t, dtype=float)
    if len(t) < 2:
        raise ValueError("a signal needs at least two samples")
    if dt is None:
        dt = float(np.median(np.diff(t)))
    if not dt > 0:
        raise ValueError(f"sample interval must be > 0, got {dt}")
    n = int(np.floor((t[-1] - t[0]) / dt * (1 + 1e-9))) + 1
    return t[0] + dt * np.arange(n)


def acceleration_from_velocity(t: np.ndarray, v: np.ndarray, dt: float | None = None
                               ) -> tuple[np.ndarray, np.ndarray]:
    """Interval-mean acceleration of a velocity history on a uniform grid.

    Parameters
    ----------
    t, v : sample times [s] and velocities [m/s] (any spacing, increasing times)
    dt : grid step [s]; default the median sample interval

    Returns
    -------
    (t_mid, a) : the midpoints of the uniform grid intervals [s] and the mean acceleration
        over each interval [m/s^2]; ``sum(a) * dt`` equals the velocity change of the grid.
    """
    grid = uniform_times(t, dt)
    v_grid = np.interp(grid, t, v)
    step = grid[1] - grid[0]
    return 0.5 * (grid[1:] + grid[:-1]), np.diff(v_grid) / step


def crossing_time(t: np.ndarray, y: np.ndarray, i: int, level: float) -> float:
    """Time at which ``y`` crosses ``level`` between samples ``i`` and ``i + 1`` (linear)."""
    y0, y1 = y[i], y[i + 1]
    if y1 == y0:
        return float(t[i])
    return float(t[i] + (level - y0) / (y1 - y0) * (t[i + 1] - t[i]))

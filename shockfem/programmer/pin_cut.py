"""The metering pin cut on the liquid column: the orifice's area table a(x) iterated against the column's
own force history, not the quasi-steady law it starts from.

The closed form (``dashpot_design``) cuts the pin on the incompressible orifice law: at each stroke x
the area that makes the design force at the relative speed a constant force leaves.  On the column the
force at x is not that: the contact front carries part of the flow with the liquid, the floor reflects
it doubled, and the force overshoots where the waves return.  ``cut_pin`` runs the column with a(x),
reads the payload's force F_col(x) against the stroke, and updates the table by the orifice law's
scaling, the force ~ (Q / a)^2 at a given flow:

    a_new(x) = clip(a(x) (F_col(x) / F_target(x))^(omega / 2), a_min, a_max)

with ``RELAXATION`` omega, each step's factor capped at exp(``STEP_CAP``), the log ratio smoothed over
``SMOOTHING`` pin points either side.  F_target is the design force (``design["force"]``) held over the
stroke, reached over the checked shape's rise (MIL-STD-810's trapezoid: 10% of the duration) at the time
the run reaches x.

What the fixed point assumes, and how it is made to hold:
- the force at a stroke answers the area there (locally, as the quasi-steady law says), and the waves
  couple it only to what happened before (causality: the force at x does not depend on a beyond x),
  no sooner than the waves an area sends return from the floor.  So the iteration marches: each step
  leaves alone the prefix of the stroke already within tolerance (held at a bound, or passed: below)
  and updates the table from the first point that is not, over the strokes the run reaches within one transit of the
  column left, (L0 - x) / c, after it (a wave's round trip is longer: the window is a lower bound);
- the run's stroke rises monotonically to its end (the payload does not rebound inside the body read);
- the body read is the stroke from the first pin point to where the relative speed falls below
  ``BODY_SPEED`` of the closing speed (there the pin closes toward its end and the force falls as the
  speed does, whatever the area); the table beyond it is left as it is.

The bounds: a_max the orifice law's largest area ratio times the bore (``OrificeLaw.largest_ratio``:
the law's checked data unless the design widens it), a_min the machinable pin's least annulus, a radial
gap of ``LEAST_GAP`` in the piston's hole.  Where the force is over its target with the pin already at
a_max (or under it at a_min), no pin in the law's range does better there: the point is held, and the
iteration goes on past it.

Convergence: the largest |F_col / F_target - 1| over the body past the rise within ``TOLERANCE``
("converged"), or no point left outside it that is neither held at a bound nor passed, or
``ITERATIONS`` runs.  The march never goes back; a point it has worked on for ``STALL`` iterations
without bringing it inside (its bin holds the arrival of a returning wave, which moves along the stroke
as the table changes) is passed, its residual left.  The best table found (the least largest deviation,
or the least of a designer's ``score``) is the one returned, with each iteration's peak overshoot (the
largest F_col / F_target - 1 past the rise) and largest deviation.  The cut pin is then checked by
every validity check of ``dashpot_validity`` (``column_design.confirm``), as any design is.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..metrics import shapes
from .column_dashpot import CELLS, simulate_column
from .dashpot_design import LUMPED_SAMPLES, PulseSpec, dashpot_lumped
from .liquids import DesignLiquid

RELAXATION = 1.0            # omega: the quasi-steady exponent whole (the waves make the force answer less)
STEP_CAP = 0.2              # at most a factor exp(0.2) = 1.22 on an area in one iteration
SMOOTHING = 2               # the log ratio averaged over this many pin points either side
TOLERANCE = 0.05            # the force within 5% of its target: well inside the band's 20% less its 3% design margin
ITERATIONS = 40
STALL = 3
BODY_SPEED = 0.1            # the body read ends where the relative speed falls below this share of V
LEAST_GAP = 1.0e-4          # [m] the pin's least radial gap in the piston's hole: a turned pin's clearance


@dataclass(frozen=True)
class CutStep:
    """One iteration: its peak overshoot (largest F_col / F_target - 1 over the body past the rise), its
    largest deviation |F_col / F_target - 1|, the payload's peak [m/s^2], the stroke's first point outside
    the tolerance that could still move [m] (nan: none), and the largest overshoot where the pin is held
    at the law's largest opening (what no pin in the law's range takes off there; 0: none)."""
    overshoot: float
    deviation: float
    peak: float
    first_free: float
    held_overshoot: float

    def as_dict(self) -> dict:
        return {"overshoot": self.overshoot, "deviation": self.deviation, "peak": self.peak,
                "first_free": self.first_free, "held_overshoot": self.held_overshoot}


def least_area(d: dict) -> float:
    """The pin's least opening [m^2]: a radial gap of ``LEAST_GAP`` in the hole of the law's largest
    opening (the piston's hole)."""
    r_hole = math.sqrt(d["orifice_law"]["largest_ratio"] * d["piston_area"] / math.pi)
    return math.pi * (r_hole ** 2 - max(r_hole - LEAST_GAP, 0.0) ** 2)


def pin_bounds(d: dict) -> tuple[float, float]:
    """The cut pin's bounds [m^2]: (``least_area``, the law's largest area ratio times the bore)."""
    return least_area(d), d["orifice_law"]["largest_ratio"] * d["piston_area"]


def target_force(d: dict, pulse: PulseSpec, t: np.ndarray) -> np.ndarray:
    """F_target at the times ``t`` [s] from contact: the design force, reached over the checked shape's
    rise (a rectangle's checked trapezoid: 10% of the duration; none for a shape without one)."""
    rise = shapes.specified(pulse.checked_shape, pulse.peak, pulse.duration).rise
    return d["force"] * (np.minimum(t / rise, 1.0) if rise > 0.0 else np.ones_like(t))


def force_on_stroke(d: dict, pulse: PulseSpec, run, x: np.ndarray):
    """The run's payload force, its target and the time averaged over each pin point's share of the
    stroke (midpoints between points), and the body read (``BODY_SPEED``): (F_col, F_target, t, body)."""
    end = int(np.argmax(run.stroke))
    s = np.maximum.accumulate(run.stroke[:end + 1])
    force = run.acceleration[:end + 1] * d["payload_mass"]
    target = target_force(d, pulse, run.t[:end + 1])
    relative = (run.striker_speed - run.payload_speed)[:end + 1]
    edges = 0.5 * (x[1:] + x[:-1])
    share = np.searchsorted(edges, s)
    count = np.bincount(share, minlength=len(x))[:len(x)]
    mean = lambda y: np.bincount(share, y, minlength=len(x))[:len(x)] / np.maximum(count, 1)
    body = (count > 0) & (mean(relative) > BODY_SPEED * d["striker_speed"]) & (np.arange(len(x)) >= 1)
    return mean(force), mean(target), mean(run.t[:end + 1]), body


def _smoothed(y: np.ndarray, width: int) -> np.ndarray:
    kernel = np.ones(2 * width + 1) / (2 * width + 1)
    return np.convolve(np.pad(y, width, mode="edge"), kernel, mode="valid")


def cut_pin(d: dict, pulse: PulseSpec, liquid: DesignLiquid, cells: int = CELLS, iterations: int = ITERATIONS,
            tolerance: float = TOLERANCE, echo=None, score=None) -> tuple:
    """The design ``d`` (``dashpot_design``) with its pin cut on the column at ``cells`` (the module's
    fixed point): (a copy of ``d`` with the best pin found and, under ``"pin_cut"``, each iteration's
    ``CutStep``, the best iteration, whether it converged (within ``tolerance``) and why it stopped;
    the best pin's column run, or None if no run completed).  ``score(design, run)``: what "best" means
    among the iterates (the least; a designer's own objective); by default the largest deviation."""
    pin = np.array(d["pin"], dtype=float)
    x, a = pin[:, 0], pin[:, 1].copy()
    a_min, a_max = pin_bounds(d)
    a = np.clip(a, a_min, a_max)
    steps, best, best_run, stop = [], None, None, f"{iterations} iterations"
    front, stuck, scores = 0, 0, []
    trial = dict(d)
    rise = shapes.specified(pulse.checked_shape, pulse.peak, pulse.duration).rise
    c = liquid.sound_speed()
    for k in range(iterations):
        trial["pin"] = [[float(u), float(v)] for u, v in zip(x, a)]
        try:
            run = simulate_column(dashpot_lumped(trial), pulse.record_end(), LUMPED_SAMPLES, cells, liquid.column())
        except (RuntimeError, ValueError) as exc:        # the piston reached the floor: keep the best
            stop = f"the column did not run ({exc})"
            break
        force, target, t, body = force_on_stroke(trial, pulse, run, x)
        ratio = np.where(body, force / np.where(body, target, 1.0), 1.0)
        off = body & (np.abs(ratio - 1.0) > tolerance)
        held = ((ratio > 1.0) & (a >= a_max * (1 - 1e-9))) | ((ratio < 1.0) & (a <= a_min * (1 + 1e-9)))
        free = np.flatnonzero(off & ~held & (np.arange(len(x)) >= front))
        topped = body & (t >= rise)         # the convergence is read past the rise (the front's step is the law's)
        deviation = float(np.max(np.abs(ratio[topped] - 1.0), initial=0.0))
        steps.append(CutStep(float(np.max(force[topped], initial=0.0)) / d["force"] - 1.0, deviation,
                             float(np.max(np.abs(run.acceleration))), float(x[free[0]]) if len(free) else math.nan,
                             float(np.max(ratio[topped & held & (ratio > 1.0)] - 1.0, initial=0.0))))
        if echo:
            echo(f"    pin cut {k}: overshoot {steps[-1].overshoot:+.3f}, deviation {deviation:.3f}")
        value = deviation if score is None else score(trial, run)
        scores.append(float(value))
        if best is None or value < scores[best]:
            best, best_pin, best_run = k, a.copy(), run
        if deviation <= tolerance:
            stop = "converged"
            break
        if not len(free):
            stop = "every point outside the tolerance held at a bound or passed"
            break
        # the march never goes back; a point it has worked on for ``STALL`` iterations without bringing
        # it inside (its bin holds a returning wave's arrival, which moves with the stroke) is passed
        front, stuck = (free[0], 0) if free[0] > front else (front, stuck + 1)
        if stuck >= STALL:
            later = free[free > front]
            if not len(later):
                stop = "every point outside the tolerance held at a bound or passed"
                break
            front, stuck = later[0], 0
        change = np.clip(0.5 * RELAXATION * _smoothed(np.log(ratio), SMOOTHING), -STEP_CAP, STEP_CAP)
        change[:front] = 0.0             # the prefix already within tolerance (held, or passed) stays as it is
        # later than one transit of the column left from the march's front, the force answers this
        # step's change too (its waves return from the floor): that part waits for the next iterations
        change[t > t[front] + (d["column"] - x[front]) / c] = 0.0
        a = np.clip(a * np.exp(change), a_min, a_max)
    out = dict(d)
    if best is not None:
        out["pin"] = [[float(u), float(v)] for u, v in zip(x, best_pin)]
    out["pin_cut"] = {"steps": [{**s.as_dict(), "score": v} for s, v in zip(steps, scores)], "best": best, "stop": stop,
                      "converged": stop == "converged", "cells": cells, "tolerance": tolerance,
                      "least_area": a_min, "largest_area": a_max}
    return out, best_run

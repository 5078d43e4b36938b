"""The striker that carries its housing: the fixed point of a design with the housing it needs.

A design at a striker ratio r (striker over payload) closes at the collision law's speed for r; its
column's pressures size its housing, and the striker must weigh at least that housing with its pin and
oil: the ratio it asks, needed(r).  A heavier striker closes slower, so the pressure, the wall and the
housing fall: g(r) = needed(r) - r decreases with r, and the striker is its root, never below the least
ratio asked (where g(least) < 0, the least ratio already carries its housing and stands).

The search goes both ways from a start (``striker_fixed_point``): each trial ratio is a new design
(``needed_at``, the caller's: the designer reuses its found handles at the trial ratio, or searches
again), the next trial the ratio that design's housing asks, until a ratio where g > 0 and one where
g < 0 bracket the root, then false position with the Illinois halving within the bracket, to a share
``tol`` of the ratio, at most ``most`` designs after the first.  A lighter striker closes faster and
raises the pressure, so the root may lie outside a law's range or beyond what a housing holds: the
caller's ``admissible`` says which designs are inside every check, and where the root's design is not,
the lightest admissible trial that carries its housing is kept (a heavier striker than it needs is
ballast, not a fault).  The range of validity: g decreasing in r (a trial sequence where it is not still
ends, at ``most``, on the lightest trial that carries its housing, and says it did not converge).

The design at a trial ratio (``redesigned``): the found design's handles designed again at it are kept
only where that design is admissible and scores no worse than the found one by more than the searches'
own settle tolerance; else the handles are searched again from there, and the better of the two kept (an
admissible one over one that is not, then the lower score): reused handles that score worse than a search
would find are not the design at that striker.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

# the striker's fixed point with its housing: to this share of its ratio (each trial is a design whose
# search has its own tolerance: a finer share than its ``HANDLES_SETTLED`` would chase the search's noise),
# in at most this many designs after the first
STRIKER_TOLERANCE, STRIKER_REDESIGNS = 0.02, 6


@dataclass(frozen=True)
class Trial:
    """One design of the search: the ratio it was made at, the ratio its housing asks, and whether it
    is inside every check the caller vetoes on."""
    ratio: float
    needed: float
    admissible: bool

    def carries(self, tol: float) -> bool:
        """The design's striker weighs its housing (to ``tol``)."""
        return self.needed <= self.ratio * (1.0 + tol)


@dataclass(frozen=True)
class FixedPoint:
    """The striker ratio kept, the design at it (``state``, the caller's) and the search's record."""
    ratio: float
    needed: float
    state: object
    trials: tuple                 # of ``Trial``, in the order made
    converged: bool               # a trial within the tolerance of its housing's ratio, or the least carrying it
    binds: bool                   # the housing sets the ratio (the root above the least ratio is kept)
    kept: str                     # why this trial: "fixed point", "least ratio", "heavier admissible", ...

    @property
    def redesigns(self) -> int:
        return len(self.trials) - 1

    def record(self) -> dict:
        return {"ratio": self.ratio, "needed": self.needed, "converged": self.converged, "binds": self.binds,
                "kept": self.kept, "redesigns": self.redesigns,
                "trials": [{"ratio": t.ratio, "needed": t.needed, "admissible": t.admissible} for t in self.trials]}


def striker_fixed_point(needed_at: Callable, least: float, start: float | None = None,
                        tol: float = STRIKER_TOLERANCE, most: int = STRIKER_REDESIGNS,
                        admissible: Callable | None = None) -> FixedPoint:
    """The striker ratio r >= ``least`` at which the design's housing asks r (to ``tol`` of r), searched
    from ``start`` (``least`` if None) both ways.  ``needed_at(r)`` designs at r and returns (the ratio
    its housing asks, the design); ``admissible(design)``: the design is inside every vetoing check (all
    are, if None).  At most ``most`` designs after the first; unconverged, the lightest admissible trial
    that carries its housing (else the lightest that carries it, else the last) with ``converged`` False."""
    x = least if start is None else max(start, least)
    trials, states = [], []
    lo = hi = None                       # (ratio, g) where g = needed - ratio > 0, and < 0
    side = 0
    for k in range(most + 1):
        need, state = needed_at(x)
        trials.append(Trial(x, need, True if admissible is None else bool(admissible(state))))
        states.append(state)
        g = need - x
        if abs(g) <= tol * x:
            return _kept(trials, states, k, "fixed point", need >= least, tol)
        if g < 0 and x <= least:
            return _kept(trials, states, k, "least ratio", False, tol)
        # Illinois: an end kept twice running has its mismatch halved, so the bracket closes from both sides
        if g > 0:
            hi = (hi[0], hi[1] / 2) if side == 1 and hi else hi
            lo, side = (x, g), 1
        else:
            lo = (lo[0], lo[1] / 2) if side == -1 and lo else lo
            hi, side = (x, g), -1
        x = lo[0] - lo[1] * (hi[0] - lo[0]) / (hi[1] - lo[1]) if lo and hi else max(least, need)
    return _unconverged(trials, states, tol)


def redesigned(reuse: Callable, search: Callable, admissible: Callable, score: Callable, reference: float,
               tol: float):
    """The design at a trial ratio: ``reuse()`` (the found handles designed again at it) where it is
    ``admissible`` and its ``score`` is within ``tol`` of ``reference`` (the found design's score, lower
    is better: the searches' own settle tolerance, a finer one chases their noise); else ``search(reused)``
    from it, and of the two the admissible one, then the one of the lower score (the reused one on a tie
    of both)."""
    state = reuse()
    if admissible(state) and score(state) <= reference + tol * abs(reference):
        return state
    again = search(state)
    return again if (admissible(again), -score(again)) > (admissible(state), -score(state)) else state


def _kept(trials, states, k, why, binds, tol) -> FixedPoint:
    """The converged trial ``k`` if it is admissible, else the lightest admissible trial that carries its
    housing (heavier than the root: it carries it with ballast), else trial ``k`` all the same."""
    if not trials[k].admissible:
        heavier = [i for i, t in enumerate(trials) if t.admissible and t.carries(tol) and t.ratio >= trials[k].ratio]
        if heavier:
            i = min(heavier, key=lambda i: trials[i].ratio)
            return FixedPoint(trials[i].ratio, trials[i].needed, states[i], tuple(trials), True, False,
                              f"heavier admissible (the {why} at {trials[k].ratio:.4g} is outside a check)")
        why += " (outside a check; no admissible trial carries its housing)"
    return FixedPoint(trials[k].ratio, trials[k].needed, states[k], tuple(trials), True, binds, why)


def _unconverged(trials, states, tol) -> FixedPoint:
    """No trial within the tolerance: the lightest trial whose striker carries its housing and is
    admissible, else the lightest that carries it, else the last, each said so."""
    order = sorted(range(len(trials)), key=lambda i: trials[i].ratio)
    carrying = [i for i in order if trials[i].carries(tol)]
    for pick, why in (([i for i in carrying if trials[i].admissible], "lightest admissible carrying"),
                      (carrying, "lightest carrying (outside a check)"),
                      ([len(trials) - 1], "last (none carries its housing)")):
        if pick:
            i = pick[0]
            return FixedPoint(trials[i].ratio, trials[i].needed, states[i], tuple(trials), False, False,
                              f"not converged: {why}")

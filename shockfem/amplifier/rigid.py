"""Event-driven rigid-body model of a mass chain (the ``rigid`` fidelity).

Bodies sit in a line along x, in order, each with a length and a speed; interface k joins body
k and body k + 1 with its own restitution; an optional rigid anvil stands before body 1 (at
x = 0, bodies at x > 0).  The model jumps from collision to collision: the next one is the
closing gap that closes first; a collision is instantaneous (``gain.collide``).  It stops when
no gap is closing, and records every collision, so the first pass (each body's speed just after
it is first struck) and the final state (after any later collisions) are both available.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy.optimize import brentq

from .gain import collide

# A chain of inelastic collisions can go on without end (inelastic collapse); stop it here.
MAX_COLLISIONS = 10_000


@dataclass
class Collision:
    time: float        # [s]
    left: int          # body index, -1 for the anvil
    right: int
    before: tuple[float, float]
    after: tuple[float, float]


@dataclass
class ChainResult:
    masses: np.ndarray
    initial: np.ndarray              # [m/s]
    final: np.ndarray                # after the last collision
    first_pass: np.ndarray           # each body's speed just after it is first struck (nan: never)
    collisions: list[Collision] = field(default_factory=list)
    stopped: str = "no gap is closing"

    @property
    def kinetic_energy(self) -> tuple[float, float]:
        """(initial, final) kinetic energy [J]."""
        return (0.5 * float(self.masses @ self.initial ** 2), 0.5 * float(self.masses @ self.final ** 2))


def pad_restitution(zeta: float) -> float:
    """Restitution of two rigid bodies meeting on a linear spring-dashpot pad that never pulls,
    of damping ratio ``zeta`` on their reduced mass, whatever the stiffness and the masses.

    The pad lets go when its force k x + c x' falls to zero, before the spring is back at rest;
    with beta = zeta w0 and w = w0 sqrt(1 - zeta^2) (Schwager and Poeschel, Granular Matter 2007):
        e = exp(-(beta / w) (pi - atan2(2 beta w, w^2 - beta^2)))
    which is above exp(-pi zeta / sqrt(1 - zeta^2)), the value if the pad could pull.
    """
    if not 0 <= zeta < 1:
        raise ValueError(f"pad damping ratio must be in [0, 1), got {zeta}")
    w = math.sqrt(1 - zeta * zeta)
    return math.exp(-(zeta / w) * (math.pi - math.atan2(2 * zeta * w, w * w - zeta * zeta)))


def run_chain(masses, velocities, lengths, gaps, restitution, anvil: float | None = None,
              anvil_gap: float = 0.0) -> ChainResult:
    """Follow a chain to its last collision.

    Parameters
    ----------
    masses, velocities, lengths : per body [kg], [m/s] (along +x), [m]
    gaps : the n - 1 gaps between neighbours [m] (>= 0)
    restitution : the n - 1 interface restitutions (and ``anvil`` for the anvil's), [-]
    anvil : restitution against a rigid anvil before body 1, or None for no anvil
    anvil_gap : distance from the anvil to body 1 [m]
    """
    m = np.asarray(masses, dtype=float)
    v = np.asarray(velocities, dtype=float).copy()
    L = np.asarray(lengths, dtype=float)
    n = len(m)
    e = list(restitution)
    x = np.zeros(n)                     # left faces
    x[0] = anvil_gap
    for k in range(1, n):
        x[k] = x[k - 1] + L[k - 1] + gaps[k - 1]
    initial = v.copy()
    first = np.full(n, np.nan)
    t = 0.0
    out = ChainResult(m, initial, v, first)
    for _ in range(MAX_COLLISIONS):
        # time to close each gap that is closing (index -1: the anvil)
        best, which = math.inf, None
        if anvil is not None and v[0] < 0:
            best, which = x[0] / -v[0], -1
        for k in range(n - 1):
            closing = v[k] - v[k + 1]
            if closing > 0:
                dt = (x[k + 1] - x[k] - L[k]) / closing
                if dt < best:
                    best, which = dt, k
        if which is None:
            break
        dt = max(best, 0.0)
        x += v * dt
        t += dt
        if which == -1:
            before = (v[0], 0.0)
            v[0], _ = collide(m[0], v[0], math.inf, 0.0, anvil)
            x[0] = 0.0
            out.collisions.append(Collision(t, -1, 0, before, (v[0], 0.0)))
            continue
        k = which
        x[k + 1] = x[k] + L[k]           # exactly touching (no round-off overlap)
        before = (v[k], v[k + 1])
        v[k], v[k + 1] = collide(m[k], v[k], m[k + 1], v[k + 1], e[k])
        out.collisions.append(Collision(t, k, k + 1, before, (v[k], v[k + 1])))
        if math.isnan(first[k + 1]):
            first[k + 1] = v[k + 1]
    else:
        out.stopped = f"stopped after {MAX_COLLISIONS} collisions (inelastic collapse)"
    out.final = v
    return out


def launched_chain(masses, speed: float, e: float, lengths=None, gap: float = 1e-3) -> ChainResult:
    """Body 1 at ``speed`` into the others at rest, spaced by ``gap``."""
    n = len(masses)
    lengths = lengths if lengths is not None else [0.1] * n
    return run_chain(masses, [speed] + [0.0] * (n - 1), lengths, [gap] * (n - 1), [e] * (n - 1))


def stack_on_anvil(masses, speed: float, e: float, lengths=None, gap: float = 1e-3,
                   shrink: float = 1e-2) -> ChainResult:
    """The stack falling at ``speed`` onto a rigid anvil (restitution ``e``), heaviest body first.

    ``gap`` separates body 1 from the anvil; the gaps shrink by ``shrink`` at each level up the
    stack, so the impulse runs up the stack before the bottom body can fall back onto the anvil:
    the sequence the closed form assumes.  Equal gaps, or a stack whose bodies touch, strike in
    other orders and give other speeds (``run_chain`` follows whatever order the gaps set)."""
    n = len(masses)
    lengths = lengths if lengths is not None else [0.0] * n
    return run_chain(masses, [-speed] * n, lengths, [gap * shrink ** (k + 1) for k in range(n - 1)],
                     [e] * (n - 1), anvil=e, anvil_gap=gap)


def designed_chain(masses, speed: float, restitutions, lengths, gap: float,
                   architecture: str = "launched-chain") -> ChainResult:
    """The chain as the machine's amplifier runs it: interface k at ``restitutions[k]``, every gap ``gap``;
    launched (body 1 at ``speed`` into the others at rest) or a stack falling at ``speed`` onto an anvil
    of the interfaces' mean restitution."""
    n = len(masses)
    e = list(restitutions)
    if architecture == "launched-chain":
        return run_chain(masses, [speed] + [0.0] * (n - 1), lengths, [gap] * (n - 1), e)
    return run_chain(masses, [-speed] * n, lengths, [gap] * (n - 1), e, anvil=sum(e) / len(e), anvil_gap=gap)


def first_closing_speeds(masses, speed: float, e: float, architecture: str = "launched-chain") -> list[float]:
    """Closing speed of each neighbour pair at its first collision in a rigid launched chain (or a stack
    falling on an anvil of the same restitution)."""
    chain = launched_chain if architecture == "launched-chain" else stack_on_anvil
    first: dict[int, float] = {}
    for c in chain(masses, speed, e).collisions:
        if c.left >= 0:
            first.setdefault(c.left, abs(c.before[0] - c.before[1]))
    return [first[k] for k in range(len(masses) - 1)]


def effective_restitution(masses, speed: float, gain: float, architecture: str = "launched-chain") -> float:
    """The single restitution that gives a rigid chain of ``masses`` (launched, or a stack falling on an
    anvil of the same restitution) this ``gain`` (nan when no e in (0, 1] does)."""
    chain = launched_chain if architecture == "launched-chain" else stack_on_anvil

    def excess(e):
        return chain(masses, speed, e).final[-1] / speed - gain
    if excess(1e-6) > 0 or excess(1.0) < 0:
        return float("nan")
    return float(brentq(excess, 1e-6, 1.0, xtol=1e-10))

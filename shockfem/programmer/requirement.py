"""What a specified pulse asks of a programmer: the velocity change, the stroke, the force and the
energy for the article's mass.

The article meets the programmer at the pulse's velocity change dV and is brought to rest by it,
with no rebound (the velocity change is the pulse's area).  The stroke is the relative travel while
it stops, s = integral of v dt with v(t) = dV - integral of a, which is the pulse's first moment
integral of t a(t) dt (integrate by parts); for a rectangle of peak A and
duration T: dV = A T, s = A T^2 / 2; half-sine: 2 A T / pi, A T^2 / pi; terminal-peak sawtooth:
A T / 2, A T^2 / 3 (``fixtures.md``).  The stroke is integrated from the ideal pulse
(``metrics.shapes``) rather than written per shape, so that every shape the metrics know, a
trapezoid's ramps included, gets one; ``shockfem verify programmer_sizing`` checks it against the
closed forms above.
"""
from __future__ import annotations

from dataclasses import asdict, dataclass

import numpy as np

from ..metrics.shapes import IdealPulse, specified
from ..units import G0
# midpoints of the ideal pulse for its first moment: the jumps of a rectangle or a sawtooth fall on
# the ends, never on a sample, and the error of a smooth pulse is ~1e-11
_SAMPLES = 400_000


@dataclass(frozen=True)
class Requirement:
    """What a pulse asks of a programmer for an article of ``mass``."""
    shape: str
    peak: float              # A [m/s^2]
    duration: float          # T [s]
    mass: float              # the article (with what moves with it) [kg]
    velocity_change: float   # dV [m/s]
    stroke: float            # [m]
    force: float             # peak force m A [N]
    energy: float            # m dV^2 / 2 [J]

    def as_dict(self) -> dict:
        return asdict(self)

    @property
    def peak_g(self) -> float:
        return self.peak / G0


def ideal(shape: str, peak: float, duration: float) -> IdealPulse:
    """The ideal pulse of a shape; a rectangle is a trapezoid without ramps."""
    if shape == "rectangle":
        return IdealPulse("trapezoid", peak, duration, 0.0)
    return specified(shape, peak, duration)


def requirement(shape: str, peak: float, duration: float, mass: float) -> Requirement:
    pulse = ideal(shape, peak, duration)
    dv = pulse.velocity_change
    h = pulse.end / _SAMPLES
    t = (np.arange(_SAMPLES) + 0.5) * h
    stroke = float(h * np.sum(t * pulse(t)))
    return Requirement(shape, peak, duration, mass, dv, stroke, mass * peak, 0.5 * mass * dv * dv)

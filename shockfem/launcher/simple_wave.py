"""The ideal gun with an infinitely long chamber of the bore's section (the simple-wave gun) in closed form.

The gas starts at rest at p0, sound speed c0; the projectile (no friction, nothing ahead) is driven by the
base pressure of the centred expansion wave that follows it (Seigel, "The theory of high speed guns",
AGARDograph 91, 1965, ch. 3; the project's lumped gun takes the same law as ``gas_inertia="simple-wave"``):

    p / p0 = pi(u) = [1 - (gamma - 1) u / (2 c0)]^(2 gamma / (gamma - 1)),

which falls to zero at the escape speed 2 c0 / (gamma - 1).  With m u du/dx = p0 A pi(u), the travel to
reach u is x = m I(u) / (p0 A), I(u) = int_0^u s / pi(s) ds; with w = 1 - a u, a = (gamma - 1) / (2 c0),
k = 2 gamma / (gamma - 1):

    I(u) = [(1 - w^(1 - k)) / (1 - k) - (1 - w^(2 - k)) / (2 - k)] / a^2.

So the projectile's kinetic energy over p0 A x, the work the reservoir's pressure would do at constant
pressure over that travel, is eta(u) = u^2 / (2 I(u)), whatever the mass, bore and pressure: a gun's
efficiency is set by its muzzle speed over its gas's sound speed alone.  p0 A x is also the gun's size: a
thin barrel at the allowable S weighs 2 rho_steel p0 A x / S.  eta is an upper bound on any gun of that gas
and temperature at that pressure (a finite chamber, a valve and the air ahead only lower it).  Range: a
perfect gas at rest in the chamber (Noble-Abel covolume left out), u below the escape speed.
"""
from __future__ import annotations

import math

from scipy.optimize import brentq


def base_pressure_ratio(u: float, c0: float, gamma: float) -> float:
    """p / p0 behind a projectile at ``u`` [m/s] (zero at and past the escape speed)."""
    w = 1 - (gamma - 1) * u / (2 * c0)
    return max(w, 0.0) ** (2 * gamma / (gamma - 1))


def _integral(u: float, c0: float, gamma: float) -> float:
    """I(u) = int_0^u s / pi(s) ds [m^2/s^2] (module docstring); inf at and past the escape speed."""
    a = (gamma - 1) / (2 * c0)
    k = 2 * gamma / (gamma - 1)
    if a * u >= 1:
        return math.inf
    # 1 - w^j as -expm1(j log1p(-a u)): the two terms agree to first order in a u, so they are formed to
    # round-off before they are subtracted
    ln_w = math.log1p(-a * u)
    return (-math.expm1((1 - k) * ln_w) / (1 - k) + math.expm1((2 - k) * ln_w) / (2 - k)) / (a * a)


def travel(u: float, mass: float, pressure: float, area: float, c0: float, gamma: float) -> float:
    """Barrel travel [m] that brings ``mass`` [kg] to ``u`` [m/s] at chamber ``pressure`` [Pa] on ``area``
    [m^2], the chamber gas's sound speed ``c0`` (``Gas.sound_speed``)."""
    return mass * _integral(u, c0, gamma) / (pressure * area)


def efficiency(u: float, c0: float, gamma: float) -> float:
    """Kinetic energy at the muzzle speed ``u`` [m/s] over p0 A x (module docstring) [-]; 1 as u -> 0."""
    if u <= 1e-6 * c0:
        return 1.0
    return 0.5 * u * u / _integral(u, c0, gamma)


def muzzle_speed(length: float, mass: float, pressure: float, area: float, c0: float, gamma: float) -> float:
    """The speed [m/s] at which ``mass`` leaves a barrel of ``length`` [m] (``travel`` inverted)."""
    top = 2 * c0 / (gamma - 1)
    return float(brentq(lambda u: travel(u, mass, pressure, area, c0, gamma) - length, 0.0, top * (1 - 1e-12),
                        xtol=1e-9))

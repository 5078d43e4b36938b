"""The ideal guns in closed form: an infinitely long chamber of the bore's section (the simple-wave gun), and
an infinitely large chamber (the infinitely chambered gun).

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
thin barrel at the allowable S weighs 2 rho_steel p0 A x / S.  The simple-wave gun is the constant-area
(unchambered) gun: a finite chamber, a valve and the air ahead lower its eta, but a chamber wider than the
bore (chambrage) raises it, so it is no bound on a gun with a tank behind its breech.

The infinitely chambered gun (``chambered=True``; Seigel, ch. 3, infinite chambrage) is that bound: the
gas flows steadily and isentropically from a chamber at rest into the bore at the projectile's speed,

    p / p0 = [1 - (gamma - 1) u^2 / (2 c0^2)]^(gamma / (gamma - 1))      for u <= u* = c0 sqrt(2 / (gamma + 1)),

where the bore's entry chokes (the gas there at its sound speed c* = u*, p* = p0 (2 / (gamma + 1))^(gamma /
(gamma - 1))); above u* the bore's gas expands from that sonic state in a simple wave,
p = p* [1 - (gamma - 1) (u - u*) / (2 c*)]^(2 gamma / (gamma - 1)), to the escape speed u* + 2 c* / (gamma - 1).
Below u* its I(u) is closed too: with v = 1 - (gamma - 1) u^2 / (2 c0^2), d(v^(-1 / (gamma - 1)))/du = 2 u
v^(-gamma / (gamma - 1)) / c0^2, so I(u) = c0^2 (v^(-1 / (gamma - 1)) - 1); above it the sonic state's
I(u*) plus the simple wave's from there.  No gun of that gas, temperature and pressure gives a higher base
pressure at any speed than a chamber of unlimited size and section: eta of the chambered gun is the upper
bound the simple-wave gun is not.

Range of both: a perfect gas at rest in the chamber (Noble-Abel covolume left out: at 345 bar air's
compressibility Z is about 1.1), u below the escape speed, no friction, nothing ahead.
"""
from __future__ import annotations

import math

from scipy.optimize import brentq


def base_pressure_ratio(u: float, c0: float, gamma: float) -> float:
    """p / p0 behind a projectile at ``u`` [m/s] (zero at and past the escape speed)."""
    w = 1 - (gamma - 1) * u / (2 * c0)
    return max(w, 0.0) ** (2 * gamma / (gamma - 1))


def sonic_speed(c0: float, gamma: float) -> float:
    """u* = c* = c0 sqrt(2 / (gamma + 1)) [m/s]: the speed at which the chambered gun's bore entry chokes."""
    return c0 * math.sqrt(2 / (gamma + 1))


def sonic_pressure_ratio(gamma: float) -> float:
    """p* / p0 = (2 / (gamma + 1))^(gamma / (gamma - 1)): the chambered gun's pressure at its choked bore entry."""
    return (2 / (gamma + 1)) ** (gamma / (gamma - 1))


def chambered_pressure_ratio(u: float, c0: float, gamma: float) -> float:
    """p / p0 behind a projectile at ``u`` [m/s] in the infinitely chambered gun (module docstring)."""
    star = sonic_speed(c0, gamma)
    if u <= star:
        return max(1 - (gamma - 1) * u * u / (2 * c0 * c0), 0.0) ** (gamma / (gamma - 1))
    return sonic_pressure_ratio(gamma) * base_pressure_ratio(u - star, star, gamma)


def _integral(u: float, c0: float, gamma: float, chambered: bool = False) -> float:
    """I(u) = int_0^u s / pi(s) ds [m^2/s^2] (module docstring); inf at and past the escape speed."""
    if chambered:
        return _chambered_integral(u, c0, gamma)
    a = (gamma - 1) / (2 * c0)
    k = 2 * gamma / (gamma - 1)
    if a * u >= 1:
        return math.inf
    # 1 - w^j as -expm1(j log1p(-a u)): the two terms agree to first order in a u, so they are formed to
    # round-off before they are subtracted
    ln_w = math.log1p(-a * u)
    return (-math.expm1((1 - k) * ln_w) / (1 - k) + math.expm1((2 - k) * ln_w) / (2 - k)) / (a * a)


def _steady_integral(u: float, c0: float, gamma: float) -> float:
    """I(u) of the infinitely chambered gun up to u* (the steady inflow), c0^2 (v^(-1 / (gamma - 1)) - 1),
    v = 1 - (gamma - 1) u^2 / (2 c0^2) (module docstring), formed as expm1 of log1p for round-off at small u."""
    return c0 * c0 * math.expm1(-math.log1p(-(gamma - 1) * u * u / (2 * c0 * c0)) / (gamma - 1))


def _chambered_integral(u: float, c0: float, gamma: float) -> float:
    """I(u) of the infinitely chambered gun: the steady inflow's closed form up to u* (``_steady_integral``),
    then the simple wave from the sonic state, int_u*^u s / pi ds = (I_c*(u - u*) + u* J(u - u*)) / p*,
    I_c* the simple-wave integral with c0 = c* and J(x) = int_0^x w^(-k) ds = (w^(1 - k) - 1) / (a (k - 1)),
    w = 1 - a x; inf past the escape speed."""
    star = sonic_speed(c0, gamma)
    if u >= escape_speed(c0, gamma, True):
        return math.inf
    low = _steady_integral(min(u, star), c0, gamma)
    if u <= star:
        return low
    x = u - star
    a, k = (gamma - 1) / (2 * star), 2 * gamma / (gamma - 1)
    J = math.expm1((1 - k) * math.log1p(-a * x)) / (a * (k - 1))
    return low + (_integral(x, star, gamma) + star * J) / sonic_pressure_ratio(gamma)


def escape_speed(c0: float, gamma: float, chambered: bool = False) -> float:
    """The speed [m/s] at which the base pressure falls to zero: 2 c0 / (gamma - 1), or u* + 2 c* / (gamma - 1)
    chambered."""
    if chambered:
        star = sonic_speed(c0, gamma)
        return star + 2 * star / (gamma - 1)
    return 2 * c0 / (gamma - 1)


def travel(u: float, mass: float, pressure: float, area: float, c0: float, gamma: float,
           chambered: bool = False) -> float:
    """Barrel travel [m] that brings ``mass`` [kg] to ``u`` [m/s] at chamber ``pressure`` [Pa] on ``area``
    [m^2], the chamber gas's sound speed ``c0`` (``Gas.sound_speed``)."""
    return mass * _integral(u, c0, gamma, chambered) / (pressure * area)


def efficiency(u: float, c0: float, gamma: float, chambered: bool = False) -> float:
    """Kinetic energy at the muzzle speed ``u`` [m/s] over p0 A x (module docstring) [-]; 1 as u -> 0."""
    if u <= 1e-6 * c0:
        return 1.0
    return 0.5 * u * u / _integral(u, c0, gamma, chambered)


def muzzle_speed(length: float, mass: float, pressure: float, area: float, c0: float, gamma: float,
                 chambered: bool = False) -> float:
    """The speed [m/s] at which ``mass`` leaves a barrel of ``length`` [m] (``travel`` inverted)."""
    top = escape_speed(c0, gamma, chambered)
    return float(brentq(lambda u: travel(u, mass, pressure, area, c0, gamma, chambered) - length, 0.0,
                        top * (1 - 1e-9), xtol=1e-9))

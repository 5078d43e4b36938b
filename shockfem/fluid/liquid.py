"""The laws of a compressible liquid and its orifice, shared by the finite-element cavity
(``cavity.py``) and the lumped dashpot (``programmer/lumped_dashpot.py``).

    p    = K / n ((rho / rho0)^n - 1)         gauge pressure, Tait's law (n = 1: linear, the bulk
                                              modulus K at rest); never below 0 (the liquid cavitates
                                              rather than pulls)
    c    = sqrt(dp / drho) = sqrt(K (rho / rho0)^(n - 1) / rho0)
    mdot                                      the orifice jet (``orifice.py``: quasi-steady, into a
                                              space at zero gauge pressure, held at the sound speed),
                                              at the liquid's pressure and density

Compiled (numba, without fastmath: the same arithmetic as Python's), since the cavity solves its
outflow with them every step (``outflow_over_step``) and the lumped dashpot's integrator calls them at
every stage: as Python functions they were most of a dashpot run's time.
"""
from __future__ import annotations

import math

from numba import njit

from . import orifice


@njit(cache=True)
def pressure(ratio: float, K: float, n: float) -> float:
    """Gauge pressure at the density ratio rho / rho0."""
    return max(0.0, K / n * (ratio ** n - 1.0))


@njit(cache=True)
def sound_speed(ratio: float, K: float, n: float, rho0: float) -> float:
    return math.sqrt(K * ratio ** (n - 1.0) / rho0)


@njit(cache=True)
def orifice_mass_flow(ratio: float, area: float, passage: float, law, K: float, n: float, rho0: float) -> float:
    """The mass rate [kg/s] through an orifice of ``area`` in a passage of area ``passage`` from liquid at
    the density ratio ``ratio``, by the orifice ``law`` (``orifice.OrificeLaw.code``)."""
    return orifice.mass_flow(pressure(ratio, K, n), rho0 * ratio, sound_speed(ratio, K, n, rho0), area, passage,
                             law)


def compression_energy(ratio: float, K: float, n: float, rho0: float) -> float:
    """The compression energy per unit mass of liquid at ``ratio``, int p / rho^2 drho from rho0 [J/kg]."""
    if ratio <= 1.0:
        return 0.0
    if abs(n - 1.0) < 1e-12:
        return K / rho0 * (math.log(ratio) + 1.0 / ratio - 1.0)
    return K / (n * rho0) * ((ratio ** (n - 1.0) - 1.0) / (n - 1.0) + 1.0 / ratio - 1.0)


@njit(cache=True)
def outflow_over_step(mass: float, volume: float, dt: float, area: float, passage: float, law, K: float, n: float,
                      rho0: float) -> float:
    """The mass m an orifice of ``area`` lets out of ``mass`` of liquid in ``volume`` over a step ``dt``, at
    the pressure it leaves behind (backward Euler: m = dt mdot(M - m)), by bisection to 1e-13 of the mass:
    g(m) = m - dt mdot(M - m) rises with m from g(0) < 0 to g(M - rho0 V) > 0 (no pressure left).  One
    step's compression, K dV / V, can exceed the pressure itself: taking the outflow at the start-of-step
    pressure would overshoot it every step."""
    high = mass - rho0 * volume
    if high <= 0.0 or orifice_mass_flow(mass / (rho0 * volume), area, passage, law, K, n, rho0) == 0.0:
        return 0.0
    low = 0.0
    for _ in range(60):
        mid = 0.5 * (low + high)
        if mid - dt * orifice_mass_flow((mass - mid) / (rho0 * volume), area, passage, law, K, n, rho0) > 0.0:
            high = mid
        else:
            low = mid
        if high - low <= 1e-13 * mass:
            break
    return 0.5 * (low + high)

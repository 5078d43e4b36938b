"""The fluid dashpot as two rigid masses and a lumped liquid: the cheapest model of the fixture study's
dashpot, to design on before a finite-element run confirms the design.

A striker of mass M (carrying the housing and its liquid) closes at V on a payload of mass m (the
piston and the article, at rest).  The liquid between them, of volume V(s) = V0 - A s for the
relative stroke s, holds a mass that the orifice lets out; its pressure and jet follow
``fluid/liquid.py`` (the same laws as the finite-element cavity), the orifice area is the metering
pin's table of s:

    m x_p'' = p A,   M x_s'' = -p A,   s = x_s - x_p,   M_l' = -mdot(M_l / (rho0 V(s)), a(s))

Left out, as in the cavity: the liquid's inertia and waves, and everything elastic in the bodies
(the finite-element run has that); ``shockfem study fixture`` shows the two agree.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp

from ..fluid import liquid


@dataclass(frozen=True)
class LumpedDashpot:
    striker_mass: float                 # M [kg]
    payload_mass: float                 # m [kg]
    speed: float                        # V, the striker's closing speed [m/s]
    piston_area: float                  # A [m^2]
    column: float                       # the liquid column at rest, V0 / A [m]
    pin: tuple                          # ((stroke [m], orifice area [m^2]), ...), stroke rising
    density: float                      # rho0 [kg/m^3]
    bulk_modulus: float                 # K [Pa]
    discharge: float                    # Cd
    tait_exponent: float = 1.0
    initial_pressure: float = 0.0       # a pre-charge [Pa] (gauge), as the cavity's


@dataclass(frozen=True)
class LumpedRun:
    t: np.ndarray                       # [s]
    acceleration: np.ndarray            # the payload's [m/s^2]
    pressure: np.ndarray                # [Pa]
    stroke: np.ndarray                  # [m]
    payload_speed: np.ndarray           # [m/s]
    striker_speed: np.ndarray           # [m/s]


def simulate(d: LumpedDashpot, end_time: float, samples: int = 4000) -> LumpedRun:
    """Integrate the dashpot from first contact to ``end_time`` (adaptive Runge-Kutta, relative
    tolerance 1e-8), sampled at ``samples`` even times."""
    A, K, n, rho0 = d.piston_area, d.bulk_modulus, d.tait_exponent, d.density
    V0 = A * d.column
    pin_s, pin_a = np.array([p[0] for p in d.pin]), np.array([p[1] for p in d.pin])

    def state(y):
        s, mass = y[0], y[3]
        volume = max(V0 - A * s, 1e-12 * V0)
        ratio = mass / (rho0 * volume)
        return volume, ratio, liquid.pressure(ratio, K, n)

    def rates(t, y):
        volume, ratio, p = state(y)
        area = float(np.interp(y[0], pin_s, pin_a))
        mdot = liquid.orifice_mass_flow(ratio, area, d.discharge, K, n, rho0)
        return [y[1] - y[2], -p * A / d.striker_mass, p * A / d.payload_mass, -mdot]

    t = np.linspace(0.0, end_time, samples)
    mass0 = rho0 * (1.0 + n * d.initial_pressure / K) ** (1.0 / n) * V0
    sol = solve_ivp(rates, (0.0, end_time), [0.0, d.speed, 0.0, mass0], t_eval=t, rtol=1e-8, atol=1e-12,
                    max_step=end_time / 2000)
    p = np.array([state(y)[2] for y in sol.y.T])
    return LumpedRun(sol.t, p * A / d.payload_mass, p, sol.y[0], sol.y[2], sol.y[1])

"""A tank's choked blowdown: a fixed volume V at p0 and the chamber's temperature emptying through a throat of
area A (C_d 1) into the test cell, the closed form the gas drive's control volumes are checked against
(``machine.drive_end``, ``verify gas_drive``) and whose flow factor its ported law uses.

A fixed volume emptying isentropically through a choked throat has the closed form (Shapiro, The Dynamics
and Thermodynamics of Compressible Fluid Flow, vol. 1, ch. 4; any gas-dynamics text's "discharge of a
vessel"):

    p(t) = p0 (1 + (gamma - 1) / 2 * t / tau)^(-2 gamma / (gamma - 1)),   tau = V / (Gamma A c0),
    Gamma = (2 / (gamma + 1))^((gamma + 1) / (2 (gamma - 1))),

valid while the throat is choked, p >= p_a / (2 / (gamma + 1))^(gamma / (gamma - 1)); its thrust is
C_F p A with C_F = (gamma + 1) (2 / (gamma + 1))^(gamma / (gamma - 1)) (the sonic exit's momentum and
pressure, the ambient left out: an upper bound), and its impulse to
unchoking is C_F A p0 tau (2 / (gamma + 1)) (1 - (p_u / p0)^((gamma + 1) / (2 gamma))).

Range: a perfect gas, the tank's gas isentropic (no heat from the wall: the real gas cools less, so its
pressure falls more slowly and the impulse is a little larger), the bore's throat at its full area with no
loss (the valve open), the choked phase only (the subsonic tail's impulse left out, small against it since
the pressure is then below twice the ambient).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

ATMOSPHERE = 101325.0        # the test cell's pressure [Pa]


@dataclass
class Blowdown:
    """The choked blowdown of one tank."""
    time_constant: float     # tau [s]
    choked_time: float       # until the throat unchokes [s]
    impulse: float           # the jet's thrust integrated over the choked phase [N s]
    peak_thrust: float       # at p0 [N]


def thrust_coefficient(gamma: float) -> float:
    """C_F of a sonic exit fed at stagnation p0, the ambient left out (module docstring)."""
    return (gamma + 1) * (2 / (gamma + 1)) ** (gamma / (gamma - 1))


def mass_flow_factor(gamma: float) -> float:
    """Gamma = (2 / (gamma + 1))^((gamma + 1) / (2 (gamma - 1))) (module docstring)."""
    return (2 / (gamma + 1)) ** ((gamma + 1) / (2 * (gamma - 1)))


def time_constant(volume: float, area: float, c0: float, gamma: float) -> float:
    """tau = V / (Gamma A c0) [s] (module docstring)."""
    return volume / (mass_flow_factor(gamma) * area * c0)


def pressure(t, p0: float, tau: float, gamma: float):
    """The tank's pressure [Pa] at ``t`` [s] after the blowdown starts (module docstring, the choked phase)."""
    return p0 * (1 + 0.5 * (gamma - 1) * t / tau) ** (-2 * gamma / (gamma - 1))


def blowdown(volume: float, area: float, p0: float, c0: float, gamma: float, ambient: float = ATMOSPHERE) -> Blowdown:
    """The choked blowdown of ``volume`` [m^3] at ``p0`` [Pa], sound speed ``c0`` [m/s], through ``area`` [m^2]
    (module docstring)."""
    tau, c_f = time_constant(volume, area, c0, gamma), thrust_coefficient(gamma)
    p_u = ambient / (2 / (gamma + 1)) ** (gamma / (gamma - 1))
    if p0 <= p_u:
        return Blowdown(tau, 0.0, 0.0, c_f * p0 * area)
    t_u = 2 * tau / (gamma - 1) * ((p_u / p0) ** (-(gamma - 1) / (2 * gamma)) - 1)
    impulse = c_f * area * p0 * tau * 2 / (gamma + 1) * (1 - (p_u / p0) ** ((gamma + 1) / (2 * gamma)))
    return Blowdown(tau, t_u, impulse, c_f * p0 * area)

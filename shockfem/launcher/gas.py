"""Gas state and orifice flow.

A lumped volume of gas holds mass m and internal energy U = m c_v T.  Ideal gas: p V = m R T.
Noble-Abel (the ``real`` option, for pressures where the molecules' own volume matters):
p (V - m b) = m R T, covolume b; its internal energy is still c_v T, so p = (gamma - 1) U / (V - m b).

Mass flow through an orifice of effective area Cd A from a source (p0, T0) to a back pressure p
(isentropic nozzle; the source's stagnation state):

    choked, p / p0 <= (2 / (gamma + 1))^(gamma / (gamma - 1)):
        mdot = Cd A p0 sqrt(gamma / (R T0)) (2 / (gamma + 1))^((gamma + 1) / (2 (gamma - 1)))
    otherwise:
        mdot = Cd A p0 sqrt(2 gamma / ((gamma - 1) R T0) ((p/p0)^(2/gamma) - (p/p0)^((gamma + 1)/gamma)))
"""
from __future__ import annotations

import math
from dataclasses import dataclass


@dataclass(frozen=True)
class Gas:
    name: str
    gamma: float          # heat-capacity ratio [-]
    R: float              # specific gas constant [J/(kg K)]
    covolume: float = 0.0  # Noble-Abel b [m^3/kg]; 0: ideal

    @property
    def cv(self) -> float:
        return self.R / (self.gamma - 1)

    @property
    def cp(self) -> float:
        return self.gamma * self.cv

    def pressure(self, m: float, U: float, V: float) -> float:
        return (self.gamma - 1) * U / (V - m * self.covolume)

    def temperature(self, m: float, U: float) -> float:
        return U / (m * self.cv) if m > 0 else 0.0

    def mass_for(self, p: float, T: float, V: float) -> float:
        """Mass of gas at p, T in V [kg]."""
        return V / (self.R * T / p + self.covolume)

    def sound_speed(self, p: float, T: float) -> float:
        """Frozen sound speed [m/s] (Noble-Abel: c^2 = gamma p / (rho (1 - b rho)))."""
        rho = 1.0 / (self.R * T / p + self.covolume)
        return math.sqrt(self.gamma * p / (rho * (1 - self.covolume * rho)))

    def real(self) -> "Gas":
        """The Noble-Abel version of this gas (covolume from the table below)."""
        return Gas(self.name + " (Noble-Abel)", self.gamma, self.R, COVOLUMES[self.name])


# gamma, R: air 1.4, 287.05; nitrogen 1.4, 296.8; helium 5/3, 2077.1 (8.3145 J/mol K over 4.0026e-3
# kg/mol).  Covolumes from the van der Waals b (air 3.66e-5 m^3/mol over 0.02897 kg/mol; nitrogen 3.87e-5
# over 0.02801; helium 2.38e-5 over 4.0026e-3): 1.26e-3, 1.38e-3 and 5.95e-3 m^3/kg.
GASES = {"air": Gas("air", 1.4, 287.05), "nitrogen": Gas("nitrogen", 1.4, 296.8),
         "helium": Gas("helium", 5 / 3, 2077.1)}
COVOLUMES = {"air": 1.26e-3, "nitrogen": 1.38e-3, "helium": 5.95e-3}


# Relative pressure difference below which orifice flow is taken linear in the difference.
EQUAL = 1e-4


def orifice_flow(gas: Gas, area: float, p_up: float, T_up: float, p_down: float) -> float:
    """Mass flow [kg/s] from upstream (p_up, T_up) to p_down <= p_up through effective area
    ``area`` (Cd A).  Which side is upstream is the caller's to decide."""
    if area <= 0 or p_down >= p_up or p_up <= 0 or T_up <= 0:
        return 0.0
    g = gas.gamma
    ratio = max(p_down / p_up, 0.0)
    critical = (2 / (g + 1)) ** (g / (g - 1))
    if ratio <= critical:
        return area * p_up * math.sqrt(g / (gas.R * T_up)) * (2 / (g + 1)) ** ((g + 1) / (2 * (g - 1)))
    scale = 1.0
    if ratio > 1 - EQUAL:
        # the flow goes as sqrt(p_up - p_down) as the pressures equalise, whose derivative is
        # infinite: below a difference of EQUAL it is taken linear (continuous), so the ODE
        # solver does not crawl through the equalisation
        scale, ratio = (1 - ratio) / EQUAL, 1 - EQUAL
    return scale * area * p_up * math.sqrt(2 * g / ((g - 1) * gas.R * T_up)
                                           * (ratio ** (2 / g) - ratio ** ((g + 1) / g)))

"""Gas state and orifice flow.

A lumped volume of gas holds mass m and internal energy U = m c_v T.  Ideal gas: p V = m R T.
Noble-Abel (the ``real`` option, for pressures where the molecules' own volume matters):
p (V - m b) = m R T, covolume b; its internal energy is still c_v T, so p = (gamma - 1) U / (V - m b).

Mass flow through an orifice of effective area Cd A from a source (p0, T0) to a back pressure p
(isentropic nozzle; the source's stagnation state): ``orifice_flow``, which calls the compiled law
``fluid.gas_column.orifice_mass_flow`` (its equations there), the one the gas column's bleed calls.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from ..fluid.gas_column import orifice_mass_flow


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


def orifice_flow(gas: Gas, area: float, p_up: float, T_up: float, p_down: float) -> float:
    """Mass flow [kg/s] from upstream (p_up, T_up) to p_down <= p_up through effective area
    ``area`` (Cd A) (``fluid.gas_column.orifice_mass_flow``: choked or not, linear in the pressure
    difference below ``EQUAL`` of it).  Which side is upstream is the caller's to decide."""
    return orifice_mass_flow(gas.gamma, gas.R, area, p_up, T_up, p_down)

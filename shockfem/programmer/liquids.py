"""The liquids a fluid dashpot may be filled with, as a designer must know them: density, compressibility,
viscosity and how it rises with pressure, the pressure at which the liquid parts, and the pressure at
which it stops being a liquid.

Viscosity under pressure (what sets the orifice's Reynolds number at a dashpot's hundreds of MPa):
Roelands' law (Hamrock, Schmid & Jacobson, Fundamentals of Fluid Film Lubrication, 2nd ed., 2004,
eq. 4.11 and 4.13), which follows measured mineral oils to about 1 GPa, where Barus' exp(alpha p)
overstates them by orders of magnitude:

    log10 mu + 1.2 = (log10 mu0 + 1.2) (1 + p / 196.1 MPa)^Z        mu in mPa s (cP)
    Z = alpha / (5.1e-9 (ln mu0 + 9.67))                            mu0 in Pa s, alpha in 1/Pa

with alpha the pressure-viscosity coefficient at low pressure.  Temperature is held at the liquid's
reference: the oil heats as it is compressed and as it throttles, which lowers its viscosity, so a
Reynolds number at the reference temperature is the lower one (the check errs on the safe side).

Water's viscosity hardly depends on pressure at room temperature (within a factor of about 1.5 up to
1 GPa: Bett & Cappi, Nature 207 (1965) 620), taken as constant; but water freezes: above the melting
pressure of ice VI (IAPWS R14-08, 0.89 GPa at 20 degC) it is no longer a liquid, which bounds the
pressure a water dashpot may reach.  A mineral oil solidifies too (its glass transition near 1 GPa at
room temperature), which its viscosity, and so the Reynolds check, reaches first.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from ..fluid.column import ColumnLiquid

# Roelands' constants (Hamrock et al., eq. 4.11-4.13): the pressure scale [Pa], the viscosity offset
# (log10 of mu in mPa s), and the constants of Z from alpha
ROELANDS_PRESSURE = 196.1e6
ROELANDS_OFFSET = 1.2
ROELANDS_ALPHA = 5.1e-9
ROELANDS_LOG = 9.67
# the ice VI melting curve (IAPWS R14-08, eq. 3): its triple point with ice III and the liquid, and
# its coefficients
ICE_VI_TRIPLE = (273.31, 632.4e6)
ICE_VI_COEFFICIENTS = (1.07476, 4.6)


@dataclass(frozen=True)
class DesignLiquid:
    """A dashpot liquid: ``name``; density [kg/m^3], bulk modulus at no pressure [Pa], Tait's
    exponent (the modulus grows as K + n p), viscosity at the reference temperature [Pa s], Roelands'
    pressure-viscosity coefficient alpha [1/Pa] (0: viscosity taken as constant), whether it freezes
    as ice VI (water), the reference temperature [K], vapour pressure [Pa gauge], heat capacity
    [J/(kg K)], and where the figures come from."""
    name: str
    density: float
    bulk_modulus: float
    tait_exponent: float
    viscosity: float
    pressure_viscosity: float
    freezes_as_ice: bool
    temperature: float
    vapour_pressure: float
    heat_capacity: float
    source: str

    def column(self) -> ColumnLiquid:
        """The liquid as the compressible column takes it (``fluid.column.ColumnLiquid``)."""
        return ColumnLiquid(self.density, self.bulk_modulus, self.tait_exponent, self.vapour_pressure,
                            self.heat_capacity)

    def sound_speed(self) -> float:
        return math.sqrt(self.bulk_modulus / self.density)

    def viscosity_at(self, p: float) -> float:
        """The dynamic viscosity [Pa s] at gauge pressure ``p`` [Pa] (Roelands; constant if alpha is 0)."""
        if self.pressure_viscosity <= 0.0 or p <= 0.0:
            return self.viscosity
        z = self.pressure_viscosity / (ROELANDS_ALPHA * (math.log(self.viscosity) + ROELANDS_LOG))
        log_mu = ((math.log10(self.viscosity * 1e3) + ROELANDS_OFFSET) * (1.0 + p / ROELANDS_PRESSURE) ** z
                  - ROELANDS_OFFSET)
        return 10.0 ** log_mu * 1e-3

    def solid_pressure(self) -> float:
        """The gauge pressure [Pa] above which the liquid freezes at its temperature (ice VI for water,
        IAPWS R14-08 eq. 3); inf for a liquid whose viscosity bounds it first."""
        if not self.freezes_as_ice:
            return math.inf
        (t_star, p_star), (a, b) = ICE_VI_TRIPLE, ICE_VI_COEFFICIENTS
        return p_star * (1.0 - a * (1.0 - (self.temperature / t_star) ** b)) - 1.0e5


MINERAL_OIL = DesignLiquid(
    "mineral oil (ISO VG 32)", 870.0, 1.5e9, 1.0, 0.028, 2.0e-8, False, 313.15, -1.0e5, 1900.0,
    "ISO 3448 (VG 32: 32 mm^2/s at 40 degC, so 0.028 Pa s at 870 kg/m^3); density, modulus, heat capacity: "
    "Totten, Handbook of Hydraulic Fluid Technology, 2nd ed., ch. 3; alpha 2e-8 1/Pa, a paraffinic mineral "
    "oil's: Hamrock, Schmid & Jacobson, Fundamentals of Fluid Film Lubrication, table 4.3")
WATER = DesignLiquid(
    "water", 998.0, 2.2e9, 7.15, 1.0e-3, 0.0, True, 293.15, -1.0e5, 4180.0,
    "IAPWS-95 at 20 degC (998 kg/m^3, 2.2 GPa, 1.0 mPa s, 4.18 kJ/(kg K)); Tait's n = 7.15 (Cole, "
    "Underwater Explosions, 1948); viscosity against pressure: Bett & Cappi (1965); ice VI: IAPWS R14-08")
LIQUIDS = {"oil": MINERAL_OIL, "water": WATER}

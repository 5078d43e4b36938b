"""The liquids a fluid dashpot may be filled with, as a designer must know them: density, compressibility
and how it stiffens with pressure, viscosity and how it rises with pressure and falls with temperature,
how far compression heats it, the pressure at which it parts, and the pressure at which it stops being
a liquid.

Stiffness under pressure: Tait's law p = K / n ((rho / rho0)^n - 1), whose tangent modulus K + n p
rises with the slope n = dK_T/dp.  Mineral oils: Hayward (Compressibility equations for liquids: a
comparative study, Brit. J. Appl. Phys. 18 (1967) 965) fits their secant modulus as K0 + m p with
m = 5.6 (check: recalled); the tangent modulus of that fit rises at 2 m - 1 = 10.2 at low pressure,
within the 10-11 measured for hydraulic mineral oils (Gholizadeh, Burton & Schoenau, Fluid bulk
modulus: a literature survey, Int. J. Fluid Power 12 (2011) 5; check: recalled).  Water: n = 7.15
(Cole, Underwater Explosions, 1948).

Heating by compression (what the viscosity and the ice check are read at): the isentropic
dT/dp = T alpha / (rho c_p), taken with the liquid's thermal expansivity alpha, density and heat
capacity at its reference state, so T(p) = T0 exp(alpha p / (rho c_p)) (``compressed_temperature``).
An estimate: alpha falls with pressure in a mineral oil, so it overstates the oil's heating (about
13 K per 100 MPa at the start against the 6-9 K measured in oils of food processing, Rasanayagam et
al., J. Food Sci. 68 (2003) 254; check: recalled), and rises with pressure in cold water, so it
understates water's (1.5 K per 100 MPa against about 3 measured there).  The throttling jet heats far
more (Delta p / (rho c_p)) but leaves the bore; the column's shock heating is the column's own account.

Viscosity under pressure and temperature (what sets the orifice's Reynolds number at a dashpot's
hundreds of MPa): Roelands' law (Hamrock, Schmid & Jacobson, Fundamentals of Fluid Film Lubrication,
2nd ed., 2004, eq. 4.11-4.13), which follows measured mineral oils to about 1 GPa, where Barus'
exp(alpha p) overstates them by orders of magnitude:

    log10 mu + 1.2 = (log10 mu0 + 1.2) (1 + p / 196.1 MPa)^Z ((T - 138) / (T0 - 138))^-S0
    Z = alpha_p / (5.1e-9 (ln mu0 + 9.67))           mu in mPa s (cP) on the left, mu0 in Pa s in Z

with alpha_p the pressure-viscosity coefficient at low pressure and S0 the temperature-viscosity
index, fitted to the oil's viscosities at 40 and 100 degC.

Water's viscosity hardly depends on pressure at room temperature (within a factor of about 1.5 up to
1 GPa: Bett & Cappi, Nature 207 (1965) 620), taken as constant at its reference temperature (its
heating, which would thin it, left out: its Reynolds number is the lower one).  But water freezes:
above the melting pressure of ice VI (IAPWS R14-08 eq. 3, 0.89 GPa at 20 degC, 1.22 GPa at 40 degC)
at the compressed water's temperature it may no longer be a liquid.  Whether it freezes within a
dashpot's milliseconds is not known: under ramp compression water stays liquid far beyond the line
for tens of nanoseconds and freezes on surfaces within microseconds (Dolan & Gupta, Chem. Phys. Lett.
374 (2003) 608; Dolan et al., Nature Physics 3 (2007) 339; check: recalled), and no measurement at a
millisecond just above the line is known to this model.  So a pressure above the line is a possible
phase change.  A mineral oil solidifies too (its glass transition near 1 GPa at room temperature),
which its viscosity, and so the Reynolds check, reaches first.
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
# Roelands' temperature pole [K] (Hamrock et al., eq. 4.13)
ROELANDS_TEMPERATURE = 138.0


@dataclass(frozen=True)
class DesignLiquid:
    """A dashpot liquid: ``name``; density [kg/m^3], bulk modulus at no pressure [Pa], Tait's
    exponent (the modulus grows as K + n p), viscosity at the reference temperature [Pa s], Roelands'
    pressure-viscosity coefficient alpha [1/Pa] (0: viscosity taken as constant), whether it freezes
    as ice VI (water), the reference temperature [K], vapour pressure [Pa gauge], heat capacity
    [J/(kg K)], where the figures come from, the thermal expansivity [1/K] and Roelands' temperature
    index S0 (0: viscosity independent of temperature)."""
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
    expansivity: float = 0.0
    temperature_index: float = 0.0

    def column(self) -> ColumnLiquid:
        """The liquid as the compressible column takes it (``fluid.column.ColumnLiquid``)."""
        return ColumnLiquid(self.density, self.bulk_modulus, self.tait_exponent, self.vapour_pressure,
                            self.heat_capacity)

    def sound_speed(self) -> float:
        return math.sqrt(self.bulk_modulus / self.density)

    def compressed_temperature(self, p: float) -> float:
        """The temperature [K] the liquid reaches compressed isentropically from its reference to gauge
        pressure ``p`` [Pa]: T0 exp(alpha p / (rho c_p)) (the module's docstring: an estimate)."""
        return self.temperature * math.exp(self.expansivity * max(p, 0.0) / (self.density * self.heat_capacity))

    def viscosity_at(self, p: float, temperature: float | None = None) -> float:
        """The dynamic viscosity [Pa s] at gauge pressure ``p`` [Pa] and ``temperature`` [K] (the
        reference if None): Roelands; constant where alpha (pressure) or S0 (temperature) is 0."""
        if self.pressure_viscosity <= 0.0 and self.temperature_index <= 0.0:
            return self.viscosity
        z = self.pressure_viscosity / (ROELANDS_ALPHA * (math.log(self.viscosity) + ROELANDS_LOG))
        T = self.temperature if temperature is None else temperature
        thinning = ((T - ROELANDS_TEMPERATURE) / (self.temperature - ROELANDS_TEMPERATURE)) ** -self.temperature_index
        log_mu = ((math.log10(self.viscosity * 1e3) + ROELANDS_OFFSET) * (1.0 + max(p, 0.0) / ROELANDS_PRESSURE) ** z
                  * thinning - ROELANDS_OFFSET)
        return 10.0 ** log_mu * 1e-3

    def solid_pressure(self, temperature: float | None = None) -> float:
        """The gauge pressure [Pa] above which the liquid may freeze at ``temperature`` [K] (the
        reference if None): ice VI's melting line for water (IAPWS R14-08 eq. 3); inf for a liquid whose
        viscosity bounds it first."""
        if not self.freezes_as_ice:
            return math.inf
        T = self.temperature if temperature is None else temperature
        (t_star, p_star), (a, b) = ICE_VI_TRIPLE, ICE_VI_COEFFICIENTS
        return p_star * (1.0 - a * (1.0 - (T / t_star) ** b)) - 1.0e5

    def freezing_margin(self, p: float) -> float:
        """The gauge pressure ``p`` [Pa] over ice VI's melting pressure at the temperature compression to
        ``p`` brings the liquid to (``compressed_temperature``): above 1 it may freeze; 0 for an oil."""
        return p / self.solid_pressure(self.compressed_temperature(p))

# ISO VG 32's Roelands temperature index: log10 mu + 1.2 from 28 mPa s at 40 degC to 4.5 mPa s at 100 degC
# (5.4 mm^2/s at 830 kg/m^3, a VG 32 of viscosity index 100: ISO 2909's VI table, check) over
# ln((373.15 - 138) / (313.15 - 138))
VG32_TEMPERATURE_INDEX = (-math.log((math.log10(4.5) + 1.2) / (math.log10(28.0) + 1.2))
                          / math.log((373.15 - ROELANDS_TEMPERATURE) / (313.15 - ROELANDS_TEMPERATURE)))
# Tait's slope of a mineral oil: Hayward's secant slope 5.6 as a tangent slope, 2 m - 1 (module docstring)
MINERAL_OIL_TAIT = 2.0 * 5.6 - 1.0

MINERAL_OIL = DesignLiquid(
    "mineral oil (ISO VG 32)", 870.0, 1.5e9, MINERAL_OIL_TAIT, 0.028, 2.0e-8, False, 313.15, -1.0e5, 1900.0,
    "ISO 3448 (VG 32: 32 mm^2/s at 40 degC, so 0.028 Pa s at 870 kg/m^3); density, modulus, heat capacity, "
    "expansivity 7e-4 1/K: Totten, Handbook of Hydraulic Fluid Technology, 2nd ed., ch. 3 (check); Tait's slope "
    "10.2: Hayward (1967), 2 x 5.6 - 1; alpha 2e-8 1/Pa, a paraffinic mineral oil's: Hamrock, Schmid & Jacobson, "
    "Fundamentals of Fluid Film Lubrication, table 4.3; S0 from 4.5 mPa s at 100 degC (VI 100)",
    7.0e-4, VG32_TEMPERATURE_INDEX)
WATER = DesignLiquid(
    "water", 998.0, 2.2e9, 7.15, 1.0e-3, 0.0, True, 293.15, -1.0e5, 4180.0,
    "IAPWS-95 at 20 degC (998 kg/m^3, 2.2 GPa, 1.0 mPa s, 4.18 kJ/(kg K), expansivity 2.07e-4 1/K); Tait's "
    "n = 7.15 (Cole, Underwater Explosions, 1948); viscosity against pressure: Bett & Cappi (1965); ice VI: "
    "IAPWS R14-08", 2.07e-4)
LIQUIDS = {"oil": MINERAL_OIL, "water": WATER}

"""A gas spring as an amplifier's interface: a closed cylinder of nitrogen on the struck body, the striking
body's face its piston, storing the interface's energy in compressed gas instead of a solid's strain.

A solid returns an interface's energy elastically only up to the closing speed v* = sigma / sqrt(rho E)
(``premise.elastic_limit_speeds``); gas has no such limit, but its cylinder's steel must hold the pressure
that stores the energy, so its mass grows with the energy as a pressure vessel's does (at least
3/2 rho p V / S for any vessel holding p V: the pressure-vessel theorem, e.g. Hoffman, Trans. ASME J. Appl.
Mech. 29 (1962) 662; here the sleeve's own thick wall, tapered as the pressure along it asks).

**Sizing** (``size_gas_spring``): the interface's energy W = M* dv^2 / 2 compresses the charge (p0, T0,
column L0 over the bore A) adiabatically by the volume ratio r, W = p0 A L0 (r^(gamma-1) - 1) / (gamma - 1),
to p1 = p0 r^gamma and T1 = T0 r^(gamma-1), the stroke L0 (1 - 1/r).  r is the largest whose T1 stays
``IGNITION_MARGIN`` below the auto-ignition temperature of the seal's mineral-oil film (``OIL_AUTOIGNITION``:
the charge is nitrogen, inert, as accumulators are charged, but a charge with air leaked in must not diesel);
p1 is ``PEAK_SHARE`` of the steel's allowable (a thin sleeve; the face under the gas carries p1 too), which
sets p0 and L0.  The bore is the smaller face's diameter, the cylinder's ends the two bodies' faces (backed
by the bodies); its mass is the sleeve's wall, at each station as thick as the largest pressure it sees
(the gas behind the piston when the piston passes it) asks by ``programmer.housing.wall_ratio``.

**Restitution**, in closed form (``size_gas_spring``'s estimate, ``GasSpring.restitution``): e^2 = 1 - (the energy the cycle loses) / W,
the losses

* the **shock**: the piston closing at dv on the gas at rest drives a shock of Mach number
  Ms = a + sqrt(a^2 + 1), a = (gamma + 1) dv / (4 c0) (the piston relation, Anderson, Modern Compressible
  Flow, 3rd ed., eq. 7.11), reflected off the closed end (eq. 7.23); the charge takes the entropy rise of
  both (the normal-shock relations, ``normal_shock``), and returns on its expansion to V0 all but
  U(V0, s0 + ds) - U0 = p0 V0 / (gamma - 1) (exp((gamma - 1) ds / R) - 1);
* the **heat** the gas within a conduction depth sqrt(alpha t) of the walls gives up over the contact
  time t (the whole compression heat of that layer: an upper estimate);
* the **seal's friction**, a pressure-energised piston seal of width ``SEAL_WIDTH`` at friction coefficient
  ``SEAL_FRICTION``: mu p pi D w over the stroke both ways, 8 mu w / D of W.

The closed form's shock loss leaves out the later reverberations (the piston still moving on the compressed
gas): its loss is a lower bound and its e an upper bound.  **The gas column's run** (``lagrangian_rebound``,
``resolved``) resolves them: a 1D Lagrangian column with artificial viscosity between the piston and the
closed end, its e with the closed form's heat and friction losses; it is the interface's "run", as a pad's
finite-element run is (``pads.measure_restitution``), and its peak pressure at the closed end, above the
isentrope's p1, is what the sleeve must hold.  On the 12 lb chain's first interface it gives e 0.988 at 99 m/s
and 0.905 at 289 m/s against the closed form's shock-only 0.997 and 0.952, the peak 1.16 and 1.34 times p1
(``shockfem verify gas_spring``).  Range: a perfect gas, a 1D column (the sleeve's boundary layers and the
piston's seal leakage left out), the piston and the bodies rigid.
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass

import numpy as np
from scipy.integrate import quad

from ..launcher.gas import GASES
from ..programmer.housing import wall_ratio

GAS = "nitrogen"
CHARGE_TEMPERATURE = 293.15       # [K]
# the seal's lubricant: a mineral hydraulic oil, auto-ignition above 320 C (Shell Tellus S2 M 32, safety
# data sheet, section 9, auto-ignition temperature > 320 C by DIN 51794; check), less a margin of 50 K
OIL_AUTOIGNITION = 320.0 + 273.15   # [K]
IGNITION_MARGIN = 50.0              # [K]
# nitrogen at the charge's temperature: thermal conductivity [W/m K] (0.0259 at 300 K, Incropera, Fundamentals
# of Heat and Mass Transfer, 6th ed., Table A.4)
GAS_CONDUCTIVITY = 0.0259
# the peak pressure over the sleeve's allowable: a wall ratio exp(0.25) = 1.28 by ASME VIII-2's P = S ln Y
PEAK_SHARE = 0.25
# a PTFE-bronze piston seal on steel: friction coefficient and land width [m] (check: typical values)
SEAL_FRICTION, SEAL_WIDTH = 0.1, 0.010
# the longest gas column over the bore a sleeve may have (a longer one is a slender tube: its own check)
MAX_SLENDERNESS = 4.0


def piston_shock_mach(u: float, c0: float, gamma: float) -> float:
    """The Mach number of the shock a piston moving at ``u`` [m/s] drives into gas at rest of sound speed
    ``c0``: u / c0 = 2 (Ms - 1 / Ms) / (gamma + 1) solved, Ms = a + sqrt(a^2 + 1), a = (gamma + 1) u / (4 c0)."""
    a = (gamma + 1) * u / (4 * c0)
    return a + math.sqrt(a * a + 1)


def normal_shock(M: float, gamma: float) -> dict:
    """The normal-shock (Rankine-Hugoniot) jumps at upstream Mach number ``M``: pressure, density and
    temperature ratios, the entropy rise over R and the stagnation-pressure ratio exp(-ds / R) (Anderson,
    eqs. 3.57, 3.53, 3.59; NACA Report 1135, eqs. 93-99)."""
    m2 = M * M
    p = 1 + 2 * gamma / (gamma + 1) * (m2 - 1)
    rho = (gamma + 1) * m2 / ((gamma - 1) * m2 + 2)
    ds = math.log(p) / (gamma - 1) - gamma / (gamma - 1) * math.log(rho)
    return {"pressure": p, "density": rho, "temperature": p / rho, "entropy": ds, "stagnation_pressure": math.exp(-ds)}


def reflected_shock_mach(Ms: float, gamma: float) -> float:
    """The Mach number (in the gas behind it, at rest in the wall's frame after) of an incident shock ``Ms``'s
    reflection off a closed end: M_R / (M_R^2 - 1) = Ms / (Ms^2 - 1) sqrt(1 + 2 (gamma - 1) (Ms^2 - 1)
    (gamma + 1 / Ms^2) / (gamma + 1)^2) (Anderson, eq. 7.23)."""
    if Ms <= 1.0:
        return 1.0
    k = Ms / (Ms * Ms - 1) * math.sqrt(1 + 2 * (gamma - 1) / (gamma + 1) ** 2 * (Ms * Ms - 1) * (gamma + 1 / Ms ** 2))
    # M / (M^2 - 1) = k  ->  k M^2 - M - k = 0
    return (1 + math.sqrt(1 + 4 * k * k)) / (2 * k)


def shock_entropy(u: float, c0: float, gamma: float) -> dict:
    """The entropy rise over R [-] of gas at rest struck by a piston at ``u``: its incident shock and the
    reflection off the closed end (module docstring)."""
    Ms = piston_shock_mach(u, c0, gamma)
    Mr = reflected_shock_mach(Ms, gamma)
    return {"incident_mach": Ms, "reflected_mach": Mr,
            "entropy": normal_shock(Ms, gamma)["entropy"] + normal_shock(Mr, gamma)["entropy"]}


def max_compression() -> float:
    """The largest volume ratio r: T0 r^(gamma - 1) at the ignition limit less its margin."""
    g = GASES[GAS].gamma
    return ((OIL_AUTOIGNITION - IGNITION_MARGIN) / CHARGE_TEMPERATURE) ** (1 / (g - 1))


def stored_energy(p0: float, volume: float, r: float, gamma: float) -> float:
    """The work [J] an adiabatic compression of ``volume`` at ``p0`` by the volume ratio ``r`` stores:
    p0 V0 (r^(gamma-1) - 1) / (gamma - 1)."""
    return p0 * volume * (r ** (gamma - 1) - 1) / (gamma - 1)


@dataclass(frozen=True)
class GasSpring:
    """A gas spring sized for one interface (SI)."""
    bore: float                 # [m]
    column: float               # the gas column L0 at the charge [m]
    charge_pressure: float      # p0 [Pa]
    compression: float          # r = V0 / V1 [-]
    stroke: float               # L0 (1 - 1 / r) [m]
    peak_pressure: float        # p1 [Pa]
    peak_temperature: float     # T1 [K]
    energy: float               # W [J]
    sleeve_mass: float          # [kg]
    sleeve_outer: float         # the sleeve's outer diameter at the closed end [m]
    contact_time: float         # compression and rebound, the isentrope [s]
    incident_mach: float
    reflected_mach: float
    losses: dict                # share of W: shock, heat, friction
    restitution: float
    # the piston's speed change over one shock transit there and back, over dv: well below 1, the piston keeps
    # driving shocks into the compressed gas after the reflected one, the reverberations the closed form leaves out
    shock_range: float

    def as_dict(self) -> dict:
        return asdict(self)


def contact_time(m_star: float, W: float, p0: float, area: float, L0: float, r: float, gamma: float) -> float:
    """Compression and rebound of a rigid M* closing with the energy W on the adiabatic spring [s]:
    2 int_0^x1 dx / sqrt(2 (W - E(x)) / M*), x = x1 (1 - s^2) to take the root at the turning point."""
    x1 = L0 * (1 - 1 / r)

    def energy(x):
        return stored_energy(p0, area * L0, L0 / (L0 - x), gamma)

    def integrand(s):
        x = x1 * (1 - s * s)
        return 2 * x1 * s / math.sqrt(max(2 * (W - energy(x)) / m_star, 1e-300))
    return 2 * quad(integrand, 0.0, 1.0, epsabs=0.0, epsrel=1e-10, limit=200)[0]


def sleeve_mass(p0: float, L0: float, r: float, bore: float, allowable: float, rho_steel: float, gamma: float,
                stations: int = 400) -> tuple[float, float]:
    """The sleeve's wall [kg] and its largest outer diameter [m]: at distance y from the closed end it
    holds the gas's pressure when the piston is there, p0 (L0 / y)^gamma, or p1 within the last column
    L0 / r (``programmer.housing.wall_ratio`` at the allowable)."""
    L1 = L0 / r
    y = np.linspace(0.0, L0, stations + 1)
    mid = 0.5 * (y[1:] + y[:-1])
    p = p0 * (L0 / np.maximum(mid, L1)) ** gamma
    Y = np.array([wall_ratio(float(q), allowable) for q in p])
    R = bore / 2
    return float(rho_steel * math.pi * R * R * np.sum((Y * Y - 1) * np.diff(y))), float(bore * Y.max())


def size_gas_spring(m_star: float, speed: float, bore: float, allowable: float, rho_steel: float) -> GasSpring:
    """The gas spring that takes M* closing at ``speed`` in a sleeve of ``bore`` (module docstring)."""
    gas = GASES[GAS]
    g = gas.gamma
    W = 0.5 * m_star * speed * speed
    r = max_compression()
    p1 = PEAK_SHARE * allowable
    p0 = p1 / r ** g
    area = math.pi * bore * bore / 4
    L0 = W * (g - 1) / (p0 * area * (r ** (g - 1) - 1))
    mass, outer = sleeve_mass(p0, L0, r, bore, allowable, rho_steel, g)
    t = contact_time(m_star, W, p0, area, L0, r, g)
    c0 = gas.sound_speed(p0, CHARGE_TEMPERATURE)
    shock = shock_entropy(speed, c0, g)
    losses = _losses(shock["entropy"], p0, area * L0, W, bore, L0 / r, t, g)
    e = math.sqrt(max(1 - sum(losses.values()), 0.0))
    # the piston's speed change over one transit there and back: the shocked gas's pressure over the face
    transit = L0 / (shock["incident_mach"] * c0) + L0 / (shock["reflected_mach"] * c0)
    p2 = p0 * normal_shock(shock["incident_mach"], g)["pressure"]
    return GasSpring(bore, L0, p0, r, L0 * (1 - 1 / r), p1, CHARGE_TEMPERATURE * r ** (g - 1), W, mass, outer, t,
                     shock["incident_mach"], shock["reflected_mach"], losses, e, p2 * area * transit / (m_star * speed))


def _losses(entropy: float, p0: float, volume: float, W: float, bore: float, L1: float, t: float,
            gamma: float) -> dict:
    """Each loss of a cycle as a share of W (module docstring)."""
    gas = GASES[GAS]
    shock = p0 * volume / (gamma - 1) * (math.exp((gamma - 1) * entropy) - 1) / W
    rho = p0 / (gas.R * CHARGE_TEMPERATURE)
    depth = math.sqrt(GAS_CONDUCTIVITY / (rho * gas.cp) * t)
    heat = 2 * depth / (bore / 2) + 2 * depth / L1
    friction = 8 * SEAL_FRICTION * SEAL_WIDTH / bore
    return {"shock": shock, "heat": heat, "friction": friction}


# the Lagrangian column's artificial viscosity: quadratic and linear coefficients (von Neumann and Richtmyer,
# J. Appl. Phys. 21 (1950) 232, with Landshoff's linear term), and the Courant number
VISCOSITY_QUADRATIC, VISCOSITY_LINEAR, COURANT = 1.0, 0.1, 0.4


def lagrangian_rebound(m_star: float, speed: float, spring: GasSpring, cells: int = 200) -> dict:
    """The rebound of a rigid M* closing at ``speed`` on the spring's gas column, the gas resolved: a 1D
    Lagrangian column of ``cells`` cells (staggered leapfrog, the internal energy by the mid-step pressure,
    the shocks by artificial viscosity) between the piston (node 0, M* plus half its cell) and the closed end.
    Every reverberation is in it, which the closed form's shock loss leaves out.  Returns e (the piston's
    speed back at its start over ``speed``), the peak pressure at the closed end and the energy balance's
    error over W.  Valid while the column is resolved (its cells' transit well inside the contact)."""
    g = GASES[GAS]
    gamma, A, L0 = g.gamma, math.pi * spring.bore ** 2 / 4, spring.column
    rho0 = spring.charge_pressure / (g.R * CHARGE_TEMPERATURE)
    x = np.linspace(0.0, L0, cells + 1)
    u = np.zeros(cells + 1)
    u[0] = speed
    m = np.full(cells, rho0 * A * L0 / cells)
    e = np.full(cells, spring.charge_pressure / ((gamma - 1) * rho0))
    node = np.concatenate(([m_star + m[0] / 2], (m[:-1] + m[1:]) / 2))
    V = A * np.diff(x)
    p = (gamma - 1) * m / V * e
    energy0 = 0.5 * m_star * speed ** 2 + np.sum(m * e)
    peak, t = p[-1], 0.0
    q = np.zeros(cells)
    while True:
        rho = m / V
        c = np.sqrt(gamma * p / rho)
        dt = COURANT * np.min(np.diff(x) / (c + np.abs(np.diff(u))))
        force = np.zeros(cells + 1)
        P = p + q
        force[0] = -A * P[0]
        force[1:-1] = -A * (P[1:] - P[:-1])
        u[:-1] += force[:-1] / node * dt
        x += u * dt
        t += dt
        V_new = A * np.diff(x)
        du = np.diff(u)
        rho_new = m / V_new
        q = np.where(du < 0, rho_new * (VISCOSITY_QUADRATIC * du * du + VISCOSITY_LINEAR * c * np.abs(du)), 0.0)
        dV = V_new - V
        # e1 = e0 - ((p0 + p1) / 2 + q) dV / m, p1 = (gamma - 1) rho1 e1: solved for e1
        e = (e - (0.5 * p + q) * dV / m) / (1 + 0.5 * (gamma - 1) * rho_new * dV / m)
        V, p = V_new, (gamma - 1) * rho_new * e
        peak = max(peak, p[-1])
        if x[0] <= 0.0 and u[0] < 0.0:
            break
    kinetic = 0.5 * m_star * u[0] ** 2 + 0.5 * np.sum(node[1:] * u[1:-1] ** 2)
    W = 0.5 * m_star * speed ** 2
    return {"restitution": -u[0] / speed, "peak_pressure": float(peak), "contact_time": t,
            "energy_error": float((kinetic + np.sum(m * e) - energy0) / W)}


# the gas column's cells in a design's run: e within 1.3e-3 of 400 cells' at 99 to 289 m/s on the 12 lb chain's
# first interface (8e-5 at 99 m/s; ``shockfem verify gas_spring``)
RUN_CELLS = 100


def resolved(m_star: float, speed: float, spring: GasSpring, cells: int = RUN_CELLS) -> dict:
    """The spring's restitution with its gas resolved (``lagrangian_rebound``: the shocks and every
    reverberation) and the closed form's heat and friction losses: e^2 = e_column^2 - heat - friction; and the
    column's peak pressure at the closed end, which the sleeve (sized at the isentrope's p1) must hold."""
    r = lagrangian_rebound(m_star, speed, spring, cells)
    e2 = r["restitution"] ** 2 - spring.losses["heat"] - spring.losses["friction"]
    return {**r, "column_restitution": r["restitution"], "restitution": math.sqrt(max(e2, 0.0)), "cells": cells}

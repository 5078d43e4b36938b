"""The launcher: the lightest gas gun (``launcher.design.lightest_launcher``, ASME walls) that fires the
amplifier's first mass (or the whole stack, or the premise's striker fired directly) at its speed, within
the spec's limits, starting from the white paper's gun; with what it stores and what it costs in gas.

Every gun of the machine and of the premise starts from ``machine_gun``: the white paper's gun with its
valve opened to the full bore (``FULL_BORE``).  The white paper's own 8 in valve on its 12 in bore (2/3 of
the bore's diameter, which the design keeps as the bore changes) throttles the gas into the bore: on the
representative 12 lb striker of ``verify premise_boundary`` at 36 in x 20 ft x 5,000 psi it gives
402.6 m/s, the full-bore valve 484.2 m/s (``launcher.gun.fire``, 498.8 kg, the same 2 ms opening).  A
full-bore fast valve or a double diaphragm is ordinary gas-gun practice, and the tank behind it is a
chamber wider than the bore (chambrage): the white paper's valve would leave the direct gun, the faster
one, the more of its reach.  Both arrangements get the same valve, so the comparison stays like for like."""
from __future__ import annotations

import dataclasses
import functools
import math
from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp

from ..launcher.design import Limits, Sizing, lightest_launcher
from ..launcher.gas import GASES, orifice_flow
from ..launcher.gun import Gun, fire, white_paper_gun
from ..launcher.output import sizing
from .spec import MachineSpec

SIZING = Sizing()
# the valve's diameter over the bore's (the white paper's is 8 in on 12 in)
FULL_BORE = 1.0


def machine_gun(launched: float, gas: str) -> Gun:
    """The template of the machine's guns: the white paper's gun (its tank, pressure, 2 ms opening) with the
    valve as wide as the bore (module docstring)."""
    g = white_paper_gun(launched, gas)
    return dataclasses.replace(g, valve_area=math.pi * (FULL_BORE * g.bore) ** 2 / 4)


@dataclass
class Launcher:
    design: object                # ``launcher.design.LauncherDesign``
    sizing: dict                  # ASME walls, weights and hoop stresses (``launcher.output.sizing``)
    projectile_mass: float        # [kg]
    gas_mass: float               # in the reservoir at its pressure and temperature [kg]
    stored_energy: float          # the reservoir gas's internal energy p V / (gamma - 1) [J]
    launch_energy: float          # the projectile's kinetic energy at the muzzle [J]

    def as_dict(self) -> dict:
        return {"design": self.design.summary(), "sizing": self.sizing, "projectile_mass": self.projectile_mass,
                "gas_mass": self.gas_mass, "stored_energy": self.stored_energy, "launch_energy": self.launch_energy}


def design_launcher(spec: MachineSpec, masses: list[float], starts: int = 3) -> Launcher:
    launched = masses[0] if spec.architecture == "launched-chain" else sum(masses)
    return launcher_for(spec, launched, spec.launch_speed, starts)


def launcher_for(spec: MachineSpec, launched: float, speed: float, starts: int = 3, min_bore: float = 0.0,
                 report_binding: bool = True) -> Launcher:
    """The lightest gun within the spec's limits firing ``launched`` [kg] at ``speed``, its bore at least
    ``min_bore`` (a projectile that must fit)."""
    limits = Limits(max_length=spec.max_barrel_length, max_bore=spec.max_bore, max_pressure=spec.max_pressure,
                    **({"min_bore": min_bore} if min_bore else {}))
    d = lightest_launcher(machine_gun(launched, spec.gas), speed, limits, SIZING, starts=starts,
                          report_binding=report_binding)
    return launcher_of(d, launched)


def launcher_of(d, launched: float) -> Launcher:
    """A gun design (``launcher.design.LauncherDesign``) with its walls, gas and energies."""
    g = d.gun
    gas = GASES[g.gas]
    return Launcher(d, sizing(g, SIZING), launched,
                    gas.mass_for(g.reservoir_pressure, g.reservoir_temperature, g.reservoir_volume),
                    g.reservoir_pressure * g.reservoir_volume / (gas.gamma - 1),
                    0.5 * launched * d.muzzle_velocity ** 2)


@dataclass(frozen=True)
class MuzzleState:
    """The gas when the gun's projectile ends its travel, from the gun's own shot (``launcher.gun.fire``)."""
    base_pressure: float          # on the projectile's base [Pa] (the lumped gun's, Lagrange's gradient applied)
    reservoir_pressure: float     # the tank's, its valve still open (no valve: the barrel's) [Pa]
    push: float                   # the base pressure on the bore's area [N]


@functools.lru_cache(maxsize=64)
def muzzle_state(gun: Gun) -> MuzzleState:
    """The gas at the end of ``gun``'s travel: the pressure that still pushes whatever fills the bore there.
    The barrel is full of gas at that pressure and the valve is open, so a body stopped at the muzzle is
    pushed on (``stops``' pushed body); the push falls only as the barrel vents (past the muzzle, through a
    stripped sabot's ring) and rises toward the tank's pressure where the stopped body closes the bore
    (``ported_push`` follows both).  Range: the lumped gun's (``launcher.gun``): Lagrange's linear profile,
    at the end of a direct gun's travel a barrel gas about as heavy as its projectile (at the 12 lb
    premise's (b), about 0.9 t behind 0.79 t), the edge of that profile's use; the quasi-1D column
    (``launcher.column_gun``, ``verify premise_boundary``) puts the lumped gun's speed 1.6 to 3.3% high there."""
    shot = fire(gun, samples=2)
    p = float(shot.history["p_base"][-1])
    # with no valve the reservoir is the barrel's own gas
    tank = shot.history["p_barrel" if gun.valve_area is None else "p_reservoir"][-1]
    return MuzzleState(p, float(tank), p * gun.area)


# the barrel's last slug length ported (``ported_push``): slots over this share of the wall (the ligaments, the
# other half, carry the wall's hoop load at twice its stress there), sharp-edged, at the classical sharp-edged
# orifice's discharge coefficient (0.61, the vena contracta of a thin-plate hole)
PORT_OPEN_FRACTION = 0.5
PORT_DISCHARGE = 0.61


@dataclass(frozen=True)
class PortedPush:
    """The gas behind a projectile past the end of its gun's travel (``ported_push``), from that end."""
    ported: bool                  # the last ``length`` of the barrel ported (else shut: the unvented barrel)
    length: float                 # the ported (or unported) length past the travel [m]
    port_area: float              # the ports' effective area once all are uncovered, Cd A [m^2]
    time: np.ndarray              # [s] from the end of the travel
    travel: np.ndarray            # the base's travel past the end of the gun's travel [m]
    speed: np.ndarray             # the projectile's [m/s]
    base_pressure: np.ndarray     # on the projectile's base while it moves, the face's once held [Pa]
    reservoir_pressure: np.ndarray
    at_muzzle: float              # the time the base reaches the muzzle (then held there) [s]
    muzzle_speed: float           # the projectile's speed there [m/s]
    held_pressure: float          # the largest barrel pressure while the body is held at the muzzle [Pa]
    end_reservoir_pressure: float # the tank's at the end of the hold [Pa]

    def time_at(self, travel: float) -> float:
        """The time [s] the base has moved ``travel`` [m] past the end of the gun's travel."""
        moving = self.time <= self.at_muzzle
        return float(np.interp(travel, self.travel[moving], self.time[moving]))

    def impulse(self, area: float, t0: float, t1: float) -> float:
        """The push's impulse [N s] on ``area`` [m^2] from ``t0`` to ``t1`` [s] (the trapezoidal rule)."""
        t = np.linspace(t0, t1, 400)
        return float(np.trapz(np.interp(t, self.time, self.base_pressure) * area, t))


@functools.lru_cache(maxsize=32)
def ported_push(gun: Gun, length: float, hole: float, hold: float, ported: bool = True,
                samples: int = 400) -> PortedPush:
    """The gas behind ``gun``'s projectile over the last ``length`` [m] of the barrel past its travel (a slug
    that fills that length at the end of its travel), then with the body held at the muzzle for ``hold``
    [s] (a sabot stripped there, ``hole`` [m^2] the bore its striker leaves open through it).  ``ported``:
    that length of the wall slotted (``PORT_OPEN_FRACTION``, ``PORT_DISCHARGE``), each slot open to the
    atmosphere once the base has passed it; else shut (the unvented barrel).  From the gun's own state at the
    end of its travel (``launcher.gun.fire``'s history): the tank (a fixed volume) feeds the barrel through
    the fully open valve at the breech's pressure on Lagrange's profile, as in the gun; the barrel (its volume
    growing as A v) vents through the uncovered slots into the atmosphere (``launcher.gas.orifice_flow``, the
    one orifice law, choked or not), the vented gas leaving at the barrel's temperature; the projectile
    moves on under the base pressure alone (Lagrange's, p_mean M / (M + C / 3)), the air ahead left out
    (its front is out of the muzzle).  Held, the body at rest closes the bore but for ``hole``, which vents
    with the slots; its face carries the barrel's pressure.  Range: the barrel lumped (one pressure and
    temperature, Lagrange's gradient while the base moves: the slots' outflow near the base and the waves
    it sends back to the breech are not resolved, so the base's pressure follows the slots' opening at
    once), the gas ideal and adiabatic, the ports' ligaments not sized (their share of the wall
    ``PORT_OPEN_FRACTION``)."""
    if gun.valve_area is None or gun.gas_inertia != "lagrange":
        raise ValueError("ported_push follows a valved gun on Lagrange's profile (the machine's guns, "
                         "machine_gun): set Gun.valve_area and gas_inertia='lagrange'")
    gas = gun.gas_model()
    A, M = gun.area, gun.projectile_mass
    shot = fire(gun, samples=2)
    h = shot.history
    y0 = [float(h[k][-1]) for k in ("m_reservoir", "U_reservoir", "m_barrel", "U_barrel")] + [0.0, float(h["v"][-1])]
    Vr = gun.reservoir_volume
    V0 = (gun.dead_volume if gun.dead_volume is not None else A * gun.bore) + A * gun.length
    slots = PORT_DISCHARGE * PORT_OPEN_FRACTION * math.pi * gun.bore * length if ported else 0.0
    a_valve = gun.discharge_coefficient * gun.valve_area
    p_atm = gun.ambient_pressure

    def state(y, held):
        m_r, U_r, m_b, U_b, s, v = y
        V = V0 + A * min(s, length)
        p_r, p_b = gas.pressure(m_r, U_r, Vr), gas.pressure(m_b, U_b, V)
        T_r, T_b = gas.temperature(m_r, U_r), gas.temperature(m_b, U_b)
        acc = 0.0 if held else p_b * A / (M + m_b / 3)
        p_base = p_b - m_b * acc / (3 * A)
        p_breech = p_b + m_b * acc / (6 * A)
        m_in = orifice_flow(gas, a_valve, p_r, T_r, p_breech) - orifice_flow(gas, a_valve, p_breech, T_b, p_r)
        h_in = gas.cp * (T_r if m_in >= 0 else T_b)
        vent = slots * min(max(s, 0.0) / length, 1.0) + (PORT_DISCHARGE * hole if held else 0.0)
        m_out = orifice_flow(gas, vent, p_b, T_b, p_atm)
        return p_r, p_b, p_base, acc, m_in, h_in, m_out, T_b

    def rhs(held):
        def f(t, y):
            p_r, p_b, p_base, acc, m_in, h_in, m_out, T_b = state(y, held)
            v = 0.0 if held else y[5]
            dU_b = h_in * m_in - gas.cp * T_b * m_out - p_b * A * v - m_in * v * v / 6
            return [-m_in, -h_in * m_in, m_in - m_out, dU_b, v, acc]
        return f

    def muzzle(t, y):
        return y[4] - length
    muzzle.terminal, muzzle.direction = True, 1
    scale = np.array([y0[0] + y0[2], y0[1] + y0[3], y0[0] + y0[2], y0[1] + y0[3], length, y0[5]]) * 1e-12
    run = solve_ivp(rhs(False), (0.0, 10 * length / y0[5]), y0, method="LSODA", rtol=1e-9, atol=scale,
                    events=muzzle, dense_output=True)
    t_m = float(run.t[-1])
    rest = solve_ivp(rhs(True), (t_m, t_m + hold), run.y[:, -1], method="LSODA", rtol=1e-9, atol=scale,
                     dense_output=True)
    out = {k: [] for k in ("t", "s", "v", "p", "p_r")}
    for sol, t0, t1, held in ((run, 0.0, t_m, False), (rest, t_m, t_m + hold, True)):
        for t in np.linspace(t0, t1, samples):
            y = sol.sol(t)
            p_r, p_b, p_base, *_ = state(y, held)
            out["t"].append(t), out["s"].append(min(y[4], length)), out["v"].append(0.0 if held else y[5])
            out["p"].append(p_b if held else p_base), out["p_r"].append(p_r)
    arr = {k: np.array(v) for k, v in out.items()}
    held_p = arr["p"][arr["t"] >= t_m]
    return PortedPush(ported, length, slots, arr["t"], arr["s"], arr["v"], arr["p"], arr["p_r"], t_m,
                      float(run.y[5, -1]), float(held_p.max()), float(arr["p_r"][-1]))

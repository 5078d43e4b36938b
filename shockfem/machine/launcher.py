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

from ..launcher.design import Limits, Sizing, lightest_launcher
from ..launcher.gas import GASES
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
    stripped sabot's ring) and rises toward the tank's pressure where the stopped body closes the bore."""
    shot = fire(gun, samples=2)
    p = float(shot.history["p_base"][-1])
    # with no valve the reservoir is the barrel's own gas
    tank = shot.history["p_barrel" if gun.valve_area is None else "p_reservoir"][-1]
    return MuzzleState(p, float(tank), p * gun.area)

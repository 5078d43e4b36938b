"""The lumped gun's shot fired on the quasi-1D Euler column (``fluid.gas_column``): the independent check of
the lumped gun's gas model (``gun.fire``'s Lagrange column) behind a full-bore valve.

The barrel gas is the column from the breech to the projectile's base, its dead volume at the ambient state to
start; the tank feeds the breech through the full bore, steadily and isentropically (``gas_column``'s reservoir
breech: the first face's state on the tank's steady isentrope, joined to the first cell by the shock or
rarefaction it sends, choked at the sonic state).  The tank is the lumped gun's: well mixed, adiabatic, so it empties isentropically,

    p_r = p_r0 (m_r / m_r0)^gamma,   rho_r = m_r / V_r,

its mass falling by the column's inflow (the column's mass gain over each step, times the bore's area).  The
projectile moves under the column's face pressure less the air ahead (``gun.air_ahead_pressure``) and the
friction, m dv/dt = A (p_face - p_face_air) - F_f, its speed over each step the midpoint's from the last step's
acceleration (as ``verify.gas_column_cases.gun`` drives the simple-wave gun).

Range of validity: ``gas_column``'s (a perfect gas, no covolume, a constant bore, no friction or heat transfer to
the wall) with a valve as wide as the bore that opens at once and loses nothing (``Gun.discharge_coefficient``
1, ``opening_time`` 0, ``valve_area`` the bore's: the column has no throat narrower than the bore, no opening
time); the tank well mixed at rest.  The grid: the first order end cells and the MUSCL-Hancock interior
converge at first order at the inflow's and the dead volume's shocks; ``fire_column`` at two grids bounds it.
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass

from ..fluid.gas_column import COURANT, GasColumn
from .gun import Gun, air_ahead_pressure
from .simple_wave import sonic_speed


@dataclass(frozen=True)
class ColumnShot:
    muzzle_velocity: float    # [m/s]
    time_in_barrel: float     # [s]
    cells: int
    steps: int
    wall_time_s: float
    tank_pressure: float      # at the muzzle [Pa]
    barrel_gas: float         # the column's mass at the muzzle [kg]


def full_bore(gun: Gun) -> bool:
    """Whether ``gun``'s valve is one the column represents (module docstring: the bore's area, Cd 1, at once)."""
    return (gun.valve_area is not None and math.isclose(gun.valve_area, gun.area, rel_tol=1e-12)
            and gun.discharge_coefficient == 1.0 and gun.opening_time == 0.0 and not gun.real_gas)


def fire_column(gun: Gun, cells: int = 200, max_time: float = 10.0) -> ColumnShot:
    """The shot of ``gun`` (``full_bore``) on a column of ``cells`` finite volumes, from the valve's opening to
    the muzzle."""
    if not full_bore(gun):
        raise ValueError("the column's breech is a full-bore opening at once with no loss: valve_area the bore's, "
                         "discharge_coefficient 1, opening_time 0, an ideal gas")
    t0 = time.perf_counter()
    gas = gun.gas_model()
    A, m = gun.area, gun.projectile_mass
    dead = gun.dead_volume if gun.dead_volume is not None else A * gun.bore
    X0 = dead / A
    Vr, pr0 = gun.reservoir_volume, gun.reservoir_pressure
    m_r0 = gas.mass_for(pr0, gun.reservoir_temperature, Vr)
    col = GasColumn(gas.gamma, gas.R, X0, cells, gun.ambient_pressure, gun.ambient_temperature,
                    reservoir=(pr0, gun.reservoir_temperature))
    m_r, v, a, t, steps = m_r0, 0.0, 0.0, 0.0, 0
    muzzle = X0 + gun.length

    def acceleration(p_face: float, u: float) -> float:
        drive = A * (p_face - air_ahead_pressure(gun, u))
        friction = gun.bore_friction + gun.seal_drag * p_face * A
        # friction acts only while moving, or once the drive overcomes it
        return 0.0 if u <= 0 and drive <= friction else (drive - friction) / m

    while col.face < muzzle * (1 - 1e-12) and t < max_time:
        # the column's step sees only its cells; the tank's inflow enters the first at up to u + c = 2 c* (the
        # largest on c^2 + (gamma - 1) u^2 / 2 = c0^2 at u <= c), which outruns still gas in the dead volume: the
        # first step's shock into it moves slower (Lax's condition), so a step on 2 c* keeps it within the cell
        c_r = math.sqrt(gas.gamma * col.p0 / col.rho0)
        dt = min(col.stable_step(v), COURANT * col.face / cells / (2 * sonic_speed(c_r, gas.gamma) + 2 * v))
        if v + 0.5 * dt * a > 0:
            dt = min(dt, (muzzle - col.face) / (v + 0.5 * dt * a))
        before = col.mass()
        p = col.step(max(v + 0.5 * dt * a, 0.0), dt)
        m_r -= A * (col.mass() - before)
        share = m_r / m_r0
        col.p0, col.rho0 = pr0 * share ** gas.gamma, m_r / Vr
        a = acceleration(p, v)
        v = max(v + dt * a, 0.0)
        t, steps = t + dt, steps + 1
    return ColumnShot(v, t, cells, steps, time.perf_counter() - t0, col.p0, A * col.mass())

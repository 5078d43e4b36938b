"""The premise's boundary (``machine.boundary``): its two closed forms against the models they stand for,
and the break-even restitution rebuilt from those models.

* The chain's energy efficiency G^2 m_n / m_1 = [g (1 + e - g)]^(n-1) against the event-driven rigid
  chain (``amplifier.rigid.launched_chain``) of the geometric masses ``amplifier.gain.design`` gives:
  the same collisions, so round-off.
* The simple-wave gun's efficiency u^2 / (2 I(u)) and its travel against the lumped gun integrating the
  same base-pressure law (``launcher.gun.fire``, ``gas_inertia="simple-wave"``, no valve, evacuated):
  the integrator's rtol 1e-9, so 1e-6.
* Q = 1 at the break-even restitution, Q rebuilt from the rigid chain and the lumped gun at the
  optimum's speeds: both tolerances above.
"""
from __future__ import annotations

import math
import time

from ..amplifier.gain import chain_efficiency, design
from ..amplifier.rigid import launched_chain
from ..launcher.gas import GASES
from ..launcher.gun import Gun, fire
from ..launcher.simple_wave import efficiency, travel
from .checks import check

# (e, n, gain): a 12 lb chain's (e 0.576, 4.341: 99.06 to 430 m/s), the white paper's (0.9, 1600 ft/s over 325), an
# elastic one and a single collision
CHAINS = ((0.576, 5, 4.341), (0.9, 5, 4.923), (1.0, 3, 2.0), (0.671, 2, 1.2))
# (gas, muzzle speed [m/s]): the amplifier's launch and a 12 lb striker's speed (430 m/s)
GUNS = (("air", 99.06), ("air", 430.0), ("helium", 430.0))
CHAIN_TOL = 1e-12     # the same collisions in another order of operations
GUN_TOL = 1e-6        # the lumped gun's integrator at rtol 1e-9
MASS, PRESSURE, BORE = 300.0, 34.47e6, 0.5     # any: the efficiency does not depend on them


def _rigid_efficiency(e: float, n: int, G: float) -> float:
    d = design("launched-chain", 1.0, G, 1.0, e, n)
    r = launched_chain(d.masses, 1.0, e)
    return d.masses[-1] * r.final[-1] ** 2 / d.masses[0]


def _lumped_efficiency(gas: str, u: float) -> tuple[float, float]:
    """(muzzle speed, KE / (p0 A L)) of the lumped simple-wave gun with the closed form's travel for ``u``."""
    g = GASES[gas]
    c0 = g.sound_speed(PRESSURE, 293.15)
    area = math.pi * BORE ** 2 / 4
    L = travel(u, MASS, PRESSURE, area, c0, g.gamma)
    shot = fire(Gun(1.0, PRESSURE, BORE, L, MASS, gas=gas, air_ahead="evacuated", gas_inertia="simple-wave"),
                samples=2)
    return shot.muzzle_velocity, 0.5 * MASS * shot.muzzle_velocity ** 2 / (PRESSURE * area * L)


def premise_boundary(size: str, workdir: str) -> list[dict]:
    """The premise's break-even: the chain's and the gun's closed forms against the rigid chain and the lumped gun."""
    from ..machine.boundary import best_chain, break_even, gun_efficiency
    out = []
    for e, n, G in CHAINS:
        t0 = time.perf_counter()
        out.append(check(f"premise_boundary.chain_efficiency e={e:g} n={n} G={G:g} [-]", _rigid_efficiency(e, n, G),
                         chain_efficiency(e, G, n), CHAIN_TOL, time.perf_counter() - t0, 0))
    for gas, u in GUNS:
        t0 = time.perf_counter()
        v, eta = _lumped_efficiency(gas, u)
        g = GASES[gas]
        wall = time.perf_counter() - t0
        out.append(check(f"premise_boundary.simple_wave_travel {gas} {u:g} m/s: muzzle speed [m/s]", u, v, GUN_TOL,
                         wall, 0))
        out.append(check(f"premise_boundary.simple_wave_efficiency {gas} {u:g} m/s [-]", eta,
                         efficiency(u, g.sound_speed(PRESSURE, 293.15), g.gamma), GUN_TOL, 0.0, 0))
    for gas in ("air", "helium"):
        t0 = time.perf_counter()
        e = break_even(430.0, gas)
        c = best_chain(e, 430.0, gas)
        chi = _rigid_efficiency(e, c.masses, c.gain)
        q = _lumped_efficiency(gas, 430.0)[1] / (chi * _lumped_efficiency(gas, c.launch_speed)[1])
        out.append(check(f"premise_boundary.break_even {gas} 430 m/s: Q from the rigid chain and the lumped gun [-]",
                         1.0, q, 3 * GUN_TOL, time.perf_counter() - t0, 0))
        out[-1]["note"] = (f"break-even e {e:.4f} ({c.masses} masses launched at {c.launch_speed:.1f} m/s, gain "
                           f"{c.gain:.4f}, the chain keeping {c.chain_efficiency:.3f}; the gun's efficiency "
                           f"{gun_efficiency(430.0, gas):.4f} at 430 m/s, {gun_efficiency(c.launch_speed, gas):.4f} "
                           "at the launch)")
    return out

"""The premise's boundary in closed form: when does a velocity amplifier need less gun than firing the
striker directly?

Both machines give the same striker (mass M, speed V_s) its kinetic energy K = M V_s^2 / 2.

* The direct gun fires the striker: its size at the reservoir pressure p0 is p0 A L = K / eta(V_s),
  eta an ideal gun's efficiency at its muzzle speed (``launcher.simple_wave.efficiency``): the
  constant-area (unchambered, simple-wave) gun by default, or with ``chambered`` the infinitely chambered
  gun, the upper bound on any gun of that gas; both guns of one comparison by the same law, at the same
  pressure.
* The amplifier's gun fires its first mass at V = V_s / G and the chain of n geometric masses keeps
  chi = G^2 m_n / m_1 of that energy (``amplifier.gain.chain_efficiency``): its gun is
  p0 A L = K / (chi(e, G, n) eta(V)).

So the amplifier's gun over the direct gun's is

    Q = eta(V_s) / (chi(e, G, n) eta(V_s / G)),

independent of the striker's mass, the bore and the pressure, against a direct gun that fires the bare
striker.  A direct gun whose bore is wider than the striker fires it in a sabot, launching (M + m_sabot)
V_s^2 / 2 where the amplifier's chain, each mass filling the bore, needs none: with ``direct_load`` =
(M + m_sabot) / M, Q = eta(V_s) / (chi eta(V_s / G) direct_load).  p0 A L is what a gun costs: its
barrel's steel at a thin wall's allowable S is 2 rho p0 A L / S, the gas it draws from a tank much larger
than its barrel is p0 A L, and the spec's limits (bore, barrel, pressure) cap it.  The chain keeps at most
e per stage, the gun loses efficiency with speed: amplification pays (Q < 1) only above a restitution
``break_even``, which falls as the striker's speed nears the gas's escape speed 2 c0 / (gamma - 1).
``best_chain`` minimises Q over the launch speed and the number of masses (2 to ``MAX_MASSES``).

Range: rigid bodies, each struck once (the first pass, which the event-driven rigid chain reproduces for
geometric masses); one restitution at every interface; the launched chain (a stack on an anvil is
another law); the gun's gas a perfect gas at the ambient temperature, its barrel long enough for the
speed; the moving masses, stops and frame are not counted (they only add to the amplifier).
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass

import numpy as np
from scipy.optimize import brentq, minimize_scalar

from ..amplifier.gain import chain_efficiency
from ..launcher.gas import GASES
from ..launcher.simple_wave import efficiency
from .pads import estimated_restitution, solid_pads

# the most masses the optimum may use (the design's alternatives go to 7; more than 10 gains little)
MAX_MASSES = 10
# the chamber's temperature [K] (the lumped gun's default reservoir temperature), and the pressure its
# sound speed is read at [Pa] (a perfect gas's does not depend on it)
TEMPERATURE = 293.15
REFERENCE_PRESSURE = 1e5
# the launch speed's search: this many gains on a log grid per mass count, then a bounded refinement
GRID = 200


@dataclass(frozen=True)
class Chain:
    """The amplifier that needs the least gun for a striker at ``striker_speed``."""
    restitution: float
    striker_speed: float          # [m/s]
    masses: int
    gain: float                   # [-]
    launch_speed: float           # [m/s]
    chain_efficiency: float       # KE of the striker / KE of the first mass [-]
    gun_ratio: float              # Q: the amplifier's p0 A L over the direct gun's [-]

    def as_dict(self) -> dict:
        return asdict(self)


def sound_speed(gas: str) -> float:
    """The chamber gas's sound speed c0 [m/s] every closed form of the premise takes: ``gas`` at
    ``TEMPERATURE`` (a perfect gas, so at any pressure; the lumped gun's real gas is not these closed
    forms')."""
    return GASES[gas].sound_speed(REFERENCE_PRESSURE, TEMPERATURE)


def gun_efficiency(speed: float, gas: str, chambered: bool = False) -> float:
    """The ideal gun's kinetic energy over p0 A L at its muzzle ``speed`` [m/s], in ``gas`` (the simple-wave
    gun, or the infinitely chambered one)."""
    return efficiency(speed, sound_speed(gas), GASES[gas].gamma, chambered)


def gun_ratio(e: float, striker_speed: float, gain: float, masses: int, gas: str = "air",
              direct_gas: str | None = None, chambered: bool = False, direct_load: float = 1.0) -> float:
    """Q (module docstring): the amplifier's gun over the direct gun's, the direct gun launching
    ``direct_load`` times the striker's mass (its sabot); inf where no chain of ``masses`` gains ``gain``
    at ``e``."""
    chi = chain_efficiency(e, gain, masses)
    if chi <= 0:
        return math.inf
    direct = gun_efficiency(striker_speed, direct_gas or gas, chambered)
    return direct / (chi * gun_efficiency(striker_speed / gain, gas, chambered) * direct_load)


def best_chain(e: float, striker_speed: float, gas: str = "air", direct_gas: str | None = None,
               max_masses: int = MAX_MASSES, chambered: bool = False, direct_load: float = 1.0) -> Chain:
    """The launch speed and mass count that minimise Q (a grid in log gain, refined by a bounded search
    between the grid's neighbours of its best)."""
    best = None
    for n in range(2, max_masses + 1):
        top = math.log((1 + e) ** (n - 1)) * (1 - 1e-9)

        def q(x, n=n):
            return gun_ratio(e, striker_speed, math.exp(x), n, gas, direct_gas, chambered, direct_load)
        xs = np.linspace(top / GRID, top, GRID)
        values = [q(x) for x in xs]
        i = int(np.argmin(values))
        lo, hi = xs[max(i - 1, 0)], xs[min(i + 1, GRID - 1)]
        r = minimize_scalar(q, bounds=(lo, hi), method="bounded", options={"xatol": 1e-12})
        value, x = min((float(r.fun), float(r.x)), (values[i], float(xs[i])))
        if best is None or value < best[0]:
            best = (value, x, n)
    value, x, n = best
    G = math.exp(x)
    return Chain(e, striker_speed, n, G, striker_speed / G, chain_efficiency(e, G, n), value)


def break_even(striker_speed: float, gas: str = "air", direct_gas: str | None = None,
               max_masses: int = MAX_MASSES, masses: int | None = None, launch_speed: float | None = None,
               chambered: bool = False, direct_load: float = 1.0) -> float:
    """The restitution above which the amplifier needs less gun than the direct gun (Q = 1); nan when even
    e = 1 does not pay.  ``masses`` and ``launch_speed`` given: that chain's, not the optimum's;
    ``direct_load``: the direct gun's launched mass over the striker's (``gun_ratio``)."""
    if launch_speed is not None:
        def excess(e):
            return gun_ratio(e, striker_speed, striker_speed / launch_speed, masses, gas, direct_gas, chambered,
                             direct_load) - 1
    else:
        def excess(e):
            return best_chain(e, striker_speed, gas, direct_gas, max_masses, chambered, direct_load).gun_ratio - 1
    if excess(1.0) >= 0:
        return math.nan
    lo = 1e-3
    if excess(lo) <= 0:
        return lo
    return float(brentq(excess, lo, 1.0, xtol=1e-7))


def break_even_speed(e: float, gas: str = "air", max_masses: int = MAX_MASSES, chambered: bool = False) -> float:
    """The striker speed [m/s] above which an amplifier of restitution ``e`` needs less gun than the
    direct gun (both in ``gas``, both simple-wave or both ``chambered``); nan when none below 0.99 of the
    (simple-wave) escape speed does."""
    top = 0.99 * 2 * sound_speed(gas) / (GASES[gas].gamma - 1)

    def excess(v):
        return best_chain(e, v, gas, None, max_masses, chambered).gun_ratio - 1
    if excess(top) >= 0:
        return math.nan
    lo = 1.0
    if excess(lo) <= 0:
        return lo
    return float(brentq(excess, lo, top, xtol=1e-3))


def best_pad_restitution() -> tuple[str, float]:
    """The highest restitution any pad material of the library is sized with (``pads.estimated_restitution``:
    an elastomer's sqrt(R) on rigid masses, R its ASTM D2632 rebound; the chain's finite-element runs give
    lower; the gas spring, whose restitution depends on its interface, is ``machine.gas_spring``'s): (material,
    e)."""
    return max(((m, estimated_restitution(m)) for m in solid_pads()), key=lambda me: me[1])

"""Closed-form rigid-body gains of a velocity amplifier, and the design tool built on them.

A collision of mass m_a at v_a with m_b at v_b and restitution e leaves

    v_a' = (m_a v_a + m_b v_b - m_b e (v_a - v_b)) / (m_a + m_b)
    v_b' = (m_a v_a + m_b v_b + m_a e (v_a - v_b)) / (m_a + m_b)

Two architectures, n masses m_1 > ... > m_n with R = m_n / m_1 and geometric ratios
m_{k+1} / m_k = R^(1/(n-1)) (which maximise the gain for a given R):

* ``launched-chain``: a gun fires m_1 at V into the others at rest.  Each collision multiplies
  the speed by (1 + e) / (1 + R^(1/(n-1))), so the last mass leaves at G V with
  G = [(1 + e) / (1 + R^(1/(n-1)))]^(n-1).
* ``stack-on-anvil``: the whole stack falls at V onto a rigid anvil (restitution e too); m_1
  rebounds at e V and meets m_2 still falling, and so on (the dual-mass / "superball"
  arrangement).  In the frame of the falling stack each collision is the launched-chain one, so
  the last mass leaves at ((1 + e) G - 1) V = [(1 + e)^n / (1 + R^(1/(n-1)))^(n-1) - 1] V, which
  is the white paper's Eq. 2 (the paper applies it to the launched chain its text describes,
  for which it is not the gain).

Both assume each mass is struck once, by its heavier neighbour, before anything else happens
(the first pass); ``rigid.py`` follows every later collision too.
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass

ARCHITECTURES = ("launched-chain", "stack-on-anvil")


def collide(m_a: float, v_a: float, m_b: float, v_b: float, e: float) -> tuple[float, float]:
    """Velocities after a collision with restitution e (m_b = inf: a rigid anvil)."""
    if math.isinf(m_b):
        return v_b - e * (v_a - v_b), v_b
    p = m_a * v_a + m_b * v_b
    return (p - m_b * e * (v_a - v_b)) / (m_a + m_b), (p + m_a * e * (v_a - v_b)) / (m_a + m_b)


def stage_factor(e: float, ratio: float) -> float:
    """Speed multiplier of one launched-chain stage, m_{k+1} / m_k = ratio."""
    return (1 + e) / (1 + ratio)


def chain_gain(e: float, R: float, n: int) -> float:
    """G = v_n / V of a launched chain with geometric masses, R = m_n / m_1."""
    return stage_factor(e, R ** (1 / (n - 1))) ** (n - 1)


def chain_efficiency(e: float, G: float, n: int) -> float:
    """KE_n / KE_1 of the launched chain of n geometric masses that gains G at restitution e: G^2 m_n / m_1.

    Each stage of gain g = G^(1/(n-1)) needs the mass ratio r = (1 + e) / g - 1 and keeps g^2 r =
    g (1 + e - g) of the energy, so the chain keeps [g (1 + e - g)]^(n-1).  A stage keeps at most e (as
    g -> 1), so many masses lose everything unless e = 1, where the chain keeps 1 - O(1/n).  Zero when
    no chain of n masses gains G (g >= 1 + e)."""
    g = G ** (1 / (n - 1))
    return (g * (1 + e - g)) ** (n - 1) if g < 1 + e else 0.0


def stack_gain(e: float, R: float, n: int) -> float:
    """v_n / V of a stack falling at V onto a rigid anvil: (1 + e) G - 1 (the paper's Eq. 2)."""
    return (1 + e) * chain_gain(e, R, n) - 1


def gain(architecture: str, e: float, R: float, n: int) -> float:
    return chain_gain(e, R, n) if architecture == "launched-chain" else stack_gain(e, R, n)


@dataclass
class Design:
    architecture: str
    n: int
    restitution: float
    launch_speed: float          # first mass (launched chain) or stack (stack on anvil) [m/s]
    target_speed: float          # of the test article [m/s]
    masses: list[float]          # [kg], m_1 first, the test article last
    stage_ratio: float           # m_{k+1} / m_k
    gain: float                  # target / launch
    efficiency: float            # test article's kinetic energy / kinetic energy at launch
    intermediate_mass: float     # masses 2 .. n-1 [kg]
    feasible: bool
    reason: str = ""
    sizes: list[dict] | None = None

    def as_dict(self) -> dict:
        return asdict(self)


def design(architecture: str, article_mass: float, target_speed: float, launch_speed: float, e: float,
           n: int) -> Design:
    """Geometric masses that bring the test article (m_n) to ``target_speed`` from ``launch_speed``.

    The stage factor g = (gain needed per pass)^(1/(n-1)) fixes the mass ratio
    m_{k+1} / m_k = (1 + e) / g - 1, possible only while g < 1 + e (a stage cannot multiply a
    speed by more than 1 + e)."""
    if architecture not in ARCHITECTURES:
        raise ValueError(f"architecture must be one of {', '.join(ARCHITECTURES)}, got {architecture!r}")
    needed = target_speed / launch_speed
    per_pass = needed if architecture == "launched-chain" else (needed + 1) / (1 + e)
    g = per_pass ** (1 / (n - 1))
    if g >= 1 + e:
        limit = (1 + e) ** (n - 1) if architecture == "launched-chain" else (1 + e) ** n - 1
        return Design(architecture, n, e, launch_speed, target_speed, [], math.nan, needed, math.nan, math.nan,
                      False, f"a gain of {needed:.4g} needs more than {n} masses at e = {e:g}: "
                             f"{n} masses give less than {limit:.4g} however light the last one")
    ratio = (1 + e) / g - 1                  # m_{k+1} / m_k
    masses = [article_mass / ratio ** (n - 1 - k) for k in range(n)]
    e_launch = (0.5 * masses[0] * launch_speed ** 2 if architecture == "launched-chain"
                else 0.5 * sum(masses) * launch_speed ** 2)
    efficiency = 0.5 * article_mass * target_speed ** 2 / e_launch
    return Design(architecture, n, e, launch_speed, target_speed, masses, ratio, needed, efficiency,
                  sum(masses[1:-1]), True)


def cylinder_size(mass: float, density: float, aspect: float) -> dict:
    """Diameter and length of a cylinder of ``mass`` with length / diameter = ``aspect``."""
    volume = mass / density
    d = (4 * volume / (math.pi * aspect)) ** (1 / 3)
    return {"diameter": d, "length": aspect * d}

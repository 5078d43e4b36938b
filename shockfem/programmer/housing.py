"""The fluid dashpot's mass as a designer must count it: piston, metering pin, the housing that holds the
peak pressure, and the liquid.

The bore wall is sized by the code whose design stress it uses, ASME's Boiler and Pressure Vessel Code,
Section VIII Division 2 (design by rule, a cylindrical shell under internal pressure, Part 4.3.3; check
the edition):

    t = (D / 2) (exp(P / (S E)) - 1),  i.e.  P = S E ln Y,  Y = b / a          (``WALL_RULE``)

D the bore's diameter, S the design stress (the lesser of yield / 1.5 and tensile / 2.4, Part 3 annex
3-A), E the joint efficiency (1: a seamless forging).  S ln Y is Tresca's collapse pressure of a
closed thick cylinder of yield stress S (Hill, The Mathematical Theory of Plasticity, 1950, ch. V), so
the rule keeps the fully plastic wall 1.5 on yield from collapse at any thickness; it grows without
bound, but only as ln Y.  Its limits as recalled, not confirmed here (check): VIII-2 Part 4 sets no
upper wall ratio for this formula; above about 70 MPa (10 ksi) VIII-3 is the code meant for the
vessel, and maraging 300 is not a VIII-2-listed material (its 1.5 / 2.4 margins are borrowed).

``PRACTICAL_RATIO`` (Y_max = 4) is the largest wall ratio a design may ask of a monobloc forging: there
the wall holds S ln 4 = 1.39 S; doubling it to Y = 8 adds only half again (ln 8 / ln 4 = 1.5) for 4.2
times the steel ((64 - 1) / (16 - 1)), and a forging that thick no longer hardens through.  Beyond it
the housing is "no housing within Y_max" (its mass is still reported).

A named alternative (``WALL_RULES["shakedown"]``), not the default: an autofrettaged or shrink-fit
compound monobloc meant to stay elastic shot after shot once its proof shot has yielded the bore.
Its limit is the closed cylinder's shakedown pressure by von Mises (Melan's theorem; Hill 1950, ch. V;
Davidson & Kendall, The design of pressure vessels for very high pressure operation, Watervliet
Arsenal WVT-6917, 1969: twice the elastic range, the Bauschinger effect neglected, which lowers it:
check), with S in place of the yield stress:

    P = (2 / sqrt 3) S min(1 - 1 / Y^2, ln Y)

(the collapse pressure below Y = 2.22, where the two meet).  It saturates at 2 S / sqrt 3 = 880 MPa
for maraging 300, below VIII-2's S ln 4: cyclic elasticity costs pressure.

The elastic check, reported with every wall and governing nothing: Lame's von Mises at the bore
(Timoshenko & Goodier, Theory of Elasticity, sec. 33; Roark's Formulas for Stress and Strain, 7th ed.,
table 13.5 case 1c; closed ends)

    von Mises = sqrt(3) P Y^2 / (Y^2 - 1)

above the yield stress, the proof shot yields the bore (``first_yield``); whether the bore then stays
elastic on the next shots is the shakedown check at the yield stress (``shakes_down``).

Shot after shot: neither S nor shakedown is a fatigue or fracture limit.  The wall reports the depth
of the bore crack that is critical on one shot (``critical_flaw``: a long surface crack,
K = 1.12 (sigma_theta + P) sqrt(pi a), the pressure on its faces; K_IC of maraging 300 taken as
80 MPa sqrt(m), recalled from ASM's range 70-90: check), so the design basis is one proof shot with an
inspection for flaws below that depth; a shot count needs a VIII-3 KD-3 / KD-4 fatigue and
crack-growth assessment at the ports, the floor corner and the pin's anchorage, which this module
does not make.

The floor (the struck end's closure), a flat head forged with the wall: VIII-2 Part 4.6 (as VIII-1
UG-34), t = d sqrt(C P / (S E)), C = 0.17 for a head forged integral with the shell (check the table):
near the clamped plate's elastic edge stress 3 P a^2 / (4 t^2) = S (Roark table 11.2 case 10b,
C = 0.1875).  A floor thicker than a quarter of the bore's diameter is a thick plate, outside the
formula's bending theory (reported as ``floor_over_diameter`` and ``floor_thick``): a uniformly loaded
clamped circular plate has the same bending moments in Mindlin's shear-deformable theory as in
Kirchhoff's (Wang, Reddy & Lee, Shear Deformable Beams and Plates, 2000: check), so what a thick floor
adds is the face pressure through its thickness and the stress at the floor's corner with the wall,
which neither formula holds and a finite-element check must.  Its own period, its first mode
clamped (Blevins, Formulas for Natural Frequency and Mode Shape, table 11-1 case 2,
lambda^2 = 10.22):  T = 2 pi a^2 / (10.22 t) sqrt(12 rho (1 - nu^2) / E).

The pin: the piston's hole is the pin's largest opening a_max; at a stroke s the pin fills
a_max - a(s) of it: its volume is the integral of that over the stroke.  A pin of uniform section
standing in the liquid at p and crossing the orifice to the jet's side carries sigma_r = sigma_theta =
-p, sigma_z = 0 there: its von Mises stress is the liquid's pressure, held to the pin steel's S
(``pin_holds``; the pin of the housing's steel).

The dynamic factor, one basis for every wall: the pressure the wall is sized for is the liquid's
peak times ``dynamic_factor`` of the pressure's own history on the wall's breathing mode (a ring's,
period 2 pi b / c, c = sqrt(E / rho): ``liquids-and-machines.md``) and on the floor's first mode, an
undamped oscillator x'' + w^2 x = w^2 p(t); the factor is its largest response over the largest
pressure (Biggs, Introduction to Structural Dynamics, 1964, ch. 2: 2 for a step, 1 + |sin(pi t_r /
T)| / (pi t_r / T) for a ramp of rise t_r), exact for the sampled (piecewise-linear) history and
continuous in the period.  A design reads it from the column's histories; the closed form
(``column_design.contact_pressure_limit``) from the front's own, a shock: a step, 2.

Each slice of the wall is a ring driven by its own history (``wall_factor``): the wall is sized for the
worst slice whose history the column holds, the piston's face and the floor, not for the envelope of
the two, which no slice sees.  On the column the contact front reaches a slice at z from the floor,
then its reflection from the floor, 2 z / c later; where that delay is a whole number of the ring's
periods the two steps add in phase, and the slice responds as the floor's does, where they arrive
together as one step.  Over a column many ring periods long some slice is in phase whatever the
period, so the floor's history stands for it; the envelope's factor instead swings between
1 + |p_1 - p_2| / (p_1 + p_2) and 2 (p_1 the front, p_2 what its reflection adds) with the phase of one
delay, every few percent of the period, and would let a design choose its wall's phase.  The range: a column at least
one ring period of delay long (a shorter one is nearer the floor's single step still); slices between
the ends are not run, only argued.

The period depends on the size it sizes (the wall's on its outer radius, the floor's on its thickness):
each is the least size that holds its own response at its own period (``least_self_consistent``).

The pressurised bore runs the column and the piston's thickness; the article's guide beyond it, which
holds no pressure, is not counted.
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass

import numpy as np
from numba import njit
from scipy.optimize import brentq

from ..scene.library import initial_yield_stress, property_si

YIELD_MARGIN, TENSILE_MARGIN = 1.5, 2.4          # ASME BPVC VIII-2, Part 3 annex 3-A
JOINT_EFFICIENCY = 1.0                           # VIII-2's E for a seamless forging: no weld
PRACTICAL_RATIO = 4.0                            # Y_max, the largest b / a of a monobloc forging (above)
FLAT_HEAD_FACTOR = 0.17                          # VIII-2 4.6's C, a flat head forged integral (check)
THICK_PLATE = 0.25                               # a floor over its bore's diameter beyond which it is thick
CRACK_SHAPE = 1.12                               # a long surface crack's geometry factor (Tada, Paris & Irwin)


@dataclass(frozen=True)
class HousingSteel:
    """A housing steel: density [kg/m^3], Young's modulus [Pa], 0.2% yield and tensile strength [Pa],
    its plane-strain fracture toughness [Pa sqrt(m)] (nan where not known), and the figures' source."""
    name: str
    density: float
    youngs_modulus: float
    yield_stress: float
    tensile_strength: float
    source: str
    fracture_toughness: float = math.nan

    def allowed_stress(self) -> float:
        """ASME VIII-2's design stress: the lesser of yield / 1.5 and tensile / 2.4."""
        return min(self.yield_stress / YIELD_MARGIN, self.tensile_strength / TENSILE_MARGIN)

    def bar_speed(self) -> float:
        return math.sqrt(self.youngs_modulus / self.density)


def _library_steel(name: str, tensile: float) -> HousingSteel:
    return HousingSteel(name, property_si(name, "density", "density"), property_si(name, "youngs_modulus", "pressure"),
                        initial_yield_stress(name), tensile, f"the material library's {name}")


class _SteelTable(dict):
    """The housing steels by name.  A steel of the material library is read at its first use, not at
    import: the library's figures carry units, and reading them imports pint, which a scene of bare SI
    numbers never needs (``units._pint``)."""

    def __init__(self, steels: dict, library: dict):
        super().__init__(steels)
        self.library = library          # name: tensile strength [Pa] (the library keeps no tensile figure)

    def __missing__(self, name: str) -> HousingSteel:
        if name not in self.library:
            raise KeyError(name)
        steel = self[name] = _library_steel(name, self.library[name])
        return steel

    def __contains__(self, name) -> bool:
        return dict.__contains__(self, name) or name in self.library


HOUSING_STEELS = _SteelTable({
    "maraging_300": HousingSteel(
        "maraging_300", 8000.0, 190e9, 1790e6, 1830e6,
        "18Ni(300) maraging steel, aged: ASM Handbook vol. 1 (1990), Maraging Steels, typical properties "
        "(0.2% yield 1790-2070 MPa, tensile 1830-2100 MPa: the lower ends taken), density 8.0 g/cm^3, E 190 GPa; "
        "K_IC 80 MPa sqrt(m) (ASM's 70-90, check)", 80e6),
}, library={"high_strength_steel": 760e6})
HOUSING_STEEL = "maraging_300"


# where the shakedown rule's two limits meet: 1 - 1 / Y^2 = ln Y
_SHAKEDOWN_CORNER = brentq(lambda y: 1.0 - 1.0 / y ** 2 - math.log(y), 1.5, 3.0)


def _viii2_pressure(ratio: float, allowed: float) -> float:
    return allowed * JOINT_EFFICIENCY * math.log(ratio)


def _viii2_ratio(pressure: float, allowed: float) -> float:
    return math.exp(pressure / (allowed * JOINT_EFFICIENCY))


def _shakedown_pressure(ratio: float, allowed: float) -> float:
    return 2.0 / math.sqrt(3.0) * allowed * min(1.0 - 1.0 / ratio ** 2, math.log(ratio))


def _shakedown_ratio(pressure: float, allowed: float) -> float:
    x = math.sqrt(3.0) * pressure / (2.0 * allowed)
    if x <= math.log(_SHAKEDOWN_CORNER):
        return math.exp(x)
    return 1.0 / math.sqrt(1.0 - x) if x < 1.0 else math.inf


# each rule: (the pressure a wall of ratio Y holds at the design stress S, the ratio that holds P, its name)
WALL_RULES = {"asme_viii2": (_viii2_pressure, _viii2_ratio, "ASME VIII-2 4.3.3, P = S E ln Y"),
              "shakedown": (_shakedown_pressure, _shakedown_ratio,
                            "shakedown of an autofrettaged monobloc, P = (2 / sqrt 3) S min(1 - 1 / Y^2, ln Y)")}
WALL_RULE = "asme_viii2"


def held_pressure(ratio: float, allowed: float, rule: str = WALL_RULE) -> float:
    """The pressure [Pa] a wall of outer-over-bore ``ratio`` holds at the design stress ``allowed`` [Pa]
    by ``rule`` (``WALL_RULES``)."""
    return WALL_RULES[rule][0](ratio, allowed)


def wall_ratio(pressure: float, allowed: float, rule: str = WALL_RULE) -> float:
    """The outer-over-bore ratio a wall needs to hold ``pressure`` [Pa] at ``allowed`` [Pa] by ``rule``;
    inf where the rule saturates below the pressure."""
    return WALL_RULES[rule][1](pressure, allowed)


def bore_von_mises(pressure: float, bore: float, outer: float) -> float:
    """Lame's von Mises stress at the bore of a closed thick cylinder [Pa]."""
    return math.sqrt(3.0) * pressure * outer ** 2 / (outer ** 2 - bore ** 2)


def critical_flaw(pressure: float, ratio: float, steel: HousingSteel) -> float:
    """The depth [m] of a long bore crack that ``pressure`` [Pa] makes critical on one shot in a wall of
    ``ratio``: K_IC = 1.12 (sigma_theta + p) sqrt(pi a), sigma_theta Lame's hoop stress at the bore."""
    hoop = pressure * (ratio ** 2 + 1.0) / (ratio ** 2 - 1.0) if math.isfinite(ratio) else pressure
    return (steel.fracture_toughness / (CRACK_SHAPE * (hoop + pressure))) ** 2 / math.pi


@dataclass(frozen=True)
class Wall:
    """A bore wall sized for a pressure by a rule: its radii [m], ratio, mass per metre of bore [kg/m],
    the criterion that governs it, and its elastic and one-shot checks at that pressure."""
    rule: str
    pressure: float            # the design pressure [Pa]
    bore: float                # [m]
    outer_radius: float        # [m]
    ratio: float               # outer / bore
    mass_per_length: float     # [kg/m]
    within_practical: bool     # ratio <= PRACTICAL_RATIO
    governing: str             # the rule's criterion, or "no housing within Y_max"
    bore_von_mises: float      # Lame at the bore [Pa] (the elastic check, governs nothing)
    first_yield: bool          # the bore yields on the proof shot
    shakes_down: bool          # and stays elastic after it (shakedown at the yield stress)
    critical_flaw: float       # [m]

    def as_dict(self) -> dict:
        return asdict(self)


def wall_for(pressure: float, bore: float, steel: HousingSteel | str = HOUSING_STEEL, rule: str = WALL_RULE) -> Wall:
    """The bore wall of ``steel`` (a ``HousingSteel`` or its name) that holds ``pressure`` [Pa] in a bore
    of radius ``bore`` [m] by ``rule`` (``WALL_RULES``; VIII-2's unless named)."""
    s = HOUSING_STEELS[steel] if isinstance(steel, str) else steel
    ratio = wall_ratio(pressure, s.allowed_stress(), rule)
    outer = bore * ratio
    within = ratio <= PRACTICAL_RATIO
    finite = math.isfinite(ratio)
    walled = finite and ratio > 1.0                  # a wall at all (no pressure needs none)
    vm = bore_von_mises(pressure, bore, outer) if walled else (0.0 if finite else math.inf)
    shakes_down = pressure <= _shakedown_pressure(ratio, s.yield_stress) if walled else finite
    return Wall(rule, pressure, bore, outer, ratio, s.density * math.pi * (outer ** 2 - bore ** 2) if finite else math.inf,
                within, _governing(rule, ratio) if within else f"no housing within Y_max = {PRACTICAL_RATIO:g}",
                vm, vm > s.yield_stress, shakes_down, critical_flaw(pressure, ratio, s))


def _governing(rule: str, ratio: float) -> str:
    if rule == "shakedown":
        return WALL_RULES[rule][2] + (": collapse, Y below 2.22" if ratio < _SHAKEDOWN_CORNER else ": shakedown")
    return WALL_RULES[rule][2]


def floor_for(pressure: float, bore: float, steel: HousingSteel | str = HOUSING_STEEL) -> float:
    """The flat floor's thickness [m] that holds ``pressure`` [Pa] over a bore of radius ``bore`` [m]:
    VIII-2 4.6's integral flat head, t = d sqrt(C P / (S E))."""
    s = HOUSING_STEELS[steel] if isinstance(steel, str) else steel
    return 2.0 * bore * math.sqrt(FLAT_HEAD_FACTOR * pressure / (s.allowed_stress() * JOINT_EFFICIENCY))


def dynamic_factor(t: np.ndarray, p: np.ndarray, period: float) -> float:
    """The largest |x| of an undamped oscillator x'' + w^2 x = w^2 p(t) of ``period`` [s], at rest before
    the history, driven by the pressure ``p`` at strictly increasing times ``t`` (linear between
    samples), over the largest pressure (``largest_response``); 1 where the pressure never rises."""
    p = np.asarray(p, dtype=float)
    peak = float(np.max(p))
    return largest_response(t, p, period) / peak if peak > 0.0 else 1.0


def largest_response(t: np.ndarray, p: np.ndarray, period: float) -> float:
    """The largest |x| [p's unit] of ``dynamic_factor``'s oscillator over the history (``_largest_response``)."""
    t, p = np.ascontiguousarray(t, dtype=float), np.ascontiguousarray(p, dtype=float)
    if np.any(np.diff(t) <= 0.0):
        raise ValueError("dynamic_factor: the history's times must increase strictly")
    return _largest_response(t, p, 2.0 * math.pi / period)


@njit(cache=True)
def _largest_response(t, p, w):
    """Exact for the piecewise-linear load, and continuous in the period.  On the interval from t_k, of
    slope m_k, the load's own line is a particular solution, so x = p_k + m_k tau + Re(z_k e^(-i w tau)),
    z = (x - p) + i (x' - m) / w the free oscillation about the line: at rest at t_0, z_0 = -p_0 - i m_0 / w;
    across an interval z turns by e^(-i w h); at a sample x and x' are continuous and the slope changes,
    so z gains i (m_(k-1) - m_k) / w.  With z = A e^(i phi), x = p_k + m tau + A cos(w tau - phi), and the
    interval's largest |x| is at its ends or where x' = 0: theta = w tau - phi = asin(s) + 2 pi n (x's
    maxima) or pi - asin(s) + 2 pi n (its minima), s = m / (A w), |s| < 1 (else x is monotone there).
    Along one branch x moves by 2 pi m / w from one root to the next, so its extreme is at the branch's
    first or last root inside the interval: two roots a branch, whatever w h."""
    two_pi = 2.0 * math.pi
    slope = (p[1] - p[0]) / (t[1] - t[0])
    zr, zi = -p[0], -slope / w
    largest, turned, c, s = 0.0, -1.0, 1.0, 0.0
    for k in range(len(t) - 1):
        h = t[k + 1] - t[k]
        m = (p[k + 1] - p[k]) / h
        zi += (slope - m) / w
        slope = m
        amplitude = math.hypot(zr, zi)
        # the interval's roots only where its bound |p_k| + |m| h + A could pass the largest so far
        if (abs(p[k]) + abs(m) * h + amplitude > largest and amplitude > 0.0
                and abs(m) < amplitude * w):
            phase, base = math.atan2(zi, zr), math.asin(m / (amplitude * w))
            for branch in (base, math.pi - base):
                first = math.ceil((-phase - branch) / two_pi)
                last = math.floor((w * h - phase - branch) / two_pi)
                if first <= last:
                    for n in (first, last):
                        theta = branch + two_pi * n
                        x = p[k] + m * (theta + phase) / w + amplitude * math.cos(theta)
                        largest = max(largest, abs(x))
        if w * h != turned:                  # a uniform sampling turns by one angle: its cos and sin once
            turned = w * h
            c, s = math.cos(turned), math.sin(turned)
        zr, zi = zr * c + zi * s, zi * c - zr * s
        largest = max(largest, abs(p[k + 1] + zr))
    return largest


def wall_factor(t: np.ndarray, slices: np.ndarray, period: float) -> float:
    """The wall's dynamic factor: the largest response over its ``slices``' pressure histories (rows;
    one history alone as a 1-D array), each slice a ring of ``period`` driven by its own, over the largest
    pressure of any (see the module's docstring: the worst slice, not the envelope of the histories)."""
    slices = np.atleast_2d(np.asarray(slices, dtype=float))
    peak = float(np.max(slices))
    if peak <= 0.0:
        return 1.0
    return max(largest_response(t, p, period) for p in slices if np.max(np.abs(p)) > 0.0) / peak


# the scan for the least self-consistent size: a step of 3% in the size, so in the period (a front's
# step of rise t_r has the factor 1 + |sin x| / x, x = pi t_r / T, which 3% of T moves by about 0.01 x^2:
# under 1e-3 for a rise within a third of the period); the root to a share 1e-10 of the size
SIZE_STEP, SIZE_TOLERANCE = 1.03, 1e-10


def least_self_consistent(needed, lower: float) -> float:
    """The least size x >= ``lower`` [m] of a part whose period its size sets that holds its own response:
    ``needed(x)``, the size the part needs at the period size x gives, at most x (a wall or floor thinner
    than that does not hold the pressure at its own period; any thicker one whose need it meets does, and
    this is the lightest).  Where ``needed(lower) <= lower`` the lower bound is halved until it does not
    (a wall's bore is its least size).  Scanned up by ``SIZE_STEP`` to the first size that meets its
    need, then the root in that step (brentq); where the need turns infinite first (a rule that saturates
    below the pressure), that size.  Its range: a need that does not dip below the size and back within
    one step (the scan would step over that root)."""
    for _ in range(60):
        if needed(lower) > lower:
            break
        lower *= 0.5
    else:
        return lower
    x0, x1 = lower, lower * SIZE_STEP
    while (need := needed(x1)) > x1:
        if not math.isfinite(need):
            return x1
        x0, x1 = x1, x1 * SIZE_STEP
    return brentq(lambda x: needed(x) - x, x0, x1, xtol=SIZE_TOLERANCE * x0, rtol=1e-14)


# a steel's Poisson ratio, in the floor plate's stiffness (only its square enters)
POISSON = 0.3
# a clamped circular plate's first mode: lambda^2 (Blevins, table 11-1)
PLATE_MODE = 10.22


def floor_period(bore: float, thickness: float, s: HousingSteel) -> float:
    """The first period [s] of a clamped circular floor of radius ``bore`` and ``thickness`` [m]."""
    return 2.0 * math.pi * bore ** 2 / (PLATE_MODE * thickness) * math.sqrt(12.0 * s.density * (1 - POISSON ** 2)
                                                                           / s.youngs_modulus)


def step_factor() -> float:
    """``dynamic_factor`` of a pressure that rises as a step (a shock's front): 2 at any period."""
    return dynamic_factor(np.array([0.0, 1e-12, 10.0]), np.array([0.0, 1.0, 1.0]), 1.0)


def fixture_mass(design: dict, t: np.ndarray, wall_pressure: np.ndarray, floor_pressure: np.ndarray,
                 steel: str = HOUSING_STEEL, rule: str = WALL_RULE) -> dict:
    """The dashpot ``design`` (``dashpot_design``) weighed whole, its housing of ``HOUSING_STEELS[steel]``
    sized by ``rule`` (``wall_for``, ``floor_for``) for the pressure histories on its wall's slices (rows,
    or one history: ``wall_factor``) and on its floor [Pa] at times ``t`` [s], each times its own dynamic
    factor at the period of the least size that holds it (``least_self_consistent``): a dict
    of the parts [kg] and their sum, ``fixture``; ``housing_carried``, the housing or, beyond the practical
    ratio, the heaviest a monobloc gives (what a striker can be asked to carry); the wall (``Wall``'s fields under ``wall_``), the floor,
    the factors, ``housing_holds`` (the wall within ``PRACTICAL_RATIO``), ``holdable_pressure`` (what
    the wall holds at that ratio), and the pin's von Mises stress (``pin_pressure``: the wall's peak or the
    design's quasi-steady upstream pressure, the larger), its ratio to S (``pin_stress_ratio``: above 1 the
    pin does not hold it, ``pin_holds``)."""
    s = HOUSING_STEELS[steel]
    a = design["bore_radius"]
    allowed = s.allowed_stress()
    peak = float(np.max(wall_pressure))
    period = 2.0 * math.pi / s.bar_speed()           # the wall's breathing period per metre of outer radius

    def wall_at(outer):
        return wall_for(peak * wall_factor(t, wall_pressure, period * outer), a, s, rule)
    wall = wall_at(least_self_consistent(lambda R: wall_at(R).outer_radius, a))
    factor, outer = (wall.pressure / peak if peak > 0.0 else 1.0), wall.outer_radius
    floor_peak = float(np.max(floor_pressure))

    def floor_at(thickness):
        return floor_for(floor_peak * dynamic_factor(t, floor_pressure, floor_period(a, thickness, s)), a, s)
    floor, floor_factor = 0.0, 1.0
    if floor_peak > 0.0:
        floor = least_self_consistent(floor_at, 0.5 * floor_for(floor_peak, a, s))
        floor_factor = dynamic_factor(t, floor_pressure, floor_period(a, floor, s))
    length = design["column"] + design.get("piston_thickness", 0.015)
    housing = wall.mass_per_length * length + s.density * math.pi * outer ** 2 * floor
    # the heaviest housing a monobloc gives: the wall at the practical ratio, the same floor
    practical = s.density * math.pi * a ** 2 * ((PRACTICAL_RATIO ** 2 - 1.0) * length + PRACTICAL_RATIO ** 2 * floor)
    pin = np.array(design["pin"], dtype=float)
    pin_volume = float(np.trapz(pin[:, 1].max() - pin[:, 1], pin[:, 0]))
    parts = {"piston": design["piston_mass"], "pin": s.density * pin_volume, "housing": housing,
             "liquid": design["liquid_mass"]}
    pin_pressure = max(peak, design.get("upstream_pressure", 0.0))
    return {**parts, "fixture": sum(parts.values()), "housing_carried": min(housing, practical),
            "outer_radius": outer, "wall_ratio": wall.ratio,
            "housing_holds": wall.within_practical, "governing": wall.governing, "rule": rule,
            **{f"wall_{k}": v for k, v in wall.as_dict().items()
               if k in ("pressure", "bore_von_mises", "first_yield", "shakes_down", "critical_flaw")},
            "floor_thickness": floor, "floor_over_diameter": floor / (2.0 * a),
            "floor_thick": floor / (2.0 * a) > THICK_PLATE, "allowed_stress": allowed,
            "dynamic_factor": factor, "floor_dynamic_factor": floor_factor, "peak_pressure": peak, "steel": steel,
            "steel_source": s.source, "holdable_pressure": held_pressure(PRACTICAL_RATIO, allowed, rule),
            "pin_pressure": pin_pressure, "pin_stress_ratio": pin_pressure / allowed,
            "pin_holds": pin_pressure <= allowed}

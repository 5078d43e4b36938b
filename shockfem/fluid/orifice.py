"""The orifice of a fluid dashpot: the quasi-steady flow through an area a in a piston (or plate) that
the liquid approaches through a passage of area A, into a space at the downstream pressure.

Seen from the orifice, liquid at gauge pressure p and speed u1 = Q / A in the passage leaves as a jet
of area Cc a at the downstream pressure (0 gauge) and speed u_j = Q / (Cc a).  Bernoulli from the
passage to the jet's contracted section (the losses of a thin orifice are in Cc; they happen after it,
where the jet mixes):

    p = rho u_j^2 / 2 (1 - (Cc n)^2),     n = a / A,     mdot = rho Cc a u_j
      = rho Cc a sqrt(2 p / (rho (1 - (Cc n)^2)))

the flow-meter form with the velocity of approach (ISO 5167-1's 1 / sqrt(1 - beta^4) with the jet's
own contraction).  The contraction of a thin sharp-edged orifice against the area ratio is
Idelchik's (Handbook of Hydraulic Resistance, 3rd ed., 1994, the thin-walled sharp-edged orifice,
l / d_h <= 0.015, Re = w0 d_h / nu > 1e5, over f0 / f1 from 0 to 1; cited here as diagram 4-9, check
the number: the Modelica Standard Library's Fluid.Dissipation cites 4-9 for the sudden contraction
and 4-15 for the thick-edged orifice): the total-pressure loss referred to the passage's speed, with
the jet entering a large space (f0 / f2 -> 0),

    zeta = (1 + 0.707 sqrt(1 - n))^2 / n^2       p + rho u1^2 / 2 = zeta rho u1^2 / 2

which is the law above with

    Cc(n) = 1 / (1 + 0.707 sqrt(1 - n))          0.586 at n -> 0, 0.667 at n = 0.5, 1 at n = 1.

At small n, the end of a stroke, this Cc(0) = 0.586 is 4% under Kirchhoff's free-streamline
pi / (pi + 2) = 0.611 (and ISO 5167-2's C = 0.596 at beta -> 0): the law passes 4% less flow there than
the potential-flow jet, and a pin cut on it opens 4% wider than one cut on Kirchhoff's.

Where each part of the range comes from (every run checks them, ``programmer.dashpot_validity``):
- area ratio: Idelchik's formula covers 0 <= n <= 1, but the law is checked against measured
  coefficients only up to ISO 5167-2's beta = 0.75 (``VALID_AREA_RATIO``, n = 0.5625, where it agrees
  with the Reader-Harris/Gallagher equation within 3%: ``shockfem verify orifice_law``).  That bound
  is a flow meter's envelope, not a physical limit; it is the default largest opening a designer
  cuts (``OrificeLaw.largest_ratio``, a parameter of a design), and a design that opens wider runs on
  the law outside its checked data (``extrapolated``: flagged, not vetoed).
- the plate: a thin orifice has a land l / d_h <= ``THIN_LAND`` (Idelchik 4-9; ISO 5167-2's e <= 0.02 D
  is the meter's stricter form).  A thicker one lets the jet reattach in the bore of the orifice and
  passes more flow unless it cavitates (Idelchik's thick-edged orifice, diagrams 4-12 and 4-15: up to
  1.36 times the thin plate's coefficient, ``thick_discharge_ratio``).
- cavitation: a thick orifice whose vena contracta falls to the vapour pressure chokes; its flow is
  Nurick's Cd = Cc sqrt(K), K = (p1 - p_v) / (p1 - p2) (Nurick, Orifice cavitation and its effect on
  spray mixing, J. Fluids Eng. 98 (1976) 681-687; the formula recalled, check), whatever its land,
  the contraction Cc that of the sharp inlet.  Below about K = (Cd_thick / Cc)^2 (1.8 for a long land) it cavitates:
  at a dashpot's hundreds of MPa into the atmosphere K - 1 is below 1e-3, so the flow is choked and
  the thin law's Cc holds within sqrt(K) - 1 (``coefficient_ratio``).  ISO 5167's single-phase
  condition fails in every such design; Nurick's form is what replaces it.
- the bore: ISO 5167-2 holds its coefficient for 50 mm <= D <= 1000 mm (``ISO_DIAMETERS``); Idelchik's
  diagram names no size.  A smaller bore is outside the data the law is checked on (flagged).
- Reynolds number: the law is a turbulent orifice's; ISO 5167-2:2003 (5.3.1, corner tappings) holds
  the Reader-Harris/Gallagher equation down to Re_D = rho u1 D / mu = 5000 for beta <= 0.56 and
  16000 beta^2 above (``least_reynolds``); that bound is the edge of the standard's data set, not a
  laminar transition, and ``shockfem verify orifice_reynolds`` prints how far the coefficient has
  moved there (2.3 to 4.8% over its turbulent limit at three area ratios).  Below it the coefficient's
  viscous shift is Lichtarowicz, Duggins & Markland's (Discharge coefficients for incompressible
  non-cavitating flow through long orifices, J. Mech. Eng. Sci. 7 (1965) 210), fitted to lands
  2 <= l / d <= 10 down to Re ~ 10 and taken as the estimate of the shift for thin plates and longer
  lands too (check: recalled): 1/Cd = 1/Cd_u + 20 (1 + 2.25 l / d) / Re, Re = d sqrt(2 dp / rho) / nu
  on the orifice's own hydraulic diameter and ideal jet speed (``viscous_coefficient_ratio``); for a
  pin's annulus the length scale is the gap's hydraulic diameter 2 (r_hole - r_pin)
  (``annulus_hydraulic_diameter``), not the bore, since the boundary layers that shift the coefficient
  grow on the gap's walls.  What a run may leave to these shifts is a small share of its velocity
  change (``programmer.dashpot_validity``).

The jet's momentum: a control volume moving with the piston from the passage (pressure p, speed u1)
to the jet's contracted section (0 gauge, u_j) gives the force of the liquid on the piston

    F = p A - mdot (u_j - u1)

(the jet's reaction takes from p A what the liquid gains accelerating through the orifice); with
Bernoulli, F = rho A (u_j - u1)^2 / 2, the Borda-Carnot loss.  A law that pushes with p A alone
overstates the force by mdot (u_j - u1).

The laws a model picks (``OrificeLaw``): the study's first law (fixed Cd, no velocity of approach, no
jet reaction) kept for comparison, and the area-ratio law with approach and jet (the default).
Compiled (numba): the kernels call it every stage of an integration.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit

# the coefficient of Idelchik's thin-orifice contraction term, 0.707 = 1 / sqrt(2) (diagram 4-9)
IDELCHIK_CONTRACTION = 0.707
# the largest area ratio of ISO 5167-2's thin orifice plates (beta <= 0.75): where the law is checked against
# measured coefficients, and the default largest opening of a design (a flow meter's bound, not a physical one)
VALID_AREA_RATIO = 0.75 ** 2
# 1 - (Cc n)^2 is kept above this: at n -> 1 the law lets any flow pass at no pressure (Idelchik's Cc
# -> 1), which a stiff integration cannot follow; 1e-3 is reached only above n = 1 - 5e-7
APPROACH_FLOOR = 1e-3
# the law's codes in a kernel's parameter array (``OrificeLaw.code``)
FIXED, IDELCHIK = 0.0, 1.0


@dataclass(frozen=True)
class OrificeLaw:
    """How an orifice passes liquid.  ``discharge``: a fixed coefficient, or None for Idelchik's
    contraction against the area ratio; ``approach``: count the passage's velocity of approach;
    ``jet``: take the jet's momentum from the force on the piston; ``largest_ratio``: the largest area
    ratio a designer may cut (``VALID_AREA_RATIO`` by default, the law's checked data; a design may set
    it wider, to 1, where it runs on the law's extrapolation)."""
    discharge: float | None = None
    approach: bool = True
    jet: bool = True
    largest_ratio: float = VALID_AREA_RATIO

    def code(self) -> np.ndarray:
        """The law as four floats for the compiled kernels: (law, fixed Cd, approach, jet)."""
        return np.array([FIXED if self.discharge is not None else IDELCHIK,
                         self.discharge if self.discharge is not None else 0.0,
                         1.0 if self.approach else 0.0, 1.0 if self.jet else 0.0])

    def describe(self) -> str:
        cd = f"Cd {self.discharge:g} fixed" if self.discharge is not None else "Idelchik's Cc(a / A)"
        return (f"quasi-steady orifice, {cd}, {'with' if self.approach else 'without'} the velocity of approach, "
                f"{'with' if self.jet else 'without'} the jet's reaction on the piston")


# the study's first law (which let the orifice open to the whole bore), and the area-ratio law
FIXED_CD = OrificeLaw(discharge=0.7, approach=False, jet=False, largest_ratio=1.0)
AREA_RATIO = OrificeLaw()


@njit(cache=True)
def contraction(n: float) -> float:
    """Idelchik's jet contraction of a thin sharp-edged orifice at the area ratio n = a / A."""
    return 1.0 / (1.0 + IDELCHIK_CONTRACTION * math.sqrt(max(1.0 - n, 0.0)))


@njit(cache=True)
def jet_coefficient(n: float, law) -> float:
    """The jet's coefficient Cc: the law's fixed one, or Idelchik's at n."""
    return law[1] if law[0] == FIXED else contraction(n)


@njit(cache=True)
def approach_factor(cc: float, n: float, law) -> float:
    """1 - (Cc n)^2 with the velocity of approach (kept above ``APPROACH_FLOOR``), else 1."""
    return max(1.0 - (cc * n) ** 2, APPROACH_FLOOR) if law[2] > 0.0 else 1.0


@njit(cache=True)
def mass_flow(p: float, rho: float, c: float, a: float, A: float, law) -> float:
    """The mass rate [kg/s] through an orifice of area ``a`` from a passage of area ``A`` holding liquid
    of density ``rho`` at gauge pressure ``p`` (sound speed ``c``), the jet's speed held at ``c``."""
    if p <= 0.0 or a <= 0.0:
        return 0.0
    n = min(a / A, 1.0)
    cc = jet_coefficient(n, law)
    u_jet = min(math.sqrt(2.0 * p / (rho * approach_factor(cc, n, law))), c)
    return rho * cc * a * u_jet


@njit(cache=True)
def jet_reaction(mdot: float, rho: float, a: float, A: float, law) -> float:
    """mdot (u_j - u1) [N]: what the jet's momentum takes from p A on the piston (0 if the law leaves
    the jet out)."""
    if law[3] <= 0.0 or mdot <= 0.0 or a <= 0.0:
        return 0.0
    n = min(a / A, 1.0)
    return mdot * (mdot / (rho * jet_coefficient(n, law) * a) - mdot / (rho * A))


@njit(cache=True)
def pressure_for_flow(Q: float, rho: float, a: float, A: float, law) -> float:
    """The gauge pressure that drives a volume rate ``Q`` [m^3/s] through the orifice (the inverse of
    ``mass_flow`` below the sound speed)."""
    if Q <= 0.0:
        return 0.0
    n = min(a / A, 1.0)
    cc = jet_coefficient(n, law)
    u_jet = Q / (cc * a)
    return 0.5 * rho * u_jet * u_jet * approach_factor(cc, n, law)


def iso_discharge_coefficient(n: float, law: OrificeLaw = AREA_RATIO) -> float:
    """The law's flow written as ISO 5167's Q = C / sqrt(1 - beta^4) a sqrt(2 dp / rho), dp = p (the
    downstream tapping at the contracted jet, corner tappings): C = Cc sqrt((1 - n^2) / (1 - (Cc n)^2))."""
    code = law.code()
    cc = jet_coefficient(n, code)
    return cc * math.sqrt((1.0 - n * n) / approach_factor(cc, n, code))


@njit(cache=True)
def piston_force(a: float, speed: float, rho: float, A: float, law) -> float:
    """The force [N] of incompressible liquid on a piston of area ``A`` with an orifice ``a`` driven into
    it at ``speed`` (Q = A speed): p A less the jet's reaction."""
    p = pressure_for_flow(A * speed, rho, a, A, law)
    return p * A - jet_reaction(rho * A * speed, rho, a, A, law)


@njit(cache=True)
def area_for_force(force: float, speed: float, rho: float, A: float, largest: float, law) -> float:
    """The orifice area that holds ``force`` on the piston at ``speed`` (``piston_force`` falls as the
    area grows), by bisection to 1e-12 of ``largest``; ``largest`` if even that area throttles above
    ``force``; 0 at no speed."""
    if speed <= 0.0:
        return 0.0
    if piston_force(largest, speed, rho, A, law) >= force:
        return largest
    low, high = 0.0, largest
    for _ in range(100):
        mid = 0.5 * (low + high)
        if piston_force(mid, speed, rho, A, law) > force:
            low = mid
        else:
            high = mid
        if high - low <= 1e-12 * largest:
            break
    return 0.5 * (low + high)


def extrapolated(n: float) -> bool:
    """Whether the area ratio ``n`` lies beyond the data the law is checked on (``VALID_AREA_RATIO``)."""
    return n > VALID_AREA_RATIO


# Idelchik's thin-walled orifice: the land over the hydraulic diameter at most this (his thick-edged
# orifice's formula starts above it, diagram 4-15)
THIN_LAND = 0.015
# Idelchik's thick-edged orifice (3rd ed., tau from diagram 4-12, the loss from diagram 4-15, for l / d_h > 0.015
# and Re > 1e3, as the Modelica Standard Library's Fluid.Dissipation dp_thickEdgedOverall writes them): the jet
# reattaches fully at l / d_h = 2.4
REATTACHED_LAND = 2.4
# the inlet's and the outlet's loss of a thick-edged orifice into a large space, referred to its own
# speed, at n -> 0 (Idelchik 4-15's 0.5 (1 - n)^0.75, and the jet's whole head for its (1 - n)^2, the jet
# entering a large space), and the land's friction lambda (Idelchik's 0.02)
INLET_LOSS, EXIT_LOSS, LAND_FRICTION = 0.5, 1.0, 0.02


def thick_edge_excess(land: float) -> float:
    """Idelchik's tau(l / d_h) of a thick-edged orifice (diagram 4-12): the loss of the jet that has not
    yet reattached, (2.4 - l) 10^-phi(l), phi = 0.25 + 0.535 l^8 / (0.05 + l^8); 0 past 2.4."""
    if land >= REATTACHED_LAND:
        return 0.0
    phi = 0.25 + 0.535 * land ** 8 / (0.05 + land ** 8)
    return (REATTACHED_LAND - land) * 10.0 ** -phi


def thick_discharge(land: float) -> float:
    """The discharge coefficient of a thick-edged orifice of land ``land`` = l / d_h into a large space,
    not cavitating, at small area ratio: 1 / sqrt(inlet + tau + exit + lambda l)."""
    return 1.0 / math.sqrt(INLET_LOSS + thick_edge_excess(land) + EXIT_LOSS + LAND_FRICTION * land)


def thick_discharge_ratio(land: float) -> float:
    """The thick-edged orifice's coefficient over the thin one's (the same formula at no land): 1 for a
    thin plate, 1.36 where the jet has reattached (l / d_h = 2.4)."""
    return thick_discharge(land) / thick_discharge(0.0)


def cavitation_number(p: float, vapour_pressure: float, downstream: float = 0.0) -> float:
    """Nurick's K = (p1 - p_v) / (p1 - p2) of an orifice at the upstream gauge pressure ``p`` [Pa]
    discharging to ``downstream`` [Pa gauge]; inf with no pressure drop."""
    return (p - vapour_pressure) / (p - downstream) if p > downstream else math.inf


def coefficient_ratio(land: float, cavitation: float) -> float:
    """The orifice's coefficient over the thin law's: a thick orifice's, choked at Nurick's Cc sqrt(K)
    if that is the lower (the vena contracta at the vapour pressure); 1 for a thin plate."""
    return min(thick_discharge_ratio(land), math.sqrt(cavitation))


def cavitates(land: float, cavitation: float) -> bool:
    """Whether the orifice's flow is choked by cavitation (Nurick): sqrt(K) below the coefficient it
    would have without (a thin plate's jet is free already: it never chokes in this sense)."""
    return math.sqrt(cavitation) < thick_discharge_ratio(land)


# Lichtarowicz, Duggins & Markland (1965): the viscous term of 1/Cd, 20 (1 + 2.25 l / d) / Re
VISCOUS_TERM, VISCOUS_LAND = 20.0, 2.25


def jet_reynolds(p: float, density: float, viscosity: float, hydraulic_diameter: float) -> float:
    """The orifice's Reynolds number d_h sqrt(2 p / rho) / nu of Lichtarowicz et al. (ideal jet speed)."""
    return hydraulic_diameter * math.sqrt(2.0 * max(p, 0.0) / density) * density / viscosity


def viscous_coefficient_ratio(reynolds: float, land: float, cd: float) -> float:
    """The coefficient at ``reynolds`` over its turbulent limit ``cd`` (Lichtarowicz et al.'s viscous
    term, at the land ``land`` = l / d_h): 1 / (1 + cd 20 (1 + 2.25 l) / Re); 0 with no flow."""
    if reynolds <= 0.0:
        return 0.0
    return 1.0 / (1.0 + cd * VISCOUS_TERM * (1.0 + VISCOUS_LAND * land) / reynolds)


def annulus_hydraulic_diameter(area: float, hole_area: float) -> float:
    """The hydraulic diameter [m] of a pin's annulus of ``area`` [m^2] in a hole of ``hole_area``:
    2 (r_hole - r_pin), the whole hole's diameter with no pin."""
    r_hole = math.sqrt(hole_area / math.pi)
    r_pin = math.sqrt(max(hole_area - area, 0.0) / math.pi)
    return 2.0 * (r_hole - r_pin)


# ISO 5167-2:2003, 5.3.1: the pipe diameters [m] its orifice coefficient is measured over
ISO_DIAMETERS = (0.05, 1.0)
# ISO 5167-2:2003, 5.3.1 (corner and D-D/2 tappings): the least Re_D of the orifice coefficient, and
# the area ratio above which it grows as 16000 beta^2
ISO_LEAST_REYNOLDS, ISO_REYNOLDS_SLOPE = 5000.0, 16000.0


def least_reynolds(n: float) -> float:
    """The least pipe Reynolds number Re_D = rho u1 D / mu at which the orifice law holds at the area
    ratio ``n`` = beta^2 (ISO 5167-2:2003, 5.3.1)."""
    return max(ISO_LEAST_REYNOLDS, ISO_REYNOLDS_SLOPE * n)


def reader_harris_gallagher(beta: float, reynolds: float, diameter: float = math.inf) -> float:
    """ISO 5167-2:2003's discharge coefficient C (eq. 4) of a thin orifice plate with corner tappings
    (L1 = L2' = 0, so its tapping terms vanish) at the diameter ratio ``beta`` and Re_D ``reynolds``
    (inf: the turbulent limit) in a pipe of ``diameter`` [m] (its small-pipe term below 71.12 mm)."""
    c = 0.5961 + 0.0261 * beta ** 2 - 0.216 * beta ** 8
    if math.isfinite(reynolds):
        A = (19000.0 * beta / reynolds) ** 0.8
        c += 0.000521 * (1e6 * beta / reynolds) ** 0.7 + (0.0188 + 0.0063 * A) * beta ** 3.5 * (1e6 / reynolds) ** 0.3
    if diameter < 0.07112:
        c += 0.011 * (0.75 - beta) * (2.8 - diameter / 0.0254)
    return c


# a law without the velocity of approach holds while the term it drops, (Cc n)^2, stays below 5%
APPROACH_NEGLIGIBLE = 0.05


def valid_area_ratio(law: OrificeLaw) -> float:
    """The largest area ratio a design on ``law`` may open to: its ``largest_ratio`` for a law with the
    approach (``VALID_AREA_RATIO`` by default; beyond that ``extrapolated``), (Cc n)^2 <= 5% for one
    without (n <= 0.32 at Cd 0.7)."""
    if law.approach:
        return law.largest_ratio
    cc = law.discharge if law.discharge is not None else contraction(0.0)
    return math.sqrt(APPROACH_NEGLIGIBLE) / cc

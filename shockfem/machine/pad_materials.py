"""What an amplifier's pads can be made of: each material with the limits a pad of it must keep, and their
sources.

Five kinds, as a shock machine's struck faces are built:

* ``elastomer``: cast polyurethane discs (90A, 95A, 60D).  Hyperelastic (Neo-Hookean, nearly
  incompressible) with hysteresis: the rebound resilience R of ASTM D2632 (a plunger dropped on the
  pad, a rigid mass on it) gives the pad's restitution on rigid masses, e = sqrt(R), and so the damping
  ratio of a spring-dashpot that never pulls with that restitution (``damping_ratio``); the finite-element
  run gives the disc that damping as a band over its contact's frequencies.  Limits: the working
  compressive stress and strain, the energy per volume stored up to them, the temperature rise a shot
  (the hysteresis heat stays in the pad: polyurethane conducts 0.2 W/m K), and the height over diameter
  at which an unbonded disc stays stable.
* ``yielding metal``: annealed copper and aluminium discs that crush, as Hopkinson-bar pulse shapers do
  (Frew, Forrestal & Chen, Exp. Mech. 42 (2002) 93-106: annealed C11000 copper discs shape a ramped pulse
  by their plastic flow).  J2 with the hardening curve below; a shaper is used once.  Limits: the
  compressive strain a disc takes before it thins and spreads past the face, the temperature rise a shot
  (the plastic work, adiabatic), its height over diameter.
* ``crowned steel``: the struck body's own face crowned to a sphere (no pad): elastic while the closing
  speed is below the Hertz yield onset (``amplifier.interfaces.hertz_yield_speed``).
* ``none``: flat steel on flat steel: the 1D impedance stress must stay below the steel's allowable.
* ``gas spring``: a closed cylinder of nitrogen on the struck body, the striking body's face its piston
  (``machine.gas_spring``): the energy in compressed gas, not a solid's strain.  Its limits: the peak gas
  temperature (below the seal oil's auto-ignition), the column's length over its bore, the face's stress
  and the sleeve's mass over the struck body's; its restitution is its model's (shock, heat, seal friction).

Figures from a handbook recalled rather than read from a retrieved copy say "check" in their source,
as the references do; use certified data for a real pad.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from scipy.optimize import brentq

from ..amplifier.rigid import pad_restitution
from . import gas_spring

KINDS = ("elastomer", "yielding metal", "crowned steel", "none", "gas spring")
# the room a machine's pads start a shot at [K above 0 C]
AMBIENT = 20.0


@dataclass(frozen=True)
class PadMaterial:
    """One pad material and its limits (SI)."""
    name: str
    kind: str                          # KINDS
    density: float                     # [kg/m^3]
    youngs_modulus: float              # small-strain, in compression [Pa]
    poisson_ratio: float
    working_stress: float              # largest compressive (nominal) stress a shot [Pa]
    working_strain: float              # largest compressive (engineering) strain a shot [-]
    heat_capacity: float               # [J/kg K]
    temperature_limit: float           # highest service temperature [C]
    slenderness: float                 # largest height over diameter [-]
    source: str
    resilience: float = 0.0            # rebound resilience, ASTM D2632 [-] (elastomers)
    yield_stress: float = 0.0          # initial, J2 [Pa] (metals)
    hardening: tuple = ()              # ((plastic strain, stress [Pa]), ...) (metals)

    @property
    def temperature_rise(self) -> float:
        """The temperature rise a shot may bring from the ambient to the service limit [K]."""
        return self.temperature_limit - AMBIENT

    def damping_ratio(self) -> float:
        """The damping ratio zeta of the spring-dashpot that never pulls (rigid masses on it:
        ``amplifier.rigid.pad_restitution``) whose restitution is e = sqrt(R), R the rebound resilience
        (a plunger's rebound energy over its drop energy, ASTM D2632)."""
        if not self.resilience:
            return 0.0
        target = math.sqrt(self.resilience)
        return float(brentq(lambda z: pad_restitution(z) - target, 0.0, 0.99, xtol=1e-12))

    def flow_stress(self, eps_p: float) -> float:
        """A metal's flow stress at plastic strain ``eps_p`` [Pa] (its hardening curve, linear between
        points, flat past the last)."""
        pts = self.hardening or ((0.0, self.yield_stress),)
        if eps_p >= pts[-1][0]:
            return pts[-1][1]
        for (e0, s0), (e1, s1) in zip(pts, pts[1:]):
            if eps_p <= e1:
                return s0 + (s1 - s0) * (eps_p - e0) / (e1 - e0)
        return pts[0][1]

    def scene_material(self) -> dict:
        """The scene's material table (``scene.materials``) of this pad."""
        base = {"density": self.density, "youngs_modulus": self.youngs_modulus, "poisson_ratio": self.poisson_ratio}
        if self.kind == "elastomer":
            return {**base, "hyperelastic": "neo-hookean"}
        if self.kind == "yielding metal":
            return {**base, "hardening_curve": [[e, s] for e, s in self.hardening]}
        return base


def _johnson_cook(A: float, B: float, n: float) -> tuple:
    """A + B eps^n [MPa] tabulated at plastic strains 0 ... 1 [Pa] (Johnson & Cook 1983)."""
    return tuple((e, 1e6 * (A + B * e ** n)) for e in (0.0, 0.01, 0.02, 0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 1.0))


def _bilinear(yield_stress: float, tensile: float, elongation: float) -> tuple:
    """Yield to the tensile strength at the elongation, then flat [Pa]."""
    return ((0.0, yield_stress), (elongation, tensile), (1.0, tensile))


# Cast polyurethanes: polyether (PTMEG-TDI prepolymers cured with MOCA), as Adiprene L-100 (90A),
# L-167 (95A) and L-315 (60D) are sold.  Rebound resilience and hardness from such data sheets; the
# small-strain compression modulus, working stress and strain for impact pads (bumpers) from the
# makers' design guides; a shot's rise up to 80 C, the continuous service limit of polyether urethanes.
_PU_SOURCE = ("cast polyether polyurethane {grade} (PTMEG-TDI/MOCA, as Adiprene {product}): Bayshore rebound "
              "{rebound:.0%} (ASTM D2632), small-strain compression modulus {E:g} MPa, impact-bumper working "
              "limits {s:g} MPa and {eps:.0%} strain (maker's design guide), c_p 1.8 kJ/kg K, 80 C service "
              "(check: typical data-sheet values recalled, not a retrieved sheet); unbonded disc stable to "
              "height = diameter (Gent, Engineering with Rubber, 3rd ed. 2012, ch. 8; check)")


def _pu(name, grade, product, rho, E, stress, strain, rebound) -> PadMaterial:
    return PadMaterial(name, "elastomer", rho, E * 1e6, 0.495, stress * 1e6, strain, 1800.0, 80.0, 1.0,
                       _PU_SOURCE.format(grade=grade, product=product, rebound=rebound, E=E, s=stress, eps=strain),
                       resilience=rebound)


PAD_MATERIALS: dict[str, PadMaterial] = {m.name: m for m in [
    _pu("pu_90a", "90 Shore A", "L-100", 1100.0, 40.0, 10.0, 0.25, 0.45),
    _pu("pu_95a", "95 Shore A", "L-167", 1130.0, 70.0, 15.0, 0.20, 0.40),
    _pu("pu_60d", "60 Shore D", "L-315", 1180.0, 150.0, 25.0, 0.15, 0.40),
    PadMaterial("copper_annealed", "yielding metal", 8960.0, 124e9, 0.34, 0.0, 0.5, 385.0, 200.0, 0.5,
                "annealed OFHC copper (C10100/C11000, as the pulse shapers of Frew, Forrestal & Chen, Exp. Mech. "
                "42 (2002) 93-106): hardening A = 90 MPa, B = 292 MPa, n = 0.31 (Johnson & Cook 1983, the scene "
                "library's copper_ofhc), rate independent; a shaper crushed to 50% strain, height up to half its "
                "diameter, c_p 385 J/kg K, a shot's rise to 200 C, below its softening (check: ASM Handbook "
                "vol. 2 values recalled)",
                yield_stress=90e6, hardening=_johnson_cook(90.0, 292.0, 0.31)),
    PadMaterial("aluminium_1100_o", "yielding metal", 2710.0, 69e9, 0.33, 0.0, 0.5, 904.0, 150.0, 0.5,
                "aluminium 1100-O (annealed): yield 34 MPa, tensile 90 MPa at 35% elongation, bilinear between "
                "them, rate independent; crushed to 50% strain, height up to half its diameter, c_p 904 J/kg K, "
                "a shot's rise to 150 C (check: ASM Handbook vol. 2 values recalled)",
                yield_stress=34e6, hardening=_bilinear(34e6, 90e6, 0.35)),
    PadMaterial("crowned_steel", "crowned steel", 0.0, 0.0, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0,
                "the struck body's steel, its face crowned to a sphere: elastic up to the Hertz yield onset "
                "p0 = 1.6 Y (Johnson, Contact Mechanics, 1985, sec. 6.2 and 11.4)"),
    PadMaterial("none", "none", 0.0, 0.0, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0,
                "flat steel on flat steel: the 1D impedance stress dv Z_a Z_b / (Z_a + Z_b) over the smaller face "
                "against the steel's allowable"),
    PadMaterial("nitrogen_gas_spring", "gas spring", 0.0, 0.0, 0.3, 0.0, 0.0, 0.0,
                gas_spring.OIL_AUTOIGNITION - gas_spring.IGNITION_MARGIN - 273.15, gas_spring.MAX_SLENDERNESS,
                "a nitrogen gas spring (machine.gas_spring): the charge inert (accumulators are charged with "
                "nitrogen only); its peak temperature 50 K below the seal oil's auto-ignition (Shell Tellus S2 M 32 "
                "SDS, > 320 C by DIN 51794; check); its sleeve by ASME VIII-2 4.3.3 at the chain steel's allowable"),
]}


def pad_material(name: str) -> PadMaterial:
    """The library's pad material ``name``; a ValueError naming the choices otherwise."""
    if name not in PAD_MATERIALS:
        raise ValueError(f"pad material must be one of {', '.join(PAD_MATERIALS)}, got {name!r}")
    return PAD_MATERIALS[name]


def neo_hookean_stress(G: float, strain: float) -> float:
    """Nominal compressive stress [Pa] of an incompressible Neo-Hookean disc compressed by the engineering
    ``strain`` between frictionless faces (uniaxial, stretch l = 1 - strain): G (1/l^2 - l)
    (Treloar, The Physics of Rubber Elasticity, 1975, eq. 4.9)."""
    stretch = 1.0 - strain
    return G * (1.0 / stretch ** 2 - stretch)


def neo_hookean_energy(G: float, strain: float) -> float:
    """Strain energy per volume [J/m^3] of the same disc: G / 2 (l^2 + 2 / l - 3)."""
    stretch = 1.0 - strain
    return 0.5 * G * (stretch ** 2 + 2.0 / stretch - 3.0)


def plastic_work(material: PadMaterial, strain: float, steps: int = 200) -> float:
    """Plastic work per volume [J/m^3] of a metal disc crushed to the engineering ``strain`` between
    frictionless faces: the flow stress over the true strain, int sigma(eps) d eps, eps = -ln(1 - strain)
    (the elastic part, sigma^2 / 2E, is a thousandth of it and left out)."""
    eps = -math.log(1.0 - strain)
    h = eps / steps
    return sum(material.flow_stress((k + 0.5) * h) for k in range(steps)) * h

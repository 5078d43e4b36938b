"""The pad on one struck face of the amplifier: sized within its material's limits, and its restitution
measured by a finite-element run of that interface.

An interface is the two bodies of one collision (their masses, diameters and lengths as the chain has
them) closing at dv; its reduced mass M* = m_a m_b / (m_a + m_b) brings the energy W = M* dv^2 / 2 to
the pad at its largest compression (rigid bodies; the bodies' own waves take a little of it).

Sizing (``size_pad``), each pad as large across as the smaller face allows (an elastomer no thinner than
MIN_HEIGHT of its diameter):

* elastomer disc: compressed, faces free to slide (uniaxial), Neo-Hookean (G = E / 3) to the largest
  strain inside its working strain at which the closed-form stress times PEAK_FACTOR (the runs' peak over
  it) is RESIZE_AIM of the working stress; its volume stores W there, V = W / w(strain), as wide as the
  face unless that makes it thinner than a quarter of its diameter.  Valid where the runs' peak factor is
  inside PEAK_FACTOR_RANGE (1.15 to 1.32: measured over compact steel masses of 4 to 80 kg, mass ratios
  1 to 4, 1.5 to 6 m/s, the three polyurethanes, smoke and coarse meshes), checked on every run, and for
  pads at most FACE_SHARE_RANGE of the face's diameter (``sizing_range``: wider, up to the face, the
  runs read 1.4 to 5.6 times the closed form), checked on every pad, run or not;
* yielding-metal disc: crushed to its working strain, spreading to the face's diameter there; its
  volume absorbs W as plastic work, V = W / w_p(strain);
* crowned steel face: the crown whose contact radius at the Hertz yield onset is half the face's radius
  (the largest that keeps the yielding inside the face), and the closing speed against that onset;
* no pad: the flat faces' 1D impedance stress against the allowable;
* gas spring: a nitrogen cylinder on the struck body as wide as the smaller face, the striking face its
  piston, sized by ``gas_spring.size_gas_spring`` (its restitution its model's: no run is made).

Each check is a ``Limit`` (stress, strain, stored energy per volume, temperature rise a shot, slenderness,
the face stress on the steel, and the pad's mass over its struck body's, the range in which the chain's
masses are the steel bodies' alone); a pad that cannot keep them is sized at its working point and carries
the broken ones.

Restitution (``measure_restitution``): the two bodies and the pad as an axisymmetric finite-element
scene, the steel bodies J2 (the chain's steel) with the chain's structural damping (a band of 2% over
each body's first free-free mode to 20 times it), an elastomer Neo-Hookean with its hysteresis as a
band damping of its damping ratio over its contact's frequencies (``PadMaterial.damping_ratio``: the
ratio at which rigid masses on it restitute sqrt(R), its rebound resilience), a metal disc J2 with its
hardening curve.  e = (v_a' - v_b') / dv from the bodies' mean velocities once the faces have parted,
the pad counted with the body it rests on.  Runs are cached (``RunCache``): a table of (material,
geometry, closing speed, mesh) -> e with the run's directory, so that a design that meets the same
interface again reads it.

Resizing on the run (``RunCache.measure_within_limits``): an elastomer pad whose run's peak contact
stress over its face (``pad_contact_stress``) is outside RESIZE_BAND to 1 of its working stress is sized
again at the peak factor its run measured (``run_peak_factor``) and run again, at most MAX_RESIZES
times; its restitution is the final size's run's, and a resizing that does not end in the band says so
(``Resizing.verdict``), the last run's stress standing as its limit.  The peak is the design mesh's: on
the mesh study's pad (``verify pad_mesh``) the smoke mesh's peak is 4.2% above the fine mesh's, inside
the band's width, and the peak does not converge with refinement (it rises past the coarse mesh).  Valid: closing speeds at which the steel stays a J2 solid (below its shock
range, some 1 km/s), pads no thinner than a cell of the mesh.
"""
from __future__ import annotations

import json
import math
import os
import time
from dataclasses import asdict, dataclass, field, replace

from ..amplifier.interfaces import HERTZ_YIELD_PRESSURE, flat_face_stress, hertz_yield_speed, reduced_mass
from ..scene import resolve
from ..scene.library import LIBRARY, initial_yield_stress, property_si
from .gas_spring import resolved, size_gas_spring
from .limits import Limit
from .pad_materials import (PAD_MATERIALS, PadMaterial, neo_hookean_energy, neo_hookean_stress, pad_material, plastic_work)

# the chain's structural damping (``amplifier.chain``): a band from each body's first mode up
STRUCTURAL_DAMPING, DAMPING_BAND = 0.02, 20.0
# the pad's mass over its struck body's up to which the chain's masses may leave the pads out (the
# rigid chain's gain moves by about this share: a 10% heavier struck body changes a stage's factor
# (1 + e) / (1 + r) by about 10% of r / (1 + r))
PAD_MASS_SHARE = 0.1
# a crown's contact radius at its yield onset over the face's radius
CROWN_CONTACT = 0.5
# the gap the striker closes before it meets the pad [m]
GAP = 1e-3
# mesh resolutions: steel cells across a body's diameter, pad cells through its thickness; ESTIMATE runs
# nothing and keeps each material's estimate (a study's quickest size: its pads are sized and checked,
# their restitutions not measured)
RESOLUTIONS = {"smoke": (4, 2), "coarse": (8, 4), "default": (16, 8), "fine": (32, 16)}
ESTIMATE = "estimate"
# an elastomer pad's least height over its diameter: its shape factor d / (4 t) at most 1, where a disc
# whose faces slide is near uniaxial (the sizing's model); thinner, the faces' friction holds its rim and
# stiffens it by up to (1 + 2 S^2) (bonded, Gent, Engineering with Rubber, ch. 8; check), and in the runs
# a 2 mm pad on an 87 mm face squeezed out and went unstable
MIN_HEIGHT = 0.25
# a steel face's cells over the pad's, at most
FACE_CELLS = 4
# significant figures the cache (and the run) rounds an interface's inputs to
FIGURES = 3
# the largest run (cells times steps, as ``run_work`` estimates them) an interface gets, about 100 s on one
# core: the smoke run of a 36 m polyurethane pad took 730 cells, 157,653 steps and 111 s, estimated at
# 7.2e7 (0.63 of the count; two shorter pads 0.62 and 0.63); a pad too long or too
# soft for it is many times past its slenderness and keeps its estimated restitution (an upper bound:
# its own waves take more, as the runs of pads 15 to 35 times their limit show)
MAX_WORK = 6e7
# the pad's hysteresis band over its contact's frequency: 1:10 around it (a half-sine's spectrum), as
# narrow as holds it, since a rubber's band takes its moduli static and stiffens it by
# (4 zeta / pi) ln(band) across the band (``materials.band_damping``)
PAD_BAND = 10.0
# An elastomer pad's peak stress in its run over the closed form's at the same pad (rigid bodies on a
# Neo-Hookean disc, quasi-static): the run's band hysteresis stiffens the pad and adds its viscous stress
# at the peak, the bodies' and the pad's waves ring on it.  PEAK_FACTOR_RANGE is where the runs put it
# (``scripts/pad-sizing-range.py``, docs/machine.md "Pads"); the sizing takes PEAK_FACTOR, so that the
# closed form times it is within PEAK_FACTOR_RANGE / PEAK_FACTOR of the runs there: its range of
# validity, checked on every run (``Resizing.verdict``)
PEAK_FACTOR = 1.22
PEAK_FACTOR_RANGE = (1.15, 1.32)
# the pad's diameter over the face's up to which those runs were made (0.75 the widest, a height of
# MIN_HEIGHT of its diameter): pads as wide as the face, at 12 and 24 m/s on the same bodies, read 1.44 to
# 5.6 times the closed form and differently on each mesh (3.13 at smoke size, 2.05 at coarse for one), so
# past it the closed form is outside its range and the run's own peak is uncertain by as much
FACE_SHARE_RANGE = 0.76
# an elastomer sized (and resized on its run) to this share of its working stress: the runs' own scatter
# (a resize moves the mesh with the pad) stays below the limit; a pad is resized until its run's peak is
# between RESIZE_BAND and 1 of its working stress (or below it with the working strain binding), at most
# MAX_RESIZES times
RESIZE_AIM, RESIZE_BAND, MAX_RESIZES = 0.98, 0.93, 4


@dataclass(frozen=True)
class Interface:
    """The two bodies of one collision: the striker (a) and the struck body (b), closing at ``speed``."""
    name: str
    striker_mass: float         # [kg]
    striker_diameter: float     # [m]
    striker_length: float       # [m]
    struck_mass: float
    struck_diameter: float
    struck_length: float
    speed: float                # closing [m/s]
    steel: str                  # the bodies' library material
    allowable: float            # the steel's allowable stress [Pa]

    @property
    def m_star(self) -> float:
        return reduced_mass(self.striker_mass, self.struck_mass)

    @property
    def energy(self) -> float:
        """M* dv^2 / 2 [J]: what the pad holds at its largest compression."""
        return 0.5 * self.m_star * self.speed ** 2

    @property
    def face_diameter(self) -> float:
        return min(self.striker_diameter, self.struck_diameter)

    @property
    def face_area(self) -> float:
        return math.pi * self.face_diameter ** 2 / 4

    def rounded(self) -> "Interface":
        """The interface with every number at FIGURES significant figures (the cache's key)."""
        return replace(self, **{k: _round(v) for k, v in asdict(self).items() if isinstance(v, float)})


@dataclass(frozen=True)
class PadDesign:
    """A pad sized for an interface (SI); for a crowned face ``crown`` is its sphere radius."""
    interface: str
    material: str
    kind: str
    diameter: float = 0.0       # free (uncompressed) [m]
    thickness: float = 0.0      # free [m]
    mass: float = 0.0           # [kg]
    travel: float = 0.0         # its largest compression [m]
    peak_force: float = 0.0     # rigid bodies, quasi-static [N]
    energy: float = 0.0         # M* dv^2 / 2 [J]
    crown: float = 0.0          # [m]
    contact_time: float = 0.0   # estimated [s]
    limits: tuple = ()          # of Limit
    peak_factor: float = 1.0    # an elastomer's: the peak stress its sizing allows for over the closed form's

    @property
    def feasible(self) -> bool:
        return all(lim.holds for lim in self.limits)

    @property
    def worst(self) -> float:
        """The largest of its limits' ratios (1 or less: every limit holds)."""
        return max((lim.ratio for lim in self.limits), default=0.0)

    def as_dict(self) -> dict:
        out = asdict(self)
        out["limits"] = [lim.as_dict() for lim in self.limits]
        return out


def _round(x: float) -> float:
    return float(f"{x:.{FIGURES}g}")


def _steel(iface: Interface) -> tuple[float, float, float, float]:
    """rho, E, nu, yield of the interface's steel."""
    lib = LIBRARY[iface.steel]
    return (property_si(iface.steel, "density", "density"), property_si(iface.steel, "youngs_modulus", "pressure"),
            float(lib["poisson_ratio"]), initial_yield_stress(iface.steel))


def _common_limits(iface: Interface, mat: PadMaterial, mass: float, force: float) -> list[Limit]:
    part = f"pad {iface.name}"
    return [Limit(f"face {iface.name}", "stress", force / iface.face_area, iface.allowable, "Pa",
                  "the pad's peak force over the smaller steel face",
                  f"{iface.steel}: yield / safety factor ({LIBRARY[iface.steel]['source']})"),
            Limit(part, "mass over the struck body's", mass / iface.struck_mass, PAD_MASS_SHARE, "-",
                  "the pad's mass over the struck body's",
                  "the chain's range of validity: its masses are the steel bodies', the pads left out")]


def _working_strain(mat: PadMaterial, G: float, stress: float) -> float:
    """The largest strain inside the working strain at which the closed form's stress is at most ``stress``
    (the stress rises monotonically with the strain)."""
    strain = mat.working_strain
    if neo_hookean_stress(G, strain) <= stress:
        return strain
    lo, hi = 0.0, strain
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if neo_hookean_stress(G, mid) < stress else (lo, mid)
    return lo


def _elastomer(iface: Interface, mat: PadMaterial, e: float, peak_factor: float) -> PadDesign:
    G = mat.youngs_modulus / 3
    # the closed form's stress aimed at RESIZE_AIM of the working stress over the factor by which the runs'
    # peak exceeds it: the pad's own peak (the runs') then at RESIZE_AIM of its working stress
    target = RESIZE_AIM * mat.working_stress / peak_factor
    strain = _working_strain(mat, G, target)
    w = neo_hookean_energy(G, strain)
    # as wide as the face, or narrower where that would make it thinner than MIN_HEIGHT of its diameter
    volume = iface.energy / w
    d = min(iface.face_diameter, (4 * volume / (math.pi * MIN_HEIGHT)) ** (1 / 3))
    area = math.pi * d * d / 4
    t = volume / area
    mass = mat.density * area * t
    force = neo_hookean_stress(G, strain) * area
    k = force / (strain * t)
    duration = math.pi * math.sqrt(iface.m_star / k) + 2 * t / math.sqrt(mat.youngs_modulus / mat.density)
    heat = (1 - e * e) * iface.energy / (mass * mat.heat_capacity)
    part = f"pad {iface.name}"
    stress_binds = strain < mat.working_strain
    limits = [Limit(part, "stress", peak_factor * neo_hookean_stress(G, strain), mat.working_stress, "Pa",
                    f"Neo-Hookean disc in uniaxial compression, G (1/l^2 - l), times {peak_factor:.4g} (the runs' "
                    f"peak over it; sized to {RESIZE_AIM:g} of the working stress)", mat.source),
              Limit(part, "strain", strain, mat.working_strain, "-", "its largest compression over its thickness",
                    mat.source, sized=not stress_binds),
              Limit(part, "stored energy per volume", w, neo_hookean_energy(G, strain), "J/m^3",
                    "M* dv^2 / 2 over its volume (sized to the energy at its working point)", mat.source, sized=True),
              Limit(part, "temperature rise a shot", heat, mat.temperature_rise, "K",
                    "(1 - e^2) M* dv^2 / 2 over its mass times c_p (adiabatic)", mat.source),
              Limit(part, "slenderness", t / d, mat.slenderness, "-", "free height over diameter", mat.source),
              *_common_limits(iface, mat, mass, peak_factor * force)]
    return PadDesign(iface.name, mat.name, mat.kind, d, t, mass, strain * t, force, iface.energy, 0.0, duration,
                     tuple(limits), peak_factor)


def _metal(iface: Interface, mat: PadMaterial, e: float) -> PadDesign:
    strain = mat.working_strain
    # crushed to the working strain, the disc spreads to the face's diameter
    area = iface.face_area * (1 - strain)
    d = math.sqrt(4 * area / math.pi)
    w = plastic_work(mat, strain)
    t = (1 - e * e) * iface.energy / (w * area)
    mass = mat.density * area * t
    force = mat.flow_stress(-math.log(1 - strain)) * iface.face_area
    # a crush at a near-constant force: the closing speed falls linearly to zero over the travel
    duration = 2 * strain * t / iface.speed + 4 * iface.face_diameter / math.sqrt(mat.youngs_modulus / mat.density)
    part = f"pad {iface.name}"
    limits = [Limit(part, "strain", strain, mat.working_strain, "-", "crushed height over free height",
                    mat.source, sized=True),
              Limit(part, "stored energy per volume", w, plastic_work(mat, mat.working_strain), "J/m^3",
                    "plastic work of the hardening curve to its strain (sized to it)", mat.source, sized=True),
              Limit(part, "temperature rise a shot", w / (mat.density * mat.heat_capacity), mat.temperature_rise,
                    "K", "its plastic work over rho c_p (adiabatic)", mat.source),
              Limit(part, "slenderness", t / d, mat.slenderness, "-", "free height over diameter", mat.source),
              *_common_limits(iface, mat, mass, force)]
    return PadDesign(iface.name, mat.name, mat.kind, d, t, mass, strain * t, force, iface.energy, 0.0, duration,
                     tuple(limits))


def _steel_faces(iface: Interface, mat: PadMaterial) -> PadDesign:
    rho, E, nu, Y = _steel(iface)
    c0 = math.sqrt(E / rho)
    transit = 2 * min(iface.striker_length, iface.struck_length) / c0
    if mat.kind == "crowned steel":
        e_star = E / (2 * (1 - nu * nu))
        a = CROWN_CONTACT * iface.face_diameter / 2
        crown = 2 * e_star * a / (math.pi * HERTZ_YIELD_PRESSURE * Y)      # a = pi p0 R / (2 E*)
        onset = hertz_yield_speed(iface.m_star, crown, e_star, Y)
        limits = (Limit(f"face {iface.name}", "closing speed", iface.speed, onset, "m/s",
                        f"Hertz yield onset of a {crown:.3g} m crown (contact radius {a * 1e3:.0f} mm at p0 = 1.6 Y)",
                        mat.source + f"; {iface.steel}"),)
        return PadDesign(iface.name, mat.name, mat.kind, crown=crown, energy=iface.energy,
                         contact_time=3 * transit, limits=limits)
    z = [rho * c0 * math.pi * dd * dd / 4 for dd in (iface.striker_diameter, iface.struck_diameter)]
    stress = flat_face_stress(iface.speed, z[0], z[1], iface.face_area)
    limits = (Limit(f"face {iface.name}", "stress", stress, iface.allowable, "Pa",
                    "1D impedance stress dv Z_a Z_b / (Z_a + Z_b) over the smaller face",
                    mat.source + f"; {iface.steel}: yield / safety factor"),)
    return PadDesign(iface.name, mat.name, mat.kind, energy=iface.energy, contact_time=transit, limits=limits)


def _gas_spring(iface: Interface, mat: PadMaterial) -> PadDesign:
    rho = _steel(iface)[0]
    g = size_gas_spring(iface.m_star, iface.speed, iface.face_diameter, iface.allowable, rho)
    part = f"pad {iface.name}"
    force = g.peak_pressure * math.pi * g.bore ** 2 / 4
    limits = [Limit(part, "peak gas temperature", g.peak_temperature - 273.15, mat.temperature_limit, "C",
                    "T0 r^(gamma - 1), the adiabatic compression", mat.source, sized=True),
              Limit(part, "slenderness", g.column / g.bore, mat.slenderness, "-", "the gas column over its bore",
                    "a sleeve longer than this is a slender tube (gas_spring.MAX_SLENDERNESS)"),
              *_common_limits(iface, mat, g.sleeve_mass, force)]
    return PadDesign(iface.name, mat.name, mat.kind, g.bore, g.column, g.sleeve_mass, g.stroke, force, g.energy,
                     0.0, g.contact_time, tuple(limits))


def size_pad(iface: Interface, material: str, restitution: float = 0.0, peak_factor: float | None = None
             ) -> PadDesign:
    """The pad of ``material`` for ``iface`` (module docstring); ``restitution``: the interface's, which
    sets the share of the energy a pad turns into heat (an elastomer) or must absorb (a metal, which
    returns the rest elastically); ``peak_factor``: an elastomer's peak stress in its run over the closed
    form's (default ``PEAK_FACTOR``, measured; ``RunCache.measure_within_limits`` sets it from the runs)."""
    mat = pad_material(material)
    if mat.kind == "elastomer":
        return _elastomer(iface, mat, restitution, PEAK_FACTOR if peak_factor is None else peak_factor)
    if mat.kind == "yielding metal":
        return _metal(iface, mat, restitution)
    if mat.kind == "gas spring":
        return _gas_spring(iface, mat)
    return _steel_faces(iface, mat)


def estimated_restitution(material: str, iface: Interface | None = None) -> float:
    """The restitution to size a pad with before its run: an elastomer's on rigid masses, sqrt(R); a
    crushed metal's or steel's 0.3 (a first guess only: the run replaces it); a gas spring's, its model's on
    ``iface`` (it depends on the closing speed; nan without one: no estimate for every interface)."""
    mat = pad_material(material)
    if mat.kind == "gas spring":
        return (size_gas_spring(iface.m_star, iface.speed, iface.face_diameter, iface.allowable, _steel(iface)[0])
                .restitution if iface is not None else math.nan)
    return math.sqrt(mat.resilience) if mat.kind == "elastomer" else 0.3


def solid_pads() -> list[str]:
    """The pad materials whose restitution is one number for every interface (all but the gas spring's)."""
    return [m for m, pm in PAD_MATERIALS.items() if pm.kind != "gas spring"]


# ---------------------------------------------------------------------------------------------- the runs


def _band(ratio: float, low: float, reference: float | None = None) -> dict:
    d = {"type": "band", "ratio": ratio, "low": low, "high": DAMPING_BAND * low}
    if reference is not None:
        d["reference"] = reference
    return d


def interface_scene(iface: Interface, pad: PadDesign, resolution: str = "coarse") -> dict:
    """The interface as a raw axisymmetric scene: the struck body b standing on z = 0, the pad resting on
    its face, the striker a above it by GAP moving down at the closing speed (module docstring)."""
    rho, E, nu, Y = _steel(iface)
    c0 = math.sqrt(E / rho)
    across, through = RESOLUTIONS[resolution]
    mat = pad_material(pad.material)
    padded = mat.kind in ("elastomer", "yielding metal")
    t = pad.thickness if padded else 0.0
    h_pad = min(t / through, pad.diameter / across) if padded else math.inf

    def steel_body(name, d, L, z, v, crown=0.0):
        # a face's cells at most FACE_CELLS of the pad's: a thin pad's nodes on a coarse steel face make
        # the penalty contact unstable (a 2 mm pad on 27 mm cells created energy)
        h = min(min(d, L) / across, FACE_CELLS * h_pad)
        b = {"name": name, "material": f"steel_{name}", "shape": "cylinder", "radius": d / 2, "length": L,
             "element_size": h, "position": [0.0, z], "velocity": [0.0, v],
             "damping": _band(STRUCTURAL_DAMPING, c0 / (2 * L))}
        if crown:
            b["bottom_crown"] = crown
            # the contact patch at the yield onset is CROWN_CONTACT of the radius: cells a tenth of it there
            b["element_size"] = min(b["element_size"], CROWN_CONTACT * d / 20)
        return b
    bodies = [steel_body("a", iface.striker_diameter, iface.striker_length, iface.struck_length + t + GAP,
                         -iface.speed, pad.crown),
              steel_body("b", iface.struck_diameter, iface.struck_length, 0.0, 0.0)]
    # each body the chain's mass: a housing's wall and its oil as a solid of the wall's section and length
    materials = {f"steel_{n}": {"library": iface.steel, "density": m / (math.pi * d * d / 4 * L)}
                 for n, m, d, L in (("a", iface.striker_mass, iface.striker_diameter, iface.striker_length),
                                    ("b", iface.struck_mass, iface.struck_diameter, iface.struck_length))}
    contact = [{"name": "a_b", "a": "a.bottom", "b": "b.top", "penalty_scale": 1.0}]
    if padded:
        materials["pad"] = mat.scene_material()
        p = {"name": "pad", "material": "pad", "shape": "cylinder", "radius": pad.diameter / 2, "length": t,
             "element_size": h_pad, "position": [0.0, iface.struck_length]}
        if mat.kind == "elastomer":
            # its hysteresis over the band of its contact's frequencies (1 / (2 T) at its centre); a rubber's
            # band takes its moduli static (``scene.damping.check_band_laws``)
            centre = 1 / (2 * pad.contact_time)
            p["damping"] = {"type": "band", "ratio": mat.damping_ratio(), "low": centre / math.sqrt(PAD_BAND),
                            "high": centre * math.sqrt(PAD_BAND), "reference": 0.0}
        bodies.insert(1, p)
        contact = [{"name": "a_pad", "a": "a.bottom", "b": "pad.top", "penalty_scale": 1.0 if mat.kind != "elastomer"
                    else 0.1},
                   {"name": "pad_b", "a": "pad.bottom", "b": "b.top", "penalty_scale": 1.0 if mat.kind != "elastomer"
                    else 0.1}]
    end = GAP / iface.speed + 3 * pad.contact_time + 6 * max(iface.striker_length, iface.struck_length) / c0
    return {"scene": {"name": f"pad_{iface.name}_{pad.material}", "kinematics": "axisymmetric", "end_time": end,
                      "element": "quad"},
            "materials": materials, "bodies": bodies, "contact": contact,
            "outputs": {"field_interval": end, "history_interval": end / 400}}


@dataclass
class Measured:
    """One interface's run: its restitution and what it cost."""
    restitution: float
    run: str                    # the run directory
    wall_time_s: float
    elements: int
    steps: int
    energy_balance_error: float
    peak_interface_stress: float    # the largest contact force over the smaller face [Pa]
    peak_stress_over_yield: dict    # each steel body's von Mises peak over its yield
    pad_plastic_work: float     # [J]
    parted: bool                # the faces had parted when the run ended
    inputs: dict = field(default_factory=dict)
    cached: bool = False        # read from the cache, not run now
    note: str = ""              # why it was not run

    @property
    def ran(self) -> bool:
        return bool(self.run)

    def as_dict(self) -> dict:
        return asdict(self)


def parted(history: dict, names: list[str]) -> bool:
    """No contact force over the last tenth of the record."""
    n = len(history["time"])
    return all(abs(history[f"contact.{c}.normal_z"][-max(n // 10, 2):]).max() == 0.0 for c in names)


def run_work(raw: dict) -> float:
    """The cells times steps an interface scene will take, estimated: each body's section over its cell
    size squared, the step the smallest cell's dilatational wave allows (halved: a band's step factor,
    the contact's penalty)."""
    cells, dt = 0.0, math.inf
    for b in raw["bodies"]:
        m = raw["materials"][b["material"]]
        props = ({k: property_si(m["library"], k, d) for k, d in (("density", "density"),
                                                                   ("youngs_modulus", "pressure"))}
                 if "library" in m else m)
        rho = m.get("density", props["density"])
        E, nu = props["youngs_modulus"], m.get("poisson_ratio", 0.3)
        c = math.sqrt(E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)) / rho)
        h = b["element_size"]
        cells += b["radius"] * b["length"] / (h * h)
        dt = min(dt, 0.5 * h / c)
    return cells * raw["scene"]["end_time"] / dt


def measure_restitution(iface: Interface, pad: PadDesign, out_dir: str, resolution: str = "coarse") -> Measured:
    """Run the interface's scene (``interface_scene``) in ``out_dir`` and read its restitution; a run whose
    faces have not parted at its end runs again twice as long, once."""
    from ..output.history_file import read_history_csv
    from ..runner import run_scene
    def estimate(note: str) -> Measured:
        return Measured(estimated_restitution(pad.material, iface), "", 0.0, 0, 0, 0.0, math.nan, {}, 0.0, False,
                        {"interface": asdict(iface), "pad": pad.as_dict(), "resolution": resolution}, note=note)
    if resolution == ESTIMATE:
        return estimate("not run (pad resolution 'estimate'): the material's estimate")
    if pad.kind == "gas spring":
        return _gas_column_run(iface, pad, estimate)
    raw = interface_scene(iface, pad, resolution)
    work = run_work(raw)
    if work > MAX_WORK:
        return estimate(f"not run: about {work:.2g} cells x steps, over the {MAX_WORK:.0e} a pad run gets; "
                        f"the material's estimate kept")
    for attempt in range(2):
        res = run_scene(resolve(raw), out_dir, progress=False, write_fields=False, quiet=True)
        s = res.summary
        h = read_history_csv(os.path.join(out_dir, "history.csv"))
        names = [c["name"] for c in raw["contact"]]
        if parted(h, names) or attempt:
            break
        raw["scene"]["end_time"] *= 2
        end = raw["scene"]["end_time"]
        raw["outputs"] = {"field_interval": end, "history_interval": end / 400}
    bodies = s["bodies"]
    v_a = bodies["a"]["velocity_final"][-1]
    struck = [b for b in ("b", "pad") if b in bodies]
    m_b = sum(bodies[b]["mass"] for b in struck)
    v_b = sum(bodies[b]["mass"] * bodies[b]["velocity_final"][-1] for b in struck) / m_b
    force = max(float(abs(h[f"contact.{c}.normal_z"]).max()) for c in names)
    Y = initial_yield_stress(iface.steel)
    return Measured((v_a - v_b) / iface.speed, out_dir, s["wall_time_s"], s["elements"], s["steps"],
                    s["energy"]["balance_error"], force / iface.face_area,
                    {b: bodies[b]["max_von_mises"] / Y for b in ("a", "b")},
                    bodies["pad"]["plastic_work"] if "pad" in bodies else 0.0, parted(h, names),
                    {"interface": asdict(iface), "pad": pad.as_dict(), "resolution": resolution},
                    note=f"about {work:.2g} cells x steps estimated")


def _gas_column_run(iface: Interface, pad: PadDesign, estimate) -> Measured:
    """A gas spring's run: its gas column resolved (``gas_spring.resolved``); the peak pressure at its closed end
    as the interface's peak stress (the bore is the face)."""
    t0 = time.perf_counter()
    spring = size_gas_spring(iface.m_star, iface.speed, iface.face_diameter, iface.allowable, _steel(iface)[0])
    r = resolved(iface.m_star, iface.speed, spring)
    m = estimate(f"the gas column's run ({r['cells']} cells, energy balance {r['energy_error']:.1e} of W): e "
                 f"{r['column_restitution']:.4f} from its gas, {r['restitution']:.4f} with its heat and seal friction")
    return replace(m, restitution=r["restitution"], run=f"gas column ({r['cells']} cells)",
                   wall_time_s=time.perf_counter() - t0, elements=r["cells"], energy_balance_error=r["energy_error"],
                   peak_interface_stress=r["peak_pressure"], parted=True)


def pad_contact_stress(iface: Interface, pad: PadDesign, m: Measured) -> float:
    """The pad's peak nominal stress in its run [Pa]: the run's peak contact force over the pad's free face
    (nan where there was no run or no pad)."""
    if not m.ran or pad.diameter <= 0:
        return math.nan
    return m.peak_interface_stress * iface.face_area / (math.pi * pad.diameter ** 2 / 4)


def run_peak_factor(iface: Interface, pad: PadDesign, m: Measured) -> float:
    """The run's peak stress over the closed form's (its quasi-static peak force over the same face)."""
    return pad_contact_stress(iface, pad, m) / (pad.peak_force / (math.pi * pad.diameter ** 2 / 4))


@dataclass
class Resizing:
    """An elastomer pad sized, run and resized until its run holds its working stress
    (``RunCache.measure_within_limits``): each size's peak factor, geometry and run."""
    steps: list = field(default_factory=list)     # of dict: peak_factor, diameter, thickness, restitution, ...
    converged: bool = True
    verdict: str = ""

    def as_dict(self) -> dict:
        return asdict(self)


def _step(iface: Interface, pad: PadDesign, m: Measured, working_stress: float) -> dict:
    stress = pad_contact_stress(iface, pad, m)
    return {"peak_factor": pad.peak_factor, "diameter": pad.diameter, "thickness": pad.thickness, "mass": pad.mass,
            "restitution": m.restitution, "run": m.run, "cached": m.cached, "stress_ratio": stress / working_stress,
            "run_peak_factor": run_peak_factor(iface, pad, m)}


def _in_band(step: dict, pad: PadDesign) -> bool:
    """The run's peak at most the working stress, and above RESIZE_BAND of it unless the strain binds."""
    strain_binds = any(lim.quantity == "strain" and lim.sized for lim in pad.limits)
    return step["stress_ratio"] <= 1.0 and (step["stress_ratio"] >= RESIZE_BAND or strain_binds)


def sizing_range(iface: Interface, pad: PadDesign) -> str:
    """"" where an elastomer pad is inside the range in which its closed form's peak factor was measured
    (``FACE_SHARE_RANGE``), else the reason it is not."""
    share = pad.diameter / iface.face_diameter if iface.face_diameter else 0.0
    if pad.kind != "elastomer" or share <= FACE_SHARE_RANGE:
        return ""
    return (f"the pad is {share:.2g} of the face's diameter, past the {FACE_SHARE_RANGE:g} up to which its closed "
            f"form's peak factor was measured: its sizing is outside its range of validity, and its run's peak "
            f"stress depends on the mesh there (docs/machine.md, Pads)")


def _verdict(steps: list[dict], converged: bool, outside: str) -> str:
    first, last = steps[0], steps[-1]
    times = "once" if len(steps) == 2 else f"{len(steps) - 1} times"
    words = (f"pad resized {times} on its runs: its peak {first['stress_ratio']:.3g} -> "
             f"{last['stress_ratio']:.3g} of its working stress, {first['thickness'] * 1e3:.4g} -> "
             f"{last['thickness'] * 1e3:.4g} mm thick" if len(steps) > 1 else
             f"pad's run at {last['stress_ratio']:.3g} of its working stress")
    if not converged:
        words += f" (NOT CONVERGED in {MAX_RESIZES} resizes: the last run's peak stands as its limit)"
    lo, hi = PEAK_FACTOR_RANGE
    factors = [s["run_peak_factor"] for s in steps if not lo <= s["run_peak_factor"] <= hi]
    if factors:
        words += (f"; the closed form's peak factor {factors[0]:.3g} is outside its range of validity "
                  f"({lo:g} to {hi:g}): the first size was off by more, the runs corrected it")
    return words + (f"; {outside}" if outside else "")


class RunCache:
    """The interfaces run so far: (material, interface rounded, resolution) -> ``Measured``, kept in
    ``folder/pad_runs.json`` beside the runs' directories, so that a design meeting the same interface
    again (another iteration, another design in the same folder) reads it instead of running it."""

    def __init__(self, folder: str):
        self.folder = folder
        self.path = os.path.join(folder, "pad_runs.json")
        self.table: dict[str, dict] = {}
        if os.path.exists(self.path):
            with open(self.path) as fh:
                self.table = json.load(fh)
        self.hits = self.misses = 0

    @staticmethod
    def key(iface: Interface, pad: PadDesign, resolution: str) -> str:
        d = asdict(iface)
        d.pop("name")
        geometry = {k: _round(getattr(pad, k)) for k in ("diameter", "thickness", "crown")}
        return json.dumps({"material": pad.material, "resolution": resolution, **d, **geometry}, sort_keys=True)

    def measure_within_limits(self, iface: Interface, material: str, resolution: str = "coarse",
                              peak_factor: float | None = None) -> tuple[Measured, PadDesign, Resizing]:
        """``measure``, then an elastomer pad resized on its run while the run's peak stress is outside
        RESIZE_BAND to 1 of its working stress: the next size at the peak factor the run measured, at most
        MAX_RESIZES times; the restitution is the final size's run's.  ``peak_factor``: the first size's
        (default ``PEAK_FACTOR``)."""
        mat, rounded = pad_material(material), iface.rounded()
        m, pad = self.measure(iface, material, resolution, peak_factor=peak_factor)
        if mat.kind != "elastomer" or not m.ran:
            # not run: its stress rests on the closed form and PEAK_FACTOR alone, which the verdict says is
            # outside its range where it is
            return m, pad, Resizing(verdict=sizing_range(rounded, pad))
        steps = [_step(rounded, pad, m, mat.working_stress)]
        while not _in_band(steps[-1], pad) and len(steps) <= MAX_RESIZES:
            m, pad = self.measure(iface, material, resolution, peak_factor=steps[-1]["run_peak_factor"])
            if not m.ran:
                return m, pad, Resizing(steps, False, f"the resized pad was not run: {m.note}")
            steps.append(_step(rounded, pad, m, mat.working_stress))
        converged = _in_band(steps[-1], pad)
        # its limits at the restitution its run measured: an elastomer's geometry does not depend on it, its
        # heat a shot does
        pad = size_pad(rounded, material, m.restitution, pad.peak_factor)
        return m, pad, Resizing(steps, converged, _verdict(steps, converged, sizing_range(rounded, pad)))

    def measure(self, iface: Interface, material: str, resolution: str = "coarse",
                restitution: float | None = None, peak_factor: float | None = None) -> tuple[Measured, PadDesign]:
        """The interface's restitution with a pad of ``material`` sized on it at ``restitution`` (default
        the material's estimate) and ``peak_factor`` (``size_pad``), from the table or from a new run."""
        iface = iface.rounded()
        e0 = estimated_restitution(material) if restitution is None else restitution
        pad = size_pad(iface, material, e0, peak_factor)
        k = self.key(iface, pad, resolution)
        if k in self.table:
            self.hits += 1
            return Measured(**{**self.table[k], "cached": True}), pad
        self.misses += 1
        where = os.path.join(self.folder, f"run_{len(self.table) + 1:03d}_{iface.name}_{material}")
        m = measure_restitution(iface, pad, where, resolution)
        self.table[k] = {key: v for key, v in m.as_dict().items() if key != "cached"}
        os.makedirs(self.folder, exist_ok=True)
        with open(self.path, "w") as fh:
            json.dump(self.table, fh, indent=1)
        return m, pad

"""What a resolved scene holds: frozen dataclasses in SI, and the vocabularies a scene may use
(each defined here once; the readers in ``schema.py``, ``materials.py``, ``contacts.py`` and
``shock.py`` check the user's tables against them)."""
from __future__ import annotations

from dataclasses import dataclass, field

from ..parts.catalog import PARTS
from ..elements.one_point import HOURGLASS_FORMS as HOURGLASS_CODES
from ..materials.j2 import RATE_FORMS as J2_RATE_FORMS

KINEMATICS = ("axisymmetric", "plane-strain", "3d")
ELEMENTS = {"axisymmetric": ("quad", "tri"), "plane-strain": ("quad", "tri"), "3d": ("hex", "tet")}
SHAPES = tuple(PARTS) + ("box", "mesh")
# Named regions of the shapes outside the catalog of parts (which names its own).
BOX_REGIONS = {2: ("left", "right", "bottom", "top"), 3: ("left", "right", "front", "back", "bottom", "top")}
BC_TYPES = ("fixed", "symmetry", "velocity", "force")
DAMPING_TYPES = ("mass", "stiffness", "rayleigh", "band")
FIELDS = ("displacement", "velocity", "von_mises", "pressure", "plastic_strain", "plastic_strain_rate", "stress",
          "strain")
INTEGRATIONS = ("reduced", "full")
HOURGLASS_FORMS = tuple(HOURGLASS_CODES)   # elements/one_point.py


RATE_FORMS = tuple(J2_RATE_FORMS)          # LS-DYNA VP = 1, VP = 0 (materials/j2.py)


@dataclass(frozen=True)
class Plasticity:
    """J2 plasticity of a material (``materials/j2.py``)."""
    curve: tuple[tuple[float, float], ...]   # isotropic hardening (plastic strain [-], yield stress [Pa])
    kinematic_modulus: float                 # H_k [Pa] (MAT_003: (1 - beta) H)
    rate_D: float                            # Cowper-Symonds D [1/s]; 0: rate independent
    rate_q: float                            # Cowper-Symonds q [-]
    rate_form: str                           # RATE_FORMS
    model: str                               # what ran, for the run log

    @property
    def yield_stress(self) -> float:
        return self.curve[0][1]


@dataclass(frozen=True)
class Crush:
    """A crushable foam's crush behaviour (``materials/foam.py``, MAT_063-like)."""
    curve: tuple[tuple[float, float], ...]   # crush stress (volumetric strain 1 - V/V0 [-], stress [Pa])
    tension_cutoff: float                    # largest principal tensile stress [Pa]
    rate_D: float                            # Cowper-Symonds D [1/s] on the volumetric rate; 0: none
    rate_q: float                            # Cowper-Symonds q [-]
    model: str                               # what ran, for the run log


@dataclass(frozen=True)
class Rubber:
    """A Mooney-Rivlin rubber (``materials/rubber.py``, MAT_027-like; Neo-Hookean when c01 = 0): the
    material's E and nu give mu = 2 (C10 + C01) and the bulk modulus."""
    c01: float                               # C01 [Pa]
    model: str                               # what ran, for the run log


@dataclass(frozen=True)
class Material:
    name: str
    rho: float            # density [kg/m^3]
    E: float              # Young's modulus [Pa]
    nu: float             # Poisson's ratio [-]
    plasticity: Plasticity | None = None     # J2 plasticity; None with crush None: elastic
    source: str = ""                         # library entry and its references, if one was used
    crush: Crush | None = None               # crushable foam instead of J2
    rubber: Rubber | None = None             # hyperelastic rubber instead of Hooke's law

    @property
    def law(self) -> str:
        """The name in ``materials.laws.LAWS`` of the law this material follows."""
        return "j2" if self.plasticity else "foam" if self.crush else "rubber" if self.rubber else "elastic"

    @property
    def model(self) -> str:
        """The law with its constants, one line for the run log."""
        special = self.plasticity or self.crush or self.rubber
        return special.model if special else "linear elastic"

    @property
    def lam(self) -> float:
        """Lame's first parameter [Pa]."""
        return self.E * self.nu / ((1 + self.nu) * (1 - 2 * self.nu))

    @property
    def mu(self) -> float:
        """Shear modulus [Pa]."""
        return self.E / (2 * (1 + self.nu))

    @property
    def c_dilatational(self) -> float:
        """Dilatational wave speed sqrt((lam + 2 mu)/rho) [m/s]; sets the explicit step."""
        return ((self.lam + 2 * self.mu) / self.rho) ** 0.5

    @property
    def c_bar(self) -> float:
        """Bar wave speed sqrt(E/rho) [m/s]."""
        return (self.E / self.rho) ** 0.5


@dataclass(frozen=True)
class Damping:
    ratio: float          # fraction of critical at `frequency` (band: over [low, high])
    frequency: float      # [Hz] (band: the band's geometric centre)
    kind: str             # mass | stiffness | rayleigh | band
    low: float = 0.0      # band: its lowest and highest frequencies [Hz]
    high: float = 0.0
    reference: float | None = None   # band: where the material's moduli hold [Hz]; None: the centre, 0: static

    @property
    def reference_frequency(self) -> float:
        """A band's reference frequency [Hz]: where the body's dynamic moduli are the material's
        (``materials/band_damping.py``); the band's geometric centre unless the scene gives one."""
        return self.frequency if self.reference is None else self.reference

    def coefficients(self) -> tuple[float, float]:
        """Rayleigh coefficients (alpha [1/s], beta [s]) with zeta(omega) = alpha/(2 omega) + beta omega/2.

        ``mass``: all of the ratio from alpha; ``stiffness``: all from beta; ``rayleigh``:
        half from each, so that zeta = ratio at the given frequency and zeta is
        smallest there (the usual two-term choice with both terms equal at omega); ``band``:
        none (its Maxwell terms, ``materials/band_damping.py``, act beside the material).
        """
        import math
        if self.kind == "band":
            return 0.0, 0.0
        omega = 2 * math.pi * self.frequency
        if self.kind == "mass":
            return 2 * self.ratio * omega, 0.0
        if self.kind == "stiffness":
            return 0.0, 2 * self.ratio / omega
        return self.ratio * omega, self.ratio / omega


@dataclass(frozen=True)
class Body:
    name: str
    material: str
    shape: str
    dims: dict[str, float]           # shape parameters in SI (radius, length, size_x...)
    element_size: float
    position: tuple[float, ...]
    velocity: tuple[float, ...]
    spin: float                      # [rad/s] about the body's z axis (3D only)
    rigid: bool
    mesh_file: str | None = None
    # mesh bodies: name -> gmsh physical tag (.msh), or -> CAD face tags (.step: a tuple)
    regions: dict[str, int | tuple[int, ...]] = field(default_factory=dict)
    refine: tuple[tuple[str, float, float], ...] = ()       # (region, element size, distance) near faces
    damping: Damping | None = None   # its own stiffness-proportional damping (instead of the scene's beta)
    # 3D: the rotation R (row-major) turning the body as drawn about its position; None: as drawn
    orientation: tuple[float, ...] | None = None

    @property
    def axis(self) -> tuple[float, ...]:
        """The body's own axis (the drawn z axis, turned by its orientation), 3D."""
        return (0.0, 0.0, 1.0) if self.orientation is None else tuple(self.orientation[2::3])


@dataclass(frozen=True)
class Boundary:
    region: str                      # "body.region"
    kind: str
    components: tuple[int, ...]      # velocity/force components the condition acts on
    history: tuple[tuple[float, float], ...]   # (t, value) pairs; a constant is one pair


@dataclass(frozen=True)
class RigidSurface:
    """A rigid analytic surface moving at a constant velocity.

    ``plane``: through ``point``, ``direction`` the unit normal toward the side bodies stay on.
    ``cylinder``: of ``radius`` about the axis through ``point`` along the unit ``direction``
    (axisymmetric: the symmetry axis; plane strain: zero, the cylinder is the circle about
    ``point``); bodies stay ``inside`` or outside it.
    ``tunnel``: a cylinder that begins at ``point`` and runs along ``direction`` only (the hole a
    penetrator has made behind its nose, ``[penetration]``); bodies stay inside it.
    """
    kind: str                        # plane | cylinder | tunnel
    point: tuple[float, ...]
    direction: tuple[float, ...]
    velocity: tuple[float, ...]      # [m/s], constant
    radius: float = 0.0
    inside: bool = False

    def describe(self) -> str:
        if self.kind == "plane":
            return f"rigid plane through {self.point} m, normal {self.direction}"
        if self.kind == "tunnel":
            return (f"rigid tunnel of radius {self.radius:g} m from {self.point} m along {self.direction} "
                    f"(inside)")
        side = "inside" if self.inside else "outside"
        return f"rigid cylinder of radius {self.radius:g} m about {self.point} m ({side})"


@dataclass(frozen=True)
class Contact:
    name: str
    a: str                           # "body" or "body.region"
    b: str | None                    # the other surface, or None for a rigid surface
    rigid: RigidSurface | None
    penalty: str                     # segment | soft
    penalty_scale: float
    damping: float                   # fraction of critical (LS-DYNA VDC)
    friction: tuple[float, float, float] = (0.0, 0.0, 0.0)   # mu_static, mu_dynamic, decay [s/m]
    # > 0: initial overlaps are pushed out over this time [s] (a shrink fit's preload); 0: they are the zero
    interference_time: float = 0.0
    method: str = "penalty"          # penalty | constraint (a rigid wall that puts each node crossing it on it)


@dataclass(frozen=True)
class Cavity:
    """A liquid-filled cavity discharging through an orifice, by one of ``CAVITY_MODELS``: a control volume
    at one pressure bounded by body surfaces, the rest of its walls held still (``fluid/cavity.py``), or a
    compressible column along the bore between two walls, the floor and the piston face the orifice
    passes through (``fluid/column_source.py``)."""
    name: str
    walls: tuple[str, ...]           # "body.region" surfaces that bound the liquid (their normals face it);
                                     # a column: exactly (floor, piston face)
    volume: float                    # initial liquid volume [m^3]; 0: the walls close the cavity and give it
    density: float                   # liquid density at zero gauge pressure [kg/m^3]
    bulk_modulus: float              # K [Pa] at zero gauge pressure
    tait_exponent: float             # n of p = K/n ((rho/rho0)^n - 1); 1: linear
    discharge: float                 # the fixed_cd law's discharge coefficient Cd [-] (0 for sharp_edged)
    orifice: tuple[tuple[float, float], ...]    # (stroke [m], area [m^2]); one pair: a fixed orifice
    piston_area: float               # displaced volume / piston_area = stroke [m^2]; the passage the liquid
                                     # approaches the orifice through; 0: the orifice wall's own area
    initial_pressure: float = 0.0    # gauge [Pa] (a pre-charged cavity)
    model: str = "control_volume"    # one of CAVITY_MODELS
    law: str = "sharp_edged"         # the orifice law, one of ORIFICE_LAWS
    cells: int = 200                 # a column's finite volumes
    vapour_pressure: float = -1.0e5  # gauge [Pa]: a column parts below it (a control volume at 0 gauge)
    heat_capacity: float = 1900.0    # c_p [J/(kg K)] of the liquid (its heating)
    section: tuple[tuple[float, float], ...] = ()   # a column's (distance from the floor [m], the liquid's
                                                    # section [m^2]): a metering pin fixed to the floor


# the cavity's models and orifice laws (``fluid/cavity.py``, ``fluid/column_source.py``, ``fluid/orifice.py``)
CAVITY_MODELS = ("control_volume", "column")
ORIFICE_LAWS = ("sharp_edged", "fixed_cd")


@dataclass(frozen=True)
class Penetration:
    """A concrete target penetrated nose first (``target/penetration.py``): Forrestal's cavity-expansion
    pressure on the projectile's nose facets beyond the target's face, a crater over the first
    ``crater_depth``, and a rigid tunnel (a contact of its own, ``tunnel``) behind the nose."""
    nose: str                        # "body.region": the wetted surface (the ogive and its meplat)
    point: tuple[float, ...]         # a point of the target's face [m]
    normal: tuple[float, ...]        # the face's unit normal, out of the target (toward the projectile)
    compressive_strength: float      # f'c [Pa]
    density: float                   # rho [kg/m^3]
    strength_factor: float           # S [-]; 0: Forrestal's fit 82.6 (f'c / MPa)^-0.544
    crater_depth: float              # [m]; -1: Forrestal's 4a (two calibres, a from the nose's area)
    carried: tuple[str, ...]         # bodies moving with the projectile (their mass sets the crater law)
    friction: float                  # mu of the resisting torque mu F a / 2 about the axis (3D)
    tunnel: str = ""                 # the name of the tunnel's contact; "" if none


@dataclass(frozen=True)
class Spring:
    """A discrete spring and dashpot between two bodies (or named regions of them), acting along
    ``direction`` on the mass-weighted mean motion of each side (LS-DYNA's *ELEMENT_DISCRETE
    between rigidly averaged node sets)."""
    name: str
    a: str
    b: str
    direction: tuple[float, ...] | None     # unit; None: from a's centre of mass to b's at t = 0
    stiffness: float                        # [N/m] (linear spring), 0 with a curve
    curve: tuple[tuple[float, float], ...]  # (extension [m], tension [N]) pairs, or ()
    damping: float                          # [N s/m]
    compression_only: bool                  # pads: push, never pull


@dataclass(frozen=True)
class SectionCuts:
    """The axial and bending stress along a slender deformable body: its length along its axis cut
    into ``count`` equal slabs, in each the axial stress fitted as a plane over the section (its mean
    the axial stress, its slope times the outer radius the bending stress)."""
    body: str
    count: int


@dataclass(frozen=True)
class Outputs:
    fields: tuple[str, ...]
    field_interval: float
    history_interval: float
    sections: tuple[SectionCuts, ...] = ()


CFC_CLASSES = (60, 180, 600, 1000)       # SAE J211-1 channel frequency classes [Hz]
PULSE_SHAPES = ("half-sine", "terminal-peak sawtooth", "trapezoid")


@dataclass(frozen=True)
class Accelerometer:
    """Acceleration at a point: the node of ``body`` nearest to ``point`` (scene coordinates at t = 0);
    with a ``section`` thickness, the mass-weighted mean of the body's nodes in the slab that thick
    through the point, square to the body's axis (a cross-section's motion: a spinning or ringing
    section's own circulation averages out)."""
    name: str
    body: str
    point: tuple[float, ...]
    section: float = 0.0             # [m]; 0: the nearest node


@dataclass(frozen=True)
class PulseSpec:
    """The test pulse a test article must see (MIL-STD-810 Method 516 classical pulse)."""
    shape: str
    peak: float           # [m/s^2]
    duration: float       # [s], foot to foot


@dataclass(frozen=True)
class Shock:
    """What a shock-test engineer reads off the run (``metrics/``): pulses of the test articles
    and accelerometers along ``axis``, filtered by CFC class ``cfc`` (0: no filter, the scene's "none"), checked
    against ``spec``; the shock response spectrum at quality factor ``srs_q``."""
    test_articles: tuple[str, ...] = ()
    axis: str = ""                            # "" : the last axis (z)
    cfc: int = 1000
    srs_q: float = 10.0
    srs_frequencies: tuple[float, float] | None = None   # [Hz]; None: from the pulse (metrics/srs.pulse_band)
    srs_points_per_octave: int = 12
    accelerometers: tuple[Accelerometer, ...] = ()
    spec: PulseSpec | None = None


@dataclass(frozen=True)
class Preload:
    """``[scene.preload]``: a stage before the event in which the assembly settles under its interference
    fits (``solver/preload.py``): the event's bodies held at rest, the motion taken out by mass damping,
    until the kinetic energy stays below ``kinetic_energy_ratio`` of the stored energy after every
    interference has come on, or ``duration`` [s] has passed."""
    duration: float
    kinetic_energy_ratio: float = 1e-5
    frequency: float = 0.0           # [Hz] damped critically during the stage; 0: estimated (solver/preload.py)


@dataclass(frozen=True)
class Scene:
    name: str
    kinematics: str
    element: str
    end_time: float
    safety_factor: float
    thickness: float
    energy_error_limit: float
    integration: str                 # reduced (one point + hourglass control) | full (2x2 Gauss)
    hourglass: str                   # stiffness | viscous
    hourglass_coefficient: float
    materials: dict[str, Material]
    bodies: tuple[Body, ...]
    boundaries: tuple[Boundary, ...]
    contacts: tuple[Contact, ...]
    damping: Damping | None
    outputs: Outputs
    springs: tuple[Spring, ...] = ()
    gravity: tuple[float, ...] = ()              # [m/s^2]; empty or zero: none
    bulk_viscosity: tuple[float, float] = (1.5, 0.06)   # (Q1 quadratic, Q2 linear), LS-DYNA's defaults
    shock: Shock = Shock()
    cavities: tuple[Cavity, ...] = ()
    penetration: Penetration | None = None
    curve_elements: int = 24                     # elements round a full circle on curved faces (gmsh)
    checkpoint_interval: float = 0.0             # simulated time between checkpoints [s]; 0: on signals only
    mass_scaling_step: float = 0.0               # [s] elements below this step get mass (model/mass_scaling.py); 0: off
    mass_scaling_limit: float = 0.05             # the largest share of a body's mass the scaling may add
    folder: str = ""                             # the scene file's folder (absolute); "": built in code
    max_time_step: float = 0.0                   # [s] the step's upper bound for accuracy; 0: none
    preload: Preload | None = None               # a settling stage before the event (``[scene.preload]``)

    @property
    def gdim(self) -> int:
        return 3 if self.kinematics == "3d" else 2

    def body(self, name: str) -> Body:
        return next(b for b in self.bodies if b.name == name)

    def material_of(self, body: Body) -> Material:
        return self.materials[body.material]

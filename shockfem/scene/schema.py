"""The scene: what a user describes, resolved to SI and checked before anything runs.

A scene file is TOML (documented with a worked example in ``docs/scenes.md``).  ``resolve``
turns the raw dictionary into the frozen dataclasses below, collecting *every* problem
with its path (``bodies[1].radius: must be > 0, got -3 mm``) instead of stopping at the
first one.  Nothing here imports dolfinx: a scene can be checked on any machine.
"""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field
from typing import Any

from ..parts.catalog import CAD_FILES, MESH_FILES, PARTS
from ..elements.one_point import HOURGLASS_FORMS as HOURGLASS_CODES
from ..materials.j2 import RATE_FORMS as J2_RATE_FORMS
from .checker import Checker, SceneError

KINEMATICS = ("axisymmetric", "plane-strain", "3d")
ELEMENTS = {"axisymmetric": ("quad", "tri"), "plane-strain": ("quad", "tri"), "3d": ("hex", "tet")}
SHAPES = tuple(PARTS) + ("box", "mesh")
# Named regions of the shapes outside the catalog of parts (which names its own).
BOX_REGIONS = {2: ("left", "right", "bottom", "top"), 3: ("left", "right", "front", "back", "bottom", "top")}
BC_TYPES = ("fixed", "symmetry", "velocity", "force")
DAMPING_TYPES = ("mass", "stiffness", "rayleigh")
FIELDS = ("displacement", "velocity", "von_mises", "pressure", "plastic_strain", "plastic_strain_rate")
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
class Material:
    name: str
    rho: float            # density [kg/m^3]
    E: float              # Young's modulus [Pa]
    nu: float             # Poisson's ratio [-]
    plasticity: Plasticity | None = None     # None: elastic
    source: str = ""                         # library entry and its references, if one was used

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
    ratio: float          # fraction of critical at `frequency`
    frequency: float      # [Hz]
    kind: str             # mass | stiffness | rayleigh

    def coefficients(self) -> tuple[float, float]:
        """Rayleigh coefficients (alpha [1/s], beta [s]) with zeta(omega) = alpha/(2 omega) + beta omega/2.

        ``mass``: all of the ratio from alpha; ``stiffness``: all from beta; ``rayleigh``:
        half from each, so that zeta = ratio at the given frequency and zeta is
        smallest there (the usual two-term choice with both terms equal at omega).
        """
        import math
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
    """
    kind: str                        # plane | cylinder
    point: tuple[float, ...]
    direction: tuple[float, ...]
    velocity: tuple[float, ...]      # [m/s], constant
    radius: float = 0.0
    inside: bool = False

    def describe(self) -> str:
        if self.kind == "plane":
            return f"rigid plane through {self.point} m, normal {self.direction}"
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
class Outputs:
    fields: tuple[str, ...]
    field_interval: float
    history_interval: float


CFC_CLASSES = (60, 180, 600, 1000)       # SAE J211-1 channel frequency classes [Hz]
PULSE_SHAPES = ("half-sine", "terminal-peak sawtooth", "trapezoid")


@dataclass(frozen=True)
class Accelerometer:
    """Acceleration at a point: the node of ``body`` nearest to ``point`` (scene coordinates at t = 0)."""
    name: str
    body: str
    point: tuple[float, ...]


@dataclass(frozen=True)
class PulseSpec:
    """The test pulse a test article must see (MIL-STD-810 Method 516 classical pulse)."""
    shape: str
    peak: float           # [m/s^2]
    duration: float       # [s], foot to foot


@dataclass(frozen=True)
class Shock:
    """What a shock-test engineer reads off the run (``metrics/``): pulses of the test articles
    and accelerometers along ``axis``, filtered by CFC class ``cfc`` (0: unfiltered), checked
    against ``spec``; the shock response spectrum at quality factor ``srs_q``."""
    test_articles: tuple[str, ...] = ()
    axis: str = ""                            # "" : the last axis (z)
    cfc: int = 1000
    srs_q: float = 10.0
    srs_frequencies: tuple[float, float] = (10.0, 10000.0)   # [Hz]
    srs_points_per_octave: int = 12
    accelerometers: tuple[Accelerometer, ...] = ()
    spec: PulseSpec | None = None


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

    @property
    def gdim(self) -> int:
        return 3 if self.kinematics == "3d" else 2

    def body(self, name: str) -> Body:
        return next(b for b in self.bodies if b.name == name)

    def material_of(self, body: Body) -> Material:
        return self.materials[body.material]


def _part_dims(ck, part, b: dict, path: str, kin: str, dims: dict) -> tuple[set[str], bool]:
    """Read a catalogued part's dimensions into ``dims`` and check them together; returns the
    fields the part accepts and whether the dimensions are sound (so its regions can be drawn)."""
    for p in part.params:
        if p.kind == "lengths":
            raw = b.get(p.name)
            if not isinstance(raw, list) or not raw:
                ck.fail(f"{path}.{p.name}", f"missing (a list of lengths: {p.doc})")
                dims[p.name] = [1.0]
                continue
            values = []
            for j, item in enumerate(raw):
                values.append(ck.quantity({"v": item}, "v", "", "length", positive=True))
                if ck.problems and ck.problems[-1].startswith(".v:"):
                    ck.problems[-1] = f"{path}.{p.name}[{j}]" + ck.problems[-1][2:]
            dims[p.name] = values
        else:
            dims[p.name] = ck.quantity(b, p.name, path, "length" if p.kind == "length" else "dimensionless",
                                       default=p.default, positive=p.minimum == "positive",
                                       nonnegative=p.minimum == "nonnegative")
            if p.kind == "count" and (dims[p.name] != int(dims[p.name]) or dims[p.name] < 1):
                ck.fail(f"{path}.{p.name}", f"must be a whole number >= 1, got {b.get(p.name)!r}")
    shaped = any(dims.get(k) for k in ("bottom_chamfer", "top_chamfer", "bottom_crown", "top_crown"))
    if kin == "plane-strain" and (part.name != "cylinder" or shaped):
        ck.fail(f"{path}.shape", f"a {part.name} is a part of revolution: use kinematics 'axisymmetric' or '3d' "
                                 "(or shape = 'box' / 'mesh' in plane strain)")
    before = len(ck.problems)
    if part.name != "clamp_ring":         # a clamp ring is checked against the body it fits
        for fieldname, message in part.check(dims):
            ck.fail(f"{path}.{fieldname}", message)
    accepted = {p.name for p in part.params}
    if part.name == "clamp_ring":
        accepted.add("fits")
    return accepted, len(ck.problems) == before


def _damping(ck, raw: dict, path: str, kinds, default_kind: str) -> Damping:
    """A ``{ratio, frequency, type}`` damping table."""
    d = ck.table(raw, "damping", path)
    ck.unknown(d, ("ratio", "frequency", "type"), path)
    ratio = ck.quantity(d, "ratio", path, "dimensionless", nonnegative=True, upper=1.0)
    freq = ck.quantity(d, "frequency", path, "frequency", positive=True)
    kind = ck.choice(d, "type", path, kinds, default=default_kind)
    return Damping(ratio, freq, kind)


def _body_damping(ck, b: dict, path: str) -> Damping:
    """``bodies[i].damping``: the body's own stiffness-proportional damping, as LS-DYNA's
    *DAMPING_PART_STIFFNESS: a fraction of critical at the body's own frequency (its first mode,
    say), so that small stiff bodies are not damped at a large body's low frequency (stiffness
    damping grows with frequency).  Mass-proportional damping stays scene-wide."""
    return _damping(ck, b, f"{path}.damping", ("stiffness",), "stiffness")


def _refinements(ck, b: dict, path: str, h: float) -> tuple:
    """``refine = [{region, size, distance}]``: a finer element size near named faces, growing
    linearly to the body's element size over ``distance`` (default 5 element sizes)."""
    out = []
    fields = ("region", "size", "distance")
    for rp, r in ck.entries(b, "refine", f"{path}.refine", fields):
        ck.unknown(r, fields, rp)
        region = r.get("region")
        if not isinstance(region, str):
            ck.fail(f"{rp}.region", "missing (the name of one of the body's regions)")
        size = ck.quantity(r, "size", rp, "length", positive=True)
        if h and size >= h:
            ck.fail(f"{rp}.size", f"must be smaller than the body's element_size {h:g} m to refine, got {size:g} m")
        distance = ck.quantity(r, "distance", rp, "length", default=5 * size, positive=True)
        out.append((region if isinstance(region, str) else "", size, distance))
    return tuple(out)


def _fit_clamp_rings(ck, raw: dict, bodies: list, gdim: int) -> list:
    """Give each clamp ring its bore from the body it fits: that body's outer radius less the
    interference; the ring must be thicker than the interference and lie along that body."""
    out = []
    by_name = {b.name: b for b in bodies}
    for i, b in enumerate(bodies):
        if b.shape != "clamp_ring":
            out.append(b)
            continue
        path = f"bodies[{i}]"
        fits = raw["bodies"][i].get("fits")
        target = by_name.get(fits) if isinstance(fits, str) else None
        outer = None if target is None else target.dims.get("outer_radius", target.dims.get("radius"))
        dims = dict(b.dims)
        if target is None or outer is None or target.shape not in PARTS:
            ck.fail(f"{path}.fits", f"must name the body the ring is shrunk onto (a part of revolution), got {fits!r}")
            dims["inner_radius"] = 1.0
        else:
            dims["inner_radius"] = outer - dims["interference"]
            if dims["interference"] >= dims["thickness"]:
                ck.fail(f"{path}.interference", f"the interference ({dims['interference']:g} m) must be smaller "
                                                 f"than the ring's thickness ({dims['thickness']:g} m)")
            if dims["interference"] >= outer:
                ck.fail(f"{path}.interference", f"the ring does not fit: an interference of "
                                                 f"{dims['interference']:g} m on a radius of {outer:g} m")
            z0, z1 = b.position[-1], b.position[-1] + dims["length"]
            t0 = target.position[-1]
            t1 = t0 + target.dims.get("length", 0.0)
            if z0 < t0 - 1e-12 or z1 > t1 + 1e-12:
                ck.fail(f"{path}.position", f"the ring (z from {z0:g} to {z1:g} m) does not fit along {fits} "
                                            f"(z from {t0:g} to {t1:g} m)")
        out.append(dataclasses.replace(b, dims=dims))
    return out


def _regions_of(body, gdim: int) -> tuple[str, ...]:
    if body.shape == "mesh":
        return tuple(body.regions)
    if body.shape == "box":
        return BOX_REGIONS[gdim]
    return PARTS[body.shape].regions(body.dims, gdim)


def resolve(raw: dict, base_dir: str = ".") -> Scene:
    """Check a raw scene dictionary completely and return the resolved ``Scene``.

    Raises
    ------
    SceneError
        Listing every problem found, each with its path.
    """
    import os

    ck = Checker()
    ck.unknown(raw, ("scene", "materials", "bodies", "boundary", "contact", "spring", "damping", "outputs",
                     "shock"), "")
    s = ck.table(raw, "scene", "scene")
    ck.unknown(s, ("name", "kinematics", "element", "end_time", "safety_factor", "thickness",
                   "energy_error_limit", "integration", "hourglass", "hourglass_coefficient", "gravity",
                   "bulk_viscosity_quadratic", "bulk_viscosity_linear"), "scene")
    name = str(s.get("name", "scene"))
    kin = ck.choice(s, "kinematics", "scene", KINEMATICS)
    gdim = 3 if kin == "3d" else 2
    element = ck.choice(s, "element", "scene", ELEMENTS[kin], default=ELEMENTS[kin][0])
    end_time = ck.quantity(s, "end_time", "scene", "time", positive=True)
    sf = ck.quantity(s, "safety_factor", "scene", "dimensionless", default=0.9, positive=True)
    if sf > 1.0:
        ck.fail("scene.safety_factor", f"must be <= 1 (explicit stability), got {sf}")
    thickness = ck.quantity(s, "thickness", "scene", "length", default=1.0, positive=True)
    elimit = ck.quantity(s, "energy_error_limit", "scene", "dimensionless", default=0.05, positive=True)
    integration = ck.choice(s, "integration", "scene", INTEGRATIONS, default="reduced")
    hourglass = ck.choice(s, "hourglass", "scene", HOURGLASS_FORMS, default="stiffness")
    hg_coef = ck.quantity(s, "hourglass_coefficient", "scene", "dimensionless", default=0.05,
                          nonnegative=True, upper=1.0)
    gravity = ck.vector(s, "gravity", "scene", "acceleration", gdim, [0.0] * gdim)
    bulk_viscosity = (ck.quantity(s, "bulk_viscosity_quadratic", "scene", "dimensionless", default=1.5,
                                  nonnegative=True),
                      ck.quantity(s, "bulk_viscosity_linear", "scene", "dimensionless", default=0.06,
                                  nonnegative=True))
    if kin == "axisymmetric" and gravity[0] != 0.0:
        ck.fail("scene.gravity", "axisymmetric gravity acts along the axis: the r component must be 0")

    materials: dict[str, Material] = {}
    mats = ck.table(raw, "materials", "materials")
    for mname, m in mats.items():
        path = f"materials.{mname}"
        if not isinstance(m, dict):
            ck.fail(path, "must be a table")
            continue
        materials[mname] = _material(ck, mname, m, path)

    bodies: list[Body] = []
    raw_bodies = raw.get("bodies", [])
    if not isinstance(raw_bodies, list) or not raw_bodies:
        ck.fail("bodies", "needs at least one [[bodies]] entry")
        raw_bodies = []
    names = set()
    sound: dict[str, bool] = {}     # parts whose dimensions passed their checks
    for i, b in enumerate(raw_bodies):
        path = f"bodies[{i}]"
        if not isinstance(b, dict):
            ck.fail(path, "must be a table")
            continue
        bname = b.get("name")
        if not isinstance(bname, str) or not bname.isidentifier():
            ck.fail(f"{path}.name", f"needs a name made of letters, digits and _, got {bname!r}")
            bname = f"body{i}"
        if bname in names:
            ck.fail(f"{path}.name", f"duplicate body name {bname!r}")
        names.add(bname)
        shape = ck.choice(b, "shape", path, SHAPES)
        allowed = {"name", "material", "shape", "element_size", "position", "velocity", "spin", "rigid", "refine",
                   "damping"}
        dims: dict[str, float] = {}
        mesh_file = None
        regions: dict[str, int] = {}
        if shape in PARTS:
            accepted, sound[bname] = _part_dims(ck, PARTS[shape], b, path, kin, dims)
            allowed |= accepted
        if shape == "box":
            allowed |= {"size"}
            size = ck.vector(b, "size", path, "length", gdim, [1.0] * gdim)
            if "size" not in b:
                ck.fail(f"{path}.size", f"missing ({gdim} lengths)")
            for k, v in zip("xyz", size):
                if v <= 0:
                    ck.fail(f"{path}.size", f"every length must be > 0, got {b.get('size')}")
                    break
                dims[f"size_{k}"] = v
        elif shape == "mesh":
            allowed |= {"file", "regions"}
            f = b.get("file")
            if not isinstance(f, str) or not f.lower().endswith(MESH_FILES + CAD_FILES):
                ck.fail(f"{path}.file", "missing or not a mesh: the path of a gmsh .msh file with physical groups, "
                                        "or of a .step / .stp CAD file (lengths in its own units)")
            else:
                mesh_file = f if os.path.isabs(f) else os.path.normpath(os.path.join(base_dir, f))
                if not os.path.exists(mesh_file):
                    ck.fail(f"{path}.file", f"no such file {mesh_file}")
            cad = isinstance(f, str) and f.lower().endswith(CAD_FILES)
            reg = b.get("regions", {})
            if cad:
                # a CAD file has no physical groups: a region is one face tag or a list of them
                ok = isinstance(reg, dict) and all(
                    isinstance(v, int) or (isinstance(v, list) and v and all(isinstance(x, int) for x in v))
                    for v in reg.values())
                if not ok:
                    ck.fail(f"{path}.regions", "must map region names to the CAD file's face tags (an integer or a "
                                               "list of integers, as gmsh numbers them on import)")
                else:
                    regions = {k: tuple(v) if isinstance(v, list) else (v,) for k, v in reg.items()}
                if not b.get("element_size"):
                    ck.fail(f"{path}.element_size", "missing: a CAD file is meshed here; give an element size")
                if kin != "3d":
                    ck.fail(f"{path}.file", "a CAD (.step) body needs kinematics = '3d'; in 2D use a catalogued "
                                            "part or a .msh of the section")
            elif not isinstance(reg, dict) or not all(isinstance(v, int) for v in reg.values()):
                ck.fail(f"{path}.regions", "must map region names to gmsh physical group tags (integers)")
            else:
                regions = dict(reg)
        ck.unknown(b, allowed, path)
        mat = b.get("material")
        if mat not in materials:
            ck.fail(f"{path}.material", f"unknown material {mat!r} (defined: {', '.join(materials) or 'none'})")
        h = ck.quantity(b, "element_size", path, "length", positive=True,
                        default=None if shape != "mesh" else 0.0)
        if shape == "cylinder" and h > 0 and h > dims.get("radius", h):
            ck.fail(f"{path}.element_size", "must not exceed the radius (at least one element across)")
        refine = _refinements(ck, b, path, h)
        if refine and shape in ("box", "mesh"):
            ck.fail(f"{path}.refine", f"local refinement is drawn on the catalogued parts, not on a {shape}")
        pos = ck.vector(b, "position", path, "length", gdim, [0.0] * gdim)
        vel = ck.vector(b, "velocity", path, "velocity", gdim, [0.0] * gdim)
        spin = ck.quantity(b, "spin", path, "angular_velocity", default=0.0)
        if spin and gdim != 3:
            ck.fail(f"{path}.spin", "an initial spin needs kinematics = '3d'")
        if kin == "axisymmetric":
            if pos[0] != 0.0:
                ck.fail(f"{path}.position", "axisymmetric bodies sit on the axis: the r component must be 0")
            if vel[0] != 0.0:
                ck.fail(f"{path}.velocity", "axisymmetric bodies move along the axis: the r component must be 0")
        rigid = b.get("rigid", False)
        if not isinstance(rigid, bool):
            ck.fail(f"{path}.rigid", f"must be true or false, got {rigid!r}")
            rigid = False
        own_damping = _body_damping(ck, b, path) if "damping" in b else None
        bodies.append(Body(bname, mat if mat in materials else "", shape, dims, h, pos, vel, spin,
                           rigid, mesh_file, regions, refine, own_damping))

    bodies = _fit_clamp_rings(ck, raw, bodies, gdim)
    body_regions = {b.name: _regions_of(b, gdim) if sound.get(b.name, True) else () for b in bodies}
    for i, b in enumerate(bodies):
        for j, (region, _, _) in enumerate(b.refine):
            if region not in body_regions[b.name]:
                ck.fail(f"bodies[{i}].refine[{j}].region", f"{b.name} has no region {region!r} "
                                                          f"(it has: {', '.join(body_regions[b.name])})")
    boundaries: list[Boundary] = []
    axes = "xyz"[:gdim] if kin != "axisymmetric" else "rz"
    for path, bc in ck.entries(raw, "boundary"):
        ck.unknown(bc, ("region", "type", "direction", "value", "history"), path)
        region = bc.get("region", "")
        bname, _, rname = str(region).partition(".")
        if bname not in body_regions:
            ck.fail(f"{path}.region", f"must be 'body.region' with a known body, got {region!r}")
        elif rname not in body_regions[bname]:
            ck.fail(f"{path}.region", f"body {bname!r} has regions {', '.join(body_regions[bname])}; "
                                      f"got {rname!r}")
        kind = ck.choice(bc, "type", path, BC_TYPES)
        comps: tuple[int, ...] = tuple(range(gdim))
        history: tuple = ((0.0, 0.0),)
        if kind in ("velocity", "force"):
            d = bc.get("direction", axes[-1])
            if d not in axes:
                ck.fail(f"{path}.direction", f"must be one of {', '.join(axes)}, got {d!r}")
                d = axes[-1]
            comps = (axes.index(d),)
            dim = "velocity" if kind == "velocity" else "force"
            if "history" in bc:
                history = tuple(ck.pairs(bc, "history", path, ("time", "value"), ("time", dim))) or history
            else:
                history = ((0.0, ck.quantity(bc, "value", path, dim)),)
        boundaries.append(Boundary(region, kind, comps, history))

    contacts = _contacts(ck, raw, body_regions, kin)
    springs = _springs(ck, raw, body_regions, gdim)

    damping = _damping(ck, raw, "damping", DAMPING_TYPES, "rayleigh") if "damping" in raw else None

    o = ck.table(raw, "outputs", "outputs", required=False)
    ck.unknown(o, ("fields", "field_interval", "history_interval"), "outputs")
    fields = o.get("fields", list(FIELDS))
    if not isinstance(fields, list) or any(f not in FIELDS for f in fields):
        ck.fail("outputs.fields", f"must be a list drawn from {', '.join(FIELDS)}, got {fields!r}")
        fields = list(FIELDS)
    fi = ck.quantity(o, "field_interval", "outputs", "time", default=end_time / 10, positive=True)
    hi = ck.quantity(o, "history_interval", "outputs", "time", default=0.0, nonnegative=True)
    outputs = Outputs(tuple(fields), fi, hi)
    shock = _shock(ck, raw, body_regions, kin, end_time)

    if ck.problems:
        raise SceneError(ck.problems)
    return Scene(name, kin, element, end_time, sf, thickness, elimit, integration, hourglass, hg_coef,
                 materials, tuple(bodies),
                 tuple(boundaries), tuple(contacts), damping, outputs, tuple(springs),
                 gravity if any(gravity) else (), bulk_viscosity, shock)


def _shock(ck: Checker, raw: dict, body_regions: dict, kin: str, end_time: float) -> Shock:
    """``[shock]``: test articles, axis, CFC class, SRS settings, accelerometers, pulse spec."""
    if "shock" not in raw:
        return Shock()
    d = ck.table(raw, "shock", "shock")
    ck.unknown(d, ("test_articles", "axis", "cfc", "srs_q", "srs_frequencies", "srs_points_per_octave",
                   "accelerometers", "spec"), "shock")
    gdim = 3 if kin == "3d" else 2
    axes = "rz" if kin == "axisymmetric" else "xyz"[:gdim]
    articles = d.get("test_articles", [])
    if not isinstance(articles, list) or not all(isinstance(a, str) for a in articles):
        ck.fail("shock.test_articles", f"must be a list of body names, got {articles!r}")
        articles = []
    for j, a in enumerate(articles):
        if a not in body_regions:
            ck.fail(f"shock.test_articles[{j}]", f"unknown body {a!r} (bodies: {', '.join(body_regions)})")
    axis = d.get("axis", axes[-1])
    if axis not in axes or (kin == "axisymmetric" and axis != "z"):
        allowed = "z (the axis of symmetry)" if kin == "axisymmetric" else ", ".join(axes)
        ck.fail("shock.axis", f"must be one of {allowed}, got {axis!r}")
        axis = axes[-1]
    cfc = d.get("cfc", 1000)
    if cfc == "none":
        cfc = 0
    if cfc not in CFC_CLASSES and cfc != 0:
        ck.fail("shock.cfc", f"must be a channel frequency class {', '.join(map(str, CFC_CLASSES))} "
                             f"(SAE J211) or 'none', got {cfc!r}")
        cfc = 1000
    q = ck.quantity(d, "srs_q", "shock", "dimensionless", default=10.0, positive=True)
    band = (10.0, 10000.0)
    if "srs_frequencies" in d:
        pair = d["srs_frequencies"]
        if not isinstance(pair, list) or len(pair) != 2:
            ck.fail("shock.srs_frequencies", f"must be [lowest, highest], e.g. ['10 Hz', '10 kHz'], got {pair!r}")
        else:
            lo = ck.quantity({"srs_frequencies[0]": pair[0]}, "srs_frequencies[0]", "shock", "frequency",
                             positive=True)
            hi = ck.quantity({"srs_frequencies[1]": pair[1]}, "srs_frequencies[1]", "shock", "frequency",
                             positive=True)
            if not lo < hi:
                ck.fail("shock.srs_frequencies", f"the lowest frequency must be below the highest, got {pair!r}")
            band = (lo, hi)
    ppo = d.get("srs_points_per_octave", 12)
    if not isinstance(ppo, int) or isinstance(ppo, bool) or ppo < 1:
        ck.fail("shock.srs_points_per_octave", f"must be a whole number >= 1, got {ppo!r}")
        ppo = 12
    meters = []
    names = set()
    fields = ("name", "body", "at")
    for path, m in ck.entries(d, "accelerometers", "shock.accelerometers", fields):
        ck.unknown(m, fields, path)
        name = m.get("name")
        if not isinstance(name, str) or not name.isidentifier() or name in names:
            ck.fail(f"{path}.name", f"needs a unique name made of letters, digits and _, got {name!r}")
            name = f"accelerometer{len(meters)}"
        names.add(name)
        body = m.get("body")
        if body not in body_regions:
            ck.fail(f"{path}.body", f"unknown body {body!r} (bodies: {', '.join(body_regions)})")
        if "at" not in m:
            ck.fail(f"{path}.at", f"missing (the point, {gdim} coordinates with units)")
        at = ck.vector(m, "at", path, "length", gdim, [0.0] * gdim)
        meters.append(Accelerometer(name, str(body), at))
    spec = None
    if "spec" in d:
        sp = ck.table(d, "spec", "shock.spec")
        ck.unknown(sp, ("shape", "peak", "duration"), "shock.spec")
        shape = ck.choice(sp, "shape", "shock.spec", PULSE_SHAPES)
        peak = ck.quantity(sp, "peak", "shock.spec", "acceleration", positive=True)
        duration = ck.quantity(sp, "duration", "shock.spec", "time", positive=True)
        spec = PulseSpec(shape, peak, duration)
        if not articles and not meters:
            ck.fail("shock.spec", "a pulse spec needs a test article or an accelerometer to check")
    return Shock(tuple(articles), axis, int(cfc), q, tuple(band), ppo, tuple(meters), spec)


PENALTIES = ("segment", "soft")
CYLINDER_SIDES = ("outside", "inside")


MATERIAL_FIELDS = ("library", "density", "youngs_modulus", "poisson_ratio", "yield_stress", "tangent_modulus",
                   "isotropic_fraction", "hardening_curve", "cowper_symonds_D", "cowper_symonds_q", "rate_form")


def _material(ck: Checker, name: str, m: dict, path: str) -> Material:
    """A material: elastic, or J2-plastic with a bilinear (MAT_003) or tabulated (MAT_024) hardening
    and optional Cowper-Symonds rate effects; ``library`` fills in fields the table does not give."""
    from .library import LIBRARY
    ck.unknown(m, MATERIAL_FIELDS, path)
    source = ""
    if "library" in m:
        entry = LIBRARY.get(m["library"])
        if entry is None:
            ck.fail(f"{path}.library", f"unknown library material {m['library']!r} (known: {', '.join(LIBRARY)})")
        else:
            source = f"library {m['library']!r}: {entry['source']}"
            # the scene's fields win; its bilinear fields replace a library curve and vice versa
            bilinear = ("yield_stress", "tangent_modulus", "isotropic_fraction")
            dropped = (("hardening_curve",) if any(k in m for k in bilinear)
                       else bilinear if "hardening_curve" in m else ())
            m = {**{k: v for k, v in entry.items() if k != "source" and k not in dropped}, **m}
    rho = ck.quantity(m, "density", path, "density", positive=True)
    E = ck.quantity(m, "youngs_modulus", path, "pressure", positive=True)
    nu = ck.quantity(m, "poisson_ratio", path, "dimensionless", default=0.3)
    if not -1.0 < nu < 0.5:
        ck.fail(f"{path}.poisson_ratio", f"must be in (-1, 0.5), got {nu}")
    plastic_fields = [k for k in MATERIAL_FIELDS[4:] if k in m]
    if not plastic_fields:
        return Material(name, rho, E, nu, None, source)
    if "hardening_curve" in m:
        for k in ("yield_stress", "tangent_modulus", "isotropic_fraction"):
            if k in m:
                ck.fail(f"{path}.{k}", "give either hardening_curve (tabulated, isotropic) or yield_stress with "
                                       "tangent_modulus and isotropic_fraction (bilinear), not both")
        curve = ck.pairs(m, "hardening_curve", path, ("plastic strain", "stress"), ("dimensionless", "pressure"))
        if curve and curve[0][0] != 0.0:
            ck.fail(f"{path}.hardening_curve", f"must start at plastic strain 0 (the initial yield), got {curve[0][0]}")
        if any(sy <= 0 for _, sy in curve):
            ck.fail(f"{path}.hardening_curve", "stresses must be > 0")
        if any(s1 < s0 for (_, s0), (_, s1) in zip(curve, curve[1:])):
            ck.fail(f"{path}.hardening_curve", "stresses must not decrease (softening is not supported)")
        curve = tuple(curve) or ((0.0, 1.0),)
        kinematic = 0.0
        model = f"J2 plasticity, tabulated isotropic hardening ({len(curve)} points, MAT_024-like)"
    else:
        sy = ck.quantity(m, "yield_stress", path, "pressure", positive=True)
        Et = ck.quantity(m, "tangent_modulus", path, "pressure", default=0.0, nonnegative=True)
        if Et >= E:
            ck.fail(f"{path}.tangent_modulus", f"must be < youngs_modulus ({E:.4g} Pa), got {Et:.4g} Pa")
            Et = 0.0
        beta = ck.quantity(m, "isotropic_fraction", path, "dimensionless", default=1.0, nonnegative=True)
        if beta > 1.0:
            ck.fail(f"{path}.isotropic_fraction", f"must be in [0, 1] (1 isotropic, 0 kinematic), got {beta}")
        H = E * Et / (E - Et)                 # plastic modulus: slope of stress against plastic strain
        curve = ((0.0, sy), (1.0, sy + beta * H))
        kinematic = (1.0 - beta) * H
        model = (f"J2 plasticity, bilinear hardening (yield {sy / 1e6:.4g} MPa, tangent {Et / 1e6:.4g} MPa, "
                 f"isotropic fraction {beta:g}; MAT_003-like)")
    D = ck.quantity(m, "cowper_symonds_D", path, "strain_rate", default=0.0, positive="cowper_symonds_D" in m)
    q = ck.quantity(m, "cowper_symonds_q", path, "dimensionless", default=5.0 if D else 1.0, positive=True)
    if ("cowper_symonds_q" in m) != ("cowper_symonds_D" in m):
        ck.fail(f"{path}.{'cowper_symonds_D' if 'cowper_symonds_q' in m else 'cowper_symonds_q'}",
                "missing: Cowper-Symonds rate effects need both D and q")
    rate_form = ck.choice(m, "rate_form", path, RATE_FORMS, default=RATE_FORMS[0])
    if D:
        model += (f", Cowper-Symonds D = {D:g} /s, q = {q:g} on the "
                  f"{'plastic (VP=1)' if rate_form == RATE_FORMS[0] else 'total (VP=0)'} strain rate")
    return Material(name, rho, E, nu, Plasticity(curve, kinematic, D, q, rate_form, model), source)


def _surface_spec(ck: Checker, c: dict, key: str, path: str, body_regions: dict) -> str | None:
    """A "body" or "body.region" reference, checked against the scene's bodies."""
    spec = c.get(key)
    if not isinstance(spec, str):
        ck.fail(f"{path}.{key}", "missing ('body' or 'body.region')")
        return None
    bname, _, rname = spec.partition(".")
    if bname not in body_regions:
        ck.fail(f"{path}.{key}", f"unknown body {bname!r} (bodies: {', '.join(body_regions)})")
    elif rname and rname not in body_regions[bname]:
        ck.fail(f"{path}.{key}", f"body {bname!r} has regions {', '.join(body_regions[bname])}, got {rname!r}")
    return spec


def _unit_vector(ck: Checker, d: dict, key: str, path: str, gdim: int, default) -> tuple:
    v = ck.vector(d, key, path, "dimensionless", gdim, default)
    norm = sum(x * x for x in v) ** 0.5
    if norm == 0:
        ck.fail(f"{path}.{key}", "must not be zero")
        return tuple(default)
    return tuple(x / norm for x in v)


def _rigid_surface(ck: Checker, c: dict, path: str, kin: str) -> RigidSurface:
    """``wall = {point, normal, velocity}`` or ``cylinder = {point, axis, radius, side, velocity}``."""
    gdim = 3 if kin == "3d" else 2
    zero = [0.0] * gdim
    if "wall" in c:
        p = f"{path}.wall"
        w = ck.table(c, "wall", p)
        ck.unknown(w, ("point", "normal", "velocity"), p)
        point = ck.vector(w, "point", p, "length", gdim, zero)
        normal = _unit_vector(ck, w, "normal", p, gdim, zero[:-1] + [1.0])
        vel = ck.vector(w, "velocity", p, "velocity", gdim, zero)
        return RigidSurface("plane", point, normal, vel)
    p = f"{path}.cylinder"
    cyl = ck.table(c, "cylinder", p)
    allowed = ("point", "radius", "side", "velocity") + (("axis",) if gdim == 3 else ())
    ck.unknown(cyl, allowed, p)
    point = ck.vector(cyl, "point", p, "length", gdim, zero)
    radius = ck.quantity(cyl, "radius", p, "length", positive=True)
    side = ck.choice(cyl, "side", p, CYLINDER_SIDES, default="outside")
    vel = ck.vector(cyl, "velocity", p, "velocity", gdim, zero)
    if kin == "3d":
        axis = _unit_vector(ck, cyl, "axis", p, 3, [0.0, 0.0, 1.0])
    elif kin == "axisymmetric":
        axis = (0.0, 1.0)                 # coaxial with the bodies
        if point[0] != 0.0 or vel[0] != 0.0:
            ck.fail(p, "an axisymmetric cylinder is coaxial with the bodies: point and velocity need r = 0")
    else:
        axis = (0.0, 0.0)                 # plane strain: the circle about point
    return RigidSurface("cylinder", point, axis, vel, radius, side == "inside")


def _contacts(ck: Checker, raw: dict, body_regions: dict, kin: str) -> list[Contact]:
    """[[contact]] entries: two surfaces (``a``, ``b``) or a surface and a rigid ``wall`` or ``cylinder``."""
    out = []
    for path, c in ck.entries(raw, "contact"):
        ck.unknown(c, ("name", "a", "b", "wall", "cylinder", "penalty", "penalty_scale", "damping", "friction",
                       "friction_dynamic", "friction_decay"), path)
        a = _surface_spec(ck, c, "a", path, body_regions)
        b = rigid = None
        if sum(k in c for k in ("b", "wall", "cylinder")) != 1:
            ck.fail(path, "give exactly one of b (a second surface), wall (a rigid plane) or cylinder "
                          "(a rigid cylinder)")
        elif "b" in c:
            b = _surface_spec(ck, c, "b", path, body_regions)
            if a and b and a.partition(".")[0] == b.partition(".")[0]:
                ck.fail(f"{path}.b", "self-contact of a body is not supported; give two different bodies")
        else:
            rigid = _rigid_surface(ck, c, path, kin)
        penalty = ck.choice(c, "penalty", path, PENALTIES, default="segment")
        scale = ck.quantity(c, "penalty_scale", path, "dimensionless", default=0.1, positive=True)
        zeta = ck.quantity(c, "damping", path, "dimensionless", default=0.1, nonnegative=True, upper=1.0)
        mu_s = ck.quantity(c, "friction", path, "dimensionless", default=0.0, nonnegative=True)
        mu_d = ck.quantity(c, "friction_dynamic", path, "dimensionless", default=mu_s, nonnegative=True)
        if mu_d > mu_s:
            ck.fail(f"{path}.friction_dynamic", f"must not exceed the static coefficient friction = {mu_s:g}")
        decay = ck.quantity(c, "friction_decay", path, "slowness", default=0.0, nonnegative=True)
        name = c.get("name", f"{a}-{b or (rigid.kind if rigid else '?')}")
        out.append(Contact(str(name), a or "", b, rigid, penalty, scale, zeta, (mu_s, mu_d, decay)))
    return out


def _springs(ck: Checker, raw: dict, body_regions: dict, gdim: int) -> list[Spring]:
    """[[spring]] entries: a linear ``stiffness`` or a tabulated ``curve``, and a ``damping``."""
    out = []
    for i, (path, c) in enumerate(ck.entries(raw, "spring")):
        ck.unknown(c, ("name", "a", "b", "direction", "stiffness", "curve", "damping", "compression_only"), path)
        a = _surface_spec(ck, c, "a", path, body_regions)
        b = _surface_spec(ck, c, "b", path, body_regions)
        if a and b and a.partition(".")[0] == b.partition(".")[0]:
            ck.fail(f"{path}.b", "a spring joins two different bodies")
        direction = _unit_vector(ck, c, "direction", path, gdim, [0.0] * (gdim - 1) + [1.0]) \
            if "direction" in c else None
        stiffness = ck.quantity(c, "stiffness", path, "stiffness", default=0.0, nonnegative=True)
        curve: list[tuple[float, float]] = []
        if "curve" in c:
            if "stiffness" in c:
                ck.fail(path, "give stiffness (linear) or curve (tabulated), not both")
            curve = ck.pairs(c, "curve", path, ("extension", "force"), ("length", "force"), minimum=2)
        damping = ck.quantity(c, "damping", path, "damping", default=0.0, nonnegative=True)
        if not stiffness and not curve and not damping:
            ck.fail(path, "needs a stiffness, a curve or a damping")
        only = c.get("compression_only", False)
        if not isinstance(only, bool):
            ck.fail(f"{path}.compression_only", f"must be true or false, got {only!r}")
            only = False
        name = str(c.get("name", f"spring{i}"))
        out.append(Spring(name, a or "", b or "", direction, stiffness, tuple(curve), damping, only))
    return out


def to_plain(scene: Scene) -> dict[str, Any]:
    """The resolved scene (SI units) as plain data for ``resolved_scene.json``."""
    d = dataclasses.asdict(scene)
    d["units"] = "SI (m, kg, s, N, Pa, J)"
    return d

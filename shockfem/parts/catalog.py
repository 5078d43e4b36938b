"""The shock tester's parts, by name: their parameters, regions, outlines and closed-form volumes.

A part is described by its dimensions (``Param``), checked as a whole (``check``: a bore
wider than the part, a chamfer longer than the radius...), drawn from its (r, z) outline
(``profiles.Profile``) in axisymmetric form or revolved in 3D, with 3D-only features cut
afterwards (``cut_3d``: the split cone's slots, the dashpot's orifice); the drawing is gmsh's
and lives in ``geometry/outline.py``: this module is pure geometry.  ``volume`` is the
textbook volume of the part, written out independently of the outline so that the meshed
volume checks both the drawing and the mesh.

Conventions: z = 0 is the part's bottom, the axis is r = 0 (z in 3D), lengths are SI.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import numpy as np

from .profiles import Arc, Line, Profile


@dataclass(frozen=True)
class Param:
    name: str
    doc: str
    default: float | None = None      # None: required
    kind: str = "length"              # length | number | count (a whole number >= 1) | lengths (a list)
    minimum: str = "positive"         # positive | nonnegative


@dataclass(frozen=True)
class Part:
    name: str
    doc: str
    params: tuple[Param, ...]
    profile: Callable[[dict], Profile]
    volume: Callable[[dict, int], float]            # (dims, gdim): 3D volume of what is drawn
    check: Callable[[dict], list[tuple[str, str]]] = lambda d: []
    cut_3d: str | None = None         # a 3D-only feature ``geometry/outline.py`` cuts (CUTS_3D)
    cut_region: str = "cut"
    regions_3d_only: tuple[str, ...] = ()
    # (dims, gdim): what the drawn part leaves out of the real one, said in the run log
    approximations: Callable[[dict, int], list[str]] = lambda d, g: []

    def regions(self, dims: dict, gdim: int) -> tuple[str, ...]:
        names = [r for r in self.profile(dims).regions() if not (gdim == 3 and r == "axis")]
        if gdim == 3:
            names += [r for r in self.regions_3d_only if self._has_3d_feature(dims, r)]
        return tuple(names)

    def _has_3d_feature(self, dims, region):
        return {"slots": dims.get("segments", 0) > 1, "orifice": dims.get("orifice_radius", 0.0) > 0}.get(region, True)


def _gauss(f, a, b, n=64):
    """Gauss-Legendre quadrature of a smooth function (closed forms with no elementary integral)."""
    x, w = np.polynomial.legendre.leggauss(n)
    t = 0.5 * (b - a) * x + 0.5 * (b + a)
    return 0.5 * (b - a) * float(np.sum(w * f(t)))


def _cap_height(R, crown):
    """Height of the spherical cap of radius ``crown`` over a face of radius R (0 for a flat face)."""
    return crown - math.sqrt(crown * crown - R * R) if crown else 0.0


# ---------------------------------------------------------------------------- cylinder

def _cylinder_profile(d):
    R, L = d["radius"], d["length"]
    cb, ct = d.get("bottom_chamfer", 0.0), d.get("top_chamfer", 0.0)
    kb, kt = d.get("bottom_crown", 0.0), d.get("top_crown", 0.0)
    hb, ht = _cap_height(R, kb), _cap_height(R, kt)
    chain = []
    if kb:
        chain.append(Arc((0.0, 0.0), (R, hb), (0.0, kb), "bottom"))
    elif cb:
        chain += [Line((0.0, 0.0), (R - cb, 0.0), "bottom"), Line((R - cb, 0.0), (R, cb), "bottom_chamfer")]
    else:
        chain.append(Line((0.0, 0.0), (R, 0.0), "bottom"))
    z0, z1 = (hb if kb else cb), L - (ht if kt else ct)
    chain.append(Line((R, z0), (R, z1), "side"))
    if kt:
        chain.append(Arc((R, z1), (0.0, L), (0.0, L - kt), "top"))
    elif ct:
        chain += [Line((R, z1), (R - ct, L), "top_chamfer"), Line((R - ct, L), (0.0, L), "top")]
    else:
        chain.append(Line((R, L), (0.0, L), "top"))
    chain.append(Line((0.0, L), (0.0, 0.0), "axis"))
    return Profile(chain)


def _cylinder_volume(d, gdim):
    R, L = d["radius"], d["length"]
    v = math.pi * R * R * L
    for end in ("bottom", "top"):
        crown, c = d.get(f"{end}_crown", 0.0), d.get(f"{end}_chamfer", 0.0)
        if crown:
            h = _cap_height(R, crown)
            v -= math.pi * R * R * h - math.pi * h * h * (3 * crown - h) / 3
        if c:
            v -= 0.5 * c * c * 2 * math.pi * (R - c / 3)      # Pappus: the chamfer's triangle turned
    return v


def _cylinder_check(d):
    R, L = d["radius"], d["length"]
    out = []
    for end in ("bottom", "top"):
        crown, c = d.get(f"{end}_crown", 0.0), d.get(f"{end}_chamfer", 0.0)
        if crown and c:
            out.append((f"{end}_chamfer", f"an end is either crowned or chamfered, not both ({end}_crown is set)"))
        if crown and crown < R:
            out.append((f"{end}_crown", f"the crown's sphere radius must be at least the radius {R:g} m, "
                                        f"got {crown:g} m"))
        if c >= R:
            out.append((f"{end}_chamfer", f"must be smaller than the radius {R:g} m, got {c:g} m"))
    ends = sum(_cap_height(R, d.get(f"{e}_crown", 0.0)) if d.get(f"{e}_crown", 0.0) >= R
               else d.get(f"{e}_chamfer", 0.0) for e in ("bottom", "top"))
    if ends >= L:
        out.append(("length", f"the shaped ends ({ends:g} m together) leave no straight side in {L:g} m"))
    return out


# ---------------------------------------------------------------------------- tube, plate, stepped

def _tube_profile(d):
    ri, ro, L = d["inner_radius"], d["outer_radius"], d["length"]
    return Profile([Line((ri, 0.0), (ro, 0.0), "bottom"), Line((ro, 0.0), (ro, L), "outer"),
                    Line((ro, L), (ri, L), "top"), Line((ri, L), (ri, 0.0), "inner")])


def _tube_check(d):
    if d["inner_radius"] >= d["outer_radius"]:
        return [("inner_radius", f"the bore ({d['inner_radius']:g} m) must be smaller than outer_radius "
                                 f"({d['outer_radius']:g} m)")]
    return []


def _plate_profile(d):
    return _cylinder_profile({"radius": d["radius"], "length": d["thickness"]})


def _stepped_profile(d):
    radii, lengths = d["radii"], d["lengths"]
    chain = [Line((0.0, 0.0), (radii[0], 0.0), "bottom")]
    z = 0.0
    for k, (r, length) in enumerate(zip(radii, lengths)):
        chain.append(Line((r, z), (r, z + length), "side"))
        z += length
        nxt = radii[k + 1] if k + 1 < len(radii) else 0.0
        chain.append(Line((r, z), (nxt, z), "shoulders" if nxt else "top"))
    chain.append(Line((0.0, z), (0.0, 0.0), "axis"))
    return Profile(chain)


def _stepped_check(d):
    if len(d["radii"]) != len(d["lengths"]) or len(d["radii"]) < 2:
        return [("radii", f"needs two or more radii and as many lengths, got {len(d['radii'])} radii and "
                          f"{len(d['lengths'])} lengths")]
    if any(a == b for a, b in zip(d["radii"], d["radii"][1:])):
        return [("radii", "neighbouring steps need different radii (merge them into one step)")]
    return []


# ---------------------------------------------------------------------------- sphere

def _sphere_profile(d):
    R = d["radius"]
    return Profile([Arc((0.0, 0.0), (R, R), (0.0, R), "bottom"), Arc((R, R), (0.0, 2 * R), (0.0, R), "top"),
                    Line((0.0, 2 * R), (0.0, 0.0), "axis")])


# ---------------------------------------------------------------------------- split cone and clamp ring

def _split_cone_profile(d):
    Ro, L, r_exit, r_entry = d["outer_radius"], d["length"], d["exit_radius"], d["entry_radius"]
    return Profile([Line((r_exit, 0.0), (Ro, 0.0), "bottom"), Line((Ro, 0.0), (Ro, L), "side"),
                    Line((Ro, L), (r_entry, L), "top"), Line((r_entry, L), (r_exit, 0.0), "bore")],
                   cut_region="slots")


def _slot_area(R, w):
    """Area of the strip |y| < w/2, x > 0 inside the circle of radius R."""
    return 0.5 * w * math.sqrt(R * R - 0.25 * w * w) + R * R * math.asin(0.5 * w / R)


def _split_cone_volume(d, gdim):
    Ro, L, r1, r2 = d["outer_radius"], d["length"], d["exit_radius"], d["entry_radius"]
    v = math.pi * Ro * Ro * L - math.pi * L * (r1 * r1 + r1 * r2 + r2 * r2) / 3
    n, w = int(d["segments"]), d["slot_width"]
    if gdim == 3 and n > 1:
        def slot_section(z):
            bore = r1 + (r2 - r1) * z / L
            return np.array([_slot_area(Ro, w) - _slot_area(b, w) for b in bore])
        v -= n * _gauss(slot_section, 0.0, L)
    return v


def _split_cone_check(d):
    Ro = d["outer_radius"]
    out = [(k, f"the bore ({d[k]:g} m) must be smaller than outer_radius ({Ro:g} m)")
           for k in ("exit_radius", "entry_radius") if d[k] >= Ro]
    n, w = int(d["segments"]), d["slot_width"]
    if n > 1 and n * w >= 2 * math.pi * min(d["exit_radius"], d["entry_radius"]):
        out.append(("slot_width", f"{n} slots of {w:g} m do not fit round the bore"))
    return out


def _clamp_ring_profile(d):
    return _tube_profile({"inner_radius": d["inner_radius"], "outer_radius": d["inner_radius"] + d["thickness"],
                          "length": d["length"]})


def _cone_plug_profile(d):
    rb, rt, L = d["bottom_radius"], d["top_radius"], d["length"]
    return Profile([Line((0.0, 0.0), (rb, 0.0), "bottom"), Line((rb, 0.0), (rt, L), "side"),
                    Line((rt, L), (0.0, L), "top"), Line((0.0, L), (0.0, 0.0), "axis")])


# ---------------------------------------------------------------------------- dashpot

def _circle(rc, zc, a, region):
    """A full circle as four quarter arcs (counter-clockwise), for a toroidal cavity."""
    pts = [(rc + a, zc), (rc, zc + a), (rc - a, zc), (rc, zc - a)]
    return [Arc(pts[k], pts[(k + 1) % 4], (rc, zc), region) for k in range(4)]


def _dashpot_profile(d):
    Ro, L, rb = d["outer_radius"], d["length"], d["bore_radius"]
    zc = d["cavity_height"] or 0.5 * L
    if rb:
        chain = [Line((rb, 0.0), (Ro, 0.0), "bottom"), Line((Ro, 0.0), (Ro, L), "side"),
                 Line((Ro, L), (rb, L), "top"), Line((rb, L), (rb, 0.0), "bore")]
    else:
        chain = [Line((0.0, 0.0), (Ro, 0.0), "bottom"), Line((Ro, 0.0), (Ro, L), "side"),
                 Line((Ro, L), (0.0, L), "top"), Line((0.0, L), (0.0, 0.0), "axis")]
    return Profile(chain, [_circle(d["cavity_centre_radius"], zc, d["cavity_radius"], "cavity")],
                   cut_region="orifice")


def _dashpot_volume(d, gdim):
    Ro, L, rb, a, Rc = d["outer_radius"], d["length"], d["bore_radius"], d["cavity_radius"], d["cavity_centre_radius"]
    zc = d["cavity_height"] or 0.5 * L
    v = math.pi * (Ro * Ro - rb * rb) * L - 2 * math.pi ** 2 * Rc * a * a        # Pappus for the torus
    ro = d["orifice_radius"]
    if gdim == 3 and ro:
        # the hole from the top face down to the cavity roof, over the disc of radius ro at r = Rc
        def depth(s, t):
            rho = np.hypot(Rc + s * np.cos(t), s * np.sin(t))
            return L - zc - np.sqrt(a * a - (rho - Rc) ** 2)
        v -= _gauss(lambda s: np.array([s_ * _gauss(lambda t: depth(s_, t), 0.0, 2 * math.pi) for s_ in s]), 0.0, ro)
    return v


def _dashpot_check(d):
    Ro, L, rb, a, Rc, ro = (d["outer_radius"], d["length"], d["bore_radius"], d["cavity_radius"],
                            d["cavity_centre_radius"], d["orifice_radius"])
    zc = d["cavity_height"] or 0.5 * L
    out = []
    if rb >= Ro:
        out.append(("bore_radius", f"the bore ({rb:g} m) must be smaller than outer_radius ({Ro:g} m)"))
    if Rc - a <= rb or Rc + a >= Ro:
        out.append(("cavity_centre_radius", f"the cavity (r from {Rc - a:g} to {Rc + a:g} m) must lie inside the "
                                            f"wall (r from {rb:g} to {Ro:g} m)"))
    if zc - a <= 0 or zc + a >= L:
        out.append(("cavity_height", f"the cavity (z from {zc - a:g} to {zc + a:g} m) must lie inside the length "
                                     f"{L:g} m"))
    if ro >= a:
        out.append(("orifice_radius", f"must be smaller than the cavity_radius {a:g} m, got {ro:g} m"))
    return out


# ---------------------------------------------------------------------------- projectile, carrier

def _meplat(d):
    """Radius of the flat tip: a sharp point cannot be meshed in 3D, real noses are blunted."""
    return d["meplat_radius"] or d["radius"] / 20


def ogive(d):
    """Tangent ogive of the projectile truncated at the meplat: (ogive radius rho, nose length)."""
    R = d["radius"]
    rho = d["crh"] * 2 * R
    return rho, math.sqrt(rho * rho - (_meplat(d) + rho - R) ** 2)


def _projectile_profile(d):
    R, L = d["radius"], d["length"]
    rho, ln = ogive(d)
    chain = [Line((0.0, 0.0), (_meplat(d), 0.0), "nose"), Arc((_meplat(d), 0.0), (R, ln), (R - rho, ln), "nose"),
             Line((R, ln), (R, L), "shank"), Line((R, L), (0.0, L), "base")]
    rc, lc = d["cavity_radius"], d["cavity_length"]
    if rc and lc:
        z1 = L - d["base_thickness"]
        z0 = z1 - lc
        # the cavity meets the axis: the outline runs up the axis around it
        chain += [Line((0.0, L), (0.0, z1), "axis"), Line((0.0, z1), (rc, z1), "cavity"),
                  Line((rc, z1), (rc, z0), "cavity"), Line((rc, z0), (0.0, z0), "cavity"),
                  Line((0.0, z0), (0.0, 0.0), "axis")]
    else:
        chain.append(Line((0.0, L), (0.0, 0.0), "axis"))
    return Profile(chain)


def _nose_volume(d):
    """pi * integral of r(z)^2 over the ogive, r = sqrt(rho^2 - s^2) - (rho - R), s = ln - z from 0
    at the shank to ln at the meplat."""
    R = d["radius"]
    rho, ln = ogive(d)
    k = rho - R
    circle_area = 0.5 * (ln * math.sqrt(rho * rho - ln * ln) + rho * rho * math.asin(ln / rho))
    return math.pi * ((rho * rho + k * k) * ln - ln ** 3 / 3 - 2 * k * circle_area)


def _projectile_volume(d, gdim):
    R, L = d["radius"], d["length"]
    _, ln = ogive(d)
    v = _nose_volume(d) + math.pi * R * R * (L - ln)
    if d["cavity_radius"] and d["cavity_length"]:
        v -= math.pi * d["cavity_radius"] ** 2 * d["cavity_length"]
    return v


def _projectile_check(d):
    R, L = d["radius"], d["length"]
    out = []
    if d["crh"] < 0.5:
        return [("crh", f"a tangent ogive needs crh >= 0.5 (0.5 is a hemisphere), got {d['crh']:g}")]
    if _meplat(d) >= R:
        return [("meplat_radius", f"must be smaller than the radius {R:g} m, got {_meplat(d):g} m")]
    rho, ln = ogive(d)
    if ln >= L:
        out.append(("length", f"the ogive nose alone is {ln:g} m long; length must exceed it, got {L:g} m"))
    rc, lc, tb = d["cavity_radius"], d["cavity_length"], d["base_thickness"]
    if bool(rc) != bool(lc):
        out.append(("cavity_radius", "a cavity needs both cavity_radius and cavity_length (or neither)"))
    elif rc:
        z0 = L - tb - lc
        outer = R if z0 >= ln else math.sqrt(rho * rho - (ln - z0) ** 2) - (rho - R) if z0 > 0 else _meplat(d)
        if rc >= R:
            out.append(("cavity_radius", f"must be smaller than the radius {R:g} m, got {rc:g} m"))
        elif z0 <= 0 or rc >= outer:
            out.append(("cavity_length", f"the cavity reaches z = {z0:g} m, where the nose is too thin to hold it; "
                                         "shorten it or raise base_thickness"))
        if tb <= 0:
            out.append(("base_thickness", "a cavity needs a base: base_thickness must be > 0"))
    return out


def _carrier_profile(d):
    R, L, rs, ds = d["radius"], d["length"], d["seat_radius"], d["seat_depth"]
    return Profile([Line((0.0, 0.0), (R, 0.0), "bottom"), Line((R, 0.0), (R, L), "side"),
                    Line((R, L), (rs, L), "top"), Line((rs, L), (rs, L - ds), "seat_wall"),
                    Line((rs, L - ds), (0.0, L - ds), "seat_floor"), Line((0.0, L - ds), (0.0, 0.0), "axis")])


def _carrier_check(d):
    out = []
    if d["seat_radius"] >= d["radius"]:
        out.append(("seat_radius", f"the seat ({d['seat_radius']:g} m) must be narrower than the radius "
                                   f"({d['radius']:g} m)"))
    if d["seat_depth"] >= d["length"]:
        out.append(("seat_depth", f"the seat ({d['seat_depth']:g} m) must be shallower than the length "
                                  f"({d['length']:g} m)"))
    return out


P = Param
# Files a body can come from instead of a part: a mesh with physical groups, or CAD geometry
# that gmsh meshes at the body's element size
MESH_FILES = (".msh",)
CAD_FILES = (".step", ".stp")

PARTS: dict[str, Part] = {p.name: p for p in [
    Part("cylinder", "solid cylinder, rod or striking mass; each end flat, chamfered (45 deg) or crowned "
                     "(a spherical face of the given sphere radius, which softens and shapes the contact)",
         (P("radius", "outer radius"), P("length", "overall length, crowns included"),
          P("bottom_chamfer", "45 deg chamfer size at z = 0", 0.0, minimum="nonnegative"),
          P("top_chamfer", "45 deg chamfer size at z = length", 0.0, minimum="nonnegative"),
          P("bottom_crown", "sphere radius of a crowned bottom face (0: flat)", 0.0, minimum="nonnegative"),
          P("top_crown", "sphere radius of a crowned top face (0: flat)", 0.0, minimum="nonnegative")),
         _cylinder_profile, _cylinder_volume, _cylinder_check),
    Part("tube", "hollow cylinder", (P("outer_radius", "outer radius"), P("inner_radius", "bore radius"),
                                     P("length", "length")),
         _tube_profile, lambda d, g: math.pi * (d["outer_radius"] ** 2 - d["inner_radius"] ** 2) * d["length"],
         _tube_check),
    Part("stepped_cylinder", "cylinder of several diameters, steps listed from the bottom",
         (P("radii", "radius of each step", kind="lengths"), P("lengths", "length of each step", kind="lengths")),
         _stepped_profile, lambda d, g: sum(math.pi * r * r * h for r, h in zip(d["radii"], d["lengths"])),
         _stepped_check),
    Part("plate", "thick circular plate (a rectangular plate is shape = 'box' in 3D)",
         (P("radius", "radius"), P("thickness", "thickness")),
         _plate_profile, lambda d, g: math.pi * d["radius"] ** 2 * d["thickness"]),
    Part("sphere", "sphere, bottom pole at the body's position (its centre one radius above)",
         (P("radius", "radius"),
          P("pole_element_size", "element size at the poles, axisymmetric (0: element_size)", 0.0,
            minimum="nonnegative")),
         _sphere_profile, lambda d, g: 4.0 / 3.0 * math.pi * d["radius"] ** 3),
    Part("split_cone", "pulse-shaping fixture: a cylinder whose bore narrows from entry (top) to exit (bottom), "
                       "cut by axial slots into segments in 3D",
         (P("outer_radius", "outer radius"), P("length", "length"), P("entry_radius", "bore radius at the top"),
          P("exit_radius", "bore radius at the bottom"), P("segments", "number of segments (3D; a hoop law in axisymmetry)", 4, "count"),
          P("slot_width", "width of the axial slots", 0.001)),
         _split_cone_profile, _split_cone_volume, _split_cone_check, "slots", "slots", ("slots",),
         lambda d, g: [f"slots in axisymmetry as a slotted-ring hoop law: the {d['segments']:g} segments carry no "
                       f"hoop stress until their slots ({d['segments']:g} x {d['slot_width'] * 1e3:.3g} mm) close, "
                       "then bear as one ring in hoop compression; a segment's own bending as an arch is not "
                       "there (run 3d for it)"] if g == 2 and d["segments"] > 1 else []),
    Part("clamp_ring", "ring shrunk onto a body (fits = its name) with a radial interference that sets the preload",
         (P("thickness", "radial wall thickness"), P("length", "length"),
          P("interference", "radial interference with the body it fits", 0.0, minimum="nonnegative")),
         _clamp_ring_profile,
         lambda d, g: math.pi * ((d["inner_radius"] + d["thickness"]) ** 2 - d["inner_radius"] ** 2) * d["length"],
         approximations=lambda d, g: [f"starts overlapping the body it fits by the interference "
                                      f"{d['interference'] * 1e3:.3g} mm; a contact with an interference time "
                                      f"pushes it out to the preload (without one the overlap is the contact's zero)"]
         if d["interference"] > 0 else []),
    Part("cone_plug", "tapered plug (or a test article's tapered adapter) that a split cone grips: a frustum "
                      "whose side has the cone's half-angle when atan((top_radius - bottom_radius) / length) "
                      "matches it",
         (P("bottom_radius", "radius at z = 0"), P("top_radius", "radius at z = length"), P("length", "length")),
         _cone_plug_profile,
         lambda d, g: math.pi * d["length"] * (d["bottom_radius"] ** 2 + d["bottom_radius"] * d["top_radius"]
                                               + d["top_radius"] ** 2) / 3),
    Part("dashpot", "fluid dashpot fixture: a cylinder with a toroidal cavity (circular section) and, in 3D, an "
                    "orifice from the cavity to the top face",
         (P("outer_radius", "outer radius"), P("length", "length"),
          P("bore_radius", "central bore (0: solid)", 0.0, minimum="nonnegative"),
          P("cavity_radius", "radius of the cavity's circular section"),
          P("cavity_centre_radius", "radius at which the cavity's section is centred"),
          P("cavity_height", "height of the cavity's centre (0: mid-length)", 0.0, minimum="nonnegative"),
          P("orifice_radius", "radius of the orifice (3D; 0: none)", 0.0, minimum="nonnegative")),
         _dashpot_profile, _dashpot_volume, _dashpot_check, "orifice", "orifice", ("orifice",),
         lambda d, g: ["no orifice in axisymmetry (a hole off the axis is not axisymmetric)"]
         if g == 2 and d["orifice_radius"] > 0 else []),
    Part("projectile", "penetrator: tangent-ogive nose of crh calibre-radius-head, blunted by a small flat "
                       "(meplat) at z = 0, shank, flat base, "
                       "optional internal cavity below the base",
         (P("radius", "shank radius (half the calibre)"), P("length", "overall length"),
          P("crh", "ogive radius over calibre", 3.0, "number"),
          P("meplat_radius", "radius of the flat tip (0: radius / 20)", 0.0, minimum="nonnegative"),
          P("cavity_radius", "radius of the internal cavity (0: solid)", 0.0, minimum="nonnegative"),
          P("cavity_length", "length of the cavity", 0.0, minimum="nonnegative"),
          P("base_thickness", "material between the cavity and the base", 0.0, minimum="nonnegative")),
         _projectile_profile, _projectile_volume, _projectile_check,
         approximations=lambda d, g: [f"ogive nose blunted by a flat tip (meplat) of radius {_meplat(d) * 1e3:.3g} mm"]),
    Part("carrier", "striking mass, anvil or test-article carrier: a cylinder with a counterbored seat in its top",
         (P("radius", "radius"), P("length", "length"), P("seat_radius", "seat radius"),
          P("seat_depth", "seat depth")),
         _carrier_profile, lambda d, g: math.pi * (d["radius"] ** 2 * d["length"] - d["seat_radius"] ** 2
                                                   * d["seat_depth"]),
         _carrier_check),
]}


def solid_ogive(radius: float, crh: float, meplat_radius: float, length: float = 0.0) -> dict:
    """The dimensions of a solid (no cavity) ``projectile`` part [m]."""
    return {"radius": radius, "length": length, "crh": crh, "meplat_radius": meplat_radius,
            "cavity_radius": 0.0, "cavity_length": 0.0, "base_thickness": 0.0}


def solid_ogive_length(mass: float, density: float, radius: float, crh: float, meplat_radius: float) -> float:
    """The length [m] at which a solid ogive projectile of ``radius`` weighs ``mass`` [kg] at ``density``:
    its closed-form volume solved for the length (longer than its nose)."""
    from scipy.optimize import brentq
    _, nose = ogive(solid_ogive(radius, crh, meplat_radius))
    return brentq(lambda L: PARTS["projectile"].volume(solid_ogive(radius, crh, meplat_radius, L), 3) * density
                  - mass, 1.01 * nose, 1e4 * radius)

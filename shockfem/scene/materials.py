"""The [materials] tables: elastic constants, J2 plasticity with its hardening and rate law, a
crushable foam, or a library material by name."""
from __future__ import annotations

from .checker import Checker
from .specs import Crush, Material, Plasticity, RATE_FORMS, Rubber

J2_FIELDS = ("yield_stress", "tangent_modulus", "isotropic_fraction", "hardening_curve", "rate_form")
FOAM_FIELDS = ("crush_curve", "tension_cutoff")
RUBBER_FIELDS = ("hyperelastic", "c10", "c01")
HYPERELASTIC = ("neo-hookean", "mooney-rivlin")
RATE_FIELDS = ("cowper_symonds_D", "cowper_symonds_q")
MATERIAL_FIELDS = (("library", "density", "youngs_modulus", "poisson_ratio") + J2_FIELDS + FOAM_FIELDS + RATE_FIELDS
                   + RUBBER_FIELDS)


def read_materials(ck: Checker, raw: dict) -> dict[str, Material]:
    """Every ``[materials.NAME]`` table, by name."""
    materials: dict[str, Material] = {}
    for mname, m in ck.table(raw, "materials", "materials").items():
        path = f"materials.{mname}"
        if not isinstance(m, dict):
            ck.fail(path, "must be a table")
            continue
        materials[mname] = read_material(ck, mname, m, path)
    return materials


def read_material(ck: Checker, name: str, m: dict, path: str) -> Material:
    """A material: elastic, or J2-plastic with a bilinear (MAT_003) or tabulated (MAT_024) hardening
    and optional Cowper-Symonds rate effects; ``library`` fills in fields the table does not give."""
    from .library import LIBRARY
    ck.unknown(m, MATERIAL_FIELDS, path)
    source = ""
    if "library" in m:
        entry = LIBRARY.get(m["library"]) if isinstance(m["library"], str) else None
        if entry is None:
            ck.fail(f"{path}.library", f"unknown library material {m['library']!r} (known: {', '.join(LIBRARY)})")
        else:
            source = f"library {m['library']!r}: {entry['source']}"
            # the scene's fields win; its bilinear fields replace a library curve and vice versa
            bilinear = ("yield_stress", "tangent_modulus", "isotropic_fraction")
            dropped = (("hardening_curve",) if any(k in m for k in bilinear)
                       else bilinear if "hardening_curve" in m else ())
            m = {**{k: v for k, v in entry.items() if k != "source" and k not in dropped}, **m}
    foam = any(k in m for k in FOAM_FIELDS)
    if any(k in m for k in RUBBER_FIELDS):
        return _read_rubber(ck, name, m, path, source)
    rho = ck.quantity(m, "density", path, "density", positive=True)
    E = ck.quantity(m, "youngs_modulus", path, "pressure", positive=True)
    # a foam crushes without lateral expansion: 0 is its usual Poisson's ratio (MAT_063's PR)
    nu = _poisson_ratio(ck, m, path, 0.0 if foam else 0.3)
    if foam:
        for k in J2_FIELDS:
            if k in m:
                ck.fail(f"{path}.{k}", "is a J2 plasticity field; a crushable foam (crush_curve) takes none: "
                                       "remove it, or remove crush_curve and tension_cutoff for a metal")
        return Material(name, rho, E, nu, None, source, crush=_read_crush(ck, m, path, E))
    if not any(k in m for k in J2_FIELDS + RATE_FIELDS):
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
    D, q = _rate_constants(ck, m, path)
    rate_form = ck.choice(m, "rate_form", path, RATE_FORMS, default=RATE_FORMS[0])
    if D:
        model += (f", Cowper-Symonds D = {D:g} /s, q = {q:g} on the "
                  f"{'plastic (VP=1)' if rate_form == RATE_FORMS[0] else 'total (VP=0)'} strain rate")
    return Material(name, rho, E, nu, Plasticity(curve, kinematic, D, q, rate_form, model), source)


def _poisson_ratio(ck: Checker, m: dict, path: str, default: float) -> float:
    """Poisson's ratio in (-1, 0.5); ``default`` when absent (and after a problem, to read on)."""
    nu = ck.quantity(m, "poisson_ratio", path, "dimensionless", default=default)
    if not -1.0 < nu < 0.5:
        ck.fail(f"{path}.poisson_ratio", f"must be in (-1, 0.5), got {nu}")
        return default
    return nu


def _rate_constants(ck: Checker, m: dict, path: str) -> tuple[float, float]:
    """Cowper-Symonds D [1/s] and q [-] (D = 0: no rate effect)."""
    D = ck.quantity(m, "cowper_symonds_D", path, "strain_rate", default=0.0, positive="cowper_symonds_D" in m)
    q = ck.quantity(m, "cowper_symonds_q", path, "dimensionless", default=5.0 if D else 1.0, positive=True)
    if ("cowper_symonds_q" in m) != ("cowper_symonds_D" in m):
        ck.fail(f"{path}.{'cowper_symonds_D' if 'cowper_symonds_q' in m else 'cowper_symonds_q'}",
                "missing: Cowper-Symonds rate effects need both D and q")
    return D, q


def _read_crush(ck: Checker, m: dict, path: str, E: float) -> Crush:
    """A crushable foam (MAT_063-like, ``materials/foam.py``): crush stress against volumetric strain,
    tension cutoff, optional rate factor on the volumetric compression rate."""
    if "crush_curve" not in m:
        ck.fail(f"{path}.crush_curve", "missing: a crushable foam needs its crush stress against volumetric "
                                       "strain, e.g. [[0, \"1 MPa\"], [0.7, \"1.2 MPa\"], [0.85, \"20 MPa\"]]")
        curve = [(0.0, 1.0)]
    else:
        curve = ck.pairs(m, "crush_curve", path, ("volumetric strain", "stress"), ("dimensionless", "pressure"))
    if curve and curve[0][0] != 0.0:
        ck.fail(f"{path}.crush_curve", f"must start at volumetric strain 0 (the initial crush stress), got "
                                       f"{curve[0][0]}")
    if any(not 0.0 <= x < 1.0 for x, _ in curve):
        ck.fail(f"{path}.crush_curve", "volumetric strains 1 - V/V0 must be in [0, 1)")
    if any(y <= 0.0 for _, y in curve):
        ck.fail(f"{path}.crush_curve", "crush stresses must be > 0")
    slopes = [(y1 - y0) / (x1 - x0) for (x0, y0), (x1, y1) in zip(curve, curve[1:]) if x1 > x0]
    if slopes and max(slopes) > E:
        ck.fail(f"{path}.youngs_modulus", f"must be at least the crush curve's steepest slope, "
                                          f"{max(slopes) / 1e6:.4g} MPa (the stress would lag behind the curve "
                                          f"there), got {E / 1e6:.4g} MPa: raise it (a densified foam unloads that "
                                          f"stiffly) or make the curve less steep")
    tension = ck.quantity(m, "tension_cutoff", path, "pressure", default=0.0, nonnegative=True)
    D, q = _rate_constants(ck, m, path)
    curve = tuple(curve) or ((0.0, 1.0),)
    model = (f"crushable foam, crush stress {curve[0][1] / 1e6:.4g} MPa at first, {len(curve)}-point curve of "
             f"volumetric strain, tension cutoff {tension / 1e6:.4g} MPa (MAT_063-like)")
    if D:
        model += f", Cowper-Symonds D = {D:g} /s, q = {q:g} on the volumetric strain rate"
    return Crush(curve, tension, D, q, model)


def _read_rubber(ck: Checker, name: str, m: dict, path: str, source: str) -> Material:
    """A hyperelastic rubber (MAT_027-like, ``materials/rubber.py``): Neo-Hookean from youngs_modulus and
    poisson_ratio, or Mooney-Rivlin from c10 and c01 (the modulus is then 4 (c10 + c01) (1 + nu))."""
    kind = ck.choice(m, "hyperelastic", path, HYPERELASTIC, default="mooney-rivlin" if "c10" in m else "neo-hookean")
    for k in J2_FIELDS + FOAM_FIELDS + RATE_FIELDS:
        if k in m:
            ck.fail(f"{path}.{k}", "is not a field of a hyperelastic rubber: remove it, or remove hyperelastic, "
                                   "c10 and c01")
    rho = ck.quantity(m, "density", path, "density", positive=True)
    # a rubber is nearly incompressible; LS-DYNA's MAT_027 asks for 0.49 or more
    nu = _poisson_ratio(ck, m, path, 0.495)
    if kind == "neo-hookean":
        for k in ("c10", "c01"):
            if k in m:
                ck.fail(f"{path}.{k}", "is a Mooney-Rivlin constant: a Neo-Hookean rubber takes youngs_modulus; "
                                       "set hyperelastic = \"mooney-rivlin\" to give c10 and c01")
        E = ck.quantity(m, "youngs_modulus", path, "pressure", positive=True)
        c01 = 0.0
        model = (f"Neo-Hookean rubber, shear modulus {E / (2 * (1 + nu)) / 1e6:.4g} MPa, Poisson's ratio {nu:g} "
                 f"(MAT_027-like with C01 = 0)")
    else:
        if "youngs_modulus" in m:
            ck.fail(f"{path}.youngs_modulus", "a Mooney-Rivlin rubber takes c10 and c01 (its modulus is "
                                              "4 (c10 + c01) (1 + nu)); remove youngs_modulus")
        c10 = ck.quantity(m, "c10", path, "pressure", positive=True)
        c01 = ck.quantity(m, "c01", path, "pressure", default=0.0, nonnegative=True)
        E = 4.0 * (c10 + c01) * (1.0 + nu)
        model = (f"Mooney-Rivlin rubber, C10 = {c10 / 1e6:.4g} MPa, C01 = {c01 / 1e6:.4g} MPa, Poisson's ratio "
                 f"{nu:g} (MAT_027-like)")
    return Material(name, rho, E, nu, None, source, rubber=Rubber(c01, model))

"""LS-DYNA materials as scene material tables, every value with its unit (``docs/scenes.md``, materials).

| LS-DYNA | shockfem |
|---|---|
| *MAT_ELASTIC (001): RO E PR | density, youngs_modulus, poisson_ratio |
| *MAT_PLASTIC_KINEMATIC (003): SIGY ETAN BETA SRC SRP VP | yield_stress, tangent_modulus, isotropic_fraction, cowper_symonds_D / _q, rate_form |
| *MAT_PIECEWISE_LINEAR_PLASTICITY (024): LCSS (a curve, or a table of one curve) or EPS/ES, or SIGY ETAN; C P VP | hardening_curve (or the bilinear fields), cowper_symonds_D / _q, rate_form |
| *MAT_RIGID (020): RO E PR | the body rigid; its material's density, E and nu |
| *MAT_CRUSHABLE_FOAM (063): LCID TSC | crush_curve, tension_cutoff |
"""
from __future__ import annotations

import numpy as np

from .cards import DeckError
from .unit_sets import UnitSet


def material_table(mat, curves: dict, tables: dict, u: UnitSet) -> tuple[dict, list[str]]:
    """The scene table of a deck material and the notes of what differs; ``DeckError`` where it cannot map."""
    v, kw = mat.values, mat.keyword
    for key in ("RO", "E"):
        if not v.get(key):
            raise DeckError([kw.error(0, f"{key} is blank or 0: material {v['MID']} needs a density and a "
                                         "Young's modulus")])
    table = {"density": u.quantity(v["RO"], "density"), "youngs_modulus": u.quantity(v["E"], "pressure"),
             "poisson_ratio": v.get("PR") or 0.0}
    notes = []
    if mat.kind == "plastic_kinematic":
        notes += _plastic_kinematic(v, table, u)
    elif mat.kind == "piecewise_linear":
        notes += _piecewise_linear(mat, curves, tables, table, u)
    elif mat.kind == "crushable_foam":
        notes += _crushable_foam(mat, curves, table, u)
    elif mat.kind == "rigid":
        notes.append("*MAT_RIGID: its parts move as rigid bodies (E and PR only set their contact stiffness)")
        if v.get("CMO") and v["CMO"] != 1:
            raise DeckError([kw.error(1, f"CMO {v['CMO']}: constraints of a rigid material in a local system "
                                         "are not mapped; give them in global axes (CMO 1) or hold the body with "
                                         "*BOUNDARY_PRESCRIBED_MOTION_RIGID")])
    if mat.kind == "elastic" and (v.get("DA") or v.get("DB")):
        notes.append("*MAT_ELASTIC DA/DB (axial and bending damping of beams) ignored: no beams here")
    return table, notes


def _rate(v: dict, table: dict, D: float | None, q: float | None, u: UnitSet) -> list[str]:
    """Cowper-Symonds constants and the strain rate they see: VP = 1 the plastic strain rate
    (viscoplastic), otherwise (VP = 0, LS-DYNA's default) the total strain rate scaling the yield."""
    if not D:
        return []
    table["cowper_symonds_D"] = u.quantity(D, "strain_rate")
    table["cowper_symonds_q"] = q or 1.0
    table["rate_form"] = "plastic-strain-rate" if v.get("VP") == 1 else "total-strain-rate"
    return ["VP = -1 (deviatoric strain rate) taken as the total strain rate"] if v.get("VP") == -1 else []


def _plastic_kinematic(v: dict, table: dict, u: UnitSet) -> list[str]:
    table["yield_stress"] = u.quantity(v["SIGY"] or 0.0, "pressure")
    table["tangent_modulus"] = u.quantity(v["ETAN"] or 0.0, "pressure")
    table["isotropic_fraction"] = v["BETA"] or 0.0
    notes = _rate(v, table, v.get("SRC"), v.get("SRP"), u)
    if v.get("FS"):
        notes.append(f"failure strain FS = {v['FS']:g} ignored: shockfem does not erode elements")
    return notes


def _piecewise_linear(mat, curves: dict, tables: dict, table: dict, u: UnitSet) -> list[str]:
    v, kw = mat.values, mat.keyword
    notes = _rate(v, table, v.get("C"), v.get("P"), u)
    if v.get("LCSR"):
        raise DeckError([kw.error(1, f"LCSR {v['LCSR']}: a yield-scaling curve of strain rate is not mapped; "
                                     "give Cowper-Symonds C and P")])
    lcss = v.get("LCSS") or 0
    eps = [v.get(f"EPS{k}") for k in range(1, 9)]
    es = [v.get(f"ES{k}") for k in range(1, 9)]
    if lcss:
        x, y = _hardening_source(kw, lcss, curves, tables)
    elif any(e is not None for e in es):
        pairs = [(a or 0.0, b) for a, b in zip(eps, es) if b is not None]
        x, y = np.array(pairs).T
    else:
        table["yield_stress"] = u.quantity(v["SIGY"] or 0.0, "pressure")
        table["tangent_modulus"] = u.quantity(v["ETAN"] or 0.0, "pressure")
        return notes
    if x[0] != 0.0:
        raise DeckError([kw.error(1, f"the hardening curve starts at plastic strain {x[0]:g}; shockfem's starts "
                                     "at 0 (the initial yield)")])
    table["hardening_curve"] = [[float(a), u.quantity(b, "pressure")] for a, b in zip(x, y)]
    if v.get("FAIL"):
        notes.append(f"failure strain FAIL = {v['FAIL']:g} ignored: shockfem does not erode elements")
    return notes


def _hardening_source(kw, lcss: int, curves: dict, tables: dict):
    """LCSS as a curve of yield stress against plastic strain, or a table of one strain rate's curve."""
    if lcss in tables:
        values, ids, _ = tables[lcss]
        if len(ids) != 1:
            raise DeckError([kw.error(1, f"LCSS {lcss} is a *DEFINE_TABLE of {len(ids)} strain rates: shockfem "
                                         "has no tabulated rate dependence; give one curve and Cowper-Symonds "
                                         "C and P")])
        lcss = ids[0]
    if lcss not in curves:
        raise DeckError([kw.error(1, f"LCSS {lcss} is not defined by any *DEFINE_CURVE or *DEFINE_TABLE")])
    return curves[lcss].x, curves[lcss].y


def _crushable_foam(mat, curves: dict, table: dict, u: UnitSet) -> list[str]:
    v, kw = mat.values, mat.keyword
    if v.get("LCID") not in curves:
        raise DeckError([kw.error(0, f"LCID {v.get('LCID')} is not defined by any *DEFINE_CURVE")])
    c = curves[v["LCID"]]
    table["crush_curve"] = [[float(a), u.quantity(b, "pressure")] for a, b in zip(c.x, c.y)]
    table["tension_cutoff"] = u.quantity(v.get("TSC") or 0.0, "pressure")
    table["poisson_ratio"] = v.get("PR") or 0.0
    return [f"DAMP = {v['DAMP']:g} (rate-sensitive foam damping) ignored"] if v.get("DAMP") else []

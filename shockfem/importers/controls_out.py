"""A deck's controls and database requests as the scene's [scene] and [outputs] fields.

| LS-DYNA | shockfem |
|---|---|
| *CONTROL_TERMINATION ENDTIM | scene.end_time |
| *CONTROL_TIMESTEP TSSFAC, DT2MS < 0 | scene.safety_factor, scene.mass_scaling_step = TSSFAC abs(DT2MS) |
| *CONTROL_HOURGLASS IHQ QH | scene.hourglass (IHQ 1-3 viscous, 4-5 stiffness), hourglass_coefficient |
| *CONTROL_BULK_VISCOSITY Q1 Q2 | scene.bulk_viscosity_quadratic, _linear |
| *DATABASE_BINARY_D3PLOT DT | outputs.field_interval |
| *DATABASE_GLSTAT / MATSUM / RCFORC / NODOUT DT | outputs.history_interval (the smallest) |
"""
from __future__ import annotations

# LS-DYNA's defaults where the deck says nothing (Keyword Manual, *CONTROL_HOURGLASS, *CONTROL_TIMESTEP)
LSDYNA_HOURGLASS = (1, 0.1)
LSDYNA_TSSFAC = 0.9
HISTORY_DATABASES = ("DATABASE_GLSTAT", "DATABASE_MATSUM", "DATABASE_RCFORC", "DATABASE_NODOUT")


def controls(mapper) -> float | None:
    """Fill [scene] and [outputs]; returns the end time in deck units (None when the deck has none)."""
    s, u, c = mapper.scene["scene"], mapper.u, mapper.m.controls
    term, term_kw = c.get("CONTROL_TERMINATION", ({}, None))
    end = term.get("ENDTIM")
    if term_kw is None and "CONTROL_TERMINATION" not in mapper.m.unread:     # (a refused card is said already)
        mapper.problems.append(f"{mapper.source}: no *CONTROL_TERMINATION: the run needs an end time (ENDTIM)")
    elif term_kw is not None and not end:
        mapper.problems.append(term_kw.error(0, "ENDTIM is blank or 0: the run needs an end time"))
    elif end:
        s["end_time"] = u.quantity(end, "time")
        mapper.origin("scene.end_time", term_kw)
    ts, kw = c.get("CONTROL_TIMESTEP", ({}, None))
    for name in ("safety_factor", "mass_scaling_step"):
        mapper.origin(f"scene.{name}", kw)
    tssfac = ts.get("TSSFAC") or LSDYNA_TSSFAC
    s["safety_factor"] = tssfac
    dt2ms = ts.get("DT2MS") or 0.0
    if dt2ms < 0:
        s["mass_scaling_step"] = u.quantity(tssfac * abs(dt2ms), "time")
        mapper.notes.append("DT2MS < 0: mass scaling of the elements whose step is below TSSFAC |DT2MS| "
                            "(scene.mass_scaling_step); the run refuses it past 5% of a body's mass")
    elif dt2ms > 0:
        mapper.problems.append(kw.error(0, "DT2MS > 0 (every element scaled to one step) is not mapped; give it "
                                           "negative (only the elements below the step are scaled)"))
    if ts.get("TSLIMT"):
        mapper.notes.append("TSLIMT ignored: shockfem's mass scaling is DT2MS's")
    hg, hg_kw = c.get("CONTROL_HOURGLASS", ({}, None))
    for name in ("hourglass", "hourglass_coefficient"):
        mapper.origin(f"scene.{name}", hg_kw)
    ihq, qh = hg.get("IHQ") or LSDYNA_HOURGLASS[0], hg.get("QH") or LSDYNA_HOURGLASS[1]
    if not hg:
        mapper.notes.append("no *CONTROL_HOURGLASS: LS-DYNA's default, viscous (IHQ 1) with QH 0.1")
    s["hourglass"] = "viscous" if ihq in (1, 2, 3) else "stiffness"
    if ihq not in (1, 2, 3, 4, 5):
        mapper.notes.append(f"IHQ {ihq} taken as Flanagan-Belytschko stiffness hourglass control (IHQ 4)")
    s["hourglass_coefficient"] = qh
    bv, bv_kw = c.get("CONTROL_BULK_VISCOSITY", ({}, None))
    for name in ("bulk_viscosity_quadratic", "bulk_viscosity_linear"):
        mapper.origin(f"scene.{name}", bv_kw)
    if bv.get("Q1") is not None:
        s["bulk_viscosity_quadratic"] = bv["Q1"]
    if bv.get("Q2") is not None:
        s["bulk_viscosity_linear"] = bv["Q2"]
    outputs(mapper)
    return end


def outputs(mapper):
    o = {}
    db = mapper.m.outputs
    if db.get("DATABASE_BINARY_D3PLOT"):
        o["field_interval"] = mapper.u.quantity(db["DATABASE_BINARY_D3PLOT"], "time")
        mapper.origin("outputs.field_interval", mapper.m.output_keywords["DATABASE_BINARY_D3PLOT"])
    histories = [db[k] for k in HISTORY_DATABASES if db.get(k)]
    if histories:
        o["history_interval"] = mapper.u.quantity(min(histories), "time")
        smallest = min((k for k in HISTORY_DATABASES if db.get(k)), key=lambda k: db[k])
        mapper.origin("outputs.history_interval", mapper.m.output_keywords[smallest])
        mapper.notes.append(f"{', '.join(k.removeprefix('DATABASE_') for k in HISTORY_DATABASES if db.get(k))}: "
                            "shockfem writes every history (energies, body motions, contact forces) at one "
                            "interval, the smallest asked for")
    if o:
        mapper.scene["outputs"] = o

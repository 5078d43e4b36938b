"""The fixture study's section-4 dashpot designed at a wider largest opening n_max than the orifice law's
checked range (``fluid.orifice.VALID_AREA_RATIO``): the law's extrapolation, which the design's checks flag.

    python scripts/fixture-nmax.py 0.8 --liquid oil
    python scripts/fixture-nmax.py 0.9 --liquid water --seated
    python scripts/fixture-nmax.py 0.8 --liquid oil --pin-iterations 0     # the quasi-steady pin, not cut
    python scripts/fixture-nmax.py 0.5625 --liquid water --confirm results/confirm   # and section 4.7's runs
    python scripts/fixture-nmax.py 0.5625 --liquid oil --confirm results/closest --speed-tail-slap   # and 5, 6

The study's own objects (its pulse, article, liquids and its default size's designer settings) go to
``programmer.column_design.design_on_column`` exactly as section 4 passes them, with ``largest_ratio``
the one change (and ``--pin-iterations``, the runs of the pin's cut on the column, the designer's own by
default; 0 keeps the quasi-steady pin).  ``--seated`` designs the dashpot with section 3's nose seat
(``study.fixture.nose_seat.nose_seat_design``) riding with the article.  One JSON line a design: bore, striker, the column's
pulse and peak pressure, the housing's wall ratio and mass, the article's base-stress check
(``programmer.article_base``), the verdict, and the pin's cut on the column
(its peak overshoot by iteration, the iterate kept, why it stopped) and the striker's fixed point
(its trials, converged or not, why its design was kept), and the column run's energy balance (the
kinetic energy in against the bodies', the column's stored, the jet's and the dissipated: ``energy_balance``)
and its checks (the rebound off the striker among them); the designer's progress on stderr.
``--grid 100,200,400`` runs the design found on the column at those cells, one more JSON line
(``grid``: each grid's pulse, band excess, peak pressure, rebound and wall), the design grid's error by
cells. ``--speed-tail-slap`` (with ``--confirm``) goes on as the study does after 4.7: its sections 5 (speed
against error) and 6 (tail-slap initiation) on that design (``study.fixture.speed``,
``study.fixture.tail_slap``), into the same report.
"""
from __future__ import annotations

import argparse
import json
import sys
import time

from shockfem.programmer.column_design import PIN_ROUNDS, design_on_column
from shockfem.programmer.liquids import LIQUIDS
from shockfem.programmer.pin_cut import ITERATIONS as PIN_ITERATIONS
from shockfem.study.fixture.common import ARTICLE_LB, SIZES
from shockfem.study.fixture.dashpot import SPEC_PULSE
from shockfem.study.fixture.design import study_article
from shockfem.study.fixture.nose_seat import nose_seat_design
from shockfem.units import G0, LB


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("largest_ratio", type=float, help="n_max, the widest the pin may open [-]")
    ap.add_argument("--liquid", choices=sorted(LIQUIDS), default="oil")
    ap.add_argument("--shape", default="rectangle", help="the pulse shape section 1 chooses")
    ap.add_argument("--seated", action="store_true", help="the dashpot with the nose seat")
    ap.add_argument("--confirm", metavar="OUT_DIR", help="and confirm the plain design in finite elements as "
                    "section 4.7 does (the column and the control volume), its report in OUT_DIR")
    ap.add_argument("--speed-tail-slap", action="store_true", help="with --confirm: and the study's sections 5 "
                    "and 6 on the confirmed design (the mesh study and the 3D yawed runs), into OUT_DIR's report")
    ap.add_argument("--pin-rounds", type=int, default=PIN_ROUNDS,
                    help="handle searches, each after the first on the last one's cut pin (1: the quasi-steady pin's) [-]")
    ap.add_argument("--pin-iterations", type=int, default=PIN_ITERATIONS,
                    help="column runs of the pin's cut on the column (0: the quasi-steady pin) [-]")
    ap.add_argument("--grid", metavar="CELLS", help="and run the design found on the column at these cells, "
                    "comma-separated (a grid study of the cut design)")
    a = ap.parse_args()
    if a.speed_tail_slap and not a.confirm:
        ap.error("--speed-tail-slap: sections 5 and 6 run on 4.7's confirmed design; add --confirm OUT_DIR")
    cfg = SIZES["default"]
    out = design_on_column(SPEC_PULSE[a.shape], ARTICLE_LB * LB, nose_seat_design()["mass"] if a.seated else 0.0,
                           LIQUIDS[a.liquid], evaluations=cfg["design_evaluations"],
                           search_cells=cfg["design_cells"], largest_ratio=a.largest_ratio,
                           pin_iterations=a.pin_iterations, pin_rounds=a.pin_rounds, article=study_article(),
                           echo=lambda line: print(line, file=sys.stderr, flush=True))
    d, col, w = out["design"], out["models"].get("column"), out["fixture"]
    flagged = [lim["name"] for lim in col["limits"] if not lim["holds"] and not lim["vetoes"]] if col else []
    print(json.dumps({
        "largest_ratio": a.largest_ratio, "liquid": a.liquid, "seated": a.seated, "pin_iterations": a.pin_iterations,
        "bore_mm": d["bore_radius"] * 1e3, "striker_kg": out["striker"]["mass"],
        "striker_speed_m_s": d["striker_speed"],
        "peak_g": col and col["peak"] / G0, "duration_ms": col and col["duration"] * 1e3,
        "velocity_change_m_s": col and col["velocity_change"], "band_passed": col and col["band_passed"],
        "worst_excess": col and col["worst_excess"], "peak_pressure_MPa": col and col["peak_pressure"] / 1e6,
        "wall_ratio": w and w["wall_ratio"], "housing_kg": w and w["housing"], "fixture_kg": w and w["fixture"],
        "flagged": flagged, "search_wall_s": out["search_wall"], "verdict": out["verdict"],
        "pin_cut_overshoots": [s["overshoot"] for s in d.get("pin_cut", {}).get("steps", [])],
        "pin_cut_kept": d.get("pin_cut", {}).get("best"), "pin_cut_stop": d.get("pin_cut", {}).get("stop"),
        "kept_overshoot": (d["pin_cut"]["steps"][d["pin_cut"]["best"]]["overshoot"]
                           if d.get("pin_cut", {}).get("best") is not None else None),
        "kept_held_overshoot": (d["pin_cut"]["steps"][d["pin_cut"]["best"]]["held_overshoot"]
                                if d.get("pin_cut", {}).get("best") is not None else None),
        "search_rounds": out["search_rounds"], "objective": out["objective"], "confirm_wall_s": out["confirm_wall"],
        "column_holds": col and col["holds"], "pin_holds": w and w["pin_holds"],
        "housing_holds": w and w["housing_holds"], "striker_carrying_kg": out["striker"]["carrying"],
        "wall_pressure_MPa": w and w["peak_pressure"] / 1e6, "dynamic_factor": w and w["dynamic_factor"],
        "liquid_kg": d["liquid_mass"], "column_m": d["column"],
        "lumped_peak_g": out["models"].get("lumped", {}).get("peak", float("nan")) / G0,
        "limits": col and col["limits"], "energy_balance": col and col["accounts"], "lumped_limits": out["models"].get("lumped", {}).get("limits"),
        "fixture": w, "jet": out["jet"], "striker": out["striker"], "handles": d["handles"],
        "pin_cut_steps": d.get("pin_cut", {}).get("steps"),
        "article_base": out["article_base"], "striker_fixed_point": out["striker_fixed_point"]}, default=float), flush=True)
    if a.grid:
        print(json.dumps({"grid": _grid(out, a, [int(n) for n in a.grid.split(",")])}, default=float), flush=True)
    if a.confirm:
        _confirm_in_finite_elements(out, a, cfg)


def _grid(out: dict, a, cells: list[int]) -> list[dict]:
    """The design found on the column at each of ``cells``, as ``column_design.confirm`` runs it."""
    from shockfem.programmer.column_dashpot import simulate_column
    from shockfem.programmer.dashpot_design import LUMPED_SAMPLES, dashpot_lumped
    from shockfem.programmer.dashpot_validity import rebound
    pulse, liquid, rows = SPEC_PULSE[a.shape], LIQUIDS[a.liquid], []
    for n in cells:
        started = time.perf_counter()
        run = simulate_column(dashpot_lumped(out["design"]), pulse.record_end(), LUMPED_SAMPLES, n, liquid.column())
        metrics, band = pulse.band(run.t, run.acceleration)
        rows.append({"cells": n, "peak_g": metrics.peak / G0, "duration_ms": metrics.duration * 1e3,
                     "velocity_change_m_s": metrics.velocity_change, "worst_excess": band.worst_excess,
                     "peak_pressure_MPa": float(max(run.pressure)) / 1e6,
                     "floor_pressure_MPa": float(max(run.floor_pressure)) / 1e6, "rebound": rebound(run),
                     "wall_s": time.perf_counter() - started})
    return rows


def _confirm_in_finite_elements(out: dict, a, cfg: dict):
    """Section 4.7's two finite-element runs of the plain design (``study.fixture.design``), and with
    ``a.speed_tail_slap`` the study's sections 5 and 6 on it, their report in ``a.confirm``."""
    from shockfem.study.fixture.common import Context
    from shockfem.study.fixture.dashpot import dashpot_scene
    from shockfem.study.fixture.design import Variant, _confirm
    from shockfem.study.report import Report
    from shockfem.study.fixture.speed import speed_against_error
    from shockfem.study.fixture.tail_slap import tail_slap_initiation
    if a.seated:
        raise SystemExit("--confirm: the plain dashpot only (the seated one needs section 3's seat run); drop --seated")
    started = time.perf_counter()
    rep = Report(a.confirm, "The dashpot's finite-element confirmation (section 4.7)"
                 + (" and sections 5 and 6 on it" if a.speed_tail_slap else ""))
    ctx = Context(cfg, a.confirm, print, a.shape)
    _confirm(rep, ctx, (Variant("dashpot", "the dashpot", None, "piston", dashpot_scene), a.liquid, out), False)
    if a.speed_tail_slap:                 # as the study goes on: ctx.chosen is 4.7's design and its column run
        speed_against_error(rep, ctx)
        tail_slap_initiation(rep, ctx)
    rep.finish(started)


if __name__ == "__main__":
    main()

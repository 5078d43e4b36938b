"""The fixture study's section-4 dashpot designed at a wider largest opening n_max than the orifice law's
checked range (``fluid.orifice.VALID_AREA_RATIO``): the law's extrapolation, which the design's checks flag.

    python scripts/fixture-nmax.py 0.8 --liquid oil
    python scripts/fixture-nmax.py 0.9 --liquid water --seated
    python scripts/fixture-nmax.py 0.8 --liquid oil --pin-iterations 0     # the quasi-steady pin, not cut

The study's own objects (its pulse, article, liquids and its default size's designer settings) go to
``programmer.column_design.design_on_column`` exactly as section 4 passes them, with ``largest_ratio``
the one change (and ``--pin-iterations``, the runs of the pin's cut on the column, the designer's own by
default; 0 keeps the quasi-steady pin).  ``--seated`` designs the dashpot with section 3's nose seat
(``study.fixture.nose_seat.nose_seat_design``) riding with the article.  One JSON line a design: bore, striker, the column's
pulse and peak pressure, the housing's wall ratio and mass, the verdict, and the pin's cut on the column
(its peak overshoot by iteration, the iterate kept, why it stopped).
"""
from __future__ import annotations

import argparse
import json

from shockfem.programmer.column_design import design_on_column
from shockfem.programmer.liquids import LIQUIDS
from shockfem.programmer.pin_cut import ITERATIONS as PIN_ITERATIONS
from shockfem.study.fixture.common import ARTICLE_LB, SIZES
from shockfem.study.fixture.dashpot import SPEC_PULSE
from shockfem.study.fixture.nose_seat import nose_seat_design
from shockfem.units import G0, LB


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("largest_ratio", type=float, help="n_max, the widest the pin may open [-]")
    ap.add_argument("--liquid", choices=sorted(LIQUIDS), default="oil")
    ap.add_argument("--shape", default="rectangle", help="the pulse shape section 1 chooses")
    ap.add_argument("--seated", action="store_true", help="the dashpot with the nose seat")
    ap.add_argument("--pin-iterations", type=int, default=PIN_ITERATIONS,
                    help="column runs of the pin's cut on the column (0: the quasi-steady pin) [-]")
    a = ap.parse_args()
    cfg = SIZES["default"]
    out = design_on_column(SPEC_PULSE[a.shape], ARTICLE_LB * LB, nose_seat_design()["mass"] if a.seated else 0.0,
                           LIQUIDS[a.liquid], evaluations=cfg["design_evaluations"],
                           search_cells=cfg["design_cells"], largest_ratio=a.largest_ratio,
                           pin_iterations=a.pin_iterations)
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
        "pin_cut_kept": d.get("pin_cut", {}).get("best"), "pin_cut_stop": d.get("pin_cut", {}).get("stop")}))


if __name__ == "__main__":
    main()

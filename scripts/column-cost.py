"""What the liquid column costs a fixture run against the control volume: the fixture study's dashpot scene
(``study/fixture/dashpot.py``'s ``dashpot_scene`` on its closed-form design, at the study's default mesh)
run with its [[cavity]] as a control volume and as a column, the same orifice law, in pairs, interleaved
(control volume, column, control volume, column, ...) so that a machine whose speed drifts loads both
alike.  Each run is ``shockfem run`` in its own process; the figure is the time loop's wall time
(summary.json's ``wall_time_s``), whose ratio column / control volume is printed per pair, with the median.
docs/performance.md gives the figures.

    python scripts/column-cost.py PAIRS [SIZE] [END_TIME]      (SIZE: the study's, default "default";
                                                                END_TIME [s]: the scene's end, default its own)
"""
import json
import os
import statistics
import subprocess
import sys
import tempfile

from shockfem.scene.toml_writer import dumps
from shockfem.study.fixture.common import SIZES
from shockfem.study.fixture.dashpot import dashpot_design, dashpot_scene


def scenes(size: str, end: float | None) -> dict:
    """The dashpot scene with its cavity as a control volume and as a column, on the same law."""
    d = dashpot_design("rectangle")
    law = d["orifice_law"]
    out = {}
    for model in ("control_volume", "column"):
        raw = dashpot_scene(d, "rectangle", SIZES[size], end)
        cavity = raw["cavity"][0]
        cavity["model"] = model
        cavity["orifice"].pop("discharge", None)
        if law["discharge"] is not None:
            cavity["orifice"].update(law="fixed_cd", discharge=law["discharge"])
        raw["scene"]["name"] = f"fixture_dashpot_{model}"
        out[model] = raw
    return out


def run(path: str, out: str) -> float:
    subprocess.run([sys.executable, "-m", "shockfem", "run", path, "--out", out, "--no-progress", "--no-fields"],
                   check=True, capture_output=True)
    with open(os.path.join(out, "summary.json")) as fh:
        s = json.load(fh)
    return s["wall_time_s"], s["steps"], {**s["cavities"]["oil"], "pulse": s["shock"]["channels"]["article"]["pulse"]}


def main():
    pairs = int(sys.argv[1])
    size = sys.argv[2] if len(sys.argv) > 2 else "default"
    end = float(sys.argv[3]) if len(sys.argv) > 3 else None
    work = tempfile.mkdtemp(prefix="column-cost-")
    paths = {}
    for model, raw in scenes(size, end).items():
        paths[model] = os.path.join(work, f"{model}.toml")
        with open(paths[model], "w") as fh:
            fh.write(dumps(raw))
    for model in paths:                        # untimed: the mesh cached, the kernels compiled
        run(paths[model], os.path.join(work, f"warm_{model}"))
    ratios = []
    for k in range(pairs):
        cv, steps_cv, cv_summary = run(paths["control_volume"], os.path.join(work, f"cv{k}"))
        col, steps_col, summary = run(paths["column"], os.path.join(work, f"col{k}"))
        ratios.append(col / cv)
        print(f"pair {k}: control volume {cv:.2f} s ({steps_cv} steps), column {col:.2f} s ({steps_col} steps, "
              f"{summary['column_substeps']} column steps): ratio {col / cv:.3f}", flush=True)
    residual = summary["coupling_residual"] / summary["energy_taken"]
    for name, s in (("control volume", cv_summary), ("column", summary)):
        print(f"{name}: the article's peak {s['pulse']['peak'] / 9.80665:.0f} g (CFC 1000), velocity change "
              f"{s['pulse']['velocity_change']:.2f} m/s")
    print(f"the column's coupling residual: {residual:.2g} of the walls' work on the liquid")
    print(f"median ratio column / control volume over {pairs} pairs: {statistics.median(ratios):.3f}")


if __name__ == "__main__":
    main()

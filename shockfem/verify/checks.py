"""What a verification check is, and the helpers every case module shares.

A check is ``{name, reference, result, error, tolerance, passed, wall_time_s, elements}``;
``error`` is relative unless the check's name says otherwise.  Tolerances carry a comment
saying where they come from.
"""
from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys

import numpy as np

from ..output.history_file import read_history_csv
from ..scene.toml_writer import dumps

# Element size of the rods per verification size [m].
SIZES = {"coarse": 2.0, "default": 1.0, "fine": 0.5}


def check(name, reference, result, tolerance, wall, elements, absolute=False):
    error = abs(result - reference) if absolute else abs(result - reference) / abs(reference)
    return {"name": name, "reference": float(reference), "result": float(result), "error": float(error),
            "tolerance": float(tolerance), "passed": bool(error <= tolerance), "wall_time_s": float(wall),
            "elements": int(elements)}


def richardson(coarse: float, medium: float, fine: float, ratio: float = 2.0) -> tuple[float, float]:
    """The observed order p and Richardson's extrapolation of three results on meshes refined by ``ratio``:
    p = ln((f1 - f2) / (f2 - f3)) / ln r, f = f3 + (f3 - f2) / (r^p - 1) (Roache, Verification and
    Validation in Computational Science and Engineering, 1998, ch. 5); (nan, nan) where the differences
    change sign (not in the asymptotic range: no estimate) or vanish."""
    d1, d2 = coarse - medium, medium - fine
    if d1 * d2 <= 0:
        return float("nan"), float("nan")
    p = float(np.log(d1 / d2) / np.log(ratio))
    if p <= 0:                  # the differences do not shrink: diverging, no estimate
        return p, float("nan")
    return p, float(fine + (fine - medium) / (ratio ** p - 1))


def element_count(solver) -> int:
    """Cells of the solver's mesh over all ranks."""
    return solver.model.num_cells_global


def parallel_agreement(raw: dict, name: str, workdir: str, columns: list[str]):
    """Run a raw scene with 1 and 2 MPI processes (``shockfem run``); the largest difference of the
    history ``columns``, each relative to its own largest magnitude, must be round-off."""
    path = os.path.join(workdir, f"{raw['scene']['name']}.toml")
    os.makedirs(workdir, exist_ok=True)
    with open(path, "w") as fh:
        fh.write(dumps(raw))
    mpirun = shutil.which("mpirun")
    exe = [sys.executable, "-m", "shockfem", "run", path, "--no-progress", "--no-fields"]
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1")
    results = {}
    wall = 0.0
    for n in (1, 2):
        out = os.path.join(workdir, f"{raw['scene']['name']}_np{n}")
        cmd = exe + ["--out", out]
        if n > 1:
            if mpirun is None:
                return {"name": name, "reference": 0.0, "result": float("nan"),
                        "error": float("nan"), "tolerance": 1e-9, "passed": False, "wall_time_s": 0.0,
                        "elements": 0, "note": "mpirun not found (apt-get install openmpi-bin)"}
            cmd = [mpirun, "-n", str(n)] + cmd
        proc = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=900)
        if proc.returncode != 0:
            raise RuntimeError(f"parallel run with {n} process(es) failed:\n{proc.stderr[-2000:]}")
        results[n] = read_history_csv(os.path.join(out, "history.csv"))
        with open(os.path.join(out, "summary.json")) as fh:
            summary = json.load(fh)
        wall += summary["wall_time_s"]
    a, b = results[1], results[2]
    diff = max(np.abs(a[c] - b[c]).max() / max(np.abs(a[c]).max(), 1e-30) for c in columns)
    # same arithmetic up to the order of floating-point sums across ranks
    return check(f"{name} [-, abs]", 0.0, diff, 1e-9, wall, summary["elements"], absolute=True)

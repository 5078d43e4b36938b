"""A study's finite-element case: a raw scene run into a run directory of its own (``shockfem run``'s:
XDMF fields, histories, summary, the pictures of its deformed shape), and the run read back."""
from __future__ import annotations

import json
import os
import time
from dataclasses import dataclass

from ..errors import ModelError, UnstableRun
from ..output.history_file import read_history
from ..runner import run_scene
from ..scene import resolve


@dataclass(frozen=True)
class CaseRun:
    """A finished case, read back from its run directory."""
    path: str
    summary: dict                 # summary.json
    history: dict                 # history.csv columns by name (SI)


def run_case(name: str, raw: dict, out_dir: str, echo) -> tuple[CaseRun | None, float, str]:
    """Run a case's scene into ``out_dir/name`` (the run directory of ``shockfem run``: XDMF fields,
    histories, summary); returns (the run or None, wall time, status)."""
    t0 = time.perf_counter()
    path = os.path.join(out_dir, name)
    try:
        run_scene(resolve(raw), path, progress=False, quiet=True)
    except UnstableRun as exc:
        echo(f"  {name}: unstable: {exc}")
        return None, time.perf_counter() - t0, "unstable"
    except ModelError as exc:                 # a mesh gmsh cannot make: the study goes on without the run
        echo(f"  {name}: not run: {exc}")
        return None, time.perf_counter() - t0, "not meshed"
    with open(os.path.join(path, "summary.json")) as fh:
        summary = json.load(fh)
    result = CaseRun(path, summary, read_history(os.path.join(path, "history.csv"))[0])
    return result, time.perf_counter() - t0, summary["status"]

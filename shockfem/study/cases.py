"""A study's finite-element case: a raw scene run into a run directory of its own (``shockfem run``'s:
XDMF fields, histories, summary, the pictures of its deformed shape), and the run read back."""
from __future__ import annotations

import json
import os
import sys
import time
from dataclasses import dataclass

from ..errors import ModelError, UnstableRun
from ..output.history_file import read_history
from ..runner import resume_run, run_scene
from ..scene import resolve, to_plain


@dataclass(frozen=True)
class CaseRun:
    """A finished case, read back from its run directory."""
    path: str
    summary: dict                 # summary.json
    history: dict                 # history.csv columns by name (SI)


# ``shockfem study NAME --resume`` sets it: a case whose directory holds a completed run of the same
# resolved scene is read back instead of run, one stopped with a checkpoint goes on from it
RESUME_ENV = "SHOCKFEM_STUDY_RESUME"


def _completed_before(path: str, scene) -> bool:
    """Whether ``path`` holds a completed run of ``scene`` (its resolved scene as written)."""
    try:
        with open(os.path.join(path, "summary.json")) as fh:
            status = json.load(fh).get("status")
        with open(os.path.join(path, "resolved_scene.json")) as fh:
            ran = json.load(fh)
    except (OSError, ValueError):
        return False
    return status == "completed" and ran == json.loads(json.dumps(to_plain(scene)))


def run_case(name: str, raw: dict, out_dir: str, echo) -> tuple[CaseRun | None, float, str]:
    """Run a case's scene into ``out_dir/name`` (the run directory of ``shockfem run``: XDMF fields,
    histories, summary); returns (the run or None, wall time, status).  With ``RESUME_ENV`` set, a
    case completed before is read back and one stopped with a checkpoint resumed."""
    t0 = time.perf_counter()
    path = os.path.join(out_dir, name)
    scene = resolve(raw)
    resuming = os.environ.get(RESUME_ENV) == "1"
    # a study's cases run for minutes: someone at a terminal sees each one's progress bar; logs do not
    watched = sys.stderr.isatty()
    try:
        if resuming and _completed_before(path, scene):
            echo(f"  {name}: completed before, read back")
        elif resuming and os.path.exists(os.path.join(path, "checkpoint", "latest.json")):
            echo(f"  {name}: resumed from its checkpoint")
            resume_run(path, progress=watched, quiet=True, scene=scene)
        else:
            run_scene(scene, path, progress=watched, quiet=True)
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

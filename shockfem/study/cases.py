"""A study's finite-element case: a raw scene run into a run directory of its own (``shockfem run``'s:
XDMF fields, histories, summary, the pictures of its deformed shape), and the run read back.

``run_case`` runs one case in this process (a design iteration that needs the last case's answer before
it can set up the next); ``run_cases`` runs a set of independent cases (a design of experiments) as a
table through the batch runner (``batch.py``): each its own ``shockfem run`` process, both cores;
``run_chain_cases`` does the same for chain scenes (``amplifier/chain.py``), read back as their chain
results."""
from __future__ import annotations

import json
import os
import sys
import time
from dataclasses import dataclass

from ..amplifier.chain import resolve_chain
from ..errors import ModelError, UnstableRun
from ..output.history_file import read_history
from ..runner import resume_run, run_scene
from ..scene import resolve, to_plain
from ..scene.toml_writer import dumps
from .batch import Case, run_batch


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


def run_wall(summary: dict, elapsed: float, read_back: bool) -> float:
    """A case's wall time [s] as a study's tables give it: what running it took, or for a case read back
    from an earlier run its run's own (``summary.json``'s ``wall_time_s``, the solver's), not the read's."""
    return float(summary.get("wall_time_s", elapsed)) if read_back else elapsed


def run_case(name: str, raw: dict, out_dir: str, echo) -> tuple[CaseRun | None, float, str]:
    """Run a case's scene into ``out_dir/name`` (the run directory of ``shockfem run``: XDMF fields,
    histories, summary); returns (the run or None, wall time, status).  With ``RESUME_ENV`` set, a
    case completed before is read back (its wall time its run's, ``run_wall``) and one stopped with a
    checkpoint resumed."""
    t0 = time.perf_counter()
    path = os.path.join(out_dir, name)
    scene = resolve(raw)
    resuming = os.environ.get(RESUME_ENV) == "1"
    # a study's cases run for minutes: someone at a terminal sees each one's progress bar; logs do not
    watched = sys.stderr.isatty()
    read_back = resuming and _completed_before(path, scene)
    try:
        if read_back:
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
    return result, run_wall(summary, time.perf_counter() - t0, read_back), summary["status"]


def _text(path: str) -> str | None:
    try:
        with open(path) as fh:
            return fh.read()
    except OSError:
        return None


def _run_table(cases: list[tuple[str, dict]], out_dir: str, factors: list[dict] | None, echo) -> list[dict]:
    """Write each case's scene as ``out_dir/<name>/scene.toml`` and run them all as a table
    (``batch.run_batch``, the local executor: as many at a time as there are cores); the batch's rows."""
    batch = []
    for k, (name, raw) in enumerate(cases):
        path = os.path.join(out_dir, name)
        os.makedirs(path, exist_ok=True)
        scene_file = os.path.join(path, "scene.toml")
        text = dumps(raw)
        if _text(scene_file) != text:
            with open(scene_file, "w") as fh:
                fh.write(text)
            # a changed scene at the same path: the batch, which knows a case by its file and overrides,
            # must not take the run of the old one for this one
            if os.path.exists(os.path.join(path, "case.json")):
                os.remove(os.path.join(path, "case.json"))
        batch.append(Case(name, scene_file, (), (factors or [{}] * len(cases))[k]))
    # a terminal shows the batch's progress bar, a log its line per case as each ends
    return run_batch(batch, out_dir, "local", progress=sys.stderr.isatty(), echo=echo,
                     rerun=os.environ.get(RESUME_ENV) != "1")


def _status(row: dict) -> str:
    return "not meshed" if row["exit code"] == 2 else row["status"]


def _say(echo, name: str, row: dict):
    """A case that did not complete, with why (the batch has shown each case's status as it ended)."""
    if _status(row) != "completed":
        echo(f"  {name}: {_status(row)}" + (f": {row['diagnosis']}" if row["diagnosis"] else ""))


def run_cases(cases: list[tuple[str, dict]], out_dir: str, echo,
              factors: list[dict] | None = None) -> list[tuple[CaseRun | None, float, str]]:
    """Run independent cases ``(name, raw scene)`` into ``out_dir/<name>`` as a table (``batch.run_batch``,
    the local executor: as many at a time as there are cores), each scene written beside its run as
    ``<name>/scene.toml``; ``out_dir`` gets the batch's ``cases.csv`` (``factors``: each case's levels for
    it).  Returns what ``run_case`` returns for each, in order.  With ``RESUME_ENV`` set, the completed
    cases are read back and the stopped ones resumed (the batch's own rule: same scene file, same
    overrides); without it every case runs from the start."""
    for _, raw in cases:
        resolve(raw)                              # a bad scene is the study's bug: say so before running any
    out = []
    for (name, _), row in zip(cases, _run_table(cases, out_dir, factors, echo)):
        _say(echo, name, row)
        path, result, wall = os.path.join(out_dir, name), None, float(row["wall time [s]"])
        if _status(row) == "completed":
            with open(os.path.join(path, "summary.json")) as fh:
                result = CaseRun(path, json.load(fh), read_history(os.path.join(path, "history.csv"))[0])
            wall = run_wall(result.summary, wall, row["how"].startswith("skipped"))
        out.append((result, wall, _status(row)))
    return out


def run_chain_cases(cases: list[tuple[str, dict]], out_dir: str,
                    echo) -> dict[str, tuple[dict | None, float, str, str]]:
    """Run independent chain scenes ``(name, raw chain scene)`` (``amplifier/chain.py``, each at its
    ``chain.fidelity``) into ``out_dir/<name>`` as a table, as ``run_cases`` does; by name: (the chain's
    results, ``summary.json``'s ``chain``, or None; the case's wall time; its status; its diagnosis)."""
    for _, raw in cases:
        resolve_chain(raw)                        # a bad scene is the study's bug: say so before running any
    out = {}
    for (name, _), row in zip(cases, _run_table(cases, out_dir, None, echo)):
        _say(echo, name, row)
        chain = None
        if _status(row) == "completed":
            with open(os.path.join(out_dir, name, "summary.json")) as fh:
                chain = json.load(fh)["chain"]
        out[name] = (chain, float(row["wall time [s]"]), _status(row), row["diagnosis"])
    return out

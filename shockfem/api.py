"""The Python API: load a scene, run it, read a run directory back.

    import shockfem

    scene = shockfem.load_scene("studies/foundation/bar_impact.toml",
                                overrides=['boundary.0.value = "2 m/s"'])
    run = shockfem.run(scene, "results/bar_2ms")
    run.summary["status"]              # "completed"
    run.history["bar.v_z"]             # numpy array, run.units["bar.v_z"] == "m/s"
    run.fields                         # results/bar_2ms/fields.xdmf, for ParaView or pyvista
    again = shockfem.load_run("results/bar_2ms")
    shockfem.resume("results/bar_2ms")     # a run stopped by SIGTERM or a kill goes on from its checkpoint

A scene is a TOML file or a dictionary of the same tables (units as strings, "5 m/s"); overrides
are the command line's ``--set`` assignments.  ``run`` writes the same run directory as
``shockfem run`` (``docs/outputs.md``) and returns what ``load_run`` reads from it, so a result
in hand and one read back later are the same object.  Chain scenes (``[chain]``) run with
``shockfem run``; this API runs plain scenes.
"""
from __future__ import annotations

import json
import os
from dataclasses import dataclass
from types import MappingProxyType

import numpy as np

from .output.history import read_history
from .scene import Scene, apply_override, load_scene as _load_scene_file, resolve


@dataclass(frozen=True)
class Run:
    """A run directory, read: its summary, its histories as read-only arrays with their units, the
    resolved scene it ran, and the path of its fields."""
    path: str
    summary: dict
    history: MappingProxyType            # column name -> array (SI), e.g. "time", "bar.v_z", "energy.kinetic"
    units: MappingProxyType              # column name -> unit, e.g. "s", "m/s", "J"
    scene: dict                          # resolved_scene.json: the scene as run, in SI

    @property
    def fields(self) -> str | None:
        """Path of ``fields.xdmf`` (None when the run wrote no fields)."""
        path = os.path.join(self.path, "fields.xdmf")
        return path if os.path.exists(path) else None

    @property
    def status(self) -> str:
        return self.summary.get("status", "unknown")


def load_scene(source: str | dict, overrides: list[str] | tuple = ()) -> Scene:
    """A checked scene (SI inside) from a TOML path or a dictionary, with ``--set``-style overrides.

    Raises ``shockfem.errors.SceneError`` listing every problem (field, what is wrong, what was given)."""
    if isinstance(source, (str, os.PathLike)):
        return _load_scene_file(os.fspath(source), list(overrides))
    raw = source
    for assignment in overrides:
        raw = apply_override(raw, assignment)
    return resolve(raw)


def run(scene: Scene | str | dict, out_dir: str, progress: bool = False, fields: bool = True,
        on_step=None) -> Run:
    """Run a scene (a ``Scene``, a path or a dictionary) into the run directory ``out_dir``.

    ``on_step(step)`` is called after every step with a read-only record: ``step.step``, ``step.t``
    and ``step.dt`` [s], ``step.dt_stable`` [s], ``step.energy`` (a copy: ``kinetic``, ``internal``,
    ``plastic``, ... [J], ``balance_error``) and ``step.messages``.  Raises
    ``shockfem.errors.UnstableRun`` when the run goes unstable (its outputs are kept); a
    ``SceneError`` or ``ModelError`` on bad input."""
    from .runner import run_scene
    if not isinstance(scene, Scene):
        scene = load_scene(scene)
    run_scene(scene, out_dir, progress=progress, write_fields=fields, quiet=True, on_step=on_step)
    return load_run(out_dir)


def resume(out_dir: str, progress: bool = False, on_step=None) -> Run:
    """Continue the stopped run in ``out_dir`` from its last checkpoint (``docs/outputs.md``) and return
    its ``Run``: the same as a run that was never stopped.  Raises ``ModelError`` when there is nothing to
    resume (a completed run, no checkpoint) or it cannot be (another number of MPI processes)."""
    from .runner import resume_run
    resume_run(out_dir, progress=progress, quiet=True, on_step=on_step)
    return load_run(out_dir)


def load_run(path: str) -> Run:
    """Read a run directory written by ``run`` or ``shockfem run``."""
    def read_json(name):
        with open(os.path.join(path, name)) as fh:
            return json.load(fh)
    if not os.path.exists(os.path.join(path, "summary.json")):
        raise FileNotFoundError(f"{path}: not a run directory (no summary.json)")
    history, units = {}, {}
    csv_path = os.path.join(path, "history.csv")
    if os.path.exists(csv_path):
        columns, units = read_history(csv_path)
        for name, values in columns.items():
            history[name] = np.ascontiguousarray(values)
            history[name].flags.writeable = False
    scene = read_json("resolved_scene.json") if os.path.exists(os.path.join(path, "resolved_scene.json")) else {}
    return Run(path, read_json("summary.json"), MappingProxyType(history), MappingProxyType(units), scene)

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
    rows = shockfem.sweep("studies/foundation/bar_impact.toml", ['boundary.0.value=[2, 5] m/s'],
                          "results/bar_sweep")   # a case per level, both cores; rows of cases.csv
    done = shockfem.import_deck("studies/lsdyna/taylor_bar.k", "taylor.toml", units="mm-ms-kg-kN")
    shockfem.run(done.scene, "results/taylor")      # done.report: what the import changed or left out

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
from typing import TYPE_CHECKING
from types import MappingProxyType

import numpy as np

from .output.history_file import read_history

# the scene layer (and through it numba and dolfinx) loads on first use: load_run reads a run directory
# without them
if TYPE_CHECKING:
    from .scene import Scene


def check_raw(raw: dict, warn=None, base_dir: str = ".") -> str:
    """What ``shockfem check`` does to a raw scene (plain, chain or launcher): read every field through
    the checker; returns what it is, or raises ``SceneError`` listing every problem.  ``warn(sentence)``,
    if given, hears what a valid scene should still change (mass damping on a free body, ``scene.advice``'s
    warnings); ``base_dir``: the folder the scene's mesh files are relative to (the scene file's)."""
    from .scene import is_chain, is_launcher_scene
    if is_chain(raw):
        from .amplifier.chain import resolve_chain
        spec, scene, _ = resolve_chain(raw)
        return f"chain of {len(scene.bodies)} bodies, {spec.architecture}, fidelity {spec.fidelity}"
    if is_launcher_scene(raw):
        from .launcher.scene import resolve_design, resolve_launcher
        name, gun, _ = resolve_launcher(raw)
        design = f", design: muzzle velocity {resolve_design(raw)[0]:.6g} m/s" if "design" in raw else ""
        return f"launcher {name}, bore {gun.bore:.6g} m, barrel {gun.length:.6g} m{design}"
    from .scene import resolve
    from .scene.advice import scene_warnings
    from .scene.damping import mass_damping_warnings
    scene = resolve(raw, base_dir=base_dir)
    for warning in mass_damping_warnings(scene) + scene_warnings(scene) if warn else ():
        warn(warning)
    return f"{scene.kinematics}, {len(scene.bodies)} bodies, end time {scene.end_time:.6g} s"


def sweep(scene: str, vary: list[str], out_dir: str, design: str = "full", generators: str = "",
          resolution: int = 3, overrides: list[str] | tuple = (), cases_table: str | None = None,
          executor: str = "local", workers: int | None = None, ranks: int = 1, scheduler: str | None = None,
          progress: bool = False, echo=print, verbose: bool = False) -> list[dict]:
    """Run a sweep of the scene file ``scene``: the cases of ``design`` over the factors ``vary``
    (``"bodies.striker.velocity=[5, 10, 20] m/s"``, as ``shockfem sweep --vary``), or of the CSV table
    ``cases_table``, each with ``overrides`` first; every case checked before any runs (``SceneError``
    lists the problems of all); run by ``executor`` (``study/batch.py``: "local" processes or "dask") into
    ``out_dir/<case>``, skipping cases completed before (``verbose``: Dask's INFO log lines shown).  Returns
    the table's rows (``cases.csv``)."""
    from .scene import apply_overrides, read_toml
    from .scene.checker import SceneError
    from .study.batch import run_batch
    from .study.sweep import cases_from_table, design_cases, parse_vary
    if cases_table:
        cases = cases_from_table(scene, cases_table, tuple(overrides))
    else:
        cases = design_cases(scene, [parse_vary(v) for v in vary], design, generators, resolution, tuple(overrides))
    problems = []
    base = read_toml(scene)
    for case in cases:
        try:
            check_raw(apply_overrides(base, case.overrides))
        except SceneError as e:
            problems += [f"{case.name} ({', '.join(f'{k}={v}' for k, v in case.factors.items())}): {p}"
                         for p in e.problems]
    if problems:
        raise SceneError(problems)
    return run_batch(cases, out_dir, executor, workers, ranks, scheduler, progress, echo, verbose=verbose)


def import_deck(deck: str, out: str | None = None, units: str | None = None):
    """What ``shockfem import`` does: the LS-DYNA keyword deck (or Abaqus ``.inp`` mesh) ``deck`` written as
    the scene ``out`` (default: the deck's name with ``.toml``) with its bodies' meshes beside it and an
    import report; ``units`` names the deck's consistent unit set (``"mm-ms-kg-kN"``; required for a deck).

    Returns the paths written (``scene``, ``mesh_dir``, ``report``) and the report's ``text``.  Raises
    ``SceneError`` listing every problem of the deck, each naming its file, line, keyword and card."""
    from .importers import import_model
    return import_model(deck, out, units)


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
    from .scene import apply_overrides, load_scene as _load_scene_file, resolve
    if isinstance(source, (str, os.PathLike)):
        return _load_scene_file(os.fspath(source), list(overrides))
    return resolve(apply_overrides(source, overrides))


def run(scene: Scene | str | dict, out_dir: str, progress: bool = False, fields: bool = True,
        on_step=None) -> Run:
    """Run a scene (a ``Scene``, a path or a dictionary) into the run directory ``out_dir``.

    ``on_step(step)`` is called after every step with a read-only record: ``step.step``, ``step.t``
    and ``step.dt`` [s], ``step.dt_stable`` [s], ``step.energy`` (a copy: ``kinetic``, ``internal``,
    ``plastic``, ... [J], ``balance_error``) and ``step.messages``.  Raises
    ``shockfem.errors.UnstableRun`` when the run goes unstable (its outputs are kept); a
    ``SceneError`` or ``ModelError`` on bad input."""
    from .mpi_start import start_mpi
    from .dolfinx_start import import_dolfinx
    start_mpi()
    import_dolfinx()
    from .runner import run_scene
    from .scene import Scene
    if not isinstance(scene, Scene):
        scene = load_scene(scene)
    run_scene(scene, out_dir, progress=progress, write_fields=fields, quiet=True, on_step=on_step)
    return load_run(out_dir)


def resume(out_dir: str, progress: bool = False, on_step=None) -> Run:
    """Continue the stopped run in ``out_dir`` from its last checkpoint (``docs/outputs.md``) and return
    its ``Run``: the same as a run that was never stopped.  Raises ``ModelError`` when there is nothing to
    resume (a completed run, no checkpoint) or it cannot be (another number of MPI processes)."""
    from .mpi_start import start_mpi
    from .dolfinx_start import import_dolfinx
    start_mpi()
    import_dolfinx()
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

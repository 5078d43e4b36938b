"""Run a scene: scene -> mesh -> model -> time loop -> run directory.

``run_scene`` is what ``shockfem run`` calls; verification cases and studies call it too,
and read their results back from the run directory.
"""
from __future__ import annotations

import signal
import threading
import time
from dataclasses import dataclass, replace

import numpy as np
from mpi4py import MPI

from .errors import ModelError, RunInterrupted, UnstableRun
from .forces import registry as force_sources
from .geometry import build_mesh
from .geometry.quality import check_mesh
from .model import build_model, describe
from .output.fields import FieldWriter, write_final_shape
from .output import checkpoint
from .output.consumers import Checkpoints, FieldFrames, HistoryRows, LoopState, ProgressBar, StopRules
from .output.history import HistoryRecorder
from .output.peak_stress import PeakStress
from .output.picture_process import PictureProcess, pictures_wanted
from .output.plots import plot_histories
from .output.rundir import RunDirectory
from .scene import Scene, to_plain
from .scene.advice import scene_warnings
from .scene.damping import mass_damping_warnings
from .materials.layout import S_EPS
from .solver.explicit import ExplicitSolver
from .solver.preload import settle


@dataclass
class RunResult:
    summary: dict
    solver: ExplicitSolver
    history: HistoryRecorder
    path: str


# what a finished run is warned of (``run_warnings``)
HOURGLASS_SHARE = 0.10         # a body's hourglass energy over its internal energy (stored and plastic, LS-DYNA's
                               # sense): the hourglass control shapes the answer
HOURGLASS_FLOOR = 1e-3         # ... unless its hourglass energy is below this share of the run's largest energy
NEGATIVE_INTERNAL = 1e-4       # internal energy below minus this share of the largest energy: not round-off
CONTACT_PENETRATION = 0.2      # a contact's deepest penetration (beyond any initial overlap) over its smallest facet


def run_warnings(summary: dict) -> list[str]:
    """What a user should act on in a finished run's ``summary``: each a sentence with the number and the fix."""
    out = []
    e = summary["energy"]
    largest = max(abs(e["initial_total"]), abs(e["kinetic"]), abs(e["internal"]), abs(e["external_work"]))
    for name, b in summary["bodies"].items():
        # a body whose hourglass work is a sliver of the run's energy shapes nothing: left out
        if b["hourglass_to_internal"] > HOURGLASS_SHARE and b["hourglass_energy"] > HOURGLASS_FLOOR * largest:
            out.append(f"body {name}: the hourglass energy is {b['hourglass_to_internal']:.0%} of its internal energy "
                       f"({b['hourglass_energy']:.4g} J of {b['internal_energy']:.4g} J; above {HOURGLASS_SHARE:.0%}): "
                       "the one-point elements' hourglass control is shaping its answer. Refine the mesh where it "
                       "deforms most, or set scene.integration = \"full\"")
    if e["internal"] < -NEGATIVE_INTERNAL * largest:
        out.append(f"the internal energy ends negative ({e['internal']:.4g} J, {-e['internal'] / largest:.2g} of the "
                   "largest energy): elements returned more work than they took, a sign of an unstable or "
                   "inverted element. Lower scene.safety_factor or refine")
    for name, c in summary["contacts"].items():
        beyond = c["max_penetration"] - c["initial_overlap"]["deepest"]
        if c["smallest_facet"] > 0 and beyond > CONTACT_PENETRATION * c["smallest_facet"]:
            out.append(f"contact {name}: surfaces went {beyond:.3g} m into each other, {beyond / c['smallest_facet']:.0%} "
                       f"of its smallest facet ({c['smallest_facet']:.3g} m; above {CONTACT_PENETRATION:.0%}): the "
                       "penalty is soft for this impact. Raise the contact's penalty_scale or refine the surfaces")
    for name, c in summary.get("cavities", {}).items():
        # a liquid's model checks its range every run (fluid/cavity.py, fluid/column_source.py)
        for check in c.get("validity", []):
            if not check["holds"]:
                out.append(f"cavity {name}: {check['name']} reached {check['value']:.3g}, beyond {check['limit']:.3g}: "
                           f"outside the range of its model ({c['model'].split(';')[0]})")
    return out


# a run is refused before it starts when its step or its number of steps is beyond any useful run: a
# stable step under a picosecond, or more steps than a day of small runs
SMALLEST_STEP = 1e-12          # [s]
MOST_STEPS = 1e8


def _refuse_endless(scene: Scene, solver: ExplicitSolver):
    """A ``ModelError`` (exit 2) naming what sets the step, when the run could not end in useful time."""
    dt = solver.stable_step()
    steps = scene.end_time / dt
    if dt >= SMALLEST_STEP and steps <= MOST_STEPS:
        return
    cell = solver.critical_cell
    body = scene.bodies[solver.model.cell_body[cell]] if cell >= 0 else None
    where = (f"body '{body.name}' (material '{body.material}', element_size {body.element_size:.3g} m)"
             if body is not None else "a contact or spring")
    raise ModelError(f"the stable step is {dt:.3g} s, set by {where}: scene.end_time {scene.end_time:.3g} s would take "
                     f"{steps:.3g} steps (limits: a step of at least {SMALLEST_STEP:g} s, at most {MOST_STEPS:.0e} "
                     "steps). Check that material's modulus and density (units), coarsen the body, or shorten "
                     "scene.end_time.")


def damping_step_note(scene: Scene, qualities, dt: float) -> str | None:
    """A note when stiffness-proportional damping shortens the stable step more than twice: its
    damping ratio grows with frequency, so the smallest elements' modes are overdamped and the step
    shrinks as (2 / w)(sqrt(1 + xi^2) - xi) with xi far above 1."""
    undamped = min((q.stable_step for q, b in zip(qualities, scene.bodies) if not b.rigid), default=np.inf)
    if not np.isfinite(undamped) or dt > 0.5 * undamped:
        return None
    own = any(b.damping for b in scene.bodies)
    where = ("the bodies' damping (bodies[i].damping; a chain scene sets it from chain.damping, 0.02 unless "
             "given)" if own else "the scene's damping")
    return (f"stiffness-proportional damping shortens the stable step {undamped / dt:.3g} times (from "
            f"{undamped:.3g} s without it): the smallest elements' frequencies are damped far above critical "
            f"by {where}. If the run is slow: " + ("" if own else "damp each body at its own first frequency "
                                                   "(bodies[i].damping), ")
            + "damp at a higher frequency, use damping.type = 'mass', or coarsen the elements.")


def run_scene(scene: Scene, out_dir: str, comm=MPI.COMM_WORLD, progress: bool = True,
              write_fields: bool = True, quiet: bool = False, on_step=None, origin: dict | None = None) -> RunResult:
    """Run ``scene`` and write the run directory ``out_dir``; ``on_step(step)``, if given, is called
    after every step with the loop's read-only ``solver.explicit.Step`` (t, dt, step, energies).
    ``origin``: how the run was started, kept with its checkpoints for ``--resume`` (a chain's table).

    Raises
    ------
    UnstableRun
        After writing everything produced so far and a summary with ``status = "unstable"``.
    RunInterrupted
        On SIGINT or SIGTERM, at the next step, after finishing the outputs and writing a checkpoint
        (``status = "interrupted"``).
    """
    return _run(scene, out_dir, comm, progress, write_fields, quiet, on_step, origin, None)


def resume_run(out_dir: str, comm=MPI.COMM_WORLD, progress: bool = True, quiet: bool = False, on_step=None,
               scene: Scene | None = None) -> RunResult:
    """Continue the run in ``out_dir`` from its last checkpoint (``output/checkpoint.py``) to its end time,
    in the same directory: the histories and frames after the checkpoint are written again, and match a
    run that was never stopped.  ``scene``, if given, must be the one checkpointed (a chain resumed
    builds its scene again).  Raises ``ModelError`` when there is nothing to resume or it cannot be (another
    number of processes, another mesh); otherwise as ``run_scene``."""
    info = checkpoint.latest(out_dir)
    if scene is not None and to_plain(scene) != to_plain(info["scene"]):
        raise ModelError(f"--resume {out_dir}: the scene differs from the one its checkpoint ran")
    origin = info["origin"] or {}
    return _run(info["scene"], out_dir, comm, progress, origin.get("write_fields", True), quiet, on_step, origin,
                info)


def _run(scene: Scene, out_dir: str, comm, progress: bool, write_fields: bool, quiet: bool, on_step,
         origin: dict | None, resume: dict | None) -> RunResult:
    """``run_scene`` and ``resume_run``: a new run, or (``resume``: what ``checkpoint.latest`` read) one
    going on from its checkpoint.  Build, loop over the steps, finish the outputs whatever happened."""
    run = _Run(scene, out_dir, comm, write_fields, quiet, origin, resume)
    run.build()
    status, diagnosis = "completed", None
    try:
        run.loop(progress, on_step)
    except UnstableRun as e:
        status, diagnosis = "unstable", e.diagnosis
        run.say(f"RUN STOPPED: {e.diagnosis}")
        run.history.record()
        raise
    except RunInterrupted as e:
        status, diagnosis = "interrupted", f"{signal.Signals(e.signum).name} at t = {e.time:.6g} s"
        run.interrupted(e)
        raise
    except BaseException as e:           # keep what was written and say that the run did not finish
        status, diagnosis = "failed", f"{type(e).__name__}: {e}"
        raise
    finally:
        run.finish(status, diagnosis)
    return RunResult(run.summary, run.solver, run.history, out_dir)


class _Run:
    """One run's pieces: its directory and log, the solver, the outputs that consume its steps."""

    def __init__(self, scene: Scene, out_dir: str, comm, write_fields: bool, quiet: bool, origin: dict | None,
                 resume: dict | None):
        self.scene, self.out_dir, self.comm, self.write_fields = scene, out_dir, comm, write_fields
        self.origin = {**(origin or {}), "write_fields": write_fields}
        self.resume = resume
        self.rd = RunDirectory(out_dir, comm, resume=resume is not None)
        # started now (or taken from ``shockfem run``, which starts it first thing), so that it imports its
        # libraries while this process meshes and steps
        self.pictures = (PictureProcess.for_run() if comm.rank == 0 and write_fields and pictures_wanted()
                         else None)
        self.say = (lambda msg: self.rd.log(msg, echo=not quiet))
        self.quiet = quiet
        self.fields = self.bar = self.stop = self.checkpoints = self.summary = None
        self.wall0 = time.perf_counter()

    # ------------------------------------------------------------------ build
    def build(self):
        """The run directory's first files, the mesh, the model and the solver (restored from the checkpoint
        of a resumed run), and the outputs."""
        scene, comm, say = self.scene, self.comm, self.say
        resume = self.resume
        state = None if resume is None else checkpoint.read_rank(self.out_dir, resume, comm)
        if resume is None:
            self.rd.write_scene_and_provenance(scene)
        # where this run was resumed before (and, on the next checkpoint, now)
        self.resumed = [] if state is None else state["loop"].resumed + [
            {"step": resume["step"], "time": resume["time"], "at": time.strftime("%Y-%m-%dT%H:%M:%S")}]
        self.rd.write_json("summary.json", {"status": "running", "diagnosis": None, "scene": scene.name,
                                            "started": time.strftime("%Y-%m-%dT%H:%M:%S"),
                                            "resumed_from": self.resumed})
        say(f"shockfem: scene '{scene.name}', {scene.kinematics}, {comm.size} process(es)")
        for warning in scene_warnings(scene):
            say(f"WARNING: {warning}")
        if resume is not None:
            say(f"resuming from the checkpoint at t = {resume['time']:.6g} s (step {resume['step']}, written "
                f"{resume['written']})")
        meshed = build_mesh(scene, comm, log=say)
        qualities = check_mesh(scene, meshed, log=say)
        self.model = build_model(scene, meshed)
        say("models that run:\n" + describe(self.model, scene))
        self.solver = ExplicitSolver(self.model)
        if state is None:
            for msg in self.solver.log_messages:
                say(msg)
            if scene.preload is not None:
                settle(self.solver, scene.preload, say)
        else:
            self._restore(state)
        say(f"elements: {self.model.num_cells_global}, stable step {self.solver.stable_step():.4g} s "
            f"(safety factor {scene.safety_factor})")
        _refuse_endless(scene, self.solver)
        note = damping_step_note(scene, qualities, self.solver.stable_step())
        if note:
            say(note)
        self._outputs(state)

    def _restore(self, state: dict):
        """The solver's state from the checkpoint, on the same mesh."""
        same = state["mesh"] == checkpoint.mesh_fingerprint(self.model.X0)
        if not self.comm.allreduce(same, op=MPI.LAND):
            raise ModelError(f"--resume {self.out_dir}: the mesh built again differs from the checkpointed one (a "
                             "mesh file or the mesher changed since): start the run again")
        checkpoint.restore(self.solver, state["solver"])

    def _outputs(self, state: dict | None):
        """The history and the field writer, at t = 0 (their first row and frame) or as checkpointed."""
        rd, scene = self.rd, self.scene
        self.history = HistoryRecorder(self.solver, rd.file("history.csv"), rd.file("history.h5"))
        for note in self.history.notes:
            self.say(note)
        self.fields = (FieldWriter(rd.file("fields.xdmf"), self.solver, scene.outputs.fields,
                                   resume_after=state["fields_last"] if state else None)
                       if self.write_fields else None)
        if state is None:
            self.history.record()
            if self.fields:
                self.fields.write(0.0)
            self.state = LoopState.start(scene.outputs, scene.checkpoint_interval)
        else:
            self.history.resume(self.comm.bcast(state["history"], root=0))
            for sec, saved in zip(self.history.sections, state["sections"]):
                checkpoint.restore(sec, saved)
            self.state = replace(state["loop"], resumed=self.resumed)
        self.peaks = PeakStress(self.solver, self.state.peak_stress)

    # ------------------------------------------------------------------ loop
    def loop(self, progress: bool, on_step):
        """Every step to the end time, each given to the consumers in turn (``output/consumers.py``)."""
        scene, loop = self.scene, self.state
        self.checkpoints = Checkpoints(self._save_checkpoint, loop.checkpoint, scene.end_time)
        if progress and self.comm.rank == 0 and not self.quiet:
            self.bar = ProgressBar(scene.end_time, self.solver.t)
        consumers = [lambda s: self.peaks.update(s.t),
                     HistoryRows(self.history, loop.history, scene.end_time),
                     FieldFrames(self.fields, loop.fields),
                     StopRules(loop, scene.energy_error_limit),
                     self._log_messages,
                     self.checkpoints]
        consumers += [on_step] if on_step is not None else []
        self.wall0 = time.perf_counter()
        # from here (meshing done: gmsh sets its own SIGINT handling while it works) a signal asks the loop to
        # stop between two steps
        self.stop = _StopOnSignal(self.comm).install()
        consumers += [lambda s: self.stop.check(s.step, s.t)] + ([self.bar] if self.bar is not None else [])
        for s in self.solver.steps(scene.end_time):
            for consume in consumers:
                consume(s)

    def _log_messages(self, s):
        for msg in s.messages:
            self.say(msg)

    def _save_checkpoint(self) -> float:
        """The whole state at the step just finished (``output/checkpoint.py``); returns its wall time [s].
        Collective."""
        if self.fields:
            self.fields.flush()       # a resume keeps the frames the XDMF file lists
        seen = {id(self.model)}
        kept = {"solver": checkpoint.capture(self.solver, seen),
                "sections": [checkpoint.capture(sec, seen) for sec in self.history.sections],
                "history": self.history.array() if self.comm.rank == 0 else None,
                "fields_last": self.fields.last if self.fields else None,
                "loop": replace(self.state, wall=self.state.wall + time.perf_counter() - self.wall0,
                                peak_stress=self.peaks.state()),
                "mesh": checkpoint.mesh_fingerprint(self.model.X0)}
        return checkpoint.write(self.out_dir, self.comm, self.solver.step, self.solver.t, kept, self.scene,
                                self.origin)

    def interrupted(self, e: RunInterrupted):
        """A signal stopped the loop: a checkpoint first (the row and frame the stop adds are not the run's
        cadence), then the history's row at the stop."""
        say = self.say
        say(f"RUN INTERRUPTED by {signal.Signals(e.signum).name}: finishing the outputs at t = {e.time:.6g} s")
        self.checkpoints.now()
        say(f"checkpoint written at t = {self.solver.t:.6g} s (step {self.solver.step}): continue with "
            f"shockfem run --resume {self.out_dir}")
        self.history.record()

    # ------------------------------------------------------------------ finish
    def finish(self, status: str, diagnosis):
        """Whatever the loop's end: the last frame, the history, summary.json, the plots and pictures."""
        solver, scene, rd, say, comm = self.solver, self.scene, self.rd, self.say, self.comm
        try:
            wall = time.perf_counter() - self.wall0 + self.state.wall
            if self.stop is not None:
                self.stop.finishing()
            if self.bar is not None:
                self.bar.close(solver.t)
            if self.fields:
                if status != "completed":
                    self.fields.write(solver.t)   # the state at the stop, for the diagnosis
                self.fields.close()
                write_final_shape(rd.file("final_shape.xdmf"), solver)
            self.history.write(rd.file("history.h5"), rd.file("history.csv"))
            summary = _summary(scene, solver, status, diagnosis, wall, self.peaks.per_body())
            summary["sections"] = {sec.name: sec.summary() for sec in self.history.sections}
            if getattr(solver, "preload_report", None) is not None:
                summary["preload"] = solver.preload_report     # solver/preload.py, checkpointed with the solver
            checkpoint_time = self.checkpoints.wall_time if self.checkpoints is not None else 0.0
            summary["checkpoints"] = {"interval": scene.checkpoint_interval, "wall_time_s": checkpoint_time,
                                      "resumed_from": self.resumed}
            summary["warnings"] = mass_damping_warnings(scene) + scene_warnings(scene) + run_warnings(summary)
            for warning in mass_damping_warnings(scene) + run_warnings(summary):    # the scene's: said at the start
                say(f"WARNING: {warning}")
            if status == "completed" and comm.rank == 0:
                checkpoint.clear(self.out_dir)
            rd.write_json("summary.json", summary)
            self._plots_and_pictures(summary)
            say(f"{status}: {solver.step} steps to t = {solver.t:.6g} s in {wall:.2f} s "
                f"({summary['element_cycles_per_s']:.3g} element-cycles/s); energy balance error "
                f"{solver.energy.balance_error:.2e}")
            say(f"results in {self.out_dir}")
            rd.close()
            self.summary = summary
        finally:
            if self.stop is not None:
                self.stop.restore()

    def _plots_and_pictures(self, summary: dict):
        """Rank 0: the history plots, the shock metrics into ``summary``, and the pictures of the deformable
        bodies (rigid ones carry no stress and may hide the rest)."""
        if self.comm.rank == 0 and self.history.count > 1:
            if self.pictures is not None:
                rigid = {rb.index for rb in self.model.rigid}
                self.pictures.request(self.out_dir, [i for i in range(len(self.model.bodies)) if i not in rigid])
            _never_failing("the history plots", self.say, plot_histories, self.out_dir,
                           [b.name for b in self.scene.bodies])
            summary["shock"] = _never_failing("the shock metrics", self.say, _shock_metrics, self.out_dir, self.say)
            if self.pictures is not None:
                self.pictures.collect(self.say)
        elif self.pictures is not None:
            self.pictures.cancel()


class _StopOnSignal:
    """SIGINT and SIGTERM, while a run's time loop is on, ask it to stop between two steps (``check``)
    rather than wherever the signal lands: the run then finishes its outputs and says ``interrupted``.
    Only the main thread can take signals; elsewhere the defaults stay.  Under MPI the ranks agree every
    ``AGREE_EVERY`` steps, so that all stop at the same step."""

    AGREE_EVERY = 50

    def __init__(self, comm):
        self.comm = comm
        self.signum = 0
        self.previous = {}
        self.finished = False

    def install(self) -> "_StopOnSignal":
        if threading.current_thread() is threading.main_thread():
            for sig in (signal.SIGINT, signal.SIGTERM):
                self.previous[sig] = signal.signal(sig, self._note)
        return self

    def _note(self, signum, frame):
        self.signum = self.signum or signum

    def finishing(self):
        """The outputs are being finished: a signal now is noted and does not cut them short."""
        self.finished = True

    def check(self, step: int, t: float):
        if self.finished:
            return
        signum = self.signum
        if self.comm.size > 1:
            if step % self.AGREE_EVERY:
                return
            signum = self.comm.allreduce(signum, op=MPI.MAX)
        if signum:
            raise RunInterrupted(signum, t)

    def restore(self):
        for sig, handler in self.previous.items():
            signal.signal(sig, handler)
        self.previous = {}


def _never_failing(what: str, say, fn, *args):
    """``fn(*args)``, or None and a warning in the log if it raises: no metric or figure may fail a run whose
    steps are done (its summary.json is written before)."""
    try:
        return fn(*args)
    except Exception as e:
        say(f"WARNING: {what} were not made ({type(e).__name__}: {e}); the run's results are complete")
        return None


def _shock_metrics(out_dir: str, say) -> dict | None:
    """Pulse metrics, spectra and the stage table (``metrics/report.py``), added to summary.json."""
    from .metrics.report import shock_report
    try:
        result, lines = shock_report(out_dir)
    except ValueError as e:        # a record too short or too coarse to measure: say so, keep the run
        say(f"shock metrics not computed: {e}")
        return None
    for line in lines:
        say(line)
    return result


def _body_maxima(solver, per_cell: np.ndarray) -> np.ndarray:
    """The largest value of a per-cell quantity in every body, over all ranks."""
    m = solver.model
    out = np.zeros(len(m.bodies))
    for i in range(len(out)):
        sel = m.cell_body[:len(per_cell)] == i
        out[i] = solver.comm.allreduce(float(per_cell[sel].max()) if sel.any() else 0.0, op=MPI.MAX)
    return out


def _max_plastic_strain(solver: ExplicitSolver) -> np.ndarray:
    """Per body (the plastic strain only grows, so its final value is its maximum)."""
    if not solver.model.plastic:
        return np.zeros(len(solver.model.bodies))
    return _body_maxima(solver, solver.plastic_state[:, :, S_EPS].max(axis=1))


def _summary(scene: Scene, solver: ExplicitSolver, status: str, diagnosis, wall: float, peaks: list[dict]) -> dict:
    m = solver.model
    v, _ = solver.body_means()
    e = solver.energy
    max_eps = _max_plastic_strain(solver)
    energies = solver.body_energies()
    elements = m.num_cells_global
    kernel_elements = solver.comm.allreduce(len(m.kernel_cells), op=MPI.SUM)
    return {
        "status": status,
        "diagnosis": diagnosis,
        "scene": scene.name,
        "kinematics": scene.kinematics,
        "element": scene.element,
        "elements": elements,
        "deformable_elements": kernel_elements,
        "nodes": m.V.dofmap.index_map.size_global,
        "processes": solver.comm.size,
        "steps": solver.step,
        "dt": solver.stable_step() if solver.step else solver.dt,
        "dt_last": solver.dt,
        "end_time": solver.t,
        "wall_time_s": wall,
        "element_cycles_per_s": elements * solver.step / wall if wall > 0 else 0.0,
        "phase_times_s": {"internal_force": solver.times.internal_force, "update": solver.times.update,
                          "contact": solver.times.contact, "energy": solver.times.energy,
                          "step_total": solver.times.total},
        "energy": {"initial_total": e.initial, "kinetic": e.kinetic, "internal": e.internal,
                   "plastic": e.plastic, "bulk_viscosity": e.bulk_viscosity,
                   "damping": e.damping, "hourglass": e.hourglass,
                   # LS-DYNA's internal energy holds the plastic work: the same ratio as each body's below
                   "hourglass_to_internal": abs(e.hourglass) / max(abs(e.internal + e.plastic), 1e-300),
                   "contact": e.contact, "external_work": e.external, "balance": e.balance,
                   "balance_reference": e.largest,
                   "balance_error": e.balance_error},
        "models": describe(m, scene).splitlines(),
        "mass_scaling": m.mass_scaling.as_dict() if m.mass_scaling is not None else None,
        **force_sources.summaries(solver.sources),     # "contacts", "springs", "cavities", "penetration"
        "bodies": {b.name: {"mass": float(m.body_mass[i]), "rigid": b.rigid,
                            "velocity_final": [float(c) for c in v[i]],
                            # tracked every step at every point (``output/peak_stress.py``)
                            "max_von_mises": peaks[i]["max_von_mises"],
                            "max_von_mises_time": peaks[i]["time"], "max_von_mises_at": peaks[i]["at"],
                            "max_plastic_strain": float(max_eps[i]),
                            "kinetic_energy": float(energies["kinetic"][i]),
                            "internal_energy": float(energies["internal"][i]),
                            "plastic_work": float(energies["plastic"][i]),
                            "hourglass_energy": float(energies["hourglass"][i]),
                            "hourglass_to_internal": float(abs(energies["hourglass"][i])
                                                           / max(abs(energies["internal"][i]), 1e-300))}
                   for i, b in enumerate(scene.bodies)},
    }

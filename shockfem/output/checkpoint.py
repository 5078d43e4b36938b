"""Checkpoints: a run's whole state on disk, so that ``shockfem run --resume DIR`` continues a killed
run to the same result as a run that was never stopped.

What a checkpoint holds, per MPI rank: every array and number of the solver and of the objects it
steps (contact pairs and their passes, springs, liquid cavities, a penetrated target, rigid bodies,
the energy account), the history recorded so far, the stress sections, and the time loop's own
counters (next history sample, next field frame, largest von Mises stress so far, wall time spent).
It is captured *generically*: the attributes of those objects are walked, and every array, number,
string and container of them is kept, so a new piece of state in a contact law is checkpointed
without anyone remembering to add it (``tests/sim/test_restart.py`` would catch a miss: the resumed
histories must equal the uninterrupted ones).  Left out: the model, the scene and the mesh (built
again from the scene, and checked to be the same mesh), compiled kernels, MPI communicators, open
files, dolfinx objects (their arrays are the solver's, restored in place), and what an object lists
in its ``NOT_STATE`` (wall-clock marks).

The directory ``checkpoint/`` of a run:

    scene.pkl                   the resolved scene, and how the run was started (a chain's table)
    step000012345.rank0.pkl     one file per rank at each checkpoint (the previous set removed after)
    latest.json                 which step is whole on every rank: time, step, processes

Each file is written beside and renamed into place, and ``latest.json`` moves on only when every rank
has written its file, so a kill at any moment leaves the previous checkpoint whole.  A checkpoint is
written every ``scene.checkpoint_interval`` of simulated time and when SIGTERM or SIGINT stops a run;
a run that completes removes its checkpoints.  Resuming needs the same number of processes (the
mesh's partition is part of the state).
"""
from __future__ import annotations

import dataclasses
import glob
import hashlib
import json
import os
import pickle
import shutil
import time

import numpy as np

from ..errors import ModelError
from .rundir import CHECKPOINT_DIRECTORY as DIRECTORY, write_json_atomic

# 2: a contact pass keeps the facets its candidate lists hold (``near``) and the slaves its rank takes
# 3: a contact pair's rank keeps only its own nodes and slaves, and its halo (``contact/halo.py``)
# 4: the solver keeps its contact pairs, springs, cavities and target in one list of force sources
# 5: the solver's buffer of a step's sums over the ranks holds band damping's loss too (15 entries)
# 6: band damping's terms held in each body's co-rotating frame (``solver/band.py``)
# 7: the peak von Mises stress kept per row of params by the element pass (the solver's ``peak``)
# 8: a liquid source's walls keep the step's forces on them (``fluid.cavity.WallNodes``)
FORMAT = 8

# objects whose state is not the run's: built again from the scene on resume
_REBUILT_MODULES = ("shockfem.model", "shockfem.scene", "shockfem.geometry")
_PLAIN = (bool, int, float, complex, str, bytes, type(None), np.generic)


class _Object(dict):
    """The captured attributes of one object (restored into the object rebuilt in its place)."""


class _Skip:
    """A value that is not state (a function, a communicator, an open file)."""


def _is_state_object(value) -> bool:
    module = type(value).__module__ or ""
    if not module.startswith("shockfem.") or module.startswith(_REBUILT_MODULES):
        return False
    if not hasattr(value, "__dict__"):
        return False
    # frozen dataclasses are inputs (specs), never changed by a run
    return not (dataclasses.is_dataclass(value) and value.__dataclass_params__.frozen)


def capture(obj, seen: set) -> _Object:
    """The state of ``obj``: its attributes that are data, walked into the shockfem objects it holds
    (each object once: ``seen`` holds the ids already taken, back references are skipped)."""
    seen.add(id(obj))
    skip = set(getattr(obj, "NOT_STATE", ()))
    out = _Object()
    for name, value in vars(obj).items():
        if name in skip:
            continue
        data = _data(value, seen)
        if data is not _Skip:
            out[name] = data
    return out


def _data(value, seen):
    if isinstance(value, np.ndarray):
        return value if value.dtype != object else _Skip
    if isinstance(value, _PLAIN):
        return value
    if isinstance(value, (list, tuple, set, frozenset)):
        items = [_data(v, seen) for v in value]
        return _Skip if any(i is _Skip for i in items) else type(value)(items)
    if isinstance(value, dict):
        items = {k: _data(v, seen) for k, v in value.items()}
        plain_keys = all(isinstance(k, _PLAIN) for k in items)
        return _Skip if not plain_keys or any(v is _Skip for v in items.values()) else items
    if _is_state_object(value) and id(value) not in seen:
        return capture(value, seen)
    return _Skip


def restore(obj, state: _Object):
    """Put ``state`` (from ``capture``) back into ``obj``: arrays of the same shape in place (the
    solver's velocity is a view of a dolfinx function's array), objects restored into the objects
    that stand there, everything else set."""
    for name, saved in state.items():
        setattr(obj, name, _put(getattr(obj, name, None), saved, name))


def _put(current, saved, name):
    if isinstance(saved, _Object):
        restore(current, saved)
        return current
    if isinstance(saved, (list, tuple)) and any(isinstance(s, _Object) for s in saved):
        if current is None or len(current) != len(saved):
            raise ModelError(f"checkpoint: '{name}' holds {len(saved)} objects, the model built again "
                             f"{0 if current is None else len(current)}: the scene is not the one checkpointed")
        for c, s in zip(current, saved):
            _put(c, s, name)
        return current
    if (isinstance(saved, np.ndarray) and isinstance(current, np.ndarray) and current.shape == saved.shape
            and current.dtype == saved.dtype and current.flags.writeable):
        current[...] = saved
        return current
    return saved


def mesh_fingerprint(coordinates: np.ndarray) -> str:
    """This rank's node coordinates, hashed: a resumed run must see the same mesh, partitioned alike."""
    return hashlib.sha1(np.ascontiguousarray(coordinates).tobytes()).hexdigest()


def _path(run_dir: str, *parts) -> str:
    return os.path.join(run_dir, DIRECTORY, *parts)


def _write_pickle(path: str, data):
    partial = path + ".partial"
    with open(partial, "wb") as fh:
        pickle.dump(data, fh, protocol=pickle.HIGHEST_PROTOCOL)
    os.replace(partial, path)


def clear(run_dir: str):
    """Remove a run directory's checkpoints (a new run, or a completed one)."""
    shutil.rmtree(_path(run_dir), ignore_errors=True)


def write(run_dir: str, comm, step: int, t: float, state: dict, scene=None, origin=None) -> float:
    """Every rank writes its ``state``; then rank 0 points ``latest.json`` at this step and removes the
    older files.  ``scene`` and ``origin`` (how the run was started) are written once, by rank 0.
    Collective; returns the wall time it took [s]."""
    started = time.perf_counter()
    if comm.rank == 0:
        os.makedirs(_path(run_dir), exist_ok=True)
        if scene is not None and not os.path.exists(_path(run_dir, "scene.pkl")):
            _write_pickle(_path(run_dir, "scene.pkl"), {"format": FORMAT, "scene": scene, "origin": origin})
    comm.barrier()
    name = f"step{step:09d}.rank{comm.rank}.pkl"
    _write_pickle(_path(run_dir, name), {"format": FORMAT, "rank": comm.rank, "step": step, "time": t, **state})
    comm.barrier()
    if comm.rank == 0:
        write_json_atomic(_path(run_dir, "latest.json"), {
            "format": FORMAT, "step": step, "time": t, "processes": comm.size,
            "files": [f"step{step:09d}.rank{r}.pkl" for r in range(comm.size)],
            "written": time.strftime("%Y-%m-%dT%H:%M:%S")})
        for old in glob.glob(_path(glob.escape(run_dir), "step*.rank*.pkl*")):
            if not os.path.basename(old).startswith(f"step{step:09d}."):
                os.remove(old)
    comm.barrier()
    return time.perf_counter() - started


def latest(run_dir: str) -> dict:
    """What ``latest.json`` says, with the scene and how the run was started; a ``ModelError`` (exit 2)
    saying why when there is nothing to resume."""
    summary = os.path.join(run_dir, "summary.json")
    if not os.path.isdir(run_dir):
        raise ModelError(f"--resume {run_dir}: no such run directory")
    pointer = _path(run_dir, "latest.json")
    if not os.path.exists(pointer):
        status = None
        if os.path.exists(summary):
            with open(summary) as fh:
                status = json.load(fh).get("status")
        why = ("it completed (a completed run removes its checkpoints)" if status == "completed" else
               f"its summary says '{status}' and it wrote no checkpoint (checkpoints are written every "
               "scene.checkpoint_interval and when SIGTERM or SIGINT stops a run)" if status else
               "it is not a run directory written by shockfem run")
        raise ModelError(f"--resume {run_dir}: nothing to resume: {why}")
    with open(pointer) as fh:
        info = json.load(fh)
    with open(_path(run_dir, "scene.pkl"), "rb") as fh:
        info.update(pickle.load(fh))
    if info.get("format") != FORMAT:
        raise ModelError(f"--resume {run_dir}: checkpoint format {info.get('format')}, this shockfem reads "
                         f"{FORMAT}: resume it with the version that wrote it")
    return info


def read_rank(run_dir: str, info: dict, comm) -> dict:
    """This rank's state of the checkpoint ``info`` names; a ``ModelError`` when the processes differ."""
    if info["processes"] != comm.size:
        raise ModelError(f"--resume: the run was checkpointed on {info['processes']} process(es); resume it "
                         f"on as many (mpirun -n {info['processes']}), this is {comm.size}")
    with open(_path(run_dir, info["files"][comm.rank]), "rb") as fh:
        return pickle.load(fh)

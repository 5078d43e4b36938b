"""The run directory: the contract later tools and users rely on (``docs/outputs.md``).

    resolved_scene.json  the scene as run, in SI
    provenance.json      versions of shockfem, dolfinx, gmsh...; git hash; command; processes
    run.log              what was run and what happened
    fields.xdmf/.h5      displacement, velocity, von Mises, pressure, stress and strain at the field cadence
    final_shape.xdmf/.h5 the deformed mesh at the end with every cell field
    history.h5/.csv      per-body mean velocity/acceleration and energies at the history cadence
    summary.json         status, sizes, speed, energy balance and per-body results
    energy.png, bodies.png, peak_stress.png, final_shape.png (the deformed shape coloured by von Mises)

Crash-safe: a rerun into the directory first removes the previous run's files (so no old summary
stands beside a new scene); ``summary.json`` says ``running`` from the start and every JSON and
picture is written beside and renamed into place; the history's CSV grows row by row and each field
frame is closed as written, so a run killed at any moment leaves them readable up to the last sample.
"""
from __future__ import annotations

import glob
import json
import os
import platform
import shutil
import subprocess
import sys
import time

from .. import compat
from ..version import __version__
from ..scene import Scene, to_plain


def git_hash() -> str | None:
    here = os.path.dirname(os.path.abspath(__file__))
    try:
        out = subprocess.run(["git", "-C", here, "rev-parse", "HEAD"], capture_output=True, text=True,
                             timeout=5)
        return out.stdout.strip() or None
    except (OSError, subprocess.SubprocessError):
        return None


# what a run writes, so that a rerun clears exactly that (a study's own files beside its runs stay)
RUN_FILES = ("resolved_scene.json", "provenance.json", "run.log", "summary.json", "fields.xdmf", "fields.h5",
             "history.h5", "history.csv", "final_shape.xdmf", "final_shape.h5", "final_shape.png", "peak_stress.png", "energy.png",
             "bodies.png", "stages.png", "pulse_*.png", "srs_*.png", "*.partial.*",
             "*.partial")
# the run's checkpoints (``checkpoint.py``), a directory of their own, cleared with the rest
CHECKPOINT_DIRECTORY = "checkpoint"


class RunDirectory:
    def __init__(self, path: str, comm, resume: bool = False):
        """A new run clears what an earlier run left at ``path``; a resumed run (``resume``) keeps it all
        and appends to its log."""
        self.path = path
        self.comm = comm
        if comm.rank == 0 and not resume:
            os.makedirs(path, exist_ok=True)
            for pattern in RUN_FILES:
                for old in glob.glob(os.path.join(glob.escape(path), pattern)):
                    os.remove(old)
            shutil.rmtree(os.path.join(path, CHECKPOINT_DIRECTORY), ignore_errors=True)
        comm.barrier()
        self._log = open(os.path.join(path, "run.log"), "a" if resume else "w") if comm.rank == 0 else None

    def file(self, name: str) -> str:
        return os.path.join(self.path, name)

    def log(self, message: str, echo=True):
        if self.comm.rank != 0:
            return
        stamp = time.strftime("%H:%M:%S")
        self._log.write(f"[{stamp}] {message}\n")
        self._log.flush()
        if echo:
            print(message, flush=True)

    def write_json(self, name: str, data):
        """Rank 0 writes ``name`` whole or not at all (beside, then renamed into place)."""
        if self.comm.rank == 0:
            write_json_atomic(self.file(name), data)

    def write_scene_and_provenance(self, scene: Scene):
        self.write_json("resolved_scene.json", to_plain(scene))
        self.write_json("provenance.json", {
            "shockfem": __version__, **compat.versions(), "git": git_hash(),
            "python": sys.version.split()[0], "platform": platform.platform(),
            "command": sys.argv, "mpi_processes": self.comm.size,
            "started": time.strftime("%Y-%m-%dT%H:%M:%S")})

    def close(self):
        if self._log:
            self._log.close()


def write_json_atomic(path: str, data):
    """``data`` as JSON at ``path``, written beside and renamed into place: readers never see half a file."""
    partial = path + ".partial"
    with open(partial, "w") as fh:
        json.dump(data, fh, indent=2, default=float)
    os.replace(partial, path)

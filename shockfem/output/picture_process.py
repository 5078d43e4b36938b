"""A run's pictures (``render.render_run``) drawn by a process of their own, started with the run.

Two reasons for a separate process:

* speed: pyvista, VTK and matplotlib take about two seconds to import; the picture process imports
  them on the other core while the run meshes and steps, and draws while the run writes its plots
  and shock metrics;
* safety: a renderer that fails hard costs the pictures, never the finished run.  VTK without a
  working OpenGL (no EGL, no OSMesa, no display: a bare container) dies with a segmentation fault
  on its first render, which no ``except`` catches in the run's own process.

The process waits on its standard input for one request (a JSON line: run directory and bodies),
draws, prints the pictures it wrote as a JSON list and ends; an empty input (the run failed before
it had anything to show) ends it without drawing.

``shockfem run`` starts it first thing (``start_early``), before it imports the solver: the warm-up
(imports and a first picture, 1.2 s) is longer than a small run's own start, and the run's end waited
for it.
"""
from __future__ import annotations

import atexit
import gc
import json
import os
import signal
import subprocess
import sys
import threading

WAIT_S = 600.0          # for the drawing, after the request: a few seconds is usual


def pictures_wanted() -> bool:
    """Whether runs draw their deformed shapes (``render.render_run``): unless ``SHOCKFEM_PICTURES=0`` (the
    test suite's setting: about 1.5 s a run; batch users may want it too)."""
    return os.environ.get("SHOCKFEM_PICTURES", "1") != "0"


class PictureProcess:
    """The picture process of one run (rank 0 only)."""

    _early: "PictureProcess | None" = None      # started by ``start_early``, not yet taken by a run

    def __init__(self):
        self._proc = subprocess.Popen([sys.executable, "-m", "shockfem.output.picture_process"],
                                      stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                      text=True)

    @classmethod
    def start_early(cls):
        """Start the picture process of the run this process is about to make (``for_run`` takes it); if
        no run takes it (bad input, say), it is stopped as this process ends."""
        if cls._early is None:
            cls._early = cls()
            atexit.register(cls._stop_untaken)

    @classmethod
    def for_run(cls) -> "PictureProcess":
        """The process ``start_early`` started, if it is still waiting, or a new one."""
        early, cls._early = cls._early, None
        return early if early is not None and early._proc.poll() is None else cls()

    @classmethod
    def _stop_untaken(cls):
        early, cls._early = cls._early, None
        if early is not None and early._proc.poll() is None:
            early._proc.kill()
            early._proc.communicate()

    def request(self, run_dir: str, bodies: list[int]):
        """Ask for the run's pictures of ``bodies`` (scene indices), once its files are written; the process
        draws while the run goes on with its plots (``collect`` waits for it)."""
        if threading.current_thread() is threading.main_thread():
            # PETSc's and gmsh's signal handlers, installed as dolfinx and gmsh start, turn SIGPIPE (a write to
            # a process that has ended) into an abort of the whole run; Python's own choice: ignore it and
            # raise BrokenPipeError at the write
            signal.signal(signal.SIGPIPE, signal.SIG_IGN)
        try:
            self._proc.stdin.write(json.dumps({"run_dir": run_dir, "bodies": bodies}) + "\n")
            self._proc.stdin.flush()
        except BrokenPipeError:          # it ended already: ``collect`` says how
            pass

    def collect(self, say) -> list[str]:
        """Wait for the pictures; returns those written.  A failure is said (``say``), not raised."""
        try:
            out, err = self._proc.communicate(timeout=WAIT_S)
        except subprocess.TimeoutExpired:
            self._proc.kill()
            self._proc.communicate()
            say(f"no pictures of the deformed shape: the picture process took over {WAIT_S:g} s and was stopped")
            return []
        code = self._proc.returncode
        if code == 0:
            return json.loads(out.strip().splitlines()[-1]) if out.strip() else []
        last = [line for line in err.strip().splitlines() if line.strip()][-3:]
        how = (f"ended on signal {signal.Signals(-code).name}" if code < 0 else f"exited with status {code}")
        hint = (" (VTK found no OpenGL to draw with: install libegl1, libegl-mesa0 and libgl1-mesa-dri)"
                if code == -signal.SIGSEGV else "")
        say(f"no pictures of the deformed shape: the picture process {how}{hint}"
            + (": " + " | ".join(last) if last else ""))
        return []

    def cancel(self):
        """The run has nothing to draw: let the process end without drawing."""
        if self._proc.poll() is None:
            try:
                self._proc.communicate("", timeout=30)
            except subprocess.TimeoutExpired:
                self._proc.kill()
                self._proc.communicate()


def main() -> int:
    try:
        from .render import warm_up
        warm_up()                # the slow imports and the first picture's set-up, while the run goes on
        missing = None
    except ImportError as exc:
        missing = exc
    line = sys.stdin.readline()
    if not line.strip():
        return 0
    if missing is not None:
        print(f"{missing} (pip install shockfem[viz])", file=sys.stderr)
        return 4
    request = json.loads(line)
    from .render import render_run
    written = render_run(request["run_dir"], request["bodies"])
    print(json.dumps(written), flush=True)
    # the run waits for this process to end: without the interpreter's last collections over VTK's and
    # matplotlib's objects (``cli.console`` says why)
    gc.freeze()
    return 0


if __name__ == "__main__":
    sys.exit(main())

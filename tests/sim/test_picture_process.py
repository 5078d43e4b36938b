"""The run's pictures are drawn by a process of their own (``output/picture_process.py``): a renderer that
fails, even by a segmentation fault (VTK without OpenGL in a bare container did), costs the pictures and
never the finished run.  The crash is made by sending the picture process SIGSEGV itself."""
import json
import os
import signal

import pytest

import shockfem
from shockfem.output import picture_process
from shockfem.output.picture_process import PictureProcess

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def _bar(end="30 us"):
    return shockfem.load_scene(os.path.join(REPO, "studies", "foundation", "bar_impact.toml"),
                               [f'scene.end_time="{end}"', 'outputs.field_interval="10 us"'])


def test_a_picture_process_that_fails_is_said_and_returns_nothing(tmp_path):
    said = []
    p = PictureProcess()
    p.request(str(tmp_path / "no_such_run"), [0])
    assert p.collect(said.append) == []
    assert len(said) == 1 and "exited with status 1" in said[0] and "FileNotFoundError" in said[0], said


def test_a_crashed_picture_process_is_named_with_its_signal(tmp_path):
    said = []
    p = PictureProcess()
    os.kill(p._proc.pid, signal.SIGSEGV)
    p.request(str(tmp_path), [0])
    assert p.collect(said.append) == []
    assert "ended on signal SIGSEGV" in said[0] and "libegl1" in said[0], said


def test_cancel_ends_the_process_without_drawing():
    p = PictureProcess()
    p.cancel()
    assert p._proc.returncode == 0


@pytest.mark.parametrize("crash", [False, True])
def test_the_run_finishes_whatever_the_picture_process_does(tmp_path, monkeypatch, crash):
    """With pictures on: drawn beside the run (both PNGs); with the picture process crashing: the run
    completes all the same, its summary, history and fields written, the log saying why no pictures."""
    monkeypatch.setenv("SHOCKFEM_PICTURES", "1")
    if crash:
        request = PictureProcess.request

        def crash_then_request(self, run_dir, bodies):
            os.kill(self._proc.pid, signal.SIGSEGV)
            self._proc.wait()
            request(self, run_dir, bodies)
        monkeypatch.setattr(picture_process.PictureProcess, "request", crash_then_request)
    out = tmp_path / "run"
    result = shockfem.run(_bar(), str(out))
    assert result.summary["status"] == "completed"
    assert json.loads((out / "summary.json").read_text())["status"] == "completed"
    for f in ("history.csv", "history.h5", "fields.xdmf", "final_shape.xdmf"):
        assert (out / f).exists(), f
    log = (out / "run.log").read_text()
    pictures = [(out / p).exists() for p in ("peak_stress.png", "final_shape.png")]
    if crash:
        assert pictures == [False, False] and "picture process ended on signal SIGSEGV" in log
    else:
        assert pictures == [True, True] and "no pictures" not in log


def test_a_process_started_early_is_the_one_the_run_takes_or_is_stopped():
    """``shockfem run`` starts the picture process before it imports the solver (``start_early``): the run
    takes that one (``for_run``), and one no run took is stopped when the command ends (bad input)."""
    PictureProcess.start_early()
    early = PictureProcess._early
    taken = PictureProcess.for_run()
    assert taken is early and PictureProcess._early is None
    taken.cancel()
    assert taken._proc.returncode == 0
    fresh = PictureProcess.for_run()                      # nothing waiting: a new one
    assert fresh is not early
    fresh._proc.kill()
    fresh._proc.communicate()
    PictureProcess.start_early()
    untaken = PictureProcess._early
    PictureProcess._stop_untaken()
    assert untaken._proc.returncode == -signal.SIGKILL and PictureProcess._early is None

"""A run killed halfway keeps what it wrote: SIGTERM and SIGINT stop it between two steps, and it
finishes its outputs and says ``interrupted`` (exit 143 / 130); after SIGKILL its ``summary.json`` says
``running``, its streamed ``history.csv`` reads to its last whole row and ``history.h5`` to its last
snapshot. A rerun into the same directory
starts from a clean one. The rod impact of ``studies/metrics/rod_pulse.toml`` is run far past its event
(20 ms) so that the signal lands mid-run; a field frame every 10 us (a few per second of wall time)."""
import json
import os
import signal
import subprocess
import sys
import time

import h5py
import meshio
import pytest

from shockfem.output.history_file import read_history_csv

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCENE = os.path.join(REPO, "studies", "metrics", "rod_pulse.toml")


def _start(out, frames="10 us", launcher=(), env=None):
    """The rod impact run far past its event into ``out`` (``launcher``: e.g. mpirun's command before it)."""
    return subprocess.Popen([*launcher, sys.executable, "-m", "shockfem", "run", SCENE, "--out", str(out),
                             "--no-progress", "--set", 'scene.end_time="20 ms"', "--set",
                             f'outputs.field_interval="{frames}"'],
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, env=env)


def _finished_outputs(out, signame: str, err: str) -> int:
    """An interrupted run's outputs, read back: the summary says so and names the signal, both histories
    hold the same rows (over 300), every field frame reads; returns the number of frames."""
    s = json.loads((out / "summary.json").read_text())
    assert s["status"] == "interrupted" and signame in s["diagnosis"], err[-3000:]
    assert 0.0 < s["end_time"] < 0.02
    h = read_history_csv(str(out / "history.csv"))
    with h5py.File(out / "history.h5") as f:
        assert len(f["time"]) == len(h["time"]) > 300
    reader = meshio.xdmf.TimeSeriesReader(str(out / "fields.xdmf"))
    reader.read_points_cells()
    for k in range(reader.num_steps):
        reader.read_data(k)
    return reader.num_steps


def _wait_for_rows(out, rows=300, timeout=300):
    """Until the streamed history has ``rows`` rows (the loop is well under way)."""
    t0 = time.time()
    path = out / "history.csv"
    while time.time() - t0 < timeout:
        if path.exists() and path.read_text().count("\n") > rows:
            return
        time.sleep(0.2)
    raise AssertionError("the run did not start streaming its history")


def _png_ok(path):
    return path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


@pytest.mark.parametrize("sig, code, frames", [(signal.SIGTERM, 143, "10 us"), (signal.SIGINT, 130, "10 us"),
                                              (signal.SIGTERM, 143, "0.1 us")])
def test_sigterm_and_sigint_finish_the_outputs(tmp_path, sig, code, frames):
    """(A frame every 0.1 us, every step or so: the stop lands right after a frame, whose time the last
    frame must not write again: CI caught "name already exists" there once.)"""
    out = tmp_path / "run"
    p = _start(out, frames)
    _wait_for_rows(out)
    time.sleep(0.37)
    p.send_signal(sig)
    _, err = p.communicate(timeout=300)
    assert p.returncode == code, err[-3000:]
    assert _finished_outputs(out, signal.Signals(sig).name, err) >= 2 and (out / "final_shape.xdmf").exists()
    for png in ("energy.png", "bodies.png"):
        assert _png_ok(out / png)
    assert not list(out.glob("*.partial*"))
    assert "RUN INTERRUPTED" in (out / "run.log").read_text()


def test_sigkill_leaves_a_running_summary_and_a_readable_history_and_a_rerun_starts_clean(tmp_path):
    out = tmp_path / "run"
    p = _start(out)
    _wait_for_rows(out)
    time.sleep(0.53)
    p.kill()
    p.wait(timeout=60)
    assert json.loads((out / "summary.json").read_text())["status"] == "running"
    h = read_history_csv(str(out / "history.csv"))
    assert len(h["time"]) > 300 and (h["time"][1:] > h["time"][:-1]).all()
    # the HDF5 history is whole to its last snapshot (at most a few half seconds behind the CSV): every
    # column, the same rows as the CSV's first ones
    with h5py.File(out / "history.h5") as f:
        t5 = f["time"][:]
        assert 0 < len(t5) <= len(h["time"]) and set(f) == set(h)
        assert (t5 == h["time"][:len(t5)]).all()
        assert f["striker.v_z"].attrs["unit"] == "m/s"
    # the same directory again, a short run: nothing of the killed one is left beside it
    (out / "pulse_ghost.png").write_bytes(b"old")
    done = subprocess.run([sys.executable, "-m", "shockfem", "run", SCENE, "--out", str(out), "--no-progress",
                           "--no-fields", "--set", 'scene.end_time="5 us"'], capture_output=True, text=True,
                          timeout=300)
    assert done.returncode == 0, done.stderr
    assert json.loads((out / "summary.json").read_text())["status"] == "completed"
    assert not (out / "fields.xdmf").exists() and not (out / "pulse_ghost.png").exists()
    assert read_history_csv(str(out / "history.csv"))["time"][-1] == pytest.approx(5e-6)


def test_sigterm_under_mpirun_finishes_every_rank(tmp_path):
    """Two MPI ranks: SIGTERM to mpirun reaches both, they agree to stop at the same step (they compare
    notes every 50 steps) and rank 0 finishes the outputs: status ``interrupted``, the histories and the
    fields whole. (mpirun itself exits 1 when its ranks exit 143.)"""
    import shutil
    mpirun = shutil.which("mpirun")
    assert mpirun, "mpirun not found (apt-get install openmpi-bin)"
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1")
    out = tmp_path / "run"
    p = _start(out, launcher=(mpirun, "-n", "2"), env=env)
    _wait_for_rows(out)
    p.send_signal(signal.SIGTERM)
    _, err = p.communicate(timeout=300)
    assert p.returncode != 0, err[-3000:]
    assert _finished_outputs(out, "SIGTERM", err) >= 2

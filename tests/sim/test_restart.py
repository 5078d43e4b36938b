"""Restart: a run stopped by SIGTERM, SIGINT or SIGKILL and resumed from its checkpoint
(``shockfem run --resume DIR``) ends with the histories of a run that was never stopped, bit for bit
(the state is restored whole and the arithmetic is the same; any difference is a piece of state the
checkpoint missed), in one process and under ``mpirun -n 2``, and for a chain scene through to its
report.  The scenes cover every stateful part of the loop: rigid bodies, friction and an interference
preload (the split cone), a liquid cavity (the piston dashpot), a liquid column, a penetrated target with plasticity,
3D with rotation (the tilted drop, also band-damped), a run settled in a preload stage, discrete springs and a
constraint wall."""
import json
import os
import shutil
import signal
import subprocess
import sys
import time

import meshio
import numpy as np
import pytest

import shockfem
from shockfem import runner
from shockfem.cli import main
from shockfem.errors import RunInterrupted
from shockfem.output.history_file import read_history_csv
from shockfem.verify import contact_cases, spring_cases

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
GALLERY = os.path.join(REPO, "studies", "gallery")
ROD = os.path.join(REPO, "studies", "metrics", "rod_pulse.toml")


def _spring_scene():
    raw, _, _ = spring_cases._scene(0.01)
    raw["scene"]["end_time"] = 2e-4
    return raw


def _constraint_wall_scene():
    """A rod on a constraint wall (``verify rod_on_constraint_wall`` at 0.5 mm), in contact from the start:
    stopped mid-contact, the wall's impulse and its nodes' velocities go through the checkpoint."""
    raw = contact_cases._scene("rod_on_constraint_wall", [contact_cases._rod("rod", 0.0, -1.0, 0.0005)],
                               {"name": "wall", "a": "rod.bottom", "method": "constraint",
                                "wall": {"point": [0.0, 0.0], "normal": [0.0, 1.0]}}, 5e-5)
    return raw


SCENES = {   # name: (scene, overrides, the step at which a SIGTERM stops it)
    "cone_drop": (os.path.join(GALLERY, "cone_drop.toml"), ['scene.end_time="0.3 ms"'], 900),
    "piston_dashpot": (os.path.join(GALLERY, "piston_dashpot.toml"), ['scene.end_time="0.3 ms"'], 500),
    # the column steps every few steps of the bodies: a stop between two holds its half-gathered interval
    "column_dashpot": (os.path.join(GALLERY, "column_dashpot.toml"), ['scene.end_time="0.3 ms"'], 501),
    "penetration": (os.path.join(GALLERY, "penetration.toml"), ['scene.end_time="0.2 ms"'], 500),
    "tilted_drop_3d": (os.path.join(GALLERY, "tilted_drop.toml"), ['scene.end_time="0.1 ms"'], 300),
    # band damping's terms in the bodies' co-rotating frames (3D), and a run that settled in a preload stage
    "band_tilted_3d": (os.path.join(GALLERY, "tilted_drop.toml"),
                       ['scene.end_time="0.1 ms"', 'damping={type="band", ratio=0.02, low="2 kHz", high="40 kHz"}'],
                       300),
    "cone_drop_preload": (os.path.join(GALLERY, "cone_drop.toml"),
                          ['scene.end_time="0.3 ms"', 'scene.preload={duration="500 us"}'], 8500),   # the stage: 7830 steps
    "springs": (_spring_scene, [], 100),
    "constraint_wall": (_constraint_wall_scene, [], 300),
}


def _frame_times(run_dir):
    reader = meshio.xdmf.TimeSeriesReader(str(run_dir / "fields.xdmf"))
    reader.read_points_cells()
    return [reader.read_data(k)[0] for k in range(reader.num_steps)]


def _same_run(a_dir, b_dir):
    """Two run directories hold the same run: every history column equal, bit for bit, the same
    field frames, the same end state in the summary."""
    a, b = shockfem.load_run(str(a_dir)), shockfem.load_run(str(b_dir))
    assert a.status == b.status == "completed"
    assert list(a.history) == list(b.history)
    differ = [k for k in a.history if not np.array_equal(a.history[k], b.history[k])]
    assert not differ, f"columns differ after the resume: {differ[:8]}"
    for key in ("steps", "end_time", "dt"):
        assert a.summary[key] == b.summary[key]
    assert a.summary["energy"] == b.summary["energy"]
    assert a.summary["bodies"] == b.summary["bodies"]
    assert a.summary["contacts"] == b.summary["contacts"]     # impulses, peaks, intervals, searches
    if a.fields:
        assert _frame_times(a_dir) == _frame_times(b_dir)
    assert not (b_dir / "checkpoint").exists(), "a completed run keeps no checkpoint"


@pytest.mark.parametrize("name", list(SCENES))
def test_a_resumed_run_is_the_uninterrupted_run(tmp_path, name):
    path, overrides, stop_at = SCENES[name]
    scene = shockfem.load_scene(path() if callable(path) else path, overrides)
    shockfem.run(scene, str(tmp_path / "whole"))

    def stop(step):
        if step.step == stop_at:
            os.kill(os.getpid(), signal.SIGTERM)     # as a scheduler would: caught, the loop stops there

    with pytest.raises(RunInterrupted):
        shockfem.run(scene, str(tmp_path / "cut"), on_step=stop)
    cut = json.loads((tmp_path / "cut" / "checkpoint" / "latest.json").read_text())
    assert cut["step"] == stop_at and cut["processes"] == 1
    shockfem.resume(str(tmp_path / "cut"))
    _same_run(tmp_path / "whole", tmp_path / "cut")
    resumed = shockfem.load_run(str(tmp_path / "cut")).summary["checkpoints"]["resumed_from"]
    assert [r["step"] for r in resumed] == [stop_at]
    # a stage's report comes back with the solver's state
    stage = shockfem.load_run(str(tmp_path / "cut")).summary.get("preload")
    assert stage == shockfem.load_run(str(tmp_path / "whole")).summary.get("preload")
    assert (stage is not None and stage["settled"]) == name.endswith("preload")


def _cli(*args, launcher=(), env=None, **kw):
    return subprocess.Popen([*launcher, sys.executable, "-m", "shockfem", "run", *args, "--no-progress"],
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, env=env, **kw)


# the rod's pulse run on long enough for a signal sent just past a checkpoint (0.5 or 0.75 ms) to land before
# the end: the last 0.45 ms are seconds of run, the tests' polling 50 ms
ROD_LONG = ["--set", 'scene.end_time="1.2 ms"', "--set", 'outputs.field_interval="50 us"',
            "--set", 'scene.checkpoint_interval="0.25 ms"']


def _wait_for_checkpoint(run_dir, after: float, timeout=300):
    """Until the run has a checkpoint past ``after`` seconds of simulated time."""
    latest = run_dir / "checkpoint" / "latest.json"
    t0 = time.time()
    while time.time() - t0 < timeout:
        try:
            if json.loads(latest.read_text())["time"] > after:
                return
        except (OSError, ValueError):
            pass
        time.sleep(0.05)
    raise AssertionError("no checkpoint was written")


def test_sigkill_then_resume_from_the_command_line(tmp_path):
    """SIGKILL gives no warning: the run goes on from its last periodic checkpoint (every 0.25 ms here),
    its later rows and frames written again."""
    whole = _cli(ROD, "--out", str(tmp_path / "whole"), *ROD_LONG)
    cut = _cli(ROD, "--out", str(tmp_path / "cut"), *ROD_LONG)
    _wait_for_checkpoint(tmp_path / "cut", 0.6e-3)
    cut.send_signal(signal.SIGKILL)
    cut.communicate(timeout=300)
    assert whole.wait(timeout=300) == 0, whole.stderr.read()[-3000:]
    assert json.loads((tmp_path / "cut" / "summary.json").read_text())["status"] == "running"
    resumed = _cli("--resume", str(tmp_path / "cut"))
    _, err = resumed.communicate(timeout=300)
    assert resumed.returncode == 0, err[-3000:]
    _same_run(tmp_path / "whole", tmp_path / "cut")
    assert "resuming from the checkpoint" in (tmp_path / "cut" / "run.log").read_text()


@pytest.mark.long
def test_resume_under_mpirun(tmp_path):
    """Two ranks stopped by SIGTERM (to mpirun) resume on two ranks to the two-rank run's histories; on
    one rank the resume is refused, naming the count it needs (exit 2)."""
    mpirun = shutil.which("mpirun")
    assert mpirun, "mpirun not found (apt-get install openmpi-bin)"
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1")
    two = (mpirun, "-n", "2")
    whole = _cli(ROD, "--out", str(tmp_path / "whole"), *ROD_LONG, launcher=two, env=env)
    # the suite's first run on a fresh clone: both ranks compile the kernels (numba's cache is empty) while
    # the other worker runs the fixture study; it took over 300 s once in CI, and 45 s warm here
    assert whole.wait(timeout=900) == 0, whole.stderr.read()[-3000:]
    cut = _cli(ROD, "--out", str(tmp_path / "cut"), *ROD_LONG, launcher=two, env=env)
    _wait_for_checkpoint(tmp_path / "cut", 0.3e-3)
    cut.send_signal(signal.SIGTERM)
    cut.communicate(timeout=300)
    assert json.loads((tmp_path / "cut" / "summary.json").read_text())["status"] == "interrupted"
    one = subprocess.run([sys.executable, "-m", "shockfem", "run", "--resume", str(tmp_path / "cut")],
                         capture_output=True, text=True, timeout=300)
    assert one.returncode == 2 and "mpirun -n 2" in one.stderr, one.stderr[-3000:]
    resumed = _cli("--resume", str(tmp_path / "cut"), launcher=two, env=env)
    _, err = resumed.communicate(timeout=300)
    assert resumed.returncode == 0, err[-3000:]
    _same_run(tmp_path / "whole", tmp_path / "cut")


def test_a_chain_resumes_through_to_its_report(tmp_path, monkeypatch):
    """A chain scene's finite-element run, stopped and resumed, ends in the same chain report (gain,
    stages) as one never stopped."""
    chain = os.path.join(REPO, "studies", "amplifier", "three_rods.toml")
    args = ["run", chain, "--fidelity", "axisymmetric", "--no-progress"]
    assert main(args + ["--out", str(tmp_path / "whole")]) == 0
    steps = json.loads((tmp_path / "whole" / "summary.json").read_text())["steps"]
    cut = tmp_path / "cut"
    # the SIGTERM at a fixed step of the command's loop, as the tests above send it through ``on_step``: a
    # thread watching the files raced a run of half a second and lost it once
    loop = runner._Run.loop

    def loop_stopped_midway(self, progress, on_step):
        def stop(step):
            if step.step == steps // 2:
                os.kill(os.getpid(), signal.SIGTERM)
        return loop(self, progress, stop)

    monkeypatch.setattr(runner._Run, "loop", loop_stopped_midway)
    assert main(args + ["--out", str(cut)]) == 128 + signal.SIGTERM
    monkeypatch.undo()
    assert main(["run", "--resume", str(cut), "--no-progress"]) == 0
    a = json.loads((tmp_path / "whole" / "summary.json").read_text())["chain"]
    b = json.loads((cut / "summary.json").read_text())["chain"]
    for key in ("gain", "test_article_speed", "stages", "peak_stress"):
        assert a[key] == b[key], key
    h_a, h_b = read_history_csv(str(tmp_path / "whole" / "history.csv")), read_history_csv(str(cut / "history.csv"))
    assert all(np.array_equal(h_a[k], h_b[k]) for k in h_a)


def test_what_cannot_be_resumed_is_refused(tmp_path, capsys):
    """Exit 2 and the reason: a completed run, a directory that is no run, a scene beside --resume."""
    done = tmp_path / "done"
    assert main(["run", ROD, "--out", str(done), "--no-progress", "--no-fields", "--set",
                 'scene.end_time="5 us"']) == 0
    capsys.readouterr()
    assert main(["run", "--resume", str(done)]) == 2
    assert "it completed" in capsys.readouterr().err
    assert main(["run", "--resume", str(tmp_path / "nowhere")]) == 2
    assert "no such run directory" in capsys.readouterr().err
    assert main(["run", ROD, "--resume", str(done)]) == 2
    assert "drop a scene file" in capsys.readouterr().err
    with pytest.raises(SystemExit) as stopped:        # argparse's usage, as for any missing argument
        main(["run"])
    assert stopped.value.code == 2
    err = capsys.readouterr().err
    assert err.startswith("usage: shockfem run") and "--resume RUN_DIR" in err

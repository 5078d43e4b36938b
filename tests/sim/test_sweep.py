"""``shockfem sweep``: the same table from local processes and from Dask's LocalCluster; a sweep killed
with a case half run is run again and only what was not done runs (the finished case is not touched,
the killed one goes on from its checkpoint or starts again); a bad level is refused before anything
runs, naming the case and the field (exit 2)."""
import csv
import json
import os
import signal
import subprocess
import sys
import time

import pytest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCENE = os.path.join(REPO, "studies", "foundation", "bar_impact.toml")
QUICK = ["--set", 'scene.end_time="20 us"', "--set", 'bodies.bar.element_size="2 mm"', "--no-progress"]
# wall time and how a case ran differ from one sweep to another; every other column is the physics
VARYING = {"wall time [s]", "how"}


def _sweep(*args, **kwargs):
    return subprocess.run([sys.executable, "-m", "shockfem", "sweep", SCENE, *args], capture_output=True, text=True,
                          timeout=900, **kwargs)


def _table(out):
    with open(out / "cases.csv", newline="") as fh:
        return [{k: v for k, v in r.items() if k not in VARYING} for r in csv.DictReader(fh)]


def test_local_and_dask_give_the_same_table(tmp_path):
    vary = ["--vary", "boundary.0.value=[2, 5] m/s", "--vary", "scene.safety_factor=[0.5, 0.9]"]
    local = _sweep(*vary, *QUICK, "--out", str(tmp_path / "local"))
    assert local.returncode == 0, local.stderr[-3000:]
    dask = _sweep(*vary, *QUICK, "--out", str(tmp_path / "dask"), "--executor", "dask", "--workers", "2")
    assert dask.returncode == 0, dask.stderr[-3000:]
    a, b = _table(tmp_path / "local"), _table(tmp_path / "dask")
    assert len(a) == 4 and a == b
    assert [r["boundary.0.value [as given]"] for r in a] == ["2 m/s", "2 m/s", "5 m/s", "5 m/s"]
    assert all(r["status"] == "completed" for r in a)
    # the physics in the table: the driven bar's speed scales with the drive (elastic: linear but for the
    # bulk viscosity's quadratic term, 0.09% measured)
    v = [float(r["bar.velocity_final_z [m/s]"]) for r in a]
    assert abs(v[2] / v[0] - 2.5) < 0.01 * 2.5


def test_a_killed_sweep_runs_only_what_was_not_done(tmp_path):
    out = tmp_path / "killed"
    args = ["--vary", "boundary.0.value=[2, 3, 4] m/s", "--set", 'scene.end_time="400 us"', "--set",
            'scene.checkpoint_interval="10 us"', "--workers", "1", "--no-progress", "--out", str(out)]
    sweep = subprocess.Popen([sys.executable, "-m", "shockfem", "sweep", SCENE, *args], start_new_session=True,
                             stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    second = out / "case_1" / "checkpoint" / "latest.json"
    t0 = time.time()
    while not second.exists() and time.time() - t0 < 600:
        time.sleep(0.1)
    assert second.exists(), "the second case did not get under way"
    os.killpg(sweep.pid, signal.SIGKILL)        # the sweep and the case it runs, as a batch system kills a job
    sweep.wait()
    first = out / "case_0" / "summary.json"
    assert json.loads(first.read_text())["status"] == "completed"
    stamp = first.stat().st_mtime_ns
    assert json.loads((out / "case_1" / "summary.json").read_text())["status"] == "running"
    again = _sweep(*args[:-3], "--no-progress", "--out", str(out))
    assert again.returncode == 0, again.stderr[-3000:]
    with open(out / "cases.csv", newline="") as fh:
        rows = {r["case"]: r for r in csv.DictReader(fh)}
    assert rows["case_0"]["how"] == "skipped: completed before" and first.stat().st_mtime_ns == stamp
    assert rows["case_1"]["how"] == "resumed from its checkpoint" and rows["case_2"]["how"] == "run"
    assert all(r["status"] == "completed" for r in rows.values())


def test_bad_levels_are_refused_before_anything_runs(tmp_path):
    p = _sweep("--vary", "boundary.0.value=[2, -3] kg", *QUICK, "--out", str(tmp_path / "bad"))
    assert p.returncode == 2 and "Traceback" not in p.stderr
    assert "case_1 (boundary.0.value=-3 kg)" in p.stderr and "boundary" in p.stderr
    assert not (tmp_path / "bad").exists()
    p = _sweep("--vary", "boundary.0.value", *QUICK)
    assert p.returncode == 2 and "PATH=LEVELS" in p.stderr


def test_a_study_runs_its_independent_cases_as_a_table(tmp_path, monkeypatch):
    """``study.cases.run_cases`` (the penetration study's design of experiments): each case's scene written
    beside its run, the cases run by the batch runner, read back as a study reads a case; without
    ``--resume`` every case runs again, with it the completed ones are read back and not run."""
    from shockfem.scene import apply_overrides, read_toml
    from shockfem.study.cases import RESUME_ENV, run_cases
    raw = apply_overrides(read_toml(SCENE), ['scene.end_time="20 us"', 'bodies.bar.element_size="2 mm"'])
    slow = apply_overrides(read_toml(SCENE), ['scene.end_time="20 us"', 'bodies.bar.element_size="2 mm"',
                                              'boundary.0.value="2 m/s"'])
    said = []
    out = str(tmp_path / "study")
    first = run_cases([("fast", raw), ("slow", slow)], out, said.append, [{"v [m/s]": 5}, {"v [m/s]": 2}])
    assert [status for _, _, status in first] == ["completed", "completed"]
    fast, slow_run = first[0][0], first[1][0]
    # the bar driven at 5 and at 2 m/s: its mean speed, read back from each run's summary, scales with the drive
    # (but for the bulk viscosity's quadratic term: 0.035% measured)
    assert abs(fast.summary["bodies"]["bar"]["velocity_final"][1]) == pytest.approx(
        2.5 * abs(slow_run.summary["bodies"]["bar"]["velocity_final"][1]), rel=1e-3)
    assert "time" in fast.history and os.path.exists(os.path.join(out, "fast", "scene.toml"))
    table = list(csv.DictReader(open(os.path.join(out, "cases.csv"))))
    assert [r["v [m/s] [as given]"] for r in table] == ["5", "2"]
    again = run_cases([("fast", raw)], out, said.append)
    assert json.load(open(os.path.join(out, "batch.json")))[0]["how"] == "run" and again[0][2] == "completed"
    monkeypatch.setenv(RESUME_ENV, "1")
    run_cases([("fast", raw)], out, said.append)
    assert json.load(open(os.path.join(out, "batch.json")))[0]["how"] == "skipped: completed before"
    assert said[-1].startswith("  fast: completed (skipped: completed before")
    # a changed scene under the same name runs again, --resume or not
    changed = apply_overrides(raw, ['scene.end_time="25 us"'])
    third = run_cases([("fast", changed)], out, said.append)
    assert json.load(open(os.path.join(out, "batch.json")))[0]["how"] == "run"
    assert third[0][0].summary["end_time"] == pytest.approx(25e-6)


def test_chain_scenes_run_as_a_table(tmp_path, monkeypatch):
    """``study.cases.run_chain_cases`` (the amplifier study's runs): a chain scene at the rigid, 1d and
    axisymmetric fidelities as a table gives the chain results the same scene gives run in this process,
    and the table carries each case's gain and each pair's first restitution; with ``--resume`` the
    completed cases are read back, not run."""
    from shockfem.amplifier.chain import run_chain_scene
    from shockfem.scene import read_toml
    from shockfem.study.cases import RESUME_ENV, run_chain_cases
    raw = read_toml(os.path.join(REPO, "studies", "amplifier", "three_rods.toml"))
    for body in raw["bodies"]:
        body["element_size"] = "5 mm"
    cases = [(fidelity, {**raw, "chain": {**raw["chain"], "fidelity": fidelity}})
             for fidelity in ("rigid", "1d", "axisymmetric")]
    said = []
    out = tmp_path / "table"
    table = run_chain_cases(cases, str(out), said.append)
    assert [table[f][2] for f, _ in cases] == ["completed"] * 3, said
    for fidelity, scene in cases:
        here = run_chain_scene(scene, str(tmp_path / "here" / fidelity), progress=False, echo=lambda *a: None)
        there = table[fidelity][0]
        assert there["fidelity"] == fidelity
        assert there["gain"] == pytest.approx(here["gain"], rel=1e-12)
        assert [s["restitution"] for s in there["stages"]] == pytest.approx(
            [s["restitution"] for s in here["stages"]], rel=1e-12)
    rows = {r["case"]: r for r in csv.DictReader(open(out / "cases.csv"))}
    # the rigid model at e = 0.9: each pair restitutes 0.9 at its first impact
    assert float(rows["rigid"]["chain.m1_m2.restitution [-]"]) == pytest.approx(0.9, rel=1e-9)
    assert float(rows["axisymmetric"]["chain.gain [-]"]) == pytest.approx(table["axisymmetric"][0]["gain"], rel=1e-12)
    assert rows["axisymmetric"]["elements"] and not rows["1d"].get("elements")
    monkeypatch.setenv(RESUME_ENV, "1")
    run_chain_cases(cases, str(out), said.append)
    assert {r["how"] for r in json.load(open(out / "batch.json"))} == {"skipped: completed before"}

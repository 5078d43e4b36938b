"""A chain scene run at each fidelity gives the same kind of answer (stage table, gain)."""
import json
import os
import subprocess
import sys

import pytest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCENE = os.path.join(REPO, "studies", "amplifier", "three_rods.toml")


def shockfem(*args):
    return subprocess.run([sys.executable, "-m", "shockfem", *args], capture_output=True, text=True, timeout=900)


def _run(tmp_path, fidelity, *sets):
    out = tmp_path / fidelity
    p = shockfem("run", SCENE, "--fidelity", fidelity, "--out", str(out), "--no-progress", *sets)
    assert p.returncode == 0, p.stderr
    return json.load(open(out / "summary.json"))["chain"], p.stdout


def test_rigid_chain_is_the_product_of_its_collisions(tmp_path):
    chain, out = _run(tmp_path, "rigid")
    m = list(chain["masses"].values())
    e = 0.9
    v2 = (1 + e) * m[0] / (m[0] + m[1]) * 10.0
    v3 = (1 + e) * m[1] / (m[1] + m[2]) * v2
    assert [s["restitution"] for s in chain["stages"]] == pytest.approx([e, e], rel=1e-9)
    assert abs(chain["stages"][0]["struck_after"]) == pytest.approx(v2, rel=1e-9)
    assert chain["test_article_speed"] == pytest.approx(v3, rel=1e-9)
    assert chain["fidelity"] == "rigid" and "event-driven" in chain["model"]
    assert "of yield 690 MPa" in out


def test_1d_chain_loses_energy_to_waves(tmp_path):
    chain, _ = _run(tmp_path, "1d", "--set", "chain.damping=0")
    assert len(chain["stages"]) == 2
    # elastic bars, no damping: restitution below 1 only by the waves left in the bodies
    for s in chain["stages"]:
        assert 0.5 < s["restitution"] < 0.95
        assert s["vibration_share"] > 0.01
    assert "energy balance" in chain["model"]
    assert set(chain["peak_stress"]) == {"m1_m2", "m2_m3"}


def test_axisymmetric_chain_reports_the_same_table(tmp_path):
    # a chain scene takes [outputs] as any scene does: here a field frame every 20 us
    sets = [f'--set=bodies.{b}.element_size="4 mm"' for b in ("m1", "m2", "m3")] + ['--set=outputs.field_interval="20 us"']
    chain, _ = _run(tmp_path, "axisymmetric", *sets)
    assert [s["pair"] for s in chain["stages"]] == ["m1_m2", "m2_m3"]
    assert chain["stages"][1]["struck"] == "m3" and chain["gain"] > 1.0
    assert chain["test_article_pulse"]["pulse"]["peak_g"] > 0
    # the chain's fields open as any run's (tests/sim/test_paraview.py): every body, named
    import meshio
    fields = tmp_path / "axisymmetric" / "fields.xdmf"
    reader = meshio.xdmf.TimeSeriesReader(str(fields))
    reader.read_points_cells()
    _, _, cells = reader.read_data(reader.num_steps - 1)
    assert set(cells["body"][0]) == {1, 2, 3} and "stress_zz" in cells
    assert all(f'key="{b}"' in fields.read_text() for b in ("m1", "m2", "m3"))
    summary = json.load(open(tmp_path / "axisymmetric" / "summary.json"))
    assert reader.num_steps == int(summary["end_time"] / 20e-6) + 1 == 19     # 0, 20, ... 360 us of 373 us


def test_bad_chain_lists_its_problems():
    """The chain's own table and its bodies go through the scene checker together: every problem in
    one message style (field: problem, got X), exit 2."""
    p = shockfem("check", SCENE, "--set", 'chain.launch_speed="-3 kg"', "--set", "chain.restitution=2",
                 "--set", "chain.fidelity=2d", "--set", 'bodies.0.radius="-1 mm"')
    assert p.returncode == 2
    for expected in ("chain.launch_speed: expected a velocity",
                     "chain.restitution: must be a coefficient of restitution in (0, 1], got 2",
                     "chain.fidelity: must be one of rigid, 1d, axisymmetric, 3d, got '2d'",
                     "bodies[0].radius: must be > 0, got -1 mm"):
        assert expected in p.stderr
    assert "Traceback" not in p.stderr


def test_gaps_per_interface_time_the_collisions(tmp_path):
    """A launched chain's gaps may be one per interface: with rigid bodies at 10 m/s, the first collision
    comes at gap_1 / 10 and the second, the struck body moving at v2, gap_2 / v2 later."""
    chain, _ = _run(tmp_path, "rigid", "--set", 'chain.gap=["5 mm", "40 mm"]')
    m = list(chain["masses"].values())
    v2 = 1.9 * m[0] / (m[0] + m[1]) * 10.0
    # the rigid history steps at each collision (samples 1e-12 s either side): a stage ends at its collision
    t1, t2 = (s["end"] for s in chain["stages"])
    assert t1 == pytest.approx(0.005 / 10.0, abs=1e-11)
    assert t2 - t1 == pytest.approx(0.040 / v2, abs=1e-11)


def test_1d_chain_damping_is_a_band_by_default_and_every_model_takes_restitution(tmp_path):
    """The chain's structural damping is 2% over each body's first 20 modes unless told otherwise; either
    2% model takes restitution from the undamped bars (measured: 0.835 and 0.774 undamped, 0.764 and 0.688
    band, 0.771 and 0.680 stiffness-proportional)."""
    e = {}
    for name, sets in (("band", ()), ("stiffness", ("--set", 'chain.damping_type="stiffness"')),
                       ("none", ("--set", "chain.damping=0"))):
        chain, _ = _run(tmp_path / name, "1d", *sets)
        e[name] = [s["restitution"] for s in chain["stages"]]
        if name != "none":
            assert ("band over each body's first mode to 20 times it" in chain["model"]) == (name == "band")
    for damped in ("band", "stiffness"):
        assert all(d < u - 0.03 for d, u in zip(e[damped], e["none"]))

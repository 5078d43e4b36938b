"""The Python API (``docs/api.md``): a scene from a file or a dictionary with overrides, a run, its
histories with units, and the same run read back from its directory."""
import math
import os

import pytest

import shockfem
from shockfem.scene import SceneError, read_toml

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BAR = os.path.join(REPO, "studies", "foundation", "bar_impact.toml")


def _short_bar(speed="2 m/s"):
    raw = read_toml(BAR)
    raw.pop("damping")                                # undamped: 1D theory is exact
    raw["scene"]["end_time"] = "30 us"
    raw["bodies"][0]["element_size"] = "2 mm"
    raw["outputs"]["field_interval"] = "10 us"
    raw["boundary"][0]["value"] = speed
    return raw


def test_run_a_dictionary_and_read_it_back(tmp_path):
    """The bar's lower end driven at v: by t < L / c0 the wave has set c0 t of the bar's length L
    moving at v, so the bar's mean velocity is v c0 t / L (1D theory; +0.17% measured at 2 mm).
    ``on_step`` sees every step as a read-only record whose last one is the summary's."""
    steps = []
    run = shockfem.run(_short_bar(), str(tmp_path / "bar"), on_step=steps.append)
    assert run.status == "completed"
    assert [s.step for s in steps] == list(range(1, run.summary["steps"] + 1))
    assert steps[-1].t == pytest.approx(30e-6, rel=1e-12) and sum(s.dt for s in steps) == pytest.approx(30e-6)
    assert all(0 < s.dt <= s.dt_stable for s in steps)
    assert steps[-1].energy.balance_error == pytest.approx(run.summary["energy"]["balance_error"], rel=1e-12)
    assert steps[1].energy.external < steps[-1].energy.external          # copies, not the solver's account
    with pytest.raises(AttributeError):
        steps[-1].t = 0.0                                                # the record is frozen
    t, vz = run.history["time"], run.history["bar.v_z"]
    assert run.units["time"] == "s" and run.units["bar.v_z"] == "m/s" and run.units["energy.kinetic"] == "J"
    c0 = math.sqrt(210e9 / 7850)
    assert vz[-1] == pytest.approx(2.0 * c0 * t[-1] / 0.3, rel=0.02)
    with pytest.raises(ValueError):
        vz[0] = 1.0                                   # histories are read-only
    assert run.fields and run.fields.endswith("fields.xdmf") and os.path.exists(run.fields)
    again = shockfem.load_run(run.path)
    assert again.summary == run.summary and (again.history["bar.v_z"] == vz).all()
    assert again.scene["bodies"][0]["name"] == "bar"


def test_load_scene_from_a_file_with_overrides():
    scene = shockfem.load_scene(BAR, ['boundary.0.value = "3 m/s"', 'scene.end_time = "20 us"'])
    assert scene.end_time == pytest.approx(20e-6) and scene.boundaries[0].history[0][1] == pytest.approx(3.0)


def test_bad_input_is_a_scene_error_naming_the_field(tmp_path):
    raw = _short_bar()
    raw["bodies"][0]["radius"] = "-1 mm"
    with pytest.raises(SceneError, match="radius"):
        shockfem.load_scene(raw)
    with pytest.raises(FileNotFoundError, match="not a run directory"):
        shockfem.load_run(str(tmp_path))


def test_load_run_reads_without_dolfinx_or_numba(tmp_path):
    """``load_run`` is the light reader of run directories: a fresh interpreter reads a run back
    without importing dolfinx, numba, petsc4py, mpi4py or gmsh."""
    import subprocess
    import sys
    run = shockfem.run(shockfem.load_scene(os.path.join(REPO, "studies", "foundation", "bar_impact.toml"),
                                           ['scene.end_time="5 us"']), str(tmp_path / "bar"), fields=False)
    code = ("import sys, shockfem\n"
            f"r = shockfem.load_run({run.path!r})\n"
            "assert r.status == 'completed' and len(r.history['time']) > 1\n"
            "print([m for m in ('dolfinx', 'numba', 'petsc4py', 'mpi4py', 'gmsh') if m in sys.modules])")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert done.stdout.strip() == "[]"

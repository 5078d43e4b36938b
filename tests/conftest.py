import os
import subprocess
import sys
import tempfile
import time

import pytest

# Open MPI refuses root without these; the parallel verification case calls mpirun.
os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
os.environ.setdefault("OMPI_MCA_rmaps_base_oversubscribe", "1")
# No pictures of the deformed shape in every run (about 1.5 s each); tests/sim/test_paraview.py draws them
os.environ.setdefault("SHOCKFEM_PICTURES", "0")


@pytest.fixture(autouse=True)
def _mesh_cache(tmp_path_factory, monkeypatch):
    """Keep test meshes out of the repository's meshes/ cache."""
    monkeypatch.setenv("SHOCKFEM_MESH_CACHE", str(tmp_path_factory.getbasetemp() / "meshes"))


def pytest_collection_modifyitems(items):
    """The tests marked ``long`` (minutes each) first: the suite runs on two workers (pytest-xdist), and a
    long test handed out last would leave one of them idle while it runs."""
    items.sort(key=lambda item: item.get_closest_marker("long") is None)


@pytest.hookimpl(tryfirst=True)
def pytest_sessionstart(session):
    """numba's kernels compiled once, before pytest-xdist starts its workers (``shockfem warm``, one process
    per family, both cores): on a clean checkout the first tests' processes would each compile them.
    Only for a suite on workers (``-n``, as ``make test``); not in the workers themselves, nor with
    ``SHOCKFEM_WARM=0``."""
    workers = getattr(session.config.option, "numprocesses", None)
    if not workers or hasattr(session.config, "workerinput") or os.environ.get("SHOCKFEM_WARM", "1") == "0":
        return
    t0 = time.perf_counter()
    with tempfile.TemporaryDirectory() as meshes:       # the warm-up's meshes out of the repository's cache
        env = dict(os.environ, SHOCKFEM_MESH_CACHE=meshes)
        families = ("axisymmetric", "3d")
        procs = [subprocess.Popen([sys.executable, "-m", "shockfem", "warm", family], stdout=subprocess.PIPE,
                                  stderr=subprocess.STDOUT, text=True, env=env) for family in families]
        for family, proc in zip(families, procs):
            out, _ = proc.communicate()
            if proc.returncode != 0:          # the tests that run these kernels will say what is wrong
                sys.stderr.write(f"shockfem warm {family} failed:\n{out[-2000:]}\n")
    sys.stderr.write(f"numba kernels compiled or loaded in {time.perf_counter() - t0:.0f} s (shockfem warm)\n")

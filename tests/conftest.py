import os

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

"""shockfem: a finite-element impact workbench on FEniCSx (dolfinx) for shock-machine design.

The Python API (``docs/api.md``): ``load_scene``, ``run``, ``resume``, ``load_run`` and the ``Run`` they return,
``sweep`` for a batch of runs, ``import_deck`` for an LS-DYNA deck or an Abaqus mesh as a scene.
They load on first use, so that ``import shockfem`` stays light.
"""
from .numba_cache import drop_stale_caches
from .version import __version__

# before any module of the package compiles or loads a compiled function: numba's own check of a cache
# sees only its module's file, not the modules it calls into (``numba_cache.py``)
drop_stale_caches()

__all__ = ["__version__", "load_scene", "run", "resume", "load_run", "Run", "sweep", "import_deck"]


def __getattr__(name):
    if name in ("load_scene", "run", "resume", "load_run", "Run", "sweep", "import_deck"):
        from . import api
        return getattr(api, name)
    raise AttributeError(f"module 'shockfem' has no attribute {name!r}")

"""dolfinx imported without setuptools' ``pkg_resources``, 0.1 s of every run's start.

ufl and ffcx (which dolfinx imports) each ask ``pkg_resources.get_distribution(name).version`` for their
own version, and importing ``pkg_resources`` scans every installed distribution first: 0.10-0.11 s here
(``python -c "import pkg_resources"``), a third of dolfinx's import.  ``import_dolfinx`` imports dolfinx
with a stand-in under that name which answers that one question from ``importlib.metadata``, and hands
anything else (another attribute, a distribution it cannot find) to the real ``pkg_resources``.  The
stand-in is taken out of ``sys.modules`` as soon as dolfinx is in, so that a later ``import
pkg_resources`` gets the real one; ufl and ffcx keep the stand-in as their module attribute.
"""
from __future__ import annotations

import importlib
import importlib.metadata
import sys
import types


class _Version:
    """What ``pkg_resources.get_distribution`` returns, as far as ufl and ffcx read it."""

    def __init__(self, version: str):
        self.version = version


class _VersionLookup(types.ModuleType):
    """``pkg_resources`` as ufl and ffcx use it while they are imported."""

    def get_distribution(self, name: str):
        try:
            return _Version(importlib.metadata.version(name))
        except Exception:                   # not found this way: the real one answers, or says why not
            return _real().get_distribution(name)

    def __getattr__(self, name: str):
        return getattr(_real(), name)


def _real():
    """The real ``pkg_resources`` (imported now if the stand-in holds its place)."""
    if isinstance(sys.modules.get("pkg_resources"), _VersionLookup):
        del sys.modules["pkg_resources"]
    return importlib.import_module("pkg_resources")


def import_dolfinx():
    """Import dolfinx (after ``mpi_start.start_mpi``: dolfinx imports mpi4py); the stand-in only where
    ``pkg_resources`` is not imported yet."""
    if "dolfinx" in sys.modules:
        return
    if "pkg_resources" in sys.modules:
        importlib.import_module("dolfinx")
        return
    sys.modules["pkg_resources"] = _VersionLookup("pkg_resources")
    try:
        importlib.import_module("dolfinx")
    finally:
        if isinstance(sys.modules.get("pkg_resources"), _VersionLookup):
            del sys.modules["pkg_resources"]

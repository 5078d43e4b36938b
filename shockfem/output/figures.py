"""Matplotlib and pyvista for pictures saved to files, set up when the first one is made (not on import).

* The Agg backend, unless the user chose one (``MPLBACKEND``) or has pyplot loaded already
  (a notebook keeps its own).
* Without the "Unable to import Axes3D" warning matplotlib prints when Debian's python3-matplotlib
  sits beside the venv's (installing ParaView brings it): shockfem draws no 3D axes, and a user can
  do nothing about the warning.  pyvista imports matplotlib too.
* Without VTK's "bad X server connection" log line on a machine with no display: pyvista renders
  off screen there and the picture is written all the same.
"""
from __future__ import annotations

import os
import sys
import warnings


def pyplot():
    """``matplotlib.pyplot``, ready to draw figures to files."""
    import matplotlib
    if "matplotlib.pyplot" not in sys.modules and "MPLBACKEND" not in os.environ:
        matplotlib.use("Agg")
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", message="Unable to import Axes3D")
        import matplotlib.pyplot as plt
    return plt


def pyvista():
    """``pyvista``, ready to render off screen to files."""
    pyplot()                        # pyvista imports matplotlib: set it up (and quiet) first
    import pyvista as pv
    # the one VTK module needed, not ``import vtk``, which loads every module VTK has (1.5 s)
    from vtkmodules.vtkCommonCore import vtkLogger
    if not os.environ.get("DISPLAY"):
        vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)
    return pv


def save(fig, path: str, close: bool = True) -> str:
    """Write ``fig`` to the PNG ``path`` (tight layout, 110 dpi) and close it (unless ``close`` is false: a
    figure drawn on again); returns the path."""
    fig.tight_layout()
    partial = partial_path(path)
    fig.savefig(partial, dpi=110)
    if close:
        pyplot().close(fig)
    os.replace(partial, path)
    return path


def partial_path(path: str) -> str:
    """Where a picture is drawn before it is renamed to ``path`` (same extension, so the writer keeps its
    format): a run killed mid-write leaves no half picture under the real name."""
    stem, ext = os.path.splitext(path)
    return f"{stem}.partial{ext}"

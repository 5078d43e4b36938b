"""Matplotlib for figures saved to files, set up when the first figure is made (not on import).

* The Agg backend, unless the user chose one (``MPLBACKEND``) or has pyplot loaded already
  (a notebook keeps its own).
* Without the "Unable to import Axes3D" warning matplotlib prints when Debian's python3-matplotlib
  sits beside the venv's (installing ParaView brings it): shockfem draws no 3D axes, and a user can
  do nothing about the warning.
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


def save(fig, path: str) -> str:
    """Write ``fig`` to the PNG ``path`` (tight layout, 110 dpi) and close it; returns the path."""
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    pyplot().close(fig)
    return path

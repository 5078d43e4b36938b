"""Scenes shockfem generates, written as TOML by tomli-w, to hand a scene to the CLI.

tomli-w writes Python's own types; a study computes with numpy, so its numbers (``np.float64`` is a
float, ``np.int64`` and arrays are not) are turned into Python's first."""
from __future__ import annotations

import numpy as np
import tomli_w


def _plain(value):
    """``value`` with numpy's numbers and arrays turned into Python's, through dicts, lists and tuples."""
    if isinstance(value, (np.generic, np.ndarray)):
        return value.tolist()
    if isinstance(value, dict):
        return {k: _plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    return value


def dumps(scene: dict) -> str:
    """``scene`` (tables, arrays of tables, strings, numbers, booleans, lists) as TOML text."""
    return tomli_w.dumps(_plain(scene))

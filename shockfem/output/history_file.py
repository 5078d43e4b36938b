"""Reading a run's ``history.csv`` back: its columns as arrays and their units.  Light on purpose (csv and
numpy only): ``shockfem.load_run`` and the metrics read run directories without dolfinx or numba."""
from __future__ import annotations

import csv

import numpy as np


def read_history(path: str) -> tuple[dict[str, np.ndarray], dict[str, str]]:
    """(columns, units) of a ``history.csv``: arrays and units keyed by the column name, whose header
    is written as "name [unit]"."""
    with open(path) as fh:
        text = fh.read()
    lines = text.splitlines()
    if not text.endswith("\n"):
        lines = lines[:-1]          # a run killed mid-write left its last row cut short: only whole rows
    header = next(csv.reader(lines[:1]))
    whole = [line for line in lines[1:] if line.count(",") == len(header) - 1]
    data = np.loadtxt(whole, delimiter=",", ndmin=2) if whole else np.zeros((0, len(header)))
    names, units = zip(*(h[:-1].rsplit(" [", 1) for h in header))
    return {n: data[:, j] for j, n in enumerate(names)}, dict(zip(names, units))


def read_history_csv(path: str) -> dict[str, np.ndarray]:
    """Columns of a ``history.csv`` keyed by name without the unit."""
    return read_history(path)[0]

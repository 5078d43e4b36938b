"""Each body's peak von Mises stress, read from the element pass's rows (``elements.blocks.track_peak``; the
pass's own peak is tested in ``tests/unit/elements``)."""
from types import SimpleNamespace

import numpy as np
import pytest

from shockfem.elements import blocks
from shockfem.output.peak_stress import PeakStress


def _solver(peak, cell_body, cell_material, kernel_cells):
    X0 = np.arange(len(cell_body) + 1, dtype=float)[:, None] * np.array([[1.0, 0.5]])
    dofmap = np.stack([np.arange(len(cell_body)), np.arange(len(cell_body)) + 1], axis=1)
    model = SimpleNamespace(bodies=[0, 1, 2], kernel_cells=kernel_cells, cell_body=cell_body,
                            cell_material=cell_material, X0=X0, dofmap=dofmap, comm=SimpleNamespace(size=1))
    return SimpleNamespace(model=model, peak=peak)


def test_each_body_takes_the_highest_of_its_rows_with_when_and_where():
    """Three bodies (the third rigid: no kernel cells); body 0's cells 0-2 on row 0 and, mass-scaled, cell 2 on
    row 3; body 1's on row 1.  Body 0's peak is its scaled row's (higher), body 1's its own row's; the rigid
    body has none; a checkpoint's state gives the same."""
    cell_body = np.array([0, 0, 0, 1, 1, 2], dtype=np.int32)
    cell_material = np.array([0, 0, 3, 1, 1, 2], dtype=np.int32)
    peak = blocks.no_peak(4)
    peak[0] = 150.0 ** 2, 3e-6, 0
    peak[3] = 200.0 ** 2, 2e-6, 2
    peak[1] = 300.0 ** 2, 1e-6, 4
    peaks = PeakStress(_solver(peak, cell_body, cell_material, np.arange(5)), {"rows": peak.copy()})
    out = peaks.per_body()
    assert out[0]["max_von_mises"] == pytest.approx(200.0, rel=1e-15) and out[0]["time"] == 2e-6
    assert out[0]["at"] == pytest.approx([2.5, 1.25])          # cell 2's reference centre
    assert out[1]["max_von_mises"] == pytest.approx(300.0, rel=1e-15) and out[1]["time"] == 1e-6
    assert out[1]["at"] == pytest.approx([4.5, 2.25])
    assert out[2] == {"max_von_mises": 0.0, "time": None, "at": None}
    fresh = blocks.no_peak(4)
    again = PeakStress(_solver(fresh, cell_body, cell_material, np.arange(5)), peaks.state())     # from a checkpoint
    assert again.per_body() == out and np.array_equal(fresh, peak)


def test_a_body_without_stress_has_no_peak():
    cell_body = np.array([0, 1], dtype=np.int32)
    peaks = PeakStress(_solver(blocks.no_peak(3), cell_body, cell_body, np.arange(2)))
    assert [p["at"] for p in peaks.per_body()] == [None, None, None]


def test_a_run_counts_its_peaks_from_its_start():
    """What the pass saw before the run's loop (the solver's set-up, a preload stage's settling) is dropped."""
    cell_body = np.array([0, 1], dtype=np.int32)
    peak = blocks.no_peak(3)
    peak[0] = 1e4, -1e-3, 1
    PeakStress(_solver(peak, cell_body, cell_body, np.arange(2)))
    assert np.array_equal(peak, blocks.no_peak(3))

"""The per-step peak von Mises pass against ``cell_fields.von_mises``, the numpy form it compiles."""
from types import SimpleNamespace

import numpy as np
import pytest

from shockfem.output.cell_fields import von_mises
from shockfem.output.peak_stress import PeakStress, largest_von_mises2, where_largest


def _solver(sigma, cell_body, kernel_cells):
    X0 = np.arange(len(cell_body) + 1, dtype=float)[:, None] * np.array([[1.0, 0.5]])
    dofmap = np.stack([np.arange(len(cell_body)), np.arange(len(cell_body)) + 1], axis=1)
    model = SimpleNamespace(bodies=[0, 1, 2], kernel_cells=kernel_cells, cell_body=cell_body, X0=X0, dofmap=dofmap,
                            comm=SimpleNamespace(size=1))
    return SimpleNamespace(model=model, sigma=sigma)


def test_the_compiled_pass_finds_the_numpy_peak_and_its_cell():
    rng = np.random.default_rng(3)
    sigma = rng.standard_normal((50, 4, 6)) * 1e8
    cells = np.arange(50, dtype=np.int64)[::3]
    vm = von_mises(sigma[cells])
    # the same formula in another order: round-off of 1e16 Pa^2
    assert largest_von_mises2(sigma, cells) == pytest.approx(vm.max() ** 2, rel=1e-12)
    assert where_largest(sigma, cells, largest_von_mises2(sigma, cells)) == cells[np.argmax(vm.max(axis=1))]


def test_each_body_keeps_its_peak_with_when_and_where():
    """Three bodies (the third rigid: no kernel cells); the stresses of three steps, the peak of body 0 in its
    second, of body 1 in its first."""
    cell_body = np.array([0, 0, 0, 1, 1, 2], dtype=np.int32)
    sigma = np.zeros((6, 1, 6))
    peaks = PeakStress(_solver(sigma, cell_body, np.arange(5)))
    steps = [{4: 300.0, 1: 100.0}, {2: 200.0, 3: 50.0}, {0: 150.0}]
    for k, uniaxial in enumerate(steps):
        sigma[:] = 0.0
        for c, s in uniaxial.items():
            sigma[c, 0, 0] = s                      # uniaxial: von Mises = |s|
        peaks.update(1e-6 * (k + 1))
    out = peaks.per_body()
    assert out[0]["max_von_mises"] == pytest.approx(200.0, rel=1e-14) and out[0]["time"] == 2e-6
    assert out[0]["at"] == pytest.approx([2.5, 1.25])          # cell 2's reference centre
    assert out[1]["max_von_mises"] == pytest.approx(300.0, rel=1e-14) and out[1]["time"] == 1e-6
    assert out[2] == {"max_von_mises": 0.0, "time": None, "at": None}
    again = PeakStress(_solver(sigma, cell_body, np.arange(5)), peaks.state())      # from a checkpoint
    assert again.per_body() == out

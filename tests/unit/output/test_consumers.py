"""The consumers of the time loop's steps (``output/consumers.py``), each at its cadence, on hand-made steps:
a history row every interval and at the end time, a checkpoint every interval but not at the end, the stop
rules following the plastic work from step to step."""
from types import SimpleNamespace

import numpy as np
import pytest

from shockfem.errors import UnstableRun
from shockfem.output.consumers import Cadence, Checkpoints, HistoryRows, LoopState, StopRules
from shockfem.solver.explicit import Energies, Step


def _steps(dt, end, **energies):
    """Steps of ``dt`` to ``end`` as the solver yields them: t summed step by step (with its round-off)."""
    t, n = 0.0, 0
    while t < end * (1 - 1e-12):
        h = min(dt, end - t)
        t += h
        n += 1
        yield Step(n, t, h, h, Energies(initial=1.0, peak=1.0, **energies))


class _History:
    def __init__(self):
        self.times = []

    def record(self, t=None):
        self.times.append(t)


def test_history_rows_every_interval_and_at_the_end():
    history = _History()
    rows = HistoryRows(history, Cadence(1e-6, 1e-6), end_time=3.5e-6)
    taken = []
    for s in _steps(0.1e-6, 3.5e-6):
        before = len(history.times)
        rows(s)
        if len(history.times) > before:
            taken.append(round(s.t * 1e7))
    # at 1, 2, 3 us (a sum of ten 0.1 us steps lands within round-off of each) and at the end, 3.5 us
    assert taken == [10, 20, 30, 35]


def test_a_zero_interval_records_every_step():
    history = _History()
    rows = HistoryRows(history, Cadence(0.0, 0.0), end_time=1e-6)
    steps = list(_steps(0.25e-6, 1e-6))
    for s in steps:
        rows(s)
    assert len(history.times) == len(steps) == 4


def test_checkpoints_every_interval_but_not_at_the_end():
    saved = []
    checkpoints = Checkpoints(lambda: saved.append(1) or 0.5, Cadence(1e-6, 1e-6), end_time=3e-6)
    for s in _steps(0.3e-6, 3e-6):
        checkpoints(s)
    # due at 1.2 and 2.1 us (the first steps at or past 1 and 2 us); 3 us is the end: the run completes there
    assert len(saved) == 2 and checkpoints.wall_time == pytest.approx(1.0)
    checkpoints.now()
    assert len(saved) == 3


def test_no_checkpoints_with_a_zero_interval():
    checkpoints = Checkpoints(lambda: pytest.fail("no checkpoint was asked for"), Cadence(0.0, 0.0), 1e-6)
    for s in _steps(0.1e-6, 1e-6):
        checkpoints(s)


def test_the_stop_rules_follow_the_plastic_work():
    loop = LoopState.start(SimpleNamespace(history_interval=0.0, field_interval=1.0), 0.0)
    rules = StopRules(loop, balance_limit=0.05)
    rules(next(_steps(1e-6, 1e-6, plastic=0.2, internal=-0.2, kinetic=1.0)))
    assert loop.plastic_before == 0.2
    with pytest.raises(UnstableRun, match="plastic work fell"):
        rules(next(_steps(1e-6, 1e-6, plastic=0.1, internal=-0.1, kinetic=1.0)))


def test_the_loop_state_starts_one_interval_on():
    loop = LoopState.start(SimpleNamespace(history_interval=2e-6, field_interval=1e-5), 3e-5)
    assert (loop.history.next, loop.fields.next, loop.checkpoint.next) == (2e-6, 1e-5, 3e-5)
    assert loop.peak_stress is None and loop.balance_at_start_up == 0.0 and loop.resumed == []

"""What a run does with each step: consumers of the solver's step generator, each at its own cadence.

The run loop is

    for step in solver.steps(end_time):
        for consume in consumers:
            consume(step)

and every consumer is a callable of the read-only ``Step``: the history's rows, the field frames, the stop
rules (``solver/guards.py``), the log of the solver's messages, the checkpoints, the API's ``on_step``, the
signal check and the progress bar.  (The bodies' peak von Mises stress needs none: the element pass keeps it
every step, ``peak_stress.py``.)
What the loop must carry across a checkpoint (when each cadence is next due, the running peaks) is one
``LoopState``, pickled whole with the checkpoint.
"""
from __future__ import annotations

import sys
from dataclasses import dataclass, field

from ..solver import guards

# a time counts as reached within this share of it (a sum of steps lands a few ulps short of a cadence's time)
DUE_SHARE = 1e-9


@dataclass
class Cadence:
    """Every ``interval`` of simulated time [s]: due once t reaches ``next``."""
    interval: float
    next: float

    def due(self, t: float) -> bool:
        return t >= self.next * (1 - DUE_SHARE)


@dataclass
class LoopState:
    """What the run loop carries from step to step, and a checkpoint keeps."""
    history: Cadence
    fields: Cadence
    checkpoint: Cadence
    peak_stress: dict | None = None  # this rank's running peaks (``PeakStress.state``), at a checkpoint
    plastic_before: float = 0.0      # the plastic work at the step before [J] (``guards.plastic_work_fell``)
    balance_at_start_up: float = 0.0  # |energy balance| at the start-up's last step [J] (``guards.balance_beyond``)
    wall: float = 0.0                # wall time of the loop before a resume [s]
    resumed: list = field(default_factory=list)

    @classmethod
    def start(cls, outputs, checkpoint_interval: float) -> "LoopState":
        """At t = 0: each cadence first due one interval on."""
        return cls(Cadence(outputs.history_interval, outputs.history_interval),
                   Cadence(outputs.field_interval, outputs.field_interval),
                   Cadence(checkpoint_interval, checkpoint_interval))


class HistoryRows:
    """A history row every ``history`` interval and at the end time (``output/history.py``).  Collective."""

    def __init__(self, history, cadence: Cadence, end_time: float):
        self.history, self.cadence, self.end_time = history, cadence, end_time

    def __call__(self, s):
        if self.cadence.due(s.t) or s.t >= self.end_time * (1 - 1e-12):
            self.history.record()
            self.cadence.next += self.cadence.interval


class FieldFrames:
    """Every ``fields`` interval, a frame of the fields when they are written (``writer``, or None).
    Collective."""

    def __init__(self, writer, cadence: Cadence):
        self.writer, self.cadence = writer, cadence

    def __call__(self, s):
        if self.cadence.due(s.t):
            if self.writer:
                self.writer.write(s.t)
            self.cadence.next += self.cadence.interval


class StopRules:
    """The run's stop rules on every step (``guards.check_step``), with the plastic work they follow."""

    def __init__(self, loop: LoopState, balance_limit: float):
        self.loop, self.balance_limit = loop, balance_limit

    def __call__(self, s):
        if s.step == guards.START_UP_STEPS:
            self.loop.balance_at_start_up = abs(s.energy.balance)
        guards.check_step(s, self.loop.plastic_before, self.balance_limit, self.loop.balance_at_start_up)
        self.loop.plastic_before = s.energy.plastic


class Checkpoints:
    """A checkpoint every ``checkpoint`` interval before the end time (none if the interval is 0):
    ``save()`` writes it and returns its wall time [s], summed in ``wall_time``.  Collective."""

    def __init__(self, save, cadence: Cadence, end_time: float):
        self.save, self.cadence, self.end_time = save, cadence, end_time
        self.wall_time = 0.0

    def __call__(self, s):
        if self.cadence.interval > 0 and self.cadence.due(s.t) and s.t < self.end_time * (1 - 1e-12):
            while self.cadence.next <= s.t * (1 + DUE_SHARE):
                self.cadence.next += self.cadence.interval
            self.wall_time += self.save()

    def now(self):
        """A checkpoint at the step just finished, out of cadence (a run stopped by a signal)."""
        self.wall_time += self.save()


class ProgressBar:
    """A tqdm bar of simulated time in microseconds, on stderr, renewed every ``EVERY`` steps."""

    EVERY = 50

    def __init__(self, total: float, t: float):
        from tqdm import tqdm
        # (tqdm writes its own ", " before a postfix)
        self.bar = tqdm(total=total * 1e6, unit="us", unit_scale=False, dynamic_ncols=True, file=sys.stderr,
                        bar_format="{l_bar}{bar}| {n:.1f}/{total:.1f} us [{elapsed}<{remaining}{postfix}]",
                        mininterval=0.5)
        self.bar.n = t * 1e6

    def __call__(self, s):
        if s.step % self.EVERY == 0:
            self.bar.n = s.t * 1e6
            self.bar.set_postfix_str(f"step {s.step}, dt {s.dt:.3g} s, E err {s.energy.balance_error:.1e}",
                                     refresh=False)
            self.bar.update(0)

    def close(self, t: float):
        self.bar.n = t * 1e6
        self.bar.close()

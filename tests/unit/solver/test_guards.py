"""The stop rules (``solver/guards.py``): each stops on its own condition and only on it, names the time
and the step, and a NaN falls through to the check that names it.  The steps are built by hand: a
``Step`` with its energy account (``solver/explicit.py``)."""
import math
from types import SimpleNamespace

import numpy as np
import pytest

from shockfem.errors import UnstableRun
from shockfem.solver import guards
from shockfem.solver.explicit import Energies, Step

LARGEST = 10.0      # [J], the largest energy in play of every step below


def _step(step=100, **energies):
    e = Energies(initial=LARGEST, peak=LARGEST, kinetic=LARGEST, **energies)
    return Step(step=step, t=1e-4, dt=1e-7, dt_stable=1e-7, energy=e)


def test_plastic_work_may_stay_but_not_fall():
    guards.plastic_work_fell(_step(plastic=2.0, internal=-2.0), plastic_before=2.0)
    # a fall within the round-off share of the largest energy is summation noise
    guards.plastic_work_fell(_step(plastic=2.0, internal=-2.0), plastic_before=2.0 + 0.5e-9 * LARGEST)
    with pytest.raises(UnstableRun, match="plastic work fell from 3 J to 2 J at t = 0.0001 s .step 100."):
        guards.plastic_work_fell(_step(plastic=2.0, internal=-2.0), plastic_before=3.0)


def test_a_non_finite_balance_stops_and_falls_through_the_others():
    nan = _step(plastic=math.nan)
    guards.plastic_work_fell(nan, plastic_before=1.0)         # not its business: NaN is no fall
    guards.balance_beyond(nan, limit=0.01, at_start_up=0.0)
    with pytest.raises(UnstableRun, match="not finite"):
        guards.energy_not_finite(nan)
    with pytest.raises(UnstableRun, match="not finite"):
        guards.check_step(nan, plastic_before=1.0, balance_limit=0.01, balance_at_start_up=0.0)


def test_the_balance_limit_holds_after_the_start_up():
    # a balance of 0.5 J over the largest 10 J: 5%
    off = dict(external=-0.5)
    guards.balance_beyond(_step(**off), limit=0.06, at_start_up=0.0)
    guards.balance_beyond(_step(step=guards.START_UP_STEPS, **off), limit=0.01, at_start_up=0.0)
    with pytest.raises(UnstableRun, match="energy balance error 0.05 exceeds the limit 0.01"):
        guards.balance_beyond(_step(**off), limit=0.01, at_start_up=0.0)


def test_a_grown_imbalance_is_energy_being_created_and_a_flat_one_does_not_advise_a_shorter_step():
    """0.5 J of imbalance over the largest 10 J: grown from 1 mJ at the start-up's end it is an instability
    (lower the safety factor); at 0.4 J then, it has not grown (a shrink fit's flat start-up imbalance, whose
    energy scale was not known, read so): no shorter step is advised."""
    off = dict(external=-0.5)
    with pytest.raises(UnstableRun, match="energy is being created.*Lower scene.safety_factor"):
        guards.balance_beyond(_step(**off), limit=0.01, at_start_up=1e-3)
    with pytest.raises(UnstableRun, match="not an instability of the step") as stop:
        guards.balance_beyond(_step(**off), limit=0.01, at_start_up=0.4)
    assert "safety_factor" not in stop.value.diagnosis and "energy_error_limit" in stop.value.diagnosis


def _solver(dt_stable, internal=0.0, step=100):
    """What the solver's guards read of a solver, with its diagnosis helpers."""
    return SimpleNamespace(dt_stable=dt_stable, dt_first=1e-6, t=2e-4, step=step, critical_cell=7,
                           energy=Energies(initial=LARGEST, peak=LARGEST, internal=internal),
                           critical_cell_said=lambda: ", body 'bar', element 7",
                           body_of_cell=lambda cell: "bar",
                           body_energies=lambda: {"internal": np.array([internal]), "plastic": np.zeros(1)},
                           model=SimpleNamespace(bodies=[SimpleNamespace(name="bar")]))


def test_a_collapsed_step_stops_naming_the_element():
    guards.step_collapse(_solver(1.01 * guards.STEP_COLLAPSE * 1e-6))
    guards.step_collapse(_solver(math.nan))                  # the non-finite checks name a NaN
    with pytest.raises(UnstableRun, match="collapsed from 1e-06 s to 5e-10 s.*element 7") as info:
        guards.step_collapse(_solver(5e-10))
    assert (info.value.body, info.value.element) == ("bar", 7)


def test_stored_energy_below_the_limit_stops_after_the_start_up():
    below = -2 * guards.ENERGY_CREATED * LARGEST
    guards.energy_created(_solver(1e-6, internal=-0.5 * guards.ENERGY_CREATED * LARGEST))
    guards.energy_created(_solver(1e-6, internal=below, step=guards.START_UP_STEPS))
    with pytest.raises(UnstableRun, match="stored energy fell to -0.2 J .-2.00% of the run's largest"):
        guards.energy_created(_solver(1e-6, internal=below))

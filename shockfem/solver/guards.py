"""The stop rules of a run: each one small check, which raises ``UnstableRun`` with a diagnosis (what
happened, where, and the fix) when the run has gone where no answer can come from.  Each is written as
"stop unless the condition holds" with the comparison that stops, so that a NaN falls through to the
check that names it (``energy_not_finite``, or the solver's non-finite state).

The solver's own (``ExplicitSolver.steps`` checks them around every step, so that any loop over the
steps has them):

    step_collapse      before a step: the elements' stable step has fallen below STEP_COLLAPSE of its
                       first value (an element crushed flat)
    energy_created     after a step: the elements' stored energy is below -ENERGY_CREATED of the run's
                       largest energy (a crushed element turned inside out gives back more than it took)

The run's (``runner``: on every ``Step`` the solver yields, in this order):

    plastic_work_fell  the plastic work fell beyond round-off: a material update created energy
    energy_not_finite  the energy balance overflowed or went NaN
    balance_beyond     the energy balance error exceeds ``scene.energy_error_limit``

A non-finite state and an inverted element are caught inside the step (``ExplicitSolver``), where the
node or cell is known.
"""
from __future__ import annotations

import math

import numpy as np

from ..errors import UnstableRun

# A run stops when the elements' stable step falls below this share of its first value: an element
# is being crushed flat, and the run would otherwise crawl on for millions of steps.
STEP_COLLAPSE = 1e-3
# ... or when the stored (elastic) energy falls below minus this share of the run's largest energy: the
# elements have given back more work than they took, which no material does; a crushed element whose
# hourglass modes turned it inside out while its centre's Jacobian stayed positive does (a copper bar
# at 3 km/s on a wall: -5% by the end, with its step 2.3e-3 of its first value, above STEP_COLLAPSE).
# The end-of-run warning (``runner.NEGATIVE_INTERNAL``) flags far smaller falls.
ENERGY_CREATED = 1e-2
# Energy checks start after this many steps: a run from rest has energies of round-off size at first,
# and the half-step account's first terms are of their order (a cone pushed from rest: the stored energy
# -20% of the largest at step 2, -1.4% at step 6, never below -1e-5 after step 20).
START_UP_STEPS = 20
# Plastic work is dissipated, never given back: a fall larger than this share of the largest energy is
# not round-off of the sum
PLASTIC_ROUND_OFF = 1e-9
# An energy balance that has grown less than this factor since the start-up steps is not growing: a fixed
# error of the account (a force switched on within a step), not an instability, which grows step by step
BALANCE_GROWTH = 2.0


# ------------------------------------------------------------------ the solver's
def step_collapse(solver) -> None:
    """Before a step: stop when the elements' stable step has collapsed (an element crushed flat)."""
    if not solver.dt_stable < STEP_COLLAPSE * solver.dt_first:
        return
    raise UnstableRun(f"the stable time step collapsed from {solver.dt_first:.3g} s to {solver.dt_stable:.3g} s "
                      f"(below {STEP_COLLAPSE:g} of its first value): an element is crushed"
                      f"{solver.critical_cell_said()}",
                      solver.t, solver.body_of_cell(solver.critical_cell), solver.critical_cell)


def energy_created(solver) -> None:
    """After a step (past the start-up): stop when the elements' stored energy has gone below
    -ENERGY_CREATED of the run's largest energy.  Collective when it stops (the bodies' energies)."""
    e = solver.energy
    if not (solver.step > START_UP_STEPS and e.internal < -ENERGY_CREATED * e.largest):
        return
    largest = e.largest
    energies = solver.body_energies()
    stored = energies["internal"] - energies["plastic"]
    body = solver.model.bodies[int(np.argmin(stored))].name
    raise UnstableRun(f"the elements' stored energy fell to {e.internal:.4g} J ({e.internal / largest:.2%} of the "
                      f"run's largest energy, {largest:.4g} J; the limit is -{ENERGY_CREATED:.0%}): elements gave "
                      f"back more work than they took, as a crushed element turned inside out does (the lowest: "
                      f"body '{body}', {stored.min():.4g} J). The stable step is {solver.dt_stable:.3g} s, "
                      f"{solver.dt_stable / solver.dt_first:.2g} of its first value, set by the most crushed element"
                      f"{solver.critical_cell_said()}",
                      solver.t, solver.body_of_cell(solver.critical_cell), solver.critical_cell)


# ------------------------------------------------------------------ the run's
def plastic_work_fell(s, plastic_before: float) -> None:
    """Stop when the plastic work of the ``Step`` ``s`` is below the step before's, ``plastic_before`` [J],
    by more than round-off: a material update is creating energy that the balance cannot see (the plastic
    term absorbs it)."""
    if not s.energy.plastic < plastic_before - PLASTIC_ROUND_OFF * s.energy.largest:
        return
    raise UnstableRun(
        f"the plastic work fell from {plastic_before:.6g} J to {s.energy.plastic:.6g} J at "
        f"t = {s.t:.6g} s (step {s.step}): a material update is creating energy (an element crushed "
        f"beyond its material's curve, or inverting). Check the impact speed against the "
        f"material, refine the mesh there, or lower scene.safety_factor.", s.t)


def energy_not_finite(s) -> None:
    """Stop when the energy balance of the ``Step`` ``s`` is not finite."""
    if math.isfinite(s.energy.balance_error):
        return
    raise UnstableRun(
        f"the energy balance is not finite ({s.energy.balance_error}) at t = {s.t:.6g} s (step "
        f"{s.step}): an energy term overflowed or went NaN (a material or a load beyond range). "
        f"Check the scene's magnitudes (density, moduli, speeds, loads).", s.t)


def balance_beyond(s, limit: float, at_start_up: float) -> None:
    """Stop when the energy balance error of the ``Step`` ``s`` exceeds ``limit`` (past the start-up), with
    its diagnosis: an imbalance grown more than ``BALANCE_GROWTH`` times since the start-up's last step
    (|balance| ``at_start_up`` [J] then) is energy being created, which a shorter step cures; one that has
    stayed where it was is not the step's doing, and the stop does not advise a shorter step."""
    if not (s.step > START_UP_STEPS and s.energy.balance_error > limit):
        return
    e = s.energy
    where = (f"energy balance error {e.balance_error:.3g} exceeds the limit {limit:.3g} at t = {s.t:.6g} s "
             f"(step {s.step}; imbalance {e.balance:.3g} J against {e.largest:.3g} J in play)")
    if abs(e.balance) > BALANCE_GROWTH * at_start_up:
        raise UnstableRun(f"{where}: it has grown from {at_start_up:.3g} J at step {START_UP_STEPS}, energy is "
                          "being created, a sign of instability. Lower scene.safety_factor or refine the mesh.",
                          s.t)
    raise UnstableRun(f"{where}: it has not grown since step {START_UP_STEPS} ({at_start_up:.3g} J then), so it "
                      "is not an instability of the step (a shorter step would not help): a force that comes on "
                      "abruptly (a load step, a contact closing with a large penalty) is not resolved by the "
                      "account. Ramp that force in, or raise scene.energy_error_limit if the run's energy is "
                      "expected to stay below this imbalance.", s.t)


def check_step(s, plastic_before: float, balance_limit: float, balance_at_start_up: float) -> None:
    """The run's stop rules on the ``Step`` ``s``, in order."""
    plastic_work_fell(s, plastic_before)
    energy_not_finite(s)
    balance_beyond(s, balance_limit, balance_at_start_up)

"""A plastic run through ``run_scene``: the run directory carries what a plastic run promises (plastic
strain in summary.json and the fields, final deformed shape, plastic and bulk-viscosity energy in
the history) and the per-pair contact force histories."""
import json
import os

import numpy as np
import pytest

from shockfem.errors import UnstableRun
from shockfem.output.history_file import read_history_csv
from shockfem.runner import run_scene
from shockfem.scene import resolve
from shockfem.verify.plasticity_cases import TAYLOR, taylor_scene


def test_taylor_bar_run_directory(tmp_path):
    raw = taylor_scene(0.0004, end_time=40e-6, impact_face="wall")
    result = run_scene(resolve(raw), str(tmp_path), progress=False, quiet=True)
    s = result.summary
    bar = s["bodies"]["bar"]
    # half-way through, the corner has flowed far but the bar is still moving
    assert 1.0 < bar["max_plastic_strain"] < 10.0
    assert s["energy"]["plastic"] > 0.5 * s["energy"]["initial_total"]
    assert s["energy"]["bulk_viscosity"] > 0.0
    assert s["energy"]["balance_error"] < 0.01
    assert any("J2 plasticity, bilinear hardening" in line for line in s["models"])
    for name in ("final_shape.xdmf", "final_shape.h5", "fields.xdmf"):
        assert os.path.exists(tmp_path / name)
    with open(tmp_path / "fields.xdmf") as fh:
        assert 'Name="plastic_strain"' in fh.read()
    h = read_history_csv(str(tmp_path / "history.csv"))
    # contact force history: the wall pushes the bar up, and the impulse equals the momentum it took
    force = h["contact.wall.normal_z"]
    assert force.max() > 0 and abs(h["contact.wall.normal_r"]).max() == 0.0
    assert h["energy.plastic"][-1] == pytest.approx(s["energy"]["plastic"])
    # the wall's impulse is the momentum the bar lost (the only force on it: equal to round-off, since the
    # impulse is integrated as the central-difference update applies the force; measured 0.0 relative, it
    # was 1.07e-3 when it took dt f_n+1), and the sampled force history integrates to it
    momentum_lost = bar["mass"] * (bar["velocity_final"][1] + TAYLOR["speed"])
    impulse = s["contacts"]["wall"]["impulse_on_a"][1]
    assert impulse == pytest.approx(momentum_lost, rel=1e-12)
    assert np.trapz(force, h["time"]) == pytest.approx(impulse, rel=0.03)


def test_crushed_element_stops_the_run_and_keeps_its_outputs(tmp_path):
    """At 3 km/s the copper bar's impact corner crushes and the run stops with the body, element and time
    named, status "unstable" and everything written so far kept.  Which guard stops it depends on round-off
    (the crush is chaotic: 1e-19 m in the face's starting gaps moved it): the stable step collapsing below
    1e-3 of its first value (13.1 us in one such run), or the stored energy falling below -1% of the largest
    (17.7 us in another, the step 1% of its first value: without this guard that run ended "completed" at
    -5%)."""
    raw = taylor_scene(0.0008, impact_face="wall")
    raw["bodies"][0]["velocity"] = [0.0, -3000.0]
    raw["scene"]["end_time"] = 20e-6
    with pytest.raises(UnstableRun) as info:
        run_scene(resolve(raw), str(tmp_path), progress=False, quiet=True)
    message = str(info.value)
    assert "time step collapsed" in message or "stored energy fell" in message
    assert "body 'bar'" in message and "element" in message
    s = json.loads((tmp_path / "summary.json").read_text())
    assert s["status"] == "unstable" and "bar" in s["diagnosis"]
    assert 0.0 < s["end_time"] < 20e-6
    for name in ("fields.xdmf", "history.csv", "final_shape.xdmf"):
        assert (tmp_path / name).exists(), name


def test_stored_energy_below_minus_one_percent_stops_the_run():
    """The guard of ``ExplicitSolver.steps`` by itself (the 3 km/s crush above reaches it or the step's
    collapse, as round-off decides): past the start-up steps, a run whose elements' stored energy stands at
    -2% of the largest energy stops at its next step, naming the body and the element that sets the step; at
    -0.5% it goes on (the limit is 1%: ``guards.ENERGY_CREATED``); within the start-up it goes on (a cone
    pushed from rest is at -20% at step 2: ``verify cone_push``)."""
    from shockfem.geometry import build_mesh
    from shockfem.model import build_model
    from shockfem.solver.explicit import ExplicitSolver
    from shockfem.solver.guards import ENERGY_CREATED, START_UP_STEPS
    raw = taylor_scene(0.0008, end_time=5e-6, impact_face="wall")
    scene = resolve(raw)
    solver = ExplicitSolver(build_model(scene, build_mesh(scene, log=lambda *a: None)))
    steps = solver.steps(scene.end_time)
    next(steps)
    solver.energy.internal = -2.0 * ENERGY_CREATED * solver.energy.initial      # within the start-up
    for _ in range(START_UP_STEPS - 1):
        next(steps)
    # the step adds its own increment to the stored energy (elastic, of order 1e-3 of the initial here)
    solver.energy.internal = -0.5 * ENERGY_CREATED * solver.energy.initial
    next(steps)
    solver.energy.internal = -2.0 * ENERGY_CREATED * solver.energy.initial
    with pytest.raises(UnstableRun) as info:
        next(steps)
    message = str(info.value)
    assert "stored energy fell" in message and "body 'bar'" in message and "element" in message
    assert info.value.body == "bar" and info.value.element is not None


def test_a_nan_in_the_state_stops_the_run_as_unstable():
    """The non-finite guard of ``nodal.finish_step`` must not be compiled with full fastmath, which lets LLVM
    fold ``math.isfinite`` to True, so a NaN would run on to "completed". A NaN velocity put into a running
    bar reaches the accelerations within a step and must stop it, naming the body and the node."""
    from shockfem.geometry import build_mesh
    from shockfem.model import build_model
    from shockfem.solver.explicit import ExplicitSolver
    from shockfem.solver.nodal import finish_step
    raw = taylor_scene(0.0008, end_time=5e-6, impact_face="wall")
    scene = resolve(raw)
    solver = ExplicitSolver(build_model(scene, build_mesh(scene, log=lambda *a: None)))
    solver.v[3, 0] = np.nan
    with pytest.raises(UnstableRun) as info:
        for _ in solver.steps(scene.end_time):
            pass
    assert "not finite" in str(info.value) and "body 'bar'" in str(info.value)
    # the compiled guard itself, on a force that is infinite at node 2 (nothing else non-finite)
    n = 4
    f = np.zeros((n, 2))
    f[2, 1] = np.inf
    bad = finish_step(np.zeros((n, 2)), np.zeros((n, 2)), np.zeros((n, 2)), f, np.zeros((n, 2)), True, np.ones((n, 2)),
                      np.ones((n, 2)), np.zeros((n, 2), dtype=np.bool_), 1e-6, n)[-1]
    assert bad == 2
    # and its loop for runs without applied forces (f_ext, f_con unread), on the internal force
    bad = finish_step(np.zeros((n, 2)), np.zeros((n, 2)), f, np.zeros((n, 2)), np.zeros((n, 2)), False, np.ones((n, 2)),
                      np.ones((n, 2)), np.zeros((n, 2), dtype=np.bool_), 1e-6, n)[-1]
    assert bad == 2

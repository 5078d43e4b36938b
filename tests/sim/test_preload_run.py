"""A run with a preload stage: the event from the settled state, its own clock, the stage in the summary."""
import json

import numpy as np
import pytest

from shockfem.runner import run_scene
from shockfem.scene import resolve
from shockfem.verify.split_cone_cases import _shrink_fit_scene


def test_a_shrink_fit_run_settles_first_and_starts_its_event_at_zero(tmp_path):
    """The shrink fit (coarse) with a striker resting 1 mm above the shaft at 2 m/s: the striker is held through
    the stage (it has not moved when the event starts), the fit settles, and the event's history starts at
    t = 0 with the striker's kinetic energy as its initial energy; the balance holds over stage and event."""
    raw = _shrink_fit_scene("coarse")
    raw["scene"]["end_time"] = 20e-6
    raw["scene"]["preload"] = {}
    raw["bodies"].append({"name": "striker", "material": "steel", "shape": "cylinder", "radius": 0.01,
                          "length": 0.01, "element_size": 0.002, "position": [0.0, 0.021], "velocity": -2.0})
    result = run_scene(resolve(raw), str(tmp_path / "run"), progress=False, quiet=True, write_fields=False)
    summary = json.load(open(tmp_path / "run" / "summary.json"))
    pre = summary["preload"]
    assert pre["settled"] and pre["held_bodies"] == ["striker"]
    assert pre["time"] >= 200e-6 * (1 - 1e-9)            # not before the fit's 200 us ramp has come on
    history = np.genfromtxt(tmp_path / "run" / "history.csv", delimiter=",", names=True)
    assert history["time_s"][0] == 0.0 and history["time_s"][-1] == pytest.approx(20e-6, rel=1e-9)
    # the striker moved 2 m/s x 20 us = 0.04 mm in the event and nothing in the stage: still 1 mm clear
    striker = result.solver.model.node_body == 2
    moved = result.solver.u[striker, 1]
    assert moved.mean() == pytest.approx(-2.0 * 20e-6, rel=1e-6)
    m = result.solver.model.body_mass[2]
    assert result.solver.energy.initial == pytest.approx(0.5 * m * 2.0 ** 2, rel=1e-9)
    # stage and event in one account: 3.0e-8 measured; 1e-5 is far below a stage that lost its damping work
    assert summary["energy"]["balance_error"] < 1e-5

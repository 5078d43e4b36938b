"""The penetration study's fold-over analysis (run at default size only, so checked here on made-up
responses): the 16 runs of D = ABC and D = -ABC are read as the full 2^4, and an interaction the half
fraction reads as AC = BD comes apart into its two halves."""
import json

import numpy as np
import pytest

from shockfem.study.penetration.experiments import RESPONSES, _full_factorial, design_runs
from shockfem.study.report import Report


def test_fold_over_separates_yaw_x_spin_from_strength_x_velocity(tmp_path):
    coded, names, _ = design_runs(centre_points=1, fold=True)
    assert names[8] == "doe_fold1" and names[-1] == "doe_centre1" and len(coded) == 17
    A, B, C, D = coded[:16].T
    # bending rises with yaw, more so spinning (AC); depth rises with velocity, less in strong concrete (BD)
    runs = [{"deflection": 1 + a, "bending": 100 + 50 * a + 30 * a * c, "deceleration": 3e4 + 4e3 * b,
             "depth": 0.5 + 0.05 * d - 0.02 * b * d} for a, b, c, d in zip(A, B, C, D)]
    rep = Report(str(tmp_path), "fold-over")
    _full_factorial(rep, coded[:16], runs)
    values = json.loads((tmp_path / "results.json").read_text())["values"]
    assert values["full_factorial_bending_yaw_x_spin"] == pytest.approx(60.0)
    assert values["full_factorial_bending_fc_x_velocity"] == pytest.approx(0.0, abs=1e-9)
    assert values["full_factorial_depth_fc_x_velocity"] == pytest.approx(-0.04)
    assert values["full_factorial_depth_yaw_x_spin"] == pytest.approx(0.0, abs=1e-12)
    table = json.loads((tmp_path / "results.json").read_text())["tables"]["doe_full_effects"]
    assert [r[0] for r in table["rows"]] == [label for label, _ in RESPONSES]
    assert "effect AC" in table["columns"] and "effect BD" in table["columns"]
    assert np.isfinite([r[1] for r in table["rows"]]).all()

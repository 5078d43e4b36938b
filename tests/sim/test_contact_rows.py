"""The solver clears only the rows of ``f_con`` that contact-like forces write
(``ExplicitSolver._rows_with_contact_forces``: each pair, cavity and target adds through its own
``NodeExchange``, a spring to its end nodes).  Were any of them to write another row, that row would keep
its force step after step; so at every step of a pair, a spring, a liquid cavity and a penetrated target,
every other row must still be exactly zero, and the forces must act (a test that cannot fail otherwise)."""
import numpy as np
import pytest

from shockfem.verify import dashpot_cases, penetration_cases, spring_cases
from shockfem.verify.contact_cases import two_rods_scene
from shockfem.verify.scenes import solve


def _scenes():
    rods = two_rods_scene(0.005)
    rods["scene"]["end_time"] = 2e-5
    spring = spring_cases._scene(0.005)[0]
    spring["scene"]["end_time"] = 2e-4
    cavity = dashpot_cases._scene("dashpot", "coarse", 2e-4, 5.0, {"area": 1e-5})
    target = penetration_cases._shot_scene(0.01, 2e-5)
    return {"pair": rods, "spring": spring, "cavity": cavity, "target": target}


@pytest.mark.parametrize("name", ["pair", "spring", "cavity", "target"])
def test_contact_forces_stay_on_their_rows(name, tmp_path):
    raw = _scenes()[name]
    seen = {"steps": 0, "loaded": 0}

    def probe(s):
        others = np.ones(len(s.f_con), dtype=bool)
        others[s._contact_rows] = False
        assert not s.f_con[others].any(), f"step {s.step}: a force outside the contact rows"
        seen["steps"] += 1
        seen["loaded"] += bool(np.abs(s.f_con).max() > 0.0)
    solver, _ = solve(raw, probe=probe, cache_dir=str(tmp_path))
    assert seen["steps"] > 10 and seen["loaded"] > 5, seen
    if name == "pair":      # two faces' nodes, not the rods'
        assert len(solver._contact_rows) < len(solver.f_con) / 4

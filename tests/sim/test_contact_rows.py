"""The solver clears only the rows of ``f_con`` that contact-like forces write
(``ExplicitSolver._rows_with_contact_forces``: each pair, cavity and target adds through its own
``NodeExchange``, a spring to its end nodes).  Were any of them to write another row, that row would keep
its force step after step; so at every step of a pair, a spring, a liquid cavity, a liquid column and a penetrated target,
every other row must still be exactly zero, and the forces must act (a test that cannot fail otherwise).

On the same scenes every source answers the rest of its protocol (``forces/source.py``): its history gives as
many values as it names columns, and the sources' own energies add up to the solver's contact account, which
the solver counts from the nodal forces on its own (``energy.contact``: the trapezoidal work of ``f_con``); a
source whose forces or work were counted twice, or not at all, would break the sum."""
import numpy as np
import pytest

from shockfem.verify import column_fe_cases, dashpot_cases, penetration_cases, spring_cases
from shockfem.verify.contact_cases import two_rods_scene
from shockfem.verify.scenes import solve


def _scenes():
    rods = two_rods_scene(0.005)
    rods["scene"]["end_time"] = 2e-5
    spring = spring_cases._scene(0.005)[0]
    spring["scene"]["end_time"] = 2e-4
    cavity = dashpot_cases._scene("dashpot", "coarse", 2e-4, 5.0, {"area": 1e-5})
    target = penetration_cases._shot_scene(0.01, 2e-5)
    # the liquid column under the same elastic piston, on a rigid floor
    piston = {**cavity["bodies"][0], "position": [0.0, dashpot_cases.COLUMN]}
    column = column_fe_cases.column_scene("column", "axisymmetric", dashpot_cases.COLUMN, 1e3, 0.2, 0.0, -5.0,
                                          {"area": 1e-5}, 2e-4, 0.004, cells=20, piston=piston)
    return {"pair": rods, "spring": spring, "cavity": cavity, "target": target, "column": column}


@pytest.mark.parametrize("name", ["pair", "spring", "cavity", "target", "column"])
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


@pytest.mark.parametrize("name", ["pair", "spring", "cavity", "target", "column"])
def test_each_source_accounts_for_its_energy(name, tmp_path):
    raw = _scenes()[name]
    solver, _ = solve(raw, cache_dir=str(tmp_path))
    axes = ("r", "z") if solver.model.axisymmetric else "xyz"[:solver.model.gdim]
    assert solver.sources, "the scene has a force source"
    for source in solver.sources:
        assert len(source.history()) == len(source.columns(axes)) > 0, source.name
        assert np.isfinite(source.history()).all()
    taken = sum(source.energy() for source in solver.sources)
    # the same trapezoidal sums over the same forces, taken per source rather than per node: equal to
    # round-off of the largest energy in play (measured: at most 2e-16 of it on the four scenes, where the
    # sources took 0.2% (target) to 58% (cavity) of it); 1e-12 leaves room for the steps' summation order
    assert abs(taken) > 1e-6 * solver.energy.largest, "the source did work"
    assert abs(taken - solver.energy.contact) <= 1e-12 * solver.energy.largest, (taken, solver.energy.contact)

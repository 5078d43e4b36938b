"""The liquid column as a force source (``fluid/column_source.py``): the forces it puts on the walls' facets
sum to the column's p A (less the jet's reaction on the piston), axisymmetric and 3D, and its energy
accounts close: the walls' work on the liquid as the column counts it is its floor's, its piston's and the
jet reaction's work to round-off, and the solver's trapezoidal work of the same forces differs from it by
the coupling's half-step lag only."""
import numpy as np
import pytest

from shockfem.geometry import build_mesh
from shockfem.model import build_model
from shockfem.scene import resolve
from shockfem.solver.explicit import ExplicitSolver
from shockfem.verify.column_fe_cases import _area, column_scene


def _solver(raw, tmp_path):
    scene = resolve(raw)
    return ExplicitSolver(build_model(scene, build_mesh(scene, cache_dir=str(tmp_path), log=lambda m: None)))


def _wall_force(solver, body):
    """The sum of f_con over a body's nodes along z [N] (one process: local nodes are all of them)."""
    return float(solver.f_con[solver.model.node_body == body, -1].sum())


@pytest.mark.parametrize("kinematics", ["axisymmetric", "3d"])
def test_the_forces_on_the_walls_sum_to_the_columns(kinematics, tmp_path):
    """A housing at 10 m/s closing on a piston through 0.3 m of oil and a sharp-edged orifice a = A / 10:
    after 300 steps the jet's reaction is on (the orifice passes oil), and the floor's and the piston's
    facets carry -p_F A and p_P A - J along the axis (round-off: a sum of facet shares)."""
    A = _area()
    raw = column_scene("forces", kinematics, 0.3, 20.0, 2.0, 10.0, 0.0, {"area": A / 10}, 1.0,
                       0.01 if kinematics == "3d" else 0.005, cells=100, max_step=2e-6)
    solver = _solver(raw, tmp_path)
    steps = solver.steps(1.0)
    for _ in range(300):
        next(steps)
    source = solver.cavities[0]
    col = source.column
    A_col = col.area(col.length())
    assert col.jet_force > 0.0 and col.mass_rate > 0.0
    # one column step per step here (its Courant step, 3 mm cells, is above 2 us): the mean forces are the step's
    assert source.substeps == 300
    assert _wall_force(solver, 0) == pytest.approx(-col.floor_pressure * A_col, rel=1e-9)
    assert _wall_force(solver, 1) == pytest.approx(col.piston_pressure * A_col - col.jet_force, rel=1e-9)


def test_the_columns_energy_accounts_close(tmp_path):
    """The same dashpot over 1 ms: the column's own count of the walls' work is W_F + W_P + int J w_P to
    round-off; the solver's trapezoidal work of the forces (``energy``) agrees with it within 2.5e-3 (the
    forces of a step act at its end, the trapezoid splits them over two steps: first order in the step,
    measured 1.27e-3 of the work at 2 us and 0.64e-3 at 1 us); the
    column's dissipation (its residual: its shock fronts, Rusanov's flux) is >= 0."""
    A = _area()
    raw = column_scene("energy", "axisymmetric", 0.3, 20.0, 2.0, 10.0, 0.0, {"area": A / 10}, 1e-3, 0.005,
                       max_step=2e-6)
    solver = _solver(raw, tmp_path)
    for _ in solver.steps(1e-3):
        pass
    source = solver.cavities[0]
    a = source.column.accounts
    assert source.column_work == pytest.approx(a[0] + a[1] + source.jet_work, rel=1e-9)
    s = source.summary()
    assert abs(s["coupling_residual"]) < 2.5e-3 * s["energy_taken"]
    assert s["energy_dissipated"] >= 0.0
    closed = s["energy_column_change"] + s["energy_out_with_jet"] + s["jet_reaction_work"] + s["energy_dissipated"]
    assert closed == pytest.approx(source.column_work, rel=1e-9)
    # the run's balance holds with the liquid as one of its force sources
    assert solver.energy.balance_error < 1e-6
    assert s["outside"] == [] and np.isfinite(s["heating"])


@pytest.mark.parametrize("walls, words", [
    (["floor.bottom", "piston.bottom"], "must face the floor"),
    (["piston.top", "floor.bottom"], "must lie beyond the floor"),     # facing, but outside the liquid
    (["floor.top", "piston.top"], "must face the floor"),
])
def test_walls_that_do_not_face_each_other_are_refused(walls, words, tmp_path):
    """A column's floor and piston face must face each other across the liquid: a ModelError (exit 2)
    naming them, not a run."""
    from shockfem.errors import ModelError
    raw = column_scene("walls", "axisymmetric", 0.3, 20.0, 2.0, 10.0, 0.0, {"area": 1e-4}, 1e-4, 0.01)
    raw["cavity"][0]["walls"] = walls
    with pytest.raises(ModelError, match=words):
        _solver(raw, tmp_path)

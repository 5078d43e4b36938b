"""Mass scaling's rows (``model/mass_scaling.py``) and its refusal above the limit.  The effect on a run is
verified in ``shockfem verify mass_scaling`` (run by tests/sim/test_verification.py)."""
import math
import os
import subprocess
import sys

import numpy as np

from shockfem.materials import layout
from shockfem.model.mass_scaling import FACTOR_STEP, row_bodies, scale_rows

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))


def _table():
    params = np.zeros((2, layout.NUM_PARAMS))
    params[:, layout.P_RHO] = [7850.0, 2700.0]
    params[:, layout.P_WAVE_SPEED] = [5900.0, 6300.0]
    curves = np.arange(2 * 3 * 2, dtype=float).reshape(2, 3, 2)
    return params, curves


def test_only_the_cells_below_the_target_get_rows_whose_step_reaches_it():
    params, curves = _table()
    cell_material = np.array([0, 0, 1, 1, 0])
    steps = np.array([1.0, 0.5, 0.9, 2.0, 0.5]) * 1e-7
    deformable = np.array([True, True, True, True, False])       # the last: a rigid body's cell
    p, c, cm, factor = scale_rows(params, curves, cell_material, steps, 1e-7, deformable)
    assert list(cm[[0, 3, 4]]) == [0, 1, 0] and list(factor[[0, 3, 4]]) == [1.0, 1.0, 1.0]
    for cell in (1, 2):
        row = cm[cell]
        assert row >= 2                                          # a new row, appended
        exact = (1e-7 / steps[cell]) ** 2
        # rounded up to the next 0.2% step: the cell's step reaches the target, overshooting by < 0.1%
        assert exact <= factor[cell] < exact * FACTOR_STEP
        source = cell_material[cell]
        assert p[row, layout.P_RHO] == params[source, layout.P_RHO] * factor[cell]
        assert math.isclose(p[row, layout.P_WAVE_SPEED], params[source, layout.P_WAVE_SPEED] / math.sqrt(factor[cell]))
        scaled_step = steps[cell] * params[source, layout.P_WAVE_SPEED] / p[row, layout.P_WAVE_SPEED]
        assert 1e-7 <= scaled_step < 1e-7 * math.sqrt(FACTOR_STEP)
        assert np.array_equal(c[row], curves[source])
    assert len(p) == 4                   # one row per (material row, factor) pair
    # each new row is its cells' body's (the bodies' energies sum their rows: ``ExplicitSolver._body_sums``)
    assert list(row_bodies(len(p), cell_material, cm)) == [0, 1, 0, 1]


def test_cells_with_the_same_factor_share_a_row_and_nothing_below_changes_nothing():
    params, curves = _table()
    cm0 = np.zeros(4, dtype=np.int64)
    p, _, cm, _ = scale_rows(params, curves, cm0, np.array([0.5, 0.5, 0.5, 1.0]) * 1e-7, 1e-7, np.ones(4, bool))
    assert len(p) == 3 and cm[0] == cm[1] == cm[2] == 2 and cm[3] == 0
    p, _, cm, f = scale_rows(params, curves, cm0, np.ones(4) * 2e-7, 1e-7, np.ones(4, bool))
    assert p is params and cm is cm0 and (f == 1).all()


def test_a_scaling_above_the_limit_is_refused_naming_the_fields(tmp_path):
    """Two rods of different element sizes: scaled to the coarse rod's step, the fine rod would gain
    about 300% (its elements' density times (2.5 / 1.25)^2): exit 2, naming both scene fields."""
    scene = tmp_path / "rods.toml"
    scene.write_text('''
[scene]
name = "rods"
kinematics = "axisymmetric"
end_time = "5 us"
mass_scaling_step = "0.25 us"
[materials.steel]
density = "7850 kg/m^3"
youngs_modulus = "200 GPa"
poisson_ratio = 0.3
[[bodies]]
name = "fine"
material = "steel"
shape = "cylinder"
radius = "10 mm"
length = "20 mm"
element_size = "1.25 mm"
[[bodies]]
name = "coarse"
material = "steel"
shape = "cylinder"
radius = "10 mm"
length = "20 mm"
element_size = "2.5 mm"
position = ["0 mm", "30 mm"]
''')
    cmd = [sys.executable, "-m", "shockfem", "run", str(scene), "--out", str(tmp_path / "out"), "--no-progress"]
    r = subprocess.run(cmd, capture_output=True, text=True, cwd=REPO)
    assert r.returncode == 2, r.stderr
    assert "scene.mass_scaling_step" in r.stderr and "scene.mass_scaling_limit" in r.stderr and "fine +" in r.stderr
    assert "Traceback" not in r.stderr
    bad = subprocess.run(cmd + ["--set", 'scene.mass_scaling_step="-1 us"'], capture_output=True, text=True, cwd=REPO)
    assert bad.returncode == 2 and "scene.mass_scaling_step" in bad.stderr

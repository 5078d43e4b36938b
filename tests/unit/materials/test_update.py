"""The one material update (``materials.update.update_stress``) at a point, against closed forms:
Hooke's law, the objective rotation, perfect plasticity, and every registered law reachable; and the
update from the elements' lanes' trial (``update_from_trial``) against it."""
import math

import numpy as np
import pytest

from shockfem.materials.laws import LAWS
from shockfem.materials.layout import J2, P_KINEMATIC, P_LAMBDA, P_LAW, P_MU, P_SLOT_WIDTH, S_EPS, STATE_SIZE
from shockfem.materials.objective import rotation_of_angular_velocity
from shockfem.materials.update import (elastic_trial_holds, elastic_update_stress, is_elastic_only, update_from_trial,
                                       update_stress)
from shockfem.model.materials import parameter_table
from shockfem.verify.material_point import material

STEEL = {"density": 7850.0, "youngs_modulus": 210e9, "poisson_ratio": 0.3}
E, NU = 210e9, 0.3
LAM, MU = E * NU / ((1 + NU) * (1 - 2 * NU)), E / (2 * (1 + NU))
ZERO = (0.0,) * 6


def _point(fields):
    params, curves = parameter_table([material(fields)], None, (0.0, 0.0))
    return params, curves, np.zeros((1, 1, STATE_SIZE))


def _step(point, s, d, w=(0.0, 0.0, 0.0), dt=1e-6, elastic_only=False):
    params, curves, state = point
    return update_stress(params, curves, 0, state, 0, 0, tuple(map(float, s)), tuple(map(float, d)),
                         tuple(map(float, w)), dt, 0.0, elastic_only)


def test_elastic_step_is_hookes_law():
    s, d, work = _step(_point(STEEL), ZERO, (1.0, 0, 0, 0, 0, 0.5), dt=1e-6)
    # C : d = lam tr(d) I + 2 mu d, times dt; the shear component is the tensor one (d_12 = 0.5)
    expected = np.array([LAM + 2 * MU, LAM, LAM, 0.0, 0.0, 2 * MU * 0.5]) * 1e-6
    assert np.allclose(s, expected, rtol=1e-14, atol=0.0)
    assert work == 0.0 and d == (1.0, 0.0, 0.0, 0.0, 0.0, 0.5)


def test_spin_turns_the_stress_without_changing_it():
    """A pure spin W12 over one step turns sigma by the Cayley angle 2 atan(W12 dt / 2) about 3."""
    s0 = (100e6, -20e6, 5e6, 0.0, 0.0, 30e6)
    spin, dt = 2e5, 1e-6
    s, _, _ = _step(_point(STEEL), s0, ZERO, (0.0, 0.0, spin), dt)
    a = 2 * math.atan(0.5 * spin * dt)
    R = np.array([[math.cos(a), math.sin(a), 0], [-math.sin(a), math.cos(a), 0], [0, 0, 1]])
    S0 = np.array([[s0[0], s0[5], s0[4]], [s0[5], s0[1], s0[3]], [s0[4], s0[3], s0[2]]])
    S1 = R @ S0 @ R.T
    assert np.allclose(s, [S1[0, 0], S1[1, 1], S1[2, 2], S1[1, 2], S1[0, 2], S1[0, 1]], rtol=0, atol=1e-6)


def test_elastic_only_path_is_the_elastic_law():
    """The kernels' loop for all-elastic meshes takes ``elastic_only``; for an elastic row it must give
    what the dispatch through the registry gives: the same operations, to round-off (the elastic path
    is inlined, the law called, and fastmath may fuse their multiply-adds differently: one unit in
    the last place was seen, 4e-16 of the largest component)."""
    s0, d, w = (100e6, -20e6, 5e6, 7e6, -3e6, 30e6), (1.0, -0.3, 0.2, 0.1, 0.4, 0.5), (3e5, -1e5, 2e5)
    point = _point(STEEL)
    assert is_elastic_only(point[0])
    s_elastic, d_elastic, work_elastic = _step(point, s0, d, w, elastic_only=True)
    s_law, d_law, work_law = _step(point, s0, d, w, elastic_only=False)
    assert d_elastic == d_law and work_elastic == work_law == 0.0
    assert np.abs(np.subtract(s_elastic, s_law)).max() <= 1e-15 * np.abs(s_law).max()


def test_a_rigid_body_turns_about_its_angular_velocity():
    """The rigid bodies' step rotation (the same Cayley transform): omega about (1, 2, 2)/3 turns a
    vector by 2 atan(|omega| dt / 2) about that axis, counterclockwise (Rodrigues' formula)."""
    axis = np.array([1.0, 2.0, 2.0]) / 3.0
    omega, dt = 4e4 * axis, 1e-5
    Q = rotation_of_angular_velocity(omega, dt)
    a = 2 * math.atan(0.5 * 4e4 * dt)
    K = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    assert np.allclose(Q, np.eye(3) + math.sin(a) * K + (1 - math.cos(a)) * K @ K, rtol=0, atol=1e-14)


def test_perfect_plasticity_returns_to_the_yield_stress():
    """Isochoric shear far past yield (d_12 only): the von Mises stress is the yield stress (a one-
    point curve is perfectly plastic), and the step's plastic work is sigma_y times the plastic
    strain increment."""
    sy = 300e6
    point = _point({**STEEL, "yield_stress": sy})
    s, total = ZERO, 0.0
    for _ in range(40):
        s, _, work = _step(point, s, (0, 0, 0, 0, 0, 100.0), dt=1e-6)
        total += work
    vm = math.sqrt(1.5 * (sum((c - sum(s[:3]) / 3) ** 2 for c in s[:3]) + 2 * sum(c * c for c in s[3:])))
    assert vm == pytest.approx(sy, rel=1e-10)
    eps_p = point[2][0, 0, S_EPS]
    assert eps_p > 0 and total == pytest.approx(sy * eps_p, rel=1e-9)


@pytest.mark.parametrize("name", sorted(LAWS))
def test_every_registered_law_runs_through_the_update(name):
    """Each law of the registry has a unique id, a material that selects it, and gives a finite stress."""
    fields = {"elastic": STEEL, "j2": {**STEEL, "yield_stress": 300e6},
              "foam": {**STEEL, "crush_curve": [[0.0, 300e6]], "tension_cutoff": 300e6},
              "rubber": {**STEEL, "hyperelastic": "neo-hookean"}}[name]
    assert material(fields).law == name
    point = _point(fields)
    assert point[0][0, P_LAW] == LAWS[name].id
    assert is_elastic_only(point[0]) == (name == "elastic")      # only elastic rows skip the dispatch
    s, _, _ = _step(point, ZERO, (1e3, -300.0, -300.0, 0, 0, 0))
    assert np.all(np.isfinite(s)) and s[0] > 0
    assert len({law.id for law in LAWS.values()}) == len(LAWS)


@pytest.mark.parametrize("fields, direct", [
    ({**STEEL, "yield_stress": 300e6, "tangent_modulus": 2e9}, True),
    ({**STEEL, "yield_stress": 300e6, "cowper_symonds_D": 40.0, "cowper_symonds_q": 5.0}, True),
    ({**STEEL, "yield_stress": 300e6, "cowper_symonds_D": 40.0, "cowper_symonds_q": 5.0,
      "rate_form": "total-strain-rate"}, True),
    ({**STEEL, "yield_stress": 300e6, "tangent_modulus": 2e9, "isotropic_fraction": 0.5}, False),
    ({**STEEL, "crush_curve": [[0.0, 50e6], [0.5, 80e6]], "tension_cutoff": 20e6}, False),
])
def test_the_update_from_the_lanes_trial_is_the_update_of_the_stress(fields, direct):
    """``update_from_trial``, which the one-point elements call for a point whose lanes' elastic trial
    (``elastic_update_stress``) is not the answer, against ``update_stress`` from the same point: a J2 row
    without kinematic hardening returns from that trial (``direct``), whose rotation and Hooke step
    ``update_stress`` would make again, so the two agree to the compiler's order of operations (1e-12 of
    the largest entry; the differences seen are round-off); other rows (kinematic hardening, foam) take
    ``update_stress`` itself, inlined into ``update_from_trial``, to the same tolerance: compiled there and
    on its own, the same code has differed in its last bits in a process that compiled both (and agreed
    to the bit when both came from numba's cache).  Random stresses near yield, strain rates and spins,
    state carried over 30 steps, 200 or more of the 1,200 steps yielding."""
    rng = np.random.default_rng(11)
    params, curves, _ = _point(fields)
    lam, mu = params[0, P_LAMBDA], params[0, P_MU]
    # the row takes the direct return (the condition ``update_from_trial`` tests) or update_stress
    assert (params[0, P_LAW] == J2 and params[0, P_KINEMATIC] == 0.0 and params[0, P_SLOT_WIDTH] == 0.0) == direct
    yielding = 0
    for sample in range(40):
        states = np.zeros((2, 1, 1, STATE_SIZE))
        s = tuple(rng.uniform(-250e6, 250e6, 6))
        for step in range(30):
            d = tuple(rng.uniform(-300.0, 300.0, 6))
            w = tuple(rng.uniform(-500.0, 500.0, 3))
            dt = 2e-7
            trial = elastic_update_stress(s, d, w, dt, lam, mu)
            if elastic_trial_holds(params, curves, 0, states[0], 0, 0, trial):
                s = trial
                states[1] = states[0]
                continue
            yielding += 1
            got = update_from_trial(params, curves, 0, states[0], 0, 0, s, trial, d, w, dt, 0.0)
            want = update_stress(params, curves, 0, states[1], 0, 0, s, d, w, dt, 0.0, False)
            scale = max(abs(c) for c in want[0])
            assert np.allclose(got[0], want[0], rtol=0.0, atol=1e-12 * scale), (sample, step)
            assert got[2] == pytest.approx(want[2], rel=1e-9, abs=1e-12 * scale)
            assert np.allclose(states[0], states[1], rtol=1e-12, atol=0.0)
            states[1] = states[0]         # carry one state on: the round-off does not accumulate apart
            assert got[1] == want[1]
            s = got[0]
    assert yielding > 200, yielding         # of 1,200 steps: the return is what is compared

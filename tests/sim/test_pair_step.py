"""A two-surface contact pair in one process runs its step as two compiled calls, a pair with a rigid surface as
one (``ContactPair._step_in_one_process``, ``contact/pair_step.py``), instead of the dozen that MPI ranks make
(``ContactPair._step``).  The two must give the same forces to the bit: the fused calls run the same kernels
in the same order.  Two solvers on one scene, one on each path, are compared at every step: the contact
forces, the pair's works and impulse, and the positions and velocities.  The scene is the two-rod case at
5 mm with friction (the rods' faces slide radially as they bulge), so that both the normal and the friction
sums are compared while the faces touch, and over the searches that follow."""
import numpy as np
import pytest

from shockfem.geometry import build_mesh
from shockfem.model import build_model
from shockfem.scene import resolve
from shockfem.solver.explicit import ExplicitSolver
from shockfem.verify.contact_cases import _sliding_block_scene, _tunnel_slide_scene, two_rods_scene


def _solver(raw, cache_dir, one_process):
    scene = resolve(raw)
    model = build_model(scene, build_mesh(scene, cache_dir=cache_dir, log=lambda m: None))
    solver = ExplicitSolver(model)
    for pair in solver.contacts:
        pair.start(solver.x, solver.v)
        assert pair.one_process          # a pair in one process takes the fused path
        pair.one_process = one_process
    return solver


def _step_both(fused, separate):
    """One step of each solver, and everything the pair's step writes compared to the bit; returns the fused
    solver's pair."""
    dt = fused.stable_step()
    assert dt == separate.stable_step()
    fused.advance(dt)
    separate.advance(dt)
    a, b = fused.contacts[0], separate.contacts[0]
    assert np.array_equal(fused.f_con, separate.f_con), f"step {fused.step}: contact forces differ"
    assert (a.work, a.friction_work) == (b.work, b.friction_work), f"step {fused.step}"
    assert np.array_equal(a.impulse, b.impulse) and a.active == b.active
    assert a.max_penetration == b.max_penetration
    for p, q in zip(a.passes, b.passes):
        assert np.array_equal(p.ft, q.ft) and np.array_equal(p.gap, q.gap)
    assert np.array_equal(fused.x, separate.x) and np.array_equal(fused.v, separate.v)
    return a


def test_the_fused_pair_step_gives_the_separate_calls_forces_to_the_bit(tmp_path):
    raw = two_rods_scene(0.005)
    raw["contact"][0].update({"friction": 0.3, "friction_dynamic": 0.2})
    raw["scene"]["end_time"] = 2e-4          # contact over 0-42 us, then apart; a search about every 0.1 ms
    fused, separate = (_solver(raw, str(tmp_path), flag) for flag in (True, False))
    touching = sliding = 0
    while fused.t < raw["scene"]["end_time"]:
        a = _step_both(fused, separate)
        touching += a.active > 0
        sliding += bool(np.abs(a.ff).max() > 0.0)
    # the comparison saw what it is for: springs acting, friction acting, more than the first search
    assert touching > 50 and sliding > 20, (touching, sliding)
    assert fused.contacts[0].searches == separate.contacts[0].searches > 1
    assert fused.contacts[0].intervals == separate.contacts[0].intervals


def _dropped_block():
    """The sliding block (a rigid floor with friction) started 5 mm above the floor, falling at 1 m/s as it
    slides: the pair is apart for its first steps (the friction histories forgotten), then lands, bounces
    and slides."""
    raw = _sliding_block_scene("coarse")
    raw["bodies"][0].update({"position": [0.0, 0.005], "velocity": [1.0, -1.0]})
    return raw


def _tunnel():
    """The tunnel slide (a rigid cylinder, the plug inside it, with friction) at its coarse size."""
    return _tunnel_slide_scene("coarse")


@pytest.mark.parametrize("scene", [_dropped_block, _tunnel], ids=["plane", "cylinder"])
def test_the_fused_rigid_step_gives_the_separate_calls_forces_to_the_bit(tmp_path, scene):
    raw = scene()
    fused, separate = (_solver(raw, str(tmp_path), flag) for flag in (True, False))
    apart = touching = sliding = 0
    for _ in range(400):
        a = _step_both(fused, separate)
        apart += a.active == 0
        touching += a.active > 0
        sliding += bool(np.abs(a.ff).max() > 0.0)
    # springs and friction acting, and the block apart before it lands (the plug rests on its tunnel throughout)
    assert touching > 30 and sliding > 30, (touching, sliding)
    if scene is _dropped_block:
        assert apart > 5, apart

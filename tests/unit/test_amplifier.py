"""The amplifier's rigid-body models against their closed forms."""
import math

import pytest

from shockfem.amplifier import gain, rigid


def test_collision_conserves_momentum_and_sets_restitution():
    va, vb = gain.collide(3.0, 5.0, 1.0, -1.0, 0.7)
    assert 3.0 * va + 1.0 * vb == pytest.approx(3.0 * 5.0 - 1.0)
    assert (vb - va) / (5.0 - -1.0) == pytest.approx(0.7)
    assert gain.collide(2.0, -4.0, math.inf, 0.0, 0.5) == (2.0, 0.0)       # anvil: rebound at e v


@pytest.mark.parametrize("architecture", gain.ARCHITECTURES)
@pytest.mark.parametrize("n,e,R", [(2, 1.0, 0.5), (4, 0.9, 0.05), (6, 0.75, 0.01)])
def test_event_driven_first_pass_equals_closed_form(architecture, n, e, R):
    q = R ** (1 / (n - 1))
    masses = [10.0 * q ** k for k in range(n)]
    run = rigid.launched_chain if architecture == "launched-chain" else rigid.stack_on_anvil
    r = run(masses, 10.0, e)
    assert r.first_pass[-1] / 10.0 == pytest.approx(gain.gain(architecture, e, R, n), rel=1e-12)


def test_stack_gain_is_the_papers_eq2():
    e, R, n = 0.9, 0.01, 5
    eq2 = (1 + e) ** n / (1 + R ** (1 / (n - 1))) ** (n - 1) - 1
    assert gain.stack_gain(e, R, n) == pytest.approx(eq2, rel=1e-14)
    assert gain.chain_gain(1.0, 1.0, 2) == 1.0          # equal masses, elastic: velocities exchanged


def test_design_meets_its_target_and_refuses_the_impossible():
    lb, fts = 0.45359237, 0.3048
    d = gain.design("launched-chain", 12 * lb, 1600 * fts, 325 * fts, 0.9, 5)
    assert d.feasible and d.masses[-1] == pytest.approx(12 * lb)
    r = rigid.launched_chain(d.masses, 325 * fts, 0.9)
    assert r.first_pass[-1] == pytest.approx(1600 * fts, rel=1e-12)
    # the white paper: intermediate masses under 800 lb from 300-350 ft/s at e = 0.9 (775 lb at 325)
    assert d.intermediate_mass / lb == pytest.approx(775.2, abs=0.1)
    assert d.efficiency == pytest.approx(12 * 1600 ** 2 / (d.masses[0] / lb * 325 ** 2), rel=1e-12)
    s = gain.design("stack-on-anvil", 12 * lb, 1600 * fts, 325 * fts, 0.9, 5)
    rs = rigid.stack_on_anvil(s.masses, 325 * fts, 0.9)
    assert rs.first_pass[-1] == pytest.approx(1600 * fts, rel=1e-12)
    bad = gain.design("launched-chain", 1.0, 16.0, 1.0, 0.9, 3)
    assert not bad.feasible and "more than 3 masses" in bad.reason

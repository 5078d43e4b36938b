"""The striker's fixed point with its housing (``programmer.fixed_point``) on a stub design: the ratio a
design's housing asks falls as the striker grows (a slower closing, a lower peak)."""
import pytest
from scipy.optimize import brentq

from shockfem.programmer.fixed_point import STRIKER_TOLERANCE as TOL, striker_fixed_point


def needed(r):
    """The shape of the 12 lb machine's housing: 84.7 payloads asked at the spec's ratio 10, falling to a
    floor of 25 (the wall of a slow closing) as the striker grows; the root of needed(r) = r is 31.1."""
    return 25.0 + 59.7 * (10.0 / r) ** 2


ROOT = brentq(lambda r: needed(r) - r, 10.0, 84.7)


def stub(calls, admissible_from=0.0):
    def needed_at(r):
        calls.append(r)
        return needed(r), ("design at", r, r >= admissible_from)
    return needed_at


@pytest.mark.parametrize("start", [10.0, 84.7])
def test_converges_from_below_and_from_above(start):
    """From the spec's ratio (below the root) and from the closed form's carried ratio (above it, the
    designer's start), the search ends within the tolerance of its own housing, at the root: with
    |needed - r| <= TOL r and needed decreasing (g' < -1), |r - root| <= TOL r."""
    calls = []
    fp = striker_fixed_point(stub(calls), 10.0, start)
    assert fp.converged and fp.binds and fp.kept == "fixed point"
    assert abs(fp.needed / fp.ratio - 1) <= TOL
    assert fp.ratio == pytest.approx(ROOT, rel=TOL) and fp.ratio < 0.5 * 84.7
    assert fp.state[:2] == ("design at", fp.ratio) and fp.redesigns == len(calls) - 1 <= 6
    assert calls[0] == start and all(r >= 10.0 for r in calls)


def test_a_housing_lighter_than_the_least_ratio_keeps_it():
    """A housing that asks less than the least ratio, from a heavier start: the search comes down to the
    least ratio and stops there (never below it); the housing does not set the striker."""
    calls = []
    fp = striker_fixed_point(lambda r: (calls.append(r) or 5.0, r), 10.0, 84.7)
    assert fp.ratio == 10.0 and fp.converged and not fp.binds and calls == [84.7, 10.0]


def test_a_root_outside_a_check_keeps_the_lightest_admissible_carrying_trial():
    """Designs lighter than 40 payloads outside a check (a lighter striker closes faster): the root at
    31.1 is not kept; the lightest trial at least 40 whose striker carries its housing is."""
    calls = []
    fp = striker_fixed_point(stub(calls, 40.0), 10.0, 84.7, admissible=lambda s: s[2])
    ok = [r for r in calls if r >= 40.0 and needed(r) <= r * (1 + TOL)]
    assert fp.converged and not fp.binds and fp.kept.startswith("heavier admissible")
    assert fp.ratio == min(ok) and fp.state[2]


def test_not_converged_says_so_and_keeps_a_striker_that_carries():
    """One redesign from the spec's ratio: the second trial (84.7) carries its housing but is not the
    root; the search says it did not converge and keeps it.  A housing that grows faster than its
    striker (needed = 2 r: outside the model's range, g increasing) never converges and says so."""
    fp = striker_fixed_point(stub([]), 10.0, most=1)
    assert not fp.converged and fp.ratio == pytest.approx(needed(10.0)) and fp.redesigns == 1
    assert fp.kept.startswith("not converged") and fp.record()["converged"] is False
    fp = striker_fixed_point(lambda r: (2.0 * r, r), 10.0, most=3)
    assert not fp.converged and fp.redesigns == 3 and "none carries" in fp.kept

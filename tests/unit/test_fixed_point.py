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


def test_reused_handles_that_score_worse_than_the_found_design_are_searched_again():
    """The design at a trial ratio (``redesigned``): reused handles inside every check but scoring 3.03
    against the found design's 2.37 (the seated water design's fixed point: 28% worse, past the
    searches' 2% settle tolerance) are searched again and the search's 2.40 kept; reused handles within
    the tolerance (2.40 against 2.37, 1.3%) are kept unsearched; a search that leaves a check is not kept
    over reused handles inside them all, however it scores."""
    from shockfem.programmer.column_design import SCORE_SETTLED
    from shockfem.programmer.fixed_point import redesigned
    searched = []

    def design(reused_score, searched_score, searched_admissible=True):
        searched.clear()

        def search(reused):
            searched.append(reused)
            return ("searched", searched_score, searched_admissible)
        return redesigned(lambda: ("reused", reused_score, True), search, lambda s: s[2], lambda s: s[1], 2.37,
                          SCORE_SETTLED)
    assert design(3.03, 2.40) == ("searched", 2.40, True) and searched == [("reused", 3.03, True)]
    assert design(2.40, 2.30) == ("reused", 2.40, True) and not searched
    assert design(3.03, 2.00, searched_admissible=False) == ("reused", 3.03, True)
    assert design(3.03, 3.10) == ("reused", 3.03, True)


def test_reused_handles_outside_a_check_are_searched_again_and_the_admissible_design_kept():
    """Reused handles outside a check the found design holds: searched again; the search's design kept
    where it is admissible (whatever its score) or scores lower, else the reused one."""
    from shockfem.programmer.fixed_point import redesigned

    def design(searched):
        return redesigned(lambda: ("reused", 2.0, False), lambda reused: searched, lambda s: s[2], lambda s: s[1],
                          2.37, TOL)
    assert design(("searched", 2.5, True)) == ("searched", 2.5, True)
    assert design(("searched", 1.9, False)) == ("searched", 1.9, False)
    assert design(("searched", 2.1, False)) == ("reused", 2.0, False)

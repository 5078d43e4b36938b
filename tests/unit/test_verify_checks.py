"""``verify.checks.richardson``: the observed order and the extrapolation of three results refined by 2."""
import math

import pytest

from shockfem.verify.checks import richardson


def test_richardson_recovers_an_exact_power_law():
    """f(h) = 3 + 0.5 h^p at h = 4, 2, 1: the order p and the limit 3 to round-off."""
    for p in (0.5, 1.0, 2.0):
        order, limit = richardson(*(3 + 0.5 * h ** p for h in (4.0, 2.0, 1.0)))
        assert order == pytest.approx(p, rel=1e-12) and limit == pytest.approx(3.0, rel=1e-12)


def test_richardson_gives_no_estimate_outside_the_asymptotic_range():
    order, limit = richardson(1.0, 0.9, 0.95)             # the differences change sign
    assert math.isnan(order) and math.isnan(limit)
    order, limit = richardson(1.0, 0.99, 0.95)            # they grow: diverging
    assert order < 0 and math.isnan(limit)

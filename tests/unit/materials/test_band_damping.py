"""Band damping's Maxwell terms against their closed forms (``materials/band_damping.py``)."""
import math

import numpy as np
import pytest

from shockfem.materials.band_damping import RIPPLE, decay_and_gain, fit_band, maxwell_update


@pytest.mark.parametrize("ratio,low,high", [(0.02, 100.0, 2000.0), (0.05, 1e3, 1e5), (0.005, 10.0, 30.0)])
def test_fit_holds_the_ratio_over_the_band(ratio, low, high):
    terms = fit_band(ratio, low, high)
    omega = 2 * math.pi * np.geomspace(low, high, 400)
    # RIPPLE is the fit's own acceptance; checked here on a finer grid than the fit's
    assert np.abs(terms.ratio_at(omega) / ratio - 1).max() <= RIPPLE
    assert all(g >= 0 for g in terms.weight)
    # far outside the band the terms fall away (a Maxwell term's loss ~ 1 / (w tau) above, ~ w tau below)
    assert terms.ratio_at(2 * math.pi * low / 100) < 0.1 * ratio
    assert terms.ratio_at(2 * math.pi * high * 100) < 0.1 * ratio


def test_one_to_twenty_at_two_percent_takes_four_terms_and_stiffens_as_causality_demands():
    terms = fit_band(0.02, 1.0, 20.0)
    assert len(terms.tau) == 4
    # Kramers-Kronig: Re K rises across a band of constant loss by about (2 / pi) Q^-1 ln(20) = 7.6%
    # (module docstring); the fit's own rise, 1.049 -> 1.136, is within a percent of it
    rise = terms.modulus(2 * math.pi * 20.0).real / terms.modulus(2 * math.pi * 1.0).real - 1
    assert rise == pytest.approx(4 * 0.02 / math.pi * math.log(20), rel=0.1)
    assert terms.step_factor == pytest.approx(1 / math.sqrt(1 + sum(terms.weight)), rel=1e-14)


def test_refuses_an_empty_band_and_a_ratio_out_of_range():
    with pytest.raises(ValueError, match="low < high"):
        fit_band(0.02, 100.0, 100.0)
    with pytest.raises(ValueError, match="ratio"):
        fit_band(0.6, 1.0, 20.0)


def test_maxwell_update_is_exact_for_a_constant_rate():
    """A force ramp f = t through one term: r(t) = g tau (1 - exp(-t / tau)) exactly, in one step or
    in a thousand (the exponential update integrates a constant rate exactly)."""
    tau, g, t_end = 1e-3, 0.1, 3e-3
    exact = g * tau * (1 - math.exp(-t_end / tau))
    for steps in (1, 1000):
        dt = t_end / steps
        decay, gain = decay_and_gain(np.array([tau]), dt)
        r = q = 0.0
        for _ in range(steps):
            r, q = maxwell_update(r, q, dt, dt, decay[0], gain[0], g)
        assert r == pytest.approx(exact, rel=1e-12)
        assert q == pytest.approx(exact / g, rel=1e-12)      # the spring's stretch: r = g K q, K = 1 here

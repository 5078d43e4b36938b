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


def test_moduli_given_at_the_reference_frequency():
    """The relaxed moduli E / Re K(w_ref) make the body's dynamic modulus at w_ref the given one: 1 / 1.0918 at
    the centre of 2% over 1:20 (the fit's Re K / K there), nothing at 0 Hz (static); waves then run
    sqrt(Re K(w) / Re K(w_ref)) of the moduli's speed, -2.0% at the band's foot and +2.0% at its top."""
    terms = fit_band(0.02, 1.0, 20.0)
    centre = math.sqrt(20.0)
    assert terms.relaxed_scale(centre) * terms.modulus(2 * math.pi * centre).real == pytest.approx(1.0, rel=1e-14)
    assert terms.relaxed_scale(centre) == pytest.approx(1 / 1.0918, rel=1e-4)
    assert terms.relaxed_scale(0.0) == 1.0
    assert np.sqrt(terms.dispersion([1.0, centre, 20.0], centre)) - 1 == pytest.approx([-0.0196, 0.0, 0.0200],
                                                                                        abs=5e-4)


def test_a_band_bodys_row_holds_relaxed_moduli_and_a_plain_bodys_the_given_ones():
    """Two bodies of one J2 steel, one band-damped: each body has its own row; only the band body's elastic
    constants (lambda, mu, the wave speed that sets the stable step) scale, by 1 / Re K(w_ref) and its square
    root; its density, yield curve and kinematic modulus stay; a foam row at reference 0 Hz is unchanged."""
    from shockfem.model.materials import parameter_table
    from shockfem.materials import layout
    from shockfem.scene import Damping, Material
    from shockfem.scene.specs import Plasticity
    j2 = Plasticity(((0.0, 300e6), (0.1, 400e6)), 1e9, 0.0, 0.0, "plastic-strain-rate", "test")
    steel = Material("steel", 7850.0, 210e9, 0.3, plasticity=j2)
    band = Damping(0.02, math.sqrt(1e3 * 2e4), "band", 1e3, 2e4)
    static = Damping(0.02, math.sqrt(1e3 * 2e4), "band", 1e3, 2e4, 0.0)
    params, curves = parameter_table([steel, steel, steel], [band, None, static])
    scale = fit_band(0.02, 1e3, 2e4).relaxed_scale(math.sqrt(1e3 * 2e4))
    for column, power in ((layout.P_LAMBDA, 1.0), (layout.P_MU, 1.0), (layout.P_WAVE_SPEED, 0.5)):
        assert params[0, column] == pytest.approx(scale ** power * params[1, column], rel=1e-14)
        assert params[2, column] == params[1, column]
    assert params[1, layout.P_MU] == steel.mu and params[1, layout.P_WAVE_SPEED] == steel.c_dilatational
    for column in (layout.P_RHO, layout.P_KINEMATIC, layout.P_CURVE_POINTS):
        assert params[0, column] == params[1, column]
    assert np.array_equal(curves[0], curves[1])

"""What a body's damping makes of its modes (``modal/damping.py``) against its closed forms."""
import math

import numpy as np
import pytest

from shockfem.materials.band_damping import RIPPLE, fit_band
from shockfem.modal.damping import mode_damping
from shockfem.scene import Damping

BAND = Damping(0.02, math.sqrt(5e3 * 1e5), "band", 5e3, 1e5)          # 2% over 1:20, moduli at its centre


def test_a_band_mode_rings_where_the_dynamic_modulus_puts_it():
    """f = f_0 sqrt(Re K(f) / Re K(f_ref)) holds to round-off (the fixed point converges by 2 zeta / pi an
    iteration); the mode at f_ref keeps its frequency; below f_ref modes ring lower, above it higher."""
    terms = fit_band(0.02, 5e3, 1e5)
    f0 = np.array([3e3, 1.29e4, BAND.reference_frequency, 5e4, 4e5])
    out = mode_damping(f0, BAND)
    f = np.array([m["damped_frequency_hz"] for m in out])
    assert f == pytest.approx(f0 * np.sqrt(terms.dispersion(f, BAND.reference_frequency)), rel=1e-12)
    assert f[2] == pytest.approx(f0[2], rel=1e-12)
    assert np.all(f[:2] < f0[:2]) and np.all(f[3:] > f0[3:])
    # the band's dispersion is about +-2% at its ends (test_band_damping): a 5% shift would be a wrong reference
    assert np.abs(f / f0 - 1).max() < 0.05
    assert [m["in_band"] for m in out] == [False, True, True, True, False]
    zeta = np.array([m["damping_ratio"] for m in out])
    # inside the band the fit's own acceptance, RIPPLE; outside it the ratio falls away
    assert zeta[1:4] == pytest.approx(0.02, rel=RIPPLE)
    assert zeta[4] < 0.02 * (1 - RIPPLE)


def test_rayleigh_modes_against_their_closed_form():
    """zeta = alpha / (2 w) + beta w / 2 (Chopra eq. 11.4.4), ringing at w sqrt(1 - zeta^2)."""
    stiffness = Damping(0.02, 1e4, "stiffness")
    alpha, beta = stiffness.coefficients()
    assert alpha == 0.0
    out = mode_damping([1e4, 2e4], stiffness)
    assert [m["damping_ratio"] for m in out] == pytest.approx([0.02, 0.04], rel=1e-12)
    assert out[1]["damped_frequency_hz"] == pytest.approx(2e4 * math.sqrt(1 - 0.04 ** 2), rel=1e-12)
    mass = Damping(0.05, 100.0, "mass")
    assert mode_damping([50.0], mass)[0]["damping_ratio"] == pytest.approx(0.1, rel=1e-12)


def test_no_damping_leaves_the_modes_alone():
    assert mode_damping([1e3], None) == [{"damped_frequency_hz": 1e3, "damping_ratio": 0.0}]

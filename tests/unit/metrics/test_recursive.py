"""The compiled second-order filters (``metrics/recursive.py``) against scipy.signal's, which they replace
on a run's path: the same numbers to round-off, for the CFC filter's and an SRS oscillator's coefficients
on records that start and end in motion."""
import math

import numpy as np
import pytest
from scipy import signal

from shockfem.metrics.filters import cfc_coefficients
from shockfem.metrics.recursive import filtfilt, lfilter
from shockfem.metrics.srs import smallwood_coefficients

RNG = np.random.default_rng(7)
# a half-sine pulse riding on a ramp and noise: nonzero at both ends
T = np.arange(2000) * 1e-5
RECORD = 100 * np.sin(np.pi * T / T[-1]) + 3e3 * T + RNG.standard_normal(len(T))


@pytest.mark.parametrize("cfc", [60, 180, 600, 1000])
def test_filtfilt_is_scipys_sosfiltfilt(cfc):
    b, a = cfc_coefficients(cfc, 1e-5)
    pad = int(math.ceil(3.0 / (2 * math.pi * cfc * 2.0775 * 1e-5)))
    ours = filtfilt(b, a, RECORD, pad)
    scipys = signal.sosfiltfilt(signal.tf2sos(b, a), RECORD, padtype="odd", padlen=pad)
    assert ours.shape == RECORD.shape
    assert np.abs(ours - scipys).max() <= 1e-10 * np.abs(scipys).max()


def test_filtfilt_without_padding_and_its_limits():
    b, a = cfc_coefficients(1000, 1e-5)
    scipys = signal.sosfiltfilt(signal.tf2sos(b, a), RECORD, padtype="odd", padlen=0)
    assert np.abs(filtfilt(b, a, RECORD, 0) - scipys).max() <= 1e-10 * np.abs(scipys).max()
    with pytest.raises(ValueError, match="padlen"):
        filtfilt(b, a, RECORD[:10], 10)
    with pytest.raises(ValueError, match="3 coefficients"):
        filtfilt(b[:2], a, RECORD, 5)


@pytest.mark.parametrize("frequency, q", [(100.0, 10.0), (5000.0, 10.0), (2000.0, math.inf)])
def test_lfilter_is_scipys(frequency, q):
    b, a = smallwood_coefficients(frequency, q, 1e-5)
    scipys = signal.lfilter(b, a, RECORD)
    assert np.abs(lfilter(b, a, RECORD) - scipys).max() <= 1e-11 * np.abs(scipys).max()


def test_a_run_does_not_import_scipy_signal():
    """What it was for: the metrics of every run load without scipy.signal (and scipy.stats)."""
    import subprocess
    import sys
    code = ("import sys; import shockfem.metrics.report; "
            "print('scipy.signal' in sys.modules, 'scipy.stats' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.split() == ["False", "False"]

"""Frequency-range ("band") damping: a damping ratio held over a band of frequencies.

A stiffness-proportional (Rayleigh beta) damping has zeta(w) = beta w / 2, growing with frequency:
set at a body's first mode, its short waves are overdamped.  The band damping holds zeta over
[f_low, f_high] instead, with a sum of Maxwell terms (a spring in series with a dashpot) in
parallel with the stiffness, each acting on the body's own deformation:

    r_k + tau_k dr_k/dt = g_k tau_k d(f)/dt,        f = the elastic force (stress), r = sum_k r_k,

that is, in the frequency domain, a complex stiffness

    K(w) = K (1 + sum_k g_k i w tau_k / (1 + i w tau_k)),

the generalized Maxwell body of the constant-Q time-domain formulations (Emmerich & Korn 1987,
Geophysics 52(9) 1252-1264; Liu & Archuleta 2006, BSSA 96(4A) 1583-1590) and of the
frequency-range damping LS-DYNA calls *DAMPING_FREQUENCY_RANGE_DEFORM (Huang, Sturt & Willford
2019, Computers & Structures 212, 101-109: Maxwell-like terms proportional to the stiffness, so
that rigid-body motion is never damped).  A mode of frequency w decays at

    zeta(w) = Im K(w) / (2 Re K(w))

(the loss factor Q^-1 = 2 zeta of a lightly damped mode).  The relaxation times tau_k are spread
evenly in log frequency over the band (and a little beyond, ``EDGE``) and the weights g_k >= 0 are the least-squares solution of
Emmerich & Korn's linearised condition Im K(w) = 2 zeta Re K(w) at frequencies across the band
(``fit_band``); terms are added until zeta(w) stays within ``RIPPLE`` of the ratio over the band.

What it costs, by causality (Kramers-Kronig): the body is stiffer at high frequencies, Re K(w) / K
rising from 1 (static) by about (4 zeta / pi) ln(f_high / f_low) across the band (7.6% for 2% over
1:20; the wave speed by half that), and at frequencies far above the band by sum_k g_k, which
shortens the stable step by 1 / sqrt(1 + sum_k g_k) (``BandTerms.step_factor``).

The material's moduli are the body's at a reference frequency f_ref (the band's geometric centre
unless the scene says): as the constant-Q formulations define the unrelaxed moduli from the one
measured at a reference frequency (Emmerich & Korn 1987; Liu & Archuleta 2006: the unrelaxed
modulus from the phase velocity at a reference frequency), the elastic law runs with

    E_relaxed = E / Re(K(w_ref) / K)        (``BandTerms.relaxed_scale``),

so that Re K(w_ref) is the given modulus.  A wave of frequency w then runs sqrt(Re K(w) / Re K(w_ref))
times as fast as the given moduli say: slower below f_ref, faster above (the dispersion the band
keeps, by causality).  f_ref = 0 keeps the static moduli.

Each Maxwell term is integrated exactly over a step for a force rate constant within it:

    r_k(n+1) = exp(-dt / tau_k) r_k(n) + g_k (tau_k / dt) (1 - exp(-dt / tau_k)) (f(n+1) - f(n))

(``decay_and_gain``, ``maxwell_update``), and so is the matching displacement of its spring,
q_k, with the displacement increment in place of f's: the term stores 0.5 q_k . r_k (elastic),
the rest of its work r_k . du is what its dashpot dissipates (the damping energy).
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np
from numba import njit

# Largest relative departure of zeta(w) from the ratio over the band that ``fit_band`` accepts.
RIPPLE = 0.02
# At most this many Maxwell terms; a 1:20 band at 2% needs 4 (``fit_band``), 1:1000 needs 8.
MAX_TERMS = 12
# Frequencies per term at which the fit and its check evaluate zeta(w) (log-spaced over the band).
SAMPLES_PER_TERM = 8
# The terms' relaxation frequencies 1 / (2 pi tau_k) span [low / EDGE, EDGE high]: terms only inside
# the band leave zeta 3% low at its ends however many there are (1:20 at 2%); with EDGE = 2, four
# terms hold it within 0.8%, against 1.3% with 1.5 (measured with ``fit_band``'s least squares).
EDGE = 2.0


@dataclass(frozen=True)
class BandTerms:
    """The Maxwell terms that hold ``ratio`` over [``low``, ``high``] [Hz]: relaxation times ``tau``
    [s] and weights ``weight`` [-] (fractions of the stiffness)."""
    ratio: float
    low: float
    high: float
    tau: tuple[float, ...]
    weight: tuple[float, ...]

    def modulus(self, omega) -> np.ndarray:
        """K(w) / K, complex, at angular frequencies ``omega`` [rad/s] (module docstring)."""
        w = np.asarray(omega, dtype=float)[..., None]
        tau, g = np.asarray(self.tau), np.asarray(self.weight)
        return 1.0 + (g * 1j * w * tau / (1.0 + 1j * w * tau)).sum(axis=-1)

    def ratio_at(self, omega) -> np.ndarray:
        """zeta(w) = Im K / (2 Re K) at angular frequencies ``omega`` [rad/s]."""
        k = self.modulus(omega)
        return k.imag / (2.0 * k.real)

    def ripple(self) -> float:
        """Largest |zeta(w) / ratio - 1| over the band (on SAMPLES_PER_TERM points per term)."""
        omega = _band_omegas(self.low, self.high, SAMPLES_PER_TERM * len(self.tau) * 4)
        return float(np.abs(self.ratio_at(omega) / self.ratio - 1.0).max())

    def relaxed_scale(self, reference: float) -> float:
        """1 / Re(K(w_ref) / K): the factor on a material's moduli that makes them its dynamic moduli at
        ``reference`` [Hz] (module docstring); 1 at ``reference`` = 0 (the given moduli are static)."""
        return 1.0 / float(self.modulus(2.0 * math.pi * reference).real)

    def dispersion(self, frequency, reference: float) -> np.ndarray:
        """Re K(w) / Re K(w_ref) at ``frequency`` [Hz] (array): the squared ratio of a wave's speed (a mode's
        frequency) at ``frequency`` to what the moduli given at ``reference`` [Hz] say."""
        return self.modulus(2.0 * np.pi * np.asarray(frequency, dtype=float)).real * self.relaxed_scale(reference)

    @property
    def stiffening(self) -> float:
        """sum_k g_k: how much stiffer than static the body is far above the band."""
        return float(sum(self.weight))

    @property
    def step_factor(self) -> float:
        """The share of the undamped stable step that the terms leave, 1 / sqrt(1 + sum_k g_k): above
        the band each term is a spring g_k K in parallel with the stiffness (module docstring)."""
        return 1.0 / math.sqrt(1.0 + self.stiffening)

    def step_scale(self, reference: float) -> float:
        """The band-damped body's stable step over what its material's moduli give: the elastic law runs
        with E x ``relaxed_scale(reference)`` (the wave speed x its square root, the step / it) and the terms
        leave ``step_factor`` of that step; 0.957 for 2% over 1:20 at the band's centre, 0.916 at 0 Hz."""
        return self.step_factor / math.sqrt(self.relaxed_scale(reference))


def _band_omegas(low: float, high: float, count: int) -> np.ndarray:
    return 2.0 * math.pi * np.geomspace(low, high, max(count, 2))


@functools.lru_cache(maxsize=64)
def fit_band(ratio: float, low: float, high: float) -> BandTerms:
    """The fewest Maxwell terms (at most MAX_TERMS) whose zeta(w) stays within RIPPLE of ``ratio`` over
    [``low``, ``high``] [Hz] (module docstring: Emmerich & Korn's least squares, weights >= 0).

    Raises
    ------
    ValueError
        If the band is empty or the ratio is not in (0, 0.5], or no fit of MAX_TERMS terms holds it.
    """
    from scipy.optimize import nnls
    if not 0.0 < low < high:
        raise ValueError(f"band damping needs 0 < low < high, got low = {low:g} Hz, high = {high:g} Hz")
    if not 0.0 < ratio <= 0.5:
        raise ValueError(f"band damping ratio must be in (0, 0.5], got {ratio:g}")
    q = 2.0 * ratio                       # the loss factor Q^-1 to hold
    best = None
    for n in range(2, MAX_TERMS + 1):
        tau = 1.0 / _band_omegas(low / EDGE, high * EDGE, n)
        w = _band_omegas(low, high, SAMPLES_PER_TERM * n)[:, None]
        wt = w * tau
        # Im K = q Re K, linear in g (Emmerich & Korn 1987, eq. 16): sum_k g_k (wt - q wt^2) / (1 + wt^2) = q
        a = (wt - q * wt * wt) / (1.0 + wt * wt)
        g, _ = nnls(a, np.full(len(w), q))
        terms = BandTerms(ratio, low, high, tuple(float(t) for t in tau), tuple(float(x) for x in g))
        if best is None or terms.ripple() < best.ripple():
            best = terms
        if terms.ripple() <= RIPPLE:
            return terms
    raise ValueError(f"band damping: no {MAX_TERMS} Maxwell terms hold {ratio:g} of critical within "
                     f"{RIPPLE:.0%} over {low:g} to {high:g} Hz (best {best.ripple():.1%}); narrow the band")


def decay_and_gain(tau: np.ndarray, dt: float) -> tuple[np.ndarray, np.ndarray]:
    """Per term, exp(-dt / tau) and (tau / dt)(1 - exp(-dt / tau)): the exact update of a Maxwell term
    over a step ``dt`` [s] for a force rate constant within it (module docstring)."""
    x = dt / np.asarray(tau)
    decay = np.exp(-x)
    return decay, -np.expm1(-x) / x


@njit(cache=True, fastmath=True, inline="always")
def maxwell_update(r, q, df, du, decay, gain, weight):
    """One Maxwell term over a step: its force ``r`` and its spring's displacement ``q`` after an
    increment ``df`` of the elastic force and ``du`` of the displacement; returns (r, q)."""
    return decay * r + weight * gain * df, decay * q + gain * du

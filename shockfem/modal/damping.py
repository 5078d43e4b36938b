"""What a body's damping does to its modes: each mode's damping ratio and the frequency it rings at.

The eigenproblem (``modal/eigen.py``) is undamped, with the material's moduli as given.  The explicit
run damps the body with its own damping or the scene's (``bodies[i].damping`` or ``[damping]``):

* Rayleigh (mass, stiffness or both, alpha and beta from ``Damping.coefficients``): a mode of angular
  frequency w is damped at zeta(w) = alpha / (2 w) + beta w / 2 and rings at w sqrt(1 - zeta^2)
  (Chopra, *Dynamics of Structures*, eq. 11.4.4 and 2.2.4).
* Band (``materials/band_damping.py``): the given moduli are the body's dynamic moduli at the band's
  reference frequency f_ref, so a mode the eigenproblem finds at f_0 rings at the f that solves

      f = f_0 sqrt(Re K(2 pi f) / Re K(2 pi f_ref))          (``BandTerms.dispersion``),

  a mode's frequency scaling as the square root of the modulus; f_ref's own mode keeps its frequency.
  It is damped at zeta(f) = Im K / (2 Re K), the band's ratio within its ripple inside the band and
  falling away outside it, which ``in_band`` says.  The ringing frequency of a complex stiffness
  differs from f by O(zeta^2) (2e-4 at 2%), left out as the verification's frequency check leaves it.

Range of validity: linear, lightly damped modes (zeta well below 1); a yielding or contacting body's
response is not a sum of these modes.
"""
from __future__ import annotations

import math

import numpy as np

from ..scene.damping import band_terms

# fixed-point iterations on f = f_0 sqrt(D(f)): D rises by about (4 zeta / pi) per e-fold of frequency
# (the module docstring of materials/band_damping.py), so each iteration shrinks the error by about
# 2 zeta / pi (1/80 at 2%): a handful reach round-off; the cap only guards a ratio near 0.5
ITERATIONS = 30


def band_frequency(terms, f0: np.ndarray, reference: float) -> np.ndarray:
    """The frequencies [Hz] at which modes found at ``f0`` [Hz] with the moduli given at ``reference`` [Hz]
    ring under the band ``terms`` (module docstring)."""
    f0 = np.asarray(f0, dtype=float)
    f = f0.copy()
    for _ in range(ITERATIONS):
        f_next = f0 * np.sqrt(terms.dispersion(f, reference))
        if np.all(np.abs(f_next - f) <= 1e-13 * np.abs(f_next)):
            return f_next
        f = f_next
    return f


def mode_damping(frequencies, damping) -> list[dict]:
    """Per mode of undamped ``frequencies`` [Hz], under ``damping`` (a scene ``Damping`` or None): the
    frequency it rings at [Hz], its damping ratio [-] and, for a band, whether it lies in the band."""
    f0 = np.asarray(frequencies, dtype=float)
    if damping is None:
        return [{"damped_frequency_hz": float(f), "damping_ratio": 0.0} for f in f0]
    terms = band_terms(damping)
    if terms is not None:
        f = band_frequency(terms, f0, damping.reference_frequency)
        zeta = terms.ratio_at(2.0 * math.pi * f)
        return [{"damped_frequency_hz": float(fi), "damping_ratio": float(z),
                 "in_band": bool(damping.low <= fi <= damping.high)} for fi, z in zip(f, zeta)]
    alpha, beta = damping.coefficients()
    omega = 2.0 * math.pi * f0
    zeta = alpha / (2.0 * omega) + beta * omega / 2.0
    ring = f0 * np.sqrt(np.maximum(1.0 - zeta * zeta, 0.0))     # 0: an overdamped mode does not ring
    return [{"damped_frequency_hz": float(fi), "damping_ratio": float(z)} for fi, z in zip(ring, zeta)]


"""Crushable foam: yield of each principal stress at a crush stress of the volumetric strain
(LS-DYNA's *MAT_CRUSHABLE_FOAM, MAT_063), for crushable pulse programmers (foams, honeycomb
used as an isotropic crushable block).

After the objective rotation (``objective.py``, done by ``update.update_stress``) the step is

    sigma_trial = sigma_n + dt C : d                       elastic, E and nu (``elastic.py``)
    eps_V       = 1 - V / V0,  ln(V / V0) += tr(d) dt      volumetric strain, compression > 0
    sigma_c     = Y(eps_V) R(-tr d)                        crush stress: the curve, times the rate factor
    sigma_k     = min(max(sigma_k_trial, -sigma_c), T)     each principal stress, T the tension cutoff

and the stress is rebuilt on the trial's principal directions (``principal.py``), so that the
principal stresses are capped independently: no Poisson effect in crushing, as in MAT_063.  Y is
a piecewise-linear table of eps_V (the plateau and the densification), R Cowper-Symonds' factor
1 + (rate / D)^(1/q) of the volumetric compression rate (``curves.py``; none when D = 0), T at most
sigma_c.  Unloading is elastic on E; a crushed point keeps its volume, so reloading yields where it
left the curve.  The plastic strain increment is C^-1 : (sigma_trial - sigma), its work sigma : d eps_p.

The law's stiffness is E: loading along a curve steeper than E would lag behind it, so the scene
checker requires E at least the curve's steepest slope (a densified foam's unloading modulus), which
is also the stiffness the stable time step sees.  Point state (``layout.py``): ``S_LOG_VOLUME``,
and ``S_EPS`` / ``S_RATE``, the equivalent plastic strain sqrt(2/3 d eps_p : d eps_p) summed, and
its rate.
"""
from __future__ import annotations

import math

from numba import njit

from .curves import piecewise_linear, rate_factor
from .elastic import elastic_step
from .layout import (P_CURVE_POINTS, P_LAMBDA, P_MU, P_RATE_D, P_RATE_Q, P_TENSION_CUTOFF, S_EPS, S_LOG_VOLUME,
                     S_RATE)
from .principal import principal_stresses, spectral_sum


@njit(cache=True, fastmath=True)
def foam_update(row, curve, point, s, d, dt):
    """The crushable foam over one step in the rotated frame (module docstring).  ``row``: the
    material's parameter row; ``curve``: its crush curve; ``point``: the point's state, updated in place.
    Returns the stress and the plastic work density of the step [J/m^3]."""
    lam = row[P_LAMBDA]
    mu = row[P_MU]
    trial = elastic_step(s, d, lam, mu, dt)
    trd = d[0] + d[1] + d[2]
    point[S_LOG_VOLUME] += trd * dt
    eps_v = 1.0 - math.exp(point[S_LOG_VOLUME])
    # a stretched point (eps_V < 0: a ring flung outward) keeps the curve's first crush stress: the
    # plateau's slope carried backward would take it to zero and below, and a negative crush stress
    # caps the principal stresses the wrong way round (negative plastic work: energy created)
    crush, _ = piecewise_linear(curve, int(row[P_CURVE_POINTS]), max(eps_v, curve[0, 0]))
    crush *= rate_factor(-trd, row[P_RATE_D], row[P_RATE_Q])
    tension = min(row[P_TENSION_CUTOFF], crush)
    (l0, l1, l2), v = principal_stresses(trial)
    c0 = min(max(l0, -crush), tension) - l0
    c1 = min(max(l1, -crush), tension) - l1
    c2 = min(max(l2, -crush), tension) - l2
    if c0 == 0.0 and c1 == 0.0 and c2 == 0.0:
        point[S_RATE] = 0.0
        return trial, 0.0
    r0, r1, r2, r3, r4, r5 = spectral_sum((c0, c1, c2), v)        # sigma - sigma_trial
    sigma = (trial[0] + r0, trial[1] + r1, trial[2] + r2, trial[3] + r3, trial[4] + r4, trial[5] + r5)
    # d eps_p = -C^-1 : r, C^-1 : x = ((1 + nu) x - nu tr(x) I) / E
    E = mu * (3.0 * lam + 2.0 * mu) / (lam + mu)
    nu = 0.5 * lam / (lam + mu)
    trr = r0 + r1 + r2
    e0 = -((1.0 + nu) * r0 - nu * trr) / E
    e1 = -((1.0 + nu) * r1 - nu * trr) / E
    e2 = -((1.0 + nu) * r2 - nu * trr) / E
    e3 = -(1.0 + nu) * r3 / E
    e4 = -(1.0 + nu) * r4 / E
    e5 = -(1.0 + nu) * r5 / E
    work = sigma[0] * e0 + sigma[1] * e1 + sigma[2] * e2 + 2.0 * (sigma[3] * e3 + sigma[4] * e4 + sigma[5] * e5)
    de = math.sqrt(2.0 / 3.0 * (e0 * e0 + e1 * e1 + e2 * e2 + 2.0 * (e3 * e3 + e4 * e4 + e5 * e5)))
    point[S_EPS] += de
    point[S_RATE] = de / dt
    return sigma, work


def pack_foam(row, curve, crush) -> None:
    """Write a material's ``crush`` (the scene's ``Crush``: curve, tension_cutoff, rate_D, rate_q) into
    its parameter ``row`` and ``curve``."""
    row[P_TENSION_CUTOFF] = crush.tension_cutoff
    row[P_RATE_D] = crush.rate_D
    row[P_RATE_Q] = crush.rate_q
    row[P_CURVE_POINTS] = len(crush.curve)
    curve[:len(crush.curve)] = crush.curve

"""Linear isotropic elasticity (hypoelastic in the objective frame): the stress rate C : d.

    C : d = lambda tr(d) I + 2 mu d

The one place of Hooke's law: the elastic law, the elastic trial step of J2 plasticity, the slotted
ring's zero-hoop-stress rate and (times beta) the viscous stress of stiffness-proportional damping.
"""
from __future__ import annotations

from numba import njit

from .layout import P_LAMBDA, P_MU


@njit(cache=True, fastmath=True, inline="always")
def hooke(d, lam, mu):
    """C : d for a symmetric d given and returned as (11, 22, 33, 23, 13, 12)."""
    d0, d1, d2, d3, d4, d5 = d
    ltr = lam * (d0 + d1 + d2)
    return (ltr + 2.0 * mu * d0, ltr + 2.0 * mu * d1, ltr + 2.0 * mu * d2,
            2.0 * mu * d3, 2.0 * mu * d4, 2.0 * mu * d5)


def _elastic_step(s, d, lam, mu, dt):
    """sigma + dt C : d, the elastic stress over one step in the rotated frame."""
    c0, c1, c2, c3, c4, c5 = hooke(d, lam, mu)
    return (s[0] + dt * c0, s[1] + dt * c1, s[2] + dt * c2, s[3] + dt * c3, s[4] + dt * c4, s[5] + dt * c5)


# One formula, compiled twice: called by the laws (``elastic_step``), and inlined at numba's IR level
# (``elastic_step_inlined``) into the elements' lanes, which vectorise only with no call left in the
# loop and every line under their own error model.  Inlined into the laws and ``update_stress`` as
# well, it made the cold compile of the first plastic run 1.6x longer (numba's IR inlining cost grows
# with nesting).  ``hooke`` is always inlined: into these two and the viscous stress.
elastic_step = njit(cache=True, fastmath=True)(_elastic_step)
elastic_step_inlined = njit(cache=True, fastmath=True, inline="always")(_elastic_step)


@njit(cache=True, fastmath=True)
def elastic_update(row, s, d, dt):
    """The elastic law over one step (``elastic_step`` with the constants of the parameter ``row``); no
    plastic work."""
    return elastic_step(s, d, row[P_LAMBDA], row[P_MU], dt), 0.0

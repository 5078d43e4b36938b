"""Material table for the compiled kernels: one row of parameters per scene material."""
from __future__ import annotations

import numpy as np

from ..scene import Damping, Material
from ..solver import kernels

ELASTIC = 0


def parameter_table(materials: list[Material], damping: Damping | None) -> np.ndarray:
    """Rows of ``kernels.NUM_PARAMS`` numbers (columns named ``kernels.P_*``).

    The stiffness-proportional damping coefficient beta [s] sits in the table because
    it acts through the material: a viscous stress beta * C : d.
    """
    beta = damping.coefficients()[1] if damping else 0.0
    table = np.zeros((max(len(materials), 1), kernels.NUM_PARAMS))
    for i, m in enumerate(materials):
        table[i, kernels.P_MODEL] = ELASTIC
        table[i, kernels.P_RHO] = m.rho
        table[i, kernels.P_LAMBDA] = m.lam
        table[i, kernels.P_MU] = m.mu
        table[i, kernels.P_WAVE_SPEED] = m.c_dilatational
        table[i, kernels.P_BETA] = beta
    return table

"""Material tables for the compiled kernels: one row of parameters per body (its material and
its damping; columns ``solver/columns.py``) and one row of hardening-curve points per row."""
from __future__ import annotations

import numpy as np

from ..scene import Damping, Material
from ..scene.schema import RATE_FORMS
from ..solver import columns as col


def parameter_table(materials: list[Material], damping: list[Damping | None] | Damping | None,
                    bulk_viscosity: tuple[float, float] = (1.5, 0.06),
                    slot_widths: list[float] | None = None) -> tuple[np.ndarray, np.ndarray]:
    """(params, curves): params (rows, ``col.NUM_PARAMS``); curves (rows, points, 2) holds each
    plastic row's isotropic hardening curve (plastic strain, yield stress).

    ``damping``: one for all rows or one per row.  The stiffness-proportional damping coefficient
    beta [s] and the bulk viscosity sit in the table because they act through the material:
    viscous stresses beta C : d and -q I.  ``slot_widths``: per row, the total width of a slotted
    ring's slots (axisymmetric split cones, ``solver/slotted.py``), 0 for a full ring.
    """
    per_row = damping if isinstance(damping, list) else [damping] * len(materials)
    betas = [d.coefficients()[1] if d else 0.0 for d in per_row]
    n = max(len(materials), 1)
    points = max([len(m.plasticity.curve) for m in materials if m.plasticity] or [1])
    table = np.zeros((n, col.NUM_PARAMS))
    curves = np.zeros((n, points, 2))
    for i, m in enumerate(materials):
        table[i, col.P_MODEL] = col.ELASTIC
        table[i, col.P_RHO] = m.rho
        table[i, col.P_LAMBDA] = m.lam
        table[i, col.P_MU] = m.mu
        table[i, col.P_WAVE_SPEED] = m.c_dilatational
        table[i, col.P_BETA] = betas[i]
        table[i, col.P_Q_QUADRATIC], table[i, col.P_Q_LINEAR] = bulk_viscosity
        table[i, col.P_SLOT_WIDTH] = slot_widths[i] if slot_widths else 0.0
        p = m.plasticity
        if p is None:
            continue
        table[i, col.P_MODEL] = col.PLASTIC
        table[i, col.P_KINEMATIC] = p.kinematic_modulus
        table[i, col.P_RATE_D] = p.rate_D
        table[i, col.P_RATE_Q] = p.rate_q
        table[i, col.P_RATE_FORM] = RATE_FORMS.index(p.rate_form)
        table[i, col.P_CURVE_POINTS] = len(p.curve)
        curves[i, :len(p.curve)] = p.curve
    return table, curves

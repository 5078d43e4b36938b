"""Material tables for the compiled laws: one row of parameters per body (its material, its damping
and its slots; columns ``materials/layout.py``) and one row of hardening-curve points per row."""
from __future__ import annotations

import dataclasses

import numpy as np

from ..materials import layout
from ..materials.band_damping import fit_band
from ..materials.laws import LAWS
from ..scene import Damping, Material


def parameter_table(materials: list[Material], damping: list[Damping | None] | Damping | None,
                    bulk_viscosity: tuple[float, float] = (1.5, 0.06),
                    slot_widths: list[float] | None = None) -> tuple[np.ndarray, np.ndarray]:
    """(params, curves): params (rows, ``layout.NUM_PARAMS``); curves (rows, points, 2) holds each
    J2 row's isotropic hardening curve (plastic strain, yield stress) and each foam row's crush
    curve (volumetric strain, crush stress).

    ``damping``: one for all rows or one per row.  The stiffness-proportional damping coefficient
    beta [s] and the bulk viscosity sit in the table because they act through the material:
    viscous stresses beta C : d and -q I.  A row with band damping holds the material's moduli
    relaxed (``relaxed_material``): the body's own row, since every body has one.  ``slot_widths``: per row, the total width of a slotted
    ring's slots (axisymmetric split cones, ``materials/slotted.py``), 0 for a full ring.
    """
    per_row = damping if isinstance(damping, list) else [damping] * len(materials)
    betas = [d.coefficients()[1] if d else 0.0 for d in per_row]
    n = max(len(materials), 1)
    points = max([len((m.plasticity or m.crush).curve) for m in materials if m.plasticity or m.crush] or [1])
    table = np.zeros((n, layout.NUM_PARAMS))
    curves = np.zeros((n, points, 2))
    for i, m in enumerate(materials):
        m = relaxed_material(m, per_row[i])
        row = table[i]
        row[layout.P_RHO] = m.rho
        row[layout.P_LAMBDA] = m.lam
        row[layout.P_MU] = m.mu
        row[layout.P_WAVE_SPEED] = m.c_dilatational
        row[layout.P_BETA] = betas[i]
        row[layout.P_Q_QUADRATIC], row[layout.P_Q_LINEAR] = bulk_viscosity
        row[layout.P_SLOT_WIDTH] = slot_widths[i] if slot_widths else 0.0
        law = LAWS[m.law]
        row[layout.P_LAW] = law.id
        if law.pack is not None:
            law.pack(row, curves[i], m.plasticity or m.crush or m.rubber)
    return table, curves


def relaxed_material(material: Material, damping: Damping | None) -> Material:
    """The material a body's elastic law runs with: as given, or under a band damping its moduli divided
    by Re(K(w_ref) / K), so that the body's dynamic modulus at the band's reference frequency is the
    given one (``materials/band_damping.py``).  Only Young's modulus scales (Poisson's ratio, the density
    and the yield stresses stay), so lambda, mu and the wave speed follow, and with the wave speed the
    stable step."""
    if damping is None or damping.kind != "band":
        return material
    scale = fit_band(damping.ratio, damping.low, damping.high).relaxed_scale(damping.reference_frequency)
    return dataclasses.replace(material, E=material.E * scale)

"""Verification of the stress along a slender body (``outputs.sections``, ``output/sections.py``).

* ``section_stress``: a free steel bar (3D hexahedra) pushed at one end by a lateral and an axial force
  that come on smoothly (a raised-cosine ramp over ten first bending periods, then held).  Held, the
  bar accelerates as a rigid body and its sections carry the inertia relief exactly: the axial force
  F_z x / L from the free end, and the bending moment of the d'Alembert forces of the part beyond the
  cut, M(x) = |mu [(F/m) x^2 / 2 + alpha (x^3 / 6 - L x^2 / 4)] - alpha mu k^2 x| (mu the mass per length,
  alpha = F (L / 2) / J the angular acceleration, J = m (L^2 / 12 + k^2), k^2 = R^2 / 4 the sections'
  own rotary inertia).  The sections' axial stress (F_z x / (L A)) and bending stress (M R / I) are
  compared, averaged over two bending periods of the hold (the ramp's residual ringing, about
  (T / D)^2, averages out), at the slabs more than three radii from the loaded end (Saint-Venant).
  The faceted bar's sections are polygons inside the circle, with a smaller second moment: the bending
  stress converges from above as h^2, +4.2% at coarse size, +1.6% at the default (tolerance 5%; fitting
  cell centres alone, without each cell's own second moment, read +23% at coarse size).
"""
from __future__ import annotations

import math

import numpy as np

from ..output.sections import SectionStresses
from .checks import SIZES, check, element_count
from .scenes import STEEL, solve, steel_c0

BAR = {"radius": 0.01, "length": 0.2, "lateral": 10.0, "axial": 10.0}     # [m], [N]
RAMP_PERIODS, HOLD_PERIODS, SLABS = 10, 2, 20


def bending_period(R: float, L: float) -> float:
    """The free-free bar's first bending period, Euler-Bernoulli (beta L = 4.730) [s]."""
    c0 = steel_c0()
    return 2 * math.pi / (4.730 ** 2 / L ** 2 * c0 * R / 2)


def inertia_relief_bending(x: np.ndarray, F: float, R: float, L: float, mass: float) -> np.ndarray:
    """The uniform bar's quasi-static bending moment at x from its free end [N m] (module docstring)."""
    mu, k2 = mass / L, R * R / 4
    alpha = F * (L / 2) / (mass * (L * L / 12 + k2))
    return np.abs(mu * ((F / mass) * x ** 2 / 2 + alpha * (x ** 3 / 6 - L * x ** 2 / 4)) - alpha * mu * k2 * x)


def section_stress(size, workdir):
    """A free bar's inertia relief under a slow lateral and axial end force, read by the sections."""
    R, L, F, Fz = BAR["radius"], BAR["length"], BAR["lateral"], BAR["axial"]
    h = 2.5e-3 * SIZES[size]
    T = bending_period(R, L)
    ramp, end = RAMP_PERIODS * T, (RAMP_PERIODS + HOLD_PERIODS) * T
    times = np.linspace(0.0, ramp, 41)
    rise = 0.5 * (1 - np.cos(math.pi * times / ramp))

    def force(direction, value):
        return {"region": "bar.top", "type": "force", "direction": direction,
                "history": [[float(t), float(value * r)] for t, r in zip(times, rise)] + [[end, value]]}
    raw = {"scene": {"name": "section_stress", "kinematics": "3d", "element": "hex", "end_time": end},
           "materials": {"steel": dict(STEEL)},
           "bodies": [{"name": "bar", "material": "steel", "shape": "cylinder", "radius": R, "length": L,
                       "element_size": h}],
           "boundary": [force("x", F), force("z", -Fz)],
           "outputs": {"field_interval": end, "sections": [{"body": "bar", "count": SLABS}]}}
    rows, state = [], {}

    def probe(sv):
        if "sections" not in state:
            state["sections"] = SectionStresses(sv, sv.model.sections[0])
        if sv.t >= ramp and sv.step % 5 == 0:              # the hold only
            rows.append(state["sections"].record())
    solver, wall = solve(raw, cache_dir=workdir, probe=probe)
    sec = state["sections"]
    held = np.array(rows)
    axial, bending = held[:, :SLABS].mean(axis=0), held[:, SLABS:].mean(axis=0)
    x = sec.positions
    mass = float(solver.model.body_mass[0])
    A, I = math.pi * R * R, math.pi * R ** 4 / 4
    inside = x <= L - 3 * R
    axial_exact = -Fz * x / (L * A)
    bending_exact = inertia_relief_bending(x, F, R, L, mass) * R / I
    n = element_count(solver)
    peak = float(np.abs(bending_exact).max())
    k = int(np.argmax(np.where(inside, bending_exact, 0.0)))
    return [
        check("section_stress.bending_at_peak_section [Pa]", bending_exact[k], bending[k], 0.05, wall, n),
        check("section_stress.bending_max_error [-, abs, of the peak]", 0.0,
              float(np.max(np.abs(bending - bending_exact)[inside])) / peak, 0.05, wall, n, absolute=True),
        check("section_stress.axial_at_peak_section [Pa]", axial_exact[k], axial[k], 0.03, wall, n),
        check("section_stress.axial_max_error [-, abs, of F_z / A]", 0.0,
              float(np.max(np.abs(axial - axial_exact)[inside])) * A / Fz, 0.05, wall, n, absolute=True),
        check("section_stress.energy_balance [-, abs]", 0.0, solver.energy.balance_error, 0.01, wall, n,
              absolute=True),
    ]

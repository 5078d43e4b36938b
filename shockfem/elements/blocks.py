"""The block driver of the lane passes: one loop over blocks of cells, shared by every element that runs in
SIMD lanes (``one_point_quads.py``, ``one_point_hexes.py``, ``linear_tets.py``).

A lane pass takes ``LANES`` cells at a time through one scratch array ``S`` (row ``r`` of lane k at
``S[r * LANES + k]``) in the phases ``one_point_quads.py``'s docstring describes:

1. gather: each cell's node positions and velocities, its stress (and hourglass resultants) and its
   orientation, through the dofmap; the block's row constants (``one_point.block_constants``);
2. kinematics lanes (``rates``): the strain rate and spin on the mid-step configuration;
3. the material update: every cell's elastic trial in lanes (``elastic``), then in a block of one J2 row of
   linear hardening (``materials.update.linear_hardening``) the returns in lanes (``j2``), otherwise each
   cell the trial does not hold for by its law (``materials.update.update_from_trial``), one by one;
4. response lanes (``response``): the viscous stresses, the nodal forces, the energies, the stable step and
   the squared von Mises stress of the stress at t_n+1;
5. scatter, in cell order: forces into the nodes, stresses (and resultants) into their arrays, the totals
   and each row's energies (``one_point.add_cell_totals``) and each row's peak von Mises stress with where
   and when (``track_peak``).

An element is a ``LaneElement``: its lane count, nodes and scratch rows, and the lanes of 2-4, each a compiled
function with the arguments ``LaneElement`` lists, the same for every element (an element ignores what it
does not need); the gather, the cell-by-cell update and the scatter are the driver's, from the element's
rows.  The driver, ``lane_pass``, is compiled once per element and per copy: the elastic copy
(``elastic_only``, every row elastic without slots: ``materials.update.is_elastic_only``) holds no call to
a law.  Every pass, the lane passes and ``full_integration.stress_divergence`` alike, takes
``PASS_ARGUMENTS`` and returns ``NO_TOTALS``' seven figures, so that the solver makes one call whatever its
cells.
"""
from __future__ import annotations

import os
import types
from dataclasses import dataclass

import numpy as np
from numba import njit

from ..materials.layout import P_MU
from ..materials.update import elastic_trial_holds, linear_hardening, update_from_trial
from .one_point import (NO_TOTALS, add_cell_totals, block_constants, gather_nodes, gather_plastic_strain,
                        scatter_forces, scatter_plastic_strain)

# What every element pass takes, in order (``full_integration.stress_divergence``'s docstring says what each
# is), so that ``ExplicitSolver`` calls any of them alike.
PASS_ARGUMENTS = ("cells", "dofmap", "cell_material", "cell_sign", "x_np1", "v_half", "t_np1", "dt", "N", "dN",
                  "wq", "kinematics", "thickness", "cell_kind", "mean_dilatation", "hourglass_form",
                  "hourglass_coefficient", "params", "curves", "state", "sigma", "hourglass", "f", "body_energy",
                  "peak")
# Columns of ``peak`` (rows of params, 3): each row's largest squared von Mises stress so far [Pa^2], the time
# it was reached [s] and its cell (-1: no stress yet)
PEAK_VM2, PEAK_TIME, PEAK_CELL = 0, 1, 2


def no_peak(rows: int) -> np.ndarray:
    """A ``peak`` array of ``rows`` rows before the first step."""
    peak = np.zeros((rows, 3))
    peak[:, PEAK_CELL] = -1.0
    return peak


@njit(cache=True, fastmath=True, inline="always")
def von_mises2(s):
    """3 J2 = ((s11 - s22)^2 + (s22 - s33)^2 + (s33 - s11)^2) / 2 + 3 (s23^2 + s13^2 + s12^2), the squared
    von Mises stress of ``s`` = (11, 22, 33, 23, 13, 12) [Pa^2] (``output.cell_fields.von_mises``, squared)."""
    a, b, d = s[0], s[1], s[2]
    return (0.5 * ((a - b) * (a - b) + (b - d) * (b - d) + (d - a) * (d - a))
            + 3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]))


@njit(cache=True, fastmath=True, inline="always")
def track_peak(peak, m, c, vm2, t_np1):
    """Row ``m``'s running peak of the squared von Mises stress, raised to cell c's ``vm2`` at ``t_np1``
    where it is higher.  In cell order, so the first cell of the highest value holds it."""
    if vm2 > peak[m, PEAK_VM2]:
        peak[m, PEAK_VM2] = vm2
        peak[m, PEAK_TIME] = t_np1
        peak[m, PEAK_CELL] = c


@dataclass(frozen=True)
class LaneElement:
    """An element that runs in lanes: what ``lane_pass`` needs of it.

    ``name`` names its passes; ``source``, the file of its module (its passes' numba caches live beside it,
    so that ``numba_cache`` drops them when it, or anything it imports, changes); ``lanes`` cells a block of
    ``nodes`` nodes in ``gdim`` dimensions; ``rows`` scratch rows.  The rows (first of each):

    * gathered: ``x_row`` and ``v_row`` the node positions and velocities (component i of node a at
      ``x_row + i * nodes + a``), ``s_row`` the stress at t_n (its ``stress_components`` of sigma's six),
      ``o_row`` the ``hourglass_modes`` resultants of the last step, ``constants_row`` the 7 of
      ``one_point.block_constants`` and ``constants_row + 7`` the orientation;
    * from the phases: ``sn_row`` the stress at t_n+1, ``f_row`` the nodal forces (as the positions),
      ``q_row`` the new resultants, ``totals_row`` the 7 of ``one_point.add_cell_totals`` and after them the
      squared von Mises stress at t_n+1, ``eps_row`` the plastic strain of ``j2`` (its rate in the next).

    The kinematics lanes write ``d_row`` the strain rate and ``spin_row`` the spin, and the material update
    ``wp_row`` the plastic work density.  The phases, compiled (``numba.njit``), with their arguments:

    * ``rates(S, count, dt, kinematics, weight)``: ``weight`` is the rule's ``wq[0]``;
    * ``elastic(S, count, dt)``;
    * ``j2(S, count, dt, mu, y0, eps0, slope)``;
    * ``response(S, count, dt, kinematics, thickness, weight, hourglass_form, hourglass_coefficient)``;

    and, for the cell-by-cell update, the element's tensors in and out of lane k (``inline="always"``):
    ``tensor6(S, row, B, k)`` a stress or strain rate as the six components, ``store_stress(S, row, B, k, s)``,
    ``spin3(S, row, B, k)`` the spin (W23, W13, W12), ``radius(S, B, k, kinematics)`` the radius of an
    axisymmetric cell's point (0 otherwise).
    """
    name: str
    source: str
    lanes: int
    nodes: int
    gdim: int
    rows: int
    x_row: int
    v_row: int
    s_row: int
    stress_components: tuple
    o_row: int
    hourglass_modes: int
    constants_row: int
    sn_row: int
    f_row: int
    q_row: int
    totals_row: int
    eps_row: int
    d_row: int
    spin_row: int
    wp_row: int
    rates: object
    elastic: object
    j2: object
    response: object
    tensor6: object
    store_stress: object
    spin3: object
    radius: object


def _element_pass(cells, dofmap, cell_material, cell_sign, x_np1, v_half, t_np1, dt, N, dN, wq, kinematics,
                  thickness, cell_kind, mean_dilatation, hourglass_form, hourglass_coefficient, params, curves,
                  state, sigma, hourglass, f, body_energy, peak):
    """One step of ``cells``: stress update and internal force, in blocks of lanes (``blocks`` module
    docstring; the arguments are ``full_integration.stress_divergence``'s).  Returns (dt_stable,
    critical_cell, damping_power, viscosity_power, plastic_work, hourglass_power, bad_cell)."""
    S = np.zeros(ROWS * B)
    totals = NO_TOTALS
    weight = wq[0]
    n = cells.shape[0]
    for start in range(0, n, B):
        count = min(B, n - start)
        # cell, row and node numbers as unsigned: numba wraps a signed index around (a compare and an add on
        # every load and store of the gather and scatter; docs/performance.md)
        block_material = np.uint32(cell_material[cells[start]])
        one_row = True
        for k in range(count):
            c = np.uint32(cells[start + k])
            one_row = one_row and np.uint32(cell_material[c]) == block_material
            gather_nodes(S, B, k, c, NODES, GDIM, X_ROW, V_ROW, dofmap, x_np1, v_half)
            for i in range(len(COMPONENTS)):
                S[(S_ROW + i) * B + k] = sigma[c, 0, COMPONENTS[i]]
            for i in range(MODES):
                S[(O_ROW + i) * B + k] = hourglass[c, i]
            S[(CONSTANTS + 7) * B + k] = cell_sign[c]
        block_constants(S, CONSTANTS, B, cells, start, count, cell_material, params, one_row, block_material)
        rates(S, count, dt, kinematics, weight)
        # every cell's elastic trial in lanes: the update of elastic rows, and of J2 points that stay inside
        # their yield surface (most of a plastic body at any time)
        elastic(S, count, dt)
        linear, y0, eps0, slope = (False, 0.0, 0.0, 0.0) if ELASTIC_ONLY else linear_hardening(
            params, curves, block_material)
        if one_row and linear:
            # a block of one J2 row of linear hardening: the returns in lanes too
            gather_plastic_strain(S, EPS, B, cells, start, count, state)
            j2(S, count, dt, params[block_material, P_MU], y0, eps0, slope)
            scatter_plastic_strain(S, EPS, B, cells, start, count, state)
        elif not ELASTIC_ONLY:
            # the others cell by cell, from their trial (a J2 return, or objective rotation, slots and law); the
            # update may change the hoop rate (a slotted ring's metal takes what its slots leave)
            for k in range(count):
                c = cells[start + k]
                trial = tensor6(S, SN_ROW, B, k)
                if elastic_trial_holds(params, curves, cell_material[c], state, c, 0, trial):
                    continue
                s_np1, d, wp = update_from_trial(params, curves, cell_material[c], state, c, 0,
                                                 tensor6(S, S_ROW, B, k), trial, tensor6(S, D_ROW, B, k),
                                                 spin3(S, SPIN_ROW, B, k), dt, radius(S, B, k, kinematics))
                store_stress(S, SN_ROW, B, k, s_np1)
                S[(D_ROW + 2) * B + k] = d[2]
                S[WP_ROW * B + k] = wp
        response(S, count, dt, kinematics, thickness, weight, hourglass_form, hourglass_coefficient)
        # scatter, in cell order: the same sums as a cell-by-cell loop
        for k in range(count):
            c = np.uint32(cells[start + k])
            m = np.uint32(cell_material[c])
            scatter_forces(S, B, k, c, NODES, GDIM, F_ROW, dofmap, f)
            for i in range(len(COMPONENTS)):
                sigma[c, 0, COMPONENTS[i]] = S[(SN_ROW + i) * B + k]
            for i in range(MODES):
                hourglass[c, i] = S[(Q_ROW + i) * B + k]
            totals = add_cell_totals(totals, S, TOTALS, B, k, c, m, dt, body_energy)
            track_peak(peak, m, c, S[(TOTALS + 7) * B + k], t_np1)
    return totals


def lane_pass(element: LaneElement, elastic_only: bool):
    """``element``'s pass in its copy for ``elastic_only``: ``_element_pass`` compiled with the element's
    phases and rows as its globals (the names it reads that this module does not define).

    They are globals, not a closure's cells: numba keys a cached closure on its cells' pickled contents,
    and a compiled function pickles with a new identity in every process, so a closure over the phases
    would never be found in the cache.  Each copy has a name of its own (``<name>_pass``,
    ``<name>_pass_elastic``; ``one_point_quads._lane_function`` says why) and is filed under the element's
    module, whose file its cache sits beside."""
    name = f"{element.name}_pass{'_elastic' if elastic_only else ''}"
    scope = dict(globals())
    e = element
    scope.update(B=e.lanes, ROWS=e.rows, NODES=e.nodes, GDIM=e.gdim, X_ROW=e.x_row, V_ROW=e.v_row, S_ROW=e.s_row,
                 COMPONENTS=tuple(e.stress_components), O_ROW=e.o_row, MODES=e.hourglass_modes,
                 CONSTANTS=e.constants_row, SN_ROW=e.sn_row, F_ROW=e.f_row, Q_ROW=e.q_row, TOTALS=e.totals_row,
                 EPS=e.eps_row, D_ROW=e.d_row, SPIN_ROW=e.spin_row, WP_ROW=e.wp_row, ELASTIC_ONLY=bool(elastic_only),
                 rates=e.rates, elastic=e.elastic, j2=e.j2, response=e.response, tensor6=e.tensor6,
                 store_stress=e.store_stress, spin3=e.spin3, radius=e.radius)
    code = _element_pass.__code__.replace(co_name=name, co_filename=element.source)
    fn = types.FunctionType(code, scope, name)
    fn.__qualname__ = name
    fn.__doc__ = _element_pass.__doc__
    fn.__module__ = f"{__package__}.{os.path.splitext(os.path.basename(element.source))[0]}"
    return njit(cache=True, fastmath=True)(fn)


def lane_passes(element: LaneElement) -> dict:
    """``element``'s pass in its two copies, keyed by ``elastic_only``."""
    return {flag: lane_pass(element, flag) for flag in (True, False)}

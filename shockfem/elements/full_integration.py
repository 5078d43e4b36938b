"""Fully integrated elements (2x2 / 2x2x2 Gauss points, any P1 cell): stress update and internal force.

The internal force of every deformable cell is the stress divergence

    f_a = int_Omega sigma : grad(N_a) dV      (+ sigma_tt N_a / r  in axisymmetry)

which is exactly the UFL form ``shockfem.model.kinematics.internal_force_form``.  dolfinx 0.5.2
assembles that form at about 7.7 million Q1 cells per second on the reference machine; this numba
twin computes the strain rate, updates the stress (``shockfem.materials.update.update_stress``) and
assembles the force in one pass over the cells at several times that rate (``shockfem bench``).
The unit test ``tests/unit/elements/test_full_integration.py`` checks it against the dolfinx assembly
of the UFL form to round-off.  Conventions: ``cells.py``.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from ..materials.layout import P_BETA, P_Q_LINEAR, P_Q_QUADRATIC, P_RHO, P_WAVE_SPEED
from ..materials.update import update_stress
from ..materials.viscosity import bulk_viscosity, viscous_step, viscous_stress
from .blocks import track_peak, von_mises2
from .cells import AXISYMMETRIC, characteristic_length, gradients


def _kernel(elastic_only: bool):
    """``stress_divergence`` compiled for ``elastic_only`` (a constant of the closure, as the one-point
    lane passes are: ``blocks.lane_passes``)."""

    @njit(cache=True, fastmath=True)
    def stress_divergence(cells, dofmap, cell_material, cell_sign, x_np1, v_half, t_np1, dt, N, dN, wq, kinematics,
                          thickness, cell_kind, mean_dilatation, hourglass_form, hourglass_coefficient, params, curves,
                          state, sigma, hourglass, f, body_energy, peak):
        """Update the stress of ``cells`` over one step and add their internal force to ``f``.

        Parameters
        ----------
        cells : (nc,) int32, the deformable cells this rank owns.
        dofmap : (num_cells, nn) int32, P1 node numbers of every cell.
        cell_material : (num_cells,) int32, row of ``params`` for every cell.
        cell_sign : (num_cells,) float64, ``cell_orientation`` of the reference mesh.
        x_np1 : (num_nodes, gdim) positions at t_{n+1} [m].
        v_half : (num_nodes, gdim) velocities at t_{n+1/2} [m/s].
        t_np1 : the time t_{n+1} [s], at which a new peak stress is stamped.
        dt : step t_n -> t_{n+1} [s].
        N, dN : shape functions (nq, nn) and reference gradients (nq, nn, tdim) at the points.
        wq : (nq,) quadrature weights on the reference cell.
        kinematics : 0 plane strain, 1 axisymmetric, 2 3D.
        thickness : out-of-plane depth for plane strain [m] (ignored otherwise).
        cell_kind : 0 tri, 1 quad, 2 tet, 3 hex (for the characteristic length).
        mean_dilatation : replace each point's volumetric strain rate by the cell average
            (Nagtegaal, Parks & Rice 1974), which removes volumetric locking.
        hourglass_form, hourglass_coefficient : the one-point elements' hourglass control (0 stiffness, 1
            viscous; the coefficient eps); unread here, as ``hourglass`` is.
        params, curves : material rows and hardening curves (``shockfem.materials.layout``).
        state : (num_cells, nq, STATE_SIZE) point state of the laws, updated in place (a (1, 1, STATE_SIZE)
            stub when no law needs one).
        sigma : (num_cells, nq, 6) Cauchy stress, updated in place from t_n to t_{n+1}.
        hourglass : the one-point elements' hourglass resultants (cells, modes x components), updated in place.
        f : (num_nodes, gdim) internal force, accumulated (caller zeroes it).
        body_energy : (rows of params, 3) accumulates per row (one per body) the work of the stresses
            dt w (sigma_n + sigma_n+1)/2 : d and the plastic work over the step [J] (columns 0 and 2;
            column 1, the hourglass work, stays: no hourglass modes at full integration).
        peak : (rows of params, 3) per row the largest squared von Mises stress of sigma at any point so
            far [Pa^2], the time [s] and the cell (``blocks.PEAK_VM2``...), raised in place.

        Returns
        -------
        dt_stable : smallest stable step over ``cells`` at t_{n+1} (before the safety factor).
        critical_cell : the cell that sets it.
        damping_power : int sigma_visc : d dV, power of the stiffness-proportional damping [W].
        viscosity_power : int -q tr(d) dV, power of the bulk viscosity [W].
        plastic_work : int sigma : d eps_p dV over the step [J].
        hourglass_power : the hourglass forces' power (0: none at full integration) [W].
        bad_cell : a cell whose Jacobian changed sign (inverted) at t_{n+1}, or -1.
        """
        nq = wq.shape[0]
        nn = dofmap.shape[1]
        gdim = x_np1.shape[1]
        xe = np.empty((nn, 3))
        xm = np.empty((nn, 3))
        ve = np.empty((nn, 3))
        dNdx = np.empty((nn, 3))
        L = np.zeros((nq, 3, 3))
        wmid = np.empty(nq)
        two_pi = 2.0 * math.pi
        dt_stable = 1e300
        critical_cell = -1
        damping_power = 0.0
        viscosity_power = 0.0
        plastic_work = 0.0
        bad_cell = -1
        for ci in range(cells.shape[0]):
            c = cells[ci]
            # unsigned copies for indexing: numba wraps a signed index around (a compare and an add per
            # access); c and m stay as they are for the material update, whose laws are compiled for them
            cu = np.uint32(c)
            m = cell_material[cu]
            sgn = cell_sign[cu]
            beta = params[m, P_BETA]
            for a in range(nn):
                node = np.uint32(dofmap[cu, a])
                for i in range(gdim):
                    xe[a, i] = x_np1[node, i]
                    ve[a, i] = v_half[node, i]
                    xm[a, i] = x_np1[node, i] - 0.5 * dt * v_half[node, i]
            # Pass 1: velocity gradient on the mid-step configuration.
            vol = 0.0
            div = 0.0
            for q in range(nq):
                det = gradients(xm, dN[q], gdim, nn, dNdx) * sgn
                for i in range(3):
                    for k in range(3):
                        L[q, i, k] = 0.0
                for i in range(gdim):
                    for k in range(gdim):
                        t = 0.0
                        for a in range(nn):
                            t += ve[a, i] * dNdx[a, k]
                        L[q, i, k] = t
                w = wq[q] * det
                if kinematics == AXISYMMETRIC:
                    r = 0.0
                    vr = 0.0
                    for a in range(nn):
                        r += N[q, a] * xm[a, 0]
                        vr += N[q, a] * ve[a, 0]
                    L[q, 2, 2] = vr / r
                    w *= two_pi * r
                wmid[q] = w
                vol += w
                div += w * (L[q, 0, 0] + L[q, 1, 1] + L[q, 2, 2])
            div_avg = div / vol
            le = characteristic_length(xe, cell_kind, nn)
            c_m = params[m, P_WAVE_SPEED]
            pq = bulk_viscosity(params[m, P_RHO], c_m, le, div_avg, params[m, P_Q_QUADRATIC], params[m, P_Q_LINEAR])
            # Pass 2: stress update and force on the end-of-step configuration.
            vm2 = 0.0           # the cell's largest squared von Mises stress over its points
            for q in range(nq):
                d0 = L[q, 0, 0]
                d1 = L[q, 1, 1]
                d2 = L[q, 2, 2]
                if mean_dilatation:
                    shift = (div_avg - (d0 + d1 + d2)) / 3.0
                    d0 += shift
                    d1 += shift
                    d2 += shift
                d = (d0, d1, d2, 0.5 * (L[q, 1, 2] + L[q, 2, 1]), 0.5 * (L[q, 0, 2] + L[q, 2, 0]),
                     0.5 * (L[q, 0, 1] + L[q, 1, 0]))
                spin = (0.5 * (L[q, 1, 2] - L[q, 2, 1]), 0.5 * (L[q, 0, 2] - L[q, 2, 0]), 0.5 * (L[q, 0, 1] - L[q, 1, 0]))
                s_n = (sigma[cu, q, 0], sigma[cu, q, 1], sigma[cu, q, 2], sigma[cu, q, 3], sigma[cu, q, 4],
                       sigma[cu, q, 5])
                s_np1, d, wp = update_stress(params, curves, m, state, c, q, s_n, d, spin, dt, 0.0, elastic_only)
                plastic_work += wmid[q] * wp
                body_energy[m, 2] += wmid[q] * wp
                body_energy[m, 0] += 0.5 * dt * wmid[q] * (
                    (s_n[0] + s_np1[0]) * d[0] + (s_n[1] + s_np1[1]) * d[1] + (s_n[2] + s_np1[2]) * d[2]
                    + 2.0 * ((s_n[3] + s_np1[3]) * d[3] + (s_n[4] + s_np1[4]) * d[4] + (s_n[5] + s_np1[5]) * d[5]))
                for k in range(6):
                    sigma[cu, q, k] = s_np1[k]
                vm2 = max(vm2, von_mises2(s_np1))
                s, pd, pv = viscous_stress(params, m, s_np1, d, pq)
                damping_power += wmid[q] * pd
                viscosity_power += wmid[q] * pv
                det = gradients(xe, dN[q], gdim, nn, dNdx) * sgn
                if det <= 0.0:
                    bad_cell = c
                w = wq[q] * det
                if gdim == 2:
                    if kinematics == AXISYMMETRIC:
                        r = 0.0
                        for a in range(nn):
                            r += N[q, a] * xe[a, 0]
                        w *= two_pi * r
                        hoop = s[2] / r
                        for a in range(nn):
                            node = np.uint32(dofmap[cu, a])
                            f[node, 0] += w * (s[0] * dNdx[a, 0] + s[5] * dNdx[a, 1] + hoop * N[q, a])
                            f[node, 1] += w * (s[5] * dNdx[a, 0] + s[1] * dNdx[a, 1])
                    else:
                        w *= thickness
                        for a in range(nn):
                            node = np.uint32(dofmap[cu, a])
                            f[node, 0] += w * (s[0] * dNdx[a, 0] + s[5] * dNdx[a, 1])
                            f[node, 1] += w * (s[5] * dNdx[a, 0] + s[1] * dNdx[a, 1])
                else:
                    for a in range(nn):
                        node = np.uint32(dofmap[cu, a])
                        f[node, 0] += w * (s[0] * dNdx[a, 0] + s[5] * dNdx[a, 1] + s[4] * dNdx[a, 2])
                        f[node, 1] += w * (s[5] * dNdx[a, 0] + s[1] * dNdx[a, 1] + s[3] * dNdx[a, 2])
                        f[node, 2] += w * (s[4] * dNdx[a, 0] + s[3] * dNdx[a, 1] + s[2] * dNdx[a, 2])
            # into the row's peak once a cell: at every point, the peak's compare and store took a tenth of the
            # 2x2 quads' pass (docs/performance.md, "The element passes' block driver")
            track_peak(peak, m, c, vm2, t_np1)
            dtc = viscous_step(le, c_m, le, div_avg, params[m, P_Q_QUADRATIC], params[m, P_Q_LINEAR], beta)
            if dtc < dt_stable:
                dt_stable = dtc
                critical_cell = c
        return dt_stable, critical_cell, damping_power, viscosity_power, plastic_work, 0.0, bad_cell
    return stress_divergence


KERNELS = {flag: _kernel(flag) for flag in (True, False)}
stress_divergence = KERNELS[False]          # the copy for any law (what the unit tests call)


def stress_divergence_kernel(elastic_only: bool):
    """``stress_divergence`` in its copy without law calls (``elastic_only``: every row elastic without
    slots, ``materials.update.is_elastic_only``) or for any law."""
    return KERNELS[bool(elastic_only)]

"""The fluid dashpot as two rigid masses and a lumped liquid: the cheapest model of the fixture study's
dashpot, to design on before a finite-element run confirms the design.

A striker of mass M (carrying the housing and its liquid) closes at V on a payload of mass m (the
piston and the article, at rest).  The liquid between them, of volume V(s) = V0 - A s for the
relative stroke s, holds a mass that the orifice lets out; its pressure and jet follow
``fluid/liquid.py`` (the same laws as the finite-element cavity), the orifice area is the metering
pin's table of s, the orifice's law one of ``fluid/orifice.py``'s (``law``: the study's first law, a
fixed Cd with no velocity of approach or jet reaction, unless another is given):

    m x_p'' = p A - J,   M x_s'' = -p A,   s = x_s - x_p,   M_l' = -mdot(M_l / (rho0 V(s)), a(s), A)

with J = mdot (u_j - u1) the jet's reaction on the piston (``orifice.jet_reaction``; 0 for a law
without it).  Left out: the liquid's inertia and waves (the column of ``programmer/column_dashpot.py``
has them), and everything elastic in the bodies (the finite-element run has that).  Its range: the
column's transit time short against the pulse's rise, the piston slow against the liquid's sound
speed, the liquid light against the payload (``programmer/dashpot_validity.py`` checks them).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit

from ..fluid import liquid, orifice
from ..fluid.orifice import OrificeLaw


@dataclass(frozen=True)
class LumpedDashpot:
    striker_mass: float                 # M [kg]
    payload_mass: float                 # m [kg]
    speed: float                        # V, the striker's closing speed [m/s]
    piston_area: float                  # A [m^2]
    column: float                       # the liquid column at rest, V0 / A [m]
    pin: tuple                          # ((stroke [m], orifice area [m^2]), ...), stroke rising
    density: float                      # rho0 [kg/m^3]
    bulk_modulus: float                 # K [Pa]
    discharge: float                    # Cd
    tait_exponent: float = 1.0
    initial_pressure: float = 0.0       # a pre-charge [Pa] (gauge), as the cavity's
    law: OrificeLaw | None = None       # the orifice's law; None: ``discharge`` fixed, as the cavity's
    orifice_land: float = 0.0           # the orifice's length through the piston [m] (0: a thin plate)

    def orifice_law(self) -> OrificeLaw:
        return self.law or OrificeLaw(discharge=self.discharge, approach=False, jet=False)


@dataclass(frozen=True)
class LumpedRun:
    t: np.ndarray                       # [s]
    acceleration: np.ndarray            # the payload's [m/s^2]
    pressure: np.ndarray                # [Pa]
    jet_force: np.ndarray               # the jet's reaction J on the piston [N]
    stroke: np.ndarray                  # [m]
    payload_speed: np.ndarray           # [m/s]
    striker_speed: np.ndarray           # [m/s]


def simulate(d: LumpedDashpot, end_time: float, samples: int = 4000) -> LumpedRun:
    """Integrate the dashpot from first contact to ``end_time`` (adaptive Runge-Kutta, relative
    tolerance 1e-8), sampled at ``samples`` even times.

    The integrator is scipy's RK45 (``solve_ivp``'s default: Dormand-Prince 5(4), its error norm, step
    control, first step and dense output at the samples) written again in numba (``_dormand_prince``)
    with scipy's own coefficients: the design iteration (``programmer.dashpot_design``) runs this a few
    hundred times: 0.54 s a run with scipy's Python step, 0.018 s compiled.  The two
    agree to round-off (``tests/unit/test_programmer.py``)."""
    A, K, n, rho0 = d.piston_area, d.bulk_modulus, d.tait_exponent, d.density
    V0 = A * d.column
    pin = np.array(d.pin, dtype=float).reshape(-1, 2)
    constants = np.concatenate([[A, d.striker_mass, d.payload_mass, V0, rho0, K, n], d.orifice_law().code()])
    t = np.linspace(0.0, end_time, samples)
    mass0 = rho0 * (1.0 + n * d.initial_pressure / K) ** (1.0 / n) * V0
    y = np.empty((samples, 4))
    done = _dormand_prince(constants, np.ascontiguousarray(pin[:, 0]), np.ascontiguousarray(pin[:, 1]),
                           np.array([0.0, d.speed, 0.0, mass0]), t, end_time, RTOL, ATOL, end_time / 2000,
                           *_tableau(), y)
    if done < samples:
        raise RuntimeError(f"lumped dashpot: the step fell below round-off at t = {t[done]:.6g} s")
    p = np.array([_pressure(constants, row) for row in y])
    jet = np.array([_jet(constants, pin[:, 0], pin[:, 1], row) for row in y])
    return LumpedRun(t, (p * A - jet) / d.payload_mass, p, jet, y[:, 0], y[:, 2], y[:, 1])


RTOL, ATOL = 1e-8, 1e-12        # the integration's tolerances (scipy's meaning)
# scipy's RK45 step-size control (``scipy/integrate/_ivp/rk.py``)
_SAFETY, _MIN_FACTOR, _MAX_FACTOR = 0.9, 0.2, 10.0
_ERROR_EXPONENT = -1.0 / 5.0     # -1 / (error estimator order 4 + 1)


def _tableau():
    """Dormand-Prince 5(4): scipy's RK45 coefficients (A, B, C, the error weights E, the dense output P)."""
    from scipy.integrate import RK45
    return tuple(np.ascontiguousarray(c, dtype=float) for c in (RK45.A, RK45.B, RK45.C, RK45.E, RK45.P))


@njit(cache=True)
def _liquid(constants, y):
    """The liquid's density ratio and gauge pressure in the state ``y`` = (stroke, striker speed, payload
    speed, liquid mass), in its volume V0 - A s (kept above 1e-12 V0)."""
    A, V0, rho0, K, n = constants[0], constants[3], constants[4], constants[5], constants[6]
    ratio = y[3] / (rho0 * max(V0 - A * y[0], 1e-12 * V0))
    return ratio, liquid.pressure(ratio, K, n)


@njit(cache=True)
def _pressure(constants, y):
    """The liquid's gauge pressure in the state ``y``."""
    return _liquid(constants, y)[1]


@njit(cache=True)
def _outflow(constants, pin_s, pin_a, y):
    """The orifice's mass rate and the jet's reaction on the piston in the state ``y``."""
    A, rho0, K, n, law = constants[0], constants[4], constants[5], constants[6], constants[7:]
    ratio, _ = _liquid(constants, y)
    area = np.interp(y[0], pin_s, pin_a)
    mdot = liquid.orifice_mass_flow(ratio, area, A, law, K, n, rho0)
    return mdot, orifice.jet_reaction(mdot, rho0 * ratio, area, A, law)


@njit(cache=True)
def _jet(constants, pin_s, pin_a, y):
    return _outflow(constants, pin_s, pin_a, y)[1]


@njit(cache=True)
def _rates(constants, pin_s, pin_a, y, out):
    """dy/dt of (stroke, striker speed, payload speed, liquid mass), into ``out``."""
    A, M, m = constants[0], constants[1], constants[2]
    _, p = _liquid(constants, y)
    mdot, jet = _outflow(constants, pin_s, pin_a, y)
    out[0] = y[1] - y[2]
    out[1] = -p * A / M
    out[2] = (p * A - jet) / m
    out[3] = -mdot


@njit(cache=True)
def _rms(x, scale):
    """scipy's error norm: the root mean square of x / scale."""
    total = 0.0
    for i in range(len(x)):
        total += (x[i] / scale[i]) ** 2
    return math.sqrt(total) / math.sqrt(len(x))


@njit(cache=True)
def _dormand_prince(constants, pin_s, pin_a, y0, t_eval, t_end, rtol, atol, max_step, A, B, C, E, P, out):
    """scipy's RK45 from t = 0 to ``t_end`` with its first step, error control and dense output, the
    states at ``t_eval`` (rising, from 0) into ``out``.  Returns how many samples it filled (all, unless
    the step fell below round-off, where scipy's solver fails too)."""
    n = len(y0)
    stages = len(B)
    y = y0.copy()
    f = np.empty(n)
    _rates(constants, pin_s, pin_a, y, f)
    # the first step (Hairer, Norsett & Wanner, II.4; scipy's ``select_initial_step``)
    scale = atol + np.abs(y0) * rtol
    d0, d1 = _rms(y0, scale), _rms(f, scale)
    h0 = 1e-6 if d0 < 1e-5 or d1 < 1e-5 else 0.01 * d0 / d1
    f1 = np.empty(n)
    _rates(constants, pin_s, pin_a, y0 + h0 * f, f1)
    d2 = _rms(f1 - f, scale) / h0
    h1 = max(1e-6, h0 * 1e-3) if d1 <= 1e-15 and d2 <= 1e-15 else (0.01 / max(d1, d2)) ** (1.0 / 5.0)
    h_abs = min(100.0 * h0, h1)
    K = np.empty((stages + 1, n))
    y_new = np.empty(n)
    f_new = np.empty(n)
    stage = np.empty(n)
    error = np.empty(n)
    Q = np.empty((n, P.shape[1]))
    t = 0.0
    filled = 0
    while t < t_end:
        min_step = 10.0 * abs(np.nextafter(t, np.inf) - t)
        h_abs = min(max(h_abs, min_step), max_step)
        rejected = False
        while True:
            if h_abs < min_step:
                return filled
            t_new = min(t + h_abs, t_end)
            h = t_new - t
            h_abs = abs(h)
            # the stages (scipy's ``rk_step``)
            K[0] = f
            for s in range(1, stages):
                for j in range(n):
                    acc = 0.0
                    for i in range(s):
                        acc += K[i, j] * A[s, i]
                    stage[j] = y[j] + acc * h
                _rates(constants, pin_s, pin_a, stage, K[s])
            for j in range(n):
                acc = 0.0
                for i in range(stages):
                    acc += K[i, j] * B[i]
                y_new[j] = y[j] + h * acc
            _rates(constants, pin_s, pin_a, y_new, f_new)
            K[stages] = f_new
            for j in range(n):
                acc = 0.0
                for i in range(stages + 1):
                    acc += K[i, j] * E[i]
                error[j] = acc * h
                scale[j] = atol + max(abs(y[j]), abs(y_new[j])) * rtol
            error_norm = _rms(error, scale)
            if error_norm < 1.0:
                factor = _MAX_FACTOR if error_norm == 0.0 else min(_MAX_FACTOR, _SAFETY * error_norm ** _ERROR_EXPONENT)
                if rejected:
                    factor = min(1.0, factor)
                h_abs *= factor
                break
            h_abs *= max(_MIN_FACTOR, _SAFETY * error_norm ** _ERROR_EXPONENT)
            rejected = True
        # the samples in (t, t_new], from the step's dense output y_old + h Q (x, x^2, x^3, x^4)
        for j in range(n):
            for k in range(P.shape[1]):
                acc = 0.0
                for i in range(stages + 1):
                    acc += K[i, j] * P[i, k]
                Q[j, k] = acc
        span = t_new - t
        while filled < len(t_eval) and t_eval[filled] <= t_new:
            x = (t_eval[filled] - t) / span
            for j in range(n):
                acc = 0.0
                power = 1.0
                for k in range(P.shape[1]):
                    power *= x
                    acc += Q[j, k] * power
                out[filled, j] = span * acc + y[j]
            filled += 1
        t = t_new
        y[:] = y_new
        f[:] = f_new
    return filled

"""The liquid of a fluid dashpot as a compressible column along the bore: its mass, its waves, its
cavitation, and what its orifice jet carries out.

The column runs from the bore's floor (x = 0 side) to the piston's face; both are walls whose
velocities a caller prescribes each step (``LiquidColumn.step``: the lumped bodies of
``programmer/column_dashpot.py``, or the finite-element walls once the liquid is a force source), and
the column returns the pressure forces on them.  The liquid crosses the piston's face only through the
orifice, by the law of ``orifice.py``.  Equations (quasi-1D Euler, barotropic), in a cell of area A(x):

    d/dt (rho A) + d/dx (rho (u - w) A)            = 0       on a grid whose faces move at w
    d/dt (rho u A) + d/dx ((rho u (u - w) + p) A)  = p dA/dx  (the pin's shoulders, the bore's steps)
    p = max(K / n ((rho / rho0)^n - 1), p_v)                  Tait's law; at the vapour pressure p_v
                                                              the liquid parts (column separation):
                                                              below rho_v a cell is liquid and vapour
                                                              at p_v, its void V - m / rho_v

discretised by finite volumes: Rusanov's flux (the local Lax-Friedrichs flux, Toro, Riemann Solvers
and Numerical Methods for Fluid Dynamics, 3rd ed., section 10.5.1) on MUSCL-Hancock's face states
(minmod slopes, half a step's predictor; Toro ch. 14.4: second order where the flow is smooth) on a grid
stretched between the two walls (ALE: the faces' velocities interpolate the walls'), at a Courant
number ``COURANT``.  A wall face takes the acoustic Riemann solution against the wall, p* = p + rho c (u - w)
(Wylie & Streeter, Fluid Transients in Systems, ch. 3: the characteristic from the liquid), kept at or
above p_v; at the piston the orifice's outflow rho (u* - w) A = mdot(p*) and the same characteristic
give p* and u* (bisection).  The column's cavity (the void summed over the cells) grows where a wall
pulls away and closes with the pressure spike of its collapse.

Energy, in the frame the walls' velocities are given in:

    E = sum of m (u^2 / 2 + e(rho))          e = int p / rho^2 drho from rho0 (``compression_energy``)
    dE/dt = p_f A_f w_f - p_p A_p w_p - mdot (e + u*^2 / 2 + p* / rho*) - D

the floor's and the piston's work on the liquid, what the jet carries out of the column (mass,
momentum mdot (w_p + u_j), energy), and D >= 0, the column's own dissipation (its shock fronts, and
Rusanov's flux): the liquid's heating, D / (m c_p).  The jet's kinetic energy seen from the piston,
mdot (p* / rho* + (u* - w)^2 / 2), ends as heat downstream (the jet's temperature rise).

Range of validity: a column whose cross-section changes slowly along it (quasi-1D: a pin's taper
over many bore diameters), the liquid barotropic (its heating does not feed back on its pressure),
friction on the bore left out (a short column at high Reynolds number), no liquid returning through
the orifice (the space behind the piston holds none at pressure), the walls' and the liquid's Mach number
below ``MACH_LIMIT`` (the wall faces take the acoustic Riemann solution on the cells behind the front,
which hold the shock's state: Tait's Hugoniot to 0.04% up to Mach 0.5).  ``shockfem verify liquid_column`` checks
the Joukowsky pressure and its reflection, a fixed orifice against the method of characteristics, a
column separation and its collapse, and the control volume recovered by a short slow column.

Why finite volumes on a 1D column and not liquid finite elements: ``docs/theory.md``.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit

from . import orifice

COURANT = 0.95                 # forward Euler with Rusanov's flux is stable up to 1; near it, its diffusion (1 - COURANT) c dx / 2 is small
# below this share of its liquid density a cell is taken as empty: its sound speed and the pressure
# walls feel are the vapour's (the mixture holds no tension)
EMPTY = 1e-9
# the liquid's end is parted from the piston when the gap exceeds this share of the column's length
GAP = 1e-12
# the column's range: the walls' and the liquid's Mach number through its grid below this.  A piston driven
# into the closed column: its face's pressure within 0.04% of Tait's exact Hugoniot (p = rho0 s V,
# rho0 s = rho1 (s - V)) at Mach 0.1 to 0.5 for n = 1 and n = 7, and at 0.7 for n = 1; at Mach 0.7 and
# n = 7, 30% off (400 cells; tests/unit/test_column.py).  Joukowsky's rho c V is 22% (n = 1) and 49%
# (n = 7) under the Hugoniot at Mach 0.5: the column, not the acoustic formula, holds there
MACH_LIMIT = 0.5
# a column parted by less than this share of its volume has not cavitated (the void's round-off)
PARTED = 1e-6
# the energy accounts, by index in ``LiquidColumn.accounts``
W_FLOOR, W_PISTON, OUT_MASS, OUT_MOMENTUM, OUT_ENERGY, JET_HEAT = range(6)
ACCOUNTS = ("work of the floor [J]", "work of the piston [J]", "mass out [kg]", "momentum out [N s]",
            "energy out [J]", "jet's heat [J]")


@dataclass(frozen=True)
class ColumnLiquid:
    """The liquid: rho0 [kg/m^3], K [Pa], Tait's n, the vapour pressure p_v [Pa, gauge] and the heat
    capacity c_p [J/(kg K)].  Defaults: a mineral hydraulic oil (ISO VG 32: 870 kg/m^3, 1.5 GPa,
    1.9 kJ/(kg K); Totten, Handbook of Hydraulic Fluid Technology, 2nd ed., ch. 3) parting at
    -0.1 MPa gauge (its vapour pressure ~0 absolute under a 0.1 MPa atmosphere)."""
    density: float = 870.0
    bulk_modulus: float = 1.5e9
    tait_exponent: float = 1.0
    vapour_pressure: float = -1.0e5
    heat_capacity: float = 1900.0

    def params(self) -> np.ndarray:
        """The kernels' array: rho0, K, n, p_v and the vapour density (``vapour_density_of``), which every
        sound speed reads: worked out once here rather than as a power at every face of every step."""
        rho0, K, n, pv = self.density, self.bulk_modulus, self.tait_exponent, self.vapour_pressure
        return np.array([rho0, K, n, pv, vapour_density_of(rho0, K, n, pv)])

    def sound_speed(self) -> float:
        return math.sqrt(self.bulk_modulus / self.density)


@njit(cache=True)
def pressure(rho, liquid):
    """Tait's gauge pressure at ``rho``, never below the vapour pressure."""
    rho0, K, n, pv = liquid[0], liquid[1], liquid[2], liquid[3]
    if n == 1.0:                 # the linear law without a power: the column takes it at every face of every step
        return max(K * (rho / rho0 - 1.0), pv)
    return max(K / n * ((rho / rho0) ** n - 1.0), pv)


@njit(cache=True)
def density(p, liquid):
    """Tait's density at the gauge pressure ``p`` (at or above the vapour pressure)."""
    rho0, K, n = liquid[0], liquid[1], liquid[2]
    if n == 1.0:
        return rho0 * (1.0 + p / K)
    return rho0 * (1.0 + n * p / K) ** (1.0 / n)


@njit(cache=True)
def vapour_density_of(rho0, K, n, pv):
    """The density at which Tait's law reaches the vapour pressure: below it the column parts."""
    if n == 1.0:
        return rho0 * max(1.0 + pv / K, EMPTY)
    return rho0 * max(1.0 + n * pv / K, EMPTY) ** (1.0 / n)


@njit(cache=True)
def vapour_density(liquid):
    """The vapour density of the kernels' array (``ColumnLiquid.params``)."""
    return liquid[4]


@njit(cache=True)
def sound_speed(rho, liquid):
    """The liquid's sound speed at ``rho`` (taken at the vapour density in a parted cell: Rusanov's
    dissipation then stays the liquid's, which keeps the collapse stable)."""
    rho0, K, n = liquid[0], liquid[1], liquid[2]
    if n == 1.0:                 # the linear law's c = sqrt(K / rho0) at every density
        return math.sqrt(K / rho0)
    r = max(rho, vapour_density(liquid)) / rho0
    return math.sqrt(K * r ** (n - 1.0) / rho0)


@njit(cache=True)
def specific_energy(rho, liquid):
    """e(rho) = int p / rho^2 drho from rho0 [J/kg]: Tait's compression energy down to the vapour
    density, then p_v (1 / rho_v - 1 / rho) for the void opened against the vapour pressure."""
    rho0, K, n, pv = liquid[0], liquid[1], liquid[2], liquid[3]
    rv = vapour_density(liquid)
    r = max(rho, rv) / rho0
    if abs(n - 1.0) < 1e-12:
        e = K / rho0 * (math.log(r) + 1.0 / r - 1.0)
    else:
        e = K / (n * rho0) * ((r ** (n - 1.0) - 1.0) / (n - 1.0) + 1.0 / r - 1.0)
    if rho < rv:
        e += pv * (1.0 / rv - 1.0 / max(rho, EMPTY * rho0))
    return e


@njit(cache=True)
def _interpolate(x, xs, ys):
    """np.interp of one point (its ends held), by bisection: numba's np.interp of a scalar allocates arrays,
    and the column interpolates its section at every face of every step (it was most of a step's time)."""
    n = len(xs)
    if x <= xs[0]:
        return ys[0]
    if x >= xs[n - 1]:
        return ys[n - 1]
    low, high = 0, n - 1
    while high - low > 1:
        mid = (low + high) // 2
        if xs[mid] <= x:
            low = mid
        else:
            high = mid
    return ys[low] + (ys[high] - ys[low]) * (x - xs[low]) / (xs[high] - xs[low])


@njit(cache=True)
def _piston_face(rho, u, p, w, a, A, liquid, law):
    """The piston's face: (p*, u*, mdot) from the liquid's characteristic p* + rho c u* = p + rho c u and
    the orifice's outflow rho (u* - w) A = mdot(p*), bisection on p* (the outflow's mismatch falls as p*
    rises); a closed face (no outflow at p* = 0) is a wall."""
    c = sound_speed(rho, liquid)
    z = rho * c
    pv = liquid[3]
    riemann = p + z * (u - w)            # the pressure of a wall at w
    if a <= 0.0 or riemann <= 0.0:
        return max(riemann, pv), w, 0.0
    low, high = 0.0, riemann
    for _ in range(80):
        mid = 0.5 * (low + high)
        rho_m = density(mid, liquid)
        u_m = u + (p - mid) / z
        mismatch = rho_m * (u_m - w) * A - orifice.mass_flow(mid, rho_m, sound_speed(rho_m, liquid), a, A, law)
        if mismatch > 0.0:
            low = mid
        else:
            high = mid
        if high - low <= 1e-12 * riemann:
            break
    p_star = 0.5 * (low + high)
    rho_s = density(p_star, liquid)
    mdot = orifice.mass_flow(p_star, rho_s, sound_speed(rho_s, liquid), a, A, law)
    return p_star, w + mdot / (rho_s * A), mdot


@njit(cache=True)
def _rusanov(rho_l, u_l, p_l, rho_r, u_r, p_r, w, liquid):
    """Rusanov's flux of (mass, momentum) per unit area through a face moving at ``w``."""
    s = max(abs(u_l - w) + sound_speed(rho_l, liquid), abs(u_r - w) + sound_speed(rho_r, liquid))
    f_mass = 0.5 * (rho_l * (u_l - w) + rho_r * (u_r - w)) - 0.5 * s * (rho_r - rho_l)
    f_mom = (0.5 * (rho_l * u_l * (u_l - w) + p_l + rho_r * u_r * (u_r - w) + p_r)
             - 0.5 * s * (rho_r * u_r - rho_l * u_l))
    return f_mass, f_mom


@njit(cache=True)
def _minmod(a, b):
    if a * b <= 0.0:
        return 0.0
    return a if abs(a) < abs(b) else b


@njit(cache=True)
def _hancock(rho, u, c, x, v_floor, w_end, dt, liquid):
    """MUSCL-Hancock's face states (Toro, ch. 14.4): each cell's density and velocity (its sound speed
    ``c``) with minmod slopes, evolved half a step by the primitive equations rho_t + (u - w) rho_x + rho u_x = 0,
    u_t + (u - w) u_x + (c^2 / rho) rho_x = 0 (c^2 = 0 in a parted cell), at its (left, right) faces:
    rows of (rho_left, u_left, rho_right, u_right).  The two end cells keep their means (first order at
    the walls, whose Riemann solutions take the cells' means)."""
    N = len(rho)
    L = x[-1] - x[0]
    rv = vapour_density(liquid)
    out = np.empty((N, 4))
    for i in range(N):
        out[i, 0] = out[i, 2] = rho[i]
        out[i, 1] = out[i, 3] = u[i]
    for i in range(1, N - 1):
        d_rho = _minmod(rho[i] - rho[i - 1], rho[i + 1] - rho[i])
        d_u = _minmod(u[i] - u[i - 1], u[i + 1] - u[i])
        dx = x[i + 1] - x[i]
        w = v_floor + (0.5 * (x[i] + x[i + 1]) - x[0]) / L * (w_end - v_floor)
        c2 = c[i] ** 2 if rho[i] >= rv else 0.0
        half = 0.5 * dt / dx
        rho_h = rho[i] - half * ((u[i] - w) * d_rho + rho[i] * d_u)
        u_h = u[i] - half * ((u[i] - w) * d_u + c2 / rho[i] * d_rho)
        out[i, 0], out[i, 1] = rho_h - 0.5 * d_rho, u_h - 0.5 * d_u
        out[i, 2], out[i, 3] = rho_h + 0.5 * d_rho, u_h + 0.5 * d_u
    return out


@njit(cache=True)
def column_step(m, q, x, x_piston, area_x, area_a, liquid, law, v_floor, v_piston, a_orifice, reservoir, dt,
                accounts):
    """One forward-Euler step of the column: cell masses ``m`` and momenta ``q`` advanced in place on the
    faces ``x`` from the floor (``x[0]``, moving at ``v_floor``) to the liquid's end (``x[-1]``), at or
    short of the piston's face at ``x_piston`` (moving at ``v_piston``); the area a table (``area_x`` from
    the floor, ``area_a``).  ``reservoir``: NaN for a floor that is a wall, else the pressure of a
    reservoir the column opens into at a still floor (the textbook water-hammer pipe).

    At the piston: attached, the orifice's face (``_piston_face``); parted (the liquid's end short of
    the piston, or the wall's Riemann pressure below p_v), a free surface at p_v moving at the liquid's
    characteristic speed u* = u + (p - p_v) / (rho c), the gap between it and the piston a cavity (the
    discrete vapour cavity at the piston, Wylie & Streeter ch. 8), until the liquid reaches the piston
    again.  Adds the step's work, outflow and jet to ``accounts``.  Returns (floor pressure, piston
    pressure, orifice mass rate, the jet's reaction on the piston, the liquid end's velocity)."""
    N = len(m)
    L = x[-1] - x[0]
    rho = np.empty(N)
    u = np.empty(N)
    p = np.empty(N)
    c = np.empty(N)
    A_face = np.empty(N + 1)
    for i in range(N + 1):
        A_face[i] = _interpolate(x[i] - x[0], area_x, area_a)
    for i in range(N):
        volume = 0.5 * (A_face[i] + A_face[i + 1]) * (x[i + 1] - x[i])
        rho[i] = m[i] / volume
        u[i] = q[i] / m[i] if m[i] > 0.0 else 0.0
        p[i] = pressure(rho[i], liquid)
        c[i] = sound_speed(rho[i], liquid)
    f_mass = np.zeros(N + 1)
    f_mom = np.zeros(N + 1)
    # the floor: a wall, or a reservoir's pressure, and the liquid's characteristic toward it
    z0 = rho[0] * c[0]
    if math.isnan(reservoir):
        p_floor = max(p[0] + z0 * (v_floor - u[0]), liquid[3])
        f_mom[0] = p_floor * A_face[0]
        accounts[W_FLOOR] += dt * p_floor * A_face[0] * v_floor
    else:
        p_floor = reservoir
        u_in = u[0] + (p_floor - p[0]) / z0
        rho_in = density(p_floor, liquid)
        f_mass[0] = rho_in * u_in * A_face[0]
        f_mom[0] = f_mass[0] * u_in + p_floor * A_face[0]
        accounts[W_FLOOR] += dt * f_mass[0] * (specific_energy(rho_in, liquid) + 0.5 * u_in * u_in
                                               + p_floor / rho_in)
    # the piston's end: attached (the orifice's face) or parted (a free surface at the vapour pressure)
    pv = liquid[3]
    zN = rho[N - 1] * c[N - 1]
    parted = x_piston - x[N] > GAP * L or p[N - 1] + zN * (u[N - 1] - v_piston) < pv
    mdot = 0.0
    if parted:
        p_piston = pv
        u_star = u[N - 1] + (p[N - 1] - pv) / zN
        # the liquid reaches the piston within the step: it lands on it
        w_end = min(u_star, (x_piston + dt * v_piston - x[N]) / dt) if dt > 0.0 else u_star
    else:
        p_piston, u_star, mdot = _piston_face(rho[N - 1], u[N - 1], p[N - 1], v_piston, a_orifice, A_face[N],
                                              liquid, law)
        w_end = v_piston
    faces = _hancock(rho, u, c, x, v_floor, w_end, dt, liquid)
    for i in range(1, N):
        w = v_floor + (x[i] - x[0]) / L * (w_end - v_floor)
        rho_l, u_l, rho_r, u_r = faces[i - 1, 2], faces[i - 1, 3], faces[i, 0], faces[i, 1]
        fm, fq = _rusanov(rho_l, u_l, pressure(rho_l, liquid), rho_r, u_r, pressure(rho_r, liquid), w, liquid)
        f_mass[i] = fm * A_face[i]
        f_mom[i] = fq * A_face[i]
    f_mass[N] = mdot
    f_mom[N] = mdot * u_star + p_piston * A_face[N]
    for i in range(N):
        m[i] -= dt * (f_mass[i + 1] - f_mass[i])
        # the pressure on the change of area within the cell
        q[i] -= dt * (f_mom[i + 1] - f_mom[i] - p[i] * (A_face[i + 1] - A_face[i]))
        m[i] = max(m[i], 0.0)
    jet = 0.0
    if mdot > 0.0:
        rho_s = density(p_piston, liquid)
        jet = orifice.jet_reaction(mdot, rho_s, a_orifice, A_face[N], law)
        u_rel = u_star - v_piston
        u_jet = mdot / (rho_s * orifice.jet_coefficient(min(a_orifice / A_face[N], 1.0), law) * a_orifice)
        accounts[OUT_MASS] += dt * mdot
        accounts[OUT_MOMENTUM] += dt * mdot * (v_piston + u_jet)
        accounts[OUT_ENERGY] += dt * mdot * (specific_energy(rho_s, liquid) + 0.5 * u_star * u_star
                                             + p_piston / rho_s)
        accounts[JET_HEAT] += dt * mdot * (p_piston / rho_s + 0.5 * u_rel * u_rel)
    accounts[W_PISTON] -= dt * p_piston * A_face[N] * w_end
    # the faces move: the floor with its wall, the end with the liquid's, the rest stretched between
    x0, x0_new, xN_new = x[0], x[0] + dt * v_floor, x[N] + dt * w_end
    for i in range(N + 1):
        x[i] = x0_new + (x[i] - x0) / L * (xN_new - x0_new)
    return p_floor, p_piston, mdot, jet, w_end


@njit(cache=True)
def stable_step(m, q, x, area_x, area_a, liquid, v_floor, v_piston):
    """COURANT times the smallest cell's crossing time by its fastest signal, |u - w| + c."""
    N = len(m)
    L = x[-1] - x[0]
    dt = np.inf
    for i in range(N):
        dx = x[i + 1] - x[i]
        A = _interpolate(0.5 * (x[i] + x[i + 1]) - x[0], area_x, area_a)
        rho = m[i] / (A * dx)
        u = q[i] / m[i] if m[i] > 0.0 else 0.0
        w = v_floor + (0.5 * (x[i] + x[i + 1]) - x[0]) / L * (v_piston - v_floor)
        dt = min(dt, COURANT * dx / (abs(u - w) + abs(v_piston - v_floor) + sound_speed(rho, liquid)))
    return dt


@njit(cache=True)
def column_energy(m, q, x, area_x, area_a, liquid):
    """The column's kinetic and compression energy [J]."""
    total = 0.0
    for i in range(len(m)):
        if m[i] <= 0.0:
            continue
        A = _interpolate(0.5 * (x[i] + x[i + 1]) - x[0], area_x, area_a)
        rho = m[i] / (A * (x[i + 1] - x[i]))
        total += m[i] * (0.5 * (q[i] / m[i]) ** 2 + specific_energy(rho, liquid))
    return total


@njit(cache=True)
def column_void(m, x, area_x, area_a, liquid):
    """The column's cavity [m^3]: the cells' volume beyond what their mass fills at the vapour density."""
    rv = vapour_density(liquid)
    total = 0.0
    for i in range(len(m)):
        A = _interpolate(0.5 * (x[i] + x[i + 1]) - x[0], area_x, area_a)
        total += max(A * (x[i + 1] - x[i]) - m[i] / rv, 0.0)
    return total


@njit(cache=True)
def column_mach(m, q, x, area_x, area_a, liquid, v_floor, v_end):
    """The largest Mach number of the liquid through the grid, |u - w| / c over the cells (w the cell's
    grid velocity, between the floor's and the liquid end's)."""
    N = len(m)
    L = x[-1] - x[0]
    largest = 0.0
    for i in range(N):
        if m[i] <= 0.0:
            continue
        A = _interpolate(0.5 * (x[i] + x[i + 1]) - x[0], area_x, area_a)
        rho = m[i] / (A * (x[i + 1] - x[i]))
        w = v_floor + (0.5 * (x[i] + x[i + 1]) - x[0]) / L * (v_end - v_floor)
        largest = max(largest, abs(q[i] / m[i] - w) / sound_speed(rho, liquid))
    return largest


@njit(cache=True)
def column_walls(m, x, area_x, area_a, liquid):
    """The column's volume [m^3] and rho c at its floor's and its liquid end's cells [Pa s/m]."""
    N = len(m)
    volume = 0.0
    z = np.empty(2)
    rv = vapour_density(liquid)
    for i in range(N):
        A = _interpolate(0.5 * (x[i] + x[i + 1]) - x[0], area_x, area_a)
        volume += A * (x[i + 1] - x[i])
        if i == 0 or i == N - 1:
            rho = max(m[i] / (A * (x[i + 1] - x[i])), rv)
            z[0 if i == 0 else 1] = rho * sound_speed(rho, liquid)
    return volume, z[0], z[1]


class LiquidColumn:
    """A column of ``cells`` finite volumes from a floor at ``x_floor`` to a piston at ``x_piston``,
    the liquid at rest at ``pressure0`` [Pa gauge] moving with ``velocity0`` [m/s]; ``area``: the
    cross-section, a number [m^2] or a table ((distance from the floor [m], area [m^2]), ...) (a pin
    fixed to the floor); ``law``: the orifice's (``orifice.OrificeLaw``); ``reservoir``: the floor as a
    reservoir at that pressure [Pa] (standing still), not a wall.  Driven by ``step`` with the
    walls' velocities and the orifice's area; SI throughout."""

    def __init__(self, liquid: ColumnLiquid, x_floor: float, x_piston: float, area, cells: int,
                 law: orifice.OrificeLaw = orifice.AREA_RATIO, pressure0: float = 0.0, velocity0: float = 0.0,
                 reservoir: float | None = None):
        table = np.array([[0.0, area], [1.0, area]] if np.isscalar(area) else area, dtype=float).reshape(-1, 2)
        self.area_x, self.area_a = np.ascontiguousarray(table[:, 0]), np.ascontiguousarray(table[:, 1])
        self.liquid = liquid
        self._liquid = liquid.params()
        self._law = law.code()
        self.law = law
        # a floor that is a reservoir at this pressure [Pa] (it must then stand still), or a wall
        self.reservoir = float("nan") if reservoir is None else reservoir
        self.x = np.linspace(x_floor, x_piston, cells + 1)       # the faces: the floor to the liquid's end
        self.x_piston = x_piston
        n, K, rho0 = liquid.tait_exponent, liquid.bulk_modulus, liquid.density
        rho = rho0 * (1.0 + n * pressure0 / K) ** (1.0 / n)
        A_mid = np.interp(0.5 * (self.x[1:] + self.x[:-1]) - x_floor, self.area_x, self.area_a)
        self.m = rho * A_mid * np.diff(self.x)
        self.q = self.m * velocity0
        self.accounts = np.zeros(len(ACCOUNTS))
        self.initial_energy = self.energy()
        self.floor_pressure = self.piston_pressure = pressure0
        self.mass_rate = self.jet_force = 0.0

    def stable_step(self, v_floor: float, v_piston: float) -> float:
        return stable_step(self.m, self.q, self.x, self.area_x, self.area_a, self._liquid, v_floor, v_piston)

    def step(self, v_floor: float, v_piston: float, a_orifice: float, dt: float) -> tuple[float, float]:
        """Advance the column over ``dt`` with the walls at these velocities (held over the step) and the
        orifice at ``a_orifice``; returns the forces of the liquid on the floor and on the piston along
        the column (floor toward piston positive): (-p_f A_f, p_p A_p - J)."""
        p_f, p_p, mdot, jet, _ = column_step(self.m, self.q, self.x, self.x_piston, self.area_x, self.area_a,
                                             self._liquid, self._law, v_floor, v_piston, a_orifice, self.reservoir,
                                             dt, self.accounts)
        self.x_piston += dt * v_piston
        self.floor_pressure, self.piston_pressure, self.mass_rate, self.jet_force = p_f, p_p, mdot, jet
        return -p_f * self.area(0.0), p_p * self.area(self.length()) - jet

    # ---------------------------------------------------------------- what it holds
    def length(self) -> float:
        """The bore's length between the floor and the piston [m]."""
        return float(self.x_piston - self.x[0])

    def gap(self) -> float:
        """The cavity between the liquid's end and the piston [m^3]."""
        return max(self.x_piston - float(self.x[-1]), 0.0) * self.area(float(self.x[-1] - self.x[0]))

    def area(self, distance: float) -> float:
        return _interpolate(float(distance), self.area_x, self.area_a)

    def mass(self) -> float:
        return float(self.m.sum())

    def volume(self) -> float:
        """The column's volume from the floor to the liquid's end [m^3]."""
        return column_walls(self.m, self.x, self.area_x, self.area_a, self._liquid)[0]

    def energy(self) -> float:
        return column_energy(self.m, self.q, self.x, self.area_x, self.area_a, self._liquid)

    def kinetic_energy(self) -> float:
        """The column's kinetic energy [J] (``energy`` less its compression energy)."""
        moving = self.m > 0.0
        return float(np.sum(0.5 * self.q[moving] ** 2 / self.m[moving]))

    def void(self) -> float:
        """The column's cavity [m^3]: the gap at the piston and the parted cells' void."""
        return self.gap() + column_void(self.m, self.x, self.area_x, self.area_a, self._liquid)

    def wall_impedances(self) -> tuple[float, float]:
        """rho c of the liquid at the floor and at the liquid's end [Pa s/m]: what a wall moving against it
        feels per unit area and speed (the acoustic Riemann solution)."""
        _, z_floor, z_end = column_walls(self.m, self.x, self.area_x, self.area_a, self._liquid)
        return z_floor, z_end

    def mach(self, v_floor: float, v_piston: float) -> float:
        """The largest Mach number of the liquid through its grid (``column_mach``)."""
        return column_mach(self.m, self.q, self.x, self.area_x, self.area_a, self._liquid, v_floor, v_piston)

    def pressures(self) -> np.ndarray:
        A = np.interp(0.5 * (self.x[1:] + self.x[:-1]) - self.x[0], self.area_x, self.area_a)
        rho = self.m / (A * np.diff(self.x))
        return np.array([pressure(r, self._liquid) for r in rho])

    def dissipated(self) -> float:
        """D: the walls' work less the change of the column's energy and what the jet carried out [J]."""
        a = self.accounts
        return a[W_FLOOR] + a[W_PISTON] - a[OUT_ENERGY] - (self.energy() - self.initial_energy)

    def summary(self) -> dict:
        a = self.accounts
        c_p = self.liquid.heat_capacity
        return {"model": "1D compressible column (finite volumes, Rusanov), " + self.law.describe(),
                **{name: float(a[k]) for k, name in enumerate(ACCOUNTS)},
                "column energy change [J]": self.energy() - self.initial_energy,
                "column dissipation [J]": self.dissipated(),
                "column heating [K]": self.dissipated() / max(self.mass(), 1e-300) / c_p,
                "jet heating [K]": a[JET_HEAT] / max(a[OUT_MASS], 1e-300) / c_p,
                "cavity [m^3]": self.void()}

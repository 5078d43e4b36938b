"""A perfect gas as a column along a constant bore (quasi-1D Euler), from a breech (a wall, or a reservoir at rest
through a full-bore opening) to a moving piston, with a distributed bleed through holes in the wall: the
independent check of the gas drive's ported face law (``machine.drive_end``).

Why its own module and not ``column.py``'s kernels: the liquid column is barotropic (Tait's law, no energy
equation, its flux Rusanov's on two variables); the gas needs the energy equation, an ideal-gas flux and a
reservoir inflow boundary.  What is shared: the minmod limiter (``column._minmod``) and the structure (cell
totals on faces stretched between the two ends, the faces moving at w(x) interpolating the ends' speeds,
MUSCL-Hancock face states, the end cells first order).

Equations, per unit bore area, on a grid whose faces move at w:

    d/dt (rho dx)  + [rho (u - w)]                 = -mdot'
    d/dt (rho u dx) + [rho u (u - w) + p]           = -mdot' v_ax
    d/dt (E dx)    + [E (u - w) + p u]              = -mdot' (h + u^2 / 2)     E = p / (gamma - 1) + rho u^2 / 2

the brackets the differences across a cell of the face fluxes, mdot' the bleed's mass rate per unit bore area
over the cell: the holes' open area in it (the wall's open share times the perimeter times the length of the
cell past the band's start, times the holes' discharge coefficient) through the orifice law (``orifice_mass_flow``,
the gas models' one, the cell's static p and T its upstream state, as the ported
law takes the face's) to the ambient.  The gas leaving takes its stagnation enthalpy h + u^2 / 2 (the wall does
no work on it); its axial speed v_ax is a choice: ``RADIAL`` jets (v_ax = 0, the cylinder takes no axial thrust,
the momentum they do not carry staying in the column) or ``AXIAL`` jets (v_ax = u, keeping the column's speed):
the two ends of the ported law's bracket.

Discretisation: HLLC's flux (Toro, Riemann Solvers and Numerical Methods for Fluid Dynamics, 3rd ed., sec. 10.4,
the wave speeds of Davis's estimate, eq. 10.48) in the frame of each face (the flux moved back to the lab frame
by the Galilean transform), on MUSCL-Hancock's face states (minmod slopes of rho, u, p, half a step's predictor of
the primitive equations; Toro sec. 14.4: second order where the flow is smooth, first at shocks), forward Euler
over the step, at ``COURANT``.  The piston's face is a reflecting wall at its speed (the mirror state: HLLC's
contact moves with it, its p* the face's pressure); a still breech is the same wall at rest; a reservoir at
(p0, T0) feeds the first face steadily and isentropically, c^2 + (gamma - 1) u^2 / 2 = c0^2, the face's state on
that isentrope joined to the first cell's by a contact and the wave it sends into the column, a shock or a
rarefaction (Toro's pressure function, sec. 4.2: so a tank opened on still gas far below its pressure drives its
shock into it), choked at the sonic
state past it (the infinitely chambered gun's entry, ``launcher.simple_wave``), a wall at p0 if the gas would
flow back.

Range of validity: a perfect gas (no covolume), a constant bore, no friction or heat transfer to the wall, the
bleed quasi-steady (each hole's flow the orifice law's at the cell's state: the gas's transit through the wall
short against the flow's time), the holes' jets taking either all or none of the column's axial momentum (the
real share between the two ends).  ``shockfem verify gas_column`` checks Sod's shock tube against the exact
Riemann solution at two grids, the face pressure of a piston withdrawn at constant speed against the simple
wave's, and the simple-wave gun's muzzle speed.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from .column import _minmod

COURANT = 0.8                # MUSCL-Hancock with HLLC is stable up to 1 (Toro sec. 14.4); 0.8 keeps the margin
RADIAL, AXIAL = 0, 1         # the bleed's jets: no axial momentum, or the column's
WALL, RESERVOIR = 0, 1       # the breech's kinds
# below this relative pressure difference the orifice's flow is taken linear in it (``orifice_mass_flow``)
EQUAL = 1e-4


@njit(cache=True)
def orifice_mass_flow(gamma, R, area, p_up, T_up, p_down):
    """The mass flow [kg/s] through the effective ``area`` (Cd A) from (p_up, T_up) to p_down <= p_up, an isentropic
    nozzle from the source's stagnation state (zero if p_down >= p_up: which side is upstream is the caller's):

        choked, p_down / p_up <= (2 / (gamma + 1))^(gamma / (gamma - 1)):
            mdot = area p_up sqrt(gamma / (R T_up)) (2 / (gamma + 1))^((gamma + 1) / (2 (gamma - 1)))
        otherwise, r = p_down / p_up:
            mdot = area p_up sqrt(2 gamma / ((gamma - 1) R T_up) (r^(2 / gamma) - r^((gamma + 1) / gamma)))

    Unchoked, the flow goes as sqrt(p_up - p_down) as the pressures equalise, whose slope is infinite: below a
    difference of ``EQUAL`` of p_up it is taken linear in the difference (continuous at EQUAL), so an ODE solver
    does not crawl through the equalisation.  The one orifice law of the gas models (``launcher.gas.orifice_flow``
    calls it); compiled, so the column's bleed calls it inside its step."""
    if area <= 0.0 or p_down >= p_up or p_up <= 0.0 or T_up <= 0.0:
        return 0.0
    ratio = max(p_down / p_up, 0.0)
    critical = (2.0 / (gamma + 1.0)) ** (gamma / (gamma - 1.0))
    if ratio <= critical:
        return area * p_up * math.sqrt(gamma / (R * T_up)) * (2.0 / (gamma + 1.0)) ** ((gamma + 1.0)
                                                                                      / (2.0 * (gamma - 1.0)))
    scale = 1.0
    if ratio > 1.0 - EQUAL:
        scale, ratio = (1.0 - ratio) / EQUAL, 1.0 - EQUAL
    return scale * area * p_up * math.sqrt(2.0 * gamma / ((gamma - 1.0) * R * T_up)
                                           * (ratio ** (2.0 / gamma) - ratio ** ((gamma + 1.0) / gamma)))


@njit(cache=True)
def _hllc(rho_l, u_l, p_l, rho_r, u_r, p_r, gamma):
    """HLLC's flux (mass, momentum, energy) per unit area through a still face, and its p* (Toro sec. 10.4)."""
    c_l = math.sqrt(gamma * p_l / rho_l)
    c_r = math.sqrt(gamma * p_r / rho_r)
    s_l = min(u_l - c_l, u_r - c_r)
    s_r = max(u_l + c_l, u_r + c_r)
    s_m = ((p_r - p_l + rho_l * u_l * (s_l - u_l) - rho_r * u_r * (s_r - u_r))
           / (rho_l * (s_l - u_l) - rho_r * (s_r - u_r)))
    p_star = p_l + rho_l * (s_l - u_l) * (s_m - u_l)
    e_l = p_l / (gamma - 1.0) + 0.5 * rho_l * u_l * u_l
    e_r = p_r / (gamma - 1.0) + 0.5 * rho_r * u_r * u_r
    if s_l >= 0.0:
        return rho_l * u_l, rho_l * u_l * u_l + p_l, u_l * (e_l + p_l), p_star
    if s_r <= 0.0:
        return rho_r * u_r, rho_r * u_r * u_r + p_r, u_r * (e_r + p_r), p_star
    if s_m >= 0.0:
        rho, u, p, e, s = rho_l, u_l, p_l, e_l, s_l
    else:
        rho, u, p, e, s = rho_r, u_r, p_r, e_r, s_r
    # the star state on the side of the face (Toro eq. 10.39), the flux F_K + S_K (U*_K - U_K)
    f = rho * (s - u) / (s - s_m)
    d_mass = f - rho
    d_mom = f * s_m - rho * u
    d_energy = f * (e / rho + (s_m - u) * (s_m + p / (rho * (s - u)))) - e
    return (rho * u + s * d_mass, rho * u * u + p + s * d_mom, u * (e + p) + s * d_energy, p_star)


@njit(cache=True)
def _moving_flux(rho_l, u_l, p_l, rho_r, u_r, p_r, w, gamma):
    """HLLC's flux through a face moving at ``w``, in the lab frame: solved in the face's frame, moved back by
    the Galilean transform (mass f, momentum f_q + w f, energy f_E + w f_q + w^2 f / 2); and its p*."""
    f, f_q, f_e, p_star = _hllc(rho_l, u_l - w, p_l, rho_r, u_r - w, p_r, gamma)
    return f, f_q + w * f, f_e + w * f_q + 0.5 * w * w * f, p_star


@njit(cache=True)
def _right_wave_speed(p, rho_r, u_r, p_r, gamma):
    """The gas's speed at pressure ``p`` on the left of a right-facing wave into the state (rho_r, u_r, p_r):
    u_r + f_R(p), Toro's pressure function (Riemann Solvers, sec. 4.2, eqs. 4.6-4.7): a shock above p_r, a
    rarefaction below."""
    if p > p_r:
        a_r, b_r = 2.0 / ((gamma + 1.0) * rho_r), (gamma - 1.0) / (gamma + 1.0) * p_r
        return u_r + (p - p_r) * math.sqrt(a_r / (p + b_r))
    c_r = math.sqrt(gamma * p_r / rho_r)
    return u_r + 2.0 * c_r / (gamma - 1.0) * ((p / p_r) ** ((gamma - 1.0) / (2.0 * gamma)) - 1.0)


@njit(cache=True)
def _reservoir_inflow(rho, u, p, p0, rho0, gamma):
    """The first face's state (rho, u, p) fed from a reservoir at rest at (p0, rho0) (module docstring): on the
    reservoir's steady isentrope, u_b(p)^2 = 2 (c0^2 - c(p)^2) / (gamma - 1), c(p) = c0 (p / p0)^((gamma - 1) /
    (2 gamma)), joined to the first cell's state by a contact and the right-facing wave (``_right_wave_speed``):
    the p where u_b(p) = u + f_R(p), by bisection (u_b falls and u + f_R rises with p); choked at the sonic
    state where the cell would take more than it, a wall at p0 where the gas would flow back."""
    c0 = math.sqrt(gamma * p0 / rho0)
    k = (gamma - 1.0) / (2.0 * gamma)
    if _right_wave_speed(p0, rho, u, p, gamma) <= 0.0:
        return rho0, 0.0, p0
    p_low = p0 * (2.0 / (gamma + 1.0)) ** (0.5 / k)
    c_star = c0 * math.sqrt(2.0 / (gamma + 1.0))
    if _right_wave_speed(p_low, rho, u, p, gamma) >= c_star:
        p_b = p_low
    else:
        lo, hi = p_low, p0
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            c = c0 * (mid / p0) ** k
            if math.sqrt(max(2.0 * (c0 * c0 - c * c) / (gamma - 1.0), 0.0)) > _right_wave_speed(mid, rho, u, p,
                                                                                                 gamma):
                lo = mid
            else:
                hi = mid
        p_b = 0.5 * (lo + hi)
    r = (p_b / p0) ** k
    u_b = c0 * math.sqrt(max(2.0 * (1.0 - r * r) / (gamma - 1.0), 0.0))
    return rho0 * r ** (2.0 / (gamma - 1.0)), u_b, p_b


@njit(cache=True)
def _primitives(m, q, e, x, gamma):
    N = len(m)
    rho, u, p = np.empty(N), np.empty(N), np.empty(N)
    for i in range(N):
        dx = x[i + 1] - x[i]
        rho[i] = m[i] / dx
        u[i] = q[i] / m[i]
        p[i] = (gamma - 1.0) * (e[i] - 0.5 * q[i] * u[i]) / dx
    return rho, u, p


@njit(cache=True)
def _hancock(rho, u, p, x, w_end, dt, gamma):
    """MUSCL-Hancock's face states (Toro sec. 14.4): minmod slopes of rho, u, p, evolved half a step by the
    primitive equations in the cell's moving frame; rows (rho, u, p) at the cell's left (0:3) and right (3:6)
    faces.  The end cells keep their means (first order at the ends)."""
    N = len(rho)
    L = x[-1] - x[0]
    out = np.empty((N, 6))
    for i in range(N):
        out[i, 0] = out[i, 3] = rho[i]
        out[i, 1] = out[i, 4] = u[i]
        out[i, 2] = out[i, 5] = p[i]
    for i in range(1, N - 1):
        d_rho = _minmod(rho[i] - rho[i - 1], rho[i + 1] - rho[i])
        d_u = _minmod(u[i] - u[i - 1], u[i + 1] - u[i])
        d_p = _minmod(p[i] - p[i - 1], p[i + 1] - p[i])
        w = (0.5 * (x[i] + x[i + 1]) - x[0]) / L * w_end
        half = 0.5 * dt / (x[i + 1] - x[i])
        v = u[i] - w
        rho_h = rho[i] - half * (v * d_rho + rho[i] * d_u)
        u_h = u[i] - half * (v * d_u + d_p / rho[i])
        p_h = p[i] - half * (v * d_p + gamma * p[i] * d_u)
        out[i, 0], out[i, 1], out[i, 2] = rho_h - 0.5 * d_rho, u_h - 0.5 * d_u, p_h - 0.5 * d_p
        out[i, 3], out[i, 4], out[i, 5] = rho_h + 0.5 * d_rho, u_h + 0.5 * d_u, p_h + 0.5 * d_p
        if out[i, 0] <= 0.0 or out[i, 2] <= 0.0 or out[i, 3] <= 0.0 or out[i, 5] <= 0.0:
            # a face state the slopes drive negative: the cell's mean (first order there)
            out[i, 0] = out[i, 3] = rho[i]
            out[i, 1] = out[i, 4] = u[i]
            out[i, 2] = out[i, 5] = p[i]
    return out


@njit(cache=True)
def gas_step(m, q, e, x, gamma, R, breech, p0, rho0, v_piston, band_start, open_width, ambient, jets, at_face, dt):
    """One step of the column: the cells' mass ``m``, momentum ``q`` and energy ``e`` per unit bore area advanced
    in place on the faces ``x`` (the breech, still, at ``x[0]``; the piston's face at ``x[-1]`` moving at
    ``v_piston``); ``breech`` ``WALL`` or ``RESERVOIR`` (at p0, rho0); the bleed: holes open from ``band_start``
    to the face, ``open_width`` [m] of effective hole area per metre of the column per unit bore area (the
    wall's open share times the perimeter times the discharge coefficient over the bore's area), to ``ambient``,
    its jets ``RADIAL`` or ``AXIAL``; ``at_face``: the whole open area in the last cell instead (the ported
    law's picture, the ports' flux at the face: the comparison that isolates the bleed's spread). Returns (the
    face's pressure, the breech's, the bleed's mass rate per unit bore area)."""
    N = len(m)
    L = x[-1] - x[0]
    rho, u, p = _primitives(m, q, e, x, gamma)
    faces = _hancock(rho, u, p, x, v_piston, dt, gamma)
    f_m, f_q, f_e = np.zeros(N + 1), np.zeros(N + 1), np.zeros(N + 1)
    if breech == RESERVOIR:
        rb, ub, pb = _reservoir_inflow(rho[0], u[0], p[0], p0, rho0, gamma)
        f_m[0] = rb * ub
        f_q[0] = rb * ub * ub + pb
        f_e[0] = ub * (pb * gamma / (gamma - 1.0) + 0.5 * rb * ub * ub)
        p_breech = pb
    else:
        _, f_q[0], _, p_breech = _moving_flux(rho[0], -u[0], p[0], rho[0], u[0], p[0], 0.0, gamma)
    for i in range(1, N):
        w = (x[i] - x[0]) / L * v_piston
        f_m[i], f_q[i], f_e[i], _ = _moving_flux(faces[i - 1, 3], faces[i - 1, 4], faces[i - 1, 5],
                                                 faces[i, 0], faces[i, 1], faces[i, 2], w, gamma)
    # the piston's face: the wall's mirror state, HLLC's contact at its speed
    r, v, pp = faces[N - 1, 3], faces[N - 1, 4], faces[N - 1, 5]
    _, _, _, p_face = _moving_flux(r, v, pp, r, 2.0 * v_piston - v, pp, v_piston, gamma)
    f_q[N] = p_face
    f_e[N] = p_face * v_piston
    bled = 0.0
    for i in range(N):
        m[i] -= dt * (f_m[i + 1] - f_m[i])
        q[i] -= dt * (f_q[i + 1] - f_q[i])
        e[i] -= dt * (f_e[i + 1] - f_e[i])
        if at_face:
            open_length = max(x[N] - band_start, 0.0) if i == N - 1 else 0.0
        else:
            open_length = max(x[i + 1] - max(x[i], band_start), 0.0)
        if open_length > 0.0 and open_width > 0.0:
            T = p[i] / (rho[i] * R)
            mdot = orifice_mass_flow(gamma, R, open_width * open_length, p[i], T, ambient)
            bled += mdot
            m[i] -= dt * mdot
            if jets == AXIAL:
                q[i] -= dt * mdot * u[i]
            e[i] -= dt * mdot * (gamma / (gamma - 1.0) * p[i] / rho[i] + 0.5 * u[i] * u[i])
    x0, xN = x[0], x[N] + dt * v_piston
    for i in range(N + 1):
        x[i] = x0 + (x[i] - x0) / L * (xN - x0)
    return p_face, p_breech, bled


@njit(cache=True)
def stable_step(m, q, e, x, gamma, v_piston):
    """``COURANT`` times the smallest cell's crossing time by its fastest signal, |u - w| + |v_piston| + c."""
    rho, u, p = _primitives(m, q, e, x, gamma)
    dt = np.inf
    for i in range(len(m)):
        c = math.sqrt(gamma * p[i] / rho[i])
        dt = min(dt, COURANT * (x[i + 1] - x[i]) / (abs(u[i]) + 2.0 * abs(v_piston) + c))
    return dt


class GasColumn:
    """A gas column of ``cells`` finite volumes from a still breech at 0 to the piston's face at ``length`` [m],
    a perfect gas of ``gamma`` and ``R`` [J/(kg K)] uniform at ``pressure`` [Pa], ``temperature`` [K] and
    ``velocity`` [m/s] (or ``profile``: a function of the cells' centres giving (p, T, u) arrays); the breech a
    wall, or a reservoir at rest at ``reservoir`` = (p0 [Pa], T0 [K]).  ``step`` advances it with the piston's
    speed and the bleed; per unit bore area throughout (the bore is constant)."""

    def __init__(self, gamma: float, R: float, length: float, cells: int, pressure: float = 0.0,
                 temperature: float = 0.0, velocity: float = 0.0, reservoir: tuple[float, float] | None = None,
                 profile=None):
        self.gamma, self.R = gamma, R
        self.x = np.linspace(0.0, length, cells + 1)
        mid = 0.5 * (self.x[1:] + self.x[:-1])
        if profile is None:
            p, T, u = (np.full(cells, v, dtype=float) for v in (pressure, temperature, velocity))
        else:
            p, T, u = (np.asarray(a, dtype=float) for a in profile(mid))
        rho = p / (R * T)
        dx = np.diff(self.x)
        self.m = rho * dx
        self.q = self.m * u
        self.e = (p / (gamma - 1) + 0.5 * rho * u * u) * dx
        self.breech = WALL if reservoir is None else RESERVOIR
        self.p0, self.rho0 = (0.0, 0.0) if reservoir is None else (reservoir[0], reservoir[0] / (R * reservoir[1]))
        self.face_pressure = self.breech_pressure = float(p[-1])
        self.bleed_rate = 0.0

    @property
    def face(self) -> float:
        """The piston's face [m]."""
        return float(self.x[-1])

    def stable_step(self, v_piston: float) -> float:
        return stable_step(self.m, self.q, self.e, self.x, self.gamma, v_piston)

    def step(self, v_piston: float, dt: float, band_start: float = math.inf, open_width: float = 0.0,
             ambient: float = 0.0, jets: int = RADIAL, at_face: bool = False) -> float:
        """Advance ``dt`` [s] with the piston at ``v_piston`` [m/s] (held over the step) and the bleed (``gas_step``);
        returns the face's pressure over the step [Pa]."""
        self.face_pressure, self.breech_pressure, self.bleed_rate = gas_step(
            self.m, self.q, self.e, self.x, self.gamma, self.R, self.breech, self.p0, self.rho0, v_piston,
            band_start, open_width, ambient, jets, at_face, dt)
        return self.face_pressure

    def state(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """The cells' centres [m], density [kg/m^3], velocity [m/s] and pressure [Pa]."""
        rho, u, p = _primitives(self.m, self.q, self.e, self.x, self.gamma)
        return 0.5 * (self.x[1:] + self.x[:-1]), rho, u, p

    def mass(self) -> float:
        """Per unit bore area [kg/m^2]."""
        return float(self.m.sum())

    def energy(self) -> float:
        """Per unit bore area [J/m^2]."""
        return float(self.e.sum())

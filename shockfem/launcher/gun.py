"""A single-stage compressed-gas gun as a lumped model (after Seigel, "The theory of high speed
guns", and D. G. Wise's "Universal Air Gun Launcher System").

Reservoir (volume V_r) --valve (Cd A_v, opening linearly over t_open)--> barrel behind the
projectile (dead volume V_d + A x) --> projectile of mass m along a barrel of length L.
State: reservoir gas (m_r, U_r), barrel gas (m_b, U_b), projectile (x, v), and the work done
against friction and against the air ahead.  Adiabatic: the gas exchanges energy only by the
enthalpy it carries through the valve and the work it does on the projectile.

Each loss is a switch, so a user sees what it costs:

* ``valve``: Cd A_v and opening time; ``None`` area: the reservoir *is* the chamber (no valve)
* ``air_ahead``: ``"evacuated"`` or ``"atmosphere"``: the projectile drives a shock into still
  air at (p_a, T_a); the pressure behind a piston-driven shock at piston speed u is
  p = p_a [1 + g(g+1)/4 M^2 + g M sqrt(1 + ((g+1)/4)^2 M^2)], M = u / c_a
* ``bore_friction`` [N], and ``seal_drag`` (a fraction of the base-pressure force)
* ``gas_inertia``: ``"none"`` (the gas is massless: base pressure = barrel pressure),
  ``"lagrange"`` (the gas column's velocity grows linearly from breech to base: the
  projectile moves as if its mass were m + C/3, C the barrel gas mass, and the gas carries
  kinetic energy C v^2 / 6), or ``"simple-wave"`` (an infinitely long chamber of the bore's
  section at the reservoir's initial state: base pressure
  p0 [1 - (g - 1) v / (2 c0)]^(2g/(g-1)), the constant-area gun, whose limit speed is
  2 c0 / (g - 1); not a bound on a gun whose chamber is wider than its bore: ``simple_wave``'s
  infinitely chambered gun is), or ``"chambered"`` (that gun's base pressure: an infinitely large
  chamber at the reservoir's initial state, ``simple_wave.chambered_pressure_ratio``).  Lagrange counts all the gas behind the projectile:
  the barrel's with a valve, the whole chamber's without one, so a chamber much longer than
  the barrel (or of a wider section) makes it too heavy; use a valve there.  With a valve, the valve
  discharges into the column's breech end, whose pressure on Lagrange's profile is the mean's plus
  C a / (6 A) (p(s) = p_breech - rho a s^2 / (2 X) for the speed linear from rest at the breech,
  uniform density rho over the column's length X): the part of the gradient that accelerates the column
  ahead of it, which the valve works against.  Range: the gas column at rest at the breech (the
  inflow's own speed and kinetic energy left out: the jet is taken to mix there) and uniform over the
  barrel, so the tank's gas reaches the base at once, without its waves.  Against the quasi-1D Euler
  column (``column_gun``; ``shockfem verify premise_boundary``: the 12 lb spec's limits gun, the bore's
  valve opened at once, the air ahead): +1.6% in muzzle speed on 220.9 kg, +3.3% on 498.8 kg, the barrel
  gas at the muzzle 3.76 times the striker against the column's 3.76, and 1.97 against 1.84.  Taking the
  mean pressure at the valve instead lets in more gas than the column's inertia allows (3.85 and 2.02 times
  the striker; +3.0% and +4.8% in speed), and passes the infinitely chambered gun by 3.7e-4 with the
  machine's 2 ms valve on 220.9 kg, where the breech's pressure keeps it 0.73% below.  The opening's
  transient (the tank's gas running up the dead volume and stagnating on the projectile above the tank's
  pressure: 36 to 41 MPa from 34.5 MPa on the column) is
  outside it.

Energy balance (lumped model): gas internal energy (+ C v^2 / 6 with Lagrange) + projectile
kinetic energy + friction work + work on the air ahead = the gas's initial internal energy.
"""
from __future__ import annotations

import math
import time
from dataclasses import asdict, dataclass, field
from typing import NamedTuple

import numpy as np
from scipy.integrate import LSODA, OdeSolution
from scipy.optimize import brentq

from ..units import FT, IN, PSI
from .gas import GASES, Gas, orifice_flow
from .simple_wave import base_pressure_ratio, chambered_pressure_ratio

GAS_INERTIA = ("none", "lagrange", "simple-wave", "chambered")
# LSODA: explicit (Adams) while the shot is non-stiff, implicit (BDF) where it turns stiff, which
# is when a small reservoir equalises with a large barrel through a big valve: the linearised
# orifice flow there has a time constant of microseconds, and DOP853 took 9.4 s (LSODA 0.13 s)
# on such a gun; on the white paper's gun the two agree to 2e-10.  Radau is not used: its stages
# probe both sides of the friction's stick at rest, and with friction it settled 6e-5 away.
METHOD = LSODA
AIR_AHEAD = ("evacuated", "atmosphere")
# a projectile that has moved is at rest once its speed is below this fraction of the speed the
# whole gas energy would give it
STOP = 1e-9
# integration pieces: the valve's opening, then restarts of a projectile that stopped and was
# pushed again by a barrel still filling
MAX_PIECES = 20
# an event's root to this many machine epsilons of its time (``scipy.integrate.solve_ivp``'s)
EPS = np.finfo(float).eps


@dataclass(frozen=True)
class Gun:
    reservoir_volume: float          # [m^3]
    reservoir_pressure: float        # [Pa]
    bore: float                      # diameter [m]
    length: float                    # barrel length travelled by the projectile [m]
    projectile_mass: float           # [kg]
    reservoir_temperature: float = 293.15   # [K]
    gas: str = "air"
    real_gas: bool = False           # Noble-Abel covolume
    valve_area: float | None = None  # [m^2]; None: no valve (the reservoir opens on the bore)
    discharge_coefficient: float = 0.8
    opening_time: float = 0.0        # [s]
    dead_volume: float | None = None  # barrel volume behind the projectile at rest [m^3]; None: one
                                      # calibre of bore (with a valve), none (without)
    air_ahead: str = "atmosphere"
    ambient_pressure: float = 101325.0
    ambient_temperature: float = 293.15
    bore_friction: float = 0.0       # [N]
    seal_drag: float = 0.0           # fraction of the base-pressure force [-]
    gas_inertia: str = "lagrange"

    @property
    def area(self) -> float:
        return math.pi * self.bore ** 2 / 4

    def gas_model(self) -> Gas:
        g = GASES[self.gas]
        return g.real() if self.real_gas else g


def white_paper_gun(mass: float, gas: str = "air") -> "Gun":
    """The white paper's gun (12 in bore, 6 ft barrel, 20 ft^3 at 2000 psi, an 8 in valve opening in
    2 ms), as ``studies/launcher/white_paper_gun.toml`` describes it, firing ``mass`` [kg]: the start the
    launcher design moves from."""
    return Gun(reservoir_volume=20 * FT ** 3, reservoir_pressure=2000 * PSI, bore=12 * IN, length=6 * FT,
               projectile_mass=mass, valve_area=math.pi * (8 * IN) ** 2 / 4, opening_time=2e-3, gas=gas)


@dataclass
class Shot:
    gun: Gun
    muzzle_velocity: float           # [m/s] (at x = L, or the last speed if it stopped)
    left_barrel: bool
    time_in_barrel: float            # [s]
    peak_acceleration: float         # [m/s^2]
    peak_base_pressure: float        # [Pa]
    efficiency: float                # projectile kinetic energy / initial gas internal energy
    energy_balance_error: float      # relative to the initial gas energy
    history: dict = field(repr=False, default_factory=dict)
    model: str = ""
    wall_time_s: float = 0.0
    note: str = ""
    travel: float = 0.0              # distance moved in the barrel [m]
    # where the gas's initial internal energy went [J]: "initial", "gas_left" (its internal energy at the
    # end), "gas_kinetic" (the Lagrange column's), "projectile", "friction", "air_ahead"
    energies: dict = field(default_factory=dict)

    def summary(self) -> dict:
        d = {k: v for k, v in asdict(self).items() if k not in ("history", "gun")}
        d["gun"] = asdict(self.gun)
        return d


def describe(gun: Gun) -> str:
    parts = [f"{gun.gas_model().name}{' (ideal)' if not gun.real_gas else ''}, adiabatic"]
    parts.append("no valve (reservoir open on the bore)" if gun.valve_area is None else
                 f"valve Cd A = {gun.discharge_coefficient:g} x {gun.valve_area:.4g} m^2 opening in "
                 f"{gun.opening_time:.3g} s")
    parts.append({"none": "massless gas", "lagrange": "Lagrange gas inertia",
                  "simple-wave": "simple-wave base pressure (infinite chamber)",
                  "chambered": "infinitely chambered base pressure"}[gun.gas_inertia])
    parts.append("evacuated barrel" if gun.air_ahead == "evacuated" else "shock in the air ahead")
    if gun.bore_friction or gun.seal_drag:
        parts.append(f"bore friction {gun.bore_friction:g} N, seal drag {gun.seal_drag:g} of the base force")
    return "; ".join(parts)


class _Piece(NamedTuple):
    """A piece of the shot's integration: what ``fire`` reads of solve_ivp's result."""
    t: np.ndarray
    y: np.ndarray
    t_events: list
    sol: OdeSolution
    success: bool


def _integrate(rhs, t0: float, t_bound: float, y0, rtol: float, atol, events, directions):
    """``scipy.integrate.solve_ivp``'s loop with LSODA, dense output and terminal events, which it is step for
    step: the same solver, steps and interpolants, each event's root by brentq on its step's interpolant to
    4 eps (solve_ivp's ``solve_event_equation``), the earliest ending the piece.  What differs is how the
    events' signs are tested: as numbers, where solve_ivp's numpy tests of three events at every step were a
    sixth of a shot's time (the premise map's guns, profiled).  ``events``: functions of the state that end
    the integration where they cross zero in their ``directions`` (+1 rising, -1 falling).  Returns the
    fields of solve_ivp's result that ``fire`` reads (t, y, t_events, sol, success)."""
    solver = METHOD(rhs, t0, y0, t_bound, rtol=rtol, atol=atol)
    ts, ys, interpolants = [t0], [y0], []
    t_events = [[] for _ in events]
    g = [event(y0) for event in events]
    status = None
    while status is None:
        solver.step()
        if solver.status == "failed":
            status = -1
            break
        status = 0 if solver.status == "finished" else None
        t_old, t, y = solver.t_old, solver.t, solver.y
        sol = solver.dense_output()
        interpolants.append(sol)
        g_new = [event(y) for event in events]
        crossed = [k for k, d in enumerate(directions)
                   if (d > 0 and g[k] <= 0 <= g_new[k]) or (d < 0 and g[k] >= 0 >= g_new[k])]
        if crossed:
            roots = sorted((brentq(lambda s, e=events[k]: e(sol(s)), t_old, t, xtol=4 * EPS, rtol=4 * EPS), k)
                           for k in crossed)
            root, k = roots[0]          # every event is terminal: the first ends the piece
            t_events[k].append(root)
            status, t, y = 1, root, sol(root)
        g = g_new
        ts.append(t)
        ys.append(y)
    return _Piece(np.array(ts), np.vstack(ys).T, [np.asarray(te) for te in t_events],
                  OdeSolution(ts, interpolants), status is not None and status >= 0)


class _joined:
    """The pieces of an integration split at known kinks, seen as one solution."""

    def __init__(self, pieces):
        self.pieces = pieces
        self.t = np.concatenate([p.t for p in pieces])
        self.y = np.concatenate([p.y for p in pieces], axis=1)
        self.t_events = [np.concatenate([p.t_events[k] for p in pieces]) for k in range(3)]

    def sol(self, ts):
        out = np.empty((self.y.shape[0], len(ts)))
        for k, t in enumerate(ts):
            piece = next((p for p in self.pieces if t <= p.t[-1]), self.pieces[-1])
            out[:, k] = piece.sol(t)
        return out


def air_ahead_pressure(gun: Gun, v: float) -> float:
    """Pressure on the projectile's face from the air it drives ahead [Pa]."""
    return _face_pressure(gun)(v)


AIR_GAMMA, AIR_R = 1.4, 287.05


def _face_pressure(gun: Gun):
    """The face pressure of ``gun``'s air ahead as a function of the projectile's speed [m/s -> Pa], its
    constants worked out once (the shot's integrator asks for it at every evaluation)."""
    if gun.air_ahead == "evacuated":
        return lambda v: 0.0
    g, p_a = AIR_GAMMA, gun.ambient_pressure
    c = math.sqrt(g * AIR_R * gun.ambient_temperature)
    square, root = g * (g + 1) / 4, ((g + 1) / 4) ** 2

    def pressure(v: float) -> float:
        M = max(v, 0.0) / c          # at rest the face sees the ambient pressure
        return p_a * (1 + square * M * M + g * M * math.sqrt(1 + root * M * M))
    return pressure


# an opening time below this share of the longest shot is an instant (double precision resolves times to
# 2.2e-16 of t; the integrator's steps need far more)
INSTANT_OPENING = 1e-9


def fire(gun: Gun, rtol: float = 1e-9, samples: int = 400, max_time: float = 10.0,
         stop_speed: float | None = None) -> Shot:
    """Integrate the shot from the valve opening until the projectile leaves the barrel (or
    stops, or reaches ``stop_speed``: then ``Shot.travel`` is the barrel length that speed needs)."""
    t0 = time.perf_counter()
    gas = gun.gas_model()
    A = gun.area
    Vr, pr0, Tr0 = gun.reservoir_volume, gun.reservoir_pressure, gun.reservoir_temperature
    no_valve = gun.valve_area is None
    # with no valve the reservoir and the barrel are one volume
    dead = gun.dead_volume if gun.dead_volume is not None else (0.0 if no_valve else A * gun.bore)
    V_d = dead + (Vr if no_valve else 0.0)
    m_r0 = 0.0 if no_valve else gas.mass_for(pr0, Tr0, Vr)
    if no_valve:
        m_b0 = gas.mass_for(pr0, Tr0, V_d)
        T_b0 = Tr0
    else:
        m_b0 = gas.mass_for(gun.ambient_pressure, gun.ambient_temperature, V_d) if V_d > 0 else 0.0
        T_b0 = gun.ambient_temperature
    U_r0, U_b0 = m_r0 * gas.cv * Tr0, m_b0 * gas.cv * T_b0
    E0 = U_r0 + U_b0
    c0 = gas.sound_speed(pr0, Tr0)
    # a valve that opens faster than the integrator can resolve on the shot's time scale opens at once: its
    # opening, a piece of its own, would leave the integrator a step with t + h = t, and no way out
    t_open = gun.opening_time if gun.opening_time > INSTANT_OPENING * max_time else 0.0
    # the ideal guns' base-pressure laws of the chamber's initial state (``simple_wave``)
    simple = gun.gas_inertia in ("simple-wave", "chambered")
    law = chambered_pressure_ratio if gun.gas_inertia == "chambered" else base_pressure_ratio
    lagrange = gun.gas_inertia == "lagrange"

    # the gun's numbers read once: the integrator calls ``state`` about a thousand times a shot
    m_p, L, mu, seal = gun.projectile_mass, gun.length, gun.bore_friction, gun.seal_drag
    valved = not no_valve and not simple
    a_valve = gun.discharge_coefficient * gun.valve_area if valved else 0.0
    gamma, cp = gas.gamma, gas.cp
    face = _face_pressure(gun)

    def state(y, t):
        """(p_r, p_b, p_base, p_face, mdot, h, acc, friction, p_mean) at ``y``, ``t``: the pressures of the
        reservoir, the barrel, on the base and on the face [Pa], the valve's mass flow [kg/s] and the enthalpy it
        carries [J/kg], the projectile's acceleration [m/s^2], the friction on it [N] and the gas's mean
        pressure [Pa]."""
        m_r, U_r, m_b, U_b, x, v = y[0], y[1], y[2], y[3], y[4], y[5]
        V_b = V_d + A * max(x, 0.0)
        p_r = gas.pressure(m_r, U_r, Vr) if m_r > 0 else 0.0
        p_b = gas.pressure(m_b, U_b, V_b) if m_b > 0 else 0.0
        if simple:
            p_base = pr0 * law(v, c0, gamma)
            p_mean, m_eff = p_base, m_p
        elif lagrange:
            m_eff = m_p + m_b / 3
            p_mean = p_b
            p_base = None
        else:
            p_mean, p_base, m_eff = p_b, p_b, m_p
        p_face = face(v)
        # the resisting force; friction acts only while moving (or when the drive could overcome it)
        drive = p_mean * A - p_face * A
        friction = mu + seal * p_mean * A
        if v <= 0 and drive <= friction:
            acc, friction_now = 0.0, 0.0
        else:
            friction_now = friction
            acc = (drive - friction_now) / m_eff
        if lagrange:
            p_base = (m_p * acc + p_face * A + friction_now) / A
        mdot, h, p_breech = 0.0, 0.0, p_b
        if valved:
            # the valve discharges into the column's breech end: on Lagrange's profile (uniform density, the
            # speed linear from rest at the breech) the pressure there is the mean's plus C a / (6 A), the part of
            # the gradient that accelerates the column ahead of it
            if lagrange:
                p_breech = p_b + m_b * acc / (6 * A)
            opening = 1.0 if t_open <= 0 else min(t / t_open, 1.0)
            if p_r >= p_breech:
                T_up = gas.temperature(m_r, U_r)
                mdot = orifice_flow(gas, a_valve * opening, p_r, T_up, p_breech)
            else:
                T_up = gas.temperature(m_b, U_b)
                mdot = -orifice_flow(gas, a_valve * opening, p_breech, T_up, p_r)
            h = cp * T_up
        return p_r, p_b, p_base, p_face, mdot, h, acc, friction_now, p_mean

    def rhs(t, y):
        _, _, _, p_face, mdot, h, acc, friction, p_mean = state(y, t)
        v = y[5]
        dU_b = h * mdot - (0.0 if simple else p_mean * A * v)
        if lagrange:
            dU_b -= mdot * v * v / 6        # the gas let in is brought up to the column's motion
        moving = max(v, 0.0)
        return [-mdot, -h * mdot, mdot, dU_b, v, acc, friction * moving, p_face * A * moving,
                (p_mean * A * v if simple else 0.0)]

    # the events, each a function of the state and whether it ends the shot (all do) when it crosses
    # zero rising (+1) or falling (-1): the muzzle; a stall (after it has moved, a projectile whose
    # speed falls to (a hair above) zero has come to rest; before it moves it may wait at rest for
    # the pressure to build; the threshold is above zero because at rest the resisting force stops
    # acting: the speed never goes below zero for an event there to see); ``stop_speed`` reached
    reach = stop_speed or math.inf
    events = (lambda y: y[4] - L, lambda y: y[5] - STOP * v_scale if y[4] > 1e-6 * L else 1.0,
              lambda y: y[5] - reach)
    directions = (1, -1, 1)

    y0 = np.array([m_r0, U_r0, m_b0, U_b0, 0.0, 0.0, 0.0, 0.0, 0.0])
    # absolute tolerances on the scale of each state: masses, energies, length, speed, works
    mass_scale = max(m_r0 + m_b0, 1e-9)
    v_scale = math.sqrt(2 * max(E0, 1.0) / gun.projectile_mass)
    atol = np.array([mass_scale, E0, mass_scale, E0, gun.length, v_scale, E0, E0, E0]) * rtol * 1e-3
    # the valve's opening ends with a kink in the flow area: integrate up to it, then on; a
    # projectile that stops while the reservoir still feeds the barrel starts again from rest
    pieces = []
    t_start, y_start = 0.0, y0
    stops = ([t_open] if (not no_valve and 0 < t_open < max_time) else []) + [max_time]
    for _ in range(MAX_PIECES):
        t_stop = next(t for t in stops if t > t_start)
        piece = _integrate(rhs, t_start, t_stop, y_start, rtol, atol, events, directions)
        pieces.append(piece)
        t_start, y_start = piece.t[-1], piece.y[:, -1].copy()
        if not piece.success or len(piece.t_events[0]) or len(piece.t_events[2]) or t_start >= max_time:
            break
        if len(piece.t_events[1]):
            p_r, p_b = state(y_start, t_start)[:2]
            if not p_r > p_b * (1 + 1e-3):
                break                 # nothing will push it again: it stays where it stopped
            y_start[5] = 0.0
    sol = _joined(pieces)
    t_end = sol.t[-1]
    left = bool(len(sol.t_events[0]))
    ts = np.linspace(0.0, t_end, samples)
    ys = sol.sol(ts)
    # the gas states too (mass [kg], internal energy [J] of the reservoir and the barrel): where a caller
    # continues the shot past the travel (``machine.launcher.ported_push``)
    hist = {"time": ts, "x": ys[4], "v": ys[5], "p_reservoir": [], "p_barrel": [], "p_base": [], "acceleration": [],
            "m_reservoir": ys[0], "U_reservoir": ys[1], "m_barrel": ys[2], "U_barrel": ys[3]}
    for k, t in enumerate(ts):
        p_r, p_b, p_base, _, _, _, acc, _, _ = state(ys[:, k], t)
        hist["p_reservoir"].append(p_r)
        hist["p_barrel"].append(p_b)
        hist["p_base"].append(p_base)
        hist["acceleration"].append(acc)
    for k in ("p_reservoir", "p_barrel", "p_base", "acceleration"):
        hist[k] = np.array(hist[k])
    y_end = sol.y[:, -1]
    m_r, U_r, m_b, U_b, x, v, W_f, W_air, W_sw = y_end
    kinetic = 0.5 * gun.projectile_mass * v * v
    gas_ke = m_b * v * v / 6 if lagrange else 0.0
    if simple:
        # the infinite chamber's gas gives the projectile its work; energy: work = KE + losses
        balance = (W_sw - kinetic - W_f - W_air) / max(W_sw, 1e-300)
        efficiency = kinetic / max(W_sw, 1e-300)
    else:
        balance = (U_r + U_b + gas_ke + kinetic + W_f + W_air - E0) / E0
        efficiency = kinetic / E0
    reached_speed = bool(len(sol.t_events[2]))
    note = "" if left or reached_speed else (f"the projectile is still in the barrel at x = {x:.4g} m after {t_end:.4g} s"
                            if t_end >= max_time else f"the projectile stopped in the barrel at x = {x:.4g} m")
    energies = {"initial": float(W_sw if simple else E0), "gas_left": float(0.0 if simple else U_r + U_b),
                "gas_kinetic": float(gas_ke), "projectile": float(kinetic), "friction": float(W_f),
                "air_ahead": float(W_air)}
    return Shot(gun, float(v), left, float(t_end), float(np.max(np.abs(hist["acceleration"]))),
                float(np.max(hist["p_base"])), float(efficiency), float(abs(balance)), hist, describe(gun),
                time.perf_counter() - t0, note, float(x), energies)


def barrel_length_for(gun: Gun, speed: float, longest: float = 1e4) -> float:
    """The barrel length [m] at which ``gun`` brings its projectile to ``speed``; inf if no barrel
    up to ``longest`` does (the gas is spent, or friction and the air ahead hold it)."""
    import dataclasses
    shot = fire(dataclasses.replace(gun, length=longest), samples=2, stop_speed=speed)
    return shot.travel if shot.muzzle_velocity >= speed * (1 - 1e-9) else math.inf

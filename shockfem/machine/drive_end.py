"""The end of the gas drive's thrust (arrangement (d), ``machine.gas_drive``): vent ports in the cylinder's wall
that the piston uncovers at the end of its stroke, and an arrest that stops the piston while the carriage and the
article run on.

Why this end.  Three ways to end a HYGE-type drive's thrust were weighed:

* a fast-closing supply valve alone does not end it: the cylinder's own charge (the swept volume at the base
  pressure) keeps pushing, falling only as (x / x_c)^-gamma, a half in helium after half the stroke again (about
  a millisecond at 441 m/s), and a full-bore valve closing faster than it opens is no more sourced than the
  opening;
* a fixed charge (no tank on the cylinder during the shot) does not end it either: the charge keeps pushing as
  it expands; it only bounds the gas a shot vents, and it holds the plateau within the band's +/- 20% only at
  (0.8 / 1.2)^(-1 / gamma) - 1 = 0.275 of its volume swept (3.6 swept volumes in helium), the band's whole width
  spent on the charge's fall (the 5% hold this design keeps needs 32);
* vent ports give the gas behind the piston a way out where the piston is, so the base pressure falls as soon
  as they open, and an arrest ahead of the piston separates the carriage and the article from it, which cuts
  what is left of the thrust on the article at once (a step).  This is the end built here.  Vent ports that the
  accelerated piston passes, a high-speed valve and braking devices for the parts that run on are the
  arrangement of an impact test facility patented by V. D. Stepanov (RU 2006807 C1); the HYGE actuator's own end
  is its lower chamber's gas and programmers (C. Lalanne, Mechanical Vibration and Shock, vol. II, ch. 6),
  which decelerate the table with the article on it rather than let it fly.

The fall.  The ports' holes (a share of the wall open, ``PORT_SHARES``, round holes on a square pitch) start where the
piston's back is at the stroke x_p; as it travels on, the uncovered area grows as A_v(x) = share pi D (x - x_p).
The fall lasts a few tenths of a millisecond, less than the column's echo from the valve (2 x_p / c0: checked),
so the ports' opening is an unsteady event in the gas column, not a new steady state: the ports at the
piston's face take a volume flux Q = mdot / rho_b out of it, so the gas at the face moves at u + Q / A, and a
rarefaction runs up the column, across which the Riemann invariant u + 2 c / (gamma - 1) of the column's own
flow (u, c_s: the chambered column at the piston's speed, c_s = c0 pi(u)^((gamma - 1) / (2 gamma))) holds.  The
face's pressure is therefore the simple-wave gun's law with the ports' flux as the face's extra speed,

    p_b = p0 pi(u) (1 - (gamma - 1) / 2 Q(p_b) / (A c_s))^(2 gamma / (gamma - 1)),
    Q = mdot(A_v, p_b, T_b) / rho_b,   T_b = T0 (p_b / p0)^((gamma - 1) / gamma),

pi the chambered law (``simple_wave.chambered_pressure_ratio``) and the bracket ``simple_wave.
base_pressure_ratio``, mdot the one orifice law (``launcher.gas.orifice_flow``, the gas at the face its upstream
state, venting to the test cell), solved for p_b at each instant (``ported_pressure_ratio``).  With the ports
choked, Q / A = Gamma alpha c_b (alpha = A_v / A, Gamma the choked flow factor, c_b = c_s w), so w = 1 - (gamma
- 1) / 2 Gamma alpha w and the law has a closed form, p_b = p0 pi(u) (1 + (gamma - 1) / 2 Gamma alpha)^(-2 gamma
/ (gamma - 1)) (``ported_ratio_closed_form``, the verification's).  The moving mass then follows u' = k p_b / p0
(k = p0 A / m) until the piston's front meets the arrest at x_a (``ported_fall``): the arrest's force rises
within its own impact time, far shorter than the fall, so the carriage and the article leave the piston there and
run free (their acceleration zero), whatever of the thrust is left.

The face's bracket.  Take the gas from a section upstream of the ports (state 1, the law above) to the piston's
face, its profile moving with the piston: its momentum balance gives p_face = p_1 + rho_1 Q (u + Q - v_ax), v_ax
the lab-frame axial speed at which the port gas leaves.  Jets that keep the column's speed (v_ax = u + Q) give
p_1, the bracket's lower end; jets that leave radially (v_ax = 0, the case in which the cylinder takes no axial
thrust from them) give p_1 (1 + gamma M_Q M_in), M_Q = Q / (A c_1), M_in = (u + Q / A) / c_1, its upper end
(``ported_pressure_ratio``'s ``recovery``).  The holes' discharge coefficient (``DISCHARGE_RANGE``: its sources
in the comment) multiplies their area: the most flow (1) with the lower end, the least with the upper
(``bracket``); the design asks the band of both ends.  The column feeding the ports must stay subsonic, M_in < 1
(``inflow_mach``): past it the bore chokes ahead of the ports and this law does not hold.

The face's bracket checked.  ``column_fall`` fires the same fall on the quasi-1-D column: the ports spread over the
band, the oldest a band's length behind the face, the column's own inertia answering the piston's acceleration
(where the law keeps the chambered pi(u)), the jets' axial momentum all or none of the local gas's.  For the 12 lb
helium design (``shockfem verify gas_column_design``, 400 cells) the column gives 0.569 to 0.706 p0 at the
separation over the four cases, inside the law's 0.489 to 0.749: the law's bracket is the wider on both ends.
Spreading the ports over the band, against all their area in the last cell (the law's picture, ``at_face``), moves
the column's face pressure at the separation by -0.044 to +0.024 p0: it lowers the radial cases (-0.016 at the upper
end's Cd 0.6) and raises the axial (+0.011 at the lower end's Cd 1); without ports the column ends 0.033 p0 below
the chambered law (0.809 against 0.841): the column's inertia.  With radial jets from ideal holes the column's flow
through the band reaches Mach 1.03: past the law's ``INFLOW_RANGE``, not the column's.

After it.  The piston runs into its arrest with the gas still pushing: up to p0 A (the column brought to rest
by a simple compression keeps u + 2 c / (gamma - 1) = 2 c0 / (gamma - 1), so it stops at c0 and p0), so the
arrest must take the piston's energy and the push's work over its stroke, and hold the push at rest
(``machine.stops``: a pushed body).  Then the tank blows down through the open valve and the ports: the
cylinder's pressure settles where the valve's inflow equals the ports' outflow, both at the tank's stagnation
temperature (adiabatic mixing, ``steady_pressure``; the valve subsonic there unless the ports exceed about 2
valve areas).  The gas approaches the ports at the column's speed u_col = mdot / (rho A): jets that keep it
thrust the cylinder by mdot u_col (``jet_thrust``, their most; radial jets, none).  The gas a shot vents is the
cylinder's and whatever the valve passes before it closes (``vent_history``: the tank and the cylinder two
control volumes, the tank's gas isentropic, the cylinder's mixing, the valve's area falling linearly over its
closing time from the separation; the cylinder to the piston at rest on its arrest); with the valve left open
it is the whole tank.

The ports' band (``port_band``): round holes of the band's wall thickness on a square pitch p, the open share
pi d^2 / (4 p^2); the ligament efficiency E = (p - d) / p (ASME VIII-1 UG-53, the longitudinal ligament) sets
the band's wall so that Lame's inner-wall hoop stress at p0 across the ligaments, p0 (Y^2 + 1) / ((Y^2 - 1) E)
(Y the band's outer over inner radius), and the arrest's force crossing the same ligaments axially,
F / (E pi D_m t), are within the allowable.  The piston on its arrest: its front annulus, from the carriage's
passage (radius r_i) to the bore, bears on the arrest, a uniform load q = F / A over its face (the push reaches
the arrest only through it: F is the whole force between them); the annulus bears (F over its area at most S)
and the central disc inside it bends as a simply supported disc of radius r_i under q, sigma = 3 (3 + nu) q r_i^2
/ (8 h^2) (Roark, 7th ed., Table 11.2 case 10a; an upper bound, the disc being continuous with the supported
annulus), so the arrest's force is at most the lesser of the two (``arrest_force_limit``).  The band's wall is
a forged ring of the specification's steel at its allowable (yield over the safety factor) flanged between the
cylinder's pipes, not the pipe's ASME grade: the ligaments need the strength, and a thinner band keeps the gas's
transit through its holes short.  No fatigue check: every shot is a cycle of both stresses at the holes.

Range (checked on every design, ``range_limits``): a perfect gas; the column into the ports subsonic
(``INFLOW_RANGE``); the ports quasi-steady (the gas crosses the band's wall, t / c_b, within ``PORT_WALL_RANGE``
of the fall); the band's wave transit l_p / c_b within ``PORT_SPREAD_RANGE`` of the fall (the band is the fall's
travel, so this is about the piston's Mach number at the face, u / c_b, whatever the share; 0.5 has no source:
it is the range the next check was run in, the 12 lb design at 0.488); the law's bracket holding the
quasi-1-D gas column's face pressure at the separation (``column_bracket``: ``fluid.gas_column`` from the valve,
a reservoir at p0, T0, to the piston's face, the column started at the ports' opening at the chambered state the
law takes, the ports a bleed over the uncovered band, each cell's holes through the orifice law at its own state,
their flux reaching the face as the column carries it, the holes' discharge coefficient at both ends of
``DISCHARGE_RANGE`` with radial and with axial jets, at ``COLUMN_CELLS``: the column's highest at most the
bracket's upper end, its lowest at least the lower end); the fall
the simple wave's (the column's echo from the valve, 2 x_p / c0, no sooner than the fall's end); the arrest's
force rising to the thrust left within a time short against the fall (stated, not checked: the absorber's
impact time).  Left out: the compression the decelerating piston sends back into the gas (about rho c du, on
top of the push, bounded by p0 A above), the air ahead of the piston in the arrest's bore (bounded in
``machine.gas_drive``), the separation's step on the article's own modes, the plenum that must contain the
ports' jets (one blocked hole is a jet's side load), the piston's seals crossing the ports' edges.
"""
from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from ..fluid import gas_column as G
from ..launcher.gas import Gas, orifice_flow
from ..launcher.simple_wave import base_pressure_ratio, chambered_pressure_ratio
from . import blowdown as B
from .limits import Limit

# the band's wall open to the ports, largest first: the design keeps the first that makes it feasible, else the
# first whose end holds its range (``machine.gas_drive``); 0.3 is d / p = 0.62, E = 0.38
PORT_SHARES = (0.3, 0.25, 0.2, 0.15, 0.1)
INFLOW_RANGE = 1.0           # the column's Mach number into the ported band: past 1 it chokes there
PORT_WALL_RANGE = 0.1        # the gas's transit through the band's wall over the fall
PORT_SPREAD_RANGE = 0.5      # the band's wave transit l_p / c_b over the fall
# the quasi-1D column's grid for the bracket's check (``column_bracket``): the 12 lb design's face pressure at the
# separation moves by at most 0.0003 p0 from 200 to 400 cells (``shockfem verify gas_column_design``)
COLUMN_CELLS = 200
RTOL = 1e-10
# The holes' discharge coefficient, the bracket's range.  A sharp-edged round hole as long as it is wide fed from
# still gas discharges about 0.78 of its ideal flow (the jet reattached in the hole: A. Lichtarowicz, R. K.
# Duggins and E. Markland, J. Mech. Eng. Sci. 7 (1965) 210, long orifices; check); gas grazing the wall lowers
# it as the approach Mach number rises (J. E. Rohde, H. T. Richards and G. W. Metger, NASA TN D-5467 (1969),
# thick-plate orifices with the approach flow perpendicular to the orifice axis; the column here reaches 0.85;
# check the figure's value), so the bracket runs from 0.6 to the ideal 1 (1 the most flow: the least thrust).
DISCHARGE_RANGE = (0.6, 1.0)


def area_ratio_rate(share: float, bore: float) -> float:
    """beta = d(A_v / A) / dx [1/m]: the uncovered ports over the bore's area per metre of travel past x_p."""
    return share * math.pi * bore / (math.pi * bore * bore / 4)


def _ported_state(u: float, alpha: float, gas: Gas, p0: float, T0: float, ambient: float):
    """(p / p0, Q / A, c) of the column where the ports are, at ``u`` [m/s] with ports of ``alpha`` times the
    bore's area open (module docstring): the simple wave from the chambered column's state."""
    c0 = gas.sound_speed(p0, T0)
    bare = chambered_pressure_ratio(u, c0, gas.gamma)
    c_s = c0 * bare ** ((gas.gamma - 1) / (2 * gas.gamma))
    if alpha <= 0 or bare * p0 <= ambient:
        return bare, 0.0, c_s

    def flux(r):
        p, T = r * p0, T0 * r ** ((gas.gamma - 1) / gas.gamma)
        return orifice_flow(gas, alpha, p, T, ambient) / (p / (gas.R * T))   # Q / A: alpha stands for A_v / A
    # at r = pi(u) the ports' flux lowers the pressure below it; at the ambient they take none
    r = float(brentq(lambda r: bare * base_pressure_ratio(flux(r), c_s, gas.gamma) - r, ambient / p0, bare,
                     xtol=1e-14, rtol=1e-13))
    return r, flux(r), c_s * (r / bare) ** ((gas.gamma - 1) / (2 * gas.gamma))


def ported_pressure_ratio(u: float, alpha: float, gas: Gas, p0: float, T0: float, ambient: float,
                          recovery: bool = False) -> float:
    """p_b / p0 at the piston's face at ``u`` [m/s] with ports of ``alpha`` times the bore's area open behind it
    (module docstring; ``alpha`` the ports' effective area, the discharge coefficient in it); ``recovery``: the
    face pressure's upper end, the port gas leaving with no axial speed, p_1 (1 + gamma M_Q M_in)."""
    r, q, c = _ported_state(u, alpha, gas, p0, T0, ambient)
    if not recovery:
        return r
    return r * (1 + gas.gamma * (q / c) * (u + q) / c)


def inflow_mach(u: float, alpha: float, gas: Gas, p0: float, T0: float, ambient: float) -> float:
    """M_in = (u + Q / A) / c: the column's Mach number into the ported band (module docstring)."""
    r, q, c = _ported_state(u, alpha, gas, p0, T0, ambient)
    return (u + q) / c


def ported_ratio_closed_form(u: float, alpha: float, c0: float, gamma: float) -> float:
    """The same with the ports choked (module docstring): pi(u) (1 + (gamma - 1) / 2 Gamma alpha)^(-2 gamma /
    (gamma - 1))."""
    w = 1 / (1 + 0.5 * (gamma - 1) * B.mass_flow_factor(gamma) * alpha)
    return chambered_pressure_ratio(u, c0, gamma) * w ** (2 * gamma / (gamma - 1))


@dataclass
class PortedFall:
    """The thrust's fall from the ports' opening to the separation."""
    time: np.ndarray             # [s]
    acceleration: np.ndarray     # [m/s^2]
    ratio: np.ndarray            # p_b / p0
    end_time: float              # the separation [s]
    end_speed: float             # [m/s]
    end_travel: float            # the piston's back at the separation, x_a [m]
    end_ratio: float             # p_b / p0 just before it
    inflow_mach: float           # the largest M_in over the fall


@dataclass(frozen=True)
class Ports:
    """The ports behind the piston: its gas and chamber state, the wall's open ``share`` and ``beta``
    (``area_ratio_rate``), the holes' discharge coefficient, and which end of the face pressure's bracket
    (``bracket``)."""
    gas: Gas
    p0: float                    # [Pa]
    T0: float                    # [K]
    beta: float                  # [1/m]
    share: float = 0.0
    recovery: bool = False
    ambient: float = B.ATMOSPHERE
    discharge: float = 1.0       # the holes' discharge coefficient (``DISCHARGE_RANGE``)


def bracket(ports: Ports) -> tuple[Ports, Ports]:
    """The face pressure's two ends (module docstring): the least, the holes at the top of ``DISCHARGE_RANGE``
    and the port gas keeping the column's speed; the most, the holes at its bottom and the port gas leaving
    radially (``ported_pressure_ratio``'s ``recovery``)."""
    low, high = DISCHARGE_RANGE
    return (dataclasses.replace(ports, discharge=high, recovery=False),
            dataclasses.replace(ports, discharge=low, recovery=True))


def ported_fall(k: float, ports: Ports, u_p: float, x_p: float, t_p: float, t_end: float | None = None,
                x_end: float | None = None, samples: int = 200) -> PortedFall:
    """u' = k p_b / p0, x' = u from the ports' opening (u_p, x_p at t_p) to the separation, at ``t_end`` [s] or
    where the piston reaches ``x_end`` [m] (module docstring)."""
    gas, p0, T0, ambient = ports.gas, ports.p0, ports.T0, ports.ambient
    beta = ports.beta * ports.discharge          # the ports' effective area's rate

    def ratio(u, x):
        return ported_pressure_ratio(u, beta * max(x - x_p, 0.0), gas, p0, T0, ambient, ports.recovery)

    def rhs(t, y):
        return [k * ratio(*y), y[0]]
    event = None
    if x_end is not None:
        def event(t, y):
            return y[1] - x_end
        event.terminal, event.direction = True, 1
    # long enough to reach x_end at the opening speed, twice over
    span = t_end - t_p if t_end is not None else 2 * (x_end - x_p) / max(u_p, 1e-9)
    sol = solve_ivp(rhs, (t_p, t_p + span), [u_p, x_p], method="DOP853", rtol=RTOL,
                    atol=[RTOL * max(u_p, 1.0), RTOL * max(x_p, 1e-3)], events=event, dense_output=True)
    t1 = float(sol.t[-1])
    t = np.linspace(t_p, t1, samples)
    y = sol.sol(t)
    r = np.array([ratio(u, x) for u, x in y.T])
    mach = max(inflow_mach(u, beta * max(x - x_p, 0.0), gas, p0, T0, ambient) for u, x in y.T)
    return PortedFall(t, k * r, r, t1, float(sol.y[0, -1]), float(sol.y[1, -1]), float(r[-1]), mach)


def column_fall(k: float, ports: Ports, u_p: float, x_p: float, t_p: float, x_end: float, cells: int,
                jets: int = G.RADIAL, at_face: bool = False, samples: int = 200) -> PortedFall:
    """The same fall as ``ported_fall`` on the quasi-1D gas column (``fluid.gas_column``), the independent check
    of the ported law: the column from the valve (a reservoir at p0, T0: the chambered law's infinite chamber) to
    the piston's face at ``x_p`` [m], uniform at the chambered state at ``u_p`` [m/s] (the state the law takes),
    ``cells`` finite volumes; the ports a bleed from ``x_p`` to the face through the holes' effective area
    (``ports.beta`` times its discharge coefficient per metre), ``jets`` ``gas_column.RADIAL`` or ``AXIAL``; the
    piston driven by u' = k p_face / p0 until its back reaches ``x_end`` (the arrest), its speed over a step
    the midpoint's from the last step's acceleration; ``at_face``: the open area all in the last cell (the law's
    picture of the ports, ``gas_column.gas_step``).  ``ratio`` the face's
    p / p0 sampled over the fall, ``inflow_mach`` the column's largest Mach number over it."""
    gas, p0, T0 = ports.gas, ports.p0, ports.T0
    r0 = chambered_pressure_ratio(u_p, gas.sound_speed(p0, T0), gas.gamma)
    col = G.GasColumn(gas.gamma, gas.R, x_p, cells, pressure=r0 * p0,
                      temperature=T0 * r0 ** ((gas.gamma - 1) / gas.gamma), velocity=u_p, reservoir=(p0, T0))
    width = ports.beta * ports.discharge
    t, u, a, times, ratios, mach = t_p, u_p, k * r0, [t_p], [r0], 0.0
    while col.face < x_end * (1 - 1e-12):
        dt = col.stable_step(u)
        v = u + 0.5 * dt * a
        dt = min(dt, (x_end - col.face) / v)
        p = col.step(u + 0.5 * dt * a, dt, x_p, width, ports.ambient, jets, at_face)
        a = k * p / p0
        t, u = t + dt, u + dt * a
        times.append(t)
        ratios.append(p / p0)
        _, rho, v, pc = col.state()
        mach = max(mach, float(np.max(np.abs(v) / np.sqrt(gas.gamma * pc / rho))))
    time = np.linspace(t_p, t, samples)
    r = np.interp(time, times, ratios)
    return PortedFall(time, k * r, r, t, u, col.face, float(ratios[-1]), mach)


def column_bracket(k: float, ports: Ports, u_p: float, x_p: float, t_p: float, x_end: float,
                   cells: int = COLUMN_CELLS) -> dict:
    """The face pressure at the separation (p / p0) by the ported law's two ends (``bracket``) and by the quasi-1D
    column (``column_fall``) at each of the holes' discharge coefficients (``DISCHARGE_RANGE``) with radial and
    axial jets: {"law": (lower, upper), "column": {(Cd, jets): PortedFall}}."""
    ends = tuple(ported_fall(k, b, u_p, x_p, t_p, x_end=x_end, samples=2).end_ratio for b in bracket(ports))
    column = {(cd, jets): column_fall(k, dataclasses.replace(ports, discharge=cd), u_p, x_p, t_p, x_end, cells, jets)
              for cd in DISCHARGE_RANGE for jets in (G.RADIAL, G.AXIAL)}
    return {"law": ends, "column": column}


def steady_pressure(gas: Gas, p0: float, T0: float, valve_area: float, port_area: float, ambient: float) -> float:
    """The cylinder's pressure [Pa] with the valve and the ports open and the piston held: the valve's inflow
    from the tank at (p0, T0) equal to the ports' outflow, the cylinder at T0 (module docstring)."""
    def balance(p):
        return orifice_flow(gas, valve_area, p0, T0, p) - orifice_flow(gas, port_area, p, T0, ambient)
    return float(brentq(balance, ambient, p0, xtol=1e-9 * p0))


def jet_thrust(gas: Gas, pressure: float, T0: float, port_area: float, bore_area: float, ambient: float) -> float:
    """The most axial thrust [N] the ports' jets put on the cylinder with the piston held at ``pressure`` [Pa]
    (module docstring): the column's axial momentum flux mdot u_col into the ports, if the jets keep it."""
    mdot = orifice_flow(gas, port_area, pressure, T0, ambient)
    return mdot * mdot / (pressure / (gas.R * T0) * bore_area)


def reflected_shock_pressure(p2: float, p1: float, gamma: float) -> float:
    """The pressure [Pa] behind a shock of p2 / p1 reflected from a closed end (the air ahead of the piston off
    the arrest's face): p5 / p2 = ((a + 2) p2 / p1 - 1) / (p2 / p1 + a), a = (gamma + 1) / (gamma - 1) (the
    normal reflection of a plane shock; Anderson, Modern Compressible Flow, sec. 7.7)."""
    a, r = (gamma + 1) / (gamma - 1), p2 / p1
    return p2 * ((a + 2) * r - 1) / (r + a)


@dataclass
class Venting:
    """The tank and the cylinder emptying after the separation."""
    vented: float                # the gas the shot vents [kg]: the tank's loss and all the cylinder held
    tank_left: float             # [kg]
    ported: float                # through the ports over the duration, the integral of their flow [kg]
    cylinder_left: float         # [kg]
    time: np.ndarray             # [s] from the separation
    cylinder_pressure: np.ndarray   # [Pa]
    tank_pressure: np.ndarray    # [Pa]


def vent_history(gas: Gas, tank: tuple[float, float, float], cylinder: tuple[float, float, float],
                 valve_area: float, port_area: float, closing: float, ambient: float, duration: float,
                 samples: int = 400) -> Venting:
    """The tank and the cylinder as control volumes (module docstring): ``tank`` and ``cylinder`` as (volume
    [m^3], pressure [Pa], temperature [K]); the valve's area falls linearly to zero over ``closing`` [s] (inf:
    left open) from the separation, the ports' area fixed; integrated over ``duration`` [s]."""
    V_t, V_c = tank[0], cylinder[0]
    m_t0, m_c0 = (gas.mass_for(p, T, V) for V, p, T in (tank, cylinder))
    y0 = [m_t0, m_t0 * gas.cv * tank[2], m_c0, m_c0 * gas.cv * cylinder[2], 0.0]

    def state(m, U, V):
        return (gas.pressure(m, U, V), gas.temperature(m, U)) if m > 0 else (0.0, 0.0)

    def valve(t):
        if not math.isfinite(closing):
            return valve_area
        return valve_area * max(1 - t / closing, 0.0) if closing > 0 else 0.0

    def rhs(t, y):
        (p_t, T_t), (p_c, T_c) = state(y[0], y[1], V_t), state(y[2], y[3], V_c)
        # the valve's flow either way, the upstream side's stagnation state; the ports to the test cell
        m_v = (orifice_flow(gas, valve(t), p_t, T_t, p_c) - orifice_flow(gas, valve(t), p_c, T_c, p_t))
        h_v = gas.cp * (T_t if m_v >= 0 else T_c)
        m_p = orifice_flow(gas, port_area, p_c, T_c, ambient)
        return [-m_v, -h_v * m_v, m_v - m_p, h_v * m_v - gas.cp * T_c * m_p, m_p]
    t_eval = np.linspace(0.0, duration, samples)
    sol = solve_ivp(rhs, (0.0, duration), y0, method="LSODA", rtol=1e-8, atol=[1e-8 * m_t0, 1e-8 * y0[1],
                    1e-8 * m_t0, 1e-8 * y0[1], 1e-8 * m_t0], t_eval=t_eval)
    p_c = np.array([state(m, U, V_c)[0] for m, U in zip(sol.y[2], sol.y[3])])
    p_t = np.array([state(m, U, V_t)[0] for m, U in zip(sol.y[0], sol.y[1])])
    # once the valve is shut the cylinder's gas goes to the cell whole (to its ambient charge, left out)
    left = float(sol.y[0, -1])
    return Venting(m_t0 + m_c0 - left, left, float(sol.y[4, -1]), float(sol.y[2, -1]), sol.t, p_c, p_t)


def arrest_force_limit(h: float, S: float, nu: float, bore: float, inner: float) -> float:
    """The largest force [N] the piston (thickness ``h``, allowable ``S``) puts on its arrest, an annulus from the
    carriage's passage (diameter ``inner``) to the ``bore`` (module docstring): the central disc's bending under
    the face's uniform load, q <= 8 h^2 S / (3 (3 + nu) r_i^2) (Roark Table 11.2 case 10a), or the annulus's
    bearing, S (A - pi r_i^2), whichever is less."""
    r_i, A = inner / 2, math.pi * bore * bore / 4
    return min(8 * h * h * S / (3 * (3 + nu) * r_i * r_i) * A, S * (A - math.pi * r_i * r_i))


@dataclass
class PortBand:
    """The ring of vent ports: holes on a square pitch in a thickened band of the cylinder's wall."""
    share: float                 # open share of the band's wall
    length: float                # along the axis, x_a - x_p [m]
    area: float                  # all its holes [m^2]
    hole: float                  # diameter [m]
    pitch: float                 # [m]
    efficiency: float            # the ligament's, (p - d) / p
    thickness: float             # the band's wall [m]
    hoop_stress: float           # across the ligaments at p0 [Pa]
    axial_stress: float          # the arrest's force across the ligaments [Pa]
    mass: float                  # the band over the plain wall it replaces [kg]


def port_band(bore: float, length: float, share: float, p0: float, allowable: float, wall: float, rho: float,
              arrest_force: float) -> PortBand:
    """The band (module docstring): its wall at the ``allowable`` across the ligaments, against p0's hoop stress
    or the arrest's force, whichever needs more; its holes one band thickness across; its mass over the plain
    ``wall`` it replaces."""
    ratio = math.sqrt(4 * share / math.pi)       # d / p
    E = 1 - ratio
    if E * allowable <= p0:
        raise ValueError(f"the ports' band: no wall carries p0 across ligaments of efficiency {E:.3g} at "
                         f"{allowable / 1e6:.3g} MPa; lower the ports' share")
    # Lame's inner-wall hoop stress p0 (Y^2 + 1) / (Y^2 - 1) across the ligaments at the allowable
    y2 = (E * allowable / p0 + 1) / (E * allowable / p0 - 1)
    t_hoop = bore / 2 * (math.sqrt(y2) - 1)
    t = max(t_hoop, brentq(lambda t: arrest_force / (E * math.pi * (bore + t) * t) - allowable, 1e-6 * bore,
                           10 * bore))
    Y2 = (1 + 2 * t / bore) ** 2
    hoop = p0 * (Y2 + 1) / (Y2 - 1) / E
    axial = arrest_force / (E * math.pi * (bore + t) * t)
    shell = rho * math.pi * (bore + t) * t * length * (1 - share)
    plain = rho * math.pi * (bore + wall) * wall * length
    return PortBand(share, length, share * math.pi * bore * length, t, t / ratio, E, t, hoop, axial,
                    shell - plain)


def range_limits(band: PortBand, fall: float, stroke: float, c0: float, c_b: float, mach: float,
                 column: dict) -> list[Limit]:
    """The ported end's range (module docstring) as limits, each checked on the design; ``c_b`` the lowest
    sound speed at the piston's face over the fall [m/s]; ``column`` the bracket's check (``column_bracket``)."""
    (lower, upper), ratios = column["law"], [f.end_ratio for f in column["column"].values()]
    return [
        Limit("gas drive ports", "quasi-1D column's highest face pressure at the separation over the bracket's",
              max(ratios) / upper, 1.0, "-", "fluid.gas_column, distributed bleed, Cd and jets at both ends",
              "the ported law's bracket (its range)"),
        Limit("gas drive ports", "the bracket's lower end over the quasi-1D column's lowest face pressure",
              lower / min(ratios), 1.0, "-", "fluid.gas_column, distributed bleed, Cd and jets at both ends",
              "the ported law's bracket (its range)"),
        Limit("gas drive ports", "gas transit through the band's wall over the fall", band.thickness / c_b / fall,
              PORT_WALL_RANGE, "-", "t / c_b over t_f", "quasi-steady port flow"),
        Limit("gas drive ports", "wave transit along the band over the fall", band.length / c_b / fall,
              PORT_SPREAD_RANGE, "-", "l_p / c_b over t_f", "the ports at the piston's face"),
        Limit("gas drive ports", "the column's Mach number into the ports", mach, INFLOW_RANGE, "-",
              "(u + Q / A) / c", "the simple wave feeding the ports (it chokes past 1)"),
        Limit("gas drive ports", "the fall over the column's echo from the valve", fall / (2 * stroke / c0), 1.0,
              "-", "t_f over 2 x_p / c0", "the simple wave through the fall (no echo yet)"),
    ]

"""Arrangement (d) of the premise: the closed-breech gas drive, the pulse made by the gas pressure itself (the
HYGE-type pneumatic shock actuator, the standard non-pyrotechnic shock tester), with no striker, no amplifier
and no dashpot.

The article stands on its nose seat (the carriage, a steel cylinder of its diameter and one diameter deep) on
a thrust piston in a closed cylinder; a chamber (the tank) at p0 opens on the piston's back through a
full-bore valve (a HYGE's seal lifting off its seat) and the gas drives piston, carriage and article over the
stroke until the piston's back uncovers vent ports in the cylinder's wall; its front then meets an arrest, and
the carriage and article leave it and run free past the pulse's monitoring window to be caught by an absorber
(``stops.design_stop``).  The end (ports, arrest, the gas a shot vents) is ``drive_end``'s.

The drive's pressure (``drive_pulse``): the infinitely chambered gun's base pressure
(``launcher.simple_wave.chambered_pressure_ratio``, Seigel 1965 ch. 3), so the specific force
k = p0 A / m falls as the piston speeds up, a(t) = k s(t) pi(u) with

* s(t) = t / t_r over the valve's opening, t_r the trapezoid's rise (10% of D, ``metrics.shapes.specified``),
  then 1: the onset ramp the valve must give (the chamber's pressure let in in proportion to its opening);
* once the piston's back uncovers the ports (at t_p = D - t_f) the base pressure falls as the ports take gas
  from the piston's face (``drive_end.ported_fall``) until the arrest at D separates the carriage and article
  (the arrest's place x_a is where the piston is at D); the ports' share of the wall is the largest of
  ``drive_end.PORT_SHARES`` that makes the design feasible, else the largest whose end holds its range; the band
  is asked at both ends of the face pressure's bracket (``drive_end.bracket``, ``recovery_check``).

The design (``design_gas_drive``) holds the trapezoid's velocity change (its band centre, 441 m/s for
10,000 g and 5 ms) and its duration D foot to foot: one specific force k does both (``specific_force_for``),
so the plateau's mean is the peak (the ports' size follows the bore, so k and the bore are a fixed point,
``_ported_design``); sizing the bore instead for m P at the pressure left at the end of the
stroke (a plateau that starts at P / pi(u_end)) would make the pulse shorter than D.  Then the parts, at the
spec's highest pressure p0 (the smallest bore and the lightest piston: the piston's own inertia takes
rho h a of the pressure):

* the piston, a flat disc of the bore, the carriage's load W = (m_article + m_carriage) a_peak entering at its
  centre over the carriage's radius r0: its thickness from a simply supported plate under a central load,
  sigma = 3 W [(1 + nu) ln(R / r0) + 1] / (2 pi h^2) = S (Roark, 7th ed., Table 11.2 case 16; Timoshenko and
  Woinowsky-Krieger, Plates and Shells, sec. 19), an upper bound: the real piston is held by its own inertia
  spread over its face, not at its rim; of the library's metals the lightest piston is kept;
* the bore A = m k / p0 with m = article + carriage + piston, solved as a fixed point (the piston grows with
  the bore); when the piston's own inertia needs more pressure than p0 gives, no drive exists (``None``);
* the cylinder (travel + piston + carriage + article long) and the tank by the launcher's ASME rules
  (``launcher.design.weights``), the tank's volume V0 such that its pressure holds within ``CHAMBER_HOLD``
  while the swept volume fills: p_c / p0 >= (V0 / (V0 + A x))^gamma (the cylinder's gas is less dense than
  the chamber's at the same entropy), so V0 = A x / ((1 - CHAMBER_HOLD)^(-1/gamma) - 1);
* the carriage bears on the piston's face: its foot is widened (a steel cylinder of the radius
  r_b = sqrt(W / (pi S_piston)), at least the article's, one article diameter deep) until the bearing stress
  W / (pi r_b^2) is the piston metal's own allowable, solved with W (``carriage_for``); the piston's central
  load then enters over r_b;
* the catch at the spec's catch deceleration (``MachineSpec.catch``, the rule every row of the premise uses),
  after a free run of the band's monitoring window after the pulse (1.5 D at u_end), so that the catch is no
  part of the record the band checks; the frame carries the largest of the drive's thrust p0 A, the catch's
  force, the arrest's force less the gas's on the breech at the separation (what the vessel takes forward at
  the arrest's impact) and the ports' jets' most axial thrust (``layout.frame_force``);
* the ports' band and the piston's arrest (``drive_end``: the band's ligaments at the allowable; the arrest
  against the gas's push, at most p0 A, its force at most what the piston's front carries, ``stops.design_stop``
  with the push);
* the gas a shot vents with the valve left open and with it closing over ``CLOSING_TIMES``
  (``closing_sensitivity``), a running cost, not a limit.

The valve's opening time is assumed, no source found for a full-bore differential-area seal's opening at this
bore and pressure; ``opening_sensitivity`` gives the band against it (the same machine, k and stroke, the
ramp's length varied) at both ends of the bracket, ``charge_sensitivity`` against a lower charge and
``arrest_sensitivity`` against the arrest's place, and the verdict states the longest opening it was found in the
band at.  The band is the metrics' (``metrics.shapes``): the specified pulse placed on the measured one by its
10% up-crossing, so a slower ramp moves the ideal later with it.

Range of the model (each checked on every design where it can be): a perfect gas at rest in the chamber at
293 K; the chamber's pressure held within ``CHAMBER_HOLD`` (by the tank's size); the valve's opening is the
stated linear ramp of pressure, not its flow dynamics; the drive's end is the ported fall within its bracket
(``drive_end``'s range); no gas friction or heat loss, no seal drag, no air ahead (bounded,
``air_ahead_bound``); the separation a step (``separation_step``); the piston and carriage rigid (their
elastic waves left out: the radial wave transit R / c_bar over the rise is checked
against ``WAVE_RANGE``).  ``lumped_check`` fires the same cylinder and tank with the lumped gun
(``launcher.gun.fire``: the finite tank, the valve's flow through its opening area, the Lagrange gas inertia,
the air ahead), the independent model the chambered law leaves those out of.
"""
from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from ..fluid.gas_column import RADIAL
from ..launcher.design import LauncherDesign, weights
from ..launcher.gas import GASES
from ..launcher.gun import Gun, air_ahead_pressure, fire
from ..launcher.simple_wave import chambered_pressure_ratio, escape_speed
from ..metrics import shapes
from ..scene.library import LIBRARY, initial_yield_stress, property_si
from ..units import G0, IN, PSI
from . import blowdown as B
from . import drive_end as E
from .boundary import TEMPERATURE
from .launcher import SIZING, launcher_of
from .layout import RING_CLEARANCE, frame_force, frame_section, ring_area, tank_length
from .limits import Limit, broken
from .premise import Arrangement
from .spec import MachineSpec
from .stops import HONEYCOMB, design_stop

# the valve's opening times [s] the band is checked against (``opening_sensitivity``)
OPENING_TIMES = (0.5e-3, 0.55e-3, 0.6e-3, 0.7e-3, 0.8e-3, 1e-3, 2e-3, 5e-3)
# the charge's pressure over the design's the band is checked against (``charge_sensitivity``)
CHARGE_SHARES = (0.99, 0.98, 0.97, 0.95, 0.9)
# separation times over D the band is checked against with the arrest moved (``arrest_sensitivity``)
SEPARATION_SHARES = (0.99, 0.98, 0.97, 0.96, 0.95)
# the openings [s] and charges each moved arrest is checked at, for its margins (fewer: a run's time)
MARGIN_OPENINGS, MARGIN_CHARGES = (0.5e-3, 0.6e-3, 0.7e-3, 0.8e-3, 1e-3), (0.98, 0.95, 0.9)
# standard conditions for the vented gas's volume (0 degC, 1 atm)
STP_TEMPERATURE, STP_PRESSURE = 273.15, 101325.0
# the chamber's pressure may fall by this share while the swept volume fills: a quarter of the band's +/- 20%
CHAMBER_HOLD = 0.05
# the piston's metals, the lightest piston kept (each with its yield and source in the scene library)
PISTON_MATERIALS = ("aluminium_6061_t6", "titanium_50a", "high_strength_steel")
# the rigid piston's range: its radial bar-wave transit R / sqrt(E / rho) at most this share of the rise
WAVE_RANGE = 0.1
SEAT_DEPTH = 1.0              # the carriage's length over the article's diameter
GASES_TRIED = ("air", "helium")
RTOL = 1e-10
FIXED_POINT_TOL, FIXED_POINT_PASSES = 1e-10, 200
PORTS_TOL = 1e-7             # the ports' bore settled
# the valve's closing times [s] the gas a shot vents is given at (``closing_sensitivity``; inf: left open)
CLOSING_TIMES = (1e-3, 5e-3, 20e-3, math.inf)


@dataclass
class DrivePulse:
    """The drive's acceleration history and where it ends."""
    time: np.ndarray             # [s]
    acceleration: np.ndarray     # [m/s^2]
    specific_force: float        # k = p0 A / m [m/s^2]
    port_time: float             # the piston's back at the ports [s]
    port_speed: float            # [m/s]
    stroke: float                # the travel to the ports, x_p [m]
    end_speed: float             # at the separation [m/s]
    fall_travel: float           # travelled from the ports to the arrest, x_a - x_p [m]
    peak: float                  # [m/s^2]
    fall: object = None          # ``drive_end.PortedFall``
    ports: object = None         # ``drive_end.Ports``

    @property
    def separation_time(self) -> float:
        return self.fall.end_time

    @property
    def arrest_travel(self) -> float:
        """The piston's back where its front meets the arrest, x_a [m]."""
        return self.stroke + self.fall_travel


def _ramp(t: float, rise: float) -> float:
    return min(t / rise, 1.0) if rise > 0 else 1.0


def _drive(k: float, c0: float, gamma: float, rise: float, port_time: float, dense: bool = False):
    """Integrate u' = k s(t) pi(u), x' = u from rest to ``port_time`` (two pieces: the ramp's kink)."""
    def rhs(t, y):
        return [k * _ramp(t, rise) * chambered_pressure_ratio(y[0], c0, gamma), y[0]]
    pieces, y = [], [0.0, 0.0]
    for t0, t1 in ((0.0, min(rise, port_time)), (min(rise, port_time), port_time)):
        if t1 > t0:
            sol = solve_ivp(rhs, (t0, t1), y, method="DOP853", rtol=RTOL, atol=[RTOL * k * port_time,
                            RTOL * k * port_time ** 2], dense_output=dense)
            pieces.append(sol)
            y = sol.y[:, -1]
    return y[0], y[1], pieces


def drive_pulse(k: float, c0: float, gamma: float, rise: float, ports, port_time: float,
                separation: float | None = None, arrest: float | None = None, record: float = 0.0,
                samples: int = 2000) -> DrivePulse:
    """The drive at specific force ``k`` [m/s^2] (module docstring) to the ports at ``port_time`` [s], then the
    ported fall (``drive_end.ported_fall``, ``ports`` a ``drive_end.Ports``) to the separation at
    ``separation`` [s] or where the piston reaches ``arrest`` [m]; its record sampled to ``record`` [s]
    (free flight after the separation)."""
    u_p, x_p, pieces = _drive(k, c0, gamma, rise, port_time, dense=True)
    fall = E.ported_fall(k, ports, u_p, x_p, port_time, t_end=separation, x_end=arrest)
    t = np.linspace(0.0, max(record, fall.end_time), samples)
    a = np.zeros_like(t)
    for k_t, s in enumerate(t):
        if s <= port_time:
            piece = next(p for p in pieces if s <= p.t[-1] * (1 + 1e-12))
            a[k_t] = k * _ramp(s, rise) * chambered_pressure_ratio(float(piece.sol(s)[0]), c0, gamma)
    on = (t > port_time) & (t <= fall.end_time)
    a[on] = np.interp(t[on], fall.time, fall.acceleration)
    # the peak is where the ramp ends (pi falls after it), whatever the sampling
    u_r = pieces[0].y[0, -1] if rise > 0 else 0.0
    peak = k * chambered_pressure_ratio(u_r, c0, gamma)
    return DrivePulse(t, a, k, port_time, u_p, x_p, fall.end_speed, fall.end_travel - x_p, float(max(a.max(), peak)),
                      fall, ports)


def specific_force_for(dv: float, duration: float, rise: float, fall: float, c0: float, gamma: float,
                       ports) -> float:
    """The specific force k [m/s^2] that gives the velocity change ``dv`` at the separation at ``duration``
    [s] (the ports opening at duration - fall, ``ports`` a ``drive_end.Ports``); inf past what the gas can
    give (the escape speed)."""
    if dv >= escape_speed(c0, gamma, chambered=True) * (1 - 1e-6):
        return math.inf
    port = duration - fall

    def short(k):
        u_p, x_p, _ = _drive(k, c0, gamma, rise, port)
        return E.ported_fall(k, ports, u_p, x_p, port, t_end=duration, samples=2).end_speed - dv
    # k D >= u_end, so half of dv / D falls short; double until the speed is passed
    lo = hi = 0.5 * dv / duration
    while short(hi) < 0:
        lo, hi = hi, 2 * hi
        if hi > 1e6 * dv / duration:
            return math.inf
    return float(brentq(short, lo, hi, xtol=1e-12 * hi, rtol=1e-13))


def piston_thickness(load: float, R: float, r0: float, S: float, nu: float) -> float:
    """The flat piston's thickness [m] (module docstring: Roark Table 11.2 case 16, simply supported, a central
    load ``load`` [N] over radius ``r0``, at the allowable ``S``)."""
    return math.sqrt(3 * load * ((1 + nu) * math.log(max(R / r0, 1.0)) + 1) / (2 * math.pi * S))


@dataclass
class Moving:
    """What the gas drives: the piston (its metal, size and stress), the carriage and the article."""
    material: str
    bore: float                  # [m]
    piston_thickness: float      # [m]
    piston_mass: float           # [kg]
    carriage_mass: float         # [kg]
    total: float                 # article, carriage and piston [kg]
    allowable: float             # the piston's, its plate stress set to it [Pa]
    wave_speed: float            # the piston's bar-wave speed sqrt(E / rho) [m/s]
    bearing_radius: float = math.nan   # the carriage's foot on the piston [m]


def moving_mass(material: str, safety: float, article: float, carriage: float, seat_radius: float, k: float,
                peak: float, p0: float) -> Moving | None:
    """The piston of ``material`` and the bore the drive's specific force ``k`` [m/s^2] needs at ``p0`` [Pa]
    for it, ``carriage`` and ``article`` [kg] at the pulse's ``peak`` [m/s^2] (a fixed point: the piston grows
    with the bore); None where the piston's own inertia needs more than p0."""
    rho = property_si(material, "density", "density")
    S = initial_yield_stress(material) / safety
    nu = float(LIBRARY[material]["poisson_ratio"])
    W = (article + carriage) * peak
    m = article + carriage
    for _ in range(FIXED_POINT_PASSES):
        R = math.sqrt(m * k / (p0 * math.pi))
        h = piston_thickness(W, R, seat_radius, S, nu)
        # the piston's share of the pressure, rho h k / p0, must stay below 1, or no bore carries it
        if rho * h * k >= p0:
            return None
        new = article + carriage + rho * math.pi * R * R * h
        if abs(new - m) <= FIXED_POINT_TOL * new:
            E = property_si(material, "youngs_modulus", "pressure")
            return Moving(material, 2 * R, h, new - article - carriage, carriage, new, S, math.sqrt(E / rho))
        m = new
    return None


def carriage_for(piston: str, spec: MachineSpec, article: float, seat_radius: float, peak: float):
    """The carriage [kg] (the spec's steel, one article diameter deep) and its foot's radius [m] on a piston of
    ``piston`` (module docstring): the bearing stress at the piston's allowable, the foot at least the seat."""
    rho = property_si(spec.material, "density", "density")
    S = initial_yield_stress(piston) / spec.safety_factor
    depth, r = SEAT_DEPTH * 2 * seat_radius, seat_radius
    for _ in range(FIXED_POINT_PASSES):
        mass = rho * math.pi * r * r * depth
        new = max(seat_radius, math.sqrt((article + mass) * peak / (math.pi * S)))
        if abs(new - r) <= FIXED_POINT_TOL * new:
            break
        r = new
    return rho * math.pi * r * r * depth, r


def tank_volume(swept: float, gamma: float) -> float:
    """The chamber's volume [m^3] that holds its pressure within ``CHAMBER_HOLD`` while ``swept`` fills
    (module docstring)."""
    return swept / ((1 - CHAMBER_HOLD) ** (-1 / gamma) - 1)


def stp_volume(gas, mass: float) -> float:
    """The volume [m^3] of ``mass`` [kg] of ``gas`` at standard conditions (0 degC, 1 atm)."""
    return mass / gas.mass_for(STP_PRESSURE, STP_TEMPERATURE, 1.0)


@dataclass
class GasDrive:
    """Arrangement (d) designed for one gas (module docstring)."""
    gas: str
    pressure: float              # the chamber's p0 [Pa]
    sound_speed: float           # c0 [m/s]
    velocity_change: float       # asked [m/s]
    pulse: DrivePulse | None
    moving: Moving | None
    gun: Gun | None              # the cylinder (bore, stroke) and the tank, as the launcher's rules size them
    launcher: object = None      # ``machine.launcher.Launcher``: walls, weights, stored gas
    cylinder_length: float = math.nan   # stroke, piston, carriage and article [m]
    cylinder_mass: float = math.nan   # its ASME wall over its length [kg]
    tank_length: float = math.nan     # [m]
    free_run: float = math.nan   # from the open end to the catch: the fall and the band's window after it [m]
    stop: object = None          # ``stops.Stop``
    frame_mass: float = math.nan
    machine_mass: float = math.nan
    machine_length: float = math.nan
    band: object = None          # ``metrics.shapes.BandCheck``
    limits: list = field(default_factory=list)
    lumped: dict = field(default_factory=dict)   # ``lumped_check``
    recovery: dict = field(default_factory=dict)  # ``recovery_check``: the face's upper end
    charges: list = field(default_factory=list)   # ``charge_sensitivity``
    separations: list = field(default_factory=list)   # ``arrest_sensitivity``
    range_limits: list = field(default_factory=list)  # the ported fall's own range (``drive_end.range_limits``)
    column: dict = field(default_factory=dict)        # the bracket on the gas column (``drive_end.column_bracket``)
    column_bands: dict = field(default_factory=dict)  # ``column_bands``
    jet_thrust: float = math.nan      # the held piston's port jets' axial momentum flux, their most [N]
    seat_stress: float = math.nan     # the carriage's seat at the peak [Pa]
    air_ahead: dict = field(default_factory=dict)   # ``air_ahead_bound``
    step: dict = field(default_factory=dict)        # ``separation_step``
    arrest_reaction: float = math.nan  # the arrest's force less the gas's on the breech at the separation [N]
    arrest_hold: float = math.nan     # the force with which the arrest stops the piston against the push (0: none)
    openings: list = field(default_factory=list)  # ``opening_sensitivity``
    vented_mass: float = math.nan     # the gas a shot vents, the valve left open [kg] (``closing_sensitivity``)
    vented_volume: float = math.nan   # the same at standard conditions [m^3]
    port_band: object = None          # ``drive_end.PortBand``
    arrest: object = None             # ``stops.Stop``: the piston's, which the carriage and article pass
    push: float = math.nan            # the gas's push on the held piston [N]
    arrest_limit: float = math.nan    # the most the piston puts on its arrest at its allowable [N]
    closings: list = field(default_factory=list)  # ``closing_sensitivity``
    notes: list[str] = field(default_factory=list)

    @property
    def in_band(self) -> bool:
        return bool(self.band is not None and self.band.passed)

    @property
    def feasible(self) -> bool:
        """Within its limits, and its pulse in the band at both of the face's bounds (``recovery_check``)."""
        return (self.moving is not None and not broken(self.limits) and self.in_band
                and bool(self.recovery) and self.recovery["band"].passed)


def _no_drive(spec: MachineSpec, gas: str, c0: float, dv: float, why: str) -> GasDrive:
    return GasDrive(gas, spec.max_pressure, c0, dv, None, None, None, notes=[why])


def design_gas_drive(spec: MachineSpec, gas: str, article: float, article_diameter: float,
                     article_length: float) -> GasDrive:
    """(d) for ``gas`` at the spec's highest pressure: the pulse, the parts, the catch, the limits and the band
    (module docstring); the article [kg], its diameter and length [m]."""
    ideal = shapes.specified(spec.pulse.checked_shape, spec.pulse.peak, spec.pulse.duration)
    in_range = None
    for share in E.PORT_SHARES:
        d = _design_with_ports(spec, gas, share, article, article_diameter, article_length, ideal)
        if d.moving is None:
            return d
        if d.feasible:
            return _checked(d, spec)
        if in_range is None and not broken(d.range_limits):
            in_range = d
    # none feasible: the largest share whose fall holds its own range, its broken limits in the verdict
    return _checked(in_range or d, spec)


def _checked(d: GasDrive, spec: MachineSpec) -> GasDrive:
    """The kept design's checks beside it (the lumped gun, the margins, the air ahead, the step) and its notes."""
    d.lumped = lumped_check(d, spec)
    d.openings = opening_sensitivity(d, spec)
    d.charges = charge_sensitivity(d, spec)
    d.separations = arrest_sensitivity(d, spec)
    d.air_ahead, d.step = air_ahead_bound(d), separation_step(d, spec)
    d.column_bands = column_bands(d, spec)
    d.notes = _notes(d, spec)
    return d


def _design_with_ports(spec: MachineSpec, gas: str, share: float, article: float, article_diameter: float,
                       article_length: float, ideal) -> GasDrive:
    """(d) with ports of ``share`` of the band's wall open (``design_gas_drive``)."""
    g, p0 = GASES[gas], spec.max_pressure
    c0, dv = g.sound_speed(p0, TEMPERATURE), ideal.velocity_change
    k, pulse, mv = _ported_design(spec, g, p0, c0, ideal, article, article_diameter / 2, share)
    if not math.isfinite(k):
        return _no_drive(spec, gas, c0, dv, f"{gas} cannot give {dv:.4g} m/s in {ideal.duration * 1e3:.3g} ms at any "
                         f"pressure: its escape speed is {escape_speed(c0, g.gamma, True):.4g} m/s")
    band = spec.pulse.band(pulse.time, pulse.acceleration)[1]
    if mv is None:
        d = _no_drive(spec, gas, c0, dv, f"no piston of {', '.join(PISTON_MATERIALS)} carries its own inertia at "
                      f"{p0 / PSI:,.0f} psi and {pulse.peak / G0:,.0f} g (its share of the pressure rho h a over "
                      f"p0 reaches 1); {_band_words(band)}")
        d.pulse, d.band = pulse, band
        return d
    d = GasDrive(gas, p0, c0, dv, pulse, mv, None, band=band)
    _size_machine(d, spec, article, article_diameter, article_length, ideal)
    d.recovery = recovery_check(d, spec, ideal)
    return d


def _ported_design(spec: MachineSpec, g, p0: float, c0: float, ideal, article: float, r0: float, share: float):
    """k, the pulse and the moving mass with ports of the bore they size (``drive_end.area_ratio_rate``): a
    fixed point on the bore, from none; (inf, None, None) where the gas cannot, (k, pulse, None) where no piston
    carries its inertia."""
    beta, pulse = 0.0, None
    for _ in range(FIXED_POINT_PASSES):
        ports = E.Ports(g, p0, TEMPERATURE, beta, share)
        k = specific_force_for(ideal.velocity_change, ideal.duration, ideal.rise, ideal.fall, c0, g.gamma, ports)
        if not math.isfinite(k):
            return k, None, None
        pulse = drive_pulse(k, c0, g.gamma, ideal.rise, ports, ideal.duration - ideal.fall,
                            separation=ideal.duration, record=spec.pulse.record_end())
        options = []
        for mat in PISTON_MATERIALS:
            carriage, r_b = carriage_for(mat, spec, article, r0, pulse.peak)
            mv = moving_mass(mat, spec.safety_factor, article, carriage, r_b, k, pulse.peak, p0)
            if mv:
                options.append(dataclasses.replace(mv, bearing_radius=r_b))
        if not options:
            return k, pulse, None
        mv = min(options, key=lambda o: o.total)
        new = E.area_ratio_rate(share, mv.bore)
        if abs(new - beta) <= PORTS_TOL * new:
            return k, pulse, mv
        beta = new
    raise RuntimeError("the ports' bore did not settle")


def _band_words(band) -> str:
    return ("its pulse is in the band" if band.passed else f"its pulse is OUTSIDE the band (worst excess "
            f"{band.worst_excess:.3g} of the peak, velocity change {band.velocity_change_error:+.2%})")


def _size_machine(d: GasDrive, spec: MachineSpec, article: float, diameter: float, length: float, ideal):
    """The cylinder, tank, ports, arrest, catch and frame of ``d``, its mass, length and limits."""
    mv, pulse, g = d.moving, d.pulse, GASES[d.gas]
    area = math.pi * mv.bore ** 2 / 4
    # the chambered column is the law through the fall too: the tank holds its pressure to the arrest
    V0 = tank_volume(area * pulse.arrest_travel, g.gamma)
    gun = Gun(V0, d.pressure, mv.bore, pulse.stroke, mv.total, TEMPERATURE, d.gas, valve_area=area,
              opening_time=ideal.rise)
    wb, wt = weights(gun, SIZING)
    L = launcher_of(LauncherDesign(gun, wb + wt, wb, wt, pulse.end_speed, d.velocity_change, pulse.peak, math.nan,
                                   True), mv.total)
    size = L.sizing
    d.gun, d.launcher = gun, L
    rho = property_si(spec.material, "density", "density")
    S = initial_yield_stress(spec.material) / spec.safety_factor
    _design_end(d, spec, size, rho, S)
    seat = SEAT_DEPTH * diameter
    d.cylinder_length = max(pulse.arrest_travel + mv.piston_thickness + d.arrest.length,
                            mv.piston_thickness + seat + length)
    d.cylinder_mass = size["barrel"]["weight"] * d.cylinder_length / pulse.stroke + d.port_band.mass
    d.tank_length = tank_length(V0, size["tank"]["diameter"], size["tank"]["head_thickness"])
    # the carriage and article run free from the separation, past the band's window, to the catch
    d.free_run = shapes.TOLERANCE["after"] * ideal.duration * pulse.end_speed
    free = article + mv.carriage_mass
    d.stop = design_stop("gas drive's carriage and article", free, pulse.end_speed, seat, rho, S,
                         ring_area(2 * mv.bearing_radius, diameter + RING_CLEARANCE), spec.oil_pressure,
                         deceleration=spec.catch)
    d.closings = closing_sensitivity(d, V0)
    # the design leaves the valve open: what it vents is the open valve's blowdown through the ports
    d.vented_mass = next(c["vented"] for c in d.closings if not math.isfinite(c["closing"]))
    d.vented_volume = stp_volume(g, d.vented_mass)
    d.machine_length = d.tank_length + d.cylinder_length + d.free_run + d.stop.length
    # the frame carries the drive's thrust, the catch, the arrest's net push on the vessel at the separation or
    # the held piston's port jets' axial thrust, whichever is largest
    d.frame_mass = 2 * rho * frame_section(frame_force([d.stop], max(d.pressure * area, d.arrest_reaction,
                                                                     d.jet_thrust)), S) * d.machine_length
    d.machine_mass = wt + d.cylinder_mass + mv.total + d.arrest.absorber_mass + d.stop.absorber_mass + d.frame_mass
    d.limits = _drive_limits(d, spec, size, article, diameter, ideal, S) + _end_limits(d, spec, S) + list(d.stop.limits)


def _design_end(d: GasDrive, spec: MachineSpec, size: dict, rho: float, S: float):
    """The ports' band and the piston's arrest (``drive_end``): the arrest against the gas's push on the piston,
    bounded by p0 A (the column brought to rest by a simple compression keeps u + 2 c / (gamma - 1) =
    2 c0 / (gamma - 1), so it stops at p0), its force at most what the piston's front carries; the band's wall
    at the cylinder's allowable against p0 and the arrest's force."""
    mv, pulse, g = d.moving, d.pulse, GASES[d.gas]
    area = math.pi * mv.bore ** 2 / 4
    ports_area = pulse.ports.share * math.pi * mv.bore * pulse.fall_travel
    steady = E.steady_pressure(g, d.pressure, TEMPERATURE, area, ports_area, B.ATMOSPHERE)
    d.push = d.pressure * area
    d.jet_thrust = E.jet_thrust(g, steady, TEMPERATURE, ports_area, area, B.ATMOSPHERE)
    nu = float(LIBRARY[mv.material]["poisson_ratio"])
    # the piston's front annulus outside the carriage's foot meets the arrest, which lets the carriage pass
    passage = 2 * mv.bearing_radius + RING_CLEARANCE
    d.arrest_limit = E.arrest_force_limit(mv.piston_thickness, mv.allowable, nu, mv.bore, passage)
    rho_p = property_si(mv.material, "density", "density")
    args = ("gas drive's piston (its arrest)", mv.piston_mass, pulse.end_speed, mv.piston_thickness, rho_p,
            mv.allowable, ring_area(mv.bore, passage), spec.oil_pressure)
    pushed = design_stop(*args, max_force=d.arrest_limit, push=d.push)
    # none stops the piston against the push: the unpushed one sizes the parts, its holding force nil
    d.arrest = pushed or design_stop(*args, max_force=d.arrest_limit)
    d.arrest_hold = d.arrest.force if pushed else 0.0
    # the vessel takes the arrest's force forward and the gas's on the breech back, least at the separation
    d.arrest_reaction = d.arrest.force - pulse.fall.end_ratio * d.pressure * area
    d.port_band = E.port_band(mv.bore, pulse.fall_travel, pulse.ports.share, d.pressure, S,
                              size["barrel"]["thickness"], rho, d.arrest.force)


def _drive_limits(d: GasDrive, spec: MachineSpec, size: dict, article: float, diameter: float, ideal,
                  S: float) -> list[Limit]:
    mv, pulse = d.moving, d.pulse
    seat_stress = d.seat_stress = (article + mv.carriage_mass) * pulse.peak / (math.pi * diameter ** 2 / 4)
    return [
        Limit("gas drive cylinder", "bore", mv.bore, spec.max_bore, "m", "the bore A = m k / p0", "the spec's limit"),
        Limit("gas drive cylinder", "length", d.cylinder_length, spec.max_barrel_length, "m",
              "the arrest's travel, the piston and the arrest", "the spec's barrel limit"),
        Limit("gas drive cylinder", "wall hoop stress (Lame, inner wall)", size["barrel"]["hoop_stress"],
              size["barrel"]["hoop_stress"] * (1 + size["barrel"]["margin"]), "Pa", size["barrel"]["rule"],
              f"ASME II-D allowable of {size['barrel']['material']}"),
        Limit("gas drive piston", "plate stress", mv.allowable, mv.allowable, "Pa",
              "Roark Table 11.2 case 16, simply supported, central load", f"{mv.material} yield / "
              f"{spec.safety_factor:g}", sized=True),
        Limit("gas drive carriage", "seat stress", seat_stress, S, "Pa", "(article + carriage) a_peak over the seat",
              f"{spec.material} yield / {spec.safety_factor:g}"),
        Limit("gas drive piston", "bearing under the carriage's foot",
              (article + mv.carriage_mass) * pulse.peak / (math.pi * mv.bearing_radius ** 2), mv.allowable, "Pa",
              "(article + carriage) a_peak over the foot", f"{mv.material} yield / {spec.safety_factor:g}", sized=True),
        Limit("gas drive piston", "radial wave transit over the valve's rise", mv.bore / 2 / mv.wave_speed / ideal.rise,
              WAVE_RANGE, "-", "R / sqrt(E / rho) over t_r", "the rigid piston's range"),
        Limit("gas drive chamber", "pressure fall while the stroke fills", CHAMBER_HOLD, CHAMBER_HOLD, "-",
              "(V0 / (V0 + A x_a))^gamma bound", "the chambered law's range (a chamber at p0)", sized=True),
    ]


def _end_limits(d: GasDrive, spec: MachineSpec, S: float) -> list[Limit]:
    """The ports', the arrest's and the ported fall's range (``drive_end``)."""
    mv, pulse, band, g = d.moving, d.pulse, d.port_band, GASES[d.gas]
    c_b = d.sound_speed * pulse.fall.ratio.min() ** ((g.gamma - 1) / (2 * g.gamma))
    steel = f"{spec.material} yield / {spec.safety_factor:g}"
    d.column = E.column_bracket(pulse.specific_force, pulse.ports, pulse.port_speed, pulse.stroke, pulse.port_time,
                                pulse.arrest_travel)
    d.range_limits = E.range_limits(band, pulse.separation_time - pulse.port_time, pulse.stroke, d.sound_speed, c_b,
                                    pulse.fall.inflow_mach, d.column)
    return [
        Limit("gas drive piston", "load on its arrest", d.arrest.force, d.arrest_limit, "N",
              "the arrest's peak force (the push reaches it only through the arrest): the annulus's bearing, the "
              "centre's bending (Roark 11.2 10a)", f"{mv.material} allowable", sized=True),
        Limit("gas drive piston's arrest", "the gas's push over the arrest's force", d.push, d.arrest_hold, "N",
              "p0 A against the absorber's force: below it the piston never stops", "the push held (module docstring)"),
        Limit("gas drive ports", "ligament hoop stress at p0 (Lame, inner wall)", band.hoop_stress, S, "Pa",
              "p0 (Y^2 + 1) / (Y^2 - 1) / E, UG-53 ligament efficiency", steel, sized=True),
        Limit("gas drive ports", "ligament axial stress under the arrest", band.axial_stress, S, "Pa",
              "F_arrest / (E pi D_m t)", steel, sized=True),
    ] + d.range_limits + list(d.arrest.limits)


def closing_sensitivity(d: GasDrive, V0: float, times=CLOSING_TIMES) -> list[dict]:
    """The gas a shot vents [kg] with the valve closing over each of ``times`` [s] from the separation
    (``drive_end.vent_history``: the tank and the cylinder, the piston held on its arrest), and how long the
    held piston's push lasts (the cylinder above twice the ambient)."""
    g, pulse = GASES[d.gas], d.pulse
    area = math.pi * d.moving.bore ** 2 / 4
    r = pulse.fall.end_ratio
    # the cylinder to the piston at rest on its arrest
    cylinder = (area * (pulse.arrest_travel + d.arrest.stroke), r * d.pressure,
                TEMPERATURE * r ** ((g.gamma - 1) / g.gamma))
    # long enough for the open valve's blowdown through the bore and the ports to end
    duration = 12 * B.time_constant(V0, area, d.sound_speed, g.gamma)
    out = []
    for closing in times:
        v = E.vent_history(g, (V0, d.pressure, TEMPERATURE), cylinder, area, d.port_band.area, closing,
                           B.ATMOSPHERE, duration)
        held = v.time[v.cylinder_pressure > 2 * B.ATMOSPHERE]
        out.append({"closing": closing, "vented": v.vented, "tank_left": v.tank_left,
                    "push_time": float(held[-1]) if len(held) else 0.0})
    return out


def end_pulse(d: GasDrive, spec: MachineSpec, ports, k: float | None = None, rise: float | None = None,
               p0: float | None = None) -> DrivePulse:
    """The same machine (stroke to the ports, arrest) fired with ``ports``, the specific force ``k``, the valve's
    ramp ``rise`` and the charge ``p0`` (the design's where None): the piston reaching the ports when it has
    travelled the stroke, the fall to the arrest."""
    c0, gamma, p = d.sound_speed, GASES[d.gas].gamma, d.pulse
    k = p.specific_force if k is None else k
    rise = spec_rise(spec) if rise is None else rise
    if p0 is not None:
        ports = dataclasses.replace(ports, p0=p0)
    port = brentq(lambda t: _drive(k, c0, gamma, rise, t)[1] - p.stroke, 0.1 * p.port_time,
                  10 * p.port_time + rise, xtol=1e-12)
    return drive_pulse(k, c0, gamma, rise, ports, port, arrest=p.arrest_travel, record=spec.pulse.record_end())


def spec_rise(spec: MachineSpec) -> float:
    """The specified trapezoid's rise [s], the valve's design opening."""
    return shapes.specified(spec.pulse.checked_shape, spec.pulse.peak, spec.pulse.duration).rise


def _band_of(spec: MachineSpec, pulse: DrivePulse):
    return spec.pulse.band(pulse.time, pulse.acceleration)[1]


def recovery_check(d: GasDrive, spec: MachineSpec, ideal) -> dict:
    """The same machine (k, ports, arrest) with the face's pressure at the bracket's upper end through the fall
    (``drive_end.bracket``), and with the port gas leaving radially from ideal holes (the momentum's extreme
    alone): each pulse against the band and its speed at the separation."""
    p = d.pulse
    upper = E.bracket(p.ports)[1]
    out = {}
    for key, ports in (("upper", upper), ("radial", dataclasses.replace(upper, discharge=1.0))):
        pulse = end_pulse(d, spec, ports, rise=ideal.rise)
        out[key] = {"band": _band_of(spec, pulse), "end_ratio": pulse.fall.end_ratio,
                    "speed_error": pulse.end_speed / p.end_speed - 1}
    return {**out["upper"], "radial": out["radial"]}


def column_bands(d: GasDrive, spec: MachineSpec) -> dict:
    """The pulse with the quasi-1D column's fall (``drive_end.column_bracket``, kept in ``d.column``) after the
    ports' opening, each (discharge coefficient, jets) against the band: {(Cd, jets): BandCheck}."""
    p = d.pulse
    t = np.linspace(0.0, max(spec.pulse.record_end(), max(f.end_time for f in d.column["column"].values())), 2000)
    before = np.interp(t, p.time, p.acceleration)
    return {key: spec.pulse.band(t, np.where(t <= p.port_time, before, np.where(
        t <= f.end_time, np.interp(t, f.time, f.acceleration), 0.0)))[1] for key, f in d.column["column"].items()}


def lumped_check(d: GasDrive, spec: MachineSpec) -> dict:
    """The same cylinder and tank fired by the lumped gun (``launcher.gun.fire``: the finite tank, the valve's
    flow through its opening area, Lagrange gas inertia, the air ahead) to the ports, then the same ported fall
    to the same arrest: its speed there, its peak and its pulse against the band, beside the chambered law's."""
    shot = fire(d.gun, samples=400)
    h = shot.history
    t_p = float(h["time"][-1])
    fall = E.ported_fall(d.pulse.specific_force, d.pulse.ports, shot.muzzle_velocity, d.pulse.stroke, t_p,
                         x_end=d.pulse.arrest_travel)
    t = np.linspace(0.0, max(spec.pulse.record_end(), fall.end_time), 2000)
    a = np.where(t <= t_p, np.interp(t, h["time"], h["acceleration"]),
                 np.where(t <= fall.end_time, np.interp(t, fall.time, fall.acceleration), 0.0))
    band = spec.pulse.band(t, a)[1]
    return {"port_speed": shot.muzzle_velocity, "end_speed": fall.end_speed, "peak": shot.peak_acceleration,
            "band": band, "speed_error": fall.end_speed / d.pulse.end_speed - 1,
            "peak_error": shot.peak_acceleration / d.pulse.peak - 1}


def opening_sensitivity(d: GasDrive, spec: MachineSpec, times=OPENING_TIMES) -> list[dict]:
    """The same machine (its k, ports and arrest) with the valve's ramp over each of ``times`` [s], at both ends
    of the face's bracket (``drive_end.bracket``): the pulse's peak, its speed at the separation and the band
    (the piston reaching the ports later as the ramp lengthens)."""
    out = []
    for rise in times:
        low, high = (end_pulse(d, spec, ports, rise=rise) for ports in E.bracket(d.pulse.ports))
        out.append({"opening": rise, "peak": low.peak, "end_speed": low.end_speed, "band": _band_of(spec, low),
                    "upper_band": _band_of(spec, high), "speed_error": low.end_speed / d.velocity_change - 1})
    return out


def charge_sensitivity(d: GasDrive, spec: MachineSpec, shares=CHARGE_SHARES) -> list[dict]:
    """The same machine charged to each of ``shares`` of its p0 (k in proportion), at both ends of the bracket."""
    out = []
    for f in shares:
        low, high = (end_pulse(d, spec, ports, k=f * d.pulse.specific_force, p0=f * d.pressure)
                     for ports in E.bracket(d.pulse.ports))
        out.append({"share": f, "band": _band_of(spec, low), "upper_band": _band_of(spec, high),
                    "speed_error": low.end_speed / d.velocity_change - 1})
    return out


def arrest_sensitivity(d: GasDrive, spec: MachineSpec, shares=SEPARATION_SHARES) -> list[dict]:
    """The same k and ports with the arrest moved to where the bracket's lower end reaches it at each of
    ``shares`` of D: both ends against the band (what would bring the step at the separation in)."""
    c0, gamma, p = d.sound_speed, GASES[d.gas].gamma, d.pulse
    rise, out = spec_rise(spec), []
    for f in shares:
        t_s = f * spec.pulse.duration
        at = drive_pulse(p.specific_force, c0, gamma, rise, p.ports, p.port_time, separation=t_s)
        moved = dataclasses.replace(d, pulse=dataclasses.replace(p, fall_travel=at.fall_travel))
        low, high = (end_pulse(moved, spec, ports) for ports in E.bracket(p.ports))
        openings = [o["opening"] for o in opening_sensitivity(moved, spec, MARGIN_OPENINGS) if _in_both(o)]
        charges = [c["share"] for c in charge_sensitivity(moved, spec, MARGIN_CHARGES) if _in_both(c)]
        out.append({"separation": t_s, "band": _band_of(spec, low), "upper_band": _band_of(spec, high),
                    "upper_ratio": high.fall.end_ratio, "speed_error": low.end_speed / d.velocity_change - 1,
                    "opening": max(openings, default=0.0), "charge": min(charges, default=math.nan)})
    return out


def _in_both(c: dict) -> bool:
    return c["band"].passed and c["upper_band"].passed


def longest_opening_in_band(d: GasDrive) -> float:
    """The longest of the checked opening times [s] at which the band still passes (0 where none does)."""
    return max((o["opening"] for o in d.openings if _in_both(o)), default=0.0)


def _notes(d: GasDrive, spec: MachineSpec) -> list[str]:
    mv, p, s, lu = d.moving, d.pulse, d.stop, d.lumped
    a_end = p.specific_force * chambered_pressure_ratio(p.port_speed, d.sound_speed, GASES[d.gas].gamma)
    out = [f"{d.gas} at {d.pressure / PSI:,.0f} psi: the acceleration {p.peak / G0:,.0f} g after the valve's ramp, "
           f"{a_end / G0:,.0f} g as the ports open ({a_end / spec.pulse.peak:.3g} of the peak), "
           f"{p.fall.acceleration[-1] / G0:,.0f} g ({p.fall.end_ratio:.3g} p0) as the arrest separates the "
           f"carriage and article {(p.separation_time - p.port_time) * 1e3:.3g} ms later; at the bracket's lower end the pulse "
           + _band_words(d.band)[10:],
           f"piston {mv.material} {mv.piston_thickness * 1e3:.0f} mm x {mv.bore / IN:.3g} in "
           f"({mv.piston_mass:.3g} kg), carriage {mv.carriage_mass:.3g} kg: {mv.total:.4g} kg driven over "
           f"{p.stroke:.3g} m to the ports and "
           f"{p.fall_travel:.3g} m past them, to {p.end_speed:.4g} m/s",
           f"tank {d.gun.reservoir_volume:.3g} m^3 ({CHAMBER_HOLD:.0%} fall at most); the carriage and article caught "
           f"at {s.deceleration / spec.pulse.peak:.0%} of the peak after {d.free_run:.3g} m of free run by a {s.kind} "
           f"({s.stroke:.3g} m of stroke, {s.length:.3g} m long, {s.absorber_mass:,.0f} kg)",
           f"the lumped gun on the same cylinder and tank (finite tank, valve flow, Lagrange gas, air ahead) to the "
           f"ports, then the same ported fall to the arrest: {lu['end_speed']:.4g} m/s ({lu['speed_error']:+.2%} of "
           f"the chambered law's), peak {lu['peak'] / G0:,.0f} g ({lu['peak_error']:+.2%}); {_band_words(lu['band'])}",
           f"machine {d.machine_mass:,.0f} kg: tank {d.launcher.design.tank_weight:,.0f}, cylinder "
           f"{d.cylinder_mass:,.0f}, moving {mv.total:.3g}, arrest {d.arrest.absorber_mass:,.0f}, catch "
           f"{s.absorber_mass:,.0f}, frame {d.frame_mass:,.0f}; length {d.machine_length:.3g} m: tank "
           f"{d.tank_length:.3g}, cylinder {d.cylinder_length:.3g}, free run {d.free_run:.3g}, catch {s.length:.3g}",
           "valve opening against the band at the bracket's lower / upper end (same k, ports and arrest): "
           + "; ".join(f"{o['opening'] * 1e3:g} ms: {o['speed_error']:+.1%} in speed, {_ends_words(o)}"
                       for o in d.openings),
           "the charge below its p0 (k in proportion, same machine), lower / upper end: " + "; ".join(
               f"{c['share']:.0%}: {_ends_words(c)}" for c in d.charges),
           "the arrest moved so that the lower end separates earlier (same k and ports), lower / upper end: "
           + "; ".join(f"{c['separation'] * 1e3:.3g} ms: {c['speed_error']:+.1%} in speed, upper end "
                       f"{c['upper_ratio']:.3g} p0 at it, {_ends_words(c)}" + _margin_words(c) for c in d.separations)]
    out[2:2] = _end_notes(d)
    out += [f"limit broken: {lim.describe()}" for lim in broken(d.limits)]
    return out


def _margin_words(c: dict) -> str:
    """The longest opening and the lowest charge checked at which both ends are in the band."""
    if not c["opening"]:
        return ""
    charge = "" if math.isnan(c["charge"]) else f", charged down to {c['charge']:.0%} of p0"
    return f" (both in with the valve opening in up to {c['opening'] * 1e3:g} ms{charge})"


def _ends_words(c: dict) -> str:
    def one(b):
        return "in" if b.passed else f"OUTSIDE ({b.worst_excess:.3g})"
    return f"{one(c['band'])} / {one(c['upper_band'])}"


def _end_notes(d: GasDrive) -> list[str]:
    """The ports, the arrest and the gas a shot vents, in words."""
    mv, band, a, r = d.moving, d.port_band, d.arrest, d.recovery
    low, high = E.DISCHARGE_RANGE
    air, step = d.air_ahead, d.step
    return [f"ports: {band.share:.0%} of a {band.length:.3g} m band open ({band.area:.3g} m^2, "
            f"{band.area / (math.pi * mv.bore ** 2 / 4):.3g} bores), holes {band.hole * 1e3:.0f} mm at a "
            f"{band.pitch * 1e3:.0f} mm pitch (ligament efficiency {band.efficiency:.2f}) in a "
            f"{band.thickness * 1e3:.0f} mm wall ({band.mass:+.3g} kg on the plain wall)",
            f"the piston's arrest against the gas's push (at most p0 A = {d.push / 1e6:.3g} MN, held at rest): a "
            f"{a.kind}, {a.force / 1e6:.3g} MN over {a.stroke:.3g} m ({a.deceleration / G0:,.0f} g), "
            f"{a.force / d.arrest_limit:.3g} of the most the piston puts on it ({d.arrest_limit / 1e6:.3g} MN); "
            f"no honeycomb grade's static crush force on the annulus ({_strongest_honeycomb(d) / 1e6:.3g} MN at "
            "most) holds the push; "
            f"at the piston's most force the stroke would be {_pushed_stroke(d, d.arrest_limit):.3g} m",
            f"the vessel at the arrest's impact takes {d.arrest_reaction / 1e6:.3g} MN forward (the arrest's force "
            f"less the gas's at the separation); the held piston's port jets, if they keep the column's axial "
            f"speed, thrust it {d.jet_thrust / 1e6:.3g} MN; the frame carries the largest of these, p0 A and "
            "the catch",
            "the gas a shot vents with the valve closing from the separation (the tank and the cylinder emptying "
            "through the ports, the piston held): " + "; ".join(_closing_words(c, d.gas) for c in d.closings),
            f"the air ahead, left out (a bound): the piston's shock {air['incident'] / 1e6:.3g} MPa, reflected off "
            f"the arrest {air['reflected'] / 1e6:.3g} MPa, {air['acceleration']:.3g} of the peak against the thrust "
            f"in the fall and {air['speed_share']:.2%} of the velocity change",
            f"the separation is a step, not a fall: {step['low']:.3g} to {step['high']:.3g} of the peak dropped "
            f"within the arrest's rise; it releases the seat's {step['stress'] / 1e6:.3g} MPa, a particle speed of "
            f"{step['particle_speed']:.3g} m/s, so the carriage and article (joined in compression only) may part "
            "and ring at their own modes after D, which the band's rigid-body record does not show",
            f"the face's bracket (holes' discharge coefficient {low:g} to {high:g}, the port gas keeping the "
            f"column's speed to leaving radially): {d.pulse.fall.end_ratio:.3g} to {r['end_ratio']:.3g} p0 at the "
            f"separation, the lower end {_band_words(d.band)[4:]}, the upper ({r['speed_error']:+.2%} in speed) "
            f"{_band_words(r['band'])[4:]}; radial jets from ideal holes alone: {r['radial']['end_ratio']:.3g} p0, "
            f"{_band_words(r['radial']['band'])[4:]}; the ports' share {band.share:g}: the largest of "
            f"{', '.join(f'{x:g}' for x in E.PORT_SHARES)} whose end holds its range",
            _column_words(d)]


def _column_upper(d: GasDrive):
    """(Cd, BandCheck) of the column's case the bracket's upper end stands for (the least flow, radial jets)."""
    cd = E.DISCHARGE_RANGE[0]
    return (cd, d.column_bands[cd, RADIAL]) if d.column_bands else None


def _column_words(d: GasDrive) -> str:
    """The bracket's check on the quasi-1D column (``drive_end.column_bracket``, ``column_bands``), in words."""
    cases = "; ".join(f"Cd {cd:g} {'radial' if jets == RADIAL else 'axial'}: {f.end_ratio:.3g} p0, "
                      f"{_band_words(d.column_bands[cd, jets])[4:]}" for (cd, jets), f in d.column["column"].items())
    lower, upper = d.column["law"]
    return (f"the bracket checked on the quasi-1D gas column ({E.COLUMN_CELLS} cells, the ports a bleed over the "
            f"band, fluid.gas_column) at the separation against the law's {lower:.3g} to {upper:.3g} p0: {cases}")


def air_ahead_bound(d: GasDrive) -> dict:
    """The air ahead of the piston in the bore the arrest's head closes (left out of the chambered law): the
    shock the piston drives at its speed at the separation (``launcher.gun.air_ahead_pressure``) over the whole
    stroke, and that shock reflected whole off the arrest's face (``drive_end.reflected_shock_pressure``) over
    the fall; a bound (the real shock is weaker earlier, and the carriage's passage and the cells relieve the
    reflection): its acceleration over the peak during the fall, and the velocity change it takes."""
    p, mv = d.pulse, d.moving
    area, ambient = math.pi * mv.bore ** 2 / 4, d.gun.ambient_pressure
    p2 = air_ahead_pressure(d.gun, p.end_speed)
    p5 = E.reflected_shock_pressure(p2, ambient, GASES["air"].gamma)
    taken = ((p2 - ambient) * p.port_time + (p5 - ambient) * (p.separation_time - p.port_time)) * area / mv.total
    return {"incident": p2, "reflected": p5, "acceleration": (p5 - ambient) * area / mv.total / d.pulse.peak,
            "speed_share": taken / d.velocity_change}


def separation_step(d: GasDrive, spec: MachineSpec) -> dict:
    """The separation as a step: the acceleration it drops (over the peak) at both ends of the bracket, and the
    seat's compression it releases, sigma = (article + carriage) a / A_seat at the lower end, as a particle speed
    sigma / (rho c) in the carriage's steel (the speed at which the carriage and article may part)."""
    rho = property_si(spec.material, "density", "density")
    c = math.sqrt(property_si(spec.material, "youngs_modulus", "pressure") / rho)
    low = d.pulse.fall.acceleration[-1]
    high = low * d.recovery["end_ratio"] / d.pulse.fall.end_ratio
    sigma = d.seat_stress * low / d.pulse.peak
    return {"low": low / spec.pulse.peak, "high": high / spec.pulse.peak, "stress": sigma,
            "particle_speed": sigma / (rho * c)}


def _strongest_honeycomb(d: GasDrive) -> float:
    """The static crush force [N] of the strongest honeycomb grade on the piston's arrest annulus."""
    annulus = ring_area(d.moving.bore, 2 * d.moving.bearing_radius + RING_CLEARANCE)
    return max(sigma for _, sigma in HONEYCOMB.values()) * annulus


def _pushed_stroke(d: GasDrive, force: float) -> float:
    """The piston's arrest stroke at a constant ``force`` against the push (``stops``: m v^2 / (2 (F - F_p)))."""
    return 0.5 * d.moving.piston_mass * d.pulse.end_speed ** 2 / (force - d.push) if force > d.push else math.inf


def _closing_words(c: dict, gas: str) -> str:
    when = "left open" if not math.isfinite(c["closing"]) else f"{c['closing'] * 1e3:g} ms"
    return (f"{when}: {c['vented']:.3g} kg of {gas} (the cylinder above twice the ambient for "
            f"{c['push_time'] * 1e3:,.0f} ms, the arrest holding the piston that long)")


def arrangement(d: GasDrive) -> Arrangement:
    """(d) as a row of the premise's table (its moving mass in the 'launched' column, no striker)."""
    nan = math.nan
    name = f"(d) gas drive, {d.gas}"
    if d.moving is None:
        return Arrangement(name, nan, nan, nan, nan, nan, nan, nan, d.pressure, nan, nan, nan, nan, nan, False,
                           list(d.notes), feasible=False)
    L, p = d.launcher, d.pulse
    return Arrangement(name, d.moving.total, p.end_speed, 0.5 * d.moving.total * p.end_speed ** 2, 0.0, nan,
                       d.gun.bore, p.stroke, d.pressure, d.gun.reservoir_volume, L.stored_energy, L.design.weight,
                       d.machine_mass, d.machine_length, True, list(d.notes), feasible=d.feasible,
                       required_energy=0.5 * d.moving.total * d.velocity_change ** 2, tank_mass=L.design.tank_weight,
                       limits=list(d.limits))


def gas_drives(spec: MachineSpec, fixture) -> list[GasDrive]:
    """(d) in air and in helium for the fixture's article (its mass, diameter and length)."""
    return [design_gas_drive(spec, gas, fixture.article_mass, fixture.article_diameter, fixture.article_length)
            for gas in GASES_TRIED]


def _candidate_words(d: GasDrive) -> str:
    t = longest_opening_in_band(d)
    shut = {c["closing"]: c for c in d.closings}
    open_ = shut[math.inf]
    quick = min((c for c in d.closings if math.isfinite(c["closing"])), key=lambda c: c["closing"])
    lumped = "in" if d.lumped["band"].passed else f"OUTSIDE (worst excess {d.lumped['band'].worst_excess:.3g})"
    return (f"a CANDIDATE, not a designed machine: within the limits checked, its thrust ended by vent ports and "
            f"the piston's arrest (computed: {d.pulse.fall.end_ratio:.3g} to {d.recovery['end_ratio']:.3g} p0 left, "
            "the face pressure's bracket, when the carriage and article separate, the pulse in the band at both "
            f"ends; the arrest a {d.arrest.kind} against the gas's push), and "
            f"its pulse in the band only if its valve opens full-bore in {t * 1e3:g} ms or less "
            f"(assumed; no valve sourced; the lumped gun's slower shot to the same arrest is {lumped} the band), "
            f"and the losses the model leaves out (the valve's loss, the seal's friction) stay within a few per "
            f"cent of the velocity change; with the valve left open a shot vents {open_['vented']:.3g} kg of "
            f"{d.gas} ({d.vented_volume:,.0f} m^3 at standard conditions) through the ports; a supply valve closing "
            f"in {quick['closing'] * 1e3:g} ms after "
            f"the separation would vent {quick['vented']:.3g} kg (assumed, no such valve sourced either); its mass "
            "and length leave out the valve and the gas's handling; and it gives an axial pulse only (it is the "
            "white paper's closed-muzzle gun)")


def _what_would_bring_it_in(d: GasDrive) -> str:
    """The changes the numbers say would bring (d) in: the arrest's force and stroke against the push, and the
    earliest separation checked at which both ends of the bracket are in the band."""
    held = [c for c in d.separations if _in_both(c)]
    moved = max(held, key=lambda c: (c["opening"], -c["charge"], c["separation"]), default=None)
    band = ("" if moved is None else f"; an arrest placed so that the carriage and article separate at "
            f"{moved['separation'] * 1e3:.3g} ms ({moved['speed_error']:+.1%} in speed) puts both ends of the "
            "bracket in the band" + _margin_words(moved))
    return (f"it would need a piston arrest that takes {d.pulse.end_speed:.0f} m/s against the push p0 A = "
            f"{d.push / 1e6:.3g} MN and holds it at rest (at the {d.arrest_limit / 1e6:.3g} MN the piston carries, "
            f"{_pushed_stroke(d, d.arrest_limit):.3g} m of stroke), which no absorber here does within its own limits{band}")


def verdict_words(drives: list[GasDrive], a: Arrangement, b: Arrangement) -> str:
    """(d)'s line in the premise's verdict, from its numbers."""
    parts = []
    for d in drives:
        if d.moving is None:
            parts.append(f"(d) in {d.gas} has no design: {d.notes[0]}")
            continue
        why = [f"{lim.component} {lim.quantity} {lim.ratio:.3g} times its limit" for lim in broken(d.limits)]
        if d.recovery and not d.recovery["band"].passed:
            why.insert(0, f"at the face pressure's upper end ({d.recovery['end_ratio']:.3g} p0 when the carriage "
                          f"and article separate) its pulse is outside the band (worst excess "
                          f"{d.recovery['band'].worst_excess:.3g} of the peak)")
            column = _column_upper(d)
            if column is not None:
                why.insert(1, f"the quasi-1D gas column's fall at the same end (holes' Cd {column[0]:g}, radial jets) "
                              f"is {'in' if column[1].passed else 'outside'} the band too (worst excess "
                              f"{column[1].worst_excess:.3g})")
        if not d.in_band:
            why.insert(0, f"its pulse is outside the band (worst excess {d.band.worst_excess:.3g} of the peak)")
        if d.moving is not None and not d.feasible:
            if d.lumped and not d.lumped["band"].passed:
                why.append(f"the lumped gun's shot to the same arrest is outside the band too (worst excess "
                           f"{d.lumped['band'].worst_excess:.3g})")
            why.append(_what_would_bring_it_in(d))
        parts.append(f"(d), the closed-breech gas drive in {d.gas} ({d.moving.total:.3g} kg driven over "
                     f"{d.pulse.stroke:.3g} m from a {d.gun.bore / IN:.3g} in bore at {d.pressure / PSI:,.0f} psi; "
                     f"{d.machine_mass / 1e3:.3g} t, {d.machine_length:.3g} m long), is "
                     + (_candidate_words(d) if d.feasible else "NOT feasible: " + "; ".join(why)))
    ok = [d for d in drives if d.feasible]
    # (a) and (b) carry the same fixture: a machine only where it, too, holds its limits
    fixture = not a.fixture_problems
    a_ok, b_ok = a.gun_feasible and a.feasible and fixture, b.gun_feasible and b.feasible and fixture
    if not ok:
        return "; ".join(parts)
    best = min(ok, key=lambda d: d.machine_mass)
    if not (a_ok or b_ok):
        why = "their common fixture breaks its own limits" if not fixture else "neither is within its limits"
        parts.append(f"so the gas drive in {best.gas} is the candidate to check where neither the amplifier nor the "
                     f"direct gun is a machine ({why}): on these numbers velocity amplification is not the answer, "
                     "and the gas drive is one only once its valve is sourced")
    else:
        other = b if b_ok else a
        parts.append(f"the gas drive in {best.gas} weighs {best.machine_mass / 1e3:.3g} t and is "
                     f"{best.machine_length:.3g} m long against {other.name}'s {other.machine_mass / 1e3:.3g} t and "
                     f"{other.machine_length:.3g} m")
    return "; ".join(parts)

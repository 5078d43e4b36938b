"""Verification of the shock metrics (``shockfem/metrics``).

* CFC filters against SAE J211-1: -3 dB at 1.65 CFC and a flat pass band (within 0.5 dB),
  measured by filtering sinusoids through the implemented code path.
* SRS: with damping taken to zero a half-sine of duration D gives the exact shock-spectrum
  peak 1.7685 at D / period = 0.8098 (``shared/references``); at Q = 10 the recursive filter
  matches a direct high-accuracy integration of the oscillator (scipy DOP853, rtol 1e-10).
* Pulse metrics on sampled analytic pulses: peak, 10% duration and velocity change exact to
  sampling, the shape recognised, the ideal pulse inside its own band and a ringing one not.
* The rod impact of the contact verification, run through ``shockfem run`` with the struck rod
  a test article: the stage table, pulse and restitution against 1D wave theory.
"""
from __future__ import annotations

import math
import time

import numpy as np

from ..metrics import filters, shapes
from ..metrics.pulse import pulse_metrics
from ..metrics.srs import shock_response_spectrum
from ..scene.specs import CFC_CLASSES
from .checks import SIZES, check
from .scenes import STEEL, steel_c0

# Exact undamped half-sine shock spectrum maximum and where it lies (shared/references/README.md).
HALF_SINE_PEAK, HALF_SINE_RATIO = 1.7685, 0.8098


def cfc_filter(size, workdir):
    """CFC 60/180/600/1000 gain: -3 dB at 1.65 CFC and within 0.5 dB over 0.1-1 CFC (SAE J211)."""
    out = []
    dt = 1e-5       # a 100 kHz channel, 10x the J211 minimum for CFC 1000
    for cfc in CFC_CLASSES:
        t0 = time.perf_counter()
        g3 = filters.gain_db(cfc, dt, 1.65 * cfc)
        band = [filters.gain_db(cfc, dt, f * cfc) for f in (0.1, 0.25, 0.5, 0.75, 1.0)]
        wall = time.perf_counter() - t0
        # J211-1: the -3 dB point of the class (1.65 CFC); the acceptance tolerance 0.5 dB
        out.append(check(f"cfc_filter.CFC{cfc}.gain_at_1.65CFC [dB, abs]", -3.0, g3, 0.5, wall, 0, absolute=True))
        worst = max(band, key=abs)
        out.append(check(f"cfc_filter.CFC{cfc}.passband_0.1-1CFC [dB, abs]", 0.0, worst, 0.5, wall, 0,
                         absolute=True))
    return out


def _half_sine(duration, samples):
    """A half-sine of unit peak sampled ``samples`` times over its duration, then 20% of zeros
    (so that the record, not the padding, says how a pulse ends)."""
    dt = duration / samples
    t = np.arange(int(1.2 * samples) + 1) * dt
    return t, np.where(t <= duration, np.sin(np.pi * np.minimum(t, duration) / duration), 0.0), dt


def _direct_srs(t, a, frequency, q):
    """Peak |absolute acceleration| of the oscillator by direct integration of
    z'' + 2 zeta wn z' + wn^2 z = -a(t) (a linear between samples), over the record and one
    natural period after it; absolute acceleration = -(2 zeta wn z' + wn^2 z)."""
    from scipy.integrate import solve_ivp
    wn = 2 * math.pi * frequency
    zeta = 0.0 if math.isinf(q) else 1 / (2 * q)
    t_end = t[-1] + 1.0 / frequency

    def rhs(s, y):
        base = np.interp(s, t, a, right=0.0)
        return [y[1], -base - 2 * zeta * wn * y[1] - wn * wn * y[0]]

    # the base acceleration has kinks at every sample: integrate sample to sample
    knots = np.concatenate([t, [t_end]])
    y0 = [0.0, 0.0]
    peak = 0.0
    for s0, s1 in zip(knots[:-1], knots[1:]):
        sol = solve_ivp(rhs, (s0, s1), y0, method="DOP853", rtol=1e-10, atol=1e-14, dense_output=True)
        ss = np.linspace(s0, s1, 41)
        z, zd = sol.sol(ss)
        peak = max(peak, float(np.abs(2 * zeta * wn * zd + wn * wn * z).max()))
        y0 = sol.y[:, -1]
    return peak


def srs_half_sine(size, workdir):
    """SRS of a half-sine: undamped peak 1.7685 at D/T = 0.8098 (exact); Q = 10 against direct integration."""
    D = 1e-3
    t, a, dt = _half_sine(D, 200)
    t0 = time.perf_counter()
    ratios = np.linspace(0.78, 0.84, 601)
    s = shock_response_spectrum(a, dt, ratios / D, q=math.inf)
    i = int(np.argmax(s.maximax))
    wall = time.perf_counter() - t0
    out = [check("srs_half_sine.undamped_peak [-]", HALF_SINE_PEAK, s.maximax[i], 0.01, wall, 0),
           check("srs_half_sine.undamped_peak_at_D/T [-]", HALF_SINE_RATIO, ratios[i], 0.01, wall, 0)]
    # Q = 10 against the direct integration: below, at and above the pulse's own frequency,
    # for a half-sine and a terminal-peak sawtooth
    saw = np.where(t <= D * (1 + 1e-9), t / D, 0.0)
    for name, pulse in (("half_sine", a), ("sawtooth", saw)):
        worst = 0.0
        t0 = time.perf_counter()
        for f in (0.1 / D, 0.5 / D, 1.0 / D, 3.0 / D, 10.0 / D):
            recursive = float(shock_response_spectrum(pulse, dt, [f], 10.0).maximax[0])
            worst = max(worst, abs(recursive / _direct_srs(t, pulse, f, 10.0) - 1))
        out.append(check(f"srs_half_sine.Q10_{name}_vs_direct [-, max rel]", 0.0, worst, 0.005,
                         time.perf_counter() - t0, 0, absolute=True))
    return out


def pulse_shapes(size, workdir):
    """Metrics of sampled analytic pulses exact to sampling; shape recognised; band check."""
    P, D, t_start = 1e5, 5e-3, 1e-3
    dt = D / 1000
    t = np.arange(-2e-3, 16e-3, dt)
    ramp = 0.1 * D
    cases = {
        # shape: (ideal, duration above 10% of peak)
        "half-sine": (shapes.IdealPulse("half-sine", P, D, t_start), D * (1 - 2 * math.asin(0.1) / math.pi)),
        "terminal-peak sawtooth": (shapes.IdealPulse("terminal-peak sawtooth", P, D, t_start), 0.9 * D),
        "trapezoid": (shapes.IdealPulse("trapezoid", P, D, t_start, ramp, ramp), D - 0.2 * ramp),
    }
    out = []
    for shape, (ideal, duration) in cases.items():
        t0 = time.perf_counter()
        a = -ideal(t)                        # a deceleration: polarity must not matter
        p = pulse_metrics(t, a)
        cls = shapes.classify(t, a, p)
        band = shapes.band_check(t, -a, ideal)
        ringing = a * (1 + 0.3 * np.sin(2 * np.pi * 2.0 / D * t))
        rp = pulse_metrics(t, ringing)
        ring_band = shapes.band_check(t, -ringing, shapes.place(ideal, t, -ringing, rp))
        wall = time.perf_counter() - t0
        key = shape.replace(" ", "_").replace("-", "_")
        # exact to sampling: the peak of a half-sine between samples is low by at most
        # (pi dt / D)^2 / 8; crossings and a sawtooth's drop are placed within one sample interval
        out += [check(f"pulse_shapes.{key}.peak [m/s^2]", P, p.peak, (np.pi * dt / D) ** 2 / 8, wall, 0),
                check(f"pulse_shapes.{key}.duration_10pct [s]", duration, p.duration, dt / duration, wall, 0),
                check(f"pulse_shapes.{key}.velocity_change [m/s]", -ideal.velocity_change, p.velocity_change,
                      P * dt / ideal.velocity_change, wall, 0),
                check(f"pulse_shapes.{key}.recognised [1 = yes]", 1.0, float(cls.shape == shape), 0.0, wall, 0),
                check(f"pulse_shapes.{key}.inside_own_band [1 = yes]", 1.0, float(band.passed), 0.0, wall, 0),
                check(f"pulse_shapes.{key}.30pct_ringing_fails [1 = yes]", 1.0, float(not ring_band.passed), 0.0,
                      wall, 0)]
        out[-3]["note"] = "misfits: " + ", ".join(f"{k} {v:.3f}" for k, v in cls.misfits.items())
    return out


RADIUS, LENGTH, SPEED, GAP = 0.0025, 0.1, 1.0, 1e-5


def rod_impact_metrics(size, workdir):
    """Rod on rod through `shockfem run`: stage table, restitution and the struck rod's pulse vs 1D theory."""
    from ..runner import run_scene
    from ..scene import resolve
    c0 = steel_c0()
    h = 0.00025 * SIZES[size]          # as rod_on_rod
    t_contact = 2 * LENGTH / c0
    t_touch = GAP / SPEED
    end = t_touch + 1.6 * t_contact
    rod = {"material": "steel", "shape": "cylinder", "radius": RADIUS, "length": LENGTH, "element_size": h}
    raw = {"scene": {"name": "rod_impact_metrics", "kinematics": "axisymmetric", "end_time": end},
           "materials": {"steel": dict(STEEL)},
           "bodies": [{"name": "striker", **rod, "position": [0.0, LENGTH + GAP], "velocity": [0.0, -SPEED]},
                      {"name": "target", **rod, "position": [0.0, 0.0]}],
           "contact": [{"name": "impact", "a": "striker.bottom", "b": "target.top"}],
           "outputs": {"field_interval": end, "history_interval": t_contact / 400},
           "shock": {"test_articles": ["target"], "cfc": "none", "srs_frequencies": ["1 kHz", "100 kHz"]}}
    result = run_scene(resolve(raw), workdir, progress=False, write_fields=False, quiet=True)
    shock = result.summary["shock"]
    wall, n = result.summary["wall_time_s"], result.summary["elements"]
    stage = shock["stages"][0]
    m = shock["channels"]["target"]
    p, fitted = m["pulse"], m["shape"]["fitted"]
    pair = result.solver.contacts[0]
    # 1D theory for equal rods: a square pulse c0 v / (2 L) for 2 L / c0, velocities exchanged, e = 1
    plateau = c0 * SPEED / (2 * LENGTH)
    out = [
        check("rod_impact_metrics.stages [count]", 1, len(shock["stages"]), 0.0, wall, n, absolute=True),
        # the rods' lateral inertia and the penalty interface (rod_on_rod: 2%)
        check("rod_impact_metrics.restitution [-]", 1.0, stage["restitution"], 0.02, wall, n),
        # the stage table and the contact pair measure the same velocities
        check("rod_impact_metrics.restitution_vs_contact_pair [-]", pair.restitution(), stage["restitution"],
              1e-3, wall, n),
        check("rod_impact_metrics.struck_velocity [m/s]", -SPEED, stage["struck_after"], 0.02, wall, n),
        check("rod_impact_metrics.velocity_ratio [-]", 1.0, stage["velocity_ratio"], 0.02, wall, n),
        check("rod_impact_metrics.shape_trapezoid [1 = yes]", 1.0, float(m["shape"]["classified"] == "trapezoid"),
              0.0, wall, n),
        # fitted level and foot-to-foot duration: within the 3% of rod_on_rod's plateau force
        check("rod_impact_metrics.fitted_plateau [m/s^2]", plateau, fitted["peak"], 0.03, wall, n),
        check("rod_impact_metrics.fitted_duration [s]", t_contact, fitted["duration"], 0.03, wall, n),
        check("rod_impact_metrics.pulse_velocity_change [m/s]", SPEED, abs(p["velocity_change"]), 0.02, wall, n),
        # the interval-mean acceleration integrates to the rigid-body velocity change exactly
        check("rod_impact_metrics.record_vs_rigid_dV [-, abs]", 0.0, m["velocity_change_mismatch"], 1e-9, wall, n,
              absolute=True),
    ]
    out[5]["note"] = "misfits: " + ", ".join(f"{k} {v:.3f}" for k, v in m["shape"]["misfits"].items())
    return out

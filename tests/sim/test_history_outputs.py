"""History columns an LS-DYNA user reaches for: the supports' reactions, each body's energies, and
accelerometers' displacement and acceleration beside their velocity.

- ``bar_impact``: the bar's end driven at 5 m/s with mass-proportional damping (alpha = 2 zeta omega =
  2161 1/s). Newton for the whole bar: d(p)/dt = R - alpha p, so the drive's impulse less the damping's
  is the bar's momentum change (measured within 1% over 150 us, trapezoid on 0.5 us samples; the test
  allows 2%), and while the front runs up the bar the drive pushes with rho c0 v A plus the damping of
  the moving part (the mean over 10-50 us measured -2.8%, the samples swinging 4.5% about it with the
  end's radial inertia; the test allows 5% on the mean).
- The bodies' energy columns end at the summary's per-body values and sum to the run's kinetic energy.
- A rigid punch driven down by a velocity ramp onto a rod: the drive's reaction is its own column
  (``reaction.punch_z``), the punch's velocity is the drive's at every sample, Newton for the punch
  (R + the contact's push = M a) holds at every sample to round-off, and the reported reaction times the
  speed, integrated, is the run's external work (trapezoid on every step: measured 0.05%, allowed 1%).
- ``rod_pulse``'s accelerometer: its displacement is the integral of its velocity and its velocity the
  integral of its acceleration (trapezoid over every step; measured 3e-5 and 0.19% of the largest
  value; the test allows 2%).
"""
import os

import numpy as np
import pytest

import shockfem

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
RHO, E, V, RADIUS = 7850.0, 210e9, 5.0, 0.010
ALPHA = 2 * 0.02 * 2 * np.pi * 8600.0          # the scene's mass damping: 2 zeta omega, ratio 0.02 at 8.6 kHz


def _integral(f, t):
    return np.concatenate([[0.0], np.cumsum(0.5 * (f[1:] + f[:-1]) * np.diff(t))])


def test_drive_reaction_is_newton_for_the_bar(tmp_path):
    scene = shockfem.load_scene(os.path.join(REPO, "studies", "foundation", "bar_impact.toml"))
    result = shockfem.run(scene, str(tmp_path / "bar"), fields=False)
    h, s = result.history, result.summary
    t, drive = h["time"], h["reaction.bar.bottom_z"]
    assert not any(k.startswith("reaction.axis") for k in h)
    p = s["bodies"]["bar"]["mass"] * h["bar.v_z"]
    impulse = _integral(drive - ALPHA * p, t)
    assert np.allclose(impulse[1:], (p - p[0])[1:], rtol=0.02, atol=0.02 * np.abs(p).max())
    running = (t > 10e-6) & (t < 50e-6)
    moving_mass = RHO * np.pi * RADIUS ** 2 * np.sqrt(E / RHO) * t[running]
    expected = RHO * np.sqrt(E / RHO) * V * np.pi * RADIUS ** 2 + ALPHA * moving_mass * V
    assert drive[running].mean() == pytest.approx(expected.mean(), rel=0.05)
    # the bar's energy columns: its own at the end, the run's kinetic energy
    assert h["bar.energy_kinetic"][-1] == pytest.approx(s["bodies"]["bar"]["kinetic_energy"], rel=1e-12)
    assert h["bar.energy_internal"][-1] == pytest.approx(s["bodies"]["bar"]["internal_energy"], rel=1e-12)
    assert np.allclose(h["bar.energy_kinetic"], h["energy.kinetic"], rtol=1e-10, atol=1e-12)


def test_accelerometer_displacement_velocity_acceleration(tmp_path):
    scene = shockfem.load_scene(os.path.join(REPO, "studies", "metrics", "rod_pulse.toml"),
                                ['scene.end_time="60 us"'])
    h = shockfem.run(scene, str(tmp_path / "rod"), fields=False).history
    t = h["time"]
    u, v, a = (h[f"accelerometer.far_end.{q}_z"] for q in "uva")
    assert np.abs(v).max() > 1.0
    assert np.abs(_integral(v, t) - (u - u[0])).max() < 0.02 * np.abs(u).max()
    assert np.abs(_integral(a, t) - (v - v[0])).max() < 0.02 * np.abs(v).max()


def test_driven_rigid_body_reports_its_drive(tmp_path):
    T, ramp, v = 6e-6, 1e-6, -1.0
    raw = {"scene": {"name": "punch", "kinematics": "axisymmetric", "end_time": T},
           "materials": {"steel": {"density": RHO, "youngs_modulus": E, "poisson_ratio": 0.3}},
           "bodies": [{"name": "rod", "material": "steel", "shape": "cylinder", "radius": 0.0025, "length": 0.04,
                       "element_size": 0.0005},
                      {"name": "punch", "material": "steel", "shape": "cylinder", "radius": 0.0025, "length": 0.005,
                       "element_size": 0.0005, "position": [0.0, 0.04], "rigid": True}],
           "boundary": [{"region": "punch", "type": "velocity", "direction": "z",
                         "history": [[0.0, 0.0], [ramp, v], [T, v]]}],
           "contact": [{"name": "face", "a": "punch.bottom", "b": "rod.top"}],
           "outputs": {"field_interval": T}}
    result = shockfem.run(shockfem.load_scene(raw), str(tmp_path / "punch"), fields=False)
    h, s = result.history, result.summary
    t, drive, push = h["time"], h["reaction.punch_z"], h["contact.face.normal_z"]
    assert not any(k.startswith("reaction.punch_r") for k in h)
    assert np.allclose(h["punch.v_z"], np.interp(t, [0.0, ramp, T], [0.0, v, v]), rtol=0, atol=1e-12)
    mass = s["bodies"]["punch"]["mass"]
    assert np.allclose(drive + push, mass * h["punch.a_z"], rtol=0, atol=1e-9 * np.abs(drive).max())
    assert np.abs(push).max() > 0.5 * RHO * np.sqrt(E / RHO) * abs(v) * np.pi * 0.0025 ** 2
    work = _integral(drive * h["punch.v_z"], t)[-1]
    assert work == pytest.approx(h["energy.external"][-1], rel=0.01)
    assert h["energy.balance_error"][-1] < 0.01


def test_fixed_rigid_body_stays_put(tmp_path):
    """A rigid plate held with ``type = "fixed"`` struck off its centre (a torque on it): it neither moves nor
    turns (to round-off), its support reports a force along every axis, and the energy still balances (the
    hold does no work on a body at rest: the balance within the penalty contact's 1%)."""
    T = 20e-6
    raw = {"scene": {"name": "anvil", "kinematics": "3d", "end_time": T},
           "materials": {"steel": {"density": RHO, "youngs_modulus": E, "poisson_ratio": 0.3}},
           "bodies": [{"name": "plate", "material": "steel", "shape": "box", "size": [0.04, 0.04, 0.01],
                       "element_size": 0.01, "position": [-0.02, -0.02, -0.01], "rigid": True},
                      {"name": "slug", "material": "steel", "shape": "cylinder", "radius": 0.005, "length": 0.02,
                       "element_size": 0.0025, "position": [0.012, 0.0, 1e-5], "velocity": [0.0, 0.0, -5.0]}],
           "boundary": [{"region": "plate", "type": "fixed"}],
           "contact": [{"name": "face", "a": "slug.bottom", "b": "plate.top"}],
           "outputs": {"field_interval": T}}
    result = shockfem.run(shockfem.load_scene(raw), str(tmp_path / "anvil"), fields=False)
    h = result.history
    assert all(f"reaction.plate_{a}" in h for a in "xyz")
    assert np.abs(h["contact.face.normal_z"]).max() > 1e3                  # the slug struck it
    # the support pushes the plate back with what the plate pushes the slug with (the force on surface a)
    assert np.allclose(h["reaction.plate_z"], h["contact.face.normal_z"], rtol=0, atol=1e-6)
    for a in "xyz":
        assert np.abs(h[f"plate.v_{a}"]).max() == 0.0
    assert h["plate.energy_kinetic"].max() == 0.0                       # nor turns    assert h["energy.balance_error"][-1] < 0.01

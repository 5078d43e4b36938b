"""The gas-gun model against closed forms, and the ASME wall formulas by hand."""
import math
import os
import subprocess
import sys

import pytest

from shockfem.launcher import vessel
from shockfem.launcher.gas import GASES, orifice_flow
from shockfem.launcher.gun import Gun, fire

from shockfem.units import FT, PSI, IN as INCH   # checked against pint in test_units.py
BORE, LENGTH, P0 = 12 * INCH, 6 * FT, 2000 * PSI
AREA = math.pi * BORE ** 2 / 4
REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def test_constant_pressure_and_adiabatic_limits():
    m = 100.0
    s = fire(Gun(1e6 * AREA * LENGTH, P0, BORE, LENGTH, m, air_ahead="evacuated", gas_inertia="none"))
    assert s.muzzle_velocity == pytest.approx(math.sqrt(2 * P0 * AREA * LENGTH / m), rel=2e-6)
    V0 = 0.05
    s = fire(Gun(V0, P0, BORE, LENGTH, m, air_ahead="evacuated", gas_inertia="none"))
    V = V0 + AREA * LENGTH
    assert s.muzzle_velocity == pytest.approx(math.sqrt(2 * P0 * V0 / (0.4 * m) * (1 - (V0 / V) ** 0.4)), rel=1e-7)


def test_full_model_conserves_energy_and_each_loss_costs_speed():
    base = dict(reservoir_volume=0.5, reservoir_pressure=P0, bore=BORE, length=LENGTH, projectile_mass=944.3,
                valve_area=0.05, opening_time=2e-3, air_ahead="evacuated", gas_inertia="none")
    v = {}
    for name, extra in (("ideal", {}), ("air", {"air_ahead": "atmosphere"}), ("lagrange", {"gas_inertia": "lagrange"}),
                        ("friction", {"bore_friction": 5000.0}), ("slow valve", {"opening_time": 20e-3})):
        s = fire(Gun(**{**base, **extra}))
        assert s.energy_balance_error < 1e-9
        v[name] = s.muzzle_velocity
    for loss in ("air", "lagrange", "friction", "slow valve"):
        assert v[loss] < v["ideal"], loss


def test_choked_flow_and_noble_abel():
    air = GASES["air"]
    # choked: independent of the back pressure; 0.0404 p0 A / sqrt(T0) for air (textbook constant)
    m1 = orifice_flow(air, 1e-4, 1e6, 300.0, 1e5)
    m2 = orifice_flow(air, 1e-4, 1e6, 300.0, 3e5)
    assert m1 == pytest.approx(m2) and m1 == pytest.approx(0.0404 * 1e6 * 1e-4 / math.sqrt(300.0), rel=2e-3)
    assert orifice_flow(air, 1e-4, 1e6, 300.0, 1e6) == 0.0
    real = air.real()
    # the covolume raises the pressure of the same mass in the same volume
    assert real.pressure(100.0, 2e7, 1.0) > air.pressure(100.0, 2e7, 1.0)


def test_asme_wall_by_hand():
    # UG-27(c)(1): t = P R / (S E - 0.6 P); 2000 psi in a 12 in SA-106-B pipe (S = 17.1 ksi)
    shell, weight = vessel.barrel_weight(P0, BORE, LENGTH, "SA-106-B")
    S = 17.1e3 * PSI
    assert shell.thickness == pytest.approx(P0 * BORE / 2 / (S - 0.6 * P0), rel=1e-12)
    assert shell.rule == "UG-27(c)(1)" and shell.margin > 0
    assert vessel.cylinder_thickness(0.6 * S, 0.1, S).rule == "Appendix 1-2(a)(1)"
    with pytest.raises(ValueError):
        vessel.cylinder_thickness(1.1 * S, 0.1, S)


def test_launcher_command(tmp_path):
    scene = os.path.join(REPO, "studies", "launcher", "white_paper_gun.toml")
    p = subprocess.run([sys.executable, "-m", "shockfem", "launcher", scene, "--out", str(tmp_path / "gun")],
                       capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stderr
    assert "muzzle velocity" in p.stdout and (tmp_path / "gun" / "launcher.png").stat().st_size > 10_000
    p = subprocess.run([sys.executable, "-m", "shockfem", "launcher", scene, "--set", 'launcher.bore="-3 in"',
                        "--set", "launcher.gas=xenon"], capture_output=True, text=True, timeout=300)
    assert p.returncode == 2 and "launcher.bore: must be > 0" in p.stderr and "launcher.gas" in p.stderr
    assert "Traceback" not in p.stderr


def test_a_valve_opening_in_no_time_opens_at_once():
    """An opening time of 1e-300 s (a scene's '1e-300 s') left the integrator a first piece with t + h = t,
    where it hung (the fuzz of the launcher's tables found it); below 1e-9 of the longest shot it is an
    instant, and the shot is the instantaneous valve's to round-off."""
    base = dict(reservoir_volume=1.0, reservoir_pressure=2e6, bore=0.1, length=2.0, projectile_mass=5.0,
                valve_area=0.005, air_ahead="evacuated", gas_inertia="none")
    instant = fire(Gun(**base))
    for t in (1e-300, 1e-12):
        assert fire(Gun(**base, opening_time=t)).muzzle_velocity == pytest.approx(instant.muzzle_velocity,
                                                                                    rel=1e-9)


def test_the_shots_integration_is_solve_ivps_step_for_step():
    """``gun._integrate`` is scipy's ``solve_ivp`` loop with LSODA, dense output and terminal events, the
    events' signs tested as numbers: on the same system (a mass on a spring pushed off at speed, with
    a rising event past x = 0.3 and a falling one at v = 0.2) the same steps, states, event time and
    interpolant to the bit, and the earliest event ends it."""
    import numpy as np
    from scipy.integrate import solve_ivp
    from shockfem.launcher.gun import EPS, _integrate

    def rhs(t, y):
        return [y[1], -4.0 * y[0]]
    y0, atol = np.array([0.0, 1.0]), np.array([1e-12, 1e-12])
    events = (lambda y: y[0] - 0.3, lambda y: y[1] - 0.2)

    def far(t, y):
        return events[0](y)

    def slow(t, y):
        return events[1](y)
    far.terminal, far.direction, slow.terminal, slow.direction = True, 1, True, -1
    ours = _integrate(rhs, 0.0, 10.0, y0, 1e-9, atol, events, (1, -1))
    theirs = solve_ivp(rhs, (0.0, 10.0), y0, method="LSODA", rtol=1e-9, atol=atol, events=(far, slow),
                       dense_output=True)
    assert ours.success and theirs.status == 1 and EPS == np.finfo(float).eps
    assert np.array_equal(ours.t, theirs.t) and np.array_equal(ours.y, theirs.y)
    assert [list(t) for t in ours.t_events] == [list(t) for t in theirs.t_events]
    # x = sin(2 t) / 2 reaches 0.3 at asin(0.6) / 2, before v = cos(2 t) falls to 0.2
    assert len(ours.t_events[0]) == 1 and len(ours.t_events[1]) == 0
    assert ours.t[-1] == pytest.approx(math.asin(0.6) / 2, rel=1e-8)
    ts = np.linspace(0.0, ours.t[-1], 7)
    assert np.array_equal(ours.sol(ts), theirs.sol(ts))

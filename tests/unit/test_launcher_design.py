"""The launcher design tool finds a real optimum, says what binds, and the chain takes a gun."""
import dataclasses
import math
import os
import subprocess
import sys

import pytest
from scipy.optimize import brentq

from shockfem.amplifier.chain import run_chain_scene
from shockfem.launcher.design import Limits, Sizing, lightest_launcher, weights
from shockfem.launcher.gun import Gun, barrel_length_for, fire
from shockfem.scene import SceneError

from shockfem.units import FT, PSI, IN as INCH   # checked against pint in test_units.py
TEMPLATE = Gun(reservoir_volume=0.02, reservoir_pressure=1000 * PSI, bore=4 * INCH, length=2.0, projectile_mass=20.0,
               valve_area=math.pi * (3 * INCH) ** 2 / 4, opening_time=1e-3)
REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def _lightest_volume_for(gun, speed):
    """Weight of the gun with the smallest tank reaching ``speed`` (the other variables fixed)."""
    def short(log_v):
        return fire(dataclasses.replace(gun, reservoir_volume=math.exp(log_v)), samples=2).muzzle_velocity - speed
    v = math.exp(brentq(short, math.log(1e-4), math.log(10.0), xtol=1e-8))
    return sum(weights(dataclasses.replace(gun, reservoir_volume=v), Sizing()))


def test_design_is_a_local_optimum_meeting_the_speed():
    speed, limits = 150.0, Limits(max_length=3.0, max_bore=8 * INCH, max_pressure=3000 * PSI)
    d = lightest_launcher(TEMPLATE, speed, limits, starts=2, report_binding=False)
    assert d.feasible and d.muzzle_velocity == pytest.approx(speed, rel=2e-4)
    assert d.weight == pytest.approx(d.barrel_weight + d.tank_weight)
    # moving bore, length or pressure 5% either way (inside the limits), with the tank resized to
    # just reach the speed, gives no lighter gun
    g = d.gun
    for name, hi in (("bore", limits.max_bore), ("length", limits.max_length), ("reservoir_pressure",
                                                                                  limits.max_pressure)):
        for f in (0.95, 1.05):
            value = getattr(g, name) * f
            if value > hi * (1 + 1e-9):
                continue
            moved = dataclasses.replace(g, **{name: value})
            if name == "bore":
                moved = dataclasses.replace(moved, valve_area=g.valve_area * f * f)
            assert _lightest_volume_for(moved, speed) > d.weight * (1 - 2e-3), (name, f)
    # a limit at the optimum is reported as binding, with what relaxing it saves
    tight = Limits(max_length=0.5 * g.length, max_bore=8 * INCH, max_pressure=3000 * PSI)
    t = lightest_launcher(TEMPLATE, speed, tight, starts=1)
    assert t.feasible and t.weight > d.weight
    binding = {b["limit"]: b for b in t.binding}
    assert "max_length" in binding and binding["max_length"]["weight_saved_by_relaxing_10%"] > 0


def test_infeasible_limits_are_reported_not_guessed():
    d = lightest_launcher(TEMPLATE, 400.0, Limits(max_length=1.0, max_bore=3 * INCH, max_pressure=500 * PSI))
    assert not d.feasible and d.muzzle_velocity < 400.0 and "no gun within the limits" in d.note
    # the bound it quotes: every variable at its largest
    assert {b["limit"] for b in d.binding} >= {"max_length", "max_bore", "max_pressure"}


def test_barrel_length_for_a_speed_matches_constant_pressure():
    gun = Gun(1e4, 2000 * PSI, 12 * INCH, 1.0, 944.0, air_ahead="evacuated", gas_inertia="none")
    v = 60.0
    assert barrel_length_for(gun, v) == pytest.approx(944.0 * v * v / (2 * 2000 * PSI * gun.area), rel=1e-5)
    # the simple-wave gun can never pass 2 c0 / (gamma - 1)
    assert barrel_length_for(dataclasses.replace(gun, gas_inertia="simple-wave"), 1800.0) == math.inf


def _chain(**launcher):
    body = {"material": "steel", "shape": "cylinder", "element_size": 0.02}
    return {"chain": {"name": "gun_chain", "fidelity": "rigid", "restitution": 0.9},
            "materials": {"steel": {"library": "high_strength_steel"}},
            "bodies": [dict(body, name="m1", radius=0.1, length=0.2), dict(body, name="m2", radius=0.05, length=0.1)],
            "launcher": {"bore": "8 in", "length": "6 ft", "reservoir_pressure": "2000 psi",
                         "reservoir_volume": "2 ft**3", "valve_diameter": "5 in", **launcher}}


def test_chain_fired_by_a_launcher(tmp_path):
    chain = run_chain_scene(_chain(), str(tmp_path), echo=lambda *a: None)
    m1 = chain["masses"]["m1"]
    gun = Gun(2 * FT ** 3, 2000 * PSI, 8 * INCH, 6 * FT, m1, valve_area=math.pi * (5 * INCH) ** 2 / 4)
    # (the scene's "2000 psi" goes through pint, units.PSI through LB G0 / IN^2: the same to 1e-15)
    assert chain["launch_speed"] == pytest.approx(fire(gun).muzzle_velocity, rel=1e-6)
    assert chain["launcher"]["sizing"]["total_weight"] > 0 and (tmp_path / "launcher" / "launcher.png").exists()
    # rigid chain, e = 0.9: v2 = (1 + e) m1 / (m1 + m2) v1
    m2 = chain["masses"]["m2"]
    assert chain["test_article_speed"] == pytest.approx(1.9 * m1 / (m1 + m2) * chain["launch_speed"], rel=1e-9)
    both = _chain()
    both["chain"]["launch_speed"] = "10 m/s"
    for bad, field in ((both, "chain.launch_speed"), (_chain(projectile_mass="3 lb"), "launcher.projectile_mass"),
                       (_chain(reservoir_pressure="20 psi"), "launcher: the gun does not fire")):
        with pytest.raises(SceneError) as e:
            run_chain_scene(bad, str(tmp_path), echo=lambda *a: None)
        assert field in "\n".join(e.value.problems)


def test_launcher_design_command(tmp_path):
    scene = tmp_path / "gun.toml"
    scene.write_text('[launcher]\nprojectile_mass = "20 kg"\nbore = "4 in"\nlength = "2 m"\n'
                     'reservoir_pressure = "1000 psi"\nreservoir_volume = "0.02 m**3"\nvalve_diameter = "3 in"\n'
                     '[design]\nmuzzle_velocity = "150 m/s"\nmax_length = "3 m"\nmax_bore = "8 in"\n'
                     'max_pressure = "3000 psi"\n')
    p = subprocess.run([sys.executable, "-m", "shockfem", "launcher", str(scene), "--lightest", "--trade", "2",
                        "--out", str(tmp_path / "out")], capture_output=True, text=True, timeout=600, cwd=REPO)
    assert p.returncode == 0, p.stderr
    assert "lightest launcher" in p.stdout and (tmp_path / "out" / "trade.png").stat().st_size > 10_000
    p = subprocess.run([sys.executable, "-m", "shockfem", "launcher", str(scene), "--lightest",
                        "--set", 'design.max_pressure="90000 psi"'], capture_output=True, text=True, timeout=300,
                       cwd=REPO)
    assert p.returncode == 2 and "design.max_pressure" in p.stderr and "Traceback" not in p.stderr

"""The programmer sizing tool (``shockfem programmer``): the requirement of each shape against
fixtures.md's closed forms, each concept's verdict where the closed forms decide it, and the
command's output and bad-option messages.  ODE checks of the dashpot: ``verify programmer_sizing``."""
import json
import math
import subprocess
import sys

import pytest

from shockfem.programmer.concepts import crushable_pad, orifice_dashpot, split_cone
from shockfem.programmer.requirement import requirement
from shockfem.units import G0, LB

A, T, M = 1e4 * G0, 5e-3, 12 * LB


@pytest.mark.parametrize("shape, dv, stroke", [("rectangle", 1.0, 0.5), ("half-sine", 2 / math.pi, 1 / math.pi),
                                               ("terminal-peak sawtooth", 0.5, 1 / 3)])
def test_requirement_matches_the_closed_forms(shape, dv, stroke):
    req = requirement(shape, A, T, M)
    assert req.velocity_change == pytest.approx(dv * A * T, rel=1e-12)
    assert req.stroke == pytest.approx(stroke * A * T ** 2, rel=1e-9)
    assert req.force == pytest.approx(M * A) and req.energy == pytest.approx(0.5 * M * (dv * A * T) ** 2)


def test_trapezoid_stroke_lies_between_the_rectangle_and_the_half_sine():
    """Ramps of 10% of T: dV = 0.9 A T; its stroke is below the rectangle's and above the half-sine's."""
    req = requirement("trapezoid", A, T, M)
    assert req.velocity_change == pytest.approx(0.9 * A * T, rel=1e-12)
    assert requirement("half-sine", A, T, M).stroke < req.stroke < requirement("rectangle", A, T, M).stroke


def test_pad_area_and_thickness():
    req = requirement("rectangle", A, T, M)
    pad = crushable_pad(req, 5e6, 0.7, 270.0)
    sizes = {label: value for label, value, _ in pad.sizes}
    assert sizes["area"] == pytest.approx(M * A / 5e6)                  # fixtures.md: 0.107 m^2 for 12 lb
    assert sizes["area"] == pytest.approx(0.107, abs=5e-4)
    assert sizes["thickness"] == pytest.approx(req.stroke / 0.7)
    assert pad.feasible and pad.gives == "rectangle"


def test_dashpot_is_ruled_out_below_its_throttling_pressure():
    """fixtures.md: no throttling of 490 m/s below rho V0^2 / (2 Cd^2) = 213 MPa for oil (Cd 0.7)."""
    req = requirement("rectangle", A, T, M)
    low = orifice_dashpot(req, 870.0, 0.7, 1.5e9, 200e6, 1900.0)
    assert not low.feasible and "213.4 MPa" in low.reason
    high = orifice_dashpot(req, 870.0, 0.7, 1.5e9, 400e6, 1900.0)
    assert high.feasible and any("compressibility" in n for n in high.notes)


def test_split_cone_self_locks_at_or_below_the_friction_angle():
    req = requirement("rectangle", A, T, M)
    assert not split_cone(req, math.atan(0.2), 0.2, 250e6, 210e9, 0.2, 7850.0).feasible
    cone = split_cone(req, math.radians(7), 0.1, 250e6, 210e9, 0.2, 7850.0)
    assert {label: v for label, v, _ in cone.sizes}["restitution of an elastic ring"] == pytest.approx(0.316, abs=5e-4)


def _shockfem(*args):
    return subprocess.run([sys.executable, "-m", "shockfem", *args], capture_output=True, text=True, timeout=300)


def test_command_prints_and_writes_json(tmp_path):
    out = tmp_path / "sizing.json"
    p = _shockfem("programmer", "--article", "12 lb", "--shape", "half-sine", "--peak", "10000 gee",
                  "--duration", "5 ms", "--json", str(out))
    assert p.returncode == 0, p.stderr
    assert "velocity change 312.2 m/s, stroke 780.4 mm" in p.stdout
    assert "orifice dashpot: ruled out: no orifice can throttle 312.2 m/s below 86.5 MPa" in p.stdout
    assert "crushable pad: gives a rectangle of the peak and the velocity change (3.183 ms), not a half-sine" in p.stdout
    data = json.loads(out.read_text())
    assert data["requirement"]["velocity_change"] == pytest.approx(312.155, rel=1e-5)
    assert [c["name"] for c in data["concepts"]] == ["crushable pad", "orifice dashpot", "split cone"]


def test_command_lists_every_bad_option():
    p = _shockfem("programmer", "--article", "-1 lb", "--shape", "rectangle", "--peak", "10 m", "--duration", "5 ms",
                  "--friction", "1.5", "--ring", "cheese")
    assert p.returncode == 2 and "Traceback" not in p.stderr
    for expected in ("--article: must be > 0", "--peak: expected an acceleration",
                     "--friction: must be in [0, 1), got 1.5", "--ring: must be one of"):
        assert expected in p.stderr, p.stderr


def test_command_refuses_an_unknown_shape_with_its_choices():
    """--shape is a list of choices (the same in every command that takes it): argparse refuses another
    with the choices and the usage, exit 2."""
    p = _shockfem("programmer", "--article", "12 lb", "--shape", "square", "--peak", "10000 gee", "--duration",
                  "5 ms")
    assert p.returncode == 2 and "Traceback" not in p.stderr
    assert "--shape: invalid choice: 'square'" in p.stderr and "half-sine" in p.stderr, p.stderr


def _scipy_lumped_dashpot(d, end_time, samples):
    """The lumped dashpot integrated by scipy's own RK45 (``solve_ivp``, the same tolerances and step bound
    as ``simulate``): the reference its compiled copy of that integrator must reproduce."""
    import numpy as np
    from scipy.integrate import solve_ivp
    from shockfem.fluid import liquid, orifice
    A, K, n, rho0 = d.piston_area, d.bulk_modulus, d.tait_exponent, d.density
    V0 = A * d.column
    pin_s, pin_a = np.array([p[0] for p in d.pin]), np.array([p[1] for p in d.pin])

    def rates(t, y):
        ratio = y[3] / (rho0 * max(V0 - A * y[0], 1e-12 * V0))
        p = liquid.pressure(ratio, K, n)
        area, law = float(np.interp(y[0], pin_s, pin_a)), d.orifice_law().code()
        mdot = liquid.orifice_mass_flow(ratio, area, A, law, K, n, rho0)
        jet = orifice.jet_reaction(mdot, rho0 * ratio, area, A, law)
        return [y[1] - y[2], -p * A / d.striker_mass, (p * A - jet) / d.payload_mass, -mdot]
    mass0 = rho0 * (1.0 + n * d.initial_pressure / K) ** (1.0 / n) * V0
    return solve_ivp(rates, (0.0, end_time), [0.0, d.speed, 0.0, mass0], t_eval=np.linspace(0.0, end_time, samples),
                     rtol=1e-8, atol=1e-12, max_step=end_time / 2000)


@pytest.mark.parametrize("shape", ["rectangle", "half-sine"])
def test_the_lumped_dashpot_integrates_as_scipys_rk45(shape):
    """``lumped_dashpot.simulate`` runs scipy's RK45 compiled (its first step, error control and dense
    output, scipy's coefficients): the study's designs against solve_ivp, to round-off (measured identical
    to the bit; the dense output with x for every power, or the error weights halved, move
    them by 8e-7 and 1.5e-7 of their largest)."""
    import numpy as np
    from shockfem.programmer.dashpot_design import LUMPED_SAMPLES, dashpot_lumped
    from shockfem.programmer.lumped_dashpot import simulate
    from shockfem.study.fixture.dashpot import SPEC_PULSE, dashpot_design
    d = dashpot_lumped(dashpot_design(shape))
    end = SPEC_PULSE[shape].record_end()
    reference = _scipy_lumped_dashpot(d, end, LUMPED_SAMPLES)
    run = simulate(d, end, LUMPED_SAMPLES)
    assert reference.status == 0 and np.array_equal(run.t, reference.t)
    for mine, theirs in ((run.stroke, reference.y[0]), (run.striker_speed, reference.y[1]),
                         (run.payload_speed, reference.y[2])):
        assert np.max(np.abs(mine - theirs)) <= 1e-12 * np.max(np.abs(theirs))

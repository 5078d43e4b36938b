import pytest

from shockfem.scene import SceneError, apply_override, resolve


def base():
    return {"scene": {"name": "t", "kinematics": "axisymmetric", "end_time": "10 us"},
            "materials": {"steel": {"density": "7850 kg/m^3", "youngs_modulus": "210 GPa",
                                    "poisson_ratio": 0.3}},
            "bodies": [{"name": "bar", "material": "steel", "shape": "cylinder", "radius": "5 mm",
                        "length": "100 mm", "element_size": "1 mm", "velocity": "-5 m/s"}]}


def test_resolves_units_to_si():
    s = resolve(base())
    b = s.bodies[0]
    assert b.dims == {"radius": 0.005, "length": 0.1}
    assert b.velocity == (0.0, -5.0)
    assert s.end_time == pytest.approx(1e-5)
    assert s.safety_factor == 0.9          # LS-DYNA's default TSSFAC


def test_every_problem_listed_with_path():
    raw = base()
    raw["bodies"][0]["radius"] = "-3 mm"
    raw["bodies"][0]["material"] = "unobtainium"
    raw["scene"]["kinematics"] = "2.5d"
    raw["bodies"][0]["colour"] = "red"
    with pytest.raises(SceneError) as e:
        resolve(raw)
    text = "\n".join(e.value.problems)
    assert "bodies[0].radius: must be > 0, got -3 mm" in text
    assert "bodies[0].material: unknown material 'unobtainium'" in text
    assert "scene.kinematics: must be one of" in text
    assert "bodies[0].colour: unknown field" in text
    assert len(e.value.problems) >= 4


def test_axisymmetric_body_off_axis_rejected():
    raw = base()
    raw["bodies"][0]["position"] = ["1 mm", "0 m"]
    with pytest.raises(SceneError, match="r component must be 0"):
        resolve(raw)


def test_override_by_body_name():
    raw = apply_override(base(), 'bodies.bar.velocity="12 m/s"')
    assert resolve(raw).bodies[0].velocity == (0.0, 12.0)


def test_override_unknown_body():
    with pytest.raises(SceneError, match="no entry 'striker'"):
        apply_override(base(), 'bodies.striker.velocity="12 m/s"')


def test_boundary_region_checked():
    raw = base()
    raw["boundary"] = [{"region": "bar.nose", "type": "fixed"}]
    with pytest.raises(SceneError, match="boundary\\[0\\].region: body 'bar' has regions"):
        resolve(raw)


def test_damping_coefficients_give_the_ratio_at_the_frequency():
    import math
    raw = base()
    raw["damping"] = {"ratio": 0.02, "frequency": "1 kHz", "type": "rayleigh"}
    d = resolve(raw).damping
    alpha, beta = d.coefficients()
    w = 2 * math.pi * 1000
    assert alpha / (2 * w) + beta * w / 2 == pytest.approx(0.02, rel=1e-12)


def test_element_integration_defaults_and_checks():
    s = resolve(base())
    assert (s.integration, s.hourglass, s.hourglass_coefficient) == ("reduced", "stiffness", 0.05)
    raw = base()
    raw["scene"].update(integration="selective", hourglass="magic", hourglass_coefficient=-0.1)
    with pytest.raises(SceneError) as e:
        resolve(raw)
    text = "\n".join(e.value.problems)
    assert "scene.integration: must be one of reduced, full" in text
    assert "scene.hourglass: must be one of stiffness, viscous" in text
    assert "scene.hourglass_coefficient: must be >= 0" in text

import pytest

from shockfem.scene import SceneError, apply_override, resolve


def base():
    return {"scene": {"name": "t", "kinematics": "axisymmetric", "end_time": "10 us"},
            "materials": {"steel": {"density": "7850 kg/m^3", "youngs_modulus": "210 GPa",
                                    "poisson_ratio": 0.3}},
            "bodies": [{"name": "bar", "material": "steel", "shape": "cylinder", "radius": "5 mm",
                        "length": "100 mm", "element_size": "1 mm", "velocity": "-5 m/s"}]}


def _problems(raw):
    """Every problem resolve() lists for a bad scene."""
    with pytest.raises(SceneError) as e:
        resolve(raw)
    return e.value.problems


def test_resolves_units_to_si():
    s = resolve(base())
    b = s.bodies[0]
    assert b.dims["radius"] == 0.005 and b.dims["length"] == 0.1
    assert b.dims["bottom_crown"] == 0.0 and b.dims["top_chamfer"] == 0.0     # catalogue defaults: flat ends
    assert b.velocity == (0.0, -5.0)
    assert s.end_time == pytest.approx(1e-5)
    assert s.safety_factor == 0.9          # LS-DYNA's default TSSFAC


def test_every_problem_listed_with_path():
    raw = base()
    raw["bodies"][0]["radius"] = "-3 mm"
    raw["bodies"][0]["material"] = "unobtainium"
    raw["scene"]["kinematics"] = "2.5d"
    raw["bodies"][0]["colour"] = "red"
    problems = _problems(raw)
    text = "\n".join(problems)
    assert "bodies[0].radius: must be > 0, got -3 mm" in text
    assert "bodies[0].material: unknown material 'unobtainium'" in text
    assert "scene.kinematics: must be one of" in text
    assert "bodies[0].colour: unknown field" in text
    assert len(problems) >= 4


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


def test_a_rigid_body_is_driven_whole():
    """A velocity or fixed condition names a rigid body itself (its centre driven); on a region of it, it
    would hold some of its nodes apart from it, and is refused with the fix; a deformable body is never
    driven whole, an axisymmetric rigid body only along z, and never by a symmetry condition."""
    raw = base()
    raw["bodies"][0]["rigid"] = True
    raw["boundary"] = [{"region": "bar", "type": "velocity", "direction": "z",
                        "history": [["0 s", 0.0], ["5 s", "-2 m/s"]]},
                       {"region": "bar", "type": "fixed"}]
    driven, held = resolve(raw).boundaries
    assert (driven.region, driven.kind, driven.components, driven.history) == (
        "bar", "velocity", (1,), ((0.0, 0.0), (5.0, -2.0)))
    assert (held.region, held.kind) == ("bar", "fixed")
    raw["boundary"] = [{"region": "bar.bottom", "type": "velocity", "value": "1 m/s"},
                       {"region": "bar", "type": "symmetry"},
                       {"region": "bar", "type": "velocity", "direction": "r", "value": "1 m/s"},
                       {"region": "bar", "type": "force", "value": "1 N"}]
    text = "\n".join(_problems(raw))
    assert ("boundary[0].region: 'bar' is a rigid body: its nodes move with it, so a velocity condition cannot "
            "hold a region of it; give region = 'bar'") in text
    assert "boundary[1].type: a rigid body ('bar') is driven with type = \"velocity\"" in text
    assert "boundary[2].direction: an axisymmetric rigid body moves along z only" in text
    assert "boundary[3].region: a force acts on a region of the rigid body 'bar'" in text
    raw["bodies"][0]["rigid"] = False
    raw["boundary"] = [{"region": "bar", "type": "velocity", "value": "1 m/s"}]
    assert "boundary[0].region: 'bar' is a deformable body: give one of its regions" in "\n".join(_problems(raw))


def test_damping_coefficients_give_the_ratio_at_the_frequency():
    import math
    raw = base()
    raw["damping"] = {"ratio": 0.02, "frequency": "1 kHz", "type": "rayleigh"}
    d = resolve(raw).damping
    alpha, beta = d.coefficients()
    w = 2 * math.pi * 1000
    assert alpha / (2 * w) + beta * w / 2 == pytest.approx(0.02, rel=1e-12)


def test_body_damping_is_stiffness_proportional_at_its_own_frequency():
    import math
    raw = base()
    raw["bodies"][0]["damping"] = {"ratio": 0.02, "frequency": "25 kHz"}
    d = resolve(raw).bodies[0].damping
    assert d.kind == "stiffness" and d.coefficients() == (0.0, pytest.approx(0.04 / (2 * math.pi * 25e3)))
    raw["bodies"][0]["damping"] = {"ratio": 0.02, "frequency": "-1 Hz", "type": "mass"}
    text = "\n".join(_problems(raw))
    assert "bodies[0].damping.type: must be one of stiffness" in text
    assert "bodies[0].damping.frequency" in text


def test_element_integration_defaults_and_checks():
    s = resolve(base())
    assert (s.integration, s.hourglass, s.hourglass_coefficient) == ("reduced", "stiffness", 0.05)
    raw = base()
    raw["scene"].update(integration="selective", hourglass="magic", hourglass_coefficient=-0.1)
    problems = _problems(raw)
    text = "\n".join(problems)
    assert "scene.integration: must be one of reduced, full" in text
    assert "scene.hourglass: must be one of stiffness, viscous" in text
    assert "scene.hourglass_coefficient: must be >= 0" in text


def _two_bodies():
    raw = base()
    raw["bodies"].append(dict(raw["bodies"][0], name="anvil", position=["0 m", "-100 mm"], velocity="0 m/s"))
    return raw


def test_contact_friction_rigid_cylinder_and_spring_resolve_to_si():
    raw = _two_bodies()
    raw["scene"]["gravity"] = "-1 gravity"
    raw["contact"] = [{"a": "bar", "b": "anvil", "friction": 0.4, "friction_dynamic": 0.3,
                       "friction_decay": "2 s/m"},
                      {"a": "bar.side", "cylinder": {"radius": "6 mm", "side": "inside"}}]
    raw["spring"] = [{"a": "bar.bottom", "b": "anvil.top", "curve": [["0 mm", "0 N"], ["1 mm", "2 kN"]],
                      "damping": "10 N*s/m", "compression_only": True}]
    s = resolve(raw)
    assert s.gravity == pytest.approx((0.0, -9.80665))
    assert s.contacts[0].friction == (0.4, 0.3, 2.0)
    cyl = s.contacts[1].rigid
    assert (cyl.kind, cyl.radius, cyl.inside, cyl.direction) == ("cylinder", 0.006, True, (0.0, 1.0))
    sp = s.springs[0]
    assert sp.curve == ((0.0, 0.0), (0.001, 2000.0)) and sp.damping == 10.0 and sp.compression_only


def test_contact_and_spring_problems_are_listed():
    raw = _two_bodies()
    raw["contact"] = [{"a": "bar", "b": "anvil", "wall": {}, "friction": 0.2, "friction_dynamic": 0.5,
                       "interference": "-200 us"},
                      {"a": "bar", "cylinder": {"radius": "-1 mm", "point": ["1 mm", "0 m"]}}]
    raw["spring"] = [{"a": "bar", "b": "bar.top"}, {"a": "bar", "b": "anvil", "stiffness": "1 kN/m",
                                                    "curve": [["1 mm", "1 N"], ["0 mm", "0 N"]]}]
    problems = _problems(raw)
    text = "\n".join(problems)
    assert "contact[0]: give exactly one of b" in text
    assert "contact[0].friction_dynamic: must not exceed" in text
    assert "contact[0].interference: must be >= 0, got -200 us" in text
    assert "contact[1].cylinder.radius: must be > 0" in text
    assert "contact[1].cylinder: an axisymmetric cylinder is coaxial" in text
    assert "spring[0].b: a spring joins two different bodies" in text
    assert "spring[0]: needs a stiffness, a curve or a damping" in text
    assert "spring[1]: give stiffness (linear) or curve (tabulated), not both" in text
    assert "spring[1].curve: extensions must increase" in text


def test_constraint_wall_resolves_and_its_problems_are_listed():
    """``method = "constraint"``: a rigid plane only, and without the penalty's keys (it has no penalty,
    damping or friction); a bad method is named with its choices."""
    raw = _two_bodies()
    raw["contact"] = [{"a": "bar.bottom", "wall": {"point": ["0 m", "-1 mm"]}, "method": "constraint"}]
    c = resolve(raw).contacts[0]
    assert (c.method, c.rigid.kind, c.rigid.point) == ("constraint", "plane", (0.0, -0.001))
    raw["contact"] = [{"a": "bar", "b": "anvil", "method": "constraint"},
                      {"a": "bar", "cylinder": {"radius": "10 mm"}, "method": "constraint"},
                      {"a": "bar", "wall": {}, "method": "constraint", "friction": 0.2, "penalty_scale": 2},
                      {"a": "bar", "wall": {}, "method": "glue"}]
    text = "\n".join(_problems(raw))
    assert text.count('holds nodes on a rigid wall (a plane) only') == 2, text
    assert 'contact[2].friction: not used by method = "constraint"' in text
    assert 'contact[2].penalty_scale: not used by method = "constraint"' in text
    assert "contact[3].method: must be one of penalty, constraint, got 'glue'" in text


def _with_material(**fields):
    raw = base()
    raw["materials"]["steel"].update(fields)
    return raw


def test_bilinear_plastic_material_resolves():
    m = resolve(_with_material(yield_stress="250 MPa", tangent_modulus="1 GPa", isotropic_fraction=0.25,
                               cowper_symonds_D="40.4 /s", cowper_symonds_q=5)).materials["steel"]
    p = m.plasticity
    H = 210e9 * 1e9 / (210e9 - 1e9)
    assert p.curve[0] == (0.0, 250e6)
    assert p.curve[1][1] == pytest.approx(250e6 + 0.25 * H)
    assert p.kinematic_modulus == pytest.approx(0.75 * H)
    assert (p.rate_D, p.rate_q, p.rate_form) == (40.4, 5.0, "plastic-strain-rate")


def test_library_material_and_override():
    m = resolve({**base(), "materials": {"steel": {"library": "mild_steel", "yield_stress": "300 MPa"}}}
                ).materials["steel"]
    assert m.E == 210e9 and m.plasticity.yield_stress == 300e6 and m.plasticity.rate_D == 40.4
    assert "Jones" in m.source
    curve = resolve({**base(), "materials": {"steel": {"library": "steel_4340"}}}).materials["steel"]
    assert curve.plasticity.curve[0] == (0.0, 792e6) and len(curve.plasticity.curve) == 10


def test_bad_plastic_fields_are_named():
    problems = _problems(_with_material(yield_stress="250 MPa", tangent_modulus="300 GPa",
                                        cowper_symonds_D="40 /s", isotropic_fraction=2))
    assert any(p.startswith("materials.steel.tangent_modulus: must be < youngs_modulus") for p in problems)
    assert any(p.startswith("materials.steel.cowper_symonds_q: missing") for p in problems)
    assert any(p.startswith("materials.steel.isotropic_fraction: must be in [0, 1]") for p in problems)
    problems = _problems(_with_material(hardening_curve=[[0.1, "300 MPa"], [0.2, "250 MPa"]],
                                        yield_stress="250 MPa"))
    assert any("must start at plastic strain 0" in p for p in problems)
    assert any("must not decrease" in p for p in problems)
    assert any(p.startswith("materials.steel.yield_stress: give either") for p in problems)
    assert any("unknown library material" in p
               for p in _problems({**base(), "materials": {"steel": {"library": "unobtainium"}}}))


def test_shock_section_resolves_units_and_defaults():
    raw = base()
    raw["shock"] = {"test_articles": ["bar"], "spec": {"shape": "half-sine", "peak": "10000 gee",
                                                        "duration": "5 ms"},
                    "accelerometers": [{"name": "top", "body": "bar", "at": ["0 mm", "100 mm"]}],
                    "srs_frequencies": ["10 Hz", "20 kHz"]}
    s = resolve(raw).shock
    assert s.test_articles == ("bar",) and s.axis == "z" and s.cfc == 1000 and s.srs_q == 10
    assert s.spec.peak == pytest.approx(98066.5) and s.spec.duration == pytest.approx(5e-3)
    assert s.accelerometers[0].point == (0.0, 0.1)
    assert s.srs_frequencies == (10.0, 20000.0)
    assert resolve(base()).shock.test_articles == ()          # no [shock]: no test article


def test_shock_section_problems_are_all_listed():
    raw = base()
    raw["shock"] = {"test_articles": ["payload"], "axis": "r", "cfc": 700,
                    "srs_frequencies": ["1 kHz", "10 Hz"], "accelerometers": [{"name": "a", "body": "nobody"}],
                    "spec": {"shape": "square", "peak": "1 kg"}}
    text = "\n".join(_problems(raw))
    for expected in ("shock.test_articles[0]: unknown body 'payload'",
                     "shock.axis: must be one of z (the axis of symmetry)",
                     "shock.cfc: must be a channel frequency class 60, 180, 600, 1000",
                     "shock.srs_frequencies: the lowest frequency must be below the highest",
                     "shock.accelerometers[0].body: unknown body 'nobody'",
                     "shock.accelerometers[0].at: missing",
                     "shock.spec.shape: must be one of half-sine, terminal-peak sawtooth, trapezoid",
                     "shock.spec.peak: expected an acceleration",
                     "shock.spec.duration: missing"):
        assert expected in text


def _oriented(orientation, velocity="-5 m/s", kinematics="3d"):
    raw = base()
    raw["scene"]["kinematics"] = kinematics
    if kinematics == "3d":
        raw["scene"]["element"] = "hex"
    b = raw["bodies"][0]
    b["position"] = [0, 0, 0] if kinematics == "3d" else [0, 0]
    b["velocity"] = velocity
    b["orientation"] = orientation
    return raw


def test_orientation_turns_the_body_and_a_single_speed_follows_its_axis():
    """A turn of 90 degrees about x takes the body's axis z to -y; a single speed then points along it,
    a vector stays in the scene's axes; direction = d gives the axis d itself."""
    import numpy as np
    b = resolve(_oriented({"axis": [1, 0, 0], "angle": "90 deg"})).bodies[0]
    assert np.allclose(b.axis, (0.0, -1.0, 0.0), atol=1e-15)
    assert np.allclose(b.velocity, (0.0, 5.0, 0.0), atol=1e-14)          # -5 m/s along -y
    b = resolve(_oriented({"axis": [1, 0, 0], "angle": "90 deg"}, velocity=[0, 0, "-5 m/s"])).bodies[0]
    assert b.velocity == (0.0, 0.0, -5.0)
    b = resolve(_oriented({"direction": [1, 2, 2]})).bodies[0]
    assert np.allclose(b.axis, (1 / 3, 2 / 3, 2 / 3), atol=1e-15)
    assert np.allclose(np.reshape(b.orientation, (3, 3)) @ np.reshape(b.orientation, (3, 3)).T, np.eye(3), atol=1e-15)
    assert resolve(_oriented({"direction": [0, 0, -2]})).bodies[0].axis == pytest.approx((0.0, 0.0, -1.0))


def test_a_2d_body_turns_end_over_end_and_its_single_speed_with_it():
    """In 2D the one turn that keeps a body on the axis: {direction = [0, -1]}, a half turn about the
    radial axis (its matrix takes z to -z); [0, 1] is the body as drawn."""
    import numpy as np
    b = resolve(_oriented({"direction": [0, -1]}, kinematics="axisymmetric")).bodies[0]
    assert np.allclose(np.reshape(b.orientation, (3, 3)), np.diag([1.0, -1.0, -1.0]), atol=1e-15)
    assert b.velocity == pytest.approx((0.0, 5.0))                          # -5 m/s along the turned axis
    assert resolve(_oriented({"direction": [0, 2]}, kinematics="axisymmetric")).bodies[0].orientation is None


@pytest.mark.parametrize("orientation, kinematics, field, words", [
    ({"axis": [1, 0, 0], "angle": "10 deg"}, "axisymmetric", "orientation", "kinematics = '3d'"),
    ({"direction": [1, 0]}, "axisymmetric", "orientation.direction", "end over end"),
    ({"direction": [0, 0, -1]}, "plane-strain", "orientation.direction", "needs 2 components"),
    ({"axis": [0, 0, 0], "angle": "10 deg"}, "3d", "orientation.axis", "zero vector"),
    ({"axis": [1, 0, 0]}, "3d", "orientation.angle", "missing"),
    ({"axis": [1, 0, 0], "angle": "10 m"}, "3d", "orientation.angle", "expected an angle"),
    ({"direction": [0, 0, 0]}, "3d", "orientation.direction", "zero vector"),
    ({"direction": [0, 0, 1], "angle": "3 deg"}, "3d", "orientation", "not both"),
    ({"yaw": "3 deg"}, "3d", "orientation.yaw", "unknown field"),
    ("10 deg", "3d", "orientation", "must be a table"),
])
def test_bad_orientation_names_the_field(orientation, kinematics, field, words):
    problems = _problems(_oriented(orientation, kinematics=kinematics, velocity=0.0))
    assert any(p.startswith(f"bodies[0].{field}:") and words in p for p in problems), problems


def test_cavity_resolves_and_its_problems_are_listed():
    raw = base()
    raw["cavity"] = [{"name": "oil", "walls": ["bar.bottom"], "volume": "25 cm^3", "initial_pressure": "1 MPa",
                      "liquid": {"density": "870 kg/m^3", "bulk_modulus": "1.5 GPa"},
                      "orifice": {"area_curve": [["0 mm", "300 mm^2"], ["5 mm", "0 mm^2"]],
                                  "piston_area": "12 cm^2"}}]
    c = resolve(raw).cavities[0]
    assert c.volume == pytest.approx(25e-6) and c.initial_pressure == 1e6 and c.tait_exponent == 1.0
    assert c.orifice == ((0.0, 3e-4), (5e-3, 0.0)) and c.piston_area == pytest.approx(12e-4)
    # the defaults: the control volume, the sharp-edged law (no fixed Cd), the column's oil
    assert c.model == "control_volume" and c.law == "sharp_edged" and c.discharge == 0.0
    assert c.vapour_pressure == -1e5 and c.heat_capacity == 1900.0
    raw["cavity"] = [{"walls": ["bar.nose"], "volume": "-1 cm^3", "liquid": {"density": "870 kg/m^3"},
                      "orifice": {"area": "1 mm^2", "area_curve": [[0, 1]], "law": "fixed_cd", "discharge": 1.5},
                      "colour": "red"}]
    text = "\n".join(_problems(raw))
    for expected in ("cavity[0].walls: body 'bar' has regions", "cavity[0].volume: must be > 0",
                     "cavity[0].liquid.bulk_modulus: missing", "cavity[0].orifice: give area (a fixed orifice) or",
                     "cavity[0].orifice.discharge: must be < 1.0, got 1.5", "cavity[0].colour: unknown field"):
        assert expected in text, text


def _column(**fields):
    raw = base()
    raw["cavity"] = [{"name": "oil", "model": "column", "walls": ["bar.bottom", "bar.top"],
                      "liquid": {"density": "870 kg/m^3", "bulk_modulus": "1.5 GPa", "vapour_pressure": "-0.1 MPa",
                                 "heat_capacity": "1.9 kJ/(kg K)"},
                      "orifice": {"area_curve": [["0 mm", "300 mm^2"], ["5 mm", "0 mm^2"]], "law": "sharp_edged"},
                      **fields}]
    return raw


def test_a_column_cavity_resolves():
    c = resolve(_column(cells=120, section=[["0 m", "10 cm^2"], ["1 m", "8 cm^2"]])).cavities[0]
    assert c.model == "column" and c.walls == ("bar.bottom", "bar.top") and c.cells == 120
    assert c.heat_capacity == pytest.approx(1900.0) and c.vapour_pressure == pytest.approx(-1e5)
    assert c.section == ((0.0, pytest.approx(1e-3)), (1.0, pytest.approx(8e-4)))
    assert c.piston_area == 0.0            # a column's metering pin needs none: its stroke is its length's


@pytest.mark.parametrize("change, field, words", [
    ({"walls": ["bar.bottom"]}, "cavity[0].walls", "exactly two walls"),
    ({"cells": 3}, "cavity[0].cells", "whole number of finite volumes"),
    ({"cells": 20.5}, "cavity[0].cells", "whole number"),
    ({"model": "lumped"}, "cavity[0].model", "must be one of control_volume, column"),
    ({"section": [["0 m", "-1 cm^2"]]}, "cavity[0].section", "must be > 0"),
    ({"orifice": {"area": "1 mm^2", "discharge": 0.7}}, "cavity[0].orifice.discharge", "fixed_cd law's"),
    ({"orifice": {"area": "1 mm^2", "law": "fixed_cd"}}, "cavity[0].orifice.discharge", "missing"),
    ({"orifice": {"area": "1 mm^2", "law": "borda"}}, "cavity[0].orifice.law", "must be one of"),
    ({"liquid": {"density": "870 kg/m^3", "bulk_modulus": "1.5 GPa", "vapour_pressure": "1 MPa"}},
     "cavity[0].liquid.vapour_pressure", "at or below 0"),
    ({"liquid": {"density": "870 kg/m^3", "bulk_modulus": "1.5 GPa", "heat_capacity": "5 m"}},
     "cavity[0].liquid.heat_capacity", ""),
])
def test_bad_column_fields_are_named(change, field, words):
    problems = _problems(_column(**change))
    assert any(p.startswith(f"{field}:") and words in p for p in problems), problems


def test_column_fields_on_a_control_volume_are_refused():
    raw = _column(cells=100)
    raw["cavity"][0]["model"] = "control_volume"
    raw["cavity"][0]["volume"] = "1 cm^3"
    raw["cavity"][0]["orifice"]["piston_area"] = "10 cm^2"
    assert any(p.startswith("cavity[0].cells: only a column") for p in _problems(raw))


def test_nan_and_infinity_in_the_new_fields_are_named():
    """A NaN or an infinity is refused like any bad value (units.to_si), with its field named."""
    raw = _oriented({"axis": [1, 0, "nan"], "angle": "inf deg"}, velocity=0.0)
    raw["contact"] = [{"a": "bar", "wall": {"point": [0, 0, 0], "normal": [0, 0, 1]}, "interference": "nan us"}]
    raw["cavity"] = [{"walls": ["bar.bottom"], "volume": "inf m^3", "liquid": {"density": "870 kg/m^3",
                      "bulk_modulus": "nan GPa"}, "orifice": {"area": "1 mm^2"}}]
    raw["materials"]["steel"].update({"crush_curve": [[0, "1 MPa"]], "tension_cutoff": "inf MPa"})
    text = "\n".join(_problems(raw))
    for field, words in (("bodies[0].orientation.axis[2]", "finite number"), ("bodies[0].orientation.angle", "finite angle"),
                         ("contact[0].interference", "finite time"), ("cavity[0].volume", "finite volume"),
                         ("cavity[0].liquid.bulk_modulus", "finite pressure"),
                         ("materials.steel.tension_cutoff", "finite pressure")):
        assert f"{field}: expected a {words}" in text, text


def _penetrator():
    raw = base()
    raw["bodies"][0].update({"shape": "projectile", "radius": "13.45 mm", "length": "218 mm", "crh": 2.0,
                             "meplat_radius": "0.5 mm"})
    raw["penetration"] = {"nose": "bar.nose", "face": {"point": [0, 0], "normal": [0, 1]},
                          "compressive_strength": "5 ksi", "density": "2300 kg/m^3", "friction": 0.4}
    return raw


def test_penetration_resolves_and_adds_its_tunnel():
    """[penetration]: units to SI, Forrestal's defaults (S from the fit: 0; crater 4a: -1), and the tunnel
    as a contact of its own along the projectile's path, of the body's radius."""
    s = resolve(_penetrator())
    p = s.penetration
    assert p.nose == "bar.nose" and p.compressive_strength == pytest.approx(5000 * 6894.757, rel=1e-6)
    assert p.strength_factor == 0.0 and p.crater_depth == -1.0 and p.friction == 0.4
    tunnel = next(c for c in s.contacts if c.name == p.tunnel)
    assert tunnel.a == "bar" and tunnel.rigid.kind == "tunnel" and tunnel.rigid.inside
    assert tunnel.rigid.radius == pytest.approx(0.01345) and tunnel.rigid.direction == (0.0, -1.0)


def test_penetration_problems_are_listed():
    raw = _penetrator()
    raw["penetration"].update({"nose": "bar.fin", "compressive_strength": "-3 MPa", "carries": ["ghost"],
                               "face": {"point": ["1 mm", 0], "normal": [0, 1]}, "tunnel": "yes", "colour": 1})
    text = "\n".join(_problems(raw))
    expected = ("nose: body 'bar' has regions", "compressive_strength: must be > 0", "carries: must list other bodies",
                "face: an axisymmetric target's face is square to the axis", "tunnel: must be true or false",
                "colour: unknown field")
    assert [e for e in expected if f"penetration.{e}" not in text] == []
    raw = _penetrator()
    raw["scene"]["kinematics"] = "plane-strain"
    assert any("needs kinematics = 'axisymmetric'" in p for p in _problems(raw))


def test_stress_sections_resolve_and_their_problems_are_listed():
    """outputs.sections: a deformable body and a whole count of cuts (default 21); a rigid or unknown
    body, a bad count and a second entry for one body are each named."""
    raw = base()
    raw["outputs"] = {"sections": [{"body": "bar"}]}
    cuts = resolve(raw).outputs.sections
    assert len(cuts) == 1 and cuts[0].body == "bar" and cuts[0].count == 21
    raw["outputs"] = {"sections": [{"body": "bar", "count": 1.5}, {"body": "bar", "count": 4}, {"body": "ghost"},
                                   {"body": "bar", "slabs": 3}]}
    text = "\n".join(_problems(raw))
    expected = ("sections[0].count: must be a whole number", "sections[1].body: 'bar' already has its sections",
                "sections[2].body: must name a deformable body", "sections[3].slabs: unknown field")
    assert [e for e in expected if f"outputs.{e}" not in text] == [], text
    raw = base()
    raw["bodies"][0]["rigid"] = True
    raw["outputs"] = {"sections": [{"body": "bar"}]}
    assert any("a rigid one has no stress" in p for p in _problems(raw))


def test_curve_elements_default_and_its_range():
    """scene.curve_elements: elements round a full circle on curved faces (gmsh's curvature sizing),
    24 unless given; a whole number in [6, 360]; it is part of the mesh cache's key."""
    from shockfem.geometry.meshing import mesh_key
    raw = base()
    assert resolve(raw).curve_elements == 24
    raw["scene"]["curve_elements"] = 12
    coarse = resolve(raw)
    assert coarse.curve_elements == 12 and mesh_key(coarse) != mesh_key(resolve(base()))
    for bad in (4, 12.5, "12", True):
        raw["scene"]["curve_elements"] = bad
        assert any(p.startswith("scene.curve_elements: must be a whole number") for p in _problems(raw))


def test_band_damping_reads_its_band_and_refuses_a_bad_one():
    raw = base()
    raw["bodies"][0]["damping"] = {"type": "band", "ratio": 0.02, "low": "1 kHz", "high": "20 kHz"}
    d = resolve(raw).bodies[0].damping
    assert (d.kind, d.ratio, d.low, d.high) == ("band", 0.02, 1e3, 2e4)
    assert d.coefficients() == (0.0, 0.0)         # no Rayleigh part: its Maxwell terms act beside the material
    scene_wide = base()
    scene_wide["damping"] = {"type": "band", "ratio": 0.02, "low": "1 kHz", "high": "20 kHz"}
    assert resolve(scene_wide).damping == d        # the same table for every body without its own
    raw["bodies"][0]["damping"] = {"type": "band", "ratio": 0.02, "low": "20 kHz", "high": "1 kHz",
                                   "frequency": "1 kHz"}
    text = "\n".join(_problems(raw))
    assert "bodies[0].damping.frequency: unknown field" in text
    assert "bodies[0].damping.high: band damping needs 0 < low < high" in text


def test_band_damping_summary_says_where_the_moduli_hold_and_what_disperses():
    """The run's summary line of a band says at which frequency the material's moduli hold (the band's
    geometric centre by default: the elastic law at E / Re K(w_c) = E x 0.9159 for 2% over 1:20, Re K / K =
    1.0918 there, ``fit_band``) and how far waves still run from the moduli's speed across the band,
    sqrt(Re K(w) / Re K(w_c)) - 1 = -2.0% at its foot and +2.0% at its top (1.0495 and 1.1360 against
    1.0918); with reference = 0 Hz the moduli are static and waves run 2.4% to 6.6% faster."""
    from shockfem.scene.damping import describe_damping
    raw = base()
    raw["bodies"][0]["damping"] = {"type": "band", "ratio": 0.02, "low": "1 kHz", "high": "20 kHz"}
    line = describe_damping(resolve(raw).bodies[0].damping)
    assert "moduli held at 4472 Hz (elastic law at E x 0.9159)" in line, line
    assert "-2.0% at 1000 Hz, +2.0% at 2e+04 Hz" in line, line
    raw["bodies"][0]["damping"]["reference"] = "0 Hz"
    line = describe_damping(resolve(raw).bodies[0].damping)
    assert "moduli static" in line and "+2.4% at 1000 Hz, +6.6% at 2e+04 Hz" in line, line


def test_band_reference_reads_with_units_and_defaults_to_the_centre():
    raw = base()
    raw["bodies"][0]["damping"] = {"type": "band", "ratio": 0.02, "low": "1 kHz", "high": "20 kHz"}
    assert resolve(raw).bodies[0].damping.reference_frequency == pytest.approx(4472.136, rel=1e-6)
    raw["bodies"][0]["damping"]["reference"] = "2 kHz"
    assert resolve(raw).bodies[0].damping.reference_frequency == 2e3
    raw["bodies"][0]["damping"]["reference"] = "-2 kHz"
    assert "bodies[0].damping.reference: must be >= 0" in "\n".join(_problems(raw))


def test_band_on_a_foam_needs_static_moduli():
    """A foam's crush curve is not a modulus a reference frequency rescales: a band on it is refused unless
    its reference is 0 Hz (the scene-wide band alike)."""
    raw = base()
    raw["materials"]["steel"].update({"crush_curve": [[0, "1 MPa"]], "tension_cutoff": "1 MPa"})
    raw["damping"] = {"type": "band", "ratio": 0.02, "low": "1 kHz", "high": "20 kHz"}
    text = "\n".join(_problems(raw))
    assert "damping.reference: body bar's material steel is a foam" in text and 'reference = "0 Hz"' in text, text
    raw["damping"]["reference"] = "0 Hz"
    assert resolve(raw).damping.reference == 0.0


def test_mass_damping_on_a_moving_body_warns_and_a_held_one_does_not():
    from shockfem.scene.damping import mass_damping_warnings
    raw = base()
    raw["damping"] = {"ratio": 0.02, "frequency": "10 kHz", "type": "mass"}
    (warning,) = mass_damping_warnings(resolve(raw))
    # alpha = 2 zeta w = 2513 1/s; at the body's 5 m/s: 12566 m/s^2
    assert "body bar" in warning and "alpha = 2513 1/s" in warning and "1.257e+04 m/s^2" in warning
    raw["boundary"] = [{"region": "bar.bottom", "type": "fixed"}]
    assert mass_damping_warnings(resolve(raw)) == []
    raw["damping"]["type"] = "stiffness"
    raw.pop("boundary")
    assert mass_damping_warnings(resolve(raw)) == []

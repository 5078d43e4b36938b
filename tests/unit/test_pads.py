"""The pads' materials and their sizing within limits (``shockfem/machine/pad_materials.py``, ``pads.py``); the
finite-element restitution runs are in ``tests/sim/test_pads.py``."""
import math

import pytest

from shockfem.amplifier import rigid
from shockfem.amplifier.interfaces import HERTZ_YIELD_PRESSURE
from shockfem.machine.amplifier import choose_pad
from shockfem.machine.pad_materials import (PAD_MATERIALS, neo_hookean_energy, neo_hookean_stress, pad_material,
                                            plastic_work)
from shockfem.machine.pads import CROWN_CONTACT, Interface, RunCache, interface_scene, size_pad
from shockfem.scene import resolve
from shockfem.scene.library import property_si

STEEL = "high_strength_steel"
# the 12 lb machine's first interface as the 2% design has it (4773 kg on 1600 kg at 99 m/s)
FIRST = Interface("m1_m2", 4772.5, 0.914, 0.926, 1599.6, 0.638, 0.638, 99.1, STEEL, 460e6)
# a small one that an elastomer pad takes inside its limits (2 kg on 2 kg at 3 m/s)
SMALL = Interface("a_b", 2.0, 0.06, 0.09, 2.0, 0.06, 0.09, 3.0, STEEL, 460e6)


def test_every_material_has_its_limits_and_a_source():
    for m in PAD_MATERIALS.values():
        assert m.source
        if m.kind in ("elastomer", "yielding metal"):
            assert m.working_strain > 0 and m.heat_capacity > 0 and m.temperature_rise > 0 and m.slenderness > 0
        if m.kind == "elastomer":
            assert m.working_stress > 0 and 0 < m.resilience < 1
        if m.kind == "yielding metal":
            assert m.hardening[0] == (0.0, m.yield_stress)
    with pytest.raises(ValueError, match="pad material must be one of"):
        pad_material("granite")


def test_damping_ratio_restitutes_the_rebound_resilience():
    """Rigid masses on the never-pulling spring-dashpot of the ratio restitute sqrt(R) (to the root's 1e-12)."""
    for m in PAD_MATERIALS.values():
        if m.resilience:
            assert rigid.pad_restitution(m.damping_ratio()) == pytest.approx(math.sqrt(m.resilience), abs=1e-9)


def test_neo_hookean_stress_is_the_energy_derivative_and_hooke_at_small_strain():
    G = 20e6
    for strain in (0.01, 0.1, 0.3):
        h = 1e-6
        dW = (neo_hookean_energy(G, strain + h) - neo_hookean_energy(G, strain - h)) / (2 * h)
        # central difference: error of order h^2 times the third derivative, far below 1e-6
        assert neo_hookean_stress(G, strain) == pytest.approx(dW, rel=1e-6)
    # small strain: E = 3 G, the first-order term; the next is 3 G strain^2 (0.3% at 0.1%)
    assert neo_hookean_stress(G, 1e-3) == pytest.approx(3 * G * 1e-3, rel=2e-3)


def test_plastic_work_of_a_flat_curve():
    """A flow stress held at 100 MPa over a crush to 50%: 100 MPa times the true strain ln 2 (midpoint rule,
    exact for a constant)."""
    from dataclasses import replace
    flat = replace(pad_material("copper_annealed"), yield_stress=100e6, hardening=((0.0, 100e6), (1.0, 100e6)))
    assert plastic_work(flat, 0.5) == pytest.approx(100e6 * math.log(2), rel=1e-12)


def test_an_elastomer_pad_stores_the_interface_energy_at_its_working_point():
    pad = size_pad(FIRST, "pu_95a", 0.6)
    mat = pad_material("pu_95a")
    G = mat.youngs_modulus / 3
    area = math.pi * pad.diameter ** 2 / 4
    strain = pad.travel / pad.thickness
    assert neo_hookean_energy(G, strain) * area * pad.thickness == pytest.approx(FIRST.energy, rel=1e-12)
    assert pad.diameter == pytest.approx(FIRST.face_diameter)
    assert neo_hookean_stress(G, strain) <= mat.working_stress * (1 + 1e-9) and strain <= mat.working_strain
    limits = {lim.quantity: lim for lim in pad.limits}
    # 5.9 MJ in polyurethane at about 1.2 MJ/m^3: a pad 15 m long on a 0.64 m face
    assert not limits["slenderness"].holds
    assert limits["slenderness"].value == pytest.approx(pad.thickness / pad.diameter)
    assert limits["temperature rise a shot"].value == pytest.approx(
        (1 - 0.36) * FIRST.energy / (pad.mass * mat.heat_capacity), rel=1e-12)
    assert not pad.feasible


def test_a_small_interface_takes_an_elastomer_inside_every_limit():
    pad, table = choose_pad(SMALL)
    assert pad.feasible and pad.kind == "elastomer"
    assert {t["material"] for t in table} == set(PAD_MATERIALS)
    # the best-restituting of those that hold: 90A's resilience (0.45) is the highest
    assert pad.material == "pu_90a"


def test_a_metal_disc_spreads_to_the_face_and_absorbs_the_energy():
    e = 0.1
    pad = size_pad(FIRST, "copper_annealed", e)
    mat = pad_material("copper_annealed")
    crushed_area = math.pi * pad.diameter ** 2 / 4 / (1 - mat.working_strain)
    assert crushed_area == pytest.approx(FIRST.face_area, rel=1e-12)
    assert plastic_work(mat, mat.working_strain) * pad.mass / mat.density == pytest.approx(
        (1 - e * e) * FIRST.energy, rel=1e-12)


def test_crowned_face_at_its_yield_onset_and_flat_faces_at_the_impedance_stress():
    rho = property_si(STEEL, "density", "density")
    E = property_si(STEEL, "youngs_modulus", "pressure")
    crowned = size_pad(FIRST, "crowned_steel")
    e_star = E / (2 * (1 - 0.3 ** 2))
    Y = 690e6
    # at the onset the Hertz pressure p0 = 2 E* a / (pi R) is 1.6 Y with a = CROWN_CONTACT of the face's radius
    a = CROWN_CONTACT * FIRST.face_diameter / 2
    assert 2 * e_star * a / (math.pi * crowned.crown) == pytest.approx(HERTZ_YIELD_PRESSURE * Y, rel=1e-12)
    flat = size_pad(FIRST, "none")
    z = [rho * math.sqrt(E / rho) * math.pi * d * d / 4 for d in (FIRST.striker_diameter, FIRST.struck_diameter)]
    assert flat.limits[0].value == pytest.approx(FIRST.speed * z[0] * z[1] / (z[0] + z[1]) / FIRST.face_area)
    assert not flat.feasible and not crowned.feasible        # 99 m/s on steel yields it either way


def test_interface_scene_gives_each_body_its_chain_mass():
    """The scene's bodies weigh what the interface says (the housing's oil smeared into its wall)."""
    iface = Interface("m4_striker", 179.7, 0.308, 0.308, 60.2, 0.1, 1.76, 300.0, STEEL, 460e6)
    pad = size_pad(iface, "copper_annealed", 0.1)
    scene = resolve(interface_scene(iface, pad, "smoke"))
    from shockfem.parts.catalog import PARTS
    masses = {b.name: scene.material_of(b).rho * PARTS[b.shape].volume(b.dims, 3) for b in scene.bodies}
    assert masses["a"] == pytest.approx(179.7, rel=1e-12) and masses["b"] == pytest.approx(60.2, rel=1e-12)
    assert masses["pad"] == pytest.approx(pad.mass, rel=1e-12)


def test_run_cache_keys_round_the_interface(tmp_path):
    cache = RunCache(str(tmp_path))
    near = Interface(**{**FIRST.__dict__, "speed": 99.1001})
    pads = [size_pad(i.rounded(), "pu_95a", 0.6) for i in (FIRST, near)]
    assert cache.key(FIRST.rounded(), pads[0], "smoke") == cache.key(near.rounded(), pads[1], "smoke")
    assert cache.key(FIRST.rounded(), pads[0], "smoke") != cache.key(FIRST.rounded(), pads[0], "coarse")


def test_plastic_restitution_is_johnsons_law():
    """Johnson's form e = C (Y / E*)^(1/2) (W / (Y R^3))^(-1/8), C = (18 pi / 5)^(1/2) (3 pi / 4)^(1/8), from the
    two steps it is derived from (to round-off), and its V^(-1/4)."""
    from shockfem.amplifier.interfaces import plastic_restitution
    m, R, E_star, Y, v = 0.0329, 0.01, 2.3e11, 1e9, 5.0
    C = math.sqrt(18 * math.pi / 5) * (3 * math.pi / 4) ** 0.125
    assert C == pytest.approx(3.74, abs=0.005)
    W = 0.5 * m * v * v
    assert plastic_restitution(v, m, R, E_star, Y) == pytest.approx(
        C * math.sqrt(Y / E_star) * (W / (Y * R ** 3)) ** -0.125, rel=1e-12)
    assert plastic_restitution(2 * v, m, R, E_star, Y) / plastic_restitution(v, m, R, E_star, Y) == pytest.approx(
        2 ** -0.25, rel=1e-12)


def test_estimate_resolution_runs_nothing(tmp_path):
    """Pad resolution "estimate": the material's estimate, sqrt(R) for an elastomer, no run directory."""
    m, pad = RunCache(str(tmp_path)).measure(SMALL, "pu_95a", "estimate")
    assert not m.ran and m.restitution == pytest.approx(math.sqrt(0.40), rel=1e-12)
    assert "estimate" in m.note and list(tmp_path.iterdir()) == [tmp_path / "pad_runs.json"]


def test_thorntons_restitution_is_one_at_the_yield_onset_and_below_johnsons_above_it():
    """Thornton's form at dv = V_y: (6 sqrt(3) / 5)^(1/2) (5/6)^(1/2) (1/3)^(1/4) = 1 exactly (an elastic
    impact); far above it, below Johnson's estimate (pressure capped at 1.6 Y, not 3 Y) and going as
    V^(-1/4) (x -> 0)."""
    from shockfem.amplifier.interfaces import hertz_yield_speed, plastic_restitution, thornton_restitution
    m, R, E_star, Y = 0.0329, 0.01, 2.3e11, 1e9
    v_y = hertz_yield_speed(m, R, E_star, Y)
    assert thornton_restitution(v_y, m, R, E_star, Y) == pytest.approx(1.0, rel=1e-12)
    far = [thornton_restitution(k * v_y, m, R, E_star, Y) for k in (1e4, 2e4)]
    assert far[1] / far[0] == pytest.approx(2 ** -0.25, rel=1e-4)
    assert far[0] < plastic_restitution(1e4 * v_y, m, R, E_star, Y)


def test_the_sizing_says_where_it_leaves_its_range():
    """A pad as wide as the face (the 12 lb machine's first interface) is past FACE_SHARE_RANGE, where the
    runs read 1.4 to 5.6 times the closed form; the small interface's pad (a quarter as thick as it is wide,
    narrower than the face) is inside it; a metal disc carries no such range."""
    from shockfem.machine.pads import FACE_SHARE_RANGE, sizing_range
    wide = size_pad(FIRST, "pu_95a", 0.6)
    assert wide.diameter / FIRST.face_diameter > FACE_SHARE_RANGE and "outside its range" in sizing_range(FIRST, wide)
    small = size_pad(SMALL, "pu_90a", 0.67)
    assert small.diameter / SMALL.face_diameter <= FACE_SHARE_RANGE and sizing_range(SMALL, small) == ""
    assert sizing_range(FIRST, size_pad(FIRST, "copper_annealed", 0.1)) == ""

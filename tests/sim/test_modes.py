"""Modal analysis: frequencies against closed forms, free and held, and the command."""
import json
import math
import os
import subprocess
import sys

import numpy as np
import pytest

from shockfem.geometry import build_mesh
from shockfem.modal.eigen import body_modes
from shockfem.modal.labels import label_modes, principal_axis
from shockfem.scene import resolve
from shockfem.scene import load_scene
from shockfem.verify.scenes import rayleigh_love_f1

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCENE = os.path.join(REPO, "studies", "modes", "rod.toml")
C0 = math.sqrt(210e9 / 7850)


def _rod_modes(overrides=(), constrained=True, count=4):
    scene = load_scene(SCENE, ['bodies.rod.element_size="4 mm"', *overrides])
    meshed = build_mesh(scene)
    modes = body_modes(scene, meshed, "rod", count, 1, constrained)
    return modes, label_modes(modes, meshed.cell_tags.find(1))


def test_free_rod_longitudinal_modes():
    modes, labels = _rod_modes()
    assert modes.rigid == 1                           # axisymmetric: the translation along z
    assert [lab["label"] for lab in labels[:3]] == ["longitudinal"] * 3
    # Rayleigh-Love 12,923 Hz; linear elements with consistent mass: 0.02% above at 4 mm
    assert modes.frequencies[0] == pytest.approx(rayleigh_love_f1(0.01, 0.2), rel=2e-3)
    assert modes.frequencies[1] == pytest.approx(2 * modes.frequencies[0], rel=5e-3)


def test_fixed_end_gives_the_quarter_wave_rod(tmp_path):
    scene_file = tmp_path / "fixed.toml"
    scene_file.write_text(open(SCENE).read() + '\n[[boundary]]\nregion = "rod.bottom"\ntype = "fixed"\n')
    scene = load_scene(str(scene_file), ['bodies.rod.element_size="4 mm"'])
    meshed = build_mesh(scene)
    modes = body_modes(scene, meshed, "rod", 2, 1, True)
    assert modes.rigid == 0 and modes.conditions == ["rod.bottom fixed"]
    # fixed-free: c0 / (4 L) = 6,465 Hz, then 3 c0 / (4 L); lateral inertia lowers them slightly
    assert modes.frequencies[0] == pytest.approx(C0 / (4 * 0.2), rel=5e-3)
    assert modes.frequencies[1] == pytest.approx(3 * C0 / (4 * 0.2), rel=1e-2)
    free = body_modes(scene, meshed, "rod", 1, 1, constrained=False)
    assert free.rigid == 1 and free.frequencies[0] == pytest.approx(C0 / (2 * 0.2), rel=5e-3)


def test_symmetry_end_is_the_half_of_a_free_rod_twice_as_long(tmp_path):
    """A symmetry plane at the bottom (u_z = 0, free to slide radially) makes the rod half of a
    free-free rod of length 2 L: its first mode is that rod's, c0 / (4 L); the second, 3 c0 / (4 L)."""
    scene_file = tmp_path / "symmetry.toml"
    scene_file.write_text(open(SCENE).read() + '\n[[boundary]]\nregion = "rod.bottom"\ntype = "symmetry"\n')
    scene = load_scene(str(scene_file), ['bodies.rod.element_size="4 mm"'])
    modes = body_modes(scene, build_mesh(scene), "rod", 2, 1, True)
    assert modes.rigid == 0 and modes.conditions == ["rod.bottom held along z"]
    assert modes.frequencies[0] == pytest.approx(rayleigh_love_f1(0.01, 0.4), rel=2e-3)
    assert modes.frequencies[1] == pytest.approx(3 * rayleigh_love_f1(0.01, 0.4), rel=1e-2)


def test_modes_command_writes_json_and_xdmf(tmp_path):
    out = tmp_path / "modes"
    p = subprocess.run([sys.executable, "-m", "shockfem", "modes", SCENE, "--count", "3", "--out", str(out),
                        "--set", 'bodies.rod.element_size="4 mm"'], capture_output=True, text=True, timeout=600)
    assert p.returncode == 0, p.stderr
    data = json.load(open(out / "modes.json"))
    assert [m["label"] for m in data["modes"]] == ["longitudinal"] * 3
    assert data["boundary"] == "free-free" and data["first"]["longitudinal"] == data["modes"][0]["frequency_hz"]
    assert (out / "modes.xdmf").exists() and (out / "modes.h5").stat().st_size > 1000
    p = subprocess.run([sys.executable, "-m", "shockfem", "modes", SCENE, "--body", "anvil"],
                       capture_output=True, text=True, timeout=600)
    assert p.returncode == 2 and "--body: unknown body 'anvil'" in p.stderr and "Traceback" not in p.stderr


@pytest.mark.parametrize("size", [[0.2, 0.02, 0.03], [0.03, 0.02, 0.2]], ids=["along_x", "along_z"])
def test_a_beam_is_labelled_by_its_own_axis(size):
    """A free steel box beam 200 x 20 x 30 mm lying along x (then along z): its first elastic mode is
    bending about the weak axis (Euler-Bernoulli free-free 22.37 sqrt(E I / (rho A L^4)) / 2 pi =
    2,658 Hz for the 20 mm depth; measured 2,570 Hz with P2 hexes), labelled "bending" whichever way
    the beam lies (labelled "torsional" along x when the labels took z as every body's axis)."""
    raw = {"scene": {"kinematics": "3d", "end_time": 1e-3, "element": "hex"},
           "materials": {"steel": {"density": 7850, "youngs_modulus": 210e9, "poisson_ratio": 0.3}},
           "bodies": [{"name": "beam", "material": "steel", "shape": "box", "size": size,
                       "element_size": 0.005, "position": [0, 0, 0]}]}
    scene = resolve(raw)
    meshed = build_mesh(scene)
    modes = body_modes(scene, meshed, "beam", 2, 2, True)         # P2: no shear locking in bending
    labels = label_modes(modes, meshed.cell_tags.find(1))
    assert labels[0]["label"] == "bending"
    depth = 0.02
    f_bending = 22.373 / (2 * math.pi) * math.sqrt(210e9 * depth ** 2 / 12 / 7850) / 0.2 ** 2
    # at L / h = 10, shear and rotary inertia (Timoshenko) lower the first free-free bending mode by
    # a few percent below Euler-Bernoulli: within 5%
    assert modes.frequencies[0] == pytest.approx(f_bending, rel=0.05)


def test_principal_axis_of_a_rod_and_a_disc():
    rng = np.random.default_rng(1)
    rod = rng.uniform(-1, 1, (2000, 3)) * [0.1, 1.0, 0.1]            # long in y
    disc = rng.uniform(-1, 1, (2000, 3)) * [1.0, 1.0, 0.05]          # thin in z
    assert abs(principal_axis(rod) @ [0, 1, 0]) == pytest.approx(1, abs=1e-3)
    assert abs(principal_axis(disc) @ [0, 0, 1]) == pytest.approx(1, abs=1e-3)


def test_a_band_damped_rods_modes_say_where_they_ring_and_how_fast_they_decay(tmp_path):
    """With 2% over 5 to 100 kHz (moduli at its centre, 22.4 kHz) the first longitudinal mode (12.9 kHz, in the
    band) is damped at 2% within the fit's ripple and rings lower, as the band's dispersion says; the
    command writes both, and the step the mesh check reports is the solver's own."""
    from shockfem.geometry.quality import mesh_quality
    from shockfem.materials.band_damping import RIPPLE, fit_band
    from shockfem.model import build_model
    from shockfem.modal.output import write_modes
    from shockfem.solver.explicit import ExplicitSolver
    band = 'bodies.rod.damping={type="band", ratio=0.02, low="5 kHz", high="100 kHz"}'
    scene = load_scene(SCENE, ['bodies.rod.element_size="4 mm"', band])
    meshed = build_mesh(scene)
    modes = body_modes(scene, meshed, "rod", 2, 1, True)
    data = write_modes(str(tmp_path), modes, label_modes(modes, meshed.cell_tags.find(1)))
    first = data["modes"][0]
    terms = fit_band(0.02, 5e3, 1e5)
    assert first["in_band"] and first["damping_ratio"] == pytest.approx(0.02, rel=RIPPLE)
    ref = math.sqrt(5e3 * 1e5)
    assert first["damped_frequency_hz"] == pytest.approx(
        first["frequency_hz"] * math.sqrt(terms.dispersion(first["damped_frequency_hz"], ref)), rel=1e-12)
    assert first["damped_frequency_hz"] < first["frequency_hz"] and data["damping"].startswith("band")
    # the mesh check's step: relaxed moduli and the terms' factor, as the solver takes it (same lengths,
    # same formula: round-off); 0.957 of the undamped scene's (the band's step_scale at its centre)
    plain = load_scene(SCENE, ['bodies.rod.element_size="4 mm"'])
    solver = ExplicitSolver(build_model(scene, meshed))
    q = mesh_quality(scene, meshed)[0]
    assert q.stable_step == pytest.approx(solver.stable_step(), rel=1e-9)
    assert q.stable_step / mesh_quality(plain, meshed)[0].stable_step == pytest.approx(terms.step_scale(ref),
                                                                                       rel=1e-12)

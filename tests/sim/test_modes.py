"""Modal analysis: frequencies against closed forms, free and held, and the command."""
import json
import math
import os
import subprocess
import sys

import pytest

from shockfem.geometry import build_mesh
from shockfem.modal.eigen import body_modes
from shockfem.modal.labels import label_modes
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

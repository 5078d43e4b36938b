"""The stress along a body (``outputs.sections``) as a run writes it: history columns and the summary's
envelope, on the rod impact of ``studies/metrics/rod_pulse.toml`` (two equal steel rods at 1 m/s: the
struck rod carries the 1D step rho c0 V / 2 until its free end's reflection returns, elementary bar
theory; penalty contact and the rods' radial inertia move its plateau's mean by 0.1%)."""
import json
import math
import os

import numpy as np
import pytest

from shockfem.output.history_file import read_history_csv
from shockfem.runner import run_scene
from shockfem.scene import read_toml, resolve

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def test_sections_record_the_struck_rods_axial_step(tmp_path):
    raw = read_toml(os.path.join(REPO, "studies", "metrics", "rod_pulse.toml"))
    for b in raw["bodies"]:
        b["element_size"] = "1 mm"
    raw["outputs"]["sections"] = [{"body": "target", "count": 10}]
    run_scene(resolve(raw), str(tmp_path / "run"), progress=False, quiet=True, write_fields=False)
    s = json.loads((tmp_path / "run" / "summary.json").read_text())["sections"]["target"]
    assert s["position"] == pytest.approx([0.005 + 0.01 * k for k in range(10)], rel=1e-9)
    assert s["area"][4] == pytest.approx(math.pi * 0.0025 ** 2, rel=1e-3)      # the ring's, 2 pi r included
    h = read_history_csv(str(tmp_path / "run" / "history.csv"))
    t, mid = h["time"], h["section.target.4.axial_stress"]                    # the slab 40-50 mm up
    step = -7850 * math.sqrt(210e9 / 7850) * 1.0 / 2
    # contact at 10 us (the 0.01 mm gap), the front down at the slab (55 mm from the struck end) 10.6 us
    # later; the free far end's reflection relieves it 2 x 45 mm / c0 = 17.4 us after that
    plateau = (t > 23e-6) & (t < 36e-6)
    assert np.mean(mid[plateau]) == pytest.approx(step, rel=0.01)      # 0.1% measured
    assert min(s["max_axial_compression"]) == pytest.approx(np.min([h[f"section.target.{k}.axial_stress"]
                                                                   for k in range(10)]), rel=1e-12)
    assert max(s["max_bending"]) == 0.0                                         # axisymmetric: none

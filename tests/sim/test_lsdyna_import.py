"""An imported LS-DYNA deck runs as its TOML scene does: the two-rod deck (a segment-set contact, another
unit set) at a coarse mesh over the first contact, and the block-on-plate test deck (MAT_003 with rates,
MAT_024 with a curve, friction, a fixed base, mass scaling) through ``shockfem run``."""
import math
import os
import pathlib

import numpy as np
import pytest

from shockfem.cli import main
from shockfem.verify.lsdyna_cases import deck_and_scene
from shockfem.verify.scenes import solve

DECKS = pathlib.Path(__file__).parents[1] / "unit" / "importers" / "decks"
# Deck against scene: the same mesh in the same order and the same numbers in m-ms-kg-MN, so the runs differ
# by the unit conversion's round-off carried through the steps; 1e-9 relative would catch any real difference
# in the mapping (a penalty or damping off by a factor changes these by percents)
ROUND_OFF = 1e-9


def test_two_rod_deck_runs_as_its_scene(tmp_path):
    raw, raw_deck = deck_and_scene("two_rods", 0.0125, str(tmp_path))
    for r in (raw, raw_deck):
        r["scene"]["end_time"] = 60e-6             # the striker's wave reaches its far end and back: 2 L / c0 = 39 us
    toml, _ = solve(raw, cache_dir=str(tmp_path))
    deck, _ = solve(raw_deck, cache_dir=str(tmp_path))
    assert deck.step == toml.step
    v_toml, _ = toml.body_means()
    v_deck, _ = deck.body_means()
    assert np.allclose(v_deck, v_toml, rtol=ROUND_OFF, atol=ROUND_OFF * 10.0)    # 10 m/s striker
    assert v_toml[1, -1] < -1.0                     # the target was struck: the contact acted
    for k in ("kinetic", "internal", "contact"):
        a, b = getattr(deck.energy, k), getattr(toml.energy, k)
        assert math.isclose(a, b, rel_tol=ROUND_OFF, abs_tol=ROUND_OFF * toml.energy.initial), k


def test_block_deck_runs(tmp_path, capsys):
    scene = tmp_path / "block.toml"
    assert main(["import", str(DECKS / "block_plain.k"), "--out", str(scene), "--units", "mm-ms-kg-kN"]) == 0
    assert main(["run", str(scene), "--out", str(tmp_path / "run"), "--no-progress", "--no-fields"]) == 0
    assert os.path.exists(tmp_path / "run" / "summary.json")

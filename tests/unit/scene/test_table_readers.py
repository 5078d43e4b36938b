"""The scene is read one table at a time (``scene/schema.py``'s ``resolve`` calls each reader in turn): each
reader stands alone on its own table, and together they fill every field of ``Scene`` once."""
import dataclasses

import pytest

from shockfem.scene.boundaries import read_boundaries
from shockfem.scene.checker import Checker
from shockfem.scene.outputs import read_outputs
from shockfem.scene.settings import read_settings
from shockfem.scene.specs import Boundary, Scene

# the fields ``resolve`` passes besides [scene]'s settings: one per table reader ([scene.preload] has its
# own reader, ``scene/preload.py``: it needs the boundaries and contacts read first)
TABLE_FIELDS = {"materials", "bodies", "boundaries", "contacts", "damping", "outputs", "springs", "shock",
                "cavities", "penetration", "preload"}
# what ``resolve`` fills itself: where the scene was read from
RESOLVED_FIELDS = {"folder"}


def test_settings_and_the_tables_fill_every_field_of_the_scene_once():
    settings = read_settings(Checker(), {"scene": {"kinematics": "axisymmetric", "end_time": "1 ms"}})
    fields = {f.name for f in dataclasses.fields(Scene)}
    assert set(settings) | TABLE_FIELDS | RESOLVED_FIELDS == fields and not set(settings) & TABLE_FIELDS


def test_settings_in_si_with_their_defaults():
    ck = Checker()
    s = read_settings(ck, {"scene": {"kinematics": "3d", "end_time": "2 ms", "gravity": [0, 0, -9.81]}})
    assert ck.problems == []
    # the defaults ``docs/scenes.md`` gives: a tenth of the end time between checkpoints, 0.9 of the step
    assert s["end_time"] == pytest.approx(2e-3) and s["checkpoint_interval"] == pytest.approx(2e-4)
    assert s["safety_factor"] == 0.9 and s["element"] == "hex" and s["gravity"] == (0.0, 0.0, -9.81)


def test_settings_collect_every_problem():
    ck = Checker()
    read_settings(ck, {"scene": {"kinematics": "4d", "end_time": "-1 s", "safety_factor": 2, "colour": "red"}})
    paths = sorted(p.split(":")[0] for p in ck.problems)
    assert paths == ["scene.colour", "scene.end_time", "scene.kinematics", "scene.safety_factor"], ck.problems


def test_a_boundary_on_its_own():
    ck = Checker()
    regions = {"bar": ("bottom", "top", "side")}
    raw = {"boundary": [{"region": "bar.bottom", "type": "velocity", "direction": "z", "value": "2 m/s"},
                        {"region": "bar.nowhere", "type": "fixed"}]}
    out = read_boundaries(ck, raw, regions, "axisymmetric")
    assert out[0] == Boundary("bar.bottom", "velocity", (1,), ((0.0, 2.0),))
    assert len(ck.problems) == 1 and ck.problems[0].startswith("boundary[1].region")


def test_outputs_default_to_ten_frames_and_a_row_every_step():
    ck = Checker()
    out = read_outputs(ck, {}, bodies=(), end_time=1e-3)
    assert ck.problems == [] and out.field_interval == pytest.approx(1e-4) and out.history_interval == 0.0

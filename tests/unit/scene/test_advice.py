"""Warnings of valid scenes, before they run (``shockfem check``) and in the run's summary."""
import os

import tomllib

from shockfem.api import check_raw
from shockfem.scene import resolve
from shockfem.scene.advice import scene_warnings

GALLERY = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))),
                       "studies", "gallery")


def _raw(name):
    with open(os.path.join(GALLERY, name), "rb") as fh:
        return tomllib.load(fh)


def test_an_interference_pushed_onto_split_cone_segments_is_warned_of():
    """The gallery's cone drop shrinks a ring (0.02 mm, pushed out over 100 us) onto a split cone of 4
    segments, which no hoop stress holds: check says so, naming the contact, the body and the fix."""
    (warning,) = scene_warnings(resolve(_raw("cone_drop.toml")))
    assert warning.startswith("contact clamp:") and "body cone" in warning and "4 segments" in warning
    assert "leave the contact's interference out" in warning
    heard = []
    check_raw(_raw("cone_drop.toml"), warn=heard.append)
    assert warning in heard


def test_a_shrink_fit_on_a_solid_shaft_and_a_cone_without_a_fit_are_not():
    assert scene_warnings(resolve(_raw("shrink_fit.toml"))) == []
    raw = _raw("cone_drop.toml")
    del raw["contact"][0]["interference"]           # the ring starts in contact, without a preload
    assert scene_warnings(resolve(raw)) == []
    heard = []
    check_raw(raw, warn=heard.append)
    assert not any("split cone" in w for w in heard)


def test_a_preload_stage_takes_the_warning_away_and_the_warning_names_it():
    """With ``[scene.preload]`` the fit settles before the event (``solver/preload.py``): nothing to warn of;
    without, the warning gives the stage as the first fix."""
    raw = _raw("cone_drop.toml")
    (warning,) = scene_warnings(resolve(raw))
    assert "Add a [scene.preload] stage" in warning
    raw["scene"]["preload"] = {"duration": "500 us"}
    assert scene_warnings(resolve(raw)) == []

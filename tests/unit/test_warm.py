"""``shockfem warm``: its families name scenes that exist, and a wrong name is an input error."""
import os

import pytest

from shockfem import warm
from shockfem.cli import main
from shockfem.errors import EXIT_BAD_INPUT, ModelError


def test_every_family_scene_is_a_studies_file_or_a_named_scene():
    # a scene of studies/ renamed or moved would silently drop its kernels from the warm-up
    named = {"taylor_3d", "two_rods_3d", "tet_rod"}
    for family, scenes in warm.FAMILIES.items():
        for scene in scenes:
            assert scene in named or os.path.isfile(os.path.join(warm.STUDIES, scene)), (family, scene)


def test_named_scenes_build_as_raw_scenes():
    for name in ("taylor_3d", "two_rods_3d", "tet_rod"):
        raw = warm._scene(name)
        assert raw["scene"]["kinematics"] == "3d", name


def test_unknown_scene_is_a_clear_input_error(capsys):
    with pytest.raises(ModelError, match="no scene file 'nowhere.toml'"):
        warm.warm(["nowhere.toml"])
    assert main(["warm", "nowhere.toml"]) == EXIT_BAD_INPUT
    assert "give a scene file" in capsys.readouterr().err

"""The fixture study's reading of a run's tracked peak von Mises stress: where and when, as its tables
print it beside each stress over yield."""
from types import SimpleNamespace

import pytest

from shockfem.programmer.dashpot_design import DASHPOT
from shockfem.study.fixture.dashpot import FLOOR, article_base_height, dashpot_design, dashpot_scene
from shockfem.study.fixture.runs import peak_where_when


def _run(at, time):
    return SimpleNamespace(summary={"bodies": {"article": {"max_von_mises": 1.2e9, "max_von_mises_at": at,
                                                           "max_von_mises_time": time}}})


def test_axisymmetric_peak_is_read_as_radius_height_above_the_base_and_time():
    # a cell centre at r = 29.5 mm, 4.25 mm above a base at z = 1.3 m, reached at 0.412 ms
    assert peak_where_when(_run([0.0295, 1.30425], 4.12e-4), "article", 1.3) == "r 29.5, z 4.2 at 0.412"


def test_3d_peak_takes_the_radius_about_the_axis():
    # (x, y) = (18, 24) mm is 30 mm from the z axis
    assert peak_where_when(_run([0.018, -0.024, 0.5], 1e-3), "article", 0.5) == "r 30.0, z 0.0 at 1.000"


def test_a_body_that_carried_no_stress_has_no_where():
    assert peak_where_when(_run(None, None), "article") == "-"


def test_the_base_height_is_where_the_scene_stands_the_article():
    """The height the tables measure from is the piston's top in the scene the study runs, on which the
    article's base stands: the floor, the column and the piston."""
    d = dashpot_design("rectangle")
    assert article_base_height(d) == pytest.approx(FLOOR + d["column"] + DASHPOT["piston_thickness"], rel=1e-15)
    scene = dashpot_scene(d, "rectangle", {"h_article": 0.006, "h_pad": 0.03, "end_margin": 1.3})
    piston = next(b for b in scene["bodies"] if b["name"] == "piston")
    assert piston["position"][1] + piston["length"] == pytest.approx(article_base_height(d), rel=1e-15)

"""The article's peak base stress on the piston (``programmer.article_base``), by hand."""
import math

import numpy as np
import pytest

from shockfem.programmer.article_base import RAYLEIGH_LOVE, Article, base_stress
from shockfem.units import G0

# the study's 12 lb article: 60 mm calibre, 281.4 mm long (``study.fixture.common.article_length``), of
# steel_4340 in the scene library: E 200 GPa, rho 7830 kg/m^3, nu 0.29, initial yield 792 MPa
ARTICLE = Article(0.030, 0.2814, "steel_4340")
C = math.sqrt(200e9 / 7830.0)                  # 5054 m/s
PERIOD = 4 * 0.2814 / C                        # the clamped-free bar's first period, 222.7 us
MASS = 12 * 0.45359237


def test_the_first_period_and_its_rayleigh_love_correction_by_hand():
    """4 L / c of a clamped-free bar; Rayleigh-Love's (nu k r_g)^2 / 2, k = pi / (2 L), r_g = R / sqrt(2):
    (0.29 x 5.582 /m x 0.02121 m)^2 / 2 = 5.90e-4."""
    assert ARTICLE.first_period() == pytest.approx(222.7e-6, rel=1e-3)
    assert ARTICLE.rayleigh_love() == pytest.approx(5.90e-4, rel=2e-3)
    assert ARTICLE.rayleigh_love() < RAYLEIGH_LOVE


def test_a_ramped_step_is_the_ramps_factor_over_the_bearing():
    """A rise of half the article's period to 10,000 g, held: an undamped oscillator's largest response to
    a ramp of rise t_r held is 1 + |sin x| / x, x = pi t_r / T (Biggs, Introduction to Structural
    Dynamics, 2.3): 1 + 2 / pi = 1.6366 at t_r = T / 2 (at the wrong period, 2 L / c, it would be 1.0).
    On the article's 60 mm base (the bore wider): 5.443 kg x 10,000 g / (pi 0.03^2) = 188.9 MPa, times the
    factor 309.1 MPa, 0.390 of 792 MPa."""
    t = np.linspace(0.0, 20 * PERIOD, 40001)
    a = 1e4 * G0 * np.clip(t / (0.5 * PERIOD), 0.0, 1.0)
    out = base_stress(t, a, MASS, ARTICLE, 0.040)
    assert out["bearing_radius"] == 0.030
    assert out["mean_stress"] == pytest.approx(MASS * 1e4 * G0 / (math.pi * 0.03 ** 2), rel=1e-12)
    assert out["mean_stress"] == pytest.approx(188.9e6, rel=1e-3)
    assert out["dynamic_factor"] == pytest.approx(1 + 2 / math.pi, rel=1e-3)
    assert out["stress"] == pytest.approx(309.1e6, rel=2e-3)
    assert out["ratio"] == pytest.approx(309.1 / 792, rel=2e-3) and out["holds"] and out["in_range"]


def test_a_narrower_bore_bears_on_its_plunger_and_the_broken_check_says_so():
    """A bore of 15 mm radius under the 30 mm base: the bearing is the plunger's, 4 times the stress; a step
    (factor 2) of 10,000 g over it: 188.9 x 4 x 2 = 1511 MPa, 1.91 of yield, the check broken."""
    t = np.array([0.0, 1e-12, 20 * PERIOD])
    a = np.array([0.0, 1e4 * G0, 1e4 * G0])
    out = base_stress(t, a, MASS, ARTICLE, 0.015)
    assert out["bearing_radius"] == 0.015
    assert out["stress"] == pytest.approx(1511e6, rel=1e-3)
    assert not out["holds"]
    broken = [lim for lim in out["limits"] if not lim["holds"]]
    assert [lim["name"].split(" (")[0] for lim in broken] == ["article base stress over its yield"]


def test_the_designers_verdict_lists_the_broken_article_check():
    """``column_design``'s verdict on the previous test's step: "inside" becomes "the article yields"; a
    verdict another check set stays (its first cause), the article's check beside it."""
    from types import SimpleNamespace

    from shockfem.programmer.column_design import _check_article
    run = SimpleNamespace(t=np.array([0.0, 1e-12, 20 * PERIOD]), acceleration=np.array([0.0, 1e4 * G0, 1e4 * G0]))
    for verdict, kept in (("inside", "the article yields"), ("fails the band", "fails the band")):
        out = {"runs": {"column": run}, "design": {"article_mass": MASS, "bore_radius": 0.015}, "verdict": verdict}
        _check_article(out, ARTICLE)
        assert out["verdict"] == kept and out["article_base"]["ratio"] == pytest.approx(1511 / 792, rel=1e-3)
    wide = {"runs": {"column": run}, "design": {"article_mass": MASS, "bore_radius": 0.040}, "verdict": "inside"}
    _check_article(wide, ARTICLE)
    assert wide["verdict"] == "inside"               # 378 MPa on the 30 mm base: 0.48 of yield

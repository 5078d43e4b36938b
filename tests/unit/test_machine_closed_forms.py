"""The whole machine's closed forms and its input checks (``shockfem/machine``); the end-to-end design runs
in ``tests/sim/test_machine.py``."""
import math

import pytest

from shockfem.amplifier import rigid
from shockfem.machine.fixture import floor_thickness, housing_wall
from shockfem.machine.layout import stop_for
from shockfem.machine.spec import REFERENCE_ARTICLE, read_spec
from shockfem.scene import SceneError
from shockfem.units import G0, LB


def test_spec_reads_units_and_scales_the_article():
    s = read_spec({"article": "100 lb", "peak": "5000 gee", "duration": "4 ms", "launch": "100 m/s"})
    assert s.article_mass == pytest.approx(100 * LB, rel=1e-12)
    assert s.pulse.peak == pytest.approx(5000 * G0, rel=1e-12)
    assert s.pulse.duration == pytest.approx(4e-3, rel=1e-12)
    # geometric similarity with the fixture study's 60 mm article at 12 lb: the calibre as mass^(1/3)
    assert s.diameter == pytest.approx(0.060 * (100 / 12) ** (1 / 3), rel=1e-12)
    assert read_spec({"article": "12 lb", "article_diameter": "80 mm"}).diameter == pytest.approx(0.08)
    assert s.catch == pytest.approx(0.5 * s.pulse.peak)          # half the pulse's peak unless given
    assert REFERENCE_ARTICLE["mass"] == pytest.approx(12 * LB)


def test_spec_names_every_bad_option():
    with pytest.raises(SceneError) as err:
        read_spec({"article": "12 furlongs", "masses": 1, "gas": "helium", "shape": "square",
                   "striker_ratio": 0.5, "max_pressure": "-1 psi", "colour": "red"})
    text = str(err.value)
    for flag in ("--article", "--masses", "--gas", "--shape", "--striker-ratio", "--max-pressure", "--colour"):
        assert flag in text, flag
    with pytest.raises(SceneError, match="--catch-deceleration"):
        read_spec({"article": "12 lb", "catch_deceleration": "20000 gee"})    # harsher than the test


def test_housing_wall_and_floor_hold_the_allowable():
    p, r, S = 200e6, 0.032, 460e6
    R = housing_wall(p, r, S)
    # Lame's hoop stress at the bore of the smallest wall is the allowable, and a thicker wall is below it
    assert p * (R * R + r * r) / (R * R - r * r) == pytest.approx(S, rel=1e-12)
    assert p * ((1.1 * R) ** 2 + r * r) / ((1.1 * R) ** 2 - r * r) < S
    assert housing_wall(S, r, S) == math.inf                   # no wall holds the allowable itself
    t = floor_thickness(p, r, S)
    assert 3 * p * r * r / (4 * t * t) == pytest.approx(S, rel=1e-12)


def test_stop_balances_work_and_energy_and_respects_inertia():
    rho, S = 7850.0, 460e6
    # a short body at a modest speed stops over its own length
    st = stop_for("m", 100.0, 50.0, 0.3, rho, S)
    assert st.stroke == pytest.approx(0.3, rel=1e-12)
    assert st.force * st.stroke == pytest.approx(st.energy, rel=1e-12)
    assert st.energy == pytest.approx(0.5 * 100 * 50 ** 2, rel=1e-12)
    # a long fast body would pass rho L a = S over its own length: it stops at that limit, over more
    st = stop_for("striker", 70.0, 430.0, 1.5, rho, S)
    assert rho * 1.5 * st.deceleration == pytest.approx(S, rel=1e-12)
    assert st.stroke > 1.5
    assert st.force * st.stroke == pytest.approx(st.energy, rel=1e-12)


@pytest.mark.parametrize("architecture", ["launched-chain", "stack-on-anvil"])
def test_effective_restitution_recovers_the_rigid_chain(architecture):
    masses = [900.0, 300.0, 100.0, 33.0]
    chain = rigid.launched_chain if architecture == "launched-chain" else rigid.stack_on_anvil
    gain = chain(masses, 10.0, 0.8).final[-1] / 10.0
    assert rigid.effective_restitution(masses, 10.0, gain, architecture) == pytest.approx(0.8, abs=1e-8)

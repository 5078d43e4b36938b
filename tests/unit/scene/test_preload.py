"""``[scene.preload]``: what it reads, and the scenes it refuses with the field and the fix."""
import pytest

from shockfem.scene import SceneError, resolve
from shockfem.scene.preload import DEFAULT_SPAN


def _fit(preload, **extra):
    """The shrink fit of ``verify/split_cone_cases.py``: a ring on a shaft, its fit brought on over 200 us."""
    raw = {"scene": {"name": "fit", "kinematics": "axisymmetric", "end_time": "1 ms", "preload": preload},
           "materials": {"steel": {"density": 7850, "youngs_modulus": "210 GPa", "poisson_ratio": 0.3}},
           "bodies": [{"name": "shaft", "material": "steel", "shape": "cylinder", "radius": "20 mm",
                       "length": "20 mm", "element_size": "2 mm"},
                      {"name": "ring", "material": "steel", "shape": "clamp_ring", "fits": "shaft",
                       "interference": "0.02 mm", "thickness": "20 mm", "length": "20 mm", "element_size": "2 mm"}],
           "contact": [{"name": "fit", "a": "ring.inner", "b": "shaft.side", "interference": "200 us"}]}
    raw.update(extra)
    return raw


def test_the_stage_defaults_to_five_interference_times():
    p = resolve(_fit({})).preload
    assert p.duration == pytest.approx(DEFAULT_SPAN * 200e-6, rel=1e-12)
    assert p.kinetic_energy_ratio == 1e-5 and p.frequency == 0.0
    p = resolve(_fit({"duration": "2 ms", "kinetic_energy_ratio": 1e-4, "frequency": "5 kHz"})).preload
    assert (p.duration, p.kinetic_energy_ratio, p.frequency) == pytest.approx((2e-3, 1e-4, 5e3), rel=1e-12)
    assert resolve(_fit({}) | {"scene": {"name": "fit", "kinematics": "axisymmetric", "end_time": "1 ms"}}).preload is None


@pytest.mark.parametrize("preload, extra, field, words", [
    ({"duration": "100 us"}, {}, "scene.preload.duration", "shorter than the longest interference"),
    ({"duration": "-1 ms"}, {}, "scene.preload.duration", "> 0"),
    ({"kinetic_energy_ratio": 2.0}, {}, "scene.preload.kinetic_energy_ratio", ""),
    ({"settle": True}, {}, "scene.preload.settle", "unknown field"),
    ({}, {"boundary": [{"region": "shaft.bottom", "type": "velocity", "direction": "z", "value": "1 m/s"}]},
     "scene.preload", "initial velocity instead"),
])
def test_bad_stages_name_the_field_and_the_fix(preload, extra, field, words):
    with pytest.raises(SceneError) as e:
        resolve(_fit(preload, **extra))
    said = [p for p in e.value.problems if p.startswith(field)]
    assert said and words in said[0], e.value.problems


def test_a_stage_without_an_interference_needs_its_duration():
    raw = _fit({})
    raw["contact"][0].pop("interference")
    with pytest.raises(SceneError, match="scene.preload.duration: give the stage's duration"):
        resolve(raw)

"""``scene.toml_writer.dumps`` (tomli-w): what a study writes reads back as the same scene, including what
a hand-written writer got wrong (a table key with a space, a string with a newline or a quote) and
numpy's numbers a study computes with."""
import tomllib

import numpy as np

from shockfem.scene.toml_writer import dumps


def test_a_generated_scene_reads_back_the_same():
    scene = {"scene": {"name": 'drop "A"\nsecond line', "end_time": "1 ms", "steps": np.int64(3),
                       "scale": np.float64(0.25), "origin": np.array([0.0, 1.5]), "flag": np.bool_(True)},
             "materials": {"steel 4340": {"density": "7850 kg/m^3", "yield_stress": "1.2 GPa"}},
             "bodies": [{"name": "bar", "material": "steel 4340", "position": (0, 0.1)}, {"name": "plate"}]}
    back = tomllib.loads(dumps(scene))
    assert back == {"scene": {"name": 'drop "A"\nsecond line', "end_time": "1 ms", "steps": 3, "scale": 0.25,
                              "origin": [0.0, 1.5], "flag": True},
                    "materials": {"steel 4340": {"density": "7850 kg/m^3", "yield_stress": "1.2 GPa"}},
                    "bodies": [{"name": "bar", "material": "steel 4340", "position": [0, 0.1]},
                               {"name": "plate"}]}
    assert type(back["scene"]["steps"]) is int and type(back["scene"]["flag"]) is bool


def test_floats_keep_every_digit():
    # a scene handed to a subprocess must run the same numbers: repr-exact round trip
    x = 0.1 + 0.2
    assert tomllib.loads(dumps({"a": x, "b": np.float64(1e-300)})) == {"a": x, "b": 1e-300}

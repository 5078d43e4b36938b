"""The run log's model line says what ran and what it leaves out: a penetration shot whose path is not
square to the target's face says so, with its angle (the load is verified at normal incidence only)."""
import pytest

from shockfem.model.model import _obliquity
from shockfem.scene import resolve


def _shot(velocity):
    return {"scene": {"name": "t", "kinematics": "3d", "element": "tet", "end_time": "10 us"},
            "materials": {"steel": {"density": "7850 kg/m^3", "youngs_modulus": "210 GPa", "poisson_ratio": 0.3}},
            "bodies": [{"name": "bar", "material": "steel", "shape": "projectile", "radius": "13.45 mm",
                        "length": "218 mm", "crh": 2.0, "element_size": "5 mm", "velocity": velocity}],
            "penetration": {"nose": "bar.nose", "face": {"point": [0, 0, 0], "normal": [0, 0, 1]},
                            "compressive_strength": "5 ksi", "density": "2300 kg/m^3"}}


@pytest.mark.parametrize("velocity, said", [([0, 0, -300], None), ([0, 0.1, -300], None),
                                            ([0, 300 * 0.5, -300 * 0.75 ** 0.5], "30 deg")])
def test_an_oblique_path_is_named_with_its_angle(velocity, said):
    s = resolve(_shot(velocity))
    line = _obliquity(s, s.penetration)
    if said is None:
        assert line == ""
    else:
        assert f"the path {said} from the face's normal" in line and "not modelled" in line

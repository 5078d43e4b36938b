"""The Mooney-Rivlin rubber (``materials/rubber.py``) at a point through the material update the
kernels call, and its scene fields.  Closed forms against the law: ``verify material_point``."""
import math

import numpy as np
import pytest

from shockfem.materials.layout import S_DEFORMATION
from shockfem.scene import SceneError
from shockfem.verify.material_point import RUBBER, MaterialPoint, material


def test_a_spin_turns_the_stress_and_leaves_the_strain_energy():
    """Stretched, then spun a quarter turn with no strain: F turns (F -> Q F), the stress turns with
    it (Q sigma Q^T) and its invariants stay (a hyperelastic stress is objective by construction)."""
    point = MaterialPoint(material(RUBBER))
    for _ in range(200):
        point.step({0: 1.0}, (1, 2), 1e-3)                  # to a stretch of e^0.2
    s0 = point.sigma.copy()
    spin, steps, dt = 0.5 * math.pi / 1e-3 / 1000, 1000, 1e-6
    for _ in range(steps):
        point.step({}, (), dt, w=(0.0, 0.0, spin))
    angle = steps * 2 * math.atan(0.5 * spin * dt)
    c, s = math.cos(angle), math.sin(angle)
    Q = np.array([[c, s, 0], [-s, c, 0], [0, 0, 1]])
    S0 = np.array([[s0[0], s0[5], s0[4]], [s0[5], s0[1], s0[3]], [s0[4], s0[3], s0[2]]])
    S1 = Q @ S0 @ Q.T
    expected = [S1[0, 0], S1[1, 1], S1[2, 2], S1[1, 2], S1[0, 2], S1[0, 1]]
    assert np.allclose(point.sigma, expected, rtol=0, atol=1e-9 * np.abs(s0).max())


def test_undeformed_rubber_has_no_stress_and_small_strains_are_hookes():
    point = MaterialPoint(material({**RUBBER, "c01": 0.0}))
    point.step({0: 1.0, 1: 1.0, 2: 1.0}, (), 0.0)
    assert np.all(point.sigma == 0.0)
    mat = material({"density": 1100, "hyperelastic": "neo-hookean", "youngs_modulus": "10 MPa", "poisson_ratio": 0.3})
    point = MaterialPoint(mat)
    point.step({0: 1.0}, (1, 2), 1e-6)                       # 1e-6 strain
    assert point.sigma[0] == pytest.approx(10e6 * 1e-6, rel=1e-5)
    assert point.state[0, 0, S_DEFORMATION] == pytest.approx(1e-6, rel=1e-5)


@pytest.mark.parametrize("fields, field", [
    ({"hyperelastic": "ogden", "youngs_modulus": "10 MPa"}, "hyperelastic"),
    ({"hyperelastic": "neo-hookean", "youngs_modulus": "10 MPa", "c10": "1 MPa"}, "c10"),
    ({"hyperelastic": "mooney-rivlin", "youngs_modulus": "10 MPa", "c10": "1 MPa"}, "youngs_modulus"),
    ({"hyperelastic": "mooney-rivlin"}, "c10"),
    ({"c10": "1 MPa", "c01": "-1 MPa"}, "c01"),
    ({"hyperelastic": "neo-hookean", "youngs_modulus": "10 MPa", "yield_stress": "1 MPa"}, "yield_stress"),
    ({"hyperelastic": "neo-hookean", "youngs_modulus": "10 MPa", "poisson_ratio": 0.5}, "poisson_ratio"),
])
def test_bad_rubber_fields_are_named(fields, field):
    with pytest.raises(SceneError) as e:
        material({"density": 1100, **fields})
    assert f"materials.m.{field}" in str(e.value), str(e.value)


def test_mooney_rivlin_modulus_and_model_line():
    mat = material(RUBBER)
    assert mat.law == "rubber" and mat.nu == RUBBER["poisson_ratio"]
    assert mat.mu == pytest.approx(2 * (RUBBER["c10"] + RUBBER["c01"]), rel=1e-12)
    assert "Mooney-Rivlin rubber, C10 = 1 MPa, C01 = 0.3 MPa" in mat.model

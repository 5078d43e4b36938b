"""The crushable foam (``materials/foam.py``) and the principal stresses it caps
(``materials/principal.py``), at one point through the material update the kernels call."""
import math

import numpy as np
import pytest

from shockfem.materials.layout import S_EPS, S_LOG_VOLUME
from shockfem.materials.principal import principal_stresses, spectral_sum
from shockfem.scene import SceneError
from shockfem.verify.material_point import FOAM, MaterialPoint, material


def _matrix(s):
    return np.array([[s[0], s[5], s[4]], [s[5], s[1], s[3]], [s[4], s[3], s[2]]])


@pytest.mark.parametrize("seed", range(5))
def test_principal_stresses_match_numpy(seed):
    """Jacobi's values and directions against numpy's eigh: round-off (1e-12 of the tensor's size)."""
    rng = np.random.default_rng(seed)
    s = tuple(rng.normal(size=6) * 1e6)
    values, v = principal_stresses(s)
    assert np.allclose(sorted(values), np.linalg.eigvalsh(_matrix(s)), rtol=0, atol=1e-12 * 1e6 * 3)
    V = np.array(v).reshape(3, 3)
    assert np.allclose(V.T @ V, np.eye(3), atol=1e-13)
    # rebuilding from the values gives the tensor back
    assert np.allclose(spectral_sum(values, v), s, rtol=0, atol=1e-12 * 1e6 * 3)


def test_principal_stresses_of_repeated_values():
    """Equal principal values (a hydrostatic state plus one axis) need no special case."""
    values, v = principal_stresses((-2.0, -2.0, 5.0, 0.0, 0.0, 0.0))
    assert sorted(values) == [-2.0, -2.0, 5.0]
    values, v = principal_stresses((3.0, 3.0, 3.0, 0.0, 0.0, 0.0))
    assert values == (3.0, 3.0, 3.0)


def test_foam_caps_each_principal_stress_in_a_rotated_frame():
    """Triaxial compression beyond the crush stress, applied in a frame turned off the axes: every
    principal stress ends at -sigma_c (the curve at the point's volumetric strain), whatever the frame."""
    point = MaterialPoint(material(FOAM))
    c, s = math.cos(0.4), math.sin(0.4)
    R = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])
    D = R @ np.diag([-50.0, -40.0, -30.0]) @ R.T              # rates [1/s], all compressive
    d = {0: D[0, 0], 1: D[1, 1], 2: D[2, 2], 5: D[0, 1]}
    for _ in range(200):                                     # strains 0.1, 0.08, 0.06: 5, 4, 3 MPa elastic
        point.step(d, (), 1e-5)
    eps_v = 1.0 - math.exp(point.state[0, 0, S_LOG_VOLUME])
    assert eps_v == pytest.approx(1.0 - math.exp(-120.0 * 2e-3), rel=1e-12)
    curve = np.array(FOAM["crush_curve"])
    crush = np.interp(eps_v, curve[:, 0], curve[:, 1])
    assert np.allclose(np.linalg.eigvalsh(_matrix(point.sigma)), -crush, rtol=1e-9)
    assert point.state[0, 0, S_EPS] > 0.0


def test_foam_below_its_crush_stress_is_elastic():
    point = MaterialPoint(material(FOAM))
    point.step({0: -1.0}, (1, 2), 1e-4)                      # 1e-4 strain: 5 kPa of 1 MPa
    assert point.sigma[0] == pytest.approx(-FOAM["youngs_modulus"] * 1e-4, rel=1e-12)
    assert point.plastic_work == 0.0 and point.state[0, 0, S_EPS] == 0.0


@pytest.mark.parametrize("fields, field", [
    ({"crush_curve": [[0.1, 1e6]]}, "crush_curve"),                          # must start at 0
    ({"crush_curve": [[0.0, 1e6], [0.5, 0.0]]}, "crush_curve"),              # stress > 0
    ({"crush_curve": [[0.0, 1e6], [1.2, 2e6]]}, "crush_curve"),              # strain < 1
    ({"crush_curve": [[0.0, 1e6], [0.1, 100e6]]}, "youngs_modulus"),         # slope 990 MPa > E 50 MPa
    ({"crush_curve": [[0.0, 1e6]], "yield_stress": 1e6}, "yield_stress"),    # a J2 field on a foam
    ({"tension_cutoff": "-1 MPa", "crush_curve": [[0.0, 1e6]]}, "tension_cutoff"),
    ({"tension_cutoff": "1 MPa"}, "crush_curve"),                            # no curve
])
def test_bad_foam_fields_are_named(fields, field):
    base = {k: v for k, v in FOAM.items() if k not in ("crush_curve", "tension_cutoff")}
    with pytest.raises(SceneError) as e:
        material({**base, **fields})
    assert f"materials.m.{field}" in str(e.value)


@pytest.mark.parametrize("entry, phi, solid_yield", [("aluminium_foam", 0.1, 150e6), ("polyurethane_foam", 0.2, 127e6)])
def test_library_foam_resolves_with_its_source(entry, phi, solid_yield):
    """The plateau is Gibson-Ashby's open-cell 0.3 sigma_ys phi^1.5 of the solid the source names."""
    mat = material({"library": entry})
    assert mat.law == "foam" and mat.nu == 0.0 and "Gibson" not in mat.source and "[GA]" in mat.source
    assert mat.crush.curve[0][1] == pytest.approx(0.3 * solid_yield * phi ** 1.5, rel=1e-3)
    assert f"{mat.crush.curve[0][1] / 1e6:.3g} MPa" in mat.source


def test_stretched_foam_keeps_its_tension_cutoff_and_never_gives_back_plastic_work():
    """Triaxial stretching to 4.5 times the volume (volumetric strain -3.5, a ring flung outward): the
    curve's plateau slope carried backward would put the crush stress at 1 + 0.4 (-3.5) = -0.4 MPa,
    and a negative crush stress caps the principal stresses the wrong way round (the fixture study's
    pad made 277 MJ of negative plastic work out of an 11 MJ impact).  The crush stress holds the
    curve's first value: every principal stress stays at the 0.2 MPa cutoff, plastic work only grows."""
    point = MaterialPoint(material(FOAM))
    before = 0.0
    for _ in range(500):
        point.step({0: 100.0, 1: 100.0, 2: 100.0}, (), 1e-5)
        assert point.plastic_work >= before
        before = point.plastic_work
    assert 1.0 - math.exp(point.state[0, 0, S_LOG_VOLUME]) == pytest.approx(1.0 - math.exp(1.5), rel=1e-9)
    assert np.allclose(point.sigma[:3], FOAM["tension_cutoff"], rtol=1e-12) and not point.sigma[3:].any()

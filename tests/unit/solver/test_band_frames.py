"""Band damping's co-rotating frames (``solver/band.py``): the best-fit rotation of a body's nodes."""
import numpy as np
import pytest

from shockfem.solver.band import best_rotation


def _covariance(ref, cur):
    ref = ref - ref.mean(axis=0)
    return ref.T @ (cur - cur.mean(axis=0))


@pytest.mark.parametrize("gdim", [2, 3])
def test_best_rotation_recovers_a_rigid_rotation_and_ignores_a_translation(gdim):
    """Points turned by R and shifted: Kabsch's rotation is R to round-off (1e-14 measured)."""
    rng = np.random.default_rng(3)
    X = rng.normal(size=(40, gdim))
    if gdim == 2:
        t = 2.5                                  # beyond pi / 2: the arctan's quadrant matters
        R = np.array([[np.cos(t), -np.sin(t)], [np.sin(t), np.cos(t)]])
    else:
        R, _ = np.linalg.qr(rng.normal(size=(3, 3)))
        R *= np.sign(np.linalg.det(R))           # a proper rotation
    x = X @ R.T + rng.normal(size=gdim)
    assert best_rotation(_covariance(X, x)) == pytest.approx(R, abs=1e-12)


def test_best_rotation_of_a_stretched_body_is_its_polar_rotation():
    """A body stretched along its own axes and then turned: the fit finds the turn, not the stretch (to within
    strain x the point cloud's anisotropy: 2.7e-4 measured for 2%; a fit that took the stretch in would be 2e-2
    off)."""
    rng = np.random.default_rng(5)
    X = rng.normal(size=(60, 3))
    U = np.diag([1.02, 0.99, 1.0])               # a 2% strain: the deformation the terms must see
    R, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    R *= np.sign(np.linalg.det(R))
    x = X @ (R @ U).T
    assert best_rotation(_covariance(X, x)) == pytest.approx(R, abs=1e-3)

"""``nodal.body_sums`` (the history's per-body momentum, force and kinetic energy) against numpy on random
states: bodies interleaved and in runs, held dofs with their prescribed motion, ghost nodes left out."""
import numpy as np
import pytest

from shockfem.solver import nodal


@pytest.mark.parametrize("gdim", [2, 3])
def test_body_sums_match_numpy(gdim):
    rng = np.random.default_rng(gdim)
    n, owned, dt, alpha = 1000, 900, 1e-3, 3.0
    v, a = rng.random((n, gdim)), rng.random((n, gdim))
    mass, kinetic_mass = rng.random(n), rng.random(n)
    held = rng.random((n, gdim)) < 0.1
    body = rng.integers(0, 3, n).astype(np.int32)
    body[100:400] = 1                                     # a run of one body, and interleaved elsewhere
    dofs = np.flatnonzero(held.reshape(-1))
    v_held, a_held = rng.random(len(dofs)), rng.random(len(dofs))
    mv, ma, kinetic = nodal.body_sums(v, a, dt, alpha, mass, kinetic_mass, held, body, 3, owned, dofs, v_held, a_held)
    v_t = v + 0.5 * dt * a
    a_t = a - alpha * v_t
    kinetic_v = np.where(held, v, v_t)                    # as finish_step counts it
    v_t.reshape(-1)[dofs], a_t.reshape(-1)[dofs] = v_held, a_held
    for b in range(3):
        sel = body[:owned] == b
        assert np.allclose(mv[b], (mass[:owned, None] * v_t[:owned])[sel].sum(axis=0), rtol=1e-13, atol=0)
        assert np.allclose(ma[b], (mass[:owned, None] * a_t[:owned])[sel].sum(axis=0), rtol=1e-13, atol=0)
        assert np.isclose(kinetic[b], (0.5 * kinetic_mass[:owned] * (kinetic_v[:owned] ** 2).sum(axis=1))[sel].sum(),
                          rtol=1e-13, atol=0)

"""study.doe: the 2^(4-1) design, its aliases, effects and Lenth's margin."""
import numpy as np
import pytest

from shockfem.study.doe import effect_columns, effects, fold_over, fractional_factorial, lenth, physical_coefficients


def test_half_fraction_with_d_equal_abc_aliases_two_factor_interactions_in_pairs():
    """pyDOE3's 2^(4-1) design in standard order: run k (from 0) has factor j at +1 where bit j of k is
    set (the first factor alternating fastest, as the penetration study numbers its runs), D = ABC."""
    X = fractional_factorial("a b c abc")
    standard = np.array([[1 if (k >> j) & 1 else -1 for j in range(3)] for k in range(8)], dtype=float)
    assert (X[:, :3] == standard).all()
    assert X.shape == (8, 4) and (X[:, 3] == X[:, 0] * X[:, 1] * X[:, 2]).all()
    assert (X.T @ X == 8 * np.eye(4)).all()                       # orthogonal main effects
    columns = effect_columns(X, "ABCD")
    assert set(columns) == {"A", "B", "C", "D", "AB = CD", "AC = BD", "AD = BC"}


def test_effects_recover_a_linear_model_and_lenth_flags_the_large_ones():
    """y = 10 + 3 A - 2 C + 0.5 AB (coded) plus small noise: effects are twice the coefficients,
    and Lenth's margin separates A and C from the rest."""
    X = fractional_factorial("a b c abc")
    noise = np.array([0.01, -0.02, 0.015, 0.0, -0.01, 0.02, -0.015, 0.005])
    y = 10 + 3 * X[:, 0] - 2 * X[:, 2] + 0.5 * X[:, 0] * X[:, 1] + noise
    e = effects(effect_columns(X, "ABCD"), y)
    assert e["A"] == pytest.approx(6.0, abs=0.05) and e["C"] == pytest.approx(-4.0, abs=0.05)
    assert e["AB = CD"] == pytest.approx(1.0, abs=0.05)
    pse, margin = lenth(e.values())
    assert abs(e["A"]) > margin and abs(e["C"]) > margin and abs(e["B"]) < margin
    c0, slopes = physical_coefficients({"A": 3.0, "B": 0.0}, 10.0, [2.0, 50.0], [2.0, 25.0], "AB")
    assert slopes["A"] == 1.5 and c0 == pytest.approx(10.0 - 3.0)


def test_fold_over_on_d_makes_the_full_factorial_and_unaliases_the_interactions():
    """D = ABC folded on D (D = -ABC): the 16 runs are the 2^4 full factorial, every one of its 15 effect
    columns distinct; a yaw x spin interaction (AC) that the half fraction could not tell from BD is
    found whole, and BD as zero."""
    X = fractional_factorial("a b c abc")
    both = np.vstack([X, fold_over(X, 3)])
    assert (both[8:, 3] == -both[8:, 0] * both[8:, 1] * both[8:, 2]).all()
    assert len({tuple(r) for r in both}) == 16
    columns = effect_columns(both, "ABCD", order=4)
    assert len(columns) == 15 and all(" = " not in n for n in columns)
    y = 5 + 2 * both[:, 0] * both[:, 2]
    half = effects(effect_columns(X, "ABCD"), y[:8])
    assert half["AC = BD"] == pytest.approx(4.0)
    e = effects(columns, y)
    assert e["AC"] == pytest.approx(4.0) and e["BD"] == pytest.approx(0.0, abs=1e-12)

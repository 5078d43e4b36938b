"""Two-level designs of experiments: the fractional factorial, its effects, their aliases and Lenth's
test of which matter.

A 2^(k-p) design runs every combination of k - p base factors at coded levels -1 / +1 and sets each
of the p others to a product of base columns (its generator, e.g. D = ABC); that confounds effects:
with I = ABCD, A is aliased with BCD and AB with CD (a resolution IV design keeps main effects clear of
two-factor interactions, which are aliased in pairs).  An effect is the mean response at +1 less the
mean at -1, twice the coded regression coefficient.  A deterministic simulation repeats itself
exactly, so replicated centre points give no error estimate (their spread is zero) but one tells
curvature: the centre's response against the factorial runs' mean.  Folding the design over on a factor
(its sign reversed in a second half) frees that factor's interactions from their aliases.  Significance then comes from
Lenth (1989): the pseudo standard error PSE = 1.5 median(|c| : |c| < 2.5 s0), s0 = 1.5 median |c|, of
the m effects, and the margin of error t(0.975, m / 3) PSE.
"""
from __future__ import annotations

import itertools
import math

import numpy as np
from scipy import stats


def fractional_factorial(generators: str) -> np.ndarray:
    """Coded levels (runs, factors) of a two-level fractional factorial, pyDOE3's ``fracfact`` of
    ``generators`` (one word a factor: a base factor's letter, or the product of base letters that sets a
    generated one: "a b c abc" is the 2^(4-1) design with D = ABC), its rows in standard order (the first
    factor alternating fastest; pyDOE3 alternates the last fastest: the same runs, reordered so that a
    run's number names the same levels as the textbooks' tables and the sweep's full factorial)."""
    import pyDOE3
    design = pyDOE3.fracfact(generators)
    base = [k for k, word in enumerate(generators.split()) if len(word.lstrip("+-")) == 1]
    return design[np.lexsort(design[:, base].T)]


def fold_over(design: np.ndarray, factor: int) -> np.ndarray:
    """The fold-over half of a fractional factorial on one factor: the same runs with that factor's
    sign reversed (D = -ABC for D = ABC).  Together with the first half it separates that factor and
    every interaction with it from their aliases; on a 2^(4-1) design folded on D the two halves are
    the full 2^4."""
    folded = np.array(design, dtype=float)
    folded[:, factor] *= -1
    return folded


def effect_columns(design: np.ndarray, names: str, order: int = 2) -> dict[str, np.ndarray]:
    """The columns of the effects up to ``order`` factors (main effects and two-factor interactions by
    default), each distinct column once and named by every effect it carries ("AC = BD"): the columns a
    saturated model can estimate."""
    out: dict[str, np.ndarray] = {}
    labels: dict[bytes, list[str]] = {}
    terms = [t for k in range(1, order + 1) for t in itertools.combinations(range(design.shape[1]), k)]
    for term in terms:
        column = np.prod(design[:, list(term)], axis=1)
        key = column.tobytes()
        label = "".join(names[i] for i in term)
        if key in labels:
            labels[key].append(label)
        elif (-column).tobytes() in labels:
            labels[(-column).tobytes()].append(f"-{label}")
        else:
            labels[key] = [label]
            out[key] = column
    return {" = ".join(labels[key]): column for key, column in out.items()}


def effects(columns: dict[str, np.ndarray], response: np.ndarray) -> dict[str, float]:
    """Each column's effect: the mean response where it is +1 less the mean where it is -1."""
    y = np.asarray(response, dtype=float)
    return {name: float(y[c > 0].mean() - y[c < 0].mean()) for name, c in columns.items()}


def lenth(values) -> tuple[float, float]:
    """(PSE, margin of error at 95%) of a set of effects (Lenth 1989)."""
    c = np.abs(np.asarray(list(values), dtype=float))
    s0 = 1.5 * float(np.median(c))
    trimmed = c[c < 2.5 * s0]
    pse = 1.5 * float(np.median(trimmed)) if len(trimmed) else s0
    return pse, float(stats.t.ppf(0.975, len(c) / 3.0)) * pse


def physical_coefficients(coded: dict[str, float], intercept: float, centres: list[float],
                          half_ranges: list[float], names: str) -> tuple[float, dict[str, float]]:
    """The main-effect model y = b0 + sum b_i x_i (x_i coded) in physical units X_i = centre_i +
    half_i x_i: y = c0 + sum c_i X_i with c_i = b_i / half_i and c0 = b0 - sum c_i centre_i."""
    slopes = {n: coded[n] / h for n, h in zip(names, half_ranges)}
    return intercept - sum(slopes[n] * c for n, c in zip(names, centres)), slopes


def significant(value: float, margin: float) -> bool:
    return math.isfinite(margin) and abs(value) > margin

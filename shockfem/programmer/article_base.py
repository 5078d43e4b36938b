"""The article's peak base stress on the dashpot's piston: a design check on the column's run.

The article stands on its flat base on the piston's top (the piston fills the bore; where the bore is
narrower than the article, the article stands on a plunger of the bore's radius), so its base bears the
contact force over the bearing area A_b = pi min(R, a)^2.  The contact force is the article's share of the
payload's force on the column, m a(t) (``column_dashpot``: the payload as one rigid body), times the dynamic
factor of the article's first axial mode driven by that history (``housing.dynamic_factor`` at the period
4 L / c of a clamped-free bar of the article's length, c = sqrt(E / rho)): the response of a bar's first
mode to its base's motion.  A piston driven by the liquid's force (the oil column's impedance rho c A is
about a twentieth of the article's) passes m a to the base with no such amplification, so on this dashpot
the factor errs on the safe side.  The check: sigma_b = D max(m a) / A_b against the article's initial
yield stress.

Its range of validity (``base_stress``'s ``limits``): the mean normal stress over the bearing (the contact
force over the contact area, by equilibrium) of a bar whose first mode is a bar's, Rayleigh-Love's
lateral-inertia correction to its period, (nu k r_g)^2 / 2 with k = pi / (2 L) and r_g = R / sqrt(2)
(Graff, Wave Motion in Elastic Solids, 2.10), within ``RAYLEIGH_LOVE``.  It is not the stress at the
bearing's edge: the base's rim on a wider piston is a flat punch's corner, where the elastic stress is
singular and the finite-element runs put the article's tracked peak (``docs/fixture.md`` 4.7 gives
both); nor the ogive's taper (a uniform bar of the article's length is slower than the ogive, whose nose
is lighter: a step's factor is 2 at any period, so that error enters only through the history's ripple).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..scene.library import initial_yield_stress, property_si
from .dashpot_validity import Limit
from .housing import dynamic_factor

# the largest Rayleigh-Love correction to the bar's first period for which its 1D mode is taken as exact
RAYLEIGH_LOVE = 0.01


@dataclass(frozen=True)
class Article:
    """The article standing on the piston: its base's ``radius`` and its ``length`` [m], and its material
    (a ``scene.library`` metal)."""
    radius: float
    length: float
    library: str

    def bar_speed(self) -> float:
        return math.sqrt(property_si(self.library, "youngs_modulus", "pressure")
                         / property_si(self.library, "density", "density"))

    def first_period(self) -> float:
        """The first axial period of a clamped-free bar of the article's length [s]: 4 L / c."""
        return 4.0 * self.length / self.bar_speed()

    def rayleigh_love(self) -> float:
        """Rayleigh-Love's correction to that period, (nu k r_g)^2 / 2 [-]."""
        nu = float(property_si(self.library, "poisson_ratio", "dimensionless"))
        k, gyration = math.pi / (2.0 * self.length), self.radius / math.sqrt(2.0)
        return 0.5 * (nu * k * gyration) ** 2


def base_stress(t: np.ndarray, acceleration: np.ndarray, article_mass: float, article: Article,
                bore_radius: float) -> dict:
    """The article's peak base stress on the piston (the module's docstring) from the payload's
    ``acceleration`` [m/s^2] at times ``t`` [s] on the column: the peak force m a, the bearing's radius,
    its mean stress, the article's first period and its dynamic factor, the stress, the yield stress, their
    ratio, ``holds`` (the stress within yield), the Rayleigh-Love correction and ``in_range`` (it within
    ``RAYLEIGH_LOVE``), and ``limits`` (``Limit.as_dict``: the check itself and its
    range)."""
    force = article_mass * np.abs(np.asarray(acceleration, dtype=float))
    bearing = min(article.radius, bore_radius)
    mean = float(np.max(force)) / (math.pi * bearing ** 2)
    period = article.first_period()
    factor = dynamic_factor(np.asarray(t, dtype=float), force, period)
    stress, yielded_at = mean * factor, initial_yield_stress(article.library)
    limits = [Limit("article base stress over its yield (mean over the bearing x its first mode's dynamic factor)",
                    stress / yielded_at, 1.0, "the article"),
              Limit("article's first axial mode: Rayleigh-Love correction to its period", article.rayleigh_love(),
                    RAYLEIGH_LOVE, "the article's base-stress estimate")]
    return {"force": float(np.max(force)), "bearing_radius": bearing, "mean_stress": mean, "period": period,
            "dynamic_factor": factor, "stress": stress, "yield_stress": yielded_at, "ratio": stress / yielded_at,
            "holds": limits[0].holds, "rayleigh_love": article.rayleigh_love(), "in_range": limits[1].holds, "limits": [lim.as_dict() for lim in limits]}

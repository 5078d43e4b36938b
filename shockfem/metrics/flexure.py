"""A slender body's bending, read from the motion of evenly spaced stations on its axis, and the
quasi-static (inertia relief) loads of its sections under a force on a free body.

The stations (accelerometers of a scene, base k = 0 to nose tip k = n - 1, n odd, spacing L / (n - 1))
record their velocities; integrated, their lateral displacements u_k (one component, or a vector of the
components square to the axis) give:

* the tail's flexural deflection: the base's displacement from the forebody's line, the line through
  the nose tip and the mid-length station carried to the base, u_0 - (2 u_mid - u_tip);
* the bending stress E R kappa (Euler-Bernoulli, outer fibre at radius R), kappa the axis's curvature
  (u_{k-1} - 2 u_k + u_{k+1}) / spacing^2 at the interior stations of the base half (the shank).

A measure of the bending mode: blind to local stresses at contacts, which the von Mises field has.
"""
from __future__ import annotations

import numpy as np


def station_travel(t: np.ndarray, velocities: np.ndarray) -> np.ndarray:
    """The stations' displacements from their recorded velocities (stations, samples[, components]),
    integrated by the trapezoidal rule from zero."""
    v = np.asarray(velocities, dtype=float)
    dt = np.diff(t).reshape((1, -1) + (1,) * (v.ndim - 2))
    steps = 0.5 * (v[:, 1:] + v[:, :-1]) * dt
    return np.concatenate([np.zeros_like(v[:, :1]), np.cumsum(steps, axis=1)], axis=1)


def tail_flexure(u: np.ndarray, length: float, radius: float, modulus: float) -> tuple[np.ndarray, np.ndarray]:
    """(tail deflection, bending stress) over the samples from the stations' lateral displacements u
    (stations, samples[, components]); vectors give their magnitudes."""
    n = u.shape[0]
    if n < 3 or n % 2 == 0:
        raise ValueError(f"tail flexure needs an odd number of stations (>= 3), got {n}")
    mid = (n - 1) // 2
    spacing = length / (n - 1)
    deflection = u[0] - (2 * u[mid] - u[-1])
    curvature = np.array([(u[k - 1] - 2 * u[k] + u[k + 1]) / spacing ** 2 for k in range(1, mid + 1)])
    if u.ndim == 3:
        deflection = np.linalg.norm(deflection, axis=-1)
        curvature = np.linalg.norm(curvature, axis=-1)
    return deflection, modulus * radius * np.abs(curvature).max(axis=0)


def inertia_relief_moment(along: np.ndarray, lateral: np.ndarray, mass: np.ndarray, force: float, at: float,
                          cuts: np.ndarray) -> np.ndarray:
    """The bending moment [N m] a lateral force puts across the sections of a free body accelerating
    rigidly under it (the quasi-static bending, d'Alembert), at the axial positions ``cuts``.

    The body is point masses ``mass`` at ``along`` (axial coordinate) and ``lateral`` (offset along the
    force); the force acts at axial position ``at``.  The rigid body accelerates at a = F / m + alpha
    (xi - c) square to the axis and turns at alpha = F (at - c) / J, J = sum m ((xi - c)^2 + y^2) about
    its centre of mass (c, y_c), y = lateral - y_c, so a point's axial acceleration is -alpha y.  The
    moment at a cut is that of the d'Alembert forces on the side the force is not on:

        M(x) = | sum over that side of m [(xi - x) a(xi) + alpha y^2] |

    (a slice's own rotary inertia is the alpha y^2 term; a uniform bar without it gives F x^2 (L - x) / L^2
    from its free end).
    """
    along, mass = np.asarray(along, dtype=float), np.asarray(mass, dtype=float)
    m = mass.sum()
    c = mass @ along / m
    y = np.asarray(lateral, dtype=float) - mass @ lateral / m
    J = mass @ ((along - c) ** 2 + y ** 2)
    alpha = force * (at - c) / J
    a = force / m + alpha * (along - c)
    out = np.zeros(len(cuts))
    for k, x in enumerate(cuts):
        side = along < x if at >= x else along > x
        out[k] = abs(np.sum(mass[side] * ((along[side] - x) * a[side] + alpha * y[side] ** 2)))
    return out


def axial_inertia_relief(slab_mass: np.ndarray, force: float) -> np.ndarray:
    """The axial force [N] across the middle of each of a free body's slabs (low end first) as it
    decelerates rigidly under ``force`` on its low end: the force less the inertia of what lies ahead
    of the section, F (mass behind it) / (whole mass)."""
    m = np.asarray(slab_mass, dtype=float)
    behind = np.cumsum(m[::-1])[::-1] - 0.5 * m
    return force * behind / m.sum()

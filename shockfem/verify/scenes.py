"""Scenes and small drivers shared by the verification cases."""
from __future__ import annotations

import math
import time

import numpy as np
from mpi4py import MPI

from ..geometry import build_mesh
from ..model import build_model
from ..scene import resolve
from ..solver.explicit import ExplicitSolver

STEEL = {"density": 7850.0, "youngs_modulus": 210e9, "poisson_ratio": 0.3}


def steel_c0() -> float:
    return math.sqrt(STEEL["youngs_modulus"] / STEEL["density"])


def rod_scene(name, kinematics="axisymmetric", element=None, radius=0.01, length=0.2, h=0.0025,
              end_time=1e-4, velocity=0.0, boundary=(), damping=None, safety_factor=0.9,
              rigid=False, integration="reduced") -> dict:
    """A steel cylinder standing on z = 0 (3D: axis z through the origin), as a raw scene."""
    gdim = 3 if kinematics == "3d" else 2
    vel = [0.0] * gdim
    if np.ndim(velocity) == 0:
        vel[-1] = float(velocity)
    else:
        vel = [float(v) for v in velocity]
    raw = {"scene": {"name": name, "kinematics": kinematics,
                     "element": element or ("hex" if gdim == 3 else "quad"),
                     "end_time": end_time, "safety_factor": safety_factor, "integration": integration},
           "materials": {"steel": dict(STEEL)},
           "bodies": [{"name": "rod", "material": "steel", "shape": "cylinder", "radius": radius,
                       "length": length, "element_size": h, "velocity": vel, "rigid": rigid,
                       "position": [0.0] * gdim}],
           "boundary": [dict(b) for b in boundary],
           "outputs": {"field_interval": end_time, "history_interval": end_time / 200}}
    if damping:
        raw["damping"] = dict(damping)
    return raw


def solve(raw: dict, initial_velocity=None, probe=None, comm=MPI.COMM_WORLD, cache_dir=None):
    """Build and run a raw scene in-process; ``probe(solver)`` is called at t = 0 and every step.

    Returns (solver, wall time of the time loop [s]).
    """
    scene = resolve(raw)
    model = build_model(scene, build_mesh(scene, comm, cache_dir=cache_dir, log=lambda m: None))
    solver = ExplicitSolver(model, initial_velocity=initial_velocity)
    if probe:
        probe(solver)
    t0 = time.perf_counter()
    for _ in solver.steps(scene.end_time):
        if probe:
            probe(solver)
    return solver, time.perf_counter() - t0


def end_nodes(solver: ExplicitSolver):
    """Local nodes on the axis (or nearest to it) at the bottom and top ends of a rod."""
    X = solver.model.X0
    r = np.linalg.norm(X[:, :-1], axis=1)
    z = X[:, -1]
    on_axis = r <= r.min() + 1e-12
    bottom = np.flatnonzero(on_axis & (z <= z.min() + 1e-12))
    top = np.flatnonzero(on_axis & (z >= z.max() - 1e-12))
    return int(bottom[0]), int(top[0])


def dominant_frequency(t: np.ndarray, y: np.ndarray) -> float:
    """Frequency of the largest peak of the amplitude spectrum (zero-padded FFT, Hann window,
    parabolic interpolation of the log amplitude around the peak bin)."""
    dt = t[1] - t[0]
    y = (y - y.mean()) * np.hanning(len(y))
    n = 16 * len(y)
    spec = np.abs(np.fft.rfft(y, n))
    k = int(np.argmax(spec[1:])) + 1
    a, b, c = np.log(spec[k - 1:k + 2] + 1e-300)
    shift = 0.5 * (a - c) / (a - 2 * b + c)
    return (k + shift) / (n * dt)


def resample(times, values, dt):
    """Values on a uniform grid of spacing dt (the explicit step varies slightly as the mesh moves)."""
    grid = np.arange(times[0], times[-1], dt)
    return grid, np.interp(grid, times, values)


def rayleigh_love_f1(radius, length, nu=STEEL["poisson_ratio"]):
    """First free-free longitudinal frequency with Rayleigh-Love lateral inertia [Hz]:
    f1 = c0 / (2 L sqrt(1 + (nu pi R / (sqrt(2) L))^2))  (shared/references/README.md)."""
    return steel_c0() / (2 * length * math.sqrt(1 + (nu * math.pi * radius / (math.sqrt(2) * length)) ** 2))

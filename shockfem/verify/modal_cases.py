"""Verification of modal analysis (``shockfem modes``, ``shockfem/modal``).

* Free-free steel rod, R = 10 mm, L = 200 mm: the first longitudinal frequency against
  Rayleigh-Love (lateral inertia), axisymmetric and 3D; in 3D the first torsional frequency
  against the exact c_s / (2 L).
* NAFEMS FV12, free thin square plate 10 m x 10 m x 0.05 m (E 200 GPa, nu 0.3, rho 8000):
  f4-f9 = 1.622, 2.360, 2.922, 4.233, 4.233, 7.416 Hz (the first three are rigid-body modes,
  which the modal solver counts apart, so they are its elastic modes 1-6) within 2%, with
  quadratic hexahedra (linear solids lock in bending).
* Free circular plate, a = 0.5 m, h = 10 mm, nu = 0.33: Kirchhoff's characteristic equation gives
  lambda^2 = omega a^2 sqrt(rho h / D) = 5.262 (two nodal diameters), 9.069 (one nodal circle,
  axisymmetric) and 12.244 (three diameters); within 1% (h / a = 0.02, so thin-plate theory is
  itself good to about (h/a)^2).
"""
from __future__ import annotations

import math

import numpy as np

from ..geometry import build_mesh
from ..modal.eigen import body_modes
from ..modal.labels import label_modes
from ..scene import resolve
from .checks import check
from .scenes import STEEL, rayleigh_love_f1

# Element-size factor per verification size.
SIZES = {"coarse": 2.0, "default": 1.0, "fine": 0.5}
FV12 = (1.622, 2.360, 2.922, 4.233, 4.233, 7.416)
PLATE_LAMBDA2 = {"5.262 (n=2)": 5.262, "9.069 (n=0, s=1)": 9.069, "12.244 (n=3)": 12.244}


def _modes(name, kinematics, material, body, count, degree, cache_dir):
    raw = {"scene": {"name": name, "kinematics": kinematics, "end_time": 1.0,
                     "element": "hex" if kinematics == "3d" else "quad"},
           "materials": {"m": material}, "bodies": [{"name": "b", "material": "m", **body}]}
    scene = resolve(raw)
    meshed = build_mesh(scene, cache_dir=cache_dir, log=lambda m: None)
    modes = body_modes(scene, meshed, "b", count, degree)
    labels = label_modes(modes, meshed.cell_tags.find(1))
    return modes, labels


def _first(modes, labels, kind):
    return next(f for f, lab in zip(modes.frequencies, labels) if lab["label"] == kind)


def modal_rod(size, workdir):
    """Free-free rod: longitudinal vs Rayleigh-Love (axisymmetric and 3D), torsional vs c_s/(2L)."""
    R, L = 0.01, 0.2
    rod = {"shape": "cylinder", "radius": R, "length": L}
    out = []
    f_rl = rayleigh_love_f1(R, L)
    for kin, h in (("axisymmetric", 0.002), ("3d", 0.004)):
        modes, labels = _modes(f"modal_rod_{kin}", kin, STEEL, {**rod, "element_size": h * SIZES[size]},
                               10, 1, workdir)
        # linear elements with consistent mass sit slightly above; 0.5% at 2 to 5 elements per radius
        out.append(check(f"modal_rod.{kin}.first_longitudinal [Hz]", f_rl, _first(modes, labels, "longitudinal"),
                         0.005, modes.wall_time_s, modes.dofs))
        if kin == "3d":
            G = STEEL["youngs_modulus"] / (2 * (1 + STEEL["poisson_ratio"]))
            c_s = math.sqrt(G / STEEL["density"])
            out.append(check("modal_rod.3d.first_torsional [Hz]", c_s / (2 * L), _first(modes, labels, "torsional"),
                             0.005, modes.wall_time_s, modes.dofs))
            out[-1]["note"] = ("first modes: " + ", ".join(f"{f:.5g} Hz {lab['label']}"
                                                           for f, lab in zip(modes.frequencies[:6], labels)))
    return out


def nafems_fv12(size, workdir):
    """NAFEMS FV12 free thin square plate: f4-f9 within 2% (quadratic hexahedra)."""
    material = {"density": 8000.0, "youngs_modulus": 200e9, "poisson_ratio": 0.3}
    plate = {"shape": "box", "size": [10.0, 10.0, 0.05], "element_size": 0.5 * SIZES[size]}
    modes, labels = _modes("nafems_fv12", "3d", material, plate, 6, 2, workdir)
    out = []
    for k, (ref, f) in enumerate(zip(FV12, modes.frequencies), start=4):
        out.append(check(f"nafems_fv12.f{k} [Hz]", ref, f, 0.02, modes.wall_time_s, modes.dofs))
    out[0]["note"] = f"{modes.rigid} rigid-body modes found; labels: " + ", ".join(lab["label"] for lab in labels)
    return out


def circular_plate(size, workdir):
    """Free circular plate against Kirchhoff's frequencies: axisymmetric (9.069) and 3D (all three)."""
    a, h, nu = 0.5, 0.01, 0.33
    material = {**STEEL, "poisson_ratio": nu}
    D = STEEL["youngs_modulus"] * h ** 3 / (12 * (1 - nu ** 2))

    def frequency(lambda2):
        return lambda2 / a ** 2 * math.sqrt(D / (STEEL["density"] * h)) / (2 * math.pi)

    disc = {"shape": "cylinder", "radius": a, "length": h}
    out = []
    modes, labels = _modes("circular_plate_axi", "axisymmetric", material,
                           {**disc, "element_size": 0.01 * SIZES[size]}, 2, 2, workdir)
    out.append(check("circular_plate.axisymmetric.lambda2=9.069 [Hz]", frequency(9.069), modes.frequencies[0],
                     0.01, modes.wall_time_s, modes.dofs))
    modes, labels = _modes("circular_plate_3d", "3d", material, {**disc, "element_size": 0.04 * SIZES[size]},
                           6, 2, workdir)
    # the n = 2 and n = 3 modes come in pairs (two orientations); n = 0 is single
    found = np.array(modes.frequencies)
    for name, lambda2 in PLATE_LAMBDA2.items():
        ref = frequency(lambda2)
        nearest = float(found[np.argmin(np.abs(found - ref))])
        out.append(check(f"circular_plate.3d.lambda2={name} [Hz]", ref, nearest, 0.01, modes.wall_time_s,
                         modes.dofs))
    out[-1]["note"] = "3D modes: " + ", ".join(f"{f:.5g}" for f in found)
    return out


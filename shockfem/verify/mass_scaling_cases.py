"""Verification of mass scaling (``model/mass_scaling.py``) on the two-rod contact case of ``shockfem bench``
(steel rods R 25 mm, L 100 mm, the striker at 10 m/s onto the target at rest, 200 us).

What mass scaling may do to a result is bounded by what the mesh already does to it: the change of the
target's final speed when the elements are halved.  Two runs are checked against that bound:

* uniform, 1% added: a target step sqrt(1.01) times the rods' element step gives every element 1% more
  density (the largest effect 1% of added mass can have: all of it where the waves run);
* selective: the target's struck face refined (0.7 of the element size, growing back over two elements: an
  unstructured graded mesh, as around a fillet or a contact face), the run scaled to the step of the
  target's 5th-percentile element: mass goes to the smallest 5% of its elements only, the striker's stay
  as they are, and the run takes the larger step.
"""
from __future__ import annotations

import math

import numpy as np


from ..model.mass_scaling import element_steps
from ..materials import layout
from .checks import SIZES, check
from .contact_cases import two_rods_scene
from .scenes import solve


def _run(raw: dict, workdir):
    solver, wall = solve(raw, cache_dir=workdir)
    v, _ = solver.body_means()
    return solver, wall, abs(float(v[1, -1]))


def _element_steps(solver) -> np.ndarray:
    """The element steps of the solver's deformable cells (safety factor included), from its rows as scaled."""
    m = solver.model
    cells = m.kernel_cells
    cell_name = m.meshed.mesh.topology.cell_name()
    return element_steps(m.X0, m.dofmap[cells], cell_name, m.params[m.cell_material[cells], layout.P_WAVE_SPEED],
                         m.safety_factor)


def mass_scaling(size, workdir):
    """Mass scaling moves the two-rod impact less than halving the elements does.

    1% added uniformly, and a refined face scaled to its 5th-percentile element step (only those
    elements get mass)."""
    h = 0.00125 * SIZES[size]
    base, wall0, v_base = _run(two_rods_scene(h), workdir)
    _, wall1, v_fine = _run(two_rods_scene(h / 2), workdir)
    mesh_effect = abs(v_fine - v_base)
    step = float(_element_steps(base).min())

    # uniform: 1% added to every element
    raw = two_rods_scene(h)
    raw["scene"]["mass_scaling_step"] = step * math.sqrt(1.01) * (1 + 1e-9)
    uniform, wall2, v_uniform = _run(raw, workdir)
    ms = uniform.model.mass_scaling
    share = sum(ms.added_mass.values()) / sum(float(uniform.model.body_mass[i]) - ms.added_mass[b.name]
                                              for i, b in enumerate(uniform.model.bodies))

    # selective: the struck face refined to 0.7 h over 2 h (an unstructured graded mesh), scaled to the step of
    # its 5th-percentile element: the smallest 5% of the target's elements get mass
    refined = two_rods_scene(h)
    refined["bodies"][1]["refine"] = [{"region": "top", "size": 0.7 * h, "distance": 2 * h}]
    plain, wall3, v_plain = _run(refined, workdir)
    steps = _element_steps(plain)[plain.model.cell_body[plain.model.kernel_cells] == 1]
    target_step = float(np.percentile(steps, 5))
    scaled_raw = two_rods_scene(h)
    scaled_raw["bodies"][1]["refine"] = refined["bodies"][1]["refine"]
    scaled_raw["scene"]["mass_scaling_step"] = target_step
    scaled, wall4, v_scaled = _run(scaled_raw, workdir)
    sel = scaled.model.mass_scaling
    target_body_mass = float(scaled.model.body_mass[1]) - sel.added_mass["target"]
    wall = wall0 + wall1 + wall2 + wall3 + wall4
    n = scaled.model.num_cells_global
    out = []
    c = check("mass_scaling.uniform_added_share [-]", 0.01, share, 0.005, wall, n)
    c["note"] = f"{ms.cells['striker'] + ms.cells['target']} elements scaled, density factor {ms.largest_factor:.5f}"
    out.append(c)
    c = check("mass_scaling.uniform_effect_vs_mesh [-, abs, <= 1]", 0.0, abs(v_uniform - v_base) / mesh_effect, 1.0,
              wall, n, absolute=True)
    c["note"] = (f"target speed {v_base:.5f} m/s, with 1% added {v_uniform:.5f}, at h/2 {v_fine:.5f} m/s: the mass "
                 f"moves it {abs(v_uniform - v_base):.2e}, the mesh {mesh_effect:.2e}")
    out.append(c)
    # only the refined layer is scaled: the striker keeps its mass, the target gains a few per cent
    out.append(check("mass_scaling.selective_striker_cells [-, abs]", 0, sel.cells["striker"], 0, wall, n,
                     absolute=True))
    c = check("mass_scaling.selective_step [s]", target_step, float(_element_steps(scaled).min()), 0.003, wall, n)
    c["note"] = (f"the refined run's element step {float(steps.min()):.4g} s unscaled; {plain.step} steps "
                 f"unscaled, {scaled.step} scaled; {sel.cells['target']} target elements scaled, "
                 f"+{sel.added_mass['target'] / target_body_mass:.2%} of its mass")
    out.append(c)
    c = check("mass_scaling.selective_effect_vs_mesh [-, abs, <= 1]", 0.0, abs(v_scaled - v_plain) / mesh_effect,
              1.0, wall, n, absolute=True)
    c["note"] = (f"target speed refined {v_plain:.5f} m/s, refined and scaled {v_scaled:.5f}: the mass moves it "
                 f"{abs(v_scaled - v_plain):.2e}, halving the elements {mesh_effect:.2e}")
    out.append(c)
    out.append(check("mass_scaling.energy_balance [-, abs]", 0.0, scaled.energy.balance_error, 0.01, wall, n,
                     absolute=True))
    return out

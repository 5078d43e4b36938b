"""Verification of the slotted ring's hoop law (the axisymmetric split cone, ``materials/slotted.py``).

A thin split ring (bore 38 mm, outer radius 40 mm, 10 mm long, 4 slots of 1 mm) is squeezed
inward by a radial velocity on its outer face, ramped to 5 m/s over 20 us.  Its slots close when
the circumference has shrunk by their total width W: at the inward displacement
u_c = W / (2 pi) = 0.637 mm, 137 us.  Before that the segments carry no hoop stress; after it
the ring is whole, the metal's hoop length 2 pi r against its natural 2 pi r0 - W, so

    sigma_tt = -E (u - u_c) / (r0 - u_c)          (thin ring: sigma_rr and sigma_zz ~ 0)

The same ring of a yielding steel (400 MPa, tangent 2.1 GPa) follows the bilinear uniaxial curve
sigma_y + E_t (eps - sigma_y / E) in hoop compression instead.  A ring without slots carries -E u / r0 from the
start, which is what the axisymmetric split cone did before this law.
"""
from __future__ import annotations

import math

import numpy as np

from .checks import SIZES, check, element_count
from .scenes import solve

RING = {"outer_radius": 0.040, "bore": 0.038, "length": 0.010, "segments": 4, "slot_width": 0.001}
SPEED, RAMP = 5.0, 20e-6
STEEL = {"density": 7850.0, "youngs_modulus": 210e9, "poisson_ratio": 0.3}
YIELDING = dict(STEEL, yield_stress=400e6, tangent_modulus=2.1e9)


def _ring_scene(h, end_time, fields, segments=RING["segments"]):
    return {"scene": {"name": "slotted_ring", "kinematics": "axisymmetric", "end_time": end_time},
            "materials": {"steel": dict(fields)},
            "bodies": [{"name": "ring", "material": "steel", "shape": "split_cone",
                        "outer_radius": RING["outer_radius"], "length": RING["length"], "entry_radius": RING["bore"],
                        "exit_radius": RING["bore"], "segments": segments, "slot_width": RING["slot_width"],
                        "element_size": h}],
            "boundary": [{"region": "ring.side", "type": "velocity", "direction": "r",
                          "history": [[0.0, 0.0], [RAMP, -SPEED], [1.0, -SPEED]]}],
            "outputs": {"field_interval": end_time, "history_interval": end_time / 50}}


def _inward(t):
    """The outer face's inward displacement at t (after the ramp)."""
    return SPEED * (t - 0.5 * RAMP)


def _hoop(solver):
    """Per cell: reference radius r0 and hoop stress."""
    m = solver.model
    cells = m.kernel_cells
    r0 = m.X0[m.dofmap[cells]].mean(axis=1)[:, 0]
    return r0, solver.sigma[cells, 0, 2]


def slotted_ring(size, workdir):
    """Open slots carry no hoop stress (to 1e-9 of a whole ring's), the closing time, and the hoop
    stress of the closed ring against -E (u - u_c) / (r0 - u_c) (within 3%), elastic and yielding."""
    h = 0.0005 * SIZES[size]
    E = STEEL["youngs_modulus"]
    width = RING["segments"] * RING["slot_width"]
    u_c = width / (2 * math.pi)
    t_open, t_closed = 100e-6, 170e-6
    out = []

    solver, wall = solve(_ring_scene(h, t_open, STEEL), cache_dir=workdir)
    whole, wall_w = solve(_ring_scene(h, t_open, STEEL, segments=1), cache_dir=workdir)
    n = element_count(solver)
    r0, hoop = _hoop(solver)
    _, hoop_whole = _hoop(whole)
    u = _inward(t_open)
    ratio = np.abs(hoop).max() / np.abs(hoop_whole).max()
    c = check("slotted_ring.open_hoop_stress [-, of a whole ring's]", 0.0, ratio, 1e-9, wall, n, absolute=True)
    c["note"] = (f"at {t_open * 1e6:.0f} us (u = {u * 1e3:.3f} mm < u_c = {u_c * 1e3:.3f} mm): slotted max |hoop| "
                 f"{np.abs(hoop).max():.3g} Pa; a whole ring {hoop_whole.mean() / 1e6:.1f} MPa "
                 f"(exact -E u / r0: {np.mean(-E * u / r0) / 1e6:.1f} MPa)")
    out.append(c)
    out.append(check("slotted_ring.whole_ring_hoop [Pa, mean]", np.mean(-E * u / r0), hoop_whole.mean(), 0.03,
                     wall_w, n))

    solver, wall = solve(_ring_scene(h, t_closed, STEEL), cache_dir=workdir)
    r0, hoop = _hoop(solver)
    u = _inward(t_closed)
    exact = -E * (u - u_c) / (r0 - u_c)
    c = check("slotted_ring.closed_hoop [Pa, mean]", exact.mean(), hoop.mean(), 0.03, wall, n)
    c["note"] = (f"at {t_closed * 1e6:.0f} us, u = {u * 1e3:.3f} mm: closed {u_c * 1e3:.3f} mm at "
                 f"{(u_c / SPEED + 0.5 * RAMP) * 1e6:.1f} us; cell-wise worst {np.abs(hoop / exact - 1).max():.2%}")
    out.append(c)

    yielding, wall = solve(_ring_scene(h, t_closed, YIELDING), cache_dir=workdir)
    r0, hoop = _hoop(yielding)
    sy, Et = YIELDING["yield_stress"], YIELDING["tangent_modulus"]
    strain = (u - u_c) / (r0 - u_c)
    flow = -(sy + Et * (strain - sy / E))                        # bilinear, uniaxial
    out.append(check("slotted_ring.closed_yielding_hoop [Pa, mean]", flow.mean(), hoop.mean(), 0.02, wall, n))
    return out

"""Verification of the pads' finite-element restitution (``shockfem/machine/pads.py``) against closed forms.

* ``pad_bars``: a bare flat interface (the pads module's own scene, pad ``none``) of two slender steel
  rods of equal impedance, the striker half as long as the struck rod, at 5 m/s (elastic): the restitution
  is the wave the longer rod keeps, L_a / L_b in St Venant's theory, and the project's 1D bars
  (``amplifier.bars``) with the same band damping give it with the damping's loss; the axisymmetric run
  against the 1D bars within 3%, the tolerance the axisymmetric-vs-1D case of the amplifier holds
  (rods 20 diameters long: their lateral inertia).
* ``pad_rigid``: a polyurethane pad (95A) between two compact steel masses at 2 m/s, compressed 5%: the
  masses move as rigid bodies (their transit is 3% of the contact) and the pad is light (1.4% of a mass)
  and quick (its transit 5% of the contact), so its restitution is that of rigid masses on a spring-dashpot
  that never pulls at the pad's damping ratio (``amplifier.rigid.pad_restitution``).
* ``pad_johnson``: an elastic-perfectly-plastic steel sphere on a rigid flat, far above its yield speed:
  Johnson's estimate (Contact Mechanics, 1985, sec. 11.5) of a fully plastic loading at the mean pressure
  p_m = 3 Y and a Hertzian elastic unloading (``amplifier.interfaces.plastic_restitution``: the constant
  3.74 derived from those two steps, which Johnson prints as 3.8), falling as V^(-1/4).  The exponent is the law's firm part
  (checked between 5 and 10 m/s); the constant rests on p_m = 3 Y, which Tabor's measured hardness puts
  at 2.8 to 3 Y, and on an unloading that leaves pile-up out.
"""
from __future__ import annotations

import math
import os
from dataclasses import replace

from ..amplifier import rigid
from ..amplifier.bars import Bar, Interface as BarInterface, run_bars
from ..amplifier.interfaces import plastic_restitution, thornton_restitution
from ..machine.pad_materials import pad_material
from ..machine.pads import (DAMPING_BAND, STRUCTURAL_DAMPING, Interface, RunCache, measure_restitution, parted,
                            size_pad)
from ..output.history_file import read_history_csv
from ..runner import run_scene
from ..scene import resolve
from ..scene.library import property_si
from .checks import check

STEEL = "high_strength_steel"


def _run_checks(name: str, reference: float, m, tolerance: float) -> list[dict]:
    """A pad run's restitution against ``reference``, that its faces parted, and its energy balance (1%)."""
    case = name.split(".")[0]
    return [check(f"{name} [-]", reference, m.restitution, tolerance, m.wall_time_s, m.elements),
            check(f"{case}.faces_parted [count]", 1, int(m.parted), 0.0, m.wall_time_s, m.elements, absolute=True),
            check(f"{case}.energy_balance [-, abs]", 0.0, m.energy_balance_error, 0.01, m.wall_time_s, m.elements,
                  absolute=True)]


def pad_bars(size, workdir):
    """A bare flat interface of two equal-impedance rods (L 0.1 / 0.2 m, D 20 mm, 5 m/s): FE against 1D bars."""
    d, La, Lb, v = 0.02, 0.1, 0.2, 5.0
    rho, E = property_si(STEEL, "density", "density"), property_si(STEEL, "youngs_modulus", "pressure")
    A = math.pi * d * d / 4
    iface = Interface("a_b", rho * A * La, d, La, rho * A * Lb, d, Lb, v, STEEL, 1e12)
    resolution = {"coarse": "coarse", "default": "default", "fine": "default"}[size]
    m, _ = RunCache(os.path.join(workdir, "pad_bars")).measure(iface, "none", resolution)
    c0 = math.sqrt(E / rho)
    bars = [Bar("a", La, A, rho, E, v), Bar("b", Lb, A, rho, E)]
    r = run_bars(bars, [BarInterface("a_b")], 8 * Lb / c0, damping_ratio=[STRUCTURAL_DAMPING] * 2,
                 damping_frequency=[0.0, 0.0],
                 damping_band=[(c0 / (2 * L), DAMPING_BAND * c0 / (2 * L)) for L in (La, Lb)],
                 damping_reference=[None, None])
    v_a, v_b = r.history["a.v_z"][-1], r.history["b.v_z"][-1]
    e_1d = (v_b - v_a) / v
    out = _run_checks("pad_bars.restitution_vs_1d_bars", e_1d, m, 0.03)
    out[0]["note"] = (f"St Venant (undamped) L_a / L_b = {La / Lb:g}; the 1D bars with the band damping "
                      f"{e_1d:.4f}, the axisymmetric run {m.restitution:.4f}")
    return out


def pad_rigid(size, workdir):
    """A 95A pad (D 100 mm, 10 mm) between steel masses (D 100 mm, L 100 mm) at 2 m/s: FE against rigid masses
    on a spring-dashpot that never pulls, at the pad's damping ratio."""
    rho = property_si(STEEL, "density", "density")
    d, L, v = 0.1, 0.1, 2.0
    mass = rho * math.pi * d * d / 4 * L
    iface = Interface("a_b", mass, d, L, mass, d, L, v, STEEL, 1e12)
    mat = pad_material("pu_95a")
    # the pads module sizes the pad to its working point; this case wants a thin one at small strain
    pad = size_pad(iface, "pu_95a", math.sqrt(mat.resilience))
    t = 0.01
    k = mat.youngs_modulus * math.pi * d * d / 4 / t
    pad = replace(pad, thickness=t, mass=mat.density * math.pi * d * d / 4 * t,
                  contact_time=math.pi * math.sqrt(iface.m_star / k))
    resolution = {"coarse": "coarse", "default": "default", "fine": "default"}[size]
    m = measure_restitution(iface, pad, os.path.join(workdir, "pad_rigid"), resolution)
    e_rigid = rigid.pad_restitution(mat.damping_ratio())
    # 6%: measured 4.6% above at coarse size (0.6615 against 0.6325) and 4.5% at the default (0.6610):
    # converged, the difference the band's Maxwell terms, whose memory lets the pad go otherwise than a
    # Kelvin-Voigt dashpot of the same ratio would, and their 2% ripple (``materials.band_damping.RIPPLE``).
    # A lost hysteresis gives e near 1, a doubled ratio about 0.4
    out = _run_checks("pad_rigid.restitution_vs_rigid_pad", e_rigid, m, 0.06)
    out[0]["note"] = (f"zeta = {mat.damping_ratio():.4f} from the rebound resilience {mat.resilience:g}; "
                      f"rigid masses {e_rigid:.4f}, finite elements {m.restitution:.4f}")
    return out


def _sphere_on_flat(speed, radius, material, size, workdir):
    h = 0.001 * {"coarse": 2.0, "default": 1.0, "fine": 0.5}[size]
    a = (4 * radius * 0.5 * material["density"] * 4 / 3 * math.pi * radius ** 3 * speed ** 2
         / (math.pi * 3 * material["yield_stress"])) ** 0.25
    c0 = math.sqrt(material["youngs_modulus"] / material["density"])
    contact = 4 * a * a / (2 * radius) / speed + 4 * radius / c0
    raw = {"scene": {"name": f"johnson_{speed:g}", "kinematics": "axisymmetric", "end_time": contact},
           "materials": {"ball": material},
           "bodies": [{"name": "ball", "material": "ball", "shape": "sphere", "radius": radius, "element_size": h,
                       # the contact radius over 15 cells at every size
                       "pole_element_size": min(a / 15, 0.1 * h), "position": [0.0, 1e-6],
                       "velocity": [0.0, -speed]}],
           "contact": [{"name": "flat", "a": "ball.bottom", "penalty_scale": 1.0,
                        "wall": {"point": [0.0, 0.0], "normal": [0.0, 1.0]}}],
           "outputs": {"field_interval": contact, "history_interval": contact / 400}}
    where = os.path.join(workdir, f"johnson_{speed:g}")
    res = run_scene(resolve(raw), where, progress=False, write_fields=False, quiet=True)
    s = res.summary
    s["parted"] = parted(read_history_csv(os.path.join(where, "history.csv")), ["flat"])
    return s["bodies"]["ball"]["velocity_final"][-1] / speed, s


def pad_johnson(size, workdir):
    """A steel sphere (R 10 mm, Y 1 GPa, perfectly plastic) on a rigid flat at 5 and 10 m/s (150 and 290 times
    its yield speed): Johnson's fully plastic restitution and its V^(-1/4)."""
    radius = 0.01
    material = {"density": 7850.0, "youngs_modulus": 210e9, "poisson_ratio": 0.3, "yield_stress": 1e9,
                "tangent_modulus": 0.0}
    runs = {v: _sphere_on_flat(v, radius, material, size, workdir) for v in (5.0, 10.0)}
    m = material["density"] * 4 / 3 * math.pi * radius ** 3
    e_star = material["youngs_modulus"] / (1 - material["poisson_ratio"] ** 2)      # on a rigid flat
    out = []
    wall = sum(s["wall_time_s"] for _, s in runs.values())
    cells = runs[5.0][1]["elements"]
    for v, (e, s) in runs.items():
        # 20%: the runs are converged (0.5629 and 0.4677 at coarse size, 0.5560 and 0.4641 at the default) and
        # 14 to 16% below the closed form, whose constant is an estimate: a mean pressure of 3 Y throughout
        # (Tabor's hardness: 2.8 to 3 Y; e goes as p_m^(5/8)), no elastic share of the loading, a Hertzian
        # unloading of the truncated sphere.  A yield stress off by 2 moves e by 54%, no plasticity to about 1
        johnson = plastic_restitution(v, m, radius, e_star, material["yield_stress"])
        out.append(check(f"pad_johnson.V={v:g}.restitution [-]", johnson, e, 0.20, s["wall_time_s"], s["elements"]))
        thornton = thornton_restitution(v, m, radius, e_star, material["yield_stress"])
        out[-1]["note"] = (f"Johnson's fully plastic estimate {johnson:.4f} (an upper estimate: p_m = 3 Y throughout), "
                           f"Thornton's model {thornton:.4f} (pressure capped at 1.6 Y: a lower one), the run {e:.4f}")
    slope = math.log(runs[10.0][0] / runs[5.0][0]) / math.log(2.0)
    # 0.05 on the exponent -1/4: between 5 and 10 m/s the elastic share of the loading (V_y / V)^(1/2) is
    # about 8%, which moves the local exponent by a few hundredths
    out.append(check("pad_johnson.exponent [-, abs]", -0.25, slope, 0.05, wall, cells, absolute=True))
    out.append(check("pad_johnson.faces_parted [count]", len(runs), sum(s["parted"] for _, s in runs.values()), 0.0,
                     wall, cells, absolute=True))
    out.append(check("pad_johnson.energy_balance [-, abs]", 0.0,
                     max(s["energy"]["balance_error"] for _, s in runs.values()), 0.01, wall, cells, absolute=True))
    return out



# the mesh study's interface: the pad tests' first (``tests/sim/test_pad_runs.py``): 8 kg on 4 kg steel
# cylinders (length = diameter) closing at 3 m/s on a 90A pad sized at its working point
MESH_STUDY = {"masses": (8.0, 4.0), "speed": 3.0, "material": "pu_90a"}
# the levels each verify size runs: the design's own mesh (smoke) and three refined by 2 for Richardson
MESH_LEVELS = {"coarse": ("smoke", "coarse", "default"), "default": ("smoke", "coarse", "default", "fine"),
               "fine": ("smoke", "coarse", "default", "fine")}


def _mesh_study_pad():
    """``MESH_STUDY``'s interface (rounded, as the pads module runs it) and its pad sized at its working point."""
    from ..amplifier.gain import cylinder_size
    from ..machine.pads import estimated_restitution
    from ..scene.library import initial_yield_stress
    rho = property_si(STEEL, "density", "density")
    (m_a, m_b), v, name = MESH_STUDY["masses"], MESH_STUDY["speed"], MESH_STUDY["material"]
    a, b = cylinder_size(m_a, rho, 1.0), cylinder_size(m_b, rho, 1.0)
    iface = Interface("a_b", m_a, a["diameter"], a["length"], m_b, b["diameter"], b["length"], v, STEEL,
                      initial_yield_stress(STEEL) / 1.5).rounded()
    return iface, size_pad(iface, name, estimated_restitution(name))


def _convergence(order: float, estimate: float) -> str:
    """Three meshes' convergence in words (``checks.richardson``)."""
    if math.isfinite(estimate):
        return f"order {order:.3g}, Richardson {estimate:.5g}"
    if math.isfinite(order):
        return f"order {order:.3g}: the differences grow with refinement, no Richardson estimate"
    return "the differences change sign: not in the asymptotic range, no Richardson estimate"


def pad_mesh(size, workdir):
    """One 90A pad between compact masses (``MESH_STUDY``) at three meshes refined by 2 (and the design's
    smoke mesh): the restitution's observed order and Richardson estimate, the design's mesh against it,
    and the peak contact stress over the pad's face, whose spread over the meshes the resizing's band
    must hold."""
    from ..machine.pads import RESIZE_BAND, pad_contact_stress
    from .checks import richardson
    # one pad at every mesh: the geometry fixed, only the cells change
    iface, pad = _mesh_study_pad()
    name = MESH_STUDY["material"]
    working = pad_material(name).working_stress
    runs = {r: measure_restitution(iface, pad, os.path.join(workdir, f"pad_mesh_{r}"), r) for r in MESH_LEVELS[size]}
    levels = MESH_LEVELS[size][-3:]
    e = [runs[r].restitution for r in levels]
    stress = {r: pad_contact_stress(iface, pad, m) / working for r, m in runs.items()}
    p_e, e_inf = richardson(*e)
    p_s, s_inf = richardson(*(stress[r] for r in levels))
    finest = runs[levels[-1]]
    wall = sum(m.wall_time_s for m in runs.values())
    table = "; ".join(f"{r} ({m.elements} cells) e {m.restitution:.5f}, peak {stress[r]:.4f} of the working stress"
                      for r, m in runs.items())
    # 0.5%: the design's smoke meshes measured 0.17% from the estimate (smoke, coarse, default) and 0.28%
    # (coarse, default, fine); a restitution that does not converge has no estimate (nan: fails), and the
    # chain's gain moves by about n e-shares of it
    out = [check(f"pad_mesh.restitution_{levels[-1]}_vs_richardson [-]", e_inf, finest.restitution, 0.005, wall,
                 finest.elements),
           check("pad_mesh.restitution_smoke_vs_richardson [-]", e_inf, runs["smoke"].restitution, 0.005, wall,
                 runs["smoke"].elements)]
    out[0]["note"] = f"{table}; restitution {_convergence(p_e, e_inf)}; peak stress {_convergence(p_s, s_inf)}"
    # 1 - RESIZE_BAND (7%): the design checks a pad's peak on its smoke mesh and resizes it into RESIZE_BAND to
    # 1 of its working stress; the smoke mesh's peak within the band's width of the finest's keeps a pad the
    # band accepts within its limit there (measured 4.2% above the fine mesh's, 6.5% above the coarse's)
    out.append(check(f"pad_mesh.peak_stress_smoke_vs_{levels[-1]} [-]", stress[levels[-1]], stress["smoke"],
                     1 - RESIZE_BAND, wall, runs["smoke"].elements))
    out += _run_checks("pad_mesh", e_inf, finest, 1.0)[1:]
    return out


def pad_1d(size, workdir):
    """The mesh study's 90A pad (``MESH_STUDY``) between its two steel bodies as three 1D bars (the pad's own
    mass and waves, linear elastic in uniaxial stress, its hysteresis a Kelvin-Voigt dashpot of its damping
    ratio at its contact's frequency; kinematic contact), against the axisymmetric run (Neo-Hookean, the
    hysteresis as a band of Maxwell terms, penalty contact, the pad free to bulge)."""
    from ..machine.pads import interface_scene
    rho = property_si(STEEL, "density", "density")
    E = property_si(STEEL, "youngs_modulus", "pressure")
    iface, pad = _mesh_study_pad()
    v, mat = iface.speed, pad_material(MESH_STUDY["material"])
    resolution = {"coarse": "coarse", "default": "default", "fine": "default"}[size]
    fe = measure_restitution(iface, pad, os.path.join(workdir, "pad_1d"), resolution)
    raw = interface_scene(iface, pad, resolution)
    c0 = math.sqrt(E / rho)
    bars = [Bar("a", iface.striker_length, iface.striker_mass / (rho * iface.striker_length), rho, E, v, 40),
            Bar("pad", pad.thickness, math.pi * pad.diameter ** 2 / 4, mat.density, mat.youngs_modulus, 0.0, 40),
            Bar("b", iface.struck_length, iface.struck_mass / (rho * iface.struck_length), rho, E, 0.0, 40)]
    steel_band = [(c0 / (2 * L), DAMPING_BAND * c0 / (2 * L)) for L in (iface.striker_length, iface.struck_length)]
    r = run_bars(bars, [BarInterface("a_pad", gap=1e-3), BarInterface("pad_b")], raw["scene"]["end_time"],
                 damping_ratio=[STRUCTURAL_DAMPING, mat.damping_ratio(), STRUCTURAL_DAMPING],
                 damping_frequency=[0.0, 1 / (2 * pad.contact_time), 0.0],
                 damping_band=[steel_band[0], None, steel_band[1]], damping_reference=[None, None, None])
    hist = r.history
    m_struck = r.masses["pad"] + r.masses["b"]
    v_struck = (r.masses["pad"] * hist["pad.v_z"][-1] + r.masses["b"] * hist["b.v_z"][-1]) / m_struck
    e_1d = (v_struck - hist["a.v_z"][-1]) / v
    # 6%: the pad_rigid case's (the band's Maxwell terms let a pad go otherwise than a Kelvin-Voigt dashpot of
    # the same ratio: 4.6% there); measured 2.8% at coarse size (the 1D bars 0.6779, the run 0.6970); a lost
    # hysteresis in either gives e near 1, a doubled ratio about 0.4
    out = _run_checks("pad_1d.restitution_fe_vs_1d_viscoelastic", e_1d, fe, 0.06)
    out[0]["note"] = (f"rigid masses on the pad's spring-dashpot {rigid.pad_restitution(mat.damping_ratio()):.4f}; "
                      f"1D viscoelastic bars {e_1d:.4f} (energy balance {r.energy_balance_error:.2g}); "
                      f"axisymmetric run {fe.restitution:.4f}: FE - 1D = {fe.restitution - e_1d:+.4f}")
    return out

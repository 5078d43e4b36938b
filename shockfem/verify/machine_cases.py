"""Verification of the whole machine's geometry and closed forms (``shockfem design-machine``).

``machine_geometry``: the solids of the STEP assembly against the closed forms the design weighs them by,
for the 12 lb machine's sizes.  OpenCASCADE integrates each solid's volume from its faces; the design
computes it by formula, so the two are independent:

* the launcher's tank: a cylinder with hemispherical heads, its steel pi ((R + t)^2 - R^2) L_cyl +
  4/3 pi ((R + t_h)^3 - R^3) at the ASME thicknesses (``launcher.vessel.tank_weight`` over the density);
* the striker's housing: pi ((R^2 - r^2) L_bore + R^2 t_floor);
* the article: the catalogue's ogive, its nose pi * integral of r(z)^2 (``parts.catalog``), turned end
  over end in the assembly.

And the housing's two rules at their sizing (``programmer.housing``, which the machine's fixture sizes
by): the wall ``wall_for`` gives holds the pressure by ASME VIII-2 4.3.3, S ln(b / a) = P, and the floor
``floor_for`` gives is VIII-2 4.6's integral flat head, t = d sqrt(0.17 P / S) (each against its
expression written out here).

``machine_energy``: the 12 lb machine's energy table closes: its parts, each from the model that owns
it (the gun's accounts, the chain's 1D stage table, the fixture's column run integrated from its
pressures and its force on the payload), sum to the gas work within 0.5%; and the gas work the table takes from the gun
equals the isentropic expansion work p0 V0 (1 - (V0 / V1)^(gamma - 1)) / (gamma - 1) where the gun is that
closed form (no valve, massless gas, an evacuated barrel), and the gas stored is p0 V0 / (gamma - 1).

``direct_striker``: the direct-striker gun (the 12 lb design's striker, 501.5 kg at 412.0 m/s, alone, within
the machine's limits, from the machine's full-bore-valve gun: the premise's (b0)) against the launcher
model's own verification, the brute-force grid of ``launcher_design`` (no grid gun lighter), and its
launch energy M V^2 / 2.  The striker is a representative point, fixed: it is the one the premise
reports (``shockfem design-machine --article "12 lb"``), not derived on each run because the fixture's
design that gives it takes over a minute (83 s for the 12 lb design).  The check is of the gun's optimiser against a brute-force search
of the same model within the same limits, which holds for any striker the gun can fire; this one is
chosen because its gun is the premise's, at the limits where the verdict is read.
"""
from __future__ import annotations

import dataclasses

import math
import time

import gmsh

from ..launcher.design import Limits
from ..launcher.gun import Gun, fire, white_paper_gun
from ..launcher.vessel import MATERIALS, tank_diameter_for, tank_weight
from ..machine.cad import article_solid, empty_gmsh, housing_solid, tank_solid
from ..programmer.housing import HOUSING_STEELS, floor_for, wall_for
from ..machine.layout import Item
from ..parts.catalog import PARTS, solid_ogive, solid_ogive_length
from ..scene.library import property_si
from .checks import check
from .launcher_cases import against_grid

# the 12 lb machine's sizes (``shockfem design-machine --article "12 lb"``, rounded): the tank at 12.2 MPa
# holding 3.91 m^3, the housing's 79 mm bore in a 97 mm wall 1.47 m deep on a 15 mm floor, the 60 mm ogive
TANK = {"pressure": 12.2e6, "volume": 3.91, "aspect": 3.0, "material": "SA-516-70"}
HOUSING = {"bore_radius": 0.0395, "outer_radius": 0.0485, "depth": 1.47, "floor": 0.015}
ARTICLE = {"radius": 0.030, "mass": 5.443, "crh": 3.0, "meplat_over_radius": 0.2}
# OpenCASCADE's volume integration of these solids agrees with the closed forms to about 1e-10 (measured);
# 1e-6 would still catch a wrong head, a missing floor or a nose drawn at the wrong radius (each >1e-3)
VOLUME_TOL = 1e-6
PRESSURE = 126e6                         # a housing's peak oil pressure


def machine_geometry(size: str, workdir: str) -> list[dict]:
    """The STEP assembly's solids against the design's closed-form volumes; the housing's Lame wall and
    clamped floor at their allowable."""
    t0 = time.perf_counter()
    out = []
    with empty_gmsh():
        gmsh.model.add("machine_geometry")
        # the tank
        D = tank_diameter_for(TANK["volume"], TANK["aspect"])
        shell, head, weight = tank_weight(TANK["pressure"], TANK["volume"], D, TANK["material"])
        R = D / 2
        L_cyl = (TANK["volume"] - 4 / 3 * math.pi * R ** 3) / (math.pi * R * R)
        sizing = {"tank": {"diameter": D, "shell_thickness": shell.thickness, "head_thickness": head}}
        tank = Item("tank", "tank", 0.0, L_cyl + 2 * (R + head), D + 2 * shell.thickness, D)
        v = sum(gmsh.model.occ.getMass(3, t) for t in tank_solid(tank, sizing))
        out.append(check("tank steel volume [m^3] (capsule, ASME walls)",
                         weight / MATERIALS[TANK["material"]]["density"], v, VOLUME_TOL, 0.0, 0))
        # the housing
        h = HOUSING
        housing = Item("striker", "housing", 10.0, h["floor"] + h["depth"], 2 * h["outer_radius"],
                       2 * h["bore_radius"])
        v = sum(gmsh.model.occ.getMass(3, t) for t in housing_solid(housing, h["floor"]))
        ref = math.pi * ((h["outer_radius"] ** 2 - h["bore_radius"] ** 2) * h["depth"]
                         + h["outer_radius"] ** 2 * h["floor"])
        out.append(check("housing steel volume [m^3] (wall and floor)", ref, v, VOLUME_TOL, 0.0, 0))
        # the article
        a = ARTICLE
        rho = property_si("steel_4340", "density", "density")
        meplat = a["meplat_over_radius"] * a["radius"]
        L = solid_ogive_length(a["mass"], rho, a["radius"], a["crh"], meplat)
        art = Item("article", "article", 20.0, L, 2 * a["radius"])
        v = sum(gmsh.model.occ.getMass(3, t) for t in article_solid(art))
        ref = PARTS["projectile"].volume(solid_ogive(a["radius"], a["crh"], meplat, L), 3)
        out.append(check("article volume [m^3] (ogive, turned end over end)", ref, v, VOLUME_TOL, 0.0, 0))
    wall = time.perf_counter() - t0
    for c in out:
        c["wall_time_s"] = wall / 3
    # the housing's rules at their sizing, against the code's expressions (maraging 300's design stress)
    r, p = h["bore_radius"], PRESSURE
    S = HOUSING_STEELS["maraging_300"].allowed_stress()
    w = wall_for(p, r, "maraging_300")
    out.append(check("ASME VIII-2 4.3.3 wall: S ln(b / a) of the sized wall [Pa]", p, S * math.log(w.outer_radius / r),
                     1e-12, 0.0, 0))
    t = floor_for(p, r, "maraging_300")
    out.append(check("ASME VIII-2 4.6 integral flat head: 0.17 P d^2 / t^2 of the sized floor [Pa]", S,
                     0.17 * p * (2 * r) ** 2 / (t * t), 1e-12, 0.0, 0))
    return out


# the fixture's search runs in machine_energy below the default size (its docstring)
COARSE_EVALUATIONS = 30


def machine_energy(size: str, workdir: str) -> list[dict]:
    """The 12 lb machine's energy table closes on the gas work (its gun's shortfall, where it falls short of
    the launch speed, taken out: the models must agree on what they hand each other); the gas work and the
    gas stored against their closed forms.  The pads at 'estimate' (their runs are ``pad_*``'s cases; the
    table reads whatever restitutions the amplifier was designed on).  Below the default size the fixture's
    search takes ``COARSE_EVALUATIONS`` runs: the table closes on whatever fixture the machine carries, so a
    less searched one checks the same accounts in a quarter of the time."""
    from ..machine.design import design_machine
    from ..machine.energy import CLOSURE_TOL, isentropic_work
    from ..machine.fixture import DESIGN_EVALUATIONS
    from ..machine.spec import read_spec
    t0 = time.perf_counter()
    spec = dataclasses.replace(read_spec({"article": "12 lb"}), pad_resolution="estimate")
    evaluations = DESIGN_EVALUATIONS if size in ("default", "fine") else COARSE_EVALUATIONS
    m = design_machine(spec, workdir, starts=1, evaluations=evaluations)
    e = m.energy
    out = [check("machine_energy.parts_sum_to_the_gas_work_and_shortfall [J]", e.gas_work + e.shortfall, e.parts,
                 CLOSURE_TOL, time.perf_counter() - t0, 0)]
    out[-1]["note"] = (f"gas work {e.gas_work / 1e6:.4f} MJ, the gun's shortfall {e.shortfall / 1e6:.4f} MJ, parts "
                       f"{e.parts / 1e6:.4f} MJ ({e.models_closure:+.3%}); " + "; ".join(e.notes))
    # the gun as the closed form: the reservoir open on the bore, massless gas, nothing ahead
    t0 = time.perf_counter()
    g = Gun(0.05, 10e6, 0.1, 3.0, 20.0, air_ahead="evacuated", gas_inertia="none")
    shot = fire(g)
    gamma = g.gas_model().gamma
    V0, V1 = g.reservoir_volume, g.reservoir_volume + g.area * g.length
    # the integrator's rtol 1e-9 on the gas's energy: 1e-6 still catches a wrong exponent or volume (>1e-2)
    out.append(check("machine_energy.gas_work_isentropic [J]", isentropic_work(g.reservoir_pressure, V0, V1, gamma),
                     shot.energies["initial"] - shot.energies["gas_left"], 1e-6, time.perf_counter() - t0, 0))
    # with a valve the gun's initial gas also holds the air at ambient in the dead volume, one calibre of bore
    wp = white_paper_gun(100.0)
    stored = (wp.reservoir_pressure * wp.reservoir_volume + wp.ambient_pressure * wp.area * wp.bore) / (
        wp.gas_model().gamma - 1)
    out.append(check("machine_energy.gas_stored_p0V0/(gamma-1) [J]", stored, fire(wp, samples=2).energies["initial"],
                     1e-12, 0.0, 0))
    return out


# the 12 lb design's striker (``shockfem design-machine --article "12 lb"``, rounded): the housing, its pin and
# its oil, at the fixture's closing speed; a representative point (the module's docstring)
STRIKER = {"mass": 501.5, "speed": 412.0}


def direct_striker(size: str, workdir: str) -> list[dict]:
    """The direct-striker gun against the launcher design's brute-force grid; its launch energy."""
    from ..machine.launcher import SIZING, machine_gun
    from ..machine.premise import direct_launcher
    from ..machine.spec import read_spec
    n = {"coarse": 5, "default": 7, "fine": 9}[size]
    spec = read_spec({"article": "12 lb"})
    t0 = time.perf_counter()
    L, _ = direct_launcher(spec, STRIKER["mass"], STRIKER["speed"], None, starts=3, report_binding=False)
    wall = time.perf_counter() - t0
    limits = Limits(max_length=spec.max_barrel_length, max_bore=spec.max_bore, max_pressure=spec.max_pressure)
    out = against_grid("direct_striker", L.design, machine_gun(STRIKER["mass"], spec.gas), STRIKER["speed"], limits,
                       SIZING, n, wall)
    out[0]["note"] += ("; the 12 lb design's striker, a representative point: the optimiser against a brute-force "
                       "search of the same gun model, which holds for any striker it can fire")
    # the muzzle speed within 2e-4 of the asked (the optimiser's constraint): twice that on its square
    out.append(check("direct_striker.launch_energy M V^2 / 2 [J]", 0.5 * STRIKER["mass"] * STRIKER["speed"] ** 2,
                     L.launch_energy, 4e-4, 0.0, 0))
    return out

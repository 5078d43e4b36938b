"""Verification of concrete penetration: the closed-form law (``penetration/forrestal.py``) and the
finite-element load that applies it on a nose (``target/``, a scene's ``[penetration]``).

* ``forrestal``: the closed-form depth against the published data point of
  ``../shared/references/README.md`` (Forrestal et al. 1994: a 0.906 kg ogive of 26.9 mm diameter, CRH 2,
  into concrete of f'c = 35.2 MPa at 277 m/s: measured 173 mm, the model's 167 mm), and the closed form's
  tunnel depth against the equation of motion m V dV/dz = -pi a^2 (S f'c + N rho V^2) integrated
  numerically from the crater's exit speed V1 to rest.  The concrete's density is not in the reference;
  2300 kg/m^3 is taken (the depth moves by 0.2% between 2200 and 2500).
* ``penetration_rigid``: that shot as a finite-element run, a rigid projectile (axisymmetric) whose
  nose carries the facet law: its depth and velocity-depth curve (crater included) against the closed
  form with the mesh's own nose factor (within 1%), the mesh's nose factor against the ogive's
  (8 psi - 1) / (24 psi^2) (the quadrature of the facet law; the meplat adds its flat), and the depth
  against the published model and measurement.
* ``penetration_wave``: an elastic steel rod whose flat nose is already in the tunnel when the run
  starts, so the force pi a^2 (S f'c + rho V^2) (a flat nose: N = 1) comes on at once: 1D theory sends a
  step of stress F / A up the rod, reaching mid-length at L / (2 c0) and cancelled there by its
  reflection from the free base at 3 L / (2 c0) (the peak is twice the quasi-static F / 2A there).
* ``penetration_spin``: a spinning rod (3D) in the tunnel with the friction torque mu F a / 2: its spin
  falls at mu F a / (2 J).
* ``penetration_yaw``: a rigid ogive (3D) yawed 5 deg to its velocity, its nose wholly in the target:
  the load's force and moment about the tip against the integral of the normal stress over the exact
  nose surface (its advancing side only); and the same nose unyawed but spinning, with the friction
  torque: on its uneven tetrahedra the torque's forces must still have no resultant.
"""
from __future__ import annotations

import math
import time

import numpy as np
from scipy.integrate import solve_ivp

from ..parts.catalog import PARTS, ogive
from ..penetration.forrestal import depth, depth_of, speed_at_depth, tunnel_entry_speed_squared, tunnel_force
from ..scene.orientation import axis_angle
from ..target.concrete import crater_law, nose_factor, normal_stress, strength_factor
from .checks import SIZES, check, element_count
from .scenes import STEEL, solve, steel_c0

SHOT = {"mass": 0.906, "radius": 0.0269 / 2, "crh": 2.0, "fc": 35.2e6, "density": 2300.0, "speed": 277.0}
MEASURED_DEPTH, MODEL_DEPTH = 0.173, 0.167
MEPLAT = 0.5e-3          # the finite-element noses' flat tip [m] (a sharp point cannot be meshed)
YAW = math.radians(5.0)


def forrestal(size, workdir):
    """Depth against the published model and measurement; the closed form against its ODE."""
    s = SHOT
    t0 = time.perf_counter()
    P = depth(s["mass"], s["radius"], s["fc"], s["density"], s["speed"], s["crh"])
    wall = time.perf_counter() - t0
    out = [check("forrestal.depth_vs_published_model [m]", MODEL_DEPTH, P, 0.015, wall, 0),
           check("forrestal.depth_vs_measured [m]", MEASURED_DEPTH, P, 0.05, wall, 0)]
    # the tunnel: m V dV/dz = -F(V) integrated from V1 (the crater's exit speed) to rest
    t0 = time.perf_counter()
    a, m = s["radius"], s["mass"]
    v1 = math.sqrt(tunnel_entry_speed_squared(m, a, s["fc"], s["density"], s["speed"], s["crh"]))

    def slowing(z, y):            # y = V^2 / 2: d(V^2/2)/dz = -F(V) / m
        return [-tunnel_force(a, s["fc"], s["density"], math.sqrt(max(2 * y[0], 0.0)), s["crh"]) / m]

    def stopped(z, y):
        return y[0]
    stopped.terminal = True
    sol = solve_ivp(slowing, (0.0, 10.0), [0.5 * v1 * v1], events=stopped, rtol=1e-11, atol=1e-12)
    out.append(check("forrestal.tunnel_depth_vs_ode [m]", sol.t_events[0][0] + 4 * a, P, 1e-7,
                     time.perf_counter() - t0, 0))
    return out


# ---------------------------------------------------------------------------- the scenes
def _projectile_dims(mass: float) -> dict:
    """The shot's projectile, solid steel, its length chosen for ``mass``."""
    d = {"radius": SHOT["radius"], "length": 0.2, "crh": SHOT["crh"], "meplat_radius": MEPLAT,
         "cavity_radius": 0.0, "cavity_length": 0.0, "base_thickness": 0.0}
    volume = PARTS["projectile"].volume(d, 2)
    d["length"] += (mass / STEEL["density"] - volume) / (math.pi * d["radius"] ** 2)
    return d


def _target(crater_depth=None, tunnel=True, friction=0.0, nose="projectile.nose", gdim=2, point=0.0):
    target = {"nose": nose, "face": {"point": [0.0] * (gdim - 1) + [point], "normal": [0.0] * (gdim - 1) + [1.0]},
              "compressive_strength": SHOT["fc"], "density": SHOT["density"], "tunnel": tunnel,
              "friction": friction}
    if crater_depth is not None:
        target["crater_depth"] = crater_depth
    return target


def _shot_scene(h: float, end_time: float) -> dict:
    d = _projectile_dims(SHOT["mass"])
    body = {"name": "projectile", "material": "steel", "shape": "projectile", "element_size": h, "rigid": True,
            "position": [0.0, 1e-4], "velocity": [0.0, -SHOT["speed"]],
            **{k: d[k] for k in ("radius", "length", "crh", "meplat_radius")}}
    return {"scene": {"name": "penetration_rigid", "kinematics": "axisymmetric", "element": "tri",
                      "end_time": end_time},
            "materials": {"steel": dict(STEEL)}, "bodies": [body], "penetration": _target(),
            "outputs": {"field_interval": end_time, "history_interval": end_time / 200}}


# ---------------------------------------------------------------------------- the cases
def penetration_rigid(size, workdir):
    """The published shot with a rigid projectile: depth, speed against depth, the mesh's nose factor."""
    s = SHOT
    h = 1e-3 * SIZES[size]
    P_ideal = depth(s["mass"], s["radius"], s["fc"], s["density"], s["speed"], s["crh"])
    end = 1.3 * P_ideal / (0.5 * s["speed"])
    samples = []
    solver, wall = solve(_shot_scene(h, end), cache_dir=workdir,
                         probe=lambda sv: samples.append((sv.target.depth, -sv.body_means()[0][0, 1])))
    tg = solver.target
    m, a, N, k = tg.mass, tg.radius, tg.nose_factor, tg.crater_depth
    strength = strength_factor(s["fc"]) * s["fc"]
    P = depth_of(m, a, strength, s["density"], N, s["speed"], k)
    z, v = np.array(samples).T
    moving = (z > 0.0) & (v > 0.05 * s["speed"])
    closed = np.array([speed_at_depth(zi, m, a, strength, s["density"], N, s["speed"], k) for zi in z[moving]])
    v1 = math.sqrt(crater_law(m, a, strength, s["density"], N, s["speed"], k)[1])
    n = element_count(solver)
    return [
        check("penetration_rigid.depth_vs_closed_form [m]", P, tg.max_depth, 0.01, wall, n),
        check("penetration_rigid.speed_vs_depth_max_error [-, abs, of strike speed]", 0.0,
              float(np.max(np.abs(v[moving] - closed))) / s["speed"], 0.01, wall, n, absolute=True),
        check("penetration_rigid.crater_exit_speed [m/s]", v1, float(np.interp(k, z, v)), 0.01, wall, n),
        check("penetration_rigid.mesh_nose_factor_vs_ogive [-]", nose_factor(s["crh"]), N, 0.02, wall, n),
        check("penetration_rigid.depth_vs_published_model [m]", MODEL_DEPTH, tg.max_depth, 0.03, wall, n),
        check("penetration_rigid.depth_vs_measured [m]", MEASURED_DEPTH, tg.max_depth, 0.05, wall, n),
        check("penetration_rigid.energy_balance [-, abs]", 0.0, solver.energy.balance_error, 0.005, wall, n,
              absolute=True),
    ]


# slender (R / L = 0.025): the Pochhammer-Chree ringing behind the front stays within the plateau's 1%
ROD = {"radius": 0.005, "length": 0.2, "speed": 100.0}


def penetration_wave(size, workdir):
    """The stress step a suddenly applied tunnel force sends up an elastic rod, at mid-length."""
    R, L, V = ROD["radius"], ROD["length"], ROD["speed"]
    h = 0.625e-3 * SIZES[size]
    c0 = steel_c0()
    end = 2.6 * L / c0
    raw = {"scene": {"name": "penetration_wave", "kinematics": "axisymmetric", "end_time": end},
           "materials": {"steel": dict(STEEL)},
           "bodies": [{"name": "rod", "material": "steel", "shape": "cylinder", "radius": R, "length": L,
                       "element_size": h, "position": [0.0, -0.005], "velocity": [0.0, -V]}],
           "penetration": _target(crater_depth=0.0, nose="rod.bottom"),
           "outputs": {"field_interval": end, "history_interval": end / 200}}
    rows = []

    def probe(sv):
        m = sv.model
        centre = sv.x[m.dofmap[m.kernel_cells]].mean(axis=1)[:, 1] - sv.u[m.dofmap[m.kernel_cells]].mean(axis=1)[:, 1]
        mid = np.abs(centre - (-0.005 + L / 2)) < 0.51 * h
        rows.append((sv.t, float(sv.sigma[m.kernel_cells[mid], :, 1].mean()), sv.target.axial_force))
    solver, wall = solve(raw, cache_dir=workdir, probe=probe)
    t, szz, F = np.array(rows).T
    A = math.pi * R * R
    arrive, transit = L / (2 * c0), L / c0
    # the step F / A as the nose sent it (the nose's speed, and with it rho V^2, drops by the wave's own
    # particle velocity sigma / (rho c0) the moment the force comes on)
    emitted = -np.interp(t - arrive, t, F) / A
    # the plateau, and the quiet after the reflection, each less a fifth of the transit at both ends
    first = (t > arrive + 0.2 * transit) & (t < arrive + 0.8 * transit)
    second = (t > arrive + 1.2 * transit) & (t < arrive + 1.8 * transit)
    # the arrival of the sharp step with the same impulse: dispersion rounds the front (at L / 2 c0 the
    # stress is about a third of the step, Skalak's Airy front) but moves no impulse
    until = t <= arrive + 0.8 * transit
    equivalent = t[until][-1] - np.trapz(szz[until] / emitted[until], t[until])
    n = element_count(solver)
    return [
        check("penetration_wave.applied_stress [Pa]",
              strength_factor(SHOT["fc"]) * SHOT["fc"] + SHOT["density"] * V * V, F[0] / A, 1e-3, wall, n),
        check("penetration_wave.plateau_at_mid_length [-, of the emitted step]", 1.0,
              float(np.mean(szz[first] / emitted[first])), 0.01, wall, n),
        check("penetration_wave.arrival_at_mid_length [s]", arrive, float(equivalent), 0.01, wall, n),
        check("penetration_wave.after_reflection [-, abs, of the emitted step]", 0.0,
              float(np.mean(szz[second] / emitted[second])), 0.02, wall, n, absolute=True),
        check("penetration_wave.energy_balance [-, abs]", 0.0, solver.energy.balance_error, 0.01, wall, n,
              absolute=True),
    ]


def penetration_spin(size, workdir):
    """A spinning rod in the tunnel: the friction torque mu F a / 2 slows its spin at mu F a / (2 J)."""
    R, L, V, mu, spin = 0.01, 0.1, 50.0, 0.4, 2000.0
    h = 2.5e-3 * SIZES[size]
    end = 6e-5              # the rod stops in about 90 us (132 kN on 0.25 kg at 50 m/s)
    raw = {"scene": {"name": "penetration_spin", "kinematics": "3d", "element": "hex", "end_time": end},
           "materials": {"steel": dict(STEEL)},
           "bodies": [{"name": "rod", "material": "steel", "shape": "cylinder", "radius": R, "length": L,
                       "element_size": h, "position": [0.0, 0.0, -0.005], "velocity": [0.0, 0.0, -V],
                       "spin": spin}],
           "penetration": _target(crater_depth=0.0, nose="rod.bottom", gdim=3, friction=mu),
           "outputs": {"field_interval": end, "history_interval": end / 100}}
    rows = []

    def probe(sv):
        m, x, v = sv.model, sv.x, sv.v + 0.5 * sv.dt * sv.a
        lz = float(np.sum(m.mass * (x[:, 0] * v[:, 1] - x[:, 1] * v[:, 0])))
        rows.append((sv.t, lz, sv.target.axial_force))
    solver, wall = solve(raw, cache_dir=workdir, probe=probe)
    t, lz, F = np.array(rows).T
    m = solver.model
    # the polar moment the run carries: its lumped masses' (the round rod's 0.5 pi rho L R^4, less what
    # the faceted section leaves out, plus what lumping moves outward)
    J = float(np.sum(m.mass * (m.X0[:, 0] ** 2 + m.X0[:, 1] ** 2)))
    a = solver.target.radius
    rate = -np.polyfit(t, lz / J, 1)[0]
    n = element_count(solver)
    return [
        check("penetration_spin.spin_down_rate [rad/s^2]", mu * float(F.mean()) * a / (2 * J), rate, 0.01, wall, n),
        # the faceted section and lumping: 1.8% above the round rod's at the default size, 7.4% at coarse
        check("penetration_spin.polar_moment_vs_round_rod [kg m^2]", 0.5 * math.pi * STEEL["density"] * L * R ** 4,
              J, 0.1, wall, n),
        check("penetration_spin.energy_balance [-, abs]", 0.0, solver.energy.balance_error, 0.01, wall, n,
              absolute=True),
    ]


def _exact_nose_load(velocity: np.ndarray, n_z=800, n_phi=2048) -> tuple[np.ndarray, np.ndarray]:
    """Force and moment about the tip [N, N m] of sigma_n = S f'c + rho v_n^2 (v_n > 0) over the exact
    blunted ogive of the shot (body frame: tip at the origin, axis +z), moving at ``velocity``: the
    midpoint rule on the meridian (z) and the periodic angle, and the meplat's disc."""
    d = _projectile_dims(SHOT["mass"])
    R = d["radius"]
    rho, ln = ogive(d)
    strength = strength_factor(SHOT["fc"]) * SHOT["fc"]
    z = (np.arange(n_z) + 0.5) * ln / n_z
    phi = (np.arange(n_phi) + 0.5) * 2 * math.pi / n_phi
    Z, PHI = np.meshgrid(z, phi, indexing="ij")
    r = np.sqrt(rho * rho - (ln - Z) ** 2) - (rho - R)
    # outward normal of the arc about (R - rho, ln) in the meridian plane; ds = rho dz / sqrt(rho^2 - (ln - z)^2)
    nr, nz = (r + rho - R) / rho, (Z - ln) / rho
    n = np.stack([nr * np.cos(PHI), nr * np.sin(PHI), nz], axis=-1)
    x = np.stack([r * np.cos(PHI), r * np.sin(PHI), Z], axis=-1)
    dA = r * (2 * math.pi / n_phi) * rho / np.sqrt(rho * rho - (ln - Z) ** 2) * (ln / n_z)
    p = normal_stress(strength, SHOT["density"], n @ velocity)
    f = -(p * dA)[..., None] * n
    force, moment = f.sum(axis=(0, 1)), np.cross(x, f).sum(axis=(0, 1))
    # the meplat: a disc of normal -z at the tip
    disc = normal_stress(strength, SHOT["density"], -velocity[2]) * math.pi * MEPLAT ** 2
    force = force + np.array([0.0, 0.0, disc])
    return force, moment


def penetration_yaw(size, workdir):
    """A rigid ogive at 5 deg of yaw wholly in the target: the load's force and moment against the
    normal stress integrated over the exact nose."""
    d = _projectile_dims(SHOT["mass"])
    h = 1.25e-3 * SIZES[size]
    V = SHOT["speed"]
    _, ln = ogive(d)
    tip = -1.5 * ln                       # the whole nose beyond the face at z = 0
    raw = {"scene": {"name": "penetration_yaw", "kinematics": "3d", "element": "tet", "end_time": 1e-9},
           "materials": {"steel": dict(STEEL)},
           "bodies": [{"name": "projectile", "material": "steel", "shape": "projectile", "element_size": h,
                       "rigid": True, "position": [0.0, 0.0, tip], "velocity": [0.0, 0.0, -V],
                       "orientation": {"axis": [1.0, 0.0, 0.0], "angle": YAW},
                       "refine": [{"region": "nose", "size": 0.5 * h, "distance": 0.01}],
                       **{k: d[k] for k in ("radius", "length", "crh", "meplat_radius")}}],
           "penetration": _target(crater_depth=0.0, tunnel=False, gdim=3),
           "outputs": {"field_interval": 1e-9, "history_interval": 1e-9}}
    loads = []

    def probe(sv):
        if sv.step == 0:               # the load on the nose as placed, before any step
            tg = sv.target
            x = tg.exchange.gather(sv.x)
            loads.append((tg.force.copy(), np.cross(x - np.array([0.0, 0.0, tip]), tg.f).sum(axis=0),
                          tg.f.sum(axis=0) - tg.force, tg.torque))
    solver, wall = solve(raw, cache_dir=workdir, probe=probe)
    force, moment = loads[0][:2]
    body = raw["bodies"][0]
    body.pop("orientation")
    body["spin"] = 600.0
    raw["penetration"]["friction"] = 0.4
    solve(raw, cache_dir=workdir, probe=probe)
    _, _, spinning, torque = loads[1]
    turn = axis_angle([1.0, 0.0, 0.0], YAW)
    f_body, m_body = _exact_nose_load(turn.T @ np.array([0.0, 0.0, -V]))
    f_exact, m_exact = turn @ f_body, turn @ m_body
    n = element_count(solver)
    return [
        check("penetration_yaw.axial_force [N]", f_exact[2], force[2], 0.01, wall, n),
        check("penetration_yaw.lateral_force [N]", f_exact[1], force[1], 0.015, wall, n),
        check("penetration_yaw.moment_about_tip [N m]", m_exact[0], moment[0], 0.015, wall, n),
        # the friction torque's forces on uneven facets: their moment T, their resultant nothing (relative
        # to T / a, the size of their forces)
        check("penetration_yaw.torque_forces_resultant [-, abs, of T / a]", 0.0,
              float(np.hypot(*spinning[:2])) / (torque / d["radius"]), 1e-9, wall, n, absolute=True),
        check("penetration_yaw.zero_yaw_axial_force [N]",
              math.pi * d["radius"] ** 2 * (strength_factor(SHOT["fc"]) * SHOT["fc"]
                                            + nose_factor(SHOT["crh"]) * SHOT["density"] * V * V),
              _exact_nose_load(np.array([0.0, 0.0, -V]))[0][2], 0.01, wall, n),
    ]


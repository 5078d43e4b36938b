"""Material-point verification of the laws: one point driven through the very function the element
kernels call (``materials.update.update_stress``: objective rotation, law), against closed forms.

The driver prescribes some strain-rate components and holds the stress of the others at zero
(uniaxial stress: d11 given, sigma22 = sigma33 = 0; plane strain: d11 given, d33 = 0,
sigma22 = 0), solving for the free rates each step with the elastic stiffness as Jacobian.
"""
from __future__ import annotations

import math
import time

import numpy as np

from ..materials.layout import S_BACK, S_DEFORMATION, S_EPS, S_LOG_VOLUME, S_RATE, STATE_SIZE
from ..materials.update import update_stress
from ..model.materials import parameter_table
from ..scene import resolve
from .checks import check

COPPER = {"density": 8930.0, "youngs_modulus": 117e9, "poisson_ratio": 0.35, "yield_stress": 400e6,
          "tangent_modulus": 100e6}
MILD_STEEL = {"library": "mild_steel"}


def material(fields: dict):
    """A resolved material from scene fields (through the scene checker, like a user's)."""
    raw = {"scene": {"kinematics": "3d", "end_time": 1.0}, "materials": {"m": dict(fields)},
           "bodies": [{"name": "b", "material": "m", "shape": "box", "size": [1, 1, 1], "element_size": 1}]}
    return resolve(raw).materials["m"]


class MaterialPoint:
    """One point of one material: stress (6), plastic state, and a step with mixed control."""

    def __init__(self, mat):
        self.params, self.curves = parameter_table([mat], None, (0.0, 0.0))
        self.lam, self.mu = mat.lam, mat.mu
        self.sigma = np.zeros(6)
        self.state = np.zeros((1, 1, STATE_SIZE))
        self.plastic_work = 0.0          # sum of the law's plastic work densities [J/m^3]

    def _update(self, d, w, dt, state):
        """The element kernels' material update at one point (no slots: radius 0)."""
        s, _, work = update_stress(self.params, self.curves, 0, state, 0, 0, tuple(map(float, self.sigma)),
                                   tuple(map(float, d)), tuple(map(float, w)), dt, 0.0, False)
        return np.array(s), work

    def step(self, d_given: dict, free: tuple, dt: float, w=(0.0, 0.0, 0.0), iterations=50):
        """Advance by dt with the strain rates ``d_given`` {index: rate} (others zero) and zero stress
        in the components ``free``, whose rates are found by Newton's method (finite-difference
        Jacobian: the rate factor of the yield-scaling form depends on the free rates too).
        Returns the strain-rate vector used."""
        d = np.zeros(6)
        for k, v in d_given.items():
            d[k] = v
        free = list(free)

        def residual(rates):
            trial = d.copy()
            trial[free] = rates
            state = self.state.copy()
            s, work = self._update(trial, w, dt, state)
            return s, state, work

        rates = -self.lam / (2 * (self.lam + self.mu)) * d[0] * np.ones(len(free))   # elastic guess
        for _ in range(iterations):
            s, state, work = residual(rates)
            # round-off floor: a nearly incompressible law's pressure K (J - 1) carries K times 1e-16
            if not free or np.abs(s[free]).max() <= 1e-9 * max(np.abs(s).max(), 1.0) + 1e-14 * (self.lam + 2 * self.mu):
                break
            h = 1e-7 * max(np.abs(d).max(), np.abs(rates).max(), 1.0)
            J = np.empty((len(free), len(free)))
            for j in range(len(free)):
                shifted = rates.copy()
                shifted[j] += h
                J[:, j] = (residual(shifted)[0][free] - s[free]) / h
            rates = rates - np.linalg.solve(J, s[free])
        else:
            raise RuntimeError(f"material point: zero stress in {free} not reached, residual {s[free]}")
        d[free] = rates
        self.sigma, self.state = s, state
        self.plastic_work += work
        return d

    @property
    def eps_p(self) -> float:
        return float(self.state[0, 0, S_EPS])

    @property
    def plastic_rate(self) -> float:
        return float(self.state[0, 0, S_RATE])

    @property
    def von_mises(self) -> float:
        s = self.sigma
        p = s[:3].mean()
        return math.sqrt(1.5 * (((s[:3] - p) ** 2).sum() + 2 * (s[3:] ** 2).sum()))


def effective_rate(d) -> float:
    """sqrt(2/3 d':d'), the effective (deviatoric) strain rate of LS-DYNA's VP = 0."""
    e = np.asarray(d[:3]) - np.mean(d[:3])
    return math.sqrt(2 / 3 * ((e ** 2).sum() + 2 * (np.asarray(d[3:]) ** 2).sum()))


def uniaxial(mat, rate: float, strain: float, steps: int = 2000):
    """Uniaxial stress at a constant total strain rate to ``strain``: arrays of strain, stress,
    plastic strain, plastic strain rate and effective total strain rate."""
    point = MaterialPoint(mat)
    dt = strain / rate / steps
    out = []
    for n in range(1, steps + 1):
        d = point.step({0: rate}, (1, 2), dt)
        out.append((n * dt * rate, point.sigma[0], point.eps_p, point.plastic_rate, effective_rate(d)))
    return np.array(out).T


def yield_and_hardening(size, workdir):
    """Uniaxial stress, bilinear copper: yield at sigma_0; slope E_t after yield (of total strain)."""
    t0 = time.perf_counter()
    mat = material(COPPER)
    E, sy, Et = COPPER["youngs_modulus"], COPPER["yield_stress"], COPPER["tangent_modulus"]
    strain, stress, eps_p, _, _ = uniaxial(mat, 1.0, 0.05)
    onset = stress[np.argmax(eps_p > 0) - 1]             # the last elastic stress
    first_plastic = np.argmax(eps_p > 0)
    onset_strain = strain[first_plastic - 1]
    late = strain > 0.02
    slope = np.polyfit(strain[late], stress[late], 1)[0]
    wall = time.perf_counter() - t0
    return [
        # one step of 2.5e-5 strain is 2.9 MPa at E: the last elastic point lies within that of sigma_0
        check("point.uniaxial.yield_onset [Pa]", sy, onset, 3.0e6 / sy, wall, 1),
        check("point.uniaxial.yield_strain [-]", sy / E, onset_strain, 0.01, wall, 1),
        check("point.uniaxial.tangent_modulus [Pa]", Et, slope, 0.005, wall, 1),
        check("point.uniaxial.final_stress [Pa]", sy + Et * (0.05 - sy / E), stress[-1], 0.002, wall, 1),
    ]


def hardening_rules(size, workdir):
    """Tabulated hardening (4340's Johnson-Cook curve of the library): the flow stress follows the
    curve at the point's plastic strain; pure kinematic hardening (isotropic_fraction = 0): after
    tension to sigma_f the point yields again in compression at sigma_f - 2 sigma_0 (Bauschinger)."""
    t0 = time.perf_counter()
    mat = material({"library": "steel_4340", "cowper_symonds_D": 1e40})      # rate effects off
    strain, stress, eps_p, _, _ = uniaxial(mat, 1.0, 0.3)
    table = np.array(mat.plasticity.curve)
    expected = np.interp(eps_p[-1], table[:, 0], table[:, 1]) * (1 + (1.0 / 1e40) ** 0.2)
    out = [check("point.tabulated.flow_stress [Pa]", expected, stress[-1], 1e-6, time.perf_counter() - t0, 1)]
    t0 = time.perf_counter()
    sy = COPPER["yield_stress"]
    point = MaterialPoint(material({**COPPER, "isotropic_fraction": 0.0}))
    dt, rate = 1e-5, 1.0
    for _ in range(2000):                                    # tension to 2% strain
        point.step({0: rate}, (1, 2), dt)
    peak, eps_peak = point.sigma[0], point.eps_p
    reverse, previous = None, peak
    for _ in range(2000):                                    # then compression
        point.step({0: -rate}, (1, 2), dt)
        if reverse is None and point.eps_p > eps_peak:
            reverse = previous
        previous = point.sigma[0]
    # one step is dt * rate * E = 1.2 MPa of stress: the last elastic point lies within that
    out.append(check("point.kinematic.reverse_yield [Pa]", peak - 2 * sy, reverse, 1.5e6 / abs(peak - 2 * sy),
                     time.perf_counter() - t0, 1))
    return out


def plane_strain_limit(size, workdir):
    """Plane strain (d33 = 0), sigma22 = 0, perfectly plastic: sigma11 tends to 2/sqrt(3) sigma_0."""
    t0 = time.perf_counter()
    sy = 300e6
    mat = material({"density": 7850, "youngs_modulus": 210e9, "poisson_ratio": 0.3, "yield_stress": sy})
    point = MaterialPoint(mat)
    dt = 1e-6
    for _ in range(3000):                     # to 0.3 total strain at 100 /s
        point.step({0: 100.0}, (1,), dt)
    wall = time.perf_counter() - t0
    return [check("point.plane_strain.limit [Pa]", 2 / math.sqrt(3) * sy, point.sigma[0], 0.002, wall, 1),
            check("point.plane_strain.sigma33_ratio [-]", 0.5, point.sigma[2] / point.sigma[0], 0.005, wall, 1)]


def cowper_symonds(size, workdir):
    """Mild steel (D = 40.4 /s, q = 5), uniaxial at constant rates 1, 100, 1e4 /s to 10% strain:
    the flow stress against sigma_iso(eps_p) (1 + (rate_p / D)^(1/q)) at the point's own plastic
    strain and plastic strain rate, within 0.5% (viscoplastic, VP = 1); the same with the total
    strain rate (yield scaling, VP = 0); and rate independence as D grows without bound."""
    out = []
    base = material(MILD_STEEL)
    p = base.plasticity
    D, q = p.rate_D, p.rate_q
    sy0, H = p.curve[0][1], p.curve[1][1] - p.curve[0][1]
    for form in ("plastic-strain-rate", "total-strain-rate"):
        mat = material({**MILD_STEEL, "rate_form": form})
        for rate in (1.0, 100.0, 1e4):
            t0 = time.perf_counter()
            strain, stress, eps_p, rate_p, rate_total = uniaxial(mat, rate, 0.1)
            r = rate_p[-1] if form == "plastic-strain-rate" else rate_total[-1]
            expected = (sy0 + H * eps_p[-1]) * (1 + (r / D) ** (1 / q))
            tag = "vp1" if form == "plastic-strain-rate" else "vp0"
            out.append(check(f"point.cowper_symonds.{tag}.rate_{rate:g} [Pa]", expected, stress[-1], 0.005,
                             time.perf_counter() - t0, 1))
    t0 = time.perf_counter()
    independent = uniaxial(_rate_free("mild_steel"), 1e4, 0.1)[1][-1]
    # the rate factor fades as D^(-1/q): at 1e4 /s and D = 1e40 /s it is 1 + 6e-8
    huge_D = uniaxial(material({**MILD_STEEL, "cowper_symonds_D": 1e40}), 1e4, 0.1)[1][-1]
    out.append(check("point.cowper_symonds.D_to_infinity [Pa]", independent, huge_D, 1e-6,
                     time.perf_counter() - t0, 1))
    return out


def _rate_free(name: str):
    """A library material without its rate constants."""
    from ..scene.library import LIBRARY
    drop = ("source", "cowper_symonds_D", "cowper_symonds_q")
    return material({k: v for k, v in LIBRARY[name].items() if k not in drop})


def _tensor_norm(a):
    """sqrt(a : a) of a symmetric tensor stored as (11, 22, 33, 23, 13, 12)."""
    return math.sqrt((a[:3] ** 2).sum() + 2 * (a[3:] ** 2).sum())


def objectivity(size, workdir):
    """A point loaded into the plastic range with mixed hardening, then spun through 90 degrees
    with no strain: the stress turns with the material (sigma = R sigma_0 R^T), the von Mises
    stress, plastic strain and back-stress size stay as they were."""
    t0 = time.perf_counter()
    mat = material({**COPPER, "isotropic_fraction": 0.5})
    point = MaterialPoint(mat)
    dt = 1e-6
    for _ in range(500):
        point.step({0: 100.0, 5: 40.0}, (1, 2), dt)         # tension with shear, into the plastic range
    s0, vm0, ep0 = point.sigma.copy(), point.von_mises, point.eps_p
    alpha0 = _tensor_norm(point.state[0, 0, S_BACK:S_BACK + 6])
    spin, steps = 0.5 * math.pi / (1000 * dt), 1000      # about z, a quarter turn
    for _ in range(steps):
        point.step({}, (), dt, w=(0.0, 0.0, spin))
    # the Hughes-Winget (Cayley) rotation turns by 2 atan(spin dt / 2) a step, not spin dt
    angle = steps * 2 * math.atan(0.5 * spin * dt)
    c, s = math.cos(angle), math.sin(angle)
    R = np.array([[c, s, 0], [-s, c, 0], [0, 0, 1]])     # W12 > 0 turns the 1 axis towards -2 (L = W)
    S0 = np.array([[s0[0], s0[5], s0[4]], [s0[5], s0[1], s0[3]], [s0[4], s0[3], s0[2]]])
    S1 = R @ S0 @ R.T
    expected = np.array([S1[0, 0], S1[1, 1], S1[2, 2], S1[1, 2], S1[0, 2], S1[0, 1]])
    wall = time.perf_counter() - t0
    scale = np.abs(s0).max()
    return [
        check("point.rotation.stress [Pa, abs]", 0.0, np.abs(point.sigma - expected).max(), 1e-8 * scale, wall, 1,
              absolute=True),
        check("point.rotation.von_mises [Pa]", vm0, point.von_mises, 1e-10, wall, 1),
        check("point.rotation.plastic_strain [-]", ep0, point.eps_p, 1e-12, wall, 1),
        check("point.rotation.back_stress [Pa]", alpha0, _tensor_norm(point.state[0, 0, S_BACK:S_BACK + 6]), 1e-10, wall, 1),
    ]


FOAM = {"density": 100.0, "youngs_modulus": 50e6, "crush_curve": [[0.0, 1e6], [0.5, 1.2e6], [0.8, 10e6]],
        "tension_cutoff": 0.2e6}     # poisson_ratio 0 by default for a foam


def crushable_foam(size, workdir):
    """The crushable foam (``materials/foam.py``), uniaxial stress (nu = 0, lateral stresses free):

    * compression at 10 /s to volumetric strain 0.75: the stress follows the crush curve at the
      point's own volumetric strain 1 - exp(-strain) (largest error over the curve, after yield);
    * unloading from there: the first step's slope is E, and the point stops at zero stress after
      the elastic strain sigma / E;
    * work: the work done on the point equals the elastic energy left plus the plastic work;
    * tension: the stress stops at the tension cutoff;
    * rate: with D = 100 /s, q = 2 at 400 /s the crush stress is Y (1 + (400/100)^(1/2)) = 3 Y."""
    out = []
    t0 = time.perf_counter()
    mat = material(FOAM)
    E = mat.E
    curve = np.array(mat.crush.curve)
    point = MaterialPoint(mat)
    dt, rate = 1e-5, 10.0
    work, errors = 0.0, []
    strain = 0.0
    while 1.0 - math.exp(-strain) < 0.75:
        before = point.sigma[0]
        point.step({0: -rate}, (1, 2), dt)
        strain += rate * dt
        work += 0.5 * (before + point.sigma[0]) * (-rate * dt)
        eps_v = 1.0 - math.exp(point.state[0, 0, S_LOG_VOLUME])
        if strain > 2 * curve[0, 1] / E:                     # past the elastic rise
            errors.append(abs(-point.sigma[0] - np.interp(eps_v, curve[:, 0], curve[:, 1])) / curve[0, 1])
    plastic = point.plastic_work
    elastic = point.sigma[0] ** 2 / (2 * E)
    peak = point.sigma[0]
    before = point.sigma[0]
    point.step({0: rate}, (1, 2), dt)
    slope = (point.sigma[0] - before) / (rate * dt)
    unload = 0.0
    while point.sigma[0] < 0.0:
        point.step({0: rate}, (1, 2), dt)
        unload += rate * dt
    wall = time.perf_counter() - t0
    out += [
        check("foam.point.crush_curve [-, abs]", 0.0, max(errors), 1e-9, wall, 1, absolute=True),
        check("foam.point.unloading_modulus [Pa]", E, slope, 1e-9, wall, 1),
        # the zero crossing falls within one step of strain of -sigma / E
        check("foam.point.elastic_recovery [-]", -peak / E, unload, rate * dt / (-peak / E), wall, 1),
        # the law's plastic work takes the end-of-step stress (first order in the step: 7e-5 here),
        # the work done on the point the trapezoidal rule
        check("foam.point.work_balance [J/m^3]", work, elastic + plastic, 2e-4, wall, 1),
    ]
    t0 = time.perf_counter()
    point = MaterialPoint(mat)
    for _ in range(1000):
        point.step({0: rate}, (1, 2), dt)                    # 1% tension: 0.5 MPa elastic, cut at 0.2 MPa
    out.append(check("foam.point.tension_cutoff [Pa]", FOAM["tension_cutoff"], point.sigma[0], 1e-9,
                     time.perf_counter() - t0, 1))
    t0 = time.perf_counter()
    point = MaterialPoint(material({**FOAM, "cowper_symonds_D": "100 /s", "cowper_symonds_q": 2.0}))
    fast = 400.0
    for _ in range(500):
        point.step({0: -fast}, (1, 2), 1e-6)                 # to 0.05 strain at 400 /s
    eps_v = 1.0 - math.exp(point.state[0, 0, S_LOG_VOLUME])
    expected = np.interp(eps_v, curve[:, 0], curve[:, 1]) * (1 + (fast / 100.0) ** 0.5)
    out.append(check("foam.point.rate_factor [Pa]", expected, -point.sigma[0], 1e-9, time.perf_counter() - t0, 1))
    return out


RUBBER = {"density": 1100.0, "hyperelastic": "mooney-rivlin", "c10": 1.0e6, "c01": 0.3e6, "poisson_ratio": 0.4999}


def rubber(size, workdir):
    """The Mooney-Rivlin rubber (``materials/rubber.py``) at a point:

    * uniaxial stress (lateral stresses free) at 1 /s to a stretch of 2 and to 0.5: Cauchy stress
      2 (lambda^2 - 1/lambda)(C10 + C01 / lambda), the incompressible closed form, within 1e-3 (the
      material's K / mu = 5,000 puts the compressible answer 4e-4 from it);
    * the point's F11 against exp(strain): the midpoint update is second order, 6e-10 at 1e-4 s steps;
    * simple shear to gamma = 1 with its spin (Neo-Hookean, C01 = 0): shear stress mu gamma and normal
      stress difference mu gamma^2, exact for any bulk modulus because simple shear keeps the volume."""
    out = []
    mat = material(RUBBER)
    c10, c01 = RUBBER["c10"], RUBBER["c01"]
    for stretch in (2.0, 0.5):
        t0 = time.perf_counter()
        point = MaterialPoint(mat)
        rate, steps = math.copysign(1.0, stretch - 1.0), 6931
        dt = abs(math.log(stretch)) / steps
        for _ in range(steps):
            point.step({0: rate}, (1, 2), dt)
        lam = point.state[0, 0, S_DEFORMATION] + 1.0
        exact = 2 * (lam ** 2 - 1 / lam) * (c10 + c01 / lam)
        wall = time.perf_counter() - t0
        out += [check(f"rubber.point.uniaxial_{stretch:g} [Pa]", exact, point.sigma[0], 1e-3, wall, 1),
                check(f"rubber.point.stretch_{stretch:g} [-]", stretch, lam, 1e-8, wall, 1)]
    t0 = time.perf_counter()
    neo = material({**RUBBER, "c01": 0.0})
    point = MaterialPoint(neo)
    rate, dt = 1.0, 1e-3
    for _ in range(1000):                                    # L = [[0, 1], [0, 0]]: d12 = w12 = 1/2
        point.step({5: 0.5 * rate}, (), dt, w=(0.0, 0.0, 0.5 * rate))
    gamma = point.state[0, 0, S_DEFORMATION + 1]
    wall = time.perf_counter() - t0
    out += [check("rubber.point.simple_shear [Pa]", neo.mu * gamma, point.sigma[5], 1e-12, wall, 1),
            check("rubber.point.normal_stress_difference [Pa]", neo.mu * gamma ** 2, point.sigma[0] - point.sigma[1],
                  1e-12, wall, 1),
            check("rubber.point.shear_strain [-]", 1.0, gamma, 1e-12, wall, 1)]
    return out


def material_point(size, workdir):
    """All material-point checks (the size does not apply: one point)."""
    return (yield_and_hardening(size, workdir) + hardening_rules(size, workdir) + plane_strain_limit(size, workdir)
            + cowper_symonds(size, workdir) + objectivity(size, workdir) + crushable_foam(size, workdir)
            + rubber(size, workdir))

"""The ``1d`` fidelity: a chain of elastic (or elastic-plastic) bars, wave propagation and contact.

Each body is a uniform bar (length, cross-section, material) cut into two-node elements with
lumped (half-element) nodal masses; the chain runs along +x.  Central differences in time,
as in the finite-element solver: the stable step is the smallest element transit time h / c0,
and that of the interface springs (2 / omega, omega^2 = k (1/m_a + 1/m_b)), times a safety
factor.  Per element: strain (x_{i+1} - x_i) / h - 1, stress by a bilinear J2 return in 1D
(yield, linear isotropic hardening) and a structural damping stress: stiffness-proportional,
beta E d(eps)/dt (damping ratio zeta at a reference frequency: beta = 2 zeta / omega), or a band
damping that holds zeta over a band of frequencies (``materials/band_damping.py``: Maxwell terms
driven by each element's stress increments, as the finite-element solver drives them by its
nodal forces, ``solver/band.py``, and let go in a yielding element, where they would carry the stress past
the yield surface; a band-damped bar's Young's modulus is its dynamic modulus at the
band's reference frequency, the elastic law running with E / Re(K(w_ref) / K)).  No bulk
viscosity: in 1D it smears the unloading front and lengthens the measured contact (9% at 100
elements per bar), where refinement costs almost nothing.

Neighbouring bars meet at their facing end nodes in one of two ways:

* contact (no stiffness given): kinematic, by a forward-increment Lagrange multiplier
  (Carpenter et al. 1991): when the velocities of a step would make the end nodes overlap, an
  impulse lambda = -g / (dt (1/m_a + 1/m_b)) >= 0 brings them exactly together; it never
  pulls.  While closed the two bars carry the wave across as one bar would, so the 1D results
  of St Venant's rod impact come out without a penalty's compliance or chatter (a penalty
  spring between two half-element end masses rebounds and re-strikes many times per contact).
* an interface spring (a pad): compression only, stiffness k and dashpot c = 2 zeta sqrt(k M*)
  (M* the two bars' reduced mass: zeta is the damping ratio of the bars bouncing on the pad),
  acting while the faces overlap.

Any two bars may also be joined by a tether: a linear spring (tension and compression) between
their middle nodes, at rest at their initial distance, such as the soft springs the white paper
put between the first and the last body of its finite-element chain.

Every ``record_every`` steps the bars' mean velocities, the interface forces and the energies
are kept, in the column names of a run's history (``<bar>.v_z``, ``contact.<name>.normal_z``,
``energy.*``), so the metrics of ``shockfem/metrics`` (stage table, pulses) read them as they
read a finite-element run.
"""
from __future__ import annotations

import dataclasses
import math
import time
from dataclasses import dataclass, field

import numpy as np
from numba import njit

from ..materials.band_damping import decay_and_gain, fit_band, maxwell_update
from ..materials.viscosity import damped_step
from .interfaces import pad_dashpot, reduced_mass

# Elements in the shortest bar when a bar does not say: the dispersion of linear elements
# (ringing behind a steep front) shifts the St Venant restitution by about 0.8% at 400
# (2% at 100); the element size is then the same in every bar (no finer than structural
# damping makes useful, see run_bars).
ELEMENTS_IN_SHORTEST = 400
# Elements per wavelength at a band damping's top frequency: coarser bars carry the step's harmonics above
# it with the dispersion of linear elements, which the band leaves less damped. Two equal 100 mm steel bars
# at 1 m/s, 2% over [f1, 20 f1]: restitution 0.8994 at 400 elements per bar, 0.9018 at 80 (8 per
# wavelength at 20 f1, 0.3% apart), 0.9042 at 50; undamped 0.9975 at 400, 0.9936 at 80.
BAND_ELEMENTS_PER_WAVE = 8
# Time constant of the low pass on the interface force, in element transit times h / c0 (the
# ringing behind a front has a period of a few transits; the plateau lasts hundreds).
SMOOTHING_TRANSITS = 4.0


@dataclass(frozen=True)
class Bar:
    name: str
    length: float                 # [m]
    area: float                   # [m^2]
    rho: float                    # [kg/m^3]
    E: float                      # [Pa]
    velocity: float = 0.0         # initial, along +x [m/s]
    elements: int = 0             # 0: the size of ELEMENTS_IN_SHORTEST elements in the shortest bar
    yield_stress: float = math.inf
    hardening: float = 0.0        # plastic modulus H = d(sigma_y)/d(eps_p) [Pa]

    @property
    def mass(self) -> float:
        return self.rho * self.area * self.length

    @property
    def c0(self) -> float:
        return math.sqrt(self.E / self.rho)


@dataclass(frozen=True)
class Interface:
    name: str
    gap: float = 0.0                      # [m]
    stiffness: float | None = None        # [N/m]; None: penalty contact
    damping_ratio: float = 0.0            # fraction of critical of the pad on the two bars' masses


@dataclass(frozen=True)
class Tether:
    name: str
    a: int                                # bar indices
    b: int
    stiffness: float                      # [N/m]


@dataclass
class BarsResult:
    history: dict                         # columns like a run's history.csv
    masses: dict                          # bar name -> mass [kg]
    steps: int
    dt: float
    wall_time_s: float
    element_cycles_per_s: float
    energy_balance_error: float
    notes: list = field(default_factory=list)
    peak_stress: dict = field(default_factory=dict)   # bar name -> largest |axial stress| [Pa], ringing included
    interface_stress: dict = field(default_factory=dict)   # interface -> peak low-passed force / smaller area [Pa]


@njit(cache=True)
def _march(x, v, m, elem, h0, area, E, sy, H, beta, iface, k_if, c_if, kinematic, anvil, dt, steps, every,
           out_v, out_f, out_e, owner, n_bars, max_stress, smoothing, peak_force, tether, k_t, rest_t,
           band_decay, band_gain, band_weight):
    """Central-difference steps; writes samples into out_v (bar mean velocities), out_f
    (interface forces) and out_e (kinetic, strain, plastic, structural damping, time, energy taken by
    the interfaces) every ``every`` steps.  ``band_*`` (elements, terms): each element's band-damping
    terms over the step dt (weight 0: none)."""
    ne = elem.shape[0]
    ni = iface.shape[0]
    nn = x.shape[0]
    eps_p = np.zeros(ne)
    alpha = np.zeros(ne)
    sigma = np.zeros(ne)
    f = np.zeros(nn)
    fcs = np.zeros(ni)
    fc_smooth = np.zeros(ni)
    plastic = 0.0
    damped = 0.0
    terms = band_weight.shape[1]
    band_r = np.zeros((ne, terms))        # the Maxwell terms' stresses [Pa] and their springs' strains
    band_q = np.zeros((ne, terms))
    sigma_prev = np.zeros(ne)
    eps_prev = np.zeros(ne)
    band_stored = 0.0
    contact_work = 0.0
    fa_prev = 0.0
    bar_mass = np.zeros(n_bars)
    for i in range(nn):
        bar_mass[owner[i]] += m[i]
    rec = 0
    for step in range(steps + 1):
        # forces at x_n (velocities are v_{n-1/2}; damping uses them)
        for i in range(nn):
            f[i] = 0.0
        strain_energy = 0.0
        stored_now = 0.0
        for e in range(ne):
            a, b = elem[e, 0], elem[e, 1]
            eps = (x[b] - x[a]) / h0[e] - 1.0
            trial = E[e] * (eps - eps_p[e])
            yield_now = sy[e] + H[e] * alpha[e]
            over = abs(trial) - yield_now
            if over > 0.0:
                dg = over / (E[e] + H[e])
                sgn = 1.0 if trial > 0.0 else -1.0
                eps_p[e] += sgn * dg
                alpha[e] += dg
                trial -= sgn * E[e] * dg
                plastic += (abs(trial) + 0.5 * H[e] * dg) * dg * area[e] * h0[e]
            sigma[e] = trial
            if abs(trial) > max_stress[e]:
                max_stress[e] = abs(trial)
            strain_energy += 0.5 * trial * trial / E[e] * area[e] * h0[e]
            rate = (v[b] - v[a]) / h0[e]
            s_damp = beta[e] * E[e] * rate
            damped += s_damp * rate * area[e] * h0[e] * dt
            # band damping: its terms follow the element's stress increment over the last step
            s_band = 0.0
            if step > 0:
                d_sigma, d_eps = trial - sigma_prev[e], eps - eps_prev[e]
                before, kept = 0.0, 0.0
                for k in range(terms):
                    if band_weight[e, k] == 0.0:
                        continue
                    before += band_r[e, k]
                    band_r[e, k], band_q[e, k] = maxwell_update(band_r[e, k], band_q[e, k], d_sigma, d_eps,
                                                                band_decay[e, k], band_gain[e, k], band_weight[e, k])
                    s_band += band_r[e, k]
                    kept += band_q[e, k] * band_r[e, k]
                if over > 0.0:
                    # yielding: the terms act on the elastic response only and let go (solver/band.py's
                    # BandGroup); what their springs held is dissipated (the stored-energy drop below)
                    for k in range(terms):
                        band_r[e, k] = 0.0
                        band_q[e, k] = 0.0
                    s_band, kept = 0.0, 0.0
                damped += 0.5 * (before + s_band) * d_eps * area[e] * h0[e]
                stored_now += 0.5 * kept * area[e] * h0[e]
            sigma_prev[e], eps_prev[e] = trial, eps
            force = (trial + s_damp + s_band) * area[e]
            f[a] += force
            f[b] -= force
        # what the band terms' springs hold is stored energy, not dissipated
        damped -= stored_now - band_stored
        band_stored = stored_now
        strain_energy += stored_now
        for j in range(tether.shape[0]):
            stretch = x[tether[j, 1]] - x[tether[j, 0]] - rest_t[j]
            strain_energy += 0.5 * k_t[j] * stretch * stretch
            f[tether[j, 0]] += k_t[j] * stretch
            f[tether[j, 1]] -= k_t[j] * stretch
        for j in range(ni):
            r, l = iface[j, 0], iface[j, 1]
            overlap = x[r] - x[l]
            fc = 0.0
            if kinematic[j]:
                # the gap after this step with the forces so far; close it exactly if it would overlap
                gap = x[l] + dt * (v[l] + dt * f[l] / m[l]) - x[r] - dt * (v[r] + dt * f[r] / m[r])
                if gap < 0.0:
                    fc = -gap / (dt * dt * (1.0 / m[r] + 1.0 / m[l]))
            elif overlap > 0.0:
                closing = v[r] - v[l]
                fc = max(k_if[j] * overlap + c_if[j] * closing, 0.0)
            # work of the interface force on the bars over the last step (trapezoidal): pads
            # store and dissipate it; a kinematic contact takes what the end nodes' first touch loses
            if step > 0:
                contact_work += 0.5 * (fcs[j] + fc) * dt * (v[l] - v[r])
            fcs[j] = fc
            # the interface force low-passed over a few element transits: the peak of the
            # plateau, not of the ringing that linear elements add behind a steep front
            fc_smooth[j] += smoothing * (fc - fc_smooth[j])
            if fc_smooth[j] > peak_force[j]:
                peak_force[j] = fc_smooth[j]
            f[r] -= fc
            f[l] += fc
            if step % every == 0:
                out_f[rec, j] = fc
        if anvil:
            # a rigid anvil at x = 0 before the first bar: the same kinematic contact
            ahead = x[0] + dt * (v[0] + dt * f[0] / m[0])
            fa = -ahead * m[0] / (dt * dt) if ahead < 0.0 else 0.0
            if step > 0:
                contact_work += 0.5 * (fa_prev + fa) * dt * v[0]
            fa_prev = fa
            f[0] += fa
        if step % every == 0:
            # velocities at t_n: half a step of the forces at t_n on v_{n-1/2}
            kinetic = 0.0
            for b in range(n_bars):
                out_v[rec, b] = 0.0
            for i in range(nn):
                v_n = v[i] + 0.5 * dt * f[i] / m[i]
                kinetic += 0.5 * m[i] * v_n * v_n
                out_v[rec, owner[i]] += m[i] * v_n
            for b in range(n_bars):
                out_v[rec, b] /= bar_mass[b]
            out_e[rec, 0] = kinetic
            out_e[rec, 1] = strain_energy
            out_e[rec, 2] = plastic
            out_e[rec, 3] = damped
            out_e[rec, 4] = step * dt
            out_e[rec, 5] = -contact_work
            rec += 1
        if step == steps:
            break
        for i in range(nn):
            v[i] += dt * f[i] / m[i]
            x[i] += dt * v[i]
    return rec


def _band_tables(band_terms: list, counts: list[int], dt: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Per element (rows) and term (columns): the band terms' decay, gain and weight over a step ``dt``
    (zero weight where a bar has no band or fewer terms)."""
    width = max([len(t.tau) for t in band_terms if t is not None], default=1)
    decay, gain, weight = (np.zeros((sum(counts), width)) for _ in range(3))
    first = np.cumsum([0] + counts)
    for k, t in enumerate(band_terms):
        if t is None:
            continue
        rows, cols = slice(first[k], first[k + 1]), slice(0, len(t.tau))
        decay[rows, cols], gain[rows, cols] = decay_and_gain(np.array(t.tau), dt)
        weight[rows, cols] = t.weight
    return decay, gain, weight


def _relaxed(bar: Bar, terms, band: tuple | None, reference: float | None) -> Bar:
    """The bar its elastic law runs with: under band damping ``terms`` its E divided by Re(K(w_ref) / K)
    (``materials/band_damping.py``; ``reference`` None: the band's geometric centre)."""
    if terms is None:
        return bar
    f_ref = math.sqrt(band[0] * band[1]) if reference is None else reference
    return dataclasses.replace(bar, E=bar.E * terms.relaxed_scale(f_ref))


def run_bars(bars: list[Bar], interfaces: list[Interface], end_time: float, safety_factor: float = 0.9,
             damping_ratio: float | list[float] = 0.0, damping_frequency: float | list[float] | None = None,
             samples: int = 2000, anvil_gap: float | None = None, tethers: tuple = (),
             damping_band: tuple | list | None = None,
             damping_reference: float | list | None = None) -> BarsResult:
    """Run a chain of bars (``interfaces[k]`` joins bars k and k + 1) to ``end_time``.

    ``tethers``: ``Tether`` springs between the middle nodes of two bars.
    ``anvil_gap``: a rigid anvil at that distance before the first bar (None: no anvil).
    ``damping_ratio`` is the structural damping of the bars at ``damping_frequency`` (default: the
    first free-free frequency c0 / 2L of the first bar); either may be one value per bar.
    ``damping_band``: (low, high) [Hz], or one per bar (None for a bar: stiffness-proportional): the
    bars' ``damping_ratio`` held over that band instead (``materials/band_damping.py``), a bar's ``E``
    being its dynamic modulus at ``damping_reference`` [Hz] (one or one per bar; None: the band's
    geometric centre; 0: ``E`` is static)."""
    if len(interfaces) != len(bars) - 1:
        raise ValueError(f"{len(bars)} bars need {len(bars) - 1} interfaces, got {len(interfaces)}")
    xs, ms, owner, elems, h0s, areas, Es, sys_, Hs, betas = [], [], [], [], [], [], [], [], [], []
    ratios = damping_ratio if isinstance(damping_ratio, (list, tuple)) else [damping_ratio] * len(bars)
    freqs = (damping_frequency if isinstance(damping_frequency, (list, tuple))
             else [damping_frequency or bars[0].c0 / (2 * bars[0].length)] * len(bars))
    bands = (damping_band if isinstance(damping_band, list) else [damping_band] * len(bars))
    band_terms = [fit_band(r, *band) if band and r > 0 else None for r, band in zip(ratios, bands)]
    references = (damping_reference if isinstance(damping_reference, (list, tuple))
                  else [damping_reference] * len(bars))
    bars = [_relaxed(b, t, band, ref) for b, t, band, ref in zip(bars, band_terms, bands, references)]
    beta_of = [2 * r / (2 * math.pi * f) if r > 0 and f > 0 and t is None else 0.0
               for r, f, t in zip(ratios, freqs, band_terms)]
    left, right = [], []
    offset = anvil_gap or 0.0
    node = 0
    # stiffness damping removes what is shorter than about beta c0 (it is overdamped there), and
    # elements finer than that only shorten the step (xi = beta / dtc grows as h falls); a band damping
    # needs its top frequency resolved (BAND_ELEMENTS_PER_WAVE)
    h_shortest = min(b.length for b in bars) / ELEMENTS_IN_SHORTEST
    resolved = [beta * b.c0 if t is None else b.c0 / (BAND_ELEMENTS_PER_WAVE * bands[k][1])
                for k, (b, beta, t) in enumerate(zip(bars, beta_of, band_terms))]
    counts = [b.elements or max(1, int(round(b.length / max(h_shortest, h)))) for b, h in zip(bars, resolved)]
    for b_index, bar in enumerate(bars):
        n = counts[b_index]
        h = bar.length / n
        xs.append(offset + h * np.arange(n + 1))
        m_node = np.full(n + 1, bar.rho * bar.area * h)
        m_node[[0, -1]] *= 0.5
        ms.append(m_node)
        owner += [b_index] * (n + 1)
        elems.append(node + np.column_stack([np.arange(n), np.arange(1, n + 1)]))
        h0s += [h] * n
        areas += [bar.area] * n
        Es += [bar.E] * n
        sys_ += [bar.yield_stress] * n
        Hs += [bar.hardening] * n
        betas += [beta_of[b_index]] * n
        left.append(node)
        right.append(node + n)
        node += n + 1
        offset += bar.length + (interfaces[b_index].gap if b_index < len(interfaces) else 0.0)
    x = np.concatenate(xs)
    m = np.concatenate(ms)
    v = np.concatenate([np.full(n + 1, b.velocity) for n, b in zip(counts, bars)])
    elem = np.concatenate(elems).astype(np.int64)
    h0, area, E = np.array(h0s), np.array(areas), np.array(Es)
    sy = np.array([s if math.isfinite(s) else 1e300 for s in sys_])
    iface = np.array([[right[k], left[k + 1]] for k in range(len(interfaces))], dtype=np.int64).reshape(-1, 2)
    k_if, c_if = np.zeros(len(interfaces)), np.zeros(len(interfaces))
    kinematic = np.array([itf.stiffness is None for itf in interfaces], dtype=np.bool_)
    # stiffness damping shortens the step as in the finite-element solver
    dt = min(damped_step(b.length / n / b.c0, beta) for n, b, beta in zip(counts, bars, beta_of))
    for k, itf in enumerate(interfaces):
        if itf.stiffness is None:
            continue
        k_if[k] = itf.stiffness
        c_if[k] = pad_dashpot(itf.damping_ratio, k_if[k], bars[k].mass, bars[k + 1].mass)
        # the stable step of the damped spring on the two end nodes: (sqrt(1 + z^2) - z) 2 / omega
        m_star = reduced_mass(m[right[k]], m[left[k + 1]])
        omega = math.sqrt(k_if[k] / m_star)
        z = c_if[k] / (2 * math.sqrt(k_if[k] * m_star))
        dt = min(dt, 2 / omega * (math.sqrt(1 + z * z) - z))
    middle = [(left[k] + right[k]) // 2 for k in range(len(bars))]
    tether = np.array([[middle[t.a], middle[t.b]] for t in tethers], dtype=np.int64).reshape(-1, 2)
    k_t = np.array([t.stiffness for t in tethers], dtype=float)
    rest_t = np.array([x[j] - x[i] for i, j in tether], dtype=float)
    for (i, j), k in zip(tether, k_t):
        dt = min(dt, 2 / math.sqrt(k * (1 / m[i] + 1 / m[j])))
    # band damping's terms stiffen the bars far above the band
    dt *= min([t.step_factor for t in band_terms if t is not None], default=1.0)
    dt *= safety_factor
    steps = int(math.ceil(end_time / dt))
    dt = end_time / steps
    band_decay, band_gain, band_weight = _band_tables(band_terms, counts, dt)
    every = max(1, steps // samples)
    n_rec = steps // every + 1
    out_v = np.zeros((n_rec, len(bars)))
    out_f = np.zeros((n_rec, len(interfaces)))
    out_e = np.zeros((n_rec, 6))
    t0 = time.perf_counter()
    max_stress = np.zeros(len(elem))
    peak_force = np.zeros(len(interfaces))
    transit = min(b.length / n / b.c0 for n, b in zip(counts, bars))
    smoothing = min(1.0, dt / (SMOOTHING_TRANSITS * transit))
    rec = _march(x, v, m, elem, h0, area, E, sy, np.array(Hs), np.array(betas), iface, k_if, c_if, kinematic,
                 anvil_gap is not None, dt, steps, every, out_v, out_f, out_e, np.array(owner, dtype=np.int64),
                 len(bars), max_stress, smoothing, peak_force, tether, k_t, rest_t, band_decay, band_gain,
                 band_weight)
    wall = time.perf_counter() - t0
    h = {"time": out_e[:rec, 4]}
    for b_index, bar in enumerate(bars):
        h[f"{bar.name}.v_z"] = out_v[:rec, b_index]
    for k, itf in enumerate(interfaces):
        h[f"contact.{itf.name}.normal_z"] = out_f[:rec, k]
    h["energy.kinetic"], h["energy.internal"] = out_e[:rec, 0], out_e[:rec, 1]
    h["energy.plastic"], h["energy.damping"] = out_e[:rec, 2], out_e[:rec, 3]
    h["energy.contact"] = out_e[:rec, 5]
    total = (h["energy.kinetic"] + h["energy.internal"] + h["energy.plastic"] + h["energy.damping"]
             + h["energy.contact"])
    balance = float(np.abs(total - total[0]).max() / total[0]) if total[0] else 0.0
    first = np.cumsum([0] + counts)
    peaks = {b.name: float(max_stress[first[i]:first[i + 1]].max()) for i, b in enumerate(bars)}
    interface_stress = {itf.name: float(peak_force[k] / min(bars[k].area, bars[k + 1].area))
                        for k, itf in enumerate(interfaces)}
    return BarsResult(h, {b.name: b.mass for b in bars}, steps, dt, wall,
                      len(elem) * steps / wall if wall > 0 else 0.0, balance, peak_stress=peaks,
                      interface_stress=interface_stress)

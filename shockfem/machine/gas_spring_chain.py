"""What the designed machine's chain gains with a gas spring (``machine.gas_spring``) at every interface: the
one interface that is not a solid, so not bound by v* = sigma / sqrt(rho E) (``premise.scale_free``).

The chain is the design's (its striker, its launch speed and mass count, ``amplifier.gain.design``'s
geometric masses), its bodies as ``machine.amplifier`` makes them, a gas spring sized on each interface
(``pads.size_pad``) and its restitution at that interface's closing speed from its gas column's run
(``gas_spring.resolved``: the shocks and their reverberations, with the heat and the seal's friction); the
rigid chain of those
restitutions, every collision followed, gives the gain and the effective e, and the masses are designed
again at that e until it settles.  The same is done for the best chain of the closed form
(``boundary.best_chain``: its launch speed and mass count at the settled e, then settled again at those), by
the simple-wave gun and by the infinitely chambered gun (the bound on any gun).
What it gains is then read as the premise reads it: the first mass and the launch energy against the
direct gun's, and each gun's p0 A L = KE / eta (``boundary.gun_efficiency``, simple-wave and infinitely
chambered) and Q, against the direct machine the premise admits (the striker in its sabot, (b): its gun
(M + m_sabot) / M times the bare striker's) and against the bare striker ((b0), the lower bound).  Range: the gas spring's (its e an upper bound, its limits
each interface's), the closed form's (rigid bodies, the first pass), and the springs' sleeves left out of
the chain's masses (their mass over the struck body's is among each spring's limits).
"""
from __future__ import annotations

import dataclasses
import math

from ..amplifier import rigid
from ..amplifier.gain import design
from ..scene.library import property_si
from .amplifier import _bodies, _chain_gain, interfaces
from .boundary import best_chain, gun_efficiency
from .limits import broken
from .gas_spring import resolved, size_gas_spring
from .pads import size_pad

MATERIAL = "nitrogen_gas_spring"
SETTLE_TOL, SETTLE_PASSES = 1e-5, 12


def settle(spec, fixture, e: float = 0.95) -> dict:
    """The chain of ``spec``'s mass count and launch speed with a gas spring at every interface, its masses
    designed again at the effective e until it settles; ``feasible`` False where no chain of those masses
    gains enough."""
    rho = property_si(spec.material, "density", "density")
    M, V = fixture.striker_mass, fixture.striker_speed
    for _ in range(SETTLE_PASSES):
        d = design(spec.architecture, M, V, spec.launch_speed, e, spec.masses)
        if not d.feasible:
            return {"feasible": False, "restitution": e, "reason": d.reason}
        bodies = _bodies(d.masses, fixture, rho, None)
        faces = interfaces(spec, d.masses, bodies, e)
        runs = [_run(f, rho) for f in faces]
        es = [r["restitution"] for r in runs]
        gain = _chain_gain(spec, d.masses, bodies, es)
        new = rigid.effective_restitution(d.masses, spec.launch_speed, gain, spec.architecture)
        done = abs(new - e) <= SETTLE_TOL
        e = new
        if done:
            break
    pads = [size_pad(f, MATERIAL) for f in faces]
    return {"feasible": True, "restitution": e, "masses": spec.masses, "launch_speed": spec.launch_speed,
            "first_mass": d.masses[0], "mass_list": d.masses, "launch_energy": 0.5 * d.masses[0] * spec.launch_speed ** 2,
            "interfaces": [_interface(f, r, p) for f, r, p in zip(faces, runs, pads)]}


def _run(iface, rho: float) -> dict:
    spring = size_gas_spring(iface.m_star, iface.speed, iface.face_diameter, iface.allowable, rho)
    return {**resolved(iface.m_star, iface.speed, spring), "closed_form": spring.restitution}


def _interface(f, run: dict, pad) -> dict:
    """One interface's spring: its run's e beside the closed form's, its size, and its limits (the sizing's and
    the sleeve's pressure in the run against its design pressure)."""
    p1 = pad.peak_force / (math.pi * pad.diameter ** 2 / 4)
    over = [f"{lim.quantity} {lim.ratio:.3g}x" for lim in broken(list(pad.limits))]
    if run["peak_pressure"] > p1 * (1 + 1e-6):
        over.append(f"sleeve pressure (gas column run) {run['peak_pressure'] / p1:.3g}x")
    return {"name": f.name, "closing_speed": f.speed, "restitution": run["restitution"],
            "closed_form_restitution": run["closed_form"], "sleeve_mass": pad.mass, "mass_share": pad.mass / f.struck_mass,
            "column": pad.thickness, "bore": pad.diameter, "peak_pressure": p1, "run_peak_pressure": run["peak_pressure"],
            "broken": over}


def guns(striker: float, speed: float, launched: float, launch_speed: float, gas: str, direct_load: float = 1.0) -> dict:
    """Each gun's p0 A L [J] (KE over the ideal gun's efficiency), simple-wave and chambered, and Q: against the
    direct gun firing the bare striker (``Q_bare``, ``direct_bare``) and against the direct machine the premise
    admits, which fires the striker in its sabot (``Q``, ``direct``: the bare one times ``direct_load`` =
    (M + m_sabot) / M, as ``premise.closed_form``'s "with_sabot"; the chain's masses fill the bore)."""
    K, E1 = 0.5 * striker * speed ** 2, 0.5 * launched * launch_speed ** 2
    out = {}
    for law, chambered in (("simple_wave", False), ("chambered", True)):
        bare = K / gun_efficiency(speed, gas, chambered)
        amp = E1 / gun_efficiency(launch_speed, gas, chambered)
        out[law] = {"direct_bare": bare, "direct": bare * direct_load, "amplifier": amp, "Q_bare": amp / bare,
                    "Q": amp / (bare * direct_load), "direct_load": direct_load}
    return out


def gas_spring_chain(m, white_paper_e: float = 0.9, sabot: float = 0.0) -> dict:
    """The design's chain and the best chain with gas springs (module docstring), and the design's chain at
    ``white_paper_e`` for comparison; Q against the direct gun firing the striker in its ``sabot`` [kg] (the
    premise's (b)) and bare (``guns``)."""
    s, f = m.spec, m.fixture
    M, V = f.striker_mass, f.striker_speed
    load = (M + sabot) / M
    spec_chain = settle(s, f)
    out = {"striker_mass": M, "striker_speed": V, "striker_energy": 0.5 * M * V * V, "spec_chain": spec_chain,
           "sabot": sabot, "direct_load": load}
    if spec_chain["feasible"]:
        spec_chain["guns"] = guns(M, V, spec_chain["first_mass"], s.launch_speed, s.gas, load)
        c = best_chain(spec_chain["restitution"], V, s.gas)
        best = settle(dataclasses.replace(s, masses=c.masses, launch_speed=c.launch_speed), f,
                      spec_chain["restitution"])
        if best["feasible"]:
            best["guns"] = guns(M, V, best["first_mass"], c.launch_speed, s.gas, load)
            best["best_chain_Q"] = best_chain(best["restitution"], V, s.gas, direct_load=load).gun_ratio
            best["best_chain_Q_chambered"] = best_chain(best["restitution"], V, s.gas, chambered=True,
                                                        direct_load=load).gun_ratio
        out["best_chain"] = best
        # the chambered gun's own best chain at the settled e, settled again on its own closing speeds
        cc = best_chain(spec_chain["restitution"], V, s.gas, chambered=True)
        chambered = settle(dataclasses.replace(s, masses=cc.masses, launch_speed=cc.launch_speed), f,
                           spec_chain["restitution"])
        if chambered["feasible"]:
            chambered["guns"] = guns(M, V, chambered["first_mass"], cc.launch_speed, s.gas, load)
        out["best_chain_chambered"] = chambered
    d = design(s.architecture, M, V, s.launch_speed, white_paper_e, s.masses)
    out["at_white_paper_e"] = {"restitution": white_paper_e, "first_mass": d.masses[0] if d.feasible else math.nan,
                               "guns": guns(M, V, d.masses[0], s.launch_speed, s.gas, load) if d.feasible else None}
    return out

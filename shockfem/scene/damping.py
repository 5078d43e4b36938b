"""The scene's damping tables (``[damping]`` and ``bodies[i].damping``) and what they warn of.

A Rayleigh table is ``{type = "mass" | "stiffness" | "rayleigh", ratio, frequency}``: the ratio of
critical at one frequency, growing above it (stiffness) or below it (mass).  A band table is
``{type = "band", ratio, low, high, reference}``: the ratio held over [low, high] by Maxwell terms
(``materials/band_damping.py``, LS-DYNA's *DAMPING_FREQUENCY_RANGE_DEFORM), the body's materials
being its moduli at ``reference`` (default the band's geometric centre; 0 Hz: static).
"""
from __future__ import annotations

import math

import numpy as np

from ..materials.band_damping import BandTerms, fit_band
from .checker import Checker
from .specs import DAMPING_TYPES, Damping


def read_damping(ck: Checker, raw: dict, path: str, kinds=DAMPING_TYPES, default_kind: str = "rayleigh") -> Damping:
    """``raw["damping"]`` found at ``path``: a ``{ratio, frequency, type}`` Rayleigh table, or a band
    ``{type = "band", ratio, low, high}``; its ``type`` one of ``kinds``."""
    d = ck.table(raw, "damping", path)
    kind = ck.choice(d, "type", path, kinds, default=default_kind)
    if kind != "band":
        ck.unknown(d, ("ratio", "frequency", "type"), path)
        ratio = ck.quantity(d, "ratio", path, "dimensionless", nonnegative=True, upper=1.0)
        freq = ck.quantity(d, "frequency", path, "frequency", positive=True)
        return Damping(ratio, freq, kind)
    ck.unknown(d, ("ratio", "low", "high", "reference", "type"), path)
    ratio = ck.quantity(d, "ratio", path, "dimensionless", positive=True, upper=0.5)
    low = ck.quantity(d, "low", path, "frequency", positive=True)
    high = ck.quantity(d, "high", path, "frequency", positive=True)
    reference = ck.quantity(d, "reference", path, "frequency", nonnegative=True) if "reference" in d else None
    if low > 0 and high > 0 and 0 < ratio < 0.5:
        try:
            fit_band(ratio, low, high)
        except ValueError as e:
            ck.fail(f"{path}.high", f"{e} (high must be above low)")
    return Damping(ratio, math.sqrt(low * high) if low > 0 and high > 0 else 0.0, "band", low, high, reference)


def read_scene_damping(ck: Checker, raw: dict) -> Damping | None:
    """The scene's ``[damping]``, or None."""
    return read_damping(ck, raw, "damping") if "damping" in raw else None


def read_body_damping(ck: Checker, b: dict, path: str) -> Damping:
    """``bodies[i].damping``: the body's own damping, stiffness-proportional as LS-DYNA's
    *DAMPING_PART_STIFFNESS (a fraction of critical at the body's own frequency, its first mode, say,
    so that small stiff bodies are not damped at a large body's low frequency: stiffness damping grows
    with frequency) or a band.  Mass-proportional damping stays scene-wide."""
    return read_damping(ck, b, f"{path}.damping", ("stiffness", "band"), "stiffness")


# Laws whose moduli a band's reference frequency may rescale: Hooke's law and J2's elastic part (its
# yield stresses and hardening stay: they are strengths, not the elastic response the terms stiffen).
# A crushable foam's and a rubber's response at large strain is their crush curve's and strain energy's,
# which a measured dynamic modulus does not define: those take a band only with static moduli.
RESCALED_LAWS = ("elastic", "j2")


def check_band_laws(ck: Checker, bodies, materials: dict, scene_damping: Damping | None) -> None:
    """Refuse a band that would rescale the moduli of a law outside ``RESCALED_LAWS`` (a foam, a rubber)
    unless its ``reference`` is 0 Hz (the material's moduli static, nothing rescaled)."""
    for i, b in enumerate(bodies):
        d = b.damping or scene_damping
        m = materials.get(b.material)
        if b.rigid or d is None or d.kind != "band" or m is None or m.law in RESCALED_LAWS or d.reference == 0.0:
            continue
        path = f"bodies[{i}].damping" if b.damping else "damping"
        ck.fail(f"{path}.reference", f"body {b.name}'s material {m.name} is a {m.law}: a band damping takes its "
                f"moduli as given at a reference frequency by rescaling Hooke's moduli, which has no meaning for "
                f"a {m.law}'s {'crush curve' if m.law == 'foam' else 'strain energy'}. Set reference = \"0 Hz\" "
                f"(its moduli static, the body stiffer than them across the band) or give it "
                f"damping.type = \"stiffness\"")


def band_terms(d: Damping | None) -> BandTerms | None:
    """The Maxwell terms of a band damping (None for no damping or a Rayleigh one)."""
    return fit_band(d.ratio, d.low, d.high) if d is not None and d.kind == "band" else None


def describe_damping(d: Damping) -> str:
    """One line of the run's summary for a damping table."""
    if d.kind == "band":
        terms = fit_band(d.ratio, d.low, d.high)
        ref = d.reference_frequency
        # the moduli are the body's at the reference frequency (E / Re K(w_ref) in the elastic law): a wave
        # of frequency f runs sqrt(Re K(w) / Re K(w_ref)) times what they say, the band's dispersion
        foot, top = np.sqrt(terms.dispersion([d.low, d.high], ref)) - 1.0
        held = (f"the material's moduli held at {ref:.4g} Hz (elastic law at E x {terms.relaxed_scale(ref):.4f})"
                if ref > 0 else "the material's moduli static (the body stiffer across the band)")
        return (f"band, {d.ratio:.3g} of critical over {d.low:.6g} to {d.high:.6g} Hz ({len(terms.tau)} Maxwell "
                f"terms, within {terms.ripple():.1%} over the band); {held}; by causality waves still disperse: "
                f"{foot:+.1%} at {d.low:.4g} Hz, {top:+.1%} at {d.high:.4g} Hz against the moduli's speed, so a "
                f"pulse timed by a wave's transit shifts by up to that much as its spectrum sits low or high in "
                f"the band; the stable step x {terms.step_scale(ref):.3f} of the "
                f"moduli's (the body {terms.stiffening:.1%} stiffer than relaxed far above the band)")
    a, b = d.coefficients()
    return f"{d.kind}, {d.ratio:.3g} of critical at {d.frequency:.6g} Hz (alpha = {a:.4g} 1/s, beta = {b:.4g} s)"


def _speed(scene, body) -> float:
    """The largest rigid-body speed a body is given [m/s]: its initial velocity or a velocity boundary's."""
    driven = [abs(v) for bc in scene.boundaries if bc.kind == "velocity" and bc.region.partition(".")[0] == body.name
              for _, v in bc.history]
    return max([math.hypot(*body.velocity)] + driven)


def _held(scene, body) -> bool:
    """Whether a boundary holds the body still: fixed, or driven at zero velocity only."""
    own = [bc for bc in scene.boundaries if bc.region.partition(".")[0] == body.name]
    return any(bc.kind == "fixed" for bc in own) or (
        any(bc.kind == "velocity" for bc in own)
        and all(v == 0.0 for bc in own if bc.kind == "velocity" for _, v in bc.history))


def mass_damping_warnings(scene) -> list[str]:
    """A sentence per deformable body that mass-proportional damping brakes: a scene damping with a
    mass part (alpha > 0) is a force -alpha m v on every node, rigid-body motion included, so a body
    that is not held still is braked (a free one loses its velocity as exp(-alpha t)) or needs more
    force to drive (LS-DYNA's manual gives the same caution for *DAMPING_GLOBAL)."""
    alpha = scene.damping.coefficients()[0] if scene.damping else 0.0
    if alpha <= 0.0:
        return []
    out = []
    for b in scene.bodies:
        if b.rigid or _held(scene, b):
            continue
        speed = _speed(scene, b)
        drag = (f"at its {speed:.4g} m/s a force alpha m v, a braking acceleration of {alpha * speed:.4g} m/s^2"
                if speed > 0 else "once it moves")
        out.append(f"body {b.name}: the scene's mass-proportional damping (damping.type = {scene.damping.kind!r}, "
                   f"alpha = {alpha:.4g} 1/s) brakes its rigid-body motion, {drag}; a free body's velocity falls "
                   f"as exp(-alpha t), by {-math.expm1(-alpha * scene.end_time):.1%} over end_time = "
                   f"{scene.end_time:.4g} s. Use damping.type = \"band\" (or \"stiffness\"), which leave "
                   "rigid-body motion alone")
    return out

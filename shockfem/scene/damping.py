"""Damping tables: the scene's ``[damping]`` (Rayleigh, mass or stiffness) and a body's own
``bodies[i].damping`` (stiffness-proportional at its own frequency)."""
from __future__ import annotations

from .checker import Checker
from .specs import DAMPING_TYPES, Damping


def read_damping(ck: Checker, raw: dict, path: str, kinds=DAMPING_TYPES, default_kind: str = "rayleigh") -> Damping:
    """A ``{ratio, frequency, type}`` damping table, ``raw["damping"]``, found at ``path``."""
    d = ck.table(raw, "damping", path)
    ck.unknown(d, ("ratio", "frequency", "type"), path)
    ratio = ck.quantity(d, "ratio", path, "dimensionless", nonnegative=True, upper=1.0)
    freq = ck.quantity(d, "frequency", path, "frequency", positive=True)
    kind = ck.choice(d, "type", path, kinds, default=default_kind)
    return Damping(ratio, freq, kind)


def read_scene_damping(ck: Checker, raw: dict) -> Damping | None:
    """The scene's ``[damping]``, or None."""
    return read_damping(ck, raw, "damping") if "damping" in raw else None


def read_body_damping(ck: Checker, b: dict, path: str) -> Damping:
    """``bodies[i].damping``: the body's own stiffness-proportional damping, as LS-DYNA's
    *DAMPING_PART_STIFFNESS: a fraction of critical at the body's own frequency (its first mode,
    say), so that small stiff bodies are not damped at a large body's low frequency (stiffness
    damping grows with frequency).  Mass-proportional damping stays scene-wide."""
    return read_damping(ck, b, f"{path}.damping", ("stiffness",), "stiffness")

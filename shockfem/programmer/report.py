"""The sizing report of ``shockfem programmer``: the requirement, then each concept's sizes, notes
and verdict, in the units a shock engineer reads (mm, MPa, g, kg)."""
from __future__ import annotations

from ..units import G0, LB
from .concepts import Concept
from .requirement import Requirement

# SI unit -> (display unit, factor)
_DISPLAY = {"m": ("mm", 1e3), "m^2": ("cm^2", 1e4), "Pa": ("MPa", 1e-6), "s": ("ms", 1e3), "kg": ("kg", 1.0),
            "m/s": ("m/s", 1.0), "K": ("K", 1.0), "-": ("", 1.0)}


def format_report(req: Requirement, concepts: list[Concept]) -> str:
    lines = [f"pulse: {req.shape}, {req.peak_g:.6g} g ({req.peak:.6g} m/s^2) for {req.duration * 1e3:.4g} ms; "
             f"article {req.mass:.4g} kg ({req.mass / LB:.4g} lb)",
             f"  velocity change {req.velocity_change:.4g} m/s, stroke {req.stroke * 1e3:.4g} mm (to rest, no "
             f"rebound), peak force {req.force / 1e6:.4g} MN, energy {req.energy / 1e3:.4g} kJ"]
    for c in concepts:
        if not c.feasible:
            verdict = f"ruled out: {c.reason}"
        elif c.gives == req.shape or (c.gives == "rectangle" and req.shape == "trapezoid"):
            verdict = "meets it with the sizes below"
        else:
            verdict = (f"gives a {c.gives} of the peak and the velocity change ({req.velocity_change / req.peak * 1e3:.4g}"
                       f" ms), not a {req.shape}, with the sizes below")
        lines += ["", f"{c.name}: {verdict}", f"  model: {c.model}"]
        for label, value, unit in c.sizes:
            shown, factor = _DISPLAY[unit]
            lines.append(f"  {label:58s} {value * factor:12.5g} {shown}")
        lines += [f"  note: {n}" for n in c.notes]
    lines += ["", f"(accelerations in standard gravities, g = {G0} m/s^2)"]
    return "\n".join(lines)

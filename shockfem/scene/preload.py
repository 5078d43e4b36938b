"""``[scene.preload]``: a stage before the event in which the assembly settles under its interference fits.

    [scene.preload]
    duration = "1 ms"                # the longest the stage may take (default: 5 x the longest interference time)
    kinetic_energy_ratio = 1e-5      # settled: the kinetic energy below this share of the stored energy
    frequency = "5 kHz"              # damped critically in the stage (default: the bodies' lowest c0 / 2L)

The event's bodies (those given an initial velocity or spin) are held at rest through the stage, the
interferences come on over their contacts' ``interference`` times, and the motion is taken out by mass
damping (``solver/preload.py``); the event then starts from the settled state with its own clock.  What the
stage cannot hold still is refused here: a velocity boundary or a rigid surface that moves would move
through the stage.
"""
from __future__ import annotations

from .checker import Checker
from .specs import Preload

PRELOAD_FIELDS = ("duration", "kinetic_energy_ratio", "frequency")
# the default stage: this many times the longest interference time (the fit comes on over one; the
# stage's damping settles a shrink fit well within the rest, ``docs/theory.md`` "The preload stage")
DEFAULT_SPAN = 5.0


def read_preload(ck: Checker, raw: dict, boundaries, contacts) -> Preload | None:
    """``raw["scene"]["preload"]`` checked against the scene's ``boundaries`` and ``contacts``, or None."""
    scene = raw.get("scene") if isinstance(raw.get("scene"), dict) else {}
    if "preload" not in scene:
        return None
    path = "scene.preload"
    p = ck.table(scene, "preload", path)
    ck.unknown(p, PRELOAD_FIELDS, path)
    longest = max((c.interference_time for c in contacts), default=0.0)
    if "duration" not in p and longest <= 0.0:
        ck.fail(f"{path}.duration", "give the stage's duration (no contact has an interference time to take it "
                "from: set a contact's interference = \"<time>\" to bring its fit on during the stage)")
    duration = ck.quantity(p, "duration", path, "time", default=DEFAULT_SPAN * longest if longest > 0 else 1.0,
                           positive=True)
    if 0.0 < duration < longest * (1.0 - 1e-9):
        ck.fail(f"{path}.duration", f"is shorter than the longest interference time ({longest:.4g} s): the fits "
                "would not have come on when the event starts; make it at least that (5 x by default)")
    ratio = ck.quantity(p, "kinetic_energy_ratio", path, "dimensionless", default=1e-5, positive=True, upper=1.0)
    for i, bc in enumerate(boundaries):
        if bc.kind == "velocity" and any(v != 0.0 for _, v in bc.history):
            ck.fail(path, f"boundary {i} drives {bc.region} at a velocity other than zero: it would move through "
                    "the preload stage; give the event's motion as the body's initial velocity instead")
    for c in contacts:
        if c.rigid is not None and any(v != 0.0 for v in c.rigid.velocity):
            ck.fail(path, f"contact {c.name}'s rigid surface moves: it would move through the preload stage; "
                    "hold it still and give the event's motion to the body instead")
    frequency = ck.quantity(p, "frequency", path, "frequency", default=0.0, positive="frequency" in p)
    return Preload(duration, ratio, frequency)

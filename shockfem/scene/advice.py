"""What a valid scene is warned of before it runs (``shockfem check``, the run's log and its summary's
``warnings``): choices that run, but not as the user most likely means them.  Each warning names the
fields, what will happen and the fix."""
from __future__ import annotations

from .specs import Scene


def split_segments(body) -> int:
    """How many segments a split cone's slots cut it into (0: none, or not a split cone): segments carry no
    hoop stress, so nothing but what they grip and what grips them holds them radially."""
    if body.shape != "split_cone" or body.rigid:
        return 0
    segments = int(body.dims.get("segments", 0))
    return segments if segments >= 2 else 0


def interference_on_free_segments(scene: Scene) -> list[str]:
    """A contact whose interference is pushed out as a preload (``interference``, a time) onto a split
    cone's segments: the ring's pressure is balanced by no hoop stress, so it drives the segments inward
    until they close on what they grip, and the event starts from that motion."""
    out = []
    if scene.preload is not None:
        return out          # the preload stage settles the fit before the event (solver/preload.py)
    for c in scene.contacts:
        if c.interference_time <= 0.0 or c.b is None:
            continue
        for side in (c.a, c.b):
            body = scene.body(side.split(".")[0])
            n = split_segments(body)
            if n:
                out.append(f"contact {c.name}: its interference (pushed out over {c.interference_time:.3g} s) "
                           f"presses on body {body.name}, a split cone of {n} segments: they carry no hoop stress, "
                           "so the preload is balanced by nothing until they bear on what they grip, and it drives "
                           "them inward as a blow before the event (the clamp opens and the rebound changes). "
                           "Add a [scene.preload] stage (the fit settles before the event), or seat the gripped "
                           "part in the bore at t = 0 so that the segments bear on it as the fit "
                           "comes on, or leave the contact's interference out (the ring then starts in contact "
                           "without a preload)")
    return out


def scene_warnings(scene: Scene) -> list[str]:
    """Every warning of ``scene``, each a sentence with the fix."""
    return interference_on_free_segments(scene)

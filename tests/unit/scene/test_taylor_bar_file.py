"""``studies/foundation/taylor_bar.toml`` (the README's picture) is the scene ``shockfem verify taylor_bar``
checks at its default size: resolved, the two are the same, every number to 1e-15 (the file's "80 us" is
8e-05 s less one unit in the last place after the unit conversion), but for the field cadence the file
asks for (the verification writes one frame; the picture wants the shape along the way)."""
import math
import os

from shockfem.scene import load_scene, resolve, to_plain
from shockfem.verify.plasticity_cases import taylor_scene

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))


def _same(a, b, path="scene"):
    """Every difference between two resolved scenes, as its path (numbers to 1e-15 relative)."""
    if isinstance(a, dict) and isinstance(b, dict):
        keys = set(a) | set(b)
        return [d for k in sorted(keys, key=str) for d in _same(a.get(k), b.get(k), f"{path}.{k}")]
    if isinstance(a, (list, tuple)) and isinstance(b, (list, tuple)) and len(a) == len(b):
        return [d for k, (x, y) in enumerate(zip(a, b)) for d in _same(x, y, f"{path}[{k}]")]
    if isinstance(a, float) and isinstance(b, float):
        return [] if math.isclose(a, b, rel_tol=1e-15, abs_tol=0.0) else [f"{path}: {a!r} != {b!r}"]
    return [] if a == b else [f"{path}: {a!r} != {b!r}"]


def test_the_scene_file_is_the_verified_taylor_bar():
    from_file = to_plain(load_scene(os.path.join(REPO, "studies", "foundation", "taylor_bar.toml")))
    verified = to_plain(resolve(taylor_scene(0.0002)))
    for scene in (from_file, verified):
        scene["outputs"].pop("field_interval")
        scene.pop("folder")             # where each was read from (the file's folder; none for the code's)
    assert _same(from_file, verified) == []

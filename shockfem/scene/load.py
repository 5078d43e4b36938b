"""Reading scene files and applying command-line overrides (``--set path=value``)."""
from __future__ import annotations

import copy
import os
import tomllib

from .checker import SceneError
from .schema import resolve
from .specs import Scene


def is_chain(raw: dict) -> bool:
    """A mass-chain scene: a [chain] table (``amplifier/chain.py``)."""
    return "chain" in raw


def is_launcher_scene(raw: dict) -> bool:
    """A gas-gun scene: a [launcher] table and no bodies (a chain's [launcher] fires its first body)."""
    return "launcher" in raw and "bodies" not in raw and "chain" not in raw


def read_toml(path: str) -> dict:
    if not os.path.exists(path):
        raise SceneError([f"{path}: no such scene file"])
    if not os.path.isfile(path):
        raise SceneError([f"{path}: a directory, not a scene file (give one .toml in it)"])
    try:
        with open(path, "rb") as fh:
            return tomllib.load(fh)
    except tomllib.TOMLDecodeError as e:
        raise SceneError([f"{path}: not valid TOML ({e})"]) from None


def _parse_value(text: str):
    """A --set value: TOML syntax if it parses ("[1, 2]", "true", "3.5"), else a plain string."""
    try:
        return tomllib.loads(f"v = {text}")["v"]
    except tomllib.TOMLDecodeError:
        return text


def apply_override(raw: dict, assignment: str) -> dict:
    """Apply ``bodies.striker.velocity="12 m/s"`` to a raw scene dictionary (returns a copy).

    List entries are addressed by their ``name`` (bodies) or by index (``boundary.0.value``).
    """
    if "=" not in assignment:
        raise SceneError([f"--set {assignment}: write it as path=value, e.g. bodies.striker.velocity='12 m/s'"])
    path, _, text = assignment.partition("=")
    keys = path.strip().split(".")
    out = copy.deepcopy(raw)
    node = out
    for i, key in enumerate(keys[:-1]):
        if isinstance(node, list):
            match = [e for e in node if isinstance(e, dict) and e.get("name") == key]
            if match:
                node = match[0]
            elif key.isdigit() and int(key) < len(node):
                node = node[int(key)]
            else:
                names = [e.get("name") for e in node if isinstance(e, dict)]
                raise SceneError([f"--set {path}: no entry {key!r} in {'.'.join(keys[:i]) or 'scene'} "
                                  f"(entries: {', '.join(map(str, names))})"])
        elif isinstance(node, dict):
            node = node.setdefault(key, {})
        else:
            raise SceneError([f"--set {path}: {'.'.join(keys[:i])} is a value, not a table"])
    if not isinstance(node, dict):
        raise SceneError([f"--set {path}: cannot set a field inside a value"])
    node[keys[-1]] = _parse_value(text.strip())
    return out


def apply_overrides(raw: dict, overrides) -> dict:
    """``apply_override`` of each assignment in turn (returns a copy)."""
    for assignment in overrides:
        raw = apply_override(raw, assignment)
    return raw


def load_scene(path: str, overrides: list[str] | tuple = ()) -> Scene:
    """Read, override and resolve a scene file; raises SceneError listing every problem."""
    raw = apply_overrides(read_toml(path), overrides)
    try:
        return resolve(raw, base_dir=os.path.dirname(os.path.abspath(path)))
    except SceneError as e:
        raise SceneError([f"{os.path.basename(path)}: {p}" for p in e.problems]) from None

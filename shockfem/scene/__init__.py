"""Scenes: TOML files describing bodies, materials, boundary conditions and outputs."""
from .load import apply_override, apply_overrides, is_chain, is_launcher_scene, load_scene, read_toml
from .checker import SceneError
from .schema import resolve, to_plain
from .specs import Body, Boundary, Damping, Material, Scene

__all__ = ["Body", "Boundary", "Damping", "Material", "Scene", "SceneError", "apply_override", "apply_overrides",
           "is_chain", "is_launcher_scene", "load_scene", "read_toml", "resolve", "to_plain"]

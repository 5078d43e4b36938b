"""Scenes: TOML files describing bodies, materials, boundary conditions and outputs."""
from .load import apply_override, load_scene, read_toml
from .schema import Body, Boundary, Damping, Material, Scene, SceneError, resolve, to_plain

__all__ = ["Body", "Boundary", "Damping", "Material", "Scene", "SceneError", "apply_override",
           "load_scene", "read_toml", "resolve", "to_plain"]

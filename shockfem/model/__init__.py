"""The discrete model: kinematics, materials, bodies, constraints and loads."""
from .model import Constraint, Load, Model, RigidBody, build_model, describe

__all__ = ["Constraint", "Load", "Model", "RigidBody", "build_model", "describe"]

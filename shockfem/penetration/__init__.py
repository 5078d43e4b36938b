"""Concrete penetration: the resistance a target applies to a projectile (the white paper's task 1)."""

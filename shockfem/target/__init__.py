"""A penetrated target's resistance as a load on the projectile's nose (concrete, cavity expansion)."""

"""shockfem's version (one place: the package, the run directory's provenance)."""
__version__ = "0.1.0"

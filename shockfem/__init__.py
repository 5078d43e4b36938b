"""shockfem: a finite-element impact workbench on FEniCSx (dolfinx) for shock-machine design."""
__version__ = "0.1.0"

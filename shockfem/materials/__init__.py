"""Material laws as compiled functions of one point over one step.

The element kernels (``shockfem.elements``) call ``update.update_stress`` at each integration point:
objective rotation, the slotted ring's hoop constraint and the row's law (``laws.LAWS``), then
``viscosity.viscous_stress`` for the force stress.  This package imports nothing else of shockfem.
"""

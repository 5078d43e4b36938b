"""The central-difference time loop over the element kernels (``shockfem.elements``), contact and loads."""

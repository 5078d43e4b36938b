"""Element kernels: one compiled pass over the cells computes the strain rate, calls the material
update (``shockfem.materials``) and assembles the internal force.

* ``cells.py``: kinematics codes, shape-function gradients, characteristic lengths, orientation;
* ``full_integration.py``: any P1 cell at its Gauss points (``stress_divergence``);
* ``one_point.py``: reduced quads and hexes with hourglass control (the hex pass);
* ``one_point_quads.py``: the quads' pass, in blocks of cells through SIMD lanes;
* ``kernels.py``: which one-point pass a mesh runs.

This package imports only ``shockfem.materials``: no model, scene, contact or geometry code.
"""

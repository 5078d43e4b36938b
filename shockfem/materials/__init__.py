"""Material laws as compiled functions of one point over one step.

The element kernels (``shockfem.elements``) call ``update.update_stress`` at each integration point:
objective rotation, the slotted ring's hoop constraint and the row's law (``laws.LAWS``), then
``viscosity.viscous_stress`` for the force stress.  This package imports nothing else of shockfem but
``numba_inline``, which makes numba's inlining of these laws into every kernel several times faster to
compile, and ``data_stack``, which puts numba's compiles on a deep data stack (every run imports this
package before its first compile).
"""
from ..data_stack import compile_on_deep_data_stack
from ..numba_inline import share_var_locations

share_var_locations()
compile_on_deep_data_stack()

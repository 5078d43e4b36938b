"""numba's inliner without its copies of every variable's source location (numba before 0.59).

An ``inline="always"`` call makes numba copy the callee's IR into the caller, statement by statement
(``copy.deepcopy``, ``inline_closurecall.InlineWorker.inline_ir``).  Before numba 0.59 a variable had no copy
method of its own: its copy copied its source location, with the file's source lines the location may hold,
and, through its scope, every variable of the function with theirs, once per statement.  That copying was
almost all of the element kernels' compile (``docs/performance.md``, "Compile time").  numba 0.59 gives
``ir.Var`` a ``__deepcopy__`` that keeps the location by reference (numba PR 9245, issue 9204);
``share_var_locations`` gives numba 0.56 (Debian 12's) the same method.  A location is read-only once made,
so the IR, and the machine code compiled from it, are the same: only the compile is faster.
"""
from __future__ import annotations

import copy


def _var_deepcopy(self, memo):
    """numba 0.59's ``ir.Var.__deepcopy__``: the scope copied, the location shared."""
    from numba.core import ir
    out = ir.Var(copy.deepcopy(self.scope, memo), self.name, self.loc)
    memo[id(self)] = out
    return out


def share_var_locations() -> bool:
    """Give numba's ``ir.Var`` the copy method of numba 0.59 where it has none; whether it was missing."""
    from numba.core import ir
    if "__deepcopy__" in vars(ir.Var):
        return False
    ir.Var.__deepcopy__ = _var_deepcopy
    return True

"""``numba_inline.share_var_locations``: numba's IR variables copy as numba 0.59 copies them."""
import copy

from numba import njit
from numba.core import ir

from shockfem.numba_inline import share_var_locations


def test_a_copied_variable_shares_its_location_and_copies_its_scope():
    share_var_locations()                      # done by shockfem.materials already; a second call changes nothing
    assert share_var_locations() is False
    loc = ir.Loc("kernel.py", 3)
    loc.lines = ["line\n"] * 1000              # what a location holds once numba has printed it
    scope = ir.Scope(None, loc)
    var = scope.define("x", loc)
    twin = copy.deepcopy(var)
    assert twin.loc is loc and twin.name == "x"
    assert twin.scope is not scope and twin.scope.get("x").name == "x"


def test_an_inlined_function_computes_the_same():
    # numba's inliner copies the callee's IR with this method: a wrong copy would change the result
    @njit(inline="always")
    def axpy(a, x, y):
        return a * x + y

    @njit
    def twice(x):
        return axpy(2.0, x, 1.0) + axpy(3.0, x, -1.0)

    assert twice(1.5) == 2.0 * 1.5 + 1.0 + 3.0 * 1.5 - 1.0

"""A call whose Python frames all fit in one block of the interpreter's data stack.

CPython 3.11 keeps its frames on a data stack made of blocks ("chunks", 16 kB at first): a call that does not
fit in the current block maps a new one (``mmap``), and the return from the block's first frame unmaps it
(``munmap``).  A program that calls and returns again and again at a block's boundary pays two system calls
and a page fault each time (CPython issue gh-142183, fixed in 3.13 and later by keeping one free block).
numba's compiler, deep recursive Python, does just that: the first ``shockfem run`` of
``studies/foundation/bar_impact.toml`` from an empty cache made 2.2 million ``mmap`` and ``munmap`` calls
and spent 9 of its 43 s of CPU in the kernel (``docs/performance.md``, "Compile time").

``call_on_deep_data_stack`` calls a function from a frame that reserves ``RESERVED_SLOTS`` slots of
evaluation stack (its code object's ``co_stacksize``, raised): the interpreter gives that frame a block of
its own, twice its size, and the frames of everything it calls fill the rest of that block, so that no
boundary is crossed below a depth of thousands of frames.  It changes no result, only where the frames'
memory comes from; the block (2 MB) lives as long as the call.

``compile_on_deep_data_stack`` puts every numba compile there, whoever calls the kernel (the console, the
Python API, a test, a script): numba's dispatcher compiles a kernel called from Python with new types in
``Dispatcher._compile_for_args``, which then runs through ``call_on_deep_data_stack``.  A compile entered
on the deep stack already (the console's ``main`` is) takes a block of its own as well, once per kernel
called from Python.
"""
from __future__ import annotations

import types

# slots of 8 bytes: 1 MB of frames above the call, more than numba's deepest compile needs
RESERVED_SLOTS = 1 << 17


def _call(fn, args, kwargs):
    return fn(*args, **kwargs)


_deep_call = types.FunctionType(_call.__code__.replace(co_stacksize=_call.__code__.co_stacksize + RESERVED_SLOTS),
                                _call.__globals__, "call_on_deep_data_stack")


def call_on_deep_data_stack(fn, *args, **kwargs):
    """``fn(*args, **kwargs)``, its frames in one large block of the interpreter's data stack (module
    docstring)."""
    return _deep_call(fn, args, kwargs)


def compile_on_deep_data_stack() -> bool:
    """Make numba's dispatcher compile on a deep data stack (module docstring); whether it did not already."""
    from numba.core.dispatcher import Dispatcher
    plain = Dispatcher._compile_for_args
    if getattr(plain, "on_deep_data_stack", False):
        return False

    def _compile_for_args(self, *args, **kws):
        return call_on_deep_data_stack(plain, self, *args, **kws)

    _compile_for_args.on_deep_data_stack = True
    Dispatcher._compile_for_args = _compile_for_args
    return True

"""``data_stack.call_on_deep_data_stack``: the call's result, and no frame block mapped again and again."""
import resource

from shockfem.data_stack import call_on_deep_data_stack


def _depth(n):
    return 0 if n == 0 else _depth(n - 1) + 1


def _sweep_depths():
    # calls to every depth up to 300 frames (tens of kB of frames): each sweep crosses a 16 kB block boundary
    for _ in range(200):
        for d in range(0, 300, 7):
            _depth(d)


def _faults(call) -> int:
    before = resource.getrusage(resource.RUSAGE_SELF).ru_minflt
    call()
    return resource.getrusage(resource.RUSAGE_SELF).ru_minflt - before


def test_returns_the_call_with_its_arguments():
    assert call_on_deep_data_stack(lambda a, b=0: (a, b), 1, b=2) == (1, 2)


def test_no_block_mapped_per_call_at_a_boundary():
    # CPython 3.11 maps and unmaps a block (a page fault each) at every crossing: 8,600 crossings here
    # (200 sweeps of 43 depths); on the deep stack the frames stay in one block, a few faults at most.
    # On a CPython that keeps a free block (3.13+) both are small, and the bound still holds.
    call_on_deep_data_stack(_sweep_depths)         # the deep block's pages touched once
    plain = _faults(_sweep_depths)
    deep = _faults(lambda: call_on_deep_data_stack(_sweep_depths))
    assert deep < max(100, plain / 10), (deep, plain)


def test_a_kernel_called_from_python_compiles_on_the_deep_data_stack():
    """Once ``shockfem.materials`` is imported (as every run's kernels import it), a kernel's compile runs
    under ``call_on_deep_data_stack``: the typing of a call inside the kernel sees its frame below."""
    import sys

    from numba import njit
    from numba.extending import overload

    import shockfem.materials  # noqa: F401  (applies the patch)
    from shockfem import data_stack
    assert not data_stack.compile_on_deep_data_stack()       # applied once, already

    seen = []

    def probe():
        pass

    @overload(probe)
    def _typing():
        frame, codes = sys._getframe(), set()
        while frame is not None:
            codes.add(frame.f_code)
            frame = frame.f_back
        seen.append(data_stack._deep_call.__code__ in codes)
        return lambda: None

    @njit
    def kernel():
        probe()

    kernel()
    assert seen and all(seen)

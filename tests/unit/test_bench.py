"""``bench.CompileClock``: numba's compile time from its events, the outermost compile of each call only."""
from numba import njit
from numba.core import event

from shockfem.bench import CompileClock


def test_the_clock_counts_every_compile_and_times_the_outermost():
    """A kernel that calls another compiles both (two events, one nested in the other); the clock counts two
    and times one span, which the second call (compiled already) leaves alone."""

    @njit
    def inner(x):
        return 2.0 * x

    @njit
    def outer(x):
        return inner(x) + 1.0

    clock = CompileClock()
    with event.install_listener("numba:compile", clock):
        assert outer(1.0) == 3.0
        count, seconds = clock.count, clock.seconds
        assert outer(2.0) == 5.0
    assert count == 2 and clock.depth == 0
    assert seconds > 0.0 and (clock.count, clock.seconds) == (count, seconds)

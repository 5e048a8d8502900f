r"""Compiled (numba) twin of :func:`magbench.integrate.rk4_step`: the same classical RK4
step, the same operations in the same order, for numba right-hand sides.

The compiled simulation loops (the detumbling, passive, bench and normalised-rotor kernels
of :mod:`magbench.sim`) take their steps with it, so the library has one RK4 and this one
twin. Their right-hand sides are numba functions of ``(time, state, *args)`` that return a
new array shaped like ``state``, members on the last (contiguous) axis; each loops over the
members in straight-line scalar code, which the compiler runs several members per SIMD
instruction.

The stages are formed as :func:`~magbench.integrate.rk4_step` forms them
(``x + (h/2)·k₁``, …, ``x + (h/6)·(k₁ + 2(k₂ + k₃) + k₄)``), elementwise and without
fast-math, so the two steps give the same numbers to the last bit; the tests hold them to it
(``tests/test_integrate.py``).

Inlined into its callers (``inline="always"``, numba's IR inlining): a cached function that
passes a right-hand side to a function it calls holds that function's address as a dynamic
global, which numba cannot cache (measured: 5 s of compilation in every process). Inlined,
the right-hand side is the caller's own global, and the caller's cache entry holds the step.
"""

from numba import njit

__all__ = ["rk4_step"]


@njit(error_model="numpy", inline="always")
def rk4_step(rhs, time, state, step, args):
    r"""Advance ẋ = f(t, x, \*args) by one classical RK4 step (the compiled twin of
    :func:`magbench.integrate.rk4_step`, which documents the method).

    ``rhs(time, state, *args)`` returns a new array shaped like ``state``; ``args`` is a
    tuple. Returns the new state (a new array).
    """
    half = 0.5 * step
    k1 = rhs(time, state, *args)
    k2 = rhs(time + half, state + half * k1, *args)
    k3 = rhs(time + half, state + half * k2, *args)
    k4 = rhs(time + step, state + step * k3, *args)
    return state + step / 6.0 * (k1 + 2.0 * (k2 + k3) + k4)


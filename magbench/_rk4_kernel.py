r"""Compiled (numba) twin of :func:`magbench.integrate.rk4_step`: the same classical RK4
step, the same operations in the same order, for numba right-hand sides, in place.

The compiled simulation loops (the detumbling, passive, bench and normalised-rotor kernels
of :mod:`magbench.sim`) take their steps with it, so the library has one RK4 and this one
twin. Their right-hand sides are numba functions ``rates(time, x, out, *args)`` that write
ẋ into ``out`` (shaped like the state, members on the last, contiguous axis); each loops
over the members in straight-line scalar code.

In place, on stages the caller allocates once: a step that allocated its four rates and
three stage states (as :func:`~magbench.integrate.rk4_step` does in numpy) spent more on
numba's allocation and reference counting than on the arithmetic at one member (measured
on the passive kernel: 1.85 times the time of a hand-written step). The stages are formed
as :func:`~magbench.integrate.rk4_step` forms them (``x + (h/2)·k₁``, …,
``x + (h/6)·(k₁ + 2(k₂ + k₃) + k₄)``), elementwise and without fast-math, so the two steps
give the same numbers to the last bit; the tests hold them to it
(``tests/sim/test_integrate.py``).

Inlined into its callers (``inline="always"``, numba's IR inlining): a cached function that
passes a right-hand side to a function it calls holds that function's address as a dynamic
global, which numba cannot cache (measured: 5 s of compilation in every process). Inlined,
the right-hand side is the caller's own global, and the caller's cache entry holds the step.
"""

from numba import njit

__all__ = ["rk4_advance"]


@njit(error_model="numpy", inline="always")
def rk4_advance(rates, time, state, step, args, stages):
    r"""Advance ẋ = f(t, x, \*args) by one classical RK4 step, in place (the compiled twin of
    :func:`magbench.integrate.rk4_step`, which documents the method).

    ``state``: a C-contiguous array, replaced by the state a step later; ``stages``: C-contiguous
    scratch of shape (5,) + state.shape (the four rates and a stage state); ``rates(time, x,
    out, *args)`` writes f(t, x) into ``out``; ``args`` is a tuple.
    """
    k1, k2, k3, k4, tmp = stages[0], stages[1], stages[2], stages[3], stages[4]
    n = state.size
    x, f1, f2, f3, f4, y = (state.reshape(n), k1.reshape(n), k2.reshape(n), k3.reshape(n), k4.reshape(n),
                            tmp.reshape(n))
    half = 0.5 * step
    rates(time, state, k1, *args)
    for i in range(n):
        y[i] = x[i] + half * f1[i]
    rates(time + half, tmp, k2, *args)
    for i in range(n):
        y[i] = x[i] + half * f2[i]
    rates(time + half, tmp, k3, *args)
    for i in range(n):
        y[i] = x[i] + step * f3[i]
    rates(time + step, tmp, k4, *args)
    sixth = step / 6.0
    for i in range(n):
        x[i] = x[i] + sixth * (f1[i] + 2.0 * (f2[i] + f3[i]) + f4[i])

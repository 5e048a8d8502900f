"""The first crossing of a tolerance by a deviation that grows from zero at the centre, shared
by the uniform zones of :mod:`~magbench.fields.uniformity` and :mod:`~magbench.fields.systems`."""

import numpy as np
from scipy import optimize


def _crossing_after_scan(deviation, tol, grid, values, end, **brent):
    """Smallest s with deviation(s) = tol: the first scanned value above ``tol`` brackets it
    with the grid point before (or 0), then Brent's method (``brent``: its tolerances).

    ``values`` is the deviation on ``grid`` (increasing, in (0, end]); ``end`` when none of
    them is above ``tol``.
    """
    above = np.flatnonzero(values > tol)
    if above.size == 0:
        return end
    j = above[0]
    lo = grid[j - 1] if j > 0 else 0.0
    return optimize.brentq(lambda s: float(deviation(s)) - tol, lo, grid[j], **brent)

r"""The hardware family's array kernels: the hysteresis rod's state equation.

Unchecked, SI, broadcasting over members (the layout of :mod:`magbench.hardware`). The checked
functions of :mod:`~magbench.hardware.hysteresis` validate their inputs and call these; a
simulator that has validated the rod once (:func:`~magbench.hardware.limb_constants`) calls
them per step.
"""

import numpy as np

__all__ = ["hysteresis_slope"]


def hysteresis_slope(b, h, direction, hc, bs, k):
    """dB/dH of the Flatley–Henretty state equation; the checked form, which documents it, is
    :func:`magbench.hardware.hysteresis_slope` (there with the rate's sign as ``direction``)."""
    x = 0.5 * np.pi * b / bs
    h_from = np.tan(x) / k - direction * hc
    return 2.0 * bs / np.pi * k * np.cos(x) ** 2 * ((h - h_from) / (2.0 * hc)) ** 2

r"""Readings of the thesis's unit-less PID gains (thesis §4.1, Figs. 15–18): each a
constant factor that turns the printed gains into SI gains.

The thesis prints gains without units; these are the readings the book tests.
"""

import numpy as np

from .._validate import as_positive

__all__ = ["GAIN_READINGS", "gain_reading_scale"]


#: Readings of the thesis's unit-less gains, each a constant factor on all three gains
#: that converts them to the SI reading (A·m² per rad, per rad·s, per rad/s).
GAIN_READINGS = {
    "si": "gains in SI: m [A·m²], e [rad], t [s], B [T] (the literal reading)",
    "per-degree": "error in degrees: K_SI = K·180/π",
    "normalised": "output as a fraction of the coils' maximum moment: K_SI = K·m_max",
    "per-degree-normalised": "error in degrees and output normalised: K_SI = K·m_max·180/π",
    "field-in-gauss": "B0 entered in gauss (CGS, as eq. 5 suggests): K_SI = K·10⁴",
    "field-in-A/m": "B0 entered as H in A/m (eq. 5 read in SI): K_SI = K/μ0",
    "torque-output": "output is a torque [N·m], not a dipole: K_SI = K/B0",
}


def gain_reading_scale(reading, field, moment_limit):
    r"""Factor that turns the thesis's printed gains into SI gains under one reading.

    Parameters
    ----------
    reading : str
        A key of :data:`GAIN_READINGS` [-].
    field : float
        B0 [T], > 0 (the true field: used by the torque-output reading).
    moment_limit : float
        The coils' maximum moment [A·m²], > 0 (used by the normalised readings).

    Returns
    -------
    float
        s [-] with K_SI = s·K_printed for all three gains.

    Notes
    -----
    Not in the thesis: it never states the units of K_p, K_i, K_d (thesis §4.1). Every candidate reading is a constant factor, so
    :func:`critical_gain_scale` decides its stability at once.

    Examples
    --------
    >>> round(gain_reading_scale("per-degree", 3e-4, 0.4), 6)
    57.29578
    """
    from ..constants import MU_0

    b = float(as_positive("field", field, unit="T"))
    m = float(as_positive("moment_limit", moment_limit, unit="A·m²"))
    scales = {"si": 1.0, "per-degree": 180.0 / np.pi, "normalised": m,
              "per-degree-normalised": m * 180.0 / np.pi, "field-in-gauss": 1e4,
              "field-in-A/m": 1.0 / MU_0, "torque-output": 1.0 / b}
    if reading not in scales:
        raise ValueError(f"reading must be one of {', '.join(GAIN_READINGS)}, got {reading!r}")
    return scales[reading]

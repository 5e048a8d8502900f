"""Named converters between SI and the units the sources print (CGS, degrees).

Only the edges of the library use these: physics functions take and return SI.

Examples
--------
>>> round(float(oersted_to_ampere_per_meter(1.0)), 3)
79.577
>>> float(gauss_to_tesla(0.5))
5e-05
"""

import numpy as np

from .constants import MU_0

__all__ = [
    "oersted_to_ampere_per_meter",
    "ampere_per_meter_to_oersted",
    "gauss_to_tesla",
    "tesla_to_gauss",
    "tesla_to_oersted",
    "oersted_to_tesla",
    "emu_to_ampere_square_meter",
    "ampere_square_meter_to_emu",
]

# 1 Oe = 1000/(4 pi) A/m exactly (definition of the CGS-Gaussian oersted).
_A_PER_M_PER_OERSTED = 1000.0 / (4.0 * np.pi)


def oersted_to_ampere_per_meter(h_oe):
    """Field strength in oersted [Oe] to SI [A/m] (1 Oe = 1000/4π A/m)."""
    return np.asarray(h_oe, dtype=float) * _A_PER_M_PER_OERSTED


def ampere_per_meter_to_oersted(h):
    """Field strength in SI [A/m] to oersted [Oe]."""
    return np.asarray(h, dtype=float) / _A_PER_M_PER_OERSTED


def gauss_to_tesla(b_gauss):
    """Flux density in gauss [G] to tesla [T] (1 G = 1e-4 T)."""
    return np.asarray(b_gauss, dtype=float) * 1e-4


def tesla_to_gauss(b):
    """Flux density in tesla [T] to gauss [G]."""
    return np.asarray(b, dtype=float) * 1e4


def tesla_to_oersted(b):
    """Vacuum flux density [T] to the field strength it corresponds to, in oersted [Oe].

    In vacuum H = B/μ0, so 1 G of B corresponds to 1 Oe of H (the CGS identity the
    sources rely on when they quote the Earth's field in oersted).
    """
    return ampere_per_meter_to_oersted(np.asarray(b, dtype=float) / MU_0)


def oersted_to_tesla(h_oe):
    """Field strength in oersted [Oe] to the vacuum flux density μ0·H [T]."""
    return MU_0 * oersted_to_ampere_per_meter(h_oe)


def emu_to_ampere_square_meter(moment_emu):
    """Magnetic moment in CGS units (G·cm³ = emu) to SI [A·m²] (1 emu = 1e-3 A·m²).

    Kovalenko (1975), p. 22, lists the equivalences "Гс·см³ = ед. СГСМ = 10⁻³ А·м²".
    """
    return np.asarray(moment_emu, dtype=float) * 1e-3


def ampere_square_meter_to_emu(moment):
    """Magnetic moment in SI [A·m²] to CGS units [G·cm³ = emu]."""
    return np.asarray(moment, dtype=float) * 1e3

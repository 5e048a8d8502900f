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

#: One degree in radians, π/180 [rad]: the one factor for the degrees the sources and the
#: figures print.
DEG = np.pi / 180.0

__all__ = [
    "DEG",
    "SI_FACTORS",
    "SI_UNIT_NAMES",
    "oersted_to_ampere_per_meter",
    "ampere_per_meter_to_oersted",
    "gauss_to_tesla",
    "tesla_to_gauss",
    "tesla_to_oersted",
    "oersted_to_tesla",
    "emu_to_ampere_square_meter",
    "ampere_square_meter_to_emu",
]


#: SI value of one unit as the sources print it (the data files' ``unit`` column).
SI_FACTORS = {
    "1": 1.0, "A": 1.0, "V": 1.0, "W": 1.0, "s": 1.0, "m": 1.0, "ohm": 1.0, "A/m": 1.0,
    "T": 1.0, "kg": 1.0, "kg m^2": 1.0, "kg/m^3": 1.0, "ohm m": 1.0, "A m^2": 1.0,
    "rad": 1.0, "rad/s": 1.0, "year": 1.0, "N m/rad": 1.0, "m^2": 1.0, "W/V": 1.0, "kg V": 1.0,
    "ohm kg/m^2": 1.0, "A/m^2": 1.0, "N m": 1.0, "N m/kg": 1.0, "kg/(N m)": 1.0,
    "m^3": 1.0, "kg m^2/s": 1.0, "J/m^3": 1.0, "A m^2 s/T": 1.0,
    "N m s/rad": 1.0, "N cm": 1e-2, "N cm s/rad": 1e-2,   # damping torques (Kovalenko 1975, p. 16)
    "S/m": 1.0, "1/s": 1.0, "A m^2/T": 1.0, "m^3/s^2": 1.0,
    "mm": 1e-3, "km": 1e3, "cm": 1e-2, "cm^3": 1e-6,
    "deg": np.pi / 180.0, "deg/s": np.pi / 180.0,
    "%": 1e-2,
    "emu": 1e-3,            # G·cm³ (Kovalenko 1975, p. 22)
    "Oe": 1000.0 / (4.0 * np.pi),
    "nT": 1e-9, "uT": 1e-6, "G": 1e-4,
    "rpm": np.pi / 30.0,   # revolutions per minute (rotor slides, seed line 101)
    "G Oe": 1e-4 * 1000.0 / (4.0 * np.pi),   # loop energy ∮H dB (Kovalenko 1975, p. 229)
}

#: The SI unit of each printed unit that is not SI itself.
SI_UNIT_NAMES = {"cm^3": "m^3", "mm": "m", "km": "m", "cm": "m", "deg": "rad", "deg/s": "rad/s", "%": "1",
            "emu": "A m^2", "Oe": "A/m", "nT": "T", "uT": "T", "G": "T", "rpm": "rad/s", "G Oe": "J/m^3",
            "N cm": "N m", "N cm s/rad": "N m s/rad"}

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

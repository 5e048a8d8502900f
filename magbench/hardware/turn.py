"""Turns and wires: the area and length of a round or square turn, wire cross-sections,
and the wire sizes a coil may be wound from.

Thesis §3.1 (eq. 19: the turn's length and the wire's cross-section) and the AWG and
IEC 60317 wire series (not in the sources). A turn has the characteristic size ``side``
= l: the diameter of a round turn (``shape="round"``, area πl²/4, length πl) or the side
of a square turn (``shape="square"``, area l², length 4l). SI throughout.
"""

from dataclasses import dataclass

import numpy as np

from .._validate import as_finite, as_nonnegative, as_positive, shown
from ._parameters import document_coil

__all__ = ["SHAPES", "Turn", "WireSizes", "turn_area", "turn_length", "wire_area", "wire_diameter", "awg_diameter"]


#: The turn shapes understood by the ``shape`` keyword.
SHAPES = ("round", "square")


def _check_shape(shape):
    if not isinstance(shape, str) or shape not in SHAPES:
        raise ValueError(f"shape must be one of {SHAPES}, got {shape!r}")
    return shape


def _area_factor(shape):
    """S / l²: π/4 for a round turn, 1 for a square one."""
    return np.pi / 4.0 if _check_shape(shape) == "round" else 1.0


def _length_factor(shape):
    """Turn length / l: π for a round turn, 4 for a square one."""
    return np.pi if _check_shape(shape) == "round" else 4.0


@dataclass(frozen=True)
class Turn:
    """The geometry of one turn of a winding, for every coil in the book.

    ``side`` is the thesis's characteristic size l: the diameter of a round turn or the
    side of a square one [m]. Build one with :meth:`round` (from the radius, as the
    simulator coils are given) or :meth:`square`; the winding functions
    (:func:`magbench.hardware.winding_resistance`, …) take it for simulator coils and
    magnetorquers alike.

    Thesis eq. (19) and eqs. (28)–(31).
    """

    shape: str
    side: float

    def __post_init__(self):
        _check_shape(self.shape)
        object.__setattr__(self, "side", as_positive("side", self.side, unit="m"))

    @classmethod
    def round(cls, radius):
        """A round turn of ``radius`` [m] (the coil radius a_c of thesis §2.2)."""
        return cls("round", 2.0 * as_positive("radius", radius, unit="m"))

    @classmethod
    def square(cls, side):
        """A square turn of ``side`` [m] (the magnetorquer's l of thesis §3.2)."""
        return cls("square", side)

    @property
    def area(self):
        """Enclosed area [m²]."""
        return turn_area(self.side, self.shape)

    @property
    def length(self):
        """Length of one turn [m]."""
        return turn_length(self.side, self.shape)


@dataclass(frozen=True)
class WireSizes:
    """The wire sizes a coil may be wound from: one conductor and enamel, several diameters.

    What the magnetorquer design solver (:func:`magbench.hardware.design_magnetorquer`)
    enumerates. The fields are checked and stored as plain floats (``diameters`` and
    ``overall_diameters`` as tuples, in the order given), so a bad table is refused where
    it is built, naming the field, the value and the range.

    Thesis §3.2 (the wire of eq. 21, bought in a standard size); not in the thesis: the
    enamel and the overall diameter (IEC 60317-0-1).

    Parameters
    ----------
    diameters : array_like, shape (k,)
        Bare conductor diameters available d [m], > 0; a size may repeat only when
        ``overall_diameters`` is not given.
    resistivity : float
        Conductor resistivity ρ [Ω·m], > 0.
    density : float
        Conductor density ρ̃ [kg/m³], > 0.
    enamel_thickness : float, optional
        Radial thickness of the enamel t [m], >= 0; the wire pitch is d + 2t. Used only for
        the winding-fit check, and only without ``overall_diameters``. The default 10 µm is
        an order of magnitude, not a standard value: 0.100 mm grade-1 enamelled wire
        measures 0.108–0.117 mm overall (4–8.5 µm radial; Elektrisola data quoted at
        enameled-wires.com, Technical-Documentation/341), thicker wires carry somewhat
        more. Take the value from the wire's datasheet.
    overall_diameters : array_like, shape (k,), optional
        Overall (enamelled) diameter of each wire of ``diameters`` [m], e.g. the maximum
        overall diameter of a wire standard's table; when given it is the winding pitch and
        ``enamel_thickness`` is not used. Each must exceed its bare diameter.

    Examples
    --------
    >>> wire = WireSizes([0.2e-3, 0.18e-3], 0.0175e-6, 8.9e3)
    >>> [round(float(p) * 1e3, 3) for p in wire.pitch]
    [0.22, 0.2]
    """

    diameters: tuple
    resistivity: float
    density: float
    enamel_thickness: float = 10e-6
    overall_diameters: tuple | None = None

    def __post_init__(self):
        # The messages name the solver's parameters as they were before the wire became one
        # argument (wire_diameters, ...): tests and the command line's flags match them.
        d = np.atleast_1d(as_positive("wire_diameters", self.diameters, unit="m"))
        if d.ndim != 1 or d.size == 0:
            raise ValueError(
                f"wire_diameters must be a non-empty 1-D array, got shape {d.shape}"
            )
        od = None
        if self.overall_diameters is None:
            as_nonnegative("enamel_thickness", self.enamel_thickness, unit="m")
        else:
            od = np.atleast_1d(as_positive("overall_diameters", self.overall_diameters, unit="m"))
            if od.shape != d.shape:
                raise ValueError(f"overall_diameters must have the shape of wire_diameters {d.shape}, "
                                 f"got {od.shape}")
            if np.any(od <= d):
                k = int(np.argmax(od <= d))
                raise ValueError(f"overall_diameters must exceed the bare diameters, got {shown(od[k])} m "
                                 f"for wire_diameters {shown(d[k])} m")
            # a repeated size with two overall diameters would be two pitches for one wire
            if np.unique(d).size != d.size:
                raise ValueError("wire_diameters must not repeat a size when overall_diameters are given")
            od = tuple(od.tolist())
        rho = float(as_positive("resistivity", self.resistivity, unit="Ω·m"))
        gamma = float(as_positive("density", self.density, unit="kg/m³"))
        # checked even when overall_diameters make it unused: a negative enamel is a typo
        t = float(as_nonnegative("enamel_thickness", self.enamel_thickness, unit="m"))
        for name, value in (("diameters", tuple(d.tolist())), ("overall_diameters", od),
                            ("resistivity", rho), ("density", gamma), ("enamel_thickness", t)):
            object.__setattr__(self, name, value)

    @property
    def pitch(self):
        """Winding pitch of each size, in the order of ``diameters`` [m]: its overall
        diameter when given, else d + 2t."""
        if self.overall_diameters is not None:
            return np.array(self.overall_diameters)
        return np.array(self.diameters) + 2.0 * self.enamel_thickness


@document_coil
def turn_area(side, shape="round"):
    r"""Area enclosed by one turn.

    Parameters
    ----------
    {side, shape}

    Returns
    -------
    ndarray
        S = πl²/4 (round) or l² (square) [m²].

    Notes
    -----
    Thesis eq. (19) ("S = πl²/4"); the square area l² is implied by eqs. (28)–(31).

    Examples
    --------
    >>> float(turn_area(0.1, "square"))
    0.010000000000000002
    """
    k = _area_factor(shape)
    return k * as_positive("side", side, unit="m") ** 2


@document_coil
def turn_length(side, shape="round"):
    r"""Length of conductor in one turn.

    Parameters
    ----------
    {side, shape}

    Returns
    -------
    ndarray
        πl (round) or 4l (square) [m].

    Notes
    -----
    Thesis eq. (19) (πl) and eq. (31) (4l).

    Examples
    --------
    >>> round(float(turn_length(0.1, "round")), 4)
    0.3142
    """
    k = _length_factor(shape)
    return k * as_positive("side", side, unit="m")


def wire_area(diameter):
    r"""Conductor cross-section of a round wire.

    Parameters
    ----------
    diameter : array_like
        Bare conductor diameter d [m].

    Returns
    -------
    ndarray
        S_r = πd²/4 [m²].

    Notes
    -----
    Thesis §3.2 (S_r "corresponds to d = 0.172 mm") and §3.3.

    Examples
    --------
    >>> round(float(wire_area(0.2e-3)) * 1e8, 4)
    3.1416
    """
    d = as_positive("diameter", diameter, unit="m")
    return np.pi * d**2 / 4.0


def wire_diameter(area):
    r"""Bare diameter of a round wire of a given conductor cross-section.

    Parameters
    ----------
    area : array_like
        Conductor cross-section S_r [m²].

    Returns
    -------
    ndarray
        d = √(4 S_r/π) [m].

    Notes
    -----
    Thesis §3.2: S_r "corresponds to d = 0.172 mm". The d = 0.172 mm follows
    from the exact S_r = 2.333·10⁻⁸ m² of eq. (21); the printed S_r = 2.34·10⁻⁸ m² is rounded
    up and would give 0.173 mm.

    Examples
    --------
    >>> round(float(wire_diameter(2.34e-8)) * 1e3, 3)
    0.173
    >>> round(float(wire_diameter(4 * 0.0175e-6 * 0.4 / 1.2)) * 1e3, 3)
    0.172
    """
    s = as_positive("area", area, unit="m²")
    return np.sqrt(4.0 * s / np.pi)


def awg_diameter(gauge):
    r"""Bare diameter of an American Wire Gauge size.

    Parameters
    ----------
    gauge : array_like
        AWG number n [-]; 0000, 000, 00 and 0 are −3, −2, −1 and 0. At least −3.

    Returns
    -------
    ndarray
        d = 0.127 mm × 92^((36 − n)/39) [m], exact by the gauge's definition (36 AWG is
        0.005 in and 0000 AWG is 0.46 in, with 38 geometric steps between them).

    Notes
    -----
    Not in the thesis: ASTM B258, the definition of the American Wire Gauge. The thesis's
    0.2 mm wire lies between 32 AWG (0.202 mm) and 33 AWG (0.180 mm).

    Examples
    --------
    >>> round(float(awg_diameter(36)) * 1e3, 4), round(float(awg_diameter(-3)) / 0.0254, 4)
    (0.127, 0.46)
    >>> round(float(awg_diameter(32)) * 1e3, 4)
    0.2019
    """
    n = as_finite("gauge", gauge)
    if np.any(n < -3):
        raise ValueError(f"gauge must be >= -3 (0000 AWG) [-], got {shown(n[n < -3].ravel()[0])}")
    return 0.127e-3 * 92.0 ** ((36.0 - n) / 39.0)

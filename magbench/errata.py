"""Places where a source disagrees with itself or with physics.

Each :class:`Erratum` keeps the value as printed, computes the value that the
source's own formula and inputs (or correct physics) give, and says why they differ.
The book's errata chapter renders :func:`errata`; ``tests/test_errata.py`` turns every
entry into a strict xfail test that asserts the printed value, so an entry that stops
disagreeing (a fix in the code, or a misreading of the source) fails the suite.
"""

from dataclasses import dataclass

import numpy as np

from . import attitude, geomag
from .constants import EARTH_POLAR_MOMENT_OF_INERTIA, EARTH_ROTATION_RATE, MU_0
from .data import load_measurements
from .params import chapter_parameters

__all__ = ["Erratum", "ERRATA_PROVIDERS", "errata", "geomagnetic_errata"]


@dataclass(frozen=True)
class Erratum:
    """A printed value beside the value computed from the source's own inputs."""

    id: str
    chapter: str
    source: str
    location: str
    quantity: str
    printed: float
    computed: float
    tolerance: float
    unit: str
    explanation: str
    computation: str

    @property
    def relative_difference(self):
        """(printed − computed) / |computed| [-]."""
        return (self.printed - self.computed) / abs(self.computed)

    @property
    def agrees(self):
        """Whether the printed value lies within ``tolerance`` of the computed one."""
        return abs(self.printed - self.computed) <= self.tolerance


def geomagnetic_errata(params=None):
    """Chapter 1's errata: thesis §1 and Kovalenko ch. 2."""
    p = params or chapter_parameters("ch01")
    kov = load_measurements("kovalenko")
    oe = 1000.0 / (4.0 * np.pi)      # A/m per Oe
    m, r = p["earth_dipole_moment"], p["earth_radius"]
    lat, lon = p["laboratory_latitude"], p["laboratory_longitude"]
    phi = geomag.geomagnetic_latitude(lat, lon, p["geomagnetic_pole_latitude"],
                                      p["geomagnetic_pole_longitude"])
    printed_j = float(np.arctan(-2.0 * np.tan(phi)))     # thesis eq. (3) as printed
    pole_h = float(geomag.dipole_total_b(np.pi / 2, m, r)) / MU_0 / oe

    g10, g11, h11 = (kov[k].value for k in ("kov-g10-1965", "kov-g11-1965", "kov-h11-1965"))
    b0_1965 = float(np.sqrt(g10**2 + g11**2 + h11**2))
    mean_dipole = float(geomag.dipole_mean_surface_b(b0_1965)) / MU_0 / oe

    jc, wc = p["mockup_inertia"], p["mockup_initial_rate"]
    exact = abs(float(attitude.momentum_exchange_energy_ratio(
        jc, wc, -wc, EARTH_POLAR_MOMENT_OF_INERTIA, EARTH_ROTATION_RATE)))
    thesis_ratio = float(attitude.thesis_energy_ratio(jc, EARTH_POLAR_MOMENT_OF_INERTIA))

    moment_l, field_h = 0.4, 250.0      # thesis design values (seed lines 240, 398)
    return [
        Erratum(
            id="thesis-eq3-inclination-sign", chapter="ch01", source="thesis",
            location="eqs. (1), (3); seed lines 108, 116 (from Kovalenko eq. 2.3)",
            quantity="Inclination J at the laboratory (St Petersburg) from eq. (3)",
            printed=float(np.degrees(printed_j)),
            computed=float(np.degrees(geomag.dipole_inclination(phi))),
            tolerance=0.05, unit="deg",
            explanation=("Printed tan J = −2 tan Φ (and Z = −2M cos θ_M/R³) makes the field point "
                         "upwards in the northern hemisphere, against the thesis's own axes "
                         "(z down, J > 0 in the north). The magnitudes are right; the sign is not. "
                         "IGRF gives +73.6° at the laboratory."),
            computation="magbench.geomag.dipole_inclination",
        ),
        Erratum(
            id="thesis-pole-field-rounding", chapter="ch01", source="thesis",
            location="§1.1, seed line 118 (copied from Kovalenko p. 35)",
            quantity="Dipole field at the poles, 2M/R³",
            printed=0.62, computed=pole_h, tolerance=0.005, unit="Oe",
            explanation=("2M/R³ with M = 8.1·10²⁵ CGS and R = 6371 km is 0.6265 Oe, which rounds "
                         "to 0.63; the printed 0.62 is twice the rounded equatorial 0.31."),
            computation="magbench.geomag.dipole_total_b",
        ),
        Erratum(
            id="thesis-eq5-cgs-torque", chapter="ch01", source="thesis",
            location="eq. (5), seed line 136",
            quantity="Torque on L = 0.4 A·m² across H = 250 A/m from M = L × H",
            printed=moment_l * field_h,
            computed=float(np.linalg.norm(geomag.magnetic_torque_from_h(
                [moment_l, 0.0, 0.0], [0.0, field_h, 0.0]))),
            tolerance=0.0, unit="N m",
            explanation=("M = L × H holds only in CGS units, where B = H in vacuum. In SI the "
                         "torque is μ0 L × H; read literally with SI inputs, eq. (5) is off by "
                         "a factor 1/μ0 ≈ 8·10⁵."),
            computation="magbench.geomag.magnetic_torque_from_h",
        ),
        Erratum(
            id="thesis-eq12a-energy-ratio", chapter="ch01", source="thesis",
            location="§1.3, seed line 196",
            quantity="Energy handed to the Earth per unit lost by a despinning mock-up, ΔT_E/ΔT_c",
            printed=thesis_ratio, computed=exact, tolerance=0.0, unit="1",
            explanation=("The thesis sets ΔT_E/ΔT_c = |Δω_E/Δω_c| = J_c/J_E by treating Δ(ω²) as "
                         "(Δω)². Because the Earth already rotates, ΔT_E ≈ ω_E ΔK_E, and the exact "
                         "ratio is ≈ ω_E/ω̄_c: some 37 orders of magnitude larger than J_c/J_E, yet "
                         "still ≪ 1, so the conclusion (the Earth takes momentum, not energy) holds."),
            computation="magbench.attitude.momentum_exchange_energy_ratio",
        ),
        Erratum(
            id="kovalenko-mean-dipole-field", chapter="ch01", source="kovalenko",
            location="§2.2, p. 40 (seed line 41)",
            quantity="Mean dipole field over the Earth's surface, from the book's own Table 1",
            printed=kov["kov-mean-field-dipole"].value / oe, computed=mean_dipole,
            tolerance=0.00005, unit="Oe",
            explanation=("The closed-form surface mean of the dipole field with Table 1's g10, g11, "
                         "h11 (−30339, −2123, 5758 γ) is 0.4272 Oe; the book prints 0.4283."),
            computation="magbench.geomag.dipole_mean_surface_b",
        ),
    ]


#: Errata providers by chapter, in book order.
ERRATA_PROVIDERS = {"ch01": geomagnetic_errata}


def errata():
    """Every erratum of the project, in chapter order."""
    entries = []
    for provider in ERRATA_PROVIDERS.values():
        entries.extend(provider())
    return entries

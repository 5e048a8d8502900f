"""Chapter 1 (the Earth's field): the thesis's and Kovalenko's printed field values.

The chapter's physics is tested with its families (tests/test_geomag.py,
tests/test_igrf.py) and its rows in tests/test_compare.py; here: which printed numbers
reproduce.
"""

from numpy.testing import assert_allclose

from magbench.chapters import errata


# ------------------------------------------------------------ printed values (errata)

CHAPTER_KEY = "ch01"

#: The printed values of this chapter's sources that do not reproduce, written here
#: independently of the library: a change that makes one suddenly reproduce (or another
#: stop reproducing) fails. Each is a strict xfail asserting the printed value.
EXPECTED_ERRATA = {
    "thesis-eq3-inclination-sign": "printed tan J = −2 tan Φ gives J < 0 in the north",
    "thesis-pole-field-rounding": "2M/R³ = 0.6265 Oe rounds to 0.63, not 0.62",
    "thesis-eq5-cgs-torque": "M = L × H lacks μ0 in SI",
    "thesis-eq12a-energy-ratio": "ΔT_E/ΔT_c ≈ ω_E/ω_c, not J_c/J_E",
    "kovalenko-mean-dipole-field": "Table 1's dipole gives 0.4272 Oe, printed 0.4283",
    "kovalenko-rms-field-R1000": "Table 2 at R+1000 km below the 1965 spectrum",
    "kovalenko-rms-dipole-R1000": "Table 2 at R+1000 km below the 1965 spectrum",
    "kovalenko-rms-field-1.5R": "Table 2 at 1.5R below the 1965 spectrum",
    "kovalenko-rms-dipole-1.5R": "Table 2 at 1.5R below the 1965 spectrum",
}


def test_printed_value(printed_check):
    # Tolerance: half a unit of the source's last printed digit (printed_check.tolerance).
    assert_allclose(printed_check.printed, printed_check.computed, rtol=0, atol=printed_check.tolerance)


def test_errata_match_expectation():
    assert {e.id for e in errata(CHAPTER_KEY)} == set(EXPECTED_ERRATA)

"""Every chapter re-run with each of its inputs halved and doubled (its comparison rows
and the computation and drawing of its figures; see ``input_sweep``).

A physically plausible input (a doubled coil current, a 24 V supply, a 5 cm coil, a
0.04 s controller) must give a chapter that says what follows ("no design fits", "this
hypothesis is excluded"), not a traceback. A value outside the quantity's domain (a
latitude of 120°, the year 4032, a filter coefficient above 1) must be refused with a
``ValueError`` that says which range it left: those cases are listed in
:data:`OUT_OF_DOMAIN` with the reason, and nothing else may raise.

Chapters 1–3 run in the default suite (about half a minute). Chapters 4–8 re-run long
simulations (bench Monte Carlo, detumbling studies, rotor and TNS-0 runs), so they carry
the ``sweep`` marker, which the default suite deselects; ``make sweep`` runs every
chapter on both cores, and CI runs it after ``make test``. A case computes only what
reads its input (each study is keyed on the inputs it declares; the rest comes from the
result cache): most cases take seconds; one that reaches TNS-0's 37-day run (one member,
10⁸ compiled RK4 steps) half a minute to two minutes, and those runs are most of the sweep.
The whole sweep took 17 min 44 s on the 2-core machine (2026-11-28; 25 min with chapter 6's
rotor runs in solve_ivp's DOP853, 38 min before the compiled bench and detumbling loops).
"""

import pytest

from magbench import chapters

from tests.chapters.input_sweep import run_scaled

FACTORS = (0.5, 2.0)

#: (chapter, input, factor): why the scaled value is outside the quantity's domain.
OUT_OF_DOMAIN = {
    ("ch01", "geomagnetic_pole_latitude", 2.0): "157° is not a latitude",
    ("ch01", "laboratory_latitude", 2.0): "120° is not a latitude",
    ("ch01", "thesis_epoch", 0.5): "the year 1008 is outside IGRF-14 (1900–2030)",
    ("ch01", "thesis_epoch", 2.0): "the year 4032 is outside IGRF-14 (1900–2030)",
    ("ch02", "laboratory_latitude", 2.0): "120° is not a latitude",
    ("ch02", "thesis_epoch", 0.5): "the year 1008 is outside IGRF-14 (1900–2030)",
    ("ch02", "thesis_epoch", 2.0): "the year 4032 is outside IGRF-14 (1900–2030)",
    ("ch03", "core_averaging_factor", 2.0): "an averaging factor (mean over peak magnetisation) is at most 1",
    ("ch03", "permalloy_design_magnetization", 2.0): "2.2e6 A/m is above permalloy's saturation a = 1.25e6 A/m",
    ("ch03", "permalloy_a", 0.5): "a saturation of 6.25e5 A/m is below the design magnetisation 1.1e6 A/m",
    ("ch04", "filter_coefficient_low", 2.0): "a complementary-filter coefficient lies in [0, 1]",
    ("ch04", "filter_coefficient_high", 2.0): "a complementary-filter coefficient lies in [0, 1]",
    ("ch04", "bench_filter_coefficient", 2.0): "a complementary-filter coefficient lies in [0, 1]",
    ("ch05", "orbit_inclination", 2.0): "twice SamSat-218D's 97.3° is not an inclination (0–180°)",
    # Counts are refused with a fraction, not truncated (the caption would show the fraction).
    ("ch04", "bench_pwm_levels", 0.5): "127.5 PWM levels is not a count",
    ("ch05", "envelope_seed", 0.5): "278.5 is not a seed",
    ("ch07", "capture_seed", 0.5): "1002.5 is not a seed",
}

FAST = ("ch01", "ch02", "ch03")


def _cases():
    # The chapters with the longest cases first: the two workers then end on short cases
    # together, instead of one waiting out a TNS-0 full run started last.
    for spec in sorted(chapters.CHAPTERS, key=lambda spec: spec.key, reverse=True):
        marks = () if spec.key in FAST else (pytest.mark.slow, pytest.mark.sweep)
        for name in spec.inputs:
            for factor in FACTORS:
                yield pytest.param(spec.key, name, factor, id=f"{spec.key}-{name}-x{factor:g}", marks=marks)


def test_out_of_domain_cases_are_inputs():
    # The list above names real inputs (a renamed input would silently drop its case).
    for key, name, factor in OUT_OF_DOMAIN:
        assert name in chapters.chapter(key).inputs and factor in FACTORS


@pytest.mark.parametrize("key, name, factor", list(_cases()))
def test_chapter_runs_with_an_input_scaled(key, name, factor):
    reason = OUT_OF_DOMAIN.get((key, name, factor))
    if reason is None:
        run_scaled(key, name, factor)
        return
    with pytest.raises(ValueError, match=r"must (lie|be)|within") as exc:
        run_scaled(key, name, factor)
    assert "Traceback" not in str(exc.value), reason

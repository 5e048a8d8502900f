r"""Attitude estimation from inertial sensors.

Thesis §4.2, eq. (39): the complementary filter that blends the integrated gyro rate
with an absolute angle from another sensor (:mod:`.complementary`). Further estimators
build on it: 3-D tilt from gyro and accelerometer (:mod:`.tilt`), tilt of a whole logged
record (:mod:`.offline`), heading from the magnetometer (:mod:`.heading`), two-vector
attitude on orbit (:mod:`.triad`, SamSat-218D), linear vs exponential decay fits (:mod:`.decay_fit`, TNS-0 Fig. 14), and the Euler-case fit of
sun-sensor sessions (:mod:`.euler_session`, TNS-0 §2).
Re-exports the public functions of its modules.
"""

from .decay_fit import DecayFit, corrected_aic, fit_exponential_decay, fit_linear_decay
from .complementary import (complementary_error_terms, complementary_filter, complementary_filter_step,
                            complementary_time_constant, gyro_offset_error)
from .euler_session import (SESSION_CONSTANTS, euler_case_sun_signals, fit_frequency_first, fit_multistart,
                            fit_nested_grid, fold_start_time, mirror_solution, momentum_bound,
                            session_identifiability, session_recovered, session_rms, synthetic_session)
from .heading import magnetometer_heading
from .triad import (magnitude_consistent, samsat_triad_frame, triad_attitude, triad_covariance,
                    vectors_well_separated)
from .tilt import accelerometer_tilt, complementary_tilt, rest_gyro_bias, strapdown_orientation
from .offline import offline_tilt, two_sided_rest

__all__ = [
    "complementary_filter", "complementary_filter_step", "complementary_time_constant", "gyro_offset_error",
    "complementary_error_terms",
    "accelerometer_tilt", "strapdown_orientation", "rest_gyro_bias", "complementary_tilt",
    "offline_tilt", "two_sided_rest",
    "magnetometer_heading", "triad_attitude", "samsat_triad_frame", "triad_covariance",
    "magnitude_consistent", "vectors_well_separated", "DecayFit", "fit_linear_decay", "fit_exponential_decay",
    "corrected_aic", "SESSION_CONSTANTS", "euler_case_sun_signals", "fold_start_time", "synthetic_session",
    "session_rms", "momentum_bound", "fit_nested_grid", "fit_multistart", "fit_frequency_first", "mirror_solution",
    "session_recovered", "session_identifiability",
]

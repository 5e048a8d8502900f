r"""Attitude estimation from inertial sensors.

Thesis §4.2, eq. (39): the complementary filter that blends the integrated gyro rate
with an absolute angle from another sensor (:mod:`.complementary`). Further estimators
build on it: 3-D tilt from gyro and accelerometer (:mod:`.tilt`) and heading from the
magnetometer (:mod:`.heading`). Re-exports the public functions of its modules.
"""

from .complementary import complementary_filter, complementary_filter_step, complementary_time_constant
from .heading import magnetometer_heading
from .tilt import accelerometer_tilt, complementary_tilt, rest_gyro_bias, strapdown_orientation

__all__ = [
    "complementary_filter", "complementary_filter_step", "complementary_time_constant",
    "accelerometer_tilt", "strapdown_orientation", "rest_gyro_bias", "complementary_tilt",
    "magnetometer_heading",
]

"""Heading from a magnetometer in a level sensor frame.

Not in the sources beyond thesis §4.2 (the mock-up's HMC5883 gives the heading). SI.
"""

import numpy as np

from .._validate import as_vectors

__all__ = ["magnetometer_heading"]


def magnetometer_heading(b_sensor):
    r"""Heading of a level sensor from the horizontal components of the measured field.

    Parameters
    ----------
    b_sensor : array_like, shape (..., 3)
        Magnetic flux density in the sensor frame [T] (any unit works: only the direction
        of the horizontal part matters), with the sensor's z axis vertical.

    Returns
    -------
    ndarray, shape (...)
        Heading ψ [rad] in (−π, π]: the rotation of the sensor about the vertical,
        counter-clockwise seen from above, from the direction of the horizontal field,
        :math:`\psi = \operatorname{atan2}(-b_y, b_x)`. Apply ``np.unwrap`` along time
        before filtering.

    Notes
    -----
    Thesis §4.2 names the HMC5883 magnetometer on the bench but gives no
    formula; eq. (39) needs an absolute heading reference, which gravity cannot supply.
    A sensor turned by ψ about the vertical sees the horizontal
    field :math:`B_h` as :math:`(B_h\cos\psi, -B_h\sin\psi)`, the convention of the
    planar field used for eq. (36). A tilted sensor needs its tilt removed first.

    Examples
    --------
    >>> psi = np.radians([0.0, 30.0, -120.0])
    >>> b = np.stack([np.cos(psi), -np.sin(psi), np.full(3, 0.7)], axis=-1)
    >>> np.round(np.degrees(magnetometer_heading(b)), 9).tolist()
    [0.0, 30.0, -120.0]
    """
    field = as_vectors("b_sensor", b_sensor)
    horizontal = np.hypot(field[..., 0], field[..., 1])
    if np.any(horizontal == 0):
        raise ValueError("b_sensor must have a non-zero horizontal part (x, y) in every sample; "
                         "a vertical field defines no heading")
    return np.arctan2(-field[..., 1], field[..., 0]) + 0.0

r"""One sample of the bench's loop, pure: the sensors' errors drawn ahead
(:func:`draw_sensor_errors`) and the controller on the readings (:func:`controller_step`:
filter, PID, allocation and PWM), as the bench's Arduino ran them (thesis §4.1–4.2).
"""

import numpy as np

from ... import control, estimation
from ...hardware.driver import quantise_duty
from ...rotations import wrap_angle

__all__ = ["controller_step", "draw_sensor_errors"]


def draw_sensor_errors(setup, steps, members, rng):
    r"""Additive errors of the gyro (vertical axis) and magnetometer (two horizontal axes).

    Parameters
    ----------
    setup : BenchSetup
        The bench (noise levels; None picks the datasheet defaults) [-].
    steps : int
        Number of samples [-].
    members : int
        Number of Monte Carlo members [-].
    rng : numpy.random.Generator, list of them, or None
        Source of randomness [-]: one generator for all members, one per member (each
        member's errors then come from its own stream, whatever members run beside it), or
        None for ideal sensors (zero errors).

    Returns
    -------
    gyro : ndarray, shape (steps, members)
        Gyro error about the vertical [rad/s].
    magnetometer : ndarray, shape (steps, members, 2)
        Magnetometer errors along coil 1's and coil 2's axes [T].

    Notes
    -----
    Not in the thesis: the errors are what :func:`magbench.hardware.sensors.gyro_readings` and
    :func:`magbench.hardware.sensors.magnetometer_readings` add to a zero signal; since both models
    add errors independent of the signal, truth + these errors is exactly their reading.

    Examples
    --------
    >>> g, m = draw_sensor_errors(None, 3, 2, None)
    >>> g.shape, m.shape, float(abs(g).max() + abs(m).max())
    ((3, 2), (3, 2, 2), 0.0)
    """
    if rng is None:
        return np.zeros((steps, members)), np.zeros((steps, members, 2))
    from ...hardware import sensors

    dt = setup.sample_interval
    gkw = {} if setup.gyro_noise_density is None else {"noise_density": setup.gyro_noise_density}
    mkw = {} if setup.magnetometer_noise is None else {"noise_std": setup.magnetometer_noise}
    if isinstance(rng, (list, tuple)):
        pairs = [(sensors.gyro_readings(np.zeros(steps), dt, rng=g, bias=setup.gyro_bias, **gkw),
                  sensors.magnetometer_readings(np.zeros((steps, 2)), dt, rng=g, **mkw)) for g in rng]
        return np.stack([g for g, _ in pairs], axis=1), np.stack([m for _, m in pairs], axis=1)
    gyro = sensors.gyro_readings(np.zeros((steps, members)), dt, rng=rng, bias=setup.gyro_bias, **gkw)
    mag = sensors.magnetometer_readings(np.zeros((steps, members, 2)), dt, rng=rng, **mkw)
    return gyro, mag


def controller_step(setup, psi_des, gyro, bx, by, estimate, integral, full_1, full_2, *,
                    filter_coefficient=None, pwm_levels=None):
    r"""One sample of the bench's controller: filter, PID, allocation and PWM (pure).

    Parameters
    ----------
    setup : BenchSetup
        The bench: sample interval, filter coefficient, gains, moment limit, PWM levels
        and nominal full-scale moments [-].
    psi_des : float
        Target angle [rad].
    gyro : array_like
        Gyro reading [rad/s], per member.
    bx, by : array_like
        Magnetometer reading along coil 1 and coil 2 [T], per member.
    estimate : array_like or None
        The filter's angle before this sample [rad]; None at the first sample, where the
        filter starts from the magnetometer heading.
    integral : array_like
        The PID integral before this sample [rad·s].
    full_1, full_2 : array_like
        Each coil's actual full-scale moment [A·m²], per member.
    filter_coefficient : array_like, optional
        A of eq. (39) per member [-]; default ``setup.filter_coefficient``.
    pwm_levels : array_like, optional
        Duty steps each way per member [-], > 0; default ``setup.pwm_levels``.

    Returns
    -------
    moment_1, moment_2, estimate, integral : ndarray
        The coils' moments held until the next sample [A·m²], the filter's new angle
        [rad] and the new integral [rad·s].

    Notes
    -----
    Thesis §4.1–4.2: eq. (39) on the magnetometer heading (the reference unwrapped to
    within half a turn of the estimate), the PID of eqs. (37)–(38) on the wrapped error
    (the shorter way round, our choice), and the thesis's allocation with m_z = −u:
    M_x = u b_y, M_y = −u b_x (torque B₀u), each duty cycle quantised to the PWM levels.
    """
    heading = np.arctan2(-by, bx)
    if estimate is None:
        estimate = heading
    reference = estimate + wrap_angle(heading - estimate)
    alpha = setup.filter_coefficient if filter_coefficient is None else filter_coefficient
    estimate = estimation.complementary_filter_step(estimate, gyro, reference, setup.sample_interval, alpha)
    error = wrap_angle(psi_des - estimate)
    u, integral = control.pid_step(error, -gyro, integral, setup.sample_interval, setup.kp, setup.ki,
                                   setup.kd, setup.moment_limit)
    u_over_b = u / np.sqrt(bx * bx + by * by)
    duty_gain = 1.0 / setup.full_scale_moments
    levels = int(setup.pwm_levels) if pwm_levels is None else pwm_levels
    moment_1 = quantise_duty(u_over_b * by * duty_gain[0], levels) * full_1
    moment_2 = quantise_duty(u_over_b * bx * -duty_gain[1], levels) * full_2
    return moment_1, moment_2, estimate, integral

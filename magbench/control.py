r"""Feedback control of the mock-up: the PID law of thesis §4 and its discrete form.

Thesis eqs. (37)–(38). The controller output is the commanded dipole moment; the
coils' maximum moment saturates it, and the integral stops winding up while the output
is saturated.
"""

import numpy as np

__all__ = ["pid_step"]


def pid_step(error, error_rate, integral, dt, kp, ki, kd, output_limit=np.inf):
    r"""One step of the discrete PID with output saturation and anti-windup.

    Parameters
    ----------
    error : array_like
        Control error e = ψ_des − ψ at this step [rad].
    error_rate : array_like
        Its time derivative de/dt (from the gyro, not differenced) [rad/s].
    integral : array_like
        Integral of the error up to the previous step [rad·s].
    dt : array_like
        Controller sample interval [s].
    kp, ki, kd : array_like
        Proportional [A·m²/rad], integral [A·m²/(rad·s)] and derivative [A·m²·s/rad]
        gains, in the units of thesis eq. (37) read in SI.
    output_limit : array_like, optional
        Largest commanded moment magnitude [A·m²] (the coils' maximum); default: none.

    Returns
    -------
    output : ndarray
        Commanded moment :math:`\mathrm{sat}(K_p e + K_i \int e\,dt + K_d\,\dot e)` [A·m²].
    integral : ndarray
        The updated error integral [rad·s]. It is frozen (conditional integration) while
        the output is saturated and the error would drive it further into saturation.

    Notes
    -----
    Thesis eq. (37), seed lines 530–534, with rectangle-rule integration. The thesis does
    not state a sample time, derivative source or anti-windup (inventory gap G15); these
    choices are ours. No argument checks: the simulation that calls this checks its
    inputs once. Broadcasts over any shape (Monte Carlo members).

    Examples
    --------
    >>> u, i = pid_step(0.1, 0.0, 0.0, 0.01, kp=2.0, ki=1.0, kd=0.0, output_limit=0.4)
    >>> round(float(u), 6), round(float(i), 6)
    (0.201, 0.001)
    >>> u, i = pid_step(1.0, 0.0, 0.0, 0.01, kp=2.0, ki=1.0, kd=0.0, output_limit=0.4)
    >>> float(u), float(i)
    (0.4, 0.0)
    """
    candidate = integral + error * dt
    unsaturated = kp * error + ki * candidate + kd * error_rate
    output = np.clip(unsaturated, -output_limit, output_limit)
    winding_up = (output != unsaturated) & (np.sign(ki * error) == np.sign(unsaturated))
    return output, np.where(winding_up, integral, candidate)

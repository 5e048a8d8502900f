r"""The PID law of thesis §4.1, eqs. (37)–(38), as a pure step, and two ways to choose gains.

The controller output is the commanded dipole moment; the coils' maximum moment
saturates it, and the integral stops winding up while the output is saturated. SI.
"""

import numpy as np

from .._validate import as_positive, shown

__all__ = ["pid_step", "pid_gains_for_triple_pole", "ziegler_nichols_pid"]


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
    Thesis eq. (37), with rectangle-rule integration. The thesis does
    not state a sample time, derivative source or anti-windup; these
    choices are ours. The only argument check is the limit's sign (a negative one would
    invert the output); the simulation that calls this checks the rest once. Broadcasts
    over any shape (Monte Carlo members).

    Examples
    --------
    >>> u, i = pid_step(0.1, 0.0, 0.0, 0.01, kp=2.0, ki=1.0, kd=0.0, output_limit=0.4)
    >>> round(float(u), 6), round(float(i), 6)
    (0.201, 0.001)
    >>> u, i = pid_step(1.0, 0.0, 0.0, 0.01, kp=2.0, ki=1.0, kd=0.0, output_limit=0.4)
    >>> float(u), float(i)
    (0.4, 0.0)
    """
    # np.clip with a negative limit returns the limit's sign flipped: the output inverted.
    if np.any(np.less_equal(output_limit, 0.0)) or np.any(np.isnan(output_limit)):
        raise ValueError(f"output_limit must be > 0 (inf for none), got {shown(np.ravel(output_limit)[0])}")
    candidate = integral + error * dt
    unsaturated = kp * error + ki * candidate + kd * error_rate
    output = np.clip(unsaturated, -output_limit, output_limit)
    winding_up = (output != unsaturated) & (np.sign(ki * error) == np.sign(unsaturated))
    return output, np.where(winding_up, integral, candidate)


def pid_gains_for_triple_pole(inertia, field, bandwidth):
    r"""PID gains that put the linearised loop's three poles at s = −ω_b.

    Parameters
    ----------
    inertia : array_like
        Moment of inertia J about the vertical [kg·m²], > 0.
    field : array_like
        Field magnitude B0 [T], > 0.
    bandwidth : array_like
        The triple pole's magnitude ω_b [rad/s], > 0.

    Returns
    -------
    kp, ki, kd : ndarray
        Gains [A·m²/rad], [A·m²/(rad·s)], [A·m²·s/rad] in the SI reading of eq. (37).

    Notes
    -----
    Not in the thesis: a starting point for stable SI gains. Eqs. (35)–(37) linearised
    about ψ = ψ_des give the characteristic polynomial
    :math:`J s^3 + B_0 K_d s^2 + B_0 K_p s + B_0 K_i`; matching it to
    :math:`J (s + \omega_b)^3` gives
    :math:`K_d = 3 J \omega_b / B_0`, :math:`K_p = 3 J \omega_b^2 / B_0`,
    :math:`K_i = J \omega_b^3 / B_0`.

    Examples
    --------
    >>> kp, ki, kd = pid_gains_for_triple_pole(0.005, 1e-4, 0.1)
    >>> [round(float(k), 9) for k in (kp, ki, kd)]
    [1.5, 0.05, 15.0]
    """
    j = as_positive("inertia", inertia, unit="kg·m²")
    b = as_positive("field", field, unit="T")
    w = as_positive("bandwidth", bandwidth, unit="rad/s")
    return 3.0 * j * w**2 / b, j * w**3 / b, 3.0 * j * w / b


def ziegler_nichols_pid(ultimate_gain, ultimate_period):
    r"""Classic Ziegler–Nichols PID gains from the ultimate gain and period.

    Parameters
    ----------
    ultimate_gain : array_like
        K_u, the P gain at which the loop oscillates steadily [A·m²/rad], > 0.
    ultimate_period : array_like
        T_u, the period of that oscillation [s], > 0.

    Returns
    -------
    kp, ki, kd : ndarray
        :math:`K_p = 0.6K_u`, :math:`K_i = 1.2K_u/T_u`, :math:`K_d = 0.075K_uT_u`
        (T_i = T_u/2, T_d = T_u/8) in the units of K_u.

    Notes
    -----
    Not in the thesis's text: its reference [11], Ziegler and Nichols (1942), table of
    the "ultimate sensitivity" method. For the double-integrator plant of the mock-up
    every P gain is ultimate (:func:`double_integrator_ultimate_gain`).

    Examples
    --------
    >>> [round(float(k), 12) for k in ziegler_nichols_pid(1.0, 10.0)]
    [0.6, 0.12, 0.75]
    """
    ku = as_positive("ultimate_gain", ultimate_gain, unit="A·m²/rad")
    tu = as_positive("ultimate_period", ultimate_period, unit="s")
    return 0.6 * ku, 1.2 * ku / tu, 0.075 * ku * tu

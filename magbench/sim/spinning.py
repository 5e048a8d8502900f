r"""The spinning spacecraft with a coaxial rotor under magnetic control: the satellite, its
dimensionless numbers and the SI simulation (the normalised model is in
:mod:`magbench.sim.rotor_normalised`, the turning-field run in :mod:`magbench.sim.turning_field`;
both are served from here under their old names).

Rotor slides (seed lines 11–102) with ``shared/reference/rotor_spin.md`` §4–§8. Composes
the gyrostat of :mod:`magbench.dynamics.gyrostat`, the laws of
:mod:`magbench.control.spin`, the Floquet tools of :mod:`magbench.control.floquet`, the
orbit of :class:`magbench.earth.CircularOrbit` and the one fixed-step
:func:`magbench.integrate.rk4_step` (the normalised runs and the monodromy that checks the
linearisation); the linearisation itself, the Floquet multipliers and the stability map are
control analysis, in :mod:`magbench.control.rotor_stability`, and are served from here
under their old names. The SI
simulation is adaptive (DOP853 through :func:`magbench.integrate.solve_adaptive`, in its compiled
twin of :func:`scipy.integrate.solve_ivp`'s): the spin period is 1/2800 of the orbit and a fixed
step fine enough would cost more than the error control.

The SI right-hand side is written in scalar ``math`` operations and compiled
(:mod:`magbench.sim._rotor_kernel`): five orbits need about a million evaluations, the same
equations on small numpy arrays run twenty times slower (``rotor_spin.md`` §9 "Speed") and
in Python about ten; a test checks it against the numpy composition of
:func:`magbench.dynamics.gyrostat_rhs` and the laws, another against its own uncompiled source.

``omega`` (the body's angular-velocity vector of a run) is a name of the chapter-6
contract (``rotor_spin.md`` §15).
"""

import math
from dataclasses import dataclass

import numpy as np
from scipy.spatial.transform import Rotation

from .._validate import (as_choice, as_finite, as_in_range, as_inertia, as_positive_or_infinite,
                         as_positive_scalar, shown)
# the linearisation and its Floquet map moved to the control family; served from here as before
from ..control.rotor_stability import rotor_floquet_multipliers, rotor_linearised_matrices, rotor_stability_map
from ..dynamics.gyrostat import airplane_231_angles, airplane_231_matrix, rotor_dimensionless_numbers
from ..earth.circular_orbit import CircularOrbit
from ..earth.dipole import dipole_equatorial_b
from ..integrate import solve_adaptive
from .result import RotorRun
# the normalised model and the turning-field run have their own modules; served from here as before
from .rotor_normalised import rotor_finite_difference_monodromy, rotor_normalised_rhs, simulate_rotor_normalised
from .turning_field import simulate_turning_field_gyrostat

__all__ = ["RotorSatellite", "RotorRun", "rotor_dimensionless", "rotor_gain_scales",
           "rotor_satellite_from_dimensionless", "rotor_normalised_rhs", "rotor_linearised_matrices", "rotor_floquet_multipliers", "rotor_stability_map",
           "rotor_finite_difference_monodromy", "simulate_rotor_normalised", "rotor_body_rhs",
           "simulate_rotor", "simulate_turning_field_gyrostat"]

DAMPING = ("rate", "momentum")


@dataclass(frozen=True)
class RotorSatellite:
    r"""A spacecraft with a coaxial rotor along body axis 1 and its magnetic controller.

    Attributes
    ----------
    inertia : ndarray, shape (3,) or (3, 3)
        Principal moments or tensor of body + rotor (rotor counted as rigid), axis 1 = rotor
        axis [kg·m²].
    rotor_inertia : float
        J_f, the rotor's axial inertia [kg·m²].
    spin_rate : float
        s, the body's spin about axis 1 on the reference at u = 0 [rad/s].
    axial_momentum : float
        H0 = I11 s + J_f ν, total axial momentum at u = 0 [N·m·s].
    restoring_gain : float
        k of the equilibrium law [A·m²/T].
    damping_gain : float
        k_w of the projected damping [N·m·s].
    moment_limit : float
        Largest dipole per body axis [A·m²]; ``inf`` for none.

    Notes
    -----
    Rotor slides, slide "Problem statement" (seed lines 13–25: rotor along the symmetry
    axis, constant rotor speed, coils for damping and restoring torques); the rotor's rate
    relative to the body follows from H0 and s (``rotor_spin.md`` §1, §15).
    """

    inertia: np.ndarray
    rotor_inertia: float
    spin_rate: float
    axial_momentum: float
    restoring_gain: float
    damping_gain: float
    moment_limit: float = math.inf

    def __post_init__(self):
        j = as_inertia("inertia", self.inertia)
        if j.shape not in ((3,), (3, 3)):
            raise ValueError(f"inertia must have shape (3,) or (3, 3) [kg·m²], got shape {j.shape}")
        object.__setattr__(self, "inertia", j)
        jf = as_positive_scalar("rotor_inertia", self.rotor_inertia, unit="kg·m²")
        if jf >= self.inertia_matrix[0, 0]:
            raise ValueError(f"rotor_inertia must be < I11 = {shown(self.inertia_matrix[0, 0])} kg·m², got {shown(jf)}")
        object.__setattr__(self, "rotor_inertia", jf)
        for name in ("spin_rate", "axial_momentum"):
            value = as_finite(name, getattr(self, name))
            if value.ndim:
                raise ValueError(f"{name} must be a scalar, got shape {value.shape}")
            object.__setattr__(self, name, float(value))
        for name, unit in (("restoring_gain", "A·m²/T"), ("damping_gain", "N·m·s")):
            value = as_in_range(name, getattr(self, name), 0.0, math.inf, unit=unit)
            if value.ndim:
                raise ValueError(f"{name} must be a scalar [{unit}], got shape {value.shape}")
            object.__setattr__(self, name, float(value))
        limit = as_positive_or_infinite("moment_limit", self.moment_limit, unit="A·m²")
        object.__setattr__(self, "moment_limit", float(limit))

    @property
    def inertia_matrix(self):
        """The inertia tensor (3, 3) [kg·m²]."""
        return self.inertia if self.inertia.shape == (3, 3) else np.diag(self.inertia)

    @property
    def transverse_inertia(self):
        """B = (I22 + I33)/2 [kg·m²]."""
        j = self.inertia_matrix
        return 0.5 * float(j[1, 1] + j[2, 2])

    @property
    def rotor_rate(self):
        """ν = (H0 − I11 s)/J_f, the rotor's rate relative to the body [rad/s]."""
        return (self.axial_momentum - self.inertia_matrix[0, 0] * self.spin_rate) / self.rotor_inertia


def _check_orbit(orbit):
    if not isinstance(orbit, CircularOrbit):
        raise ValueError(f"orbit must be a CircularOrbit, got {type(orbit).__name__}")
    if np.ndim(orbit.argument_of_latitude0) != 0:
        raise ValueError("orbit.argument_of_latitude0 must be a scalar for one satellite")
    if abs(math.sin(orbit.inclination)) < 1e-12:
        raise ValueError(f"orbit.inclination must have sin i != 0 (the law divides by sin i), got {orbit.inclination!r}")


def _check_satellite(satellite):
    if not isinstance(satellite, RotorSatellite):
        raise ValueError(f"satellite must be a RotorSatellite, got {type(satellite).__name__}")


def rotor_dimensionless(satellite, orbit):
    r"""The five dimensionless numbers of a rotor spacecraft on its orbit.

    Parameters
    ----------
    satellite : RotorSatellite
        The spacecraft and its gains [SI].
    orbit : CircularOrbit
        The orbit; its direct dipole's equatorial field at the orbit radius is B0 [SI].

    Returns
    -------
    dict
        ``axial_ratio`` a = I11/B, ``momentum`` c1 = H0/(ω0 B), ``restoring``
        κ = k B0²/(ω0² B), ``damping`` κ_w = k_w/(ω0 B) [-], ``inclination`` i [rad].

    Notes
    -----
    Rotor slides, slide "Equations of motion" (seed lines 29–38) normalised as in
    ``rotor_spin.md`` §4 (B = (I22 + I33)/2 for an asymmetric body).
    """
    _check_satellite(satellite)
    _check_orbit(orbit)
    b0 = float(dipole_equatorial_b(orbit.earth_moment, orbit.radius))
    numbers = rotor_dimensionless_numbers(satellite.inertia_matrix[0, 0], satellite.transverse_inertia,
                                          satellite.axial_momentum, satellite.restoring_gain, satellite.damping_gain,
                                          orbit.mean_motion, b0)
    return {**numbers, "inclination": float(orbit.inclination)}


def rotor_gain_scales(satellite, orbit):
    r"""The SI gains per unit of their dimensionless numbers for a rotor spacecraft on its orbit.

    Parameters
    ----------
    satellite : RotorSatellite
        The spacecraft; only B = (I22 + I33)/2 counts [SI].
    orbit : CircularOrbit
        Gives ω0 and B0, the direct dipole's equatorial field at the orbit radius [SI].

    Returns
    -------
    restoring_scale : float
        k per κ, ω0² B/B0² [A·m²/T].
    damping_scale : float
        k_w per κ_w, ω0 B [N·m·s].

    Notes
    -----
    Rotor slides, slide "Equations of motion" (seed lines 29–38) normalised as in ``rotor_spin.md`` §4
    (the factors of :func:`rotor_satellite_from_dimensionless`).
    """
    _check_satellite(satellite)
    _check_orbit(orbit)
    b = satellite.transverse_inertia
    b0 = float(dipole_equatorial_b(orbit.earth_moment, orbit.radius))
    w0 = orbit.mean_motion
    return w0**2 * b / b0**2, w0 * b


def rotor_satellite_from_dimensionless(inertia, rotor_inertia, spin_rate, orbit, *, momentum, restoring, damping,
                                       moment_limit=math.inf):
    r"""A rotor spacecraft whose momentum and gains are given by their dimensionless numbers.

    Parameters
    ----------
    inertia : array_like, shape (3,) or (3, 3)
        Body + rotor inertia, axis 1 = rotor axis [kg·m²].
    rotor_inertia : float
        J_f [kg·m²].
    spin_rate : float
        s, body spin on the reference at u = 0 [rad/s].
    orbit : CircularOrbit
        Gives ω0 and B0 [SI].
    momentum : float
        c1 = H0/(ω0 B) [-].
    restoring : float
        κ = k B0²/(ω0² B) ≥ 0 [-].
    damping : float
        κ_w = k_w/(ω0 B) ≥ 0 [-].
    moment_limit : float, optional
        Largest dipole per body axis [A·m²].

    Returns
    -------
    RotorSatellite
        With H0 = c1 ω0 B, k = κ ω0² B/B0², k_w = κ_w ω0 B [SI].

    Notes
    -----
    Rotor slides, slide "Equations of motion" (seed lines 29–38) normalised as in ``rotor_spin.md`` §4 (the inverse of
    :func:`rotor_dimensionless`); B = (I22 + I33)/2.
    """
    _check_orbit(orbit)
    j = as_inertia("inertia", inertia)
    j = j if j.shape == (3, 3) else np.diag(j)
    b = 0.5 * float(j[1, 1] + j[2, 2])
    w0 = orbit.mean_motion
    b0 = float(dipole_equatorial_b(orbit.earth_moment, orbit.radius))
    c1 = float(as_finite("momentum", momentum))
    kappa = float(as_in_range("restoring", restoring, 0.0, math.inf))
    kappa_w = float(as_in_range("damping", damping, 0.0, math.inf))
    return RotorSatellite(inertia=inertia, rotor_inertia=rotor_inertia, spin_rate=spin_rate,
                          axial_momentum=c1 * w0 * b, restoring_gain=kappa * w0**2 * b / b0**2,
                          damping_gain=kappa_w * w0 * b, moment_limit=moment_limit)


def _body_constants(satellite, orbit, damping):
    """The constants vector of the compiled right-hand side (:mod:`magbench.sim._rotor_kernel`)."""
    from ._rotor_kernel import rotor_constants

    return rotor_constants(satellite.inertia_matrix, orbit, satellite.axial_momentum,
                           satellite.rotor_inertia * satellite.rotor_rate, satellite.transverse_inertia,
                           satellite.restoring_gain, satellite.damping_gain, satellite.moment_limit,
                           float(dipole_equatorial_b(orbit.earth_moment, orbit.radius)), damping == "momentum")


def rotor_body_rhs(time, state, satellite, orbit, *, damping="rate"):
    r"""Right-hand side of the SI closed loop: gyrostat, gravity gradient, real field, the slides' law.

    Parameters
    ----------
    time : float
        t [s]; u = u0 + ω0 t.
    state : array_like, shape (7,)
        Quaternion (scalar first, v_orbital = R(q) v_body) [-] and ω, body axes [rad/s].
    satellite : RotorSatellite
        Spacecraft and gains [SI].
    orbit : CircularOrbit
        Orbit and real field (any dipole tilt and rotation) [SI].
    damping : {"rate", "momentum"}, optional
        Damp the rate error (the slides) or the momentum error (Kovalenko) [-].

    Returns
    -------
    list of float
        (q̇, ω̇) [1/s, rad/s²]: :func:`magbench.dynamics.gyrostat_rhs` with the dipole of
        the slides' law (equilibrium part on the semi-body triad, damping on the real body
        field, clipped per axis).

    Notes
    -----
    Rotor slides, slides "Choice of control" and "Control implementation" (seed lines 63–87), with ``rotor_spin.md`` §8 (controller in body axes) and
    §3 (model). The compiled scalar kernel :func:`magbench.sim._rotor_kernel.rotor_rhs` that
    :func:`simulate_rotor` integrates.
    """
    _check_satellite(satellite)
    _check_orbit(orbit)
    x = as_finite("state", state)
    if x.shape != (7,):
        raise ValueError(f"state must have shape (7,), got shape {x.shape}")
    from ._rotor_kernel import rotor_rhs

    constants = _body_constants(satellite, orbit, as_choice("damping", damping, DAMPING))
    return rotor_rhs(float(as_finite("time", time)), np.ascontiguousarray(x, dtype=float), constants).tolist()


#: DOP853 runs in the compiled twin of solve_ivp's (:func:`magbench.integrate.solve_adaptive`);
#: "scipy" is the reference the tests hold it to.
_ADAPTIVE_ENGINE = "compiled"


def simulate_rotor(satellite, orbit, duration, *, initial_angles=(0.0, 0.0, 0.0), initial_rate_error=(0.0, 0.0, 0.0),
                   sample_interval=10.0, rtol=1e-8, atol=1e-10, damping="rate", method="DOP853"):
    r"""Simulate the rotor spacecraft from an initial pointing error (adaptive integration).

    Parameters
    ----------
    satellite : RotorSatellite
        Spacecraft and gains [SI].
    orbit : CircularOrbit
        Orbit and real field; the program field is the direct dipole at
        u = argument_of_latitude0 + n t [SI].
    duration : float
        Simulated time [s].
    initial_angles : tuple of float, optional
        (α0, β0, γ0) of the start, turned from the reference [rad].
    initial_rate_error : array_like, shape (3,), optional
        Added to the reference rate at the start, body axes [rad/s].
    sample_interval : float, optional
        Spacing of the samples from 0 to ``duration`` [s].
    rtol, atol : float, optional
        Tolerances of the adaptive solve [-]; rtol ≤ 1e-8 is needed (1e-6 halves the
        transient by numerical damping, ``rotor_spin.md`` §9).
    damping : {"rate", "momentum"}, optional
        Damp the rate error (the slides) or the momentum error (Kovalenko) [-].
    method : str, optional
        :func:`scipy.integrate.solve_ivp` method [-]; DOP853 (the default) runs in the
        compiled twin of scipy's (:func:`magbench.integrate.solve_adaptive`, equal to rounding:
        ``tests/sim/test_integrate.py``), any other in scipy.

    Returns
    -------
    RotorRun
        Samples of the run (``inputs`` holds the arguments and ``nfev``).

    Notes
    -----
    Rotor slides, slide "Simulation (asymmetric spacecraft)" (lost) (seed lines 94–96),
    with ``rotor_spin.md`` §8: start C0 = :func:`magbench.dynamics.airplane_231_matrix`
    (α0, β0, γ0), ω = n C0 e2 + s_ref(u0) e1 + initial_rate_error.
    """
    _check_satellite(satellite)
    _check_orbit(orbit)
    t_end = as_positive_scalar("duration", duration, unit="s")
    dt = as_positive_scalar("sample_interval", sample_interval, unit="s")
    angles0 = as_finite("initial_angles", initial_angles)
    if angles0.shape != (3,):
        raise ValueError(f"initial_angles must have shape (3,) (α, β, γ) [rad], got shape {angles0.shape}")
    if abs(angles0[1]) >= 0.5 * math.pi:
        raise ValueError(f"initial_angles[1] (β) must be in (−π/2, π/2) rad, got {shown(angles0[1])}")
    dw = as_finite("initial_rate_error", initial_rate_error)
    if dw.shape != (3,):
        raise ValueError(f"initial_rate_error must have shape (3,) [rad/s], got shape {dw.shape}")
    rtol = as_positive_scalar("rtol", rtol)
    atol = as_positive_scalar("atol", atol)
    damping = as_choice("damping", damping, DAMPING)
    n = orbit.mean_motion
    u0 = float(orbit.argument_of_latitude0)
    c0 = airplane_231_matrix(*angles0)
    a_ax = satellite.inertia_matrix[0, 0]
    hr = satellite.rotor_inertia * satellite.rotor_rate
    s_ref0 = (satellite.axial_momentum * math.cos(u0) ** 2 - hr) / a_ax
    w0 = n * c0[:, 1] + s_ref0 * np.array([1.0, 0.0, 0.0]) + dw
    q0 = Rotation.from_matrix(c0.T).as_quat(scalar_first=True)
    # Imported here: numba's cache, set up at import, probes its folder with a file.
    from ._rotor_kernel import rotor_controller, rotor_rhs

    constants = _body_constants(satellite, orbit, damping)
    samples = np.arange(0.0, t_end * (1.0 + 1e-12), dt)
    engine = _ADAPTIVE_ENGINE if method == "DOP853" else "scipy"
    sol = solve_adaptive(rotor_rhs, (0.0, float(samples[-1])), np.concatenate([q0, w0]), method=method,
                         t_eval=samples, rtol=rtol, atol=atol, args=(constants,), engine=engine)
    y = sol.y.T
    q = y[:, :4] / np.linalg.norm(y[:, :4], axis=1, keepdims=True)
    omega = y[:, 4:]
    c = Rotation.from_quat(q, scalar_first=True).as_matrix().transpose(0, 2, 1)
    dipole, torque = np.empty((samples.size, 3)), np.empty((samples.size, 3))
    for n_s, (t, row) in enumerate(zip(samples, y)):
        out = rotor_controller(float(t), *row.tolist(), constants)
        dipole[n_s] = out[:3]
        torque[n_s] = np.cross(out[:3], out[3:6])
    u = u0 + n * samples
    return RotorRun(time=samples, argument_of_latitude=u, attitude=q, angles=np.stack(airplane_231_angles(c), axis=1),
                    omega=omega, pointing_error=np.arccos(np.clip(c[:, 0, 0], -1.0, 1.0)), spin_rate=omega[:, 0],
                    spin_reference=(satellite.axial_momentum * np.cos(u) ** 2 - hr) / a_ax, dipole=dipole,
                    torque=torque,
                    inputs={"duration": t_end, "initial_angles": tuple(angles0.tolist()),
                            "initial_rate_error": tuple(dw.tolist()), "sample_interval": dt, "rtol": rtol,
                            "atol": atol, "damping": damping, "method": method, "nfev": int(sol.nfev)})

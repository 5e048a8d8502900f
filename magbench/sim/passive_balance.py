r"""The energy balance of the passive satellite's flat spin: how fast hysteresis rods take
angular momentum from a body spinning about a transverse axis, without simulating it.

TNS-0 preprint Fig. 14 (the straight decline of L) and Kovalenko (1975) §12.1, eq. (12.1)
(the loss per cycle); the balance itself is ours. Chapter 7 sets it beside the simulated
decay (:func:`magbench.sim.simulate_passive`) and the preprint's sessions.
"""

import numpy as np

from .._validate import as_finite, as_vectors, shown
from ..constants import MU_0
from ..earth.circular_orbit import CircularOrbit
from ..hardware.hysteresis import rod_cycle_energy
from .passive import PassiveSatellite

__all__ = ["flat_spin_decay_rate"]


def flat_spin_decay_rate(satellite, orbit, momentum_direction, spin_axis_angle, *, orbit_samples=12):
    r"""dL/dt of a flat spin from the rods' energy per revolution (the energy balance).

    Parameters
    ----------
    satellite : PassiveSatellite
        Rods (axes, volume, material) [-].
    orbit : CircularOrbit
        Orbit and field; a scalar ``argument_of_latitude0`` [-].
    momentum_direction : array_like, shape (3,) or (M, 3)
        Direction of L in inertial axes (normalised here) [-].
    spin_axis_angle : float or array_like, shape (M,)
        Angle β of the spin axis from body x in the body's transverse plane: the body spins
        about ŝ = (cos β, sin β, 0) [rad].
    orbit_samples : int, optional
        Points of the argument of latitude over half an orbit, ≥ 4 (the direct dipole's field
        repeats every half orbit) [-].

    Returns
    -------
    ndarray, shape () or (M,)
        dL/dt [kg·m²/s per s], ≤ 0; independent of the spin rate.

    Notes
    -----
    Not in the sources (ours; TNS-0 preprint Fig. 14 and Kovalenko (1975) §12.1, eq. (12.1)
    for the loss per cycle). With θ = π/2 (Table 1 rows 2–7) L is fixed in space (the magnet's
    spin-averaged torque m cos θ L̂ × B vanishes) and the body turns about ŝ ∥ L at Ω ≫ n, so
    rod k sees H_k = c_k (H·L̂) + (1 − c_k²)^½ |H⊥| cos Ωt, c_k = r̂_k·ŝ: one loop of
    amplitude (1 − c_k²)^½|H⊥| about the bias c_k H·L̂ per revolution, losing
    V·:func:`~magbench.hardware.rod_cycle_energy`. The body's energy L²/2A falls by that per
    revolution, so Ω dL/dt = −(Ω/2π) Σ_k V W_k: dL/dt = −⟨Σ_k V W_k⟩/2π, averaged over the
    orbit — constant, hence a straight line in L(t). The rods' effect on the field they see
    and their torque's periodic part are neglected (quasi-static: Ω ≫ 2n).

    Examples
    --------
    >>> sat = PassiveSatellite(0.0406, 0.00625, 0.35, rod_volume=2.4e-6)
    >>> orbit = CircularOrbit(6721e3, np.radians(51.6), 7.766e22)
    >>> rate = flat_spin_decay_rate(sat, orbit, [1.0, 0.0, 0.0], np.pi / 4)
    >>> bool(-1e-7 < rate < 0)
    True
    """
    if not isinstance(satellite, PassiveSatellite):
        raise ValueError(f"satellite must be a magbench.sim.PassiveSatellite, got {type(satellite).__name__}")
    if not isinstance(orbit, CircularOrbit):
        raise ValueError(f"orbit must be a magbench.earth.CircularOrbit, got {type(orbit).__name__}")
    if np.ndim(orbit.argument_of_latitude0):
        raise ValueError("orbit.argument_of_latitude0 must be a scalar here (the balance averages over the orbit)")
    direction = as_vectors("momentum_direction", momentum_direction)
    norm = np.linalg.norm(direction, axis=-1, keepdims=True)
    if np.any(norm == 0):
        raise ValueError("momentum_direction must not be a zero vector")
    beta = as_finite("spin_axis_angle", spin_axis_angle)
    samples = int(orbit_samples)
    if samples != orbit_samples or samples < 4:
        raise ValueError(f"orbit_samples must be an integer >= 4, got {shown(orbit_samples)}")
    lhat, beta = np.broadcast_arrays(direction / norm, beta[..., None])
    beta = beta[..., 0]
    if satellite.rod_volume == 0:
        return np.zeros(beta.shape)
    times = np.arange(samples) / samples * (0.5 * orbit.period)
    h = orbit.field(times) / MU_0                                       # (S, 3)
    along = np.einsum("sj,...j->...s", h, lhat)                         # (..., S)
    across = np.sqrt(np.maximum(np.sum(h * h, axis=-1) - along**2, 0.0))
    spin = np.stack([np.cos(beta), np.sin(beta), np.zeros(beta.shape)], axis=-1)
    cosines = np.einsum("kj,...j->...k", np.array(satellite.rod_axes), spin)   # (..., k)
    amplitude = np.sqrt(1.0 - np.minimum(cosines**2, 1.0))[..., None] * across[..., None, :]
    bias = cosines[..., None] * along[..., None, :]                     # (..., k, S)
    # A rod along the spin axis (zero amplitude) is not driven round a loop: no loss.
    driven = amplitude > 0
    w = rod_cycle_energy(np.where(driven, amplitude, 1.0), satellite.rod_coercivity, satellite.rod_remanence,
                         satellite.rod_saturation, bias=bias)
    loss = satellite.rod_volume * np.sum(np.where(driven, w, 0.0), axis=-2).mean(axis=-1)
    return -loss / (2.0 * np.pi)

"""A new satellite from the library's kernels, with no new integrator: a gravity-gradient boom
with a permanent magnet along it and a viscous spherical damper, 100 members on one orbit.

The body's state is (q, ω, ω_d): attitude (body → inertial), body rate and the damper ball's
rate, all in body axes. Torques: gravity gradient (Kovalenko (1975) eq. (4.18)), the magnet's
m × B, and the damper's c(ω_d − ω) (:func:`magbench.dynamics.viscous_damper_torque`); the ball
feels the opposite torque (a free sphere of moment J_d, its inertial rate written in body axes:
:func:`magbench.dynamics.spherical_damper_rhs`, Kovalenko's (5.19)–(5.22)). Run:
``python examples/gravity_gradient_magnet_damper.py``.
"""

import numpy as np
from scipy.spatial.transform import Rotation

from magbench.dynamics import kernels
from magbench.earth import CircularOrbit
from magbench.integrate import rk4_step


def satellite_rhs(time, state, orbit, inertia, magnet, damper_inertia, damping):
    """(q̇, ω̇, ω̇_d) of every member; state (M, 10)."""
    q, w, wd = state[:, :4], state[:, 4:7], state[:, 7:]
    position = orbit.position(time)
    radial = kernels.rotate(q, position / np.linalg.norm(position, axis=-1, keepdims=True), -1.0)
    field = kernels.rotate(q, orbit.field(time), -1.0)
    torque = kernels.gravity_gradient_torque(radial, inertia, orbit.mean_motion) + kernels.cross(magnet, field)
    coupling = kernels.viscous_damper_torque(wd - w, damping)
    rates = kernels.spherical_damper_rhs(state[:, 4:], torque, np.zeros_like(torque), inertia, damper_inertia,
                                         coupling)
    return np.concatenate([kernels.quaternion_rate(q, w), rates], axis=-1)


def run(members=100, orbits=2.0, step=5.0, seed=0, damping=2e-4, magnet=(0.0, 0.0, 0.01)):
    """Random attitudes and rates (≤ 1°/s), orbit phases spread; returns time and the boom's
    angle from the local vertical per member [rad]. The step must stay below the damper's time
    constant J_d/c (50 s here) for the explicit scheme to be stable."""
    rng = np.random.default_rng(seed)
    orbit = CircularOrbit(6.871e6, 1.2, 8.0e22, argument_of_latitude0=rng.uniform(0, 2 * np.pi, members))
    inertia = np.array([0.5, 0.5, 0.02])              # kg·m²: a boom along body z
    q = Rotation.random(members, rng=rng).as_quat(scalar_first=True)
    w = rng.uniform(-1.0, 1.0, (members, 3)) * np.pi / 180
    state = np.concatenate([q, w, w], axis=-1)
    args = (orbit, inertia, np.asarray(magnet), 0.01, damping)
    times = np.arange(0.0, orbits * orbit.period, step)
    angle = np.empty((members, times.size))
    for i, t in enumerate(times):
        position = orbit.position(t)
        up = kernels.rotate(state[:, :4], position / np.linalg.norm(position, axis=-1, keepdims=True), -1.0)
        angle[:, i] = np.arccos(np.clip(np.abs(up[:, 2]), 0.0, 1.0))
        state = rk4_step(satellite_rhs, t, state, step, args)
    return times, angle


if __name__ == "__main__":
    t, angle = run()
    print(f"{angle.shape[0]} members, {t[-1] / 3600:.1f} h: boom from vertical, median "
          f"{np.degrees(np.median(angle[:, 0])):.0f}° at the start, {np.degrees(np.median(angle[:, -1])):.0f}° at the end")

"""The example models run, and obey the laws their physics must."""

import importlib.util
from pathlib import Path

import numpy as np
from numpy.testing import assert_allclose

from magbench.dynamics import kernels
from magbench.earth import CircularOrbit
from magbench.integrate import rk4_step

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"


def _load(name):
    spec = importlib.util.spec_from_file_location(name, EXAMPLES / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_damper_conserves_angular_momentum_and_dissipates_energy():
    """With no external torque (no magnet; an isotropic body feels no gravity gradient) the body
    and its damper ball only exchange momentum: H = Jω + J_d ω_d, in inertial axes, is constant,
    and the kinetic energy falls."""
    example = _load("gravity_gradient_magnet_damper")
    rng = np.random.default_rng(3)
    members, j, jd, c = 4, np.full(3, 0.3), 0.01, 2e-4
    orbit = CircularOrbit(6.871e6, 1.2, 8.0e22)
    q = rng.normal(size=(members, 4))
    state = np.concatenate([q / np.linalg.norm(q, axis=-1, keepdims=True), rng.normal(size=(members, 6)) * 0.02],
                           axis=-1)
    args = (orbit, j, np.zeros(3), jd, c)

    def momentum_and_energy(x):
        w, wd = x[:, 4:7], x[:, 7:]
        h = kernels.rotate(x[:, :4], j * w + jd * wd, 1.0)
        return h, 0.5 * np.sum(j * w * w, axis=-1) + 0.5 * jd * np.sum(wd * wd, axis=-1)

    h0, e0 = momentum_and_energy(state)
    energies = [e0]
    for i in range(1000):
        state = rk4_step(example.satellite_rhs, 2.0 * i, state, 2.0, args)
        energies.append(momentum_and_energy(state)[1])
    h1, _ = momentum_and_energy(state)
    # RK4's truncation at |ω|h ≤ 0.1 rad per step over 1000 steps: below 1e-7 of |H|; a damper
    # torque that did not act back on the body (or with the wrong sign) moves H by ~c|ω_d − ω|t,
    # tens of per cent of |H| over this run
    assert_allclose(h1, h0, rtol=0, atol=1e-6 * np.max(np.abs(h0)))
    assert np.all(np.diff(np.array(energies), axis=0) <= 1e-15)
    assert np.all(energies[-1] < 0.99 * e0)


def test_the_example_runs_100_members():
    example = _load("gravity_gradient_magnet_damper")
    t, angle = example.run(members=100, orbits=0.05)
    assert angle.shape == (100, t.size) and np.all((angle >= 0) & (angle <= np.pi / 2))

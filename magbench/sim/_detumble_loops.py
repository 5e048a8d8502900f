r"""The two detumbling loops behind :func:`magbench.sim.simulate_detumble`: the numpy reference
(all members in each RK4 step, vectors as (M,) component arrays) and the compiled loop
(:mod:`magbench.sim._detumble_kernel`, member by member), equal to the last bit (to rounding
for an inertia tensor, which the numpy loop solves and the compiled one inverts); with the
field table, the body, the laws and the duty-cycle schedule they share.

SamSat-218D §"Rate damping" (seed lines 225–273); the classical RK4 scheme of
:func:`magbench.integrate.rk4_step`, written out on component arrays.
"""

from dataclasses import dataclass

import numpy as np

from ..control.kernels import bdot_dipole, bdot_dipole_projected
from ..dynamics import kernels as dynamics_kernels
from ..earth.circular_orbit import CircularOrbit
from ..integrate import rk4_step

LAWS = ("bdot", "projected")
MODES = ("continuous", "sampled", "duty")
ESTIMATORS = ("model", "hold", "propagate")


class _Field:
    """Inertial field, its rate and the radial direction at one time, kept for the RK stages
    (the passive satellite's loop, :mod:`magbench.sim.passive`, uses it)."""

    def __init__(self, orbit):
        self.orbit = orbit
        self.cache = {}

    def __call__(self, time):
        hit = self.cache.get(time)
        if hit is None:
            if len(self.cache) > 4:
                self.cache.clear()
            b, b_rate = self.orbit.field_and_rate(time)
            hit = self.cache[time] = (b, b_rate, self.orbit.position(time) / self.orbit.radius)
        return hit


# -- the inner loop: members on the last axis, components as separate 1-D arrays ----------
# Each RK stage is ~140 elementwise operations on arrays of M members; keeping components
# apart avoids the stacking and axis handling that dominated a step with (M, 3) arrays.

def _cross3(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def _law_bdot(b, b_rate, k, limit):
    """The law on the loop's components (tuples of (M,) arrays):
    :func:`magbench.control.kernels.bdot_dipole`."""
    m = bdot_dipole(np.stack(np.broadcast_arrays(*b_rate), axis=-1), _per_member(k), limit)
    return tuple(np.moveaxis(m, -1, 0))


def _law_projected(b, b_rate, k, limit):
    """The same for :func:`magbench.control.kernels.bdot_dipole_projected`."""
    return tuple(np.moveaxis(bdot_dipole_projected(np.stack(np.broadcast_arrays(*b), axis=-1),
                                                   np.stack(np.broadcast_arrays(*b_rate), axis=-1),
                                                   _per_member(k), limit), -1, 0))


def _per_member(gain):
    return np.asarray(gain)[..., None] if np.ndim(gain) else gain


class _FieldTable:
    """Inertial field, its rate and the radial direction at the RK stage times
    t_i + s·h/2 (s = 0, 1, 2), computed for blocks of steps at once."""

    block = 256

    def __init__(self, orbit, step, n_steps, compiled=False):
        self.orbit, self.step, self.n_steps, self.start = orbit, step, n_steps, None
        phase = np.ndim(orbit.argument_of_latitude0)
        self.member_axis = phase != 0
        self.geometry = None
        if compiled and self.member_axis:
            from ..earth.kernels import orbit_geometry

            self.geometry = orbit_geometry(orbit)

    def _fill(self, start):
        count = min(self.block, self.n_steps - start)
        times = (2 * start + np.arange(2 * count + 1)) * (0.5 * self.step)
        if self.geometry is not None:
            self._fill_compiled(times)
        else:
            t = times[:, None] if self.member_axis else times
            b, b_rate, position = self.orbit.field_rate_and_position(t)
            radial = position / self.orbit.radius
            # (3, T[, M]) so that one stage's component is a contiguous (M,) array or a scalar
            self.b, self.b_rate, self.radial = (np.ascontiguousarray(np.moveaxis(a, -1, 0))
                                                for a in (b, b_rate, radial))
        self.start = start

    def _fill_compiled(self, times):
        # the same numbers as field_rate_and_position (tested bit for bit): numpy's sines
        # and cosines, the rest compiled, straight into the (3, T, M) layout
        from ..earth.kernels import field_table

        orbit = self.orbit
        u = orbit.argument_of_latitude(times[:, None])
        lam = orbit.dipole_longitude + orbit.earth_rotation_rate * times
        self.b, self.b_rate, self.radial = (np.empty((3,) + u.shape) for _ in range(3))
        field_table(np.cos(u), np.sin(u), np.cos(lam), np.sin(lam), self.geometry, float(orbit.radius),
                    self.b, self.b_rate, self.radial)

    def _index(self, i, stage):
        if self.start is None or not self.start <= i < self.start + self.block:
            self._fill(i - i % self.block)
        return 2 * (i - self.start) + stage

    def block_at(self, start):
        """The table of the block of steps from ``start`` (a multiple of :attr:`block`): B,
        Ḃ and the radial unit vector, each (3, 2·count + 1, M or 1)."""
        self._index(start, 0)
        return tuple(a if a.ndim == 3 else a[:, :, None] for a in (self.b, self.b_rate, self.radial))

    def field(self, i, stage):
        n = self._index(i, stage)
        return self.b[0, n], self.b[1, n], self.b[2, n]

    def all(self, i, stage):
        n = self._index(i, stage)
        return ((self.b[0, n], self.b[1, n], self.b[2, n]), (self.b_rate[0, n], self.b_rate[1, n], self.b_rate[2, n]),
                (self.radial[0, n], self.radial[1, n], self.radial[2, n]))


class _Propagated:
    """Duty "propagate": the field propagated from the window's end with ω⊥ (rotation by
    −ω⊥ (t − t_end), Rodrigues), and its rate −ω⊥ × B."""

    def __init__(self, b_end, w_perp, t_end, dipole):
        self.b_end, self.w_perp, self.t_end, self.dipole = b_end, w_perp, t_end, dipole
        size = np.sqrt(w_perp[0] ** 2 + w_perp[1] ** 2 + w_perp[2] ** 2)
        self.size = size
        self.axis = tuple(np.divide(c, size, out=np.zeros_like(c), where=size > 0) for c in w_perp)

    def __call__(self, time):
        angle = -self.size * (time - self.t_end)
        c, s = np.cos(angle), np.sin(angle)
        a, b = self.axis, self.b_end
        ab = a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
        axb = _cross3(a, b)
        est = tuple(bi * c + xi * s + ai * ab * (1.0 - c) for bi, xi, ai in zip(b, axb, a))
        rate = tuple(-r for r in _cross3(self.w_perp, est))
        return self.dipole(est, rate)


class _Body:
    """Euler's equations, quaternion kinematics and gravity gradient on component arrays."""

    def __init__(self, j, mean_motion):
        self.inertia = j
        self.tensor = j.shape == (3, 3)
        self.j = j if self.tensor else tuple(np.asarray(j)[..., a] for a in range(3))
        self.gg = None if mean_motion is None else 3.0 * mean_motion ** 2

    def _apply(self, m, v):
        return tuple(m[r, 0] * v[0] + m[r, 1] * v[1] + m[r, 2] * v[2] for r in range(3))

    def inertia_times(self, v):
        return self._apply(self.j, v) if self.tensor else (self.j[0] * v[0], self.j[1] * v[1], self.j[2] * v[2])

    @staticmethod
    def matrix(q):
        """R(q/|q|)ᵀ as rows (body components of the inertial axes)."""
        w, x, y, z = q
        s = 2.0 / (w * w + x * x + y * y + z * z)
        xx, yy, zz, xy, xz, yz, wx, wy, wz = (s * x * x, s * y * y, s * z * z, s * x * y, s * x * z, s * y * z,
                                              s * w * x, s * w * y, s * w * z)
        return ((1.0 - yy - zz, xy + wz, xz - wy), (xy - wz, 1.0 - xx - zz, yz + wx), (xz + wy, yz - wx, 1.0 - xx - yy))

    @staticmethod
    def rotate(rt, v):
        return tuple(r[0] * v[0] + r[1] * v[1] + r[2] * v[2] for r in rt)

    def to_body(self, q, v):
        return self.rotate(self.matrix(q), v)

    def rhs(self, fields, i, stage, state, command, dipole, time):
        q, w = state[:4], state[4:]
        b_n, b_rate_n, radial = fields.all(i, stage)
        rt = self.matrix(q)
        b = self.rotate(rt, b_n)
        if command is None:          # the on-board models: exact Ḃ in body axes
            wxb = _cross3(w, b)
            m = dipole(b, tuple(r - c for r, c in zip(self.rotate(rt, b_rate_n), wxb)))
        elif callable(command):      # duty "propagate"
            m = command(time)
        else:                        # held dipole (zero when off)
            m = command
        torque = _cross3(m, b)
        if self.gg is not None:
            r = self.rotate(rt, radial)
            g = _cross3(r, self.inertia_times(r))
            torque = tuple(t + self.gg * gi for t, gi in zip(torque, g))
        out = np.empty_like(state)
        out[:4] = dynamics_kernels.quaternion_rate(state[:4].T, state[4:].T).T
        out[4:] = dynamics_kernels.euler_rates(state[4:].T, np.stack(np.broadcast_arrays(*torque), axis=-1),
                                               self.inertia).T
        return out

    def rk4(self, fields, i, state, h, command, dipole):
        """One step of :func:`magbench.integrate.rk4_step` from step i; the field table's
        stage is the count of half steps from i·h to the stage's time."""
        start = i * h

        def rates(time, x):
            return self.rhs(fields, i, round((time - start) / (0.5 * h)), x, command, dipole, time)

        return rk4_step(rates, start, state, h)


class _Schedule:
    """What the coils do at each step: the continuous law (``None``: evaluated at every RK
    stage), the sampled law held between samples, or the duty cycle's off window and its
    estimator (SamSat-218D §"Rate damping"; the estimators are ours)."""

    _ZERO = (0.0, 0.0, 0.0)

    def __init__(self, mode, estimator, body, fields, dipole, delta, t_off, per_sample, n_off, n_on):
        self.mode, self.estimator, self.body, self.fields, self.dipole = mode, estimator, body, fields, dipole
        self.delta, self.t_off, self.per_sample, self.n_off, self.n_on = delta, t_off, per_sample, n_off, n_on
        self.current, self.previous, self.window_start = None, None, None

    def _field_body(self, i, state):
        return self.body.to_body(state[:4], self.fields.field(i, 0))

    def command(self, i, time, state):
        """The held dipole (or ``None`` for the continuous law) from step ``i`` on."""
        if self.mode == "sampled" and i % self.per_sample == 0:
            sample = self._field_body(i, state)
            self.current = self._ZERO if self.previous is None else self.dipole(
                sample, tuple((s - p) / self.delta for s, p in zip(sample, self.previous)))
            self.previous = sample
        elif self.mode == "duty":
            phase_step = i % (self.n_off + self.n_on)
            if phase_step == 0:
                self.window_start = self._field_body(i, state)
                self.current = self._ZERO
            elif phase_step == self.n_off:
                self.current = self._estimate(self._field_body(i, state), time)
        return self.current

    def _estimate(self, b_end, time):
        b_rate = tuple((e - s) / self.t_off for e, s in zip(b_end, self.window_start))
        if self.estimator == "model":
            return None
        if self.estimator == "hold":
            return self.dipole(b_end, b_rate)
        b2 = b_end[0] ** 2 + b_end[1] ** 2 + b_end[2] ** 2
        w_perp = tuple(-c / b2 for c in _cross3(b_end, b_rate))
        return _Propagated(b_end, w_perp, time, self.dipole)


@dataclass(frozen=True)
class _Loop:
    """What the inner loop needs: body, orbit, law, schedule and step counts."""

    inertia: np.ndarray
    orbit: CircularOrbit
    mean_motion: object          # None: no gravity gradient
    law: str
    gain: object                 # float or (M,)
    limit: np.ndarray            # (3,)
    mode: str
    estimator: str
    timing: tuple                # (control_interval, off_time, per_sample, n_off, n_on)
    step: float
    n_steps: int
    stride: int


def _numpy_loop(loop, q0, w0):
    """The vectorised reference: all members in each RK4 step. Returns state (7, M) and |ω| records (M, K)."""
    members = q0.shape[0]
    body = _Body(loop.inertia, loop.mean_motion)
    law_fn = _law_bdot if loop.law == "bdot" else _law_projected

    def dipole(b, b_rate):
        return law_fn(b, b_rate, loop.gain, loop.limit)

    h = loop.step
    state = np.empty((7, members))
    state[:4], state[4:] = q0.T, w0.T
    rates = np.empty((members, loop.n_steps // loop.stride + 1))
    rates[:, 0] = np.linalg.norm(w0, axis=-1)
    fields = _FieldTable(loop.orbit, h, loop.n_steps)
    schedule = _Schedule(loop.mode, loop.estimator, body, fields, dipole, *loop.timing)
    for i in range(loop.n_steps):
        command = schedule.command(i, i * h, state)
        state = body.rk4(fields, i, state, h, command, dipole)
        state[:4] /= np.sqrt(state[0] ** 2 + state[1] ** 2 + state[2] ** 2 + state[3] ** 2)
        if (i + 1) % loop.stride == 0:
            rates[:, (i + 1) // loop.stride] = np.sqrt(state[4] ** 2 + state[5] ** 2 + state[6] ** 2)
    return state, rates


def _compiled_loop(loop, q0, w0):
    """The same loop compiled (:func:`magbench.sim._detumble_kernel.advance_block`), block by
    block of the field table. Returns state (7, M) and |ω| records (M, K)."""
    from ._detumble_kernel import LAW, advance_block

    members = q0.shape[0]
    state = np.ascontiguousarray(np.concatenate([q0, w0], axis=-1).T)
    rates = np.empty((members, loop.n_steps // loop.stride + 1))
    rates[:, 0] = np.linalg.norm(w0, axis=-1)
    diag = loop.inertia.shape != (3, 3)
    jd = np.ascontiguousarray((np.broadcast_to(loop.inertia, (members, 3)) if diag else np.ones((members, 3))).T)
    jt = np.eye(3) if diag else np.ascontiguousarray(loop.inertia)
    jinv = np.eye(3) if diag else np.linalg.inv(jt)
    gain = np.ascontiguousarray(np.broadcast_to(np.asarray(loop.gain, dtype=float), (members,)))
    delta, t_off, per_sample, n_off, n_on = loop.timing
    schedule = np.array([MODES.index(loop.mode), per_sample, n_off, n_on, loop.estimator == "hold", delta, t_off],
                        dtype=float)
    how = np.full(members, LAW, dtype=np.int64)
    held, window, previous = np.zeros((3, members)), np.zeros((3, members)), np.zeros((4, members))
    gg = 0.0 if loop.mean_motion is None else 3.0 * loop.mean_motion ** 2
    limit = np.ascontiguousarray(loop.limit, dtype=float)
    fields = _FieldTable(loop.orbit, loop.step, loop.n_steps, compiled=True)
    for start in range(0, loop.n_steps, fields.block):
        count = min(fields.block, loop.n_steps - start)
        # one column per member even for a shared orbit: the kernel reads every table
        # along its contiguous member axis
        table = [np.ascontiguousarray(np.broadcast_to(a, a.shape[:2] + (members,))) for a in fields.block_at(start)]
        advance_block(state, start, count, loop.step, tuple(table), schedule, (how, held, window, previous),
                      (gain, limit, loop.law == "projected"), (gg, diag, jd, jt, jinv), loop.stride, rates)
    return state, rates

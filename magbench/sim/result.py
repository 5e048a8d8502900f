r"""The one result type of the simulations, in python-control's vocabulary, and the three runs
whose contracts (chapters 5, 6 and 7) fix other names: each is a view that gives the result
type by ``to_result()``."""

from dataclasses import dataclass, field, fields

import numpy as np

__all__ = ["SimulationResult", "DetumbleRun", "RotorRun", "PassiveRun"]


@dataclass(frozen=True)
class SimulationResult:
    r"""A simulated response: signals over time, named as python-control names them.

    Attributes
    ----------
    time : ndarray, shape (K,)
        Sample times [s].
    states : ndarray, shape (n_states, K, ...)
        State signals, one row per label in ``state_labels`` [SI].
    inputs : ndarray, shape (n_inputs, K, ...)
        Inputs of the plant (the controller's commands), one row per ``input_labels`` [SI].
    outputs : ndarray, shape (n_outputs, K, ...)
        Further signals of the run, one row per ``output_labels`` [SI].
    state_labels, input_labels, output_labels : tuple of str
        Names of the rows [-]; each signal is also an attribute (``result.psi``).
    params : dict
        What the run was given (targets, per-member draws) [SI]; each entry is also an
        attribute.
    summary : dict
        Numbers computed from the whole run (error bands) [SI]; each entry is also an
        attribute.

    Notes
    -----
    Not in the sources: the names of :class:`control.TimeResponseData` (python-control,
    ``time``, ``states``, ``inputs``, ``outputs``, ``*_labels``, ``params``). Unlike
    python-control, a signal keeps time on its first axis and Monte Carlo members after
    it, as the simulations vectorise them: ``result.psi`` has shape (K, members).

    Examples
    --------
    >>> r = SimulationResult(np.arange(3.0), np.zeros((2, 3)), np.ones((1, 3)), np.empty((0, 3)),
    ...                      ("psi", "rate"), ("command",), ())
    >>> r.command.tolist(), r.psi.shape
    ([1.0, 1.0, 1.0], (3,))
    """

    time: np.ndarray
    states: np.ndarray
    inputs: np.ndarray
    outputs: np.ndarray
    state_labels: tuple
    input_labels: tuple
    output_labels: tuple
    params: dict = field(default_factory=dict)
    summary: dict = field(default_factory=dict)

    def __post_init__(self):
        for kind in ("states", "inputs", "outputs"):
            signals, labels = getattr(self, kind), getattr(self, kind[:-1] + "_labels")
            if len(signals) != len(labels):
                raise ValueError(f"{kind} must have one row per label {labels}, got {len(signals)} rows")

    def __getattr__(self, name):
        # Only reached when normal lookup fails: a signal, parameter or summary by its name.
        if name.startswith("_") or name in {f.name for f in fields(SimulationResult)}:
            raise AttributeError(name)
        for kind in ("state", "input", "output"):
            labels = self.__dict__.get(kind + "_labels", ())
            if name in labels:
                return self.__dict__[kind + "s"][labels.index(name)]
        for table in ("params", "summary"):
            if name in self.__dict__.get(table, {}):
                return self.__dict__[table][name]
        raise AttributeError(f"{type(self).__name__!r} has no signal, parameter or summary {name!r}")


@dataclass(frozen=True)
class DetumbleRun:
    r"""A detumbling run of M members.

    Attributes
    ----------
    time : ndarray, shape (K,)
        Record times [s].
    rate : ndarray, shape (M, K)
        |ω| of every member at every record time [rad/s].
    omega : ndarray, shape (M, 3)
        Final angular velocity in body axes [rad/s].
    attitude : ndarray, shape (M, 4)
        Final attitude quaternion, scalar first, body → inertial [-].
    inputs : dict
        The run's arguments (and the step used, the initial states and any Monte Carlo
        draws) [SI].

    Notes
    -----
    Not in the sources: the names of the chapter-5 contract. ``inputs`` here is what the run
    was given, not python-control's input signals, so the run is not itself a
    :class:`~magbench.sim.SimulationResult`; :meth:`to_result` gives that view.
    """

    time: np.ndarray
    rate: np.ndarray
    omega: np.ndarray
    attitude: np.ndarray
    inputs: dict = field(default_factory=dict)

    def to_result(self):
        """The run as a :class:`~magbench.sim.SimulationResult`: state ``rate`` of shape (K, M),
        the arguments as ``params`` and the final state as ``summary``."""
        k = self.time.size
        return SimulationResult(self.time, self.rate.T[None], np.empty((0, k)), np.empty((0, k)), ("rate",), (), (),
                                params=dict(self.inputs),
                                summary={"final_angular_velocity": self.omega, "final_attitude": self.attitude})


@dataclass(frozen=True)
class RotorRun:
    r"""A simulated run of the rotor spacecraft, sampled at ``time``.

    Attributes
    ----------
    time : ndarray, shape (n,)
        Sample times [s].
    argument_of_latitude : ndarray, shape (n,)
        u = u0 + ω0 t [rad].
    attitude : ndarray, shape (n, 4)
        Quaternion, scalar first, v_orbital = R(q) v_body [-].
    angles : ndarray, shape (n, 3)
        Airplane angles α, β, γ [rad].
    omega : ndarray, shape (n, 3)
        Body absolute angular velocity, body axes [rad/s].
    pointing_error : ndarray, shape (n,)
        arccos C11, angle between the rotor axis and the velocity [rad].
    spin_rate : ndarray, shape (n,)
        ω1 [rad/s].
    spin_reference : ndarray, shape (n,)
        s_ref(u) = (H0 cos²u − J_f ν)/I11 [rad/s].
    dipole : ndarray, shape (n, 3)
        Commanded (clipped) dipole, body axes [A·m²].
    torque : ndarray, shape (n, 3)
        Magnetic torque m × B, body axes [N·m].
    inputs : dict
        The run's arguments and the solver's statistics [SI].

    Notes
    -----
    Not in the sources: the names of the chapter-6 contract (``rotor_spin.md`` §15); the
    slides' lost simulation slide (seed lines 94–96) shows these signals.
    """

    time: np.ndarray
    argument_of_latitude: np.ndarray
    attitude: np.ndarray
    angles: np.ndarray
    omega: np.ndarray
    pointing_error: np.ndarray
    spin_rate: np.ndarray
    spin_reference: np.ndarray
    dipole: np.ndarray
    torque: np.ndarray
    inputs: dict = field(default_factory=dict)

    def to_result(self):
        """The run as a :class:`~magbench.sim.SimulationResult` (states q, ω; inputs m; outputs)."""
        states = np.concatenate([self.attitude, self.omega], axis=1).T
        labels = ("q0", "q1", "q2", "q3", "rate_x", "rate_y", "rate_z")
        outputs = np.vstack([self.pointing_error, self.spin_rate, self.spin_reference, self.torque.T])
        return SimulationResult(self.time, states, self.dipole.T, outputs, labels, ("dipole_x", "dipole_y", "dipole_z"),
                                ("pointing_error", "spin_rate", "spin_reference", "torque_x", "torque_y", "torque_z"),
                                params=dict(self.inputs))


@dataclass(frozen=True)
class PassiveRun:
    r"""A passive-satellite run: samples of the quantities TNS-0's tables report.

    Attributes
    ----------
    time : ndarray, shape (n,)
        Sample times [s].
    angular_momentum : ndarray, shape (members, n) or (n,)
        |L| [kg·m²/s].
    nutation : ndarray, shape like ``angular_momentum``
        Angle between L and the symmetry axis [rad].
    axis_field_angle : ndarray, shape like ``angular_momentum``
        Angle between B and the symmetry axis (Table 2's 0.85 rad) [rad].
    momentum_field_angle : ndarray, shape like ``angular_momentum``
        Angle between B and L [rad].
    rate : ndarray, shape like ``angular_momentum``
        |ω| [rad/s].
    attitude : ndarray, shape (members, 4) or (4,)
        Final quaternion, scalar first, body → inertial [-].
    body_rate : ndarray, shape (members, 3) or (3,)
        Final angular velocity in body axes [rad/s].
    rod_induction : ndarray, shape (members, k) or (k,)
        Final induction of each rod [T].
    inputs : dict
        The run's arguments, the initial state and the steps used [SI].

    Notes
    -----
    TNS-0 preprint Table 1 (L, nutation) and Table 2 (the angle between B and the symmetry
    axis); the names are the chapter-7 contract's.
    """

    time: np.ndarray
    angular_momentum: np.ndarray
    nutation: np.ndarray
    axis_field_angle: np.ndarray
    momentum_field_angle: np.ndarray
    rate: np.ndarray
    attitude: np.ndarray
    body_rate: np.ndarray
    rod_induction: np.ndarray
    inputs: dict = field(default_factory=dict)

    def to_result(self):
        """The run as a :class:`~magbench.sim.SimulationResult`: states of shape (n, members)."""
        names = ("angular_momentum", "nutation", "axis_field_angle", "momentum_field_angle", "rate")
        states = np.stack([np.asarray(getattr(self, n)).T for n in names])
        k = self.time.size
        return SimulationResult(self.time, states, np.empty((0, k)), np.empty((0, k)), names, (), (),
                                params=dict(self.inputs),
                                summary={"final_attitude": self.attitude, "final_body_rate": self.body_rate,
                                         "final_rod_induction": self.rod_induction})

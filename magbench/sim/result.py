r"""The one result type of the simulations, in python-control's vocabulary."""

from dataclasses import dataclass, field, fields

import numpy as np

__all__ = ["SimulationResult"]


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

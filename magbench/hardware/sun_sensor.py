r"""Cosine-law sun sensors on a rotating body: what a set of flat photocells reads.

TNS-0 preprint §2 (L159–L163): each sun sensor reads the cosine of the angle between its
normal and the Sun, normalised to its maximum and zero when the Sun is behind it; the Earth's
albedo adds the same law towards the Earth, scaled by the albedo ratio k. Which sensors a
spacecraft carries (their normals) is an input. For the sensors of a body in Euler-case motion
written out for thousands of candidate motions at once, see
:func:`magbench.estimation.euler_case_sun_signals` (the same law).
"""

import numpy as np

from .._validate import as_finite, as_nonnegative, as_vectors, shown

__all__ = ["sun_sensor_signals"]


def sun_sensor_signals(rotation, normals, sun, *, earth=None, albedo_ratio=0.0):
    r"""Signals of cosine-law sun sensors: max(0, n·s) + k max(0, n·e), n the normals turned by R.

    Parameters
    ----------
    rotation : array_like, shape (..., 3, 3)
        R, body → reference frame (``R @ v_body`` gives reference components) [-].
    normals : array_like, shape (k, 3)
        Unit normals of the sensors in body axes [-].
    sun : array_like, shape (3,)
        Unit vector towards the Sun in the reference frame [-].
    earth : array_like, shape (3,), optional
        Unit vector towards the Earth in the reference frame; without it, no albedo [-].
    albedo_ratio : float, optional
        k, the albedo signal of a sensor facing the Earth over that of one facing the Sun,
        >= 0 [-].

    Returns
    -------
    ndarray, shape (..., k)
        Each sensor's signal in units of its full Sun signal [-].

    Notes
    -----
    TNS-0 preprint §2 (L159–L163): the sensors' cosine law with the albedo term; the normals
    of TNS-0's sensors are not all in the text (only n1 = −n3), so they are the caller's.
    """
    r = as_finite("rotation", rotation)
    if r.ndim < 2 or r.shape[-2:] != (3, 3):
        raise ValueError(f"rotation must have shape (..., 3, 3), got shape {r.shape}")
    n = as_vectors("normals", normals)
    if n.ndim != 2:
        raise ValueError(f"normals must have shape (k, 3), got shape {n.shape}")
    s = _direction("sun", sun)
    # the normals in the reference frame, one (k, 3) set per rotation
    turned = np.einsum("tij,kj->tki", r.reshape(-1, 3, 3), n).reshape(r.shape[:-2] + n.shape)
    signal = np.clip(turned @ s, 0.0, None)
    if earth is None:
        return signal
    k = float(as_nonnegative("albedo_ratio", albedo_ratio))
    return signal + k * np.clip(turned @ _direction("earth", earth), 0.0, None)


def _direction(name, value):
    v = as_vectors(name, value)
    if v.shape != (3,):
        raise ValueError(f"{name} must be one vector of shape (3,), got shape {v.shape}")
    if abs(np.linalg.norm(v) - 1.0) > 1e-9:
        raise ValueError(f"{name} must be a unit vector, got length {shown(float(np.linalg.norm(v)))}")
    return v

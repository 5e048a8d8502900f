r"""Two-vector attitude (TRIAD): the field and the Sun, measured in body axes and modelled in
reference axes, give the attitude matrix; measurement tests reject bad pairs.

SamSat-218D §"Attitude determination" (seed lines 71–183). Vectorised over leading axes.
"""

import numpy as np

from .._validate import as_in_range, as_nonnegative, as_positive, as_vectors

__all__ = ["triad_attitude", "samsat_triad_frame", "triad_covariance", "magnitude_consistent",
           "vectors_well_separated"]


def _cross(a, b):
    """a × b on a trailing axis of 3, written out (np.cross's axis handling costs more than
    the arithmetic at the array sizes TRIAD sees)."""
    a0, a1, a2 = a[..., 0], a[..., 1], a[..., 2]
    b0, b1, b2 = b[..., 0], b[..., 1], b[..., 2]
    return np.stack([a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0], axis=-1)


def _triad_vectors(first, second, names):
    """The unit vectors p, q, r of two vectors (p along ``first``, r along first × second)."""
    cross = _cross(first, second)
    size = np.sqrt(np.sum(cross * cross, axis=-1, keepdims=True))
    norms = (np.sqrt(np.sum(first * first, axis=-1, keepdims=True)),
             np.sqrt(np.sum(second * second, axis=-1, keepdims=True)))
    if np.any(norms[0] == 0) or np.any(norms[1] == 0):
        raise ValueError(f"{names[0]} and {names[1]} must not contain zero vectors")
    if np.any(size <= 1e-12 * norms[0] * norms[1]):
        raise ValueError(f"{names[0]} and {names[1]} must not be parallel (TRIAD needs two directions)")
    p = first / norms[0]
    r = cross / size
    return p, _cross(r, p), r


def _frame(first, second, names):
    return np.stack(_triad_vectors(first, second, names), axis=-2)


def _components_cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def _components_frame(first, second, names):
    """p, q, r of two vectors given as component arrays (x, y, z), each (N,)."""
    cross = _components_cross(first, second)
    size = np.sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2])
    n1 = np.sqrt(first[0] * first[0] + first[1] * first[1] + first[2] * first[2])
    n2 = np.sqrt(second[0] * second[0] + second[1] * second[1] + second[2] * second[2])
    if np.any(n1 == 0) or np.any(n2 == 0):
        raise ValueError(f"{names[0]} and {names[1]} must not contain zero vectors")
    if np.any(size <= 1e-12 * n1 * n2):
        raise ValueError(f"{names[0]} and {names[1]} must not be parallel (TRIAD needs two directions)")
    p = tuple(c / n1 for c in first)
    r = tuple(c / size for c in cross)
    return p, _components_cross(r, p), r


#: Members per block of :func:`triad_attitude`: its temporaries (16 kB each) stay in cache
#: and below the allocator's mmap threshold; 20 000 attitudes in one array were 4x slower.
_BLOCK = 2048


def samsat_triad_frame(field, sun):
    r"""SamSat-218D's auxiliary frame of two vectors, as rows p, q, r.

    Parameters
    ----------
    field : array_like, shape (..., 3)
        Field direction H (any length, not zero) [-].
    sun : array_like, shape (..., 3)
        Sun direction S (any length, not zero, not parallel to ``field``) [-].

    Returns
    -------
    ndarray, shape (..., 3, 3)
        Rows p = Ĥ, q = (Ŝ − Ĥ(Ĥ·Ŝ)) / |Ĥ × Ŝ|, r = Ĥ × Ŝ / |Ĥ × Ŝ| [-].

    Notes
    -----
    SamSat-218D §"Attitude determination" (seed lines 113–177): the matrices a_ij (body
    axes) and c_ij (orbital axes) divided by |H × S|; their rows are p, q, r. With M_body,
    M_orb these frames in the two axes, B2 = M_bodyᵀ M_orb (seed line 181).

    Examples
    --------
    >>> samsat_triad_frame([2.0, 0.0, 0.0], [1.0, 1.0, 0.0]).tolist()
    [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
    """
    return _frame(as_vectors("field", field), as_vectors("sun", sun), ("field", "sun"))


def triad_attitude(primary_body, secondary_body, primary_reference, secondary_reference):
    r"""Attitude matrix from two vectors measured in body axes and known in reference axes.

    Parameters
    ----------
    primary_body : array_like, shape (..., 3)
        The more accurate vector (the field), in body axes; any length [-].
    secondary_body : array_like, shape (..., 3)
        The second vector (the Sun), in body axes [-].
    primary_reference : array_like, shape (..., 3)
        The primary vector in reference (orbital) axes [-].
    secondary_reference : array_like, shape (..., 3)
        The secondary vector in reference axes [-].

    Returns
    -------
    ndarray, shape (..., 3, 3)
        A with v_body = A v_reference [-]: the primary direction is matched exactly, the
        secondary only in the plane the two span.

    Notes
    -----
    SamSat-218D §"Attitude determination" (seed lines 87–183): B2 = M_bodyᵀ M_orb with
    :func:`samsat_triad_frame`; this is TRIAD (Not in the sources: Black (1964), AIAA J.
    2(7), 1350; Shuster & Oh (1981)), equal to scipy's ``Rotation.align_vectors`` with
    weights (inf, 1).

    Examples
    --------
    >>> a = triad_attitude([0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0])
    >>> np.round(a, 12).tolist()   # 90° about z
    [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]
    """
    names = ("primary_body", "secondary_body", "primary_reference", "secondary_reference")
    vectors = [as_vectors(name, value) for name, value in
               zip(names, (primary_body, secondary_body, primary_reference, secondary_reference))]
    try:
        vectors = np.broadcast_arrays(*vectors)
    except ValueError:
        raise ValueError("primary_body, secondary_body, primary_reference and secondary_reference must broadcast, "
                         f"got shapes {[v.shape for v in vectors]}") from None
    shape = vectors[0].shape[:-1]
    flat = [v.reshape(-1, 3) for v in vectors]
    out = np.empty((flat[0].shape[0], 3, 3))
    # M_bodyᵀ M_ref = Σ_k b_k r_kᵀ over the frames' vectors, component by component, in blocks.
    for start in range(0, out.shape[0], _BLOCK):
        part = [tuple(np.ascontiguousarray(v[start:start + _BLOCK].T)) for v in flat]
        body = _components_frame(part[0], part[1], names[:2])
        reference = _components_frame(part[2], part[3], names[2:])
        block = out[start:start + _BLOCK]
        for i in range(3):
            for j in range(3):
                block[:, i, j] = body[0][i] * reference[0][j] + body[1][i] * reference[1][j] + body[2][i] * reference[2][j]
    return out.reshape(shape + (3, 3))


def triad_covariance(primary_body, secondary_body, primary_sigma, secondary_sigma):
    r"""Error covariance of the TRIAD attitude (small errors), in body axes.

    Parameters
    ----------
    primary_body : array_like, shape (..., 3)
        Primary direction in body axes (any length, not zero) [-].
    secondary_body : array_like, shape (..., 3)
        Secondary direction in body axes (not parallel to the primary) [-].
    primary_sigma : array_like
        Angular noise σ1 of the primary direction, per axis perpendicular to it [rad].
    secondary_sigma : array_like
        Angular noise σ2 of the secondary direction [rad].

    Returns
    -------
    ndarray, shape (..., 3, 3)
        P = σ1² I + |b1 × b2|⁻² [(σ2² − σ1²) b1 b1ᵀ + σ1² (b1·b2)(b1 b2ᵀ + b2 b1ᵀ)] [rad²],
        the covariance of the small rotation vector δθ with A_est = exp(−[δθ×]) A.

    Notes
    -----
    Not in the sources: Shuster & Oh (1981), "Three-axis attitude determination from vector
    observations", JGCD 4(1), 70, eq. (75), for the measurement model b̂ = b + noise ⊥ b
    with covariance σ² (I − b bᵀ). SamSat-218D §"Attitude determination" keeps the field
    primary, as this covariance recommends for the more accurate vector.

    Examples
    --------
    >>> p = triad_covariance([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], 0.01, 0.05)
    >>> np.round(np.diag(p), 12).tolist()   # about b1 only the secondary helps
    [0.0025, 0.0001, 0.0001]
    """
    b1 = as_vectors("primary_body", primary_body)
    b2 = as_vectors("secondary_body", secondary_body)
    frame = _frame(b1, b2, ("primary_body", "secondary_body"))
    b1 = frame[..., 0, :]
    b2 = b2 / np.linalg.norm(b2, axis=-1, keepdims=True)
    s1 = as_nonnegative("primary_sigma", primary_sigma, unit="rad")[..., None, None]
    s2 = as_nonnegative("secondary_sigma", secondary_sigma, unit="rad")[..., None, None]
    cross2 = np.sum(np.cross(b1, b2) ** 2, axis=-1)[..., None, None]
    dot = np.sum(b1 * b2, axis=-1)[..., None, None]
    outer = b1[..., :, None] * b1[..., None, :]
    mixed = b1[..., :, None] * b2[..., None, :]
    return s1**2 * np.eye(3) + ((s2**2 - s1**2) * outer + s1**2 * dot * (mixed + np.swapaxes(mixed, -1, -2))) / cross2


def magnitude_consistent(measured_magnitude, model_magnitude, instrument_error, model_error, margin):
    r"""SamSat-218D's rejection test: does a measured modulus agree with the model's?

    Parameters
    ----------
    measured_magnitude : array_like
        Modulus of the measured vector (|H_meas| or the panel-current vector) [T or A].
    model_magnitude : array_like
        Modulus of the modelled vector [same unit].
    instrument_error : array_like
        Instrument error δ_instr, ≥ 0 [same unit].
    model_error : array_like
        Model error δ_mod, ≥ 0 [same unit].
    margin : array_like
        Safety factor K > 0 (the paper asks for K > 1; not enforced) [-].

    Returns
    -------
    ndarray of bool
        |measured − model| ≤ K (δ_instr + δ_mod) [-].

    Notes
    -----
    SamSat-218D §"Attitude determination" (seed lines 71–107): |H_meas − H_mod| ≤ K1 δH and
    |S_meas − S_mod| ≤ K2 δS, on the moduli (seed line 107). Errors that keep the modulus
    pass.

    Examples
    --------
    >>> magnitude_consistent([50e-6, 60e-6], 49e-6, 0.35e-6, 1.7e-6, 2.0).tolist()
    [True, False]
    """
    measured = as_nonnegative("measured_magnitude", measured_magnitude)
    model = as_nonnegative("model_magnitude", model_magnitude)
    instrument = as_nonnegative("instrument_error", instrument_error)
    error = as_nonnegative("model_error", model_error)
    k = as_positive("margin", margin)
    return np.abs(measured - model) <= k * (instrument + error)


def vectors_well_separated(a, b, min_angle):
    r"""Geometric test for TRIAD: are two directions at least ``min_angle`` from parallel?

    Parameters
    ----------
    a : array_like, shape (..., 3)
        First direction (any length, not zero) [-].
    b : array_like, shape (..., 3)
        Second direction (any length, not zero) [-].
    min_angle : array_like
        Smallest accepted angle between the lines of ``a`` and ``b``, in [0, π/2] [rad].

    Returns
    -------
    ndarray of bool
        |â × b̂| ≥ sin(min_angle), i.e. the angle lies in [min_angle, π − min_angle] [-].

    Notes
    -----
    Not in the sources: SamSat-218D §"Attitude determination" has no geometric test; TRIAD
    errors grow as 1/|b1 × b2| (Shuster & Oh (1981) eq. (75)); the Cp557 detumble code uses
    |â × b̂| ≥ 0.05.

    Examples
    --------
    >>> vectors_well_separated([1.0, 0.0, 0.0], [[1.0, 0.1, 0.0], [0.0, 1.0, 0.0]], np.radians(10.0)).tolist()
    [False, True]
    """
    u = as_vectors("a", a)
    v = as_vectors("b", b)
    nu, nv = np.linalg.norm(u, axis=-1), np.linalg.norm(v, axis=-1)
    if np.any(nu == 0) or np.any(nv == 0):
        raise ValueError("a and b must not contain zero vectors")
    angle = as_in_range("min_angle", min_angle, 0.0, np.pi / 2, unit="rad")
    return np.linalg.norm(np.cross(u, v), axis=-1) / (nu * nv) >= np.sin(angle)

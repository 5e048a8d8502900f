"""The magnetorquer design space: every (turns, wire) pair that meets the limits.

Thesis §3.2, eq. (32) (the band of N/U where both the power and the mass limit hold),
enumerated over real wire sizes (IEC 60317, not in the sources). SI throughout.
"""

import math

import numpy as np

from .._docstrings import fill_docstring
from .._validate import as_positive, shown
from .coil_sizing import _RTOL
from .turn import Turn, WireSizes, turn_area, turn_length

__all__ = ["coil_designs", "binding_limit", "design_magnetorquer"]


# Largest number of (turns, wire) rows the design solver will enumerate.
_MAX_ROWS = 2_000_000


#: The parameters section shared by the three solver functions (one text, three docstrings).
_PARAMETERS_DOC = """    Parameters
    ----------
    moment : float
        Required dipole moment m [A·m²].
    voltage : float
        Supply voltage U [V].
    turn : Turn
        The turn's geometry (:class:`~magbench.hardware.turn.Turn`): its shape and its
        diameter (round) or side (square) l [m], e.g. ``Turn.square(0.1)``.
    max_power : float
        Joule power limit per coil W_max [W].
    max_mass : float
        Conductor mass limit per coil M_max [kg].
    wire : WireSizes
        The wire sizes to try (:class:`~magbench.hardware.turn.WireSizes`): bare diameters
        d [m], resistivity ρ [Ω·m], density ρ̃ [kg/m³], and the enamel t [m] or overall
        diameters [m] that set the winding pitch (d + 2t or the overall diameter).
    winding_length : float, optional
        Axial length available for one layer [m]; default ``turn.side``, the thesis's
        assumption of a single-layer winding as long as the face (thesis §3.2).
    max_layers : int, optional
        Number of layers the former can hold [-].
    require_fit : bool, optional
        If true, designs whose winding does not fit are not feasible [-].

"""


_document_parameters = fill_docstring({"parameters": _PARAMETERS_DOC})


_COLUMNS = ("turns", "wire_diameter", "wire_area", "resistance", "current", "power", "mass", "moment",
            "pitch", "layer_length", "layers", "fits", "fill_factor")


def _design_inputs(moment, voltage, turn, max_power, max_mass, wire, winding_length, max_layers):
    """Checked inputs of the design solver, with the wires sorted by bare diameter.

    The turn and the wire sizes were checked when they were built (:class:`Turn`,
    :class:`WireSizes`); here only that they are those objects.
    """
    m_req = float(as_positive("moment", moment, unit="A·m²"))
    u = float(as_positive("voltage", voltage, unit="V"))
    if not isinstance(turn, Turn):
        raise ValueError(f"turn must be a Turn (e.g. Turn.square(side) [m]), got {shown(turn)}")
    l = float(turn.side)
    w_max = float(as_positive("max_power", max_power, unit="W"))
    m_max = float(as_positive("max_mass", max_mass, unit="kg"))
    if not isinstance(wire, WireSizes):
        raise ValueError(f"wire must be a WireSizes (diameters [m], resistivity [Ω·m], density [kg/m³]), "
                         f"got {shown(wire)}")
    # np.unique sorts by bare diameter and drops repeated sizes (allowed only without overall
    # diameters, where a repeat has the same pitch d + 2t)
    d_all, first = np.unique(np.array(wire.diameters), return_index=True)
    od_all = wire.pitch[first]
    length_avail = l if winding_length is None else float(
        as_positive("winding_length", winding_length, unit="m"))
    if isinstance(max_layers, bool) or not isinstance(max_layers, (int, np.integer)) or max_layers < 1:
        raise ValueError(f"max_layers must be an integer >= 1, got {shown(max_layers)}")
    return m_req, u, l, w_max, m_max, d_all, od_all, wire.resistivity, wire.density, length_avail


def _enumerate(m_req, u, l, shape, w_max, m_max, d_all, od_all, rho, gamma, length_avail, max_layers):
    """Every (turns, wire) design within the power and mass limits, and the wires that
    reach the moment: (table of arrays, [(d, n_lo, n_hi)], any design within both limits)."""
    area = float(turn_area(l, shape))
    perimeter = float(turn_length(l, shape))

    cols = {k: [] for k in ("turns", "wire_diameter", "wire_area", "resistance", "current",
                            "power", "mass", "moment", "pitch", "layer_length", "layers", "fits",
                            "fill_factor")}
    adequate = []          # wires that reach the moment: (d, n_lo, n_hi)
    n_rows = 0
    any_power_mass = False
    for d, pitch in zip(d_all, od_all):
        s_r = math.pi * d**2 / 4.0
        r = rho * perimeter / s_r
        m_wire = u * l * s_r / (4.0 * rho)
        if m_wire < m_req * (1.0 - _RTOL):
            continue
        n_lo = max(1, math.ceil(u**2 / (r * w_max) * (1.0 - _RTOL)))
        n_hi = math.floor(m_max / (gamma * perimeter * s_r) * (1.0 + _RTOL))
        adequate.append((d, n_lo, n_hi))
        if n_hi < n_lo:
            continue
        any_power_mass = True
        n_rows += n_hi - n_lo + 1
        if n_rows > _MAX_ROWS:
            raise ValueError(
                f"max_mass = {shown(m_max)} kg admits more than {_MAX_ROWS} (turns, wire) designs; "
                "tighten the limits or give fewer sizes in wire.diameters"
            )
        n = np.arange(n_lo, n_hi + 1)
        per_layer = math.floor(length_avail / pitch * (1.0 + _RTOL))
        if per_layer >= 1:
            layers = -(-n // per_layer)
        else:
            layers = np.full(n.shape, np.iinfo(np.int64).max)
        fits = layers <= max_layers
        resistance = n * r
        cols["turns"].append(n)
        cols["wire_diameter"].append(np.full(n.shape, d))
        cols["wire_area"].append(np.full(n.shape, s_r))
        cols["resistance"].append(resistance)
        cols["current"].append(u / resistance)
        cols["power"].append(u**2 / resistance)
        cols["mass"].append(gamma * perimeter * s_r * n)
        cols["moment"].append(u / resistance * area * n)
        cols["pitch"].append(np.full(n.shape, pitch))
        cols["layer_length"].append(n * pitch)
        cols["layers"].append(layers)
        cols["fits"].append(fits)
        # conductor over the window the layers occupy (layers·pitch deep); 0 if nothing fits
        depth = np.where(per_layer >= 1, layers * pitch, np.inf)
        cols["fill_factor"].append(n * s_r / (length_avail * depth))

    dtypes = {"turns": np.int64, "layers": np.int64, "fits": bool}
    out = {k: (np.concatenate(v) if v else np.array([], dtype=dtypes.get(k, float)))
           for k, v in cols.items()}
    return out, adequate, any_power_mass



def _limit(checked, adequate, any_power_mass, max_layers):
    """(kind, numbers) of the limit that leaves no design: see :func:`binding_limit`."""
    m_req, u, l, w_max, m_max, d_all, od_all, rho, gamma, length_avail, perimeter = checked
    if not adequate:
        s_need = 4.0 * rho * m_req / (u * l)
        d_max = d_all[-1]
        return "moment", {"thickest_wire": float(d_max),
                          "thickest_wire_moment": u * l * (math.pi * d_max**2 / 4.0) / (4.0 * rho),
                          "wire_area_needed": s_need, "wire_diameter_needed": math.sqrt(4.0 * s_need / math.pi)}
    if not any_power_mass:
        d, n_lo, n_hi = adequate[0]          # thinnest adequate wire: least mass × power
        s_r = math.pi * d**2 / 4.0
        m_wire = u * l * s_r / (4.0 * rho)
        product = 16.0 * rho * gamma * m_wire**2 / l**2
        numbers = {"wire": float(d), "wire_moment": m_wire, "turns_for_power": n_lo, "turns_for_mass": n_hi,
                   "mass_power_product": product, "budget_product": m_max * w_max,
                   "exact_turns_for_power": u**2 / (rho * perimeter / s_r * w_max),
                   "exact_turns_for_mass": m_max / (gamma * perimeter * s_r)}
        if product > m_max * w_max * (1.0 + _RTOL):
            return "power and mass", numbers
        return "integer turns", numbers
    return "winding fit", {"max_layers": max_layers, "winding_length": length_avail}


def _solve(moment, voltage, turn, max_power, max_mass, wire, winding_length, max_layers, require_fit):
    checked = _design_inputs(moment, voltage, turn, max_power, max_mass, wire, winding_length, max_layers)
    m_req, u, l, w_max, m_max, d_all, od_all, rho, gamma, length_avail = checked
    table, adequate, any_power_mass = _enumerate(m_req, u, l, turn.shape, w_max, m_max, d_all, od_all, rho,
                                                 gamma, length_avail, max_layers)
    if require_fit:
        keep = table["fits"]
        table = {k: v[keep] for k, v in table.items()}
    return table, (*checked, float(turn_length(l, turn.shape))), adequate, any_power_mass


@_document_parameters
def coil_designs(moment, voltage, turn, max_power, max_mass, wire, *, winding_length=None, max_layers=1,
                 require_fit=False):
    r"""Every feasible (turns, wire) design of an air-core magnetorquer, as a table.

    Thesis §3.2, eqs. (17)–(32), enumerated over a wire table: a design is feasible when
    its moment is at least ``moment``, W ≤ ``max_power`` and M ≤ ``max_mass`` (and, with
    ``require_fit``, when its winding fits).

    {parameters}

    Returns
    -------
    dict of str to ndarray
        One array entry per feasible design, ordered by wire diameter then turns:
        ``turns``, ``wire_diameter`` [m], ``wire_area`` [m²], ``resistance`` [Ω],
        ``current`` [A], ``power`` [W], ``mass`` [kg], ``moment`` [A·m²], ``pitch`` [m],
        ``layer_length`` [m], ``layers``, ``fits`` and ``fill_factor`` [-].
    """
    return _solve(moment, voltage, turn, max_power, max_mass, wire, winding_length, max_layers, require_fit)[0]


@_document_parameters
def binding_limit(moment, voltage, turn, max_power, max_mass, wire, *, winding_length=None, max_layers=1,
                  require_fit=False):
    r"""The limit that leaves no feasible design, and the numbers that show it.

    Thesis §3.2: the moment fixes the wire (eq. 20); the mass × power product, eq.
    (26)/(30), M·W = 16ρρ̃m²/l², is independent of N and U, so with the thinnest adequate
    wire it must not exceed M_max·W_max.

    {parameters}

    Returns
    -------
    tuple of (str, dict) or None
        None when a design exists; else the kind (``"moment"``, ``"power and mass"``,
        ``"integer turns"`` or ``"winding fit"``) and its numbers in SI (the wire, its
        moment, the turns each limit allows, the two products, …).
    """
    table, checked, adequate, any_power_mass = _solve(
        moment, voltage, turn, max_power, max_mass, wire, winding_length, max_layers, require_fit)
    if table["turns"].size:
        return None
    return _limit(checked, adequate, any_power_mass, max_layers)


@_document_parameters
def design_magnetorquer(
    moment,
    voltage,
    turn,
    max_power,
    max_mass,
    wire,
    *,
    winding_length=None,
    max_layers=1,
    require_fit=False,
):
    r"""Every feasible (turns, wire) design of an air-core magnetorquer, and the best two.

    A coil of N turns of wire of bare diameter d, driven at the voltage U, has
    R = N ρ P/S_r (P the turn length), draws I = U/R and W = U²/R, weighs
    M = ρ̃ P S_r N and has the moment m = I S N = U l S_r/(4ρ), independent of N (eq. 20).
    So the wire fixes the moment, and N trades power against mass. A design is feasible
    when its moment is at least ``moment``, W ≤ ``max_power`` and M ≤ ``max_mass``; every
    integer N for every listed wire is tried.

    {parameters}

    Returns
    -------
    dict
        The table of :func:`coil_designs` (``"pitch"``: d + 2t or the overall diameter;
        ``"fill_factor"``: N S_r over the window ``winding_length`` × layers·pitch), and
        ``"min_power"`` and ``"min_mass"``: the feasible design of least power and of
        least mass, each a dict of scalars, or None. ``"feasible"``
        (bool), ``"binding_limit"`` (None, ``"moment"``, ``"power and mass"``,
        ``"integer turns"`` or ``"winding fit"``) and ``"limit_numbers"`` (the numbers
        that show it, SI, as :func:`binding_limit` returns them; None when feasible).
        The command line words them (``magbench design-coil``).

    Notes
    -----
    Not in the thesis: an enumeration over a wire table of thesis eqs. (17)–(31); the
    thesis solves the continuous problem (eq. 32) and then picks 0.2 mm wire at N = 240,
    which this solver rejects (2.69 W > 2 W). The infeasibility test is the mass × power
    product, eq. (26)/(30): with the thinnest adequate wire, M·W = 16ρρ̃m_w²/l² must not
    exceed M_max·W_max, where m_w ≥ m is that wire's moment.

    Examples
    --------
    >>> copper = WireSizes([0.18e-3, 0.2e-3], 0.0175e-6, 8.9e3)
    >>> res = design_magnetorquer(0.4, 12.0, Turn.square(0.1), 2.0, 0.1, copper)
    >>> best = res["min_mass"]
    >>> int(best["turns"]), round(best["wire_diameter"] * 1e3, 2), round(best["power"], 3)
    (262, 0.18, 1.998)
    >>> design_magnetorquer(0.4, 12.0, Turn.square(0.1), 1.0, 0.02,
    ...                     WireSizes([0.2e-3], 0.0175e-6, 8.9e3))["binding_limit"]
    'power and mass'
    """
    table, checked, adequate, any_power_mass = _solve(
        moment, voltage, turn, max_power, max_mass, wire, winding_length, max_layers, require_fit)
    out = dict(table)
    out["feasible"] = feasible = out["turns"].size > 0
    out["min_power"] = out["min_mass"] = None
    out["binding_limit"] = out["limit_numbers"] = None
    if feasible:
        for label, col in (("min_power", "power"), ("min_mass", "mass")):
            i = int(np.argmin(out[col]))
            out[label] = {k: out[k][i].item() for k in _COLUMNS}
        return out
    out["binding_limit"], out["limit_numbers"] = _limit(checked, adequate, any_power_mass, max_layers)
    return out

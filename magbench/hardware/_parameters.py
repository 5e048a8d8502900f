"""The coil parameters the hardware modules share, each described once (numpydoc entries for
:func:`magbench._docstrings.fill_docstring`)."""

from .._docstrings import fill_docstring

#: Every function that takes one of these checks it as the text says.
COIL_PARAMETERS = {
    "turns": """turns : array_like
    Number of turns N [-], > 0.""",
    "side": """side : array_like
    Turn diameter (round) or side (square) l [m], > 0.""",
    "shape": """shape : {"round", "square"}, optional
    Turn shape [-].""",
    "wire_area": """wire_area : array_like
    Conductor cross-section S_r [m²], > 0.""",
    "resistivity": """resistivity : array_like
    Conductor resistivity ρ [Ω·m], > 0.""",
    "density": """density : array_like
    Conductor density ρ̃ [kg/m³], > 0.""",
    "moment": """moment : array_like
    Required dipole moment m [A·m²].""",
    "voltage": """voltage : array_like
    Supply voltage U [V].""",
    "winding_length": """winding_length : array_like
    Axial length of the winding L [m], > 0.""",
    "turn": """turn : Turn or array_like
    The turn's geometry (:class:`~magbench.hardware.turn.Turn`), or the coil radius
    a_c of a round turn [m], > 0.""",
    "wire_diameter": """wire_diameter : array_like
    Bare conductor diameter d_w [m], > 0.""",
    "current": """current : array_like
    Current I [A].""",
    "resistance": """resistance : array_like
    Coil resistance R [Ω], > 0.""",
    "max_power": """max_power : array_like
    Joule power limit W_max [W], > 0.""",
    "max_mass": """max_mass : array_like
    Conductor mass limit M_max [kg], > 0.""",
}

document_coil = fill_docstring(COIL_PARAMETERS)

"""Figures of chapter 6 (the rotor slides and Kovalenko ch. 7)."""

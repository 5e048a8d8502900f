"""Figures of chapter 5 (registered on import)."""

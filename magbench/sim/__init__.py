"""Simulations composed from the physics families: the mock-up's PID loop (for now).

The bench loop still lives in :mod:`magbench.bench`.
"""

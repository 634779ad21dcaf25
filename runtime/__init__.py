"""Compiled integrators, simulation API, post-processing and command line."""

"""Symbolic layer: model declarations, Lagrange's equations, cam laws, code generation."""

"""Translating roller follower with a flexible (Rayleigh-beam) rod in a grooved disk cam (issue 5, paper)."""

"""Shared helpers for the test suite."""
import numpy as np
import pytest

from camdyn.runtime.checks.spine import residual_of  # noqa: F401  (cached runs, shared with the checks)


@pytest.fixture
def rng():
    return np.random.default_rng(20261122)

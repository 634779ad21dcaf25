"""Shared helpers for the test suite."""
import os

# make test runs one pytest worker per core (xdist): a multithreaded BLAS in each would
# oversubscribe the cores and slow small dense solves a hundredfold
for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402
import pytest  # noqa: E402

from camdyn.thesis.checks.spine_checks import residual_of  # noqa: F401  (cached runs, shared with the checks)


@pytest.fixture
def rng():
    return np.random.default_rng(20261122)

"""Chains of sec. 3.7: transfer functions, partial fractions and the compiled 3-DOF chain."""
import numpy as np
import pytest
import sympy as sp

from camdyn.thesis.checks.chains_checks import simulated_modal_amplitudes
from camdyn.thesis.theory import chains


@pytest.mark.parametrize("n", [1, 2, 3, 4, 5])
def test_eigenvalues_match_numpy(n, rng):
    """The roots of Delta (3.19) are the eigenvalues of M^-1 C of the chain (2.47), (2.50)."""
    m, c = rng.uniform(0.5, 2.0, n), rng.uniform(0.5, 2.0, n)
    md = chains.modes(m.tolist(), c.tolist(), n - 1)
    M, C, _ = chains.chain_matrices(list(m), list(c))
    ref = np.sort(np.linalg.eigvals(np.array(M.inv() * C, dtype=float)).real)
    np.testing.assert_allclose(md.lams, ref, rtol=1e-10)


@pytest.mark.parametrize("output", [0, 1, 2])
def test_partial_fractions_rebuild_the_transfer_function(output, rng):
    """sum A_i/(s + lambda_i) equals N/Delta at random s (3.20)."""
    m, c = rng.uniform(0.5, 2.0, 3), rng.uniform(0.5, 2.0, 3)
    N, delta = chains.transfer([sp.nsimplify(x) for x in m], [sp.nsimplify(x) for x in c], output)
    md = chains.modes(m.tolist(), c.tolist(), output)
    for s in rng.uniform(-5, 5, 5):
        direct = float(N.subs(chains.s, s) / delta.as_expr().subs(chains.s, s))
        assert sum(md.A / (s + md.lams)) == pytest.approx(direct, rel=1e-9)


def test_static_gains_sum_to_one():
    """At D = 0 every mass follows the input: sum A_i/lambda_i = 1 for every output."""
    for output in range(3):
        md = chains.modes([1, 2, 0.5], [3, 1, 2], output)
        assert float(np.sum(md.A / md.lams)) == pytest.approx(1.0, rel=1e-12)


@pytest.mark.parametrize("tau1", [2 / 7, 0.15, 0.4])
@pytest.mark.parametrize("output", [1, 2])
def test_compiled_chain_splits_into_one_dof_systems(tau1, output):
    """The residual amplitude of each mode of the compiled chain3 model equals the one-DOF
    law (3.5) weighted by its partial-fraction gain (3.20), to 1e-6: the modal picture of
    sec. 3.7.3 holds for the generated equations."""
    sim = simulated_modal_amplitudes(tau1, output)
    pred = chains.predicted_modal_amplitudes(tau1, output)
    np.testing.assert_allclose(sim, pred, rtol=1e-6)


def test_lowest_mode_dominates_unequal_chain():
    """A heavy output mass (m3 = 10, the usual case, sec. 3.7.3) makes the lowest mode even
    more dominant than in the unit chain."""
    unit = simulated_modal_amplitudes(2 / 7, 2)
    heavy = simulated_modal_amplitudes(2 / 7, 2, masses=(1, 1, 10))
    assert heavy[0] / heavy.sum() > unit[0] / unit.sum() > 0.99

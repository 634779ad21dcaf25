"""Checks of the three-DOF chain of sec. 3.7 (figs 3.6, 3.7) against the thesis."""
from __future__ import annotations

from functools import lru_cache

import numpy as np

from .check import Check

UNIT = ([1, 1, 1], [1, 1, 1])
FIG = {"3.6": 1, "3.7": 2}   # output mass (0-based) of each figure, see derive/models/chain3.py


@lru_cache(maxsize=None)
def _modes(fig: str):
    from camdyn.thesis.theory import chains

    return chains.modes(*UNIT, FIG[fig])


def _ratio(fig: str, quantity: str, i: int) -> float:
    return float(_modes(fig).contributions(quantity)[i])


def _rule(quantity: str, i: int) -> float:
    return float(_modes("3.6").rule_of_thumb(quantity)[i])


def _transfer_identity() -> bool:
    """(3.18): x2/h = c1 c2 (D^2 + c3/m3)/(m1 m2 Delta) for the chain of fig. 3.6."""
    import sympy as sp

    from camdyn.thesis.theory import chains

    m = sp.symbols("m1:4", positive=True)
    c = sp.symbols("c1:4", positive=True)
    N, _ = chains.transfer(list(m), list(c), 1)
    return sp.simplify(N - c[0] * c[1] / (m[0] * m[1]) * (chains.s + c[2] / m[2])) == 0


def _partial_fraction_identity() -> bool:
    """(3.20): N/prod(D^2 + lambda_i) = sum A_i/(D^2 + lambda_i) with A_i = N(-lambda_i)/prod(...)."""
    import sympy as sp

    from camdyn.thesis.theory import chains

    lam = sp.symbols("lambda1:4", positive=True)
    k, a = sp.symbols("k a", positive=True)
    N = k * (chains.s + a)
    A = chains.residues(N, lam)
    lhs = N / sp.Mul(*[chains.s + li for li in lam])
    return sp.simplify(lhs - sum(Ai / (chains.s + li) for Ai, li in zip(A, lam))) == 0


def _same_ratios() -> bool:
    """(3.25) is identical with (3.23): U0'' and U_sn both scale as |A_i|/w_i^3."""
    import numpy as np

    return all(np.array_equal(_modes(f).contributions("U0dd"), _modes(f).contributions("U_sn"))
               for f in FIG)


def simulated_modal_amplitudes(tau1: float, output: int, masses=(1, 1, 1), springs=(1, 1, 1),
                               law: str = "cycloidal", rtol: float = 1e-11) -> np.ndarray:
    """Residual amplitude of each mode at mass ``output`` of the compiled chain3 model.

    The chain is run through the cam rise with the reference period chosen so
    that the lowest mode has tau_1 = tau1; the state at the end of the rise is
    split into M-orthonormal modes (free vibration about X = 1 afterwards),
    giving per mode sqrt(eta^2 + (eta'/w)^2) times the mode's share at the output.
    """
    from camdyn.runtime.core.simulator import simulate

    from camdyn.thesis.theory import chains

    M = np.diag(np.asarray(masses, dtype=float))
    Mn, Cn, _ = chains.chain_matrices(list(masses), list(springs))
    lam, phi = chains.generalized_eig(np.array(Cn, dtype=float), M)
    tau = tau1 * np.sqrt(lam[0])        # reference period: w_1 = sqrt(lam_1) (2 pi/tau)
    params = {"tau": tau, **{f"m{i + 1}": float(m) for i, m in enumerate(masses)},
              **{f"c{i + 1}": float(c) for i, c in enumerate(springs)}}
    res = simulate("chain3", params, 1.0, "dp54", rtol=rtol, law=law)
    x, v = res.y[-1, :3] - 1.0, res.y[-1, 3:]
    w = np.sqrt(lam) * 2 * np.pi / tau
    eta, etad = phi.T @ M @ x, phi.T @ M @ v
    return np.abs(phi[output]) * np.hypot(eta, etad / w)


def _lowest_mode_share() -> float:
    amps = simulated_modal_amplitudes(tau1=2 / 7, output=1)
    return float(amps[0] / amps.sum())


def checks() -> list[Check]:
    out = [Check(f"ch3_7.eigenvalue.{i + 1}", f"unit chain of fig. 3.6: w_e{i + 1}^2", "(3.19), sec. 3.7.3",
                 printed, lambda i=i: float(_modes("3.6").lams[i]), exact=True)
           for i, printed in enumerate(("0.198", "1.555", "3.247"))]
    out += [
        Check("ch3_7.transfer", "x2/h by Cramer's rule: c1 c2 (D^2 + c3/m3)/(m1 m2 Delta)", "(3.17), (3.18)",
              None, _transfer_identity, rule="identity",
              note="fig. 3.6 read as output x2 with (c3, m3) beyond it: the numerators of (3.21)"),
        Check("ch3_7.partial_fractions", "partial fractions of the transfer function", "(3.20)", None,
              _partial_fraction_identity, rule="identity"),
        Check("ch3_7.eq3_25_equals_3_23", "residual-acceleration ratios equal the impact ratios",
              "(3.25), (3.23)", None, _same_ratios, rule="identity"),
    ]
    printed = {  # (equation, quantity, figure): printed ratios of modes 2 and 3 to mode 1
        ("(3.21)", "U0", "3.6"): ("7.3e-3", "2.1e-3"),
        ("(3.21)", "U0", "3.7"): ("1.1e-2", "7e-4"),
        ("(3.23)", "U_sn", "3.6"): ("5.7e-2", "3.4e-2"),
        ("(3.23)", "U_sn", "3.7"): ("8e-2", "1.2e-2"),
        ("(3.25)", "U0dd", "3.6"): ("5.7e-2", "3.4e-2"),
        ("(3.25)", "U0dd", "3.7"): ("8e-2", "1.2e-2"),
        ("(3.27)", "U_sn_dd", "3.6"): ("0.44", "0.56"),
        ("(3.27)", "U_sn_dd", "3.7"): ("0.64", "0.2"),
    }
    near = {("U0", "3.6", 1): ("rel:0.02", "computed 7.22e-3, 1 % below the printed 7.3e-3 (the thesis's "
                                           "arithmetic, also with its three-digit eigenvalues)"),
            ("U0", "3.7", 1): ("rel:0.06", "computed 1.04e-2: the printed 1.1e-2 is 5 % high"),
            ("U_sn_dd", "3.6", 2): ("rel:0.01", "computed 0.555 (0.44504 + 0.55496 = 1): the thesis rounds "
                                                "it up to 0.56 and the other down to 0.44")}
    for (eq, q, fig), values in printed.items():
        for i, p in enumerate(values, start=1):
            rule, note = near.get((q, fig, i), ("digits", ""))
            out.append(Check(f"ch3_7.{q}.fig{fig}.mode{i + 1}", f"{q} of mode {i + 1} over mode 1, fig. {fig}",
                             eq, p, lambda q=q, fig=fig, i=i: _ratio(fig, q, i), rule=rule, note=note,
                             exact=True))
    for eq, q, values in (("(3.22)", "U0", ("5.8e-3", "9e-4")), ("(3.24)", "U_sn", ("4.5e-2", "1.5e-2"))):
        for i, p in enumerate(values, start=1):
            out.append(Check(f"ch3_7.rule.{q}.mode{i + 1}", f"rule of thumb for {q}, mode {i + 1} over mode 1",
                             eq, p, lambda q=q, i=i: _rule(q, i), exact=True))
    out.append(Check("ch3_7.simulated_dominance", "share of the lowest mode in the residual amplitude of x2, "
                     "3-DOF chain simulated through generated code (tau1 = 2/7)", "sec. 3.7.3, 3.8", "1",
                     _lowest_mode_share, rule="abs:0.01",
                     note="'the lowest natural frequency dominates the dynamic response'"))
    return out

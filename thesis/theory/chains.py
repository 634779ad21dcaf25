"""Lumped chains driven by the cam: transfer functions and modal contributions (sec. 3.7).

A chain of n masses m_i and springs c_i, the cam motion h entering through
c_1 (the series chain (2.47)), obeys (D^2 M + C) x = K h with D = d/dt.  By
Cramer's rule (3.17) the response of mass k is x_k/h = N_k(D^2)/Delta(D^2)
(3.18); the roots -lambda_i of Delta, lambda_i = w_ei^2, are the eigenvalues
(3.19), and partial fractions (3.20) split the response into one
single-degree-of-freedom system per natural frequency,

    x_k/h = sum_i A_i/(D^2 + lambda_i),   A_i = N_k(-lambda_i)/prod_{j != i}(lambda_j - lambda_i).

Mode i is then the one-DOF system of ch. 3 with static gain A_i/lambda_i and
w_ei = sqrt(lambda_i), so its residual amplitudes scale as that gain times
the one-DOF laws: tau^3 for U0 (3.5) (all: |A_i|/w_i^5, (3.21)), tau for
the impact amplitude U_sn (3.11) and w^2 tau^3 for U0'' (|A_i|/w_i^3,
(3.23), (3.25)), and w^2 tau for the impact acceleration (|A_i|/w_i, (3.27)).
The rules of thumb (3.22), (3.24), (3.26) drop the numerators and
differences and keep 1/w_i^5 and 1/w_i^3.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import sympy as sp

s = sp.Symbol("s")
"""D^2, the squared differential operator of (2.49), (3.17)."""

POWERS = {"U0": 5, "U_sn": 3, "U0dd": 3, "U_sn_dd": 1}
"""Power p of w_ei in |A_i|/w_ei^p for each residual quantity, (3.21)-(3.27)."""


def chain_matrices(masses, springs):
    """M, C and the input vector K of the chain (2.47)-(2.48): h -> c1 -> m1 -> c2 -> m2 ..."""
    n = len(masses)
    masses = [sp.sympify(float(m) if hasattr(m, "dtype") else m) for m in masses]
    springs = [sp.sympify(float(c) if hasattr(c, "dtype") else c) for c in springs]
    M = sp.diag(*masses)
    C = sp.zeros(n, n)
    for i, c in enumerate(springs):
        C[i, i] += c
        if i > 0:
            C[i - 1, i - 1] += c
            C[i - 1, i] -= c
            C[i, i - 1] -= c
    K = sp.zeros(n, 1)
    K[0] = springs[0]
    return M, C, K


def transfer(masses, springs, output: int):
    """(N, Delta) with x_output/h = N(s)/Delta(s), by Cramer's rule (3.17), M divided out."""
    M, C, K = chain_matrices(masses, springs)
    A = (s * M + C)
    Minv = M.inv()
    A, b = Minv * A, Minv * K
    delta = sp.expand(A.det())
    Ak = A.copy()
    Ak[:, output] = b
    return sp.factor(Ak.det()), sp.Poly(delta, s)


def residues(N, lams):
    """A_i of the partial fractions (3.20) at the eigenvalues lambda_i."""
    out = []
    for i, li in enumerate(lams):
        den = 1
        for j, lj in enumerate(lams):
            if j != i:
                den *= (lj - li)
        out.append(N.subs(s, -li) / den)
    return out


@dataclass(frozen=True)
class ChainModes:
    """Eigenvalues and partial-fraction weights of one chain and output."""

    lams: np.ndarray            # w_ei^2, ascending (3.19)
    A: np.ndarray               # residues of x_out/h at -lambda_i (3.20)

    def contributions(self, quantity: str) -> np.ndarray:
        """|A_i|/w_ei^p normalised to the lowest mode: (3.21), (3.23), (3.25), (3.27)."""
        p = POWERS[quantity]
        w = np.sqrt(self.lams)
        c = np.abs(self.A) / w**p
        return c / c[0]

    def rule_of_thumb(self, quantity: str) -> np.ndarray:
        """(3.22), (3.24), (3.26): inversely proportional to w_ei^p."""
        w = np.sqrt(self.lams)
        return (w[0] / w) ** POWERS[quantity]


def modes(masses, springs, output: int) -> ChainModes:
    """Numerical eigenvalues and residues of a chain with numeric masses and stiffnesses."""
    N, delta = transfer([sp.nsimplify(m) for m in masses], [sp.nsimplify(c) for c in springs], output)
    roots = np.sort(np.real(np.roots([float(c) for c in delta.all_coeffs()])))
    lams = -roots[::-1]
    A = np.array([float(a) for a in residues(N, [sp.Float(l, 30) for l in lams])])
    return ChainModes(lams, A)


def generalized_eig(C: np.ndarray, M: np.ndarray):
    """Eigenvalues (ascending) and M-orthonormal mode shapes of C phi = lam M phi."""
    from scipy.linalg import eigh

    lam, phi = eigh(C, M)
    return lam, phi


def predicted_modal_amplitudes(tau1: float, output: int, masses=(1, 1, 1), springs=(1, 1, 1)):
    """The same amplitudes from the partial fractions (3.20) and the one-DOF law (3.5) per mode:
    |A_i/lambda_i| tau_i^3/(1 - tau_i^2)/pi |sin(pi/tau_i)|, tau_i = tau_1 sqrt(lambda_1/lambda_i)."""
    md = modes(list(masses), list(springs), output)
    tau_i = tau1 * np.sqrt(md.lams[0] / md.lams)
    gain = np.abs(md.A / md.lams)
    return gain * tau_i**3 / (1 - tau_i**2) / np.pi * np.abs(np.sin(np.pi / tau_i))

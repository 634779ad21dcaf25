"""Roller vibration (thesis sec. 9.2.1): the roller's mass and the contact
stiffness in series with the follower linkage (derive/models/roller.py, generated/roller.pyx).

References, each independent of the model's own output:
* the massless, rigid-contact limit is the one-DOF follower of sec. 3.3, whose residual
  vibration has the closed form (3.5) (camdyn.runtime.measure.references.U0) and whose largest
  deceleration comes from the one_dof model checked against (3.4) elsewhere;
* the natural frequencies with the roller on its wall solve det(K - w^2 M) = 0 of the two-mass
  chain (closed form below), compared with the eigenvalues of a central-difference Jacobian of
  the compiled right-hand side;
* the contact-force peak after the backlash is traversed is the impact of a mass on a spring,
  k d_max = F + (F^2 + m k v_b^2)^(1/2) with F the force pushing it in (sec. 3.6's
  F_b = v_b (m c)^(1/2) when F = 0).
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from camdyn.runtime.engine import driver
from camdyn.runtime.measure import references as closed_forms
from camdyn.runtime.core.compiled import load
from camdyn.runtime.measure.residual import residual
from camdyn.runtime.core.simulator import Simulator

TAU = 0.15
W = 2 * math.pi / TAU


def _run(t_end=3.0, rtol=1e-9, **p):
    return Simulator("roller", t_end, "dp54", rtol=rtol, max_steps=5_000_000).run(p)


def test_light_stiff_roller_approaches_the_massless_follower():
    """mu = m_r/m = 1e-3, kappa = k_c/c = 1e5, backlash 1e-4 h_m, contact damping 0.2: the
    follower's residual vibration U0 within 5 % of (3.5) at tau = 0.15 (measured 3.0 %) and
    its largest deceleration within 3 % of the one-DOF model's (measured 2.4 %); the heavier,
    softer roller (mu = 0.05, kappa = 1000, backlash 1e-3) is further off (measured 12 %): the
    high-frequency roller hardly affects the follower as the roller becomes light and the
    contact stiff (sec. 9.2.1)."""
    U0_ref = closed_forms.U0(TAU)
    one = residual(Simulator("one_dof", 3.0, "dp54", rtol=1e-10).run({"tau": TAU}))
    light = residual(_run(mu=1e-3, kappa=1e5, S=1e-4, zeta=0.2))
    heavy = residual(_run(mu=0.05, kappa=1e3, S=1e-3, zeta=0.2))
    assert abs(light.U0 / U0_ref - 1) < 0.05
    assert abs(light.Xdd_min_rise / one.Xdd_min_rise - 1) < 0.03
    assert abs(heavy.U0 / U0_ref - 1) > abs(light.U0 / U0_ref - 1)


@pytest.mark.parametrize("mu,kappa", [(0.05, 100.0), (0.05, 1000.0), (0.01, 1000.0)])
def test_natural_frequencies_of_the_roller_on_its_wall(mu, kappa):
    """Eigenvalues of the Jacobian (central differences of the compiled rhs, roller pressed
    1e-6 h_m into the lower wall, before the rise) against the closed form of the two-mass
    chain, w^2 = roots of det(K - w^2 M), M = diag(mu, 1), K = omega^2 [[kappa + 1, -1],
    [-1, 1]] (undamped): relative 1e-6."""
    m = load("roller")
    p = m.parameter_vector({"mu": mu, "kappa": kappa, "zeta": 0.0, "q": 0.0})
    codes = np.array([0], dtype=np.intc)     # cycloidal
    pars = np.zeros(1)
    names = m.state_names
    y = np.zeros(len(names))
    y[names.index("R")] = -1e-6
    t = -0.5                                 # in the dwell before the rise
    J = np.empty((len(y), len(y)))
    for j in range(len(y)):
        h = 1e-9
        yp, ym = y.copy(), y.copy()
        yp[j] += h
        ym[j] -= h
        f = driver.eval_rhs(m.capsule, p, codes, pars, np.full(2, t), np.array([yp, ym]))
        J[:, j] = (f[0] - f[1]) / (2 * h)
    w_num = np.sort(np.abs(np.linalg.eigvals(J).imag))[::2]
    M = np.diag([mu, 1.0])
    K = W**2 * np.array([[kappa + 1, -1.0], [-1.0, 1.0]])
    w_ref = np.sort(np.sqrt(np.linalg.eigvals(np.linalg.solve(M, K)).real))
    assert w_num == pytest.approx(w_ref, rel=1e-6)


@pytest.mark.parametrize("S", [0.01, 0.003])
def test_contact_force_peak_after_backlash_is_the_impact_estimate(S):
    """The roller leaves the lower wall where the deceleration begins, crosses the backlash S
    and hits the upper wall at v_b (undamped contact, mu = 0.05, kappa = 1000).  The peak of
    the contact force before it lets go again against k d_max = F + (F^2 + F_b^2)^(1/2),
    F_b = v_b (m_r k_c)^(1/2) (sec. 3.6, 9.2.1) and F the force pushing the roller into the
    wall (the linkage's, less m_r H'' of the moving wall): relative 1e-3 (measured 1e-4); and
    within 1 % of F_b alone (measured 0.1 %, 0.6 %), three to four times the largest force the
    linkage carries in the whole run (measured 4.0, 3.5)."""
    mu, kappa = 0.05, 1000.0
    res = _run(t_end=1.5, rtol=1e-10, S=S, zeta=0.0, kappa=kappa, mu=mu)
    modes = res.element_mode("contact")
    changes = [(float(res.t[j + 1]), modes[j + 1]) for j in np.flatnonzero(modes[1:] != modes[:-1])]
    t_hit = next(t for t, v in changes if v == "upper")
    t_off = next(t for t, v in changes if t > t_hit)
    at = res.sample(np.array([t_hit]))
    v_b = at["V_rel"][0]
    F_b = v_b * math.sqrt(mu * kappa) * W
    F = -at["F_link"][0] - mu * 2 * math.pi * math.sin(2 * math.pi * t_hit)   # cycloid H''
    peak = np.abs(res.sample(np.linspace(t_hit, t_off, 4001))["Fc"]).max()
    assert peak == pytest.approx(F + math.sqrt(F**2 + F_b**2), rel=1e-3)
    assert peak == pytest.approx(F_b, rel=1e-2)
    assert peak > 3 * np.abs(res.sample(np.linspace(0, 1.5, 3001))["F_link"]).max()

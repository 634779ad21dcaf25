"""NumPy references for the Rayleigh-beam follower, independent of SymPy and of the generated
code (used by tests/test_beam_energy.py and tests/test_beam.py; not a test module).

What is typed here from the physics, not taken from camdyn:

* the cycloidal RDFD motion of paper (1) and fig. 2 (rise on [0, beta_r), outer dwell to pi,
  fall on [pi, pi + beta_r), inner dwell to 2 pi), with the first two derivatives;
* the energies the model declares (derive/models/beam.py, paper (8)-(12)), integrated over
  the free rod [0, x_E] by Gauss-Legendre quadrature from the sampled states;
* the partial time derivative Phi_t of the constraints (6), (7) and the cam's power
  lambda^T Phi_t;
* a finite-element Rayleigh cantilever (Hermite cubic elements, consistent mass with the
  rotary-inertia term, clamped at the guide exit, a point mass at the tip), and a
  Rayleigh-Ritz model in the model's polynomials (x/d)^2 .. (x/d)^(N+1), with their modal
  free responses.

``p`` is a dict of the generated model's parameter values by manifest name: ``Result.params``
(Omega, d, r_b, r_r, S_T, beta_r, a_rod, E, rho, m_r, J_r, rayleigh, L_g, ...), or
``camdyn.runtime.targets.beam.parameters(case)`` for the dwell functions, which need no beta_r, L_g.
"""
import math

import numpy as np
import scipy.linalg as sla

# the integrands over [0, x_E] are polynomials in x of degree <= 2 N + 2 <= 14 for N <= 6:
# 8 Gauss points integrate them exactly
_GAUSS_X = np.polynomial.legendre.leggauss(8)


def rdfd(theta, beta):
    """R, dR/dtheta, d2R/dtheta2 (rows) of the normalized RDFD motion at the cam angles
    ``theta``: the cycloid T - sin(2 pi T)/(2 pi), T = theta/beta, on the rise (paper (1)),
    1 on the outer dwell, 1 minus the rise on the fall, 0 on the inner dwell; period 2 pi."""
    u = np.mod(np.asarray(theta, dtype=float), 2 * np.pi)
    fall = u >= np.pi
    u = np.where(fall, u - np.pi, u)
    moving = u < beta
    T = np.where(moving, u / beta, 0.0)
    w = 2 * np.pi * T
    rise = np.array([T - np.sin(w) / (2 * np.pi), (1 - np.cos(w)) / beta,
                     2 * np.pi * np.sin(w) / beta**2])
    top = np.array([1.0, 0.0, 0.0]).reshape((3,) + (1,) * u.ndim)
    h = np.where(moving, rise, top)
    return np.where(fall, top - h, h)


def section(p):
    """rho A, rho I, E I of the rod's circular section of radius a_rod (I = pi a^4/4)."""
    A, I = math.pi * p["a_rod"] ** 2, math.pi * p["a_rod"] ** 4 / 4
    return p["rho"] * A, p["rho"] * I, p["E"] * I


def pitch(p, theta):
    """r = r_b + r_r + S, S' and S'' at the cam parameter theta."""
    R = rdfd(theta, p["beta_r"])
    return p["r_b"] + p["r_r"] + p["S_T"] * R[0], p["S_T"] * R[1], p["S_T"] * R[2]


def _powers(x, d, n, order):
    """d^order/dx^order of (x/d)^k, k = 2 .. n+1 (first axis), at the points x."""
    k = np.arange(2, n + 2).reshape((n,) + (1,) * np.ndim(x))
    c = np.ones_like(k, dtype=float)
    for j in range(order):
        c = c * (k - j)
    return c * (x / d) ** np.maximum(k - order, 0) / d**order


def energies(p, s, n):
    """The model's energies (derive/models/beam.py; paper (8)-(12)) at the sampled states
    ``s`` (dict of arrays: b1..bN, xE, theta and their rates b1d.., xEd, thetad) with N = n.

    v = sum b_i (x/d)^(i+1) (13); Dv/Dt = v_t + x_E' v_x (the rod slides out at x_E').
    Returns a dict: rod_kinetic = rho A/2 (x_E x_E'^2 + int (Dv/Dt)^2 dx), rotary =
    rayleigh rho I/2 int (D v_x/Dt)^2 dx, strain = E I/2 int v_xx^2 dx, roller_translation =
    m_r (vE_dot^2 + x_E'^2)/2 (vE_dot the total rate of v(x_E(t), t)), roller_rotation =
    J_r w_n^2/2, guide = rho A L_g x_E'^2/2, their sum ``total``, and w_n = Omega - theta'
    (1 - phi'(theta)), phi = atan(S'/r) the pressure angle."""
    rho_A, rho_I, EI = section(p)
    d = p["d"]
    xE, xEd = np.asarray(s["xE"]), np.asarray(s["xEd"])
    b = np.array([s[f"b{i}"] for i in range(1, n + 1)])
    bd = np.array([s[f"b{i}d"] for i in range(1, n + 1)])
    g, w = _GAUSS_X
    x = (g[:, None] + 1) / 2 * xE            # (point, time)
    dx = w[:, None] * xE / 2

    def field(coef, order):
        return np.einsum("kt,kjt->jt", coef, _powers(x, d, n, order))

    v_x, v_xx = field(b, 1), field(b, 2)
    Dv = field(bd, 0) + xEd * v_x
    Dv_x = field(bd, 1) + xEd * v_xx
    vE_dot = (bd * _powers(xE, d, n, 0)).sum(0) + xEd * (b * _powers(xE, d, n, 1)).sum(0)
    r, S1, S2 = pitch(p, s["theta"])
    phi_theta = (S2 * r - S1**2) / (r**2 + S1**2)   # d/dtheta atan(S'/r), r' = S'
    w_n = p["Omega"] - np.asarray(s["thetad"]) * (1 - phi_theta)
    out = {
        "rod_kinetic": rho_A / 2 * (xE * xEd**2 + (dx * Dv**2).sum(0)),
        "rotary": p["rayleigh"] * rho_I / 2 * (dx * Dv_x**2).sum(0),
        "strain": EI / 2 * (dx * v_xx**2).sum(0),
        "roller_translation": p["m_r"] * (vE_dot**2 + xEd**2) / 2,
        "roller_rotation": p["J_r"] * w_n**2 / 2,
        "guide": rho_A * p["L_g"] * xEd**2 / 2,
    }
    out["total"] = sum(out.values())
    out["w_n"] = w_n
    return out


def constraints(p, t, s, n):
    """Phi_1 = r sin u - v(x_E), Phi_2 = r cos u + x_E - d, u = Omega t - theta (paper (6),
    (7)), and their partial time derivatives Phi_t = (r Omega cos u, -r Omega sin u)."""
    r, _, _ = pitch(p, s["theta"])
    u = p["Omega"] * np.asarray(t) - s["theta"]
    b = np.array([s[f"b{i}"] for i in range(1, n + 1)])
    vE = (b * _powers(np.asarray(s["xE"]), p["d"], n, 0)).sum(0)
    Phi = (r * np.sin(u) - vE, r * np.cos(u) + s["xE"] - p["d"])
    Phi_t = (r * p["Omega"] * np.cos(u), -r * p["Omega"] * np.sin(u))
    return Phi, Phi_t


def contact_power(p, s, n):
    """lambda^T Phi_t at the samples ``s`` (with t, lambda1, lambda2): the power of the
    generalized constraint force -Phi_Q^T lambda along Q', since Phi_Q Q' = -Phi_t."""
    _, Phi_t = constraints(p, s["t"], s, n)
    return s["lambda1"] * Phi_t[0] + s["lambda2"] * Phi_t[1]


def step_quadrature(t, points):
    """Gauss-Legendre nodes (flat) and weights (steps x points) over each recorded step of
    positive length, and the indices into t of the step ends, the first being t[0]."""
    a, b = t[:-1], t[1:]
    keep = b > a                   # a breakpoint is recorded twice: a step of zero length
    g, w = np.polynomial.legendre.leggauss(points)
    h = (b - a)[keep]
    nodes = (a[keep][:, None] + h[:, None] * (g + 1) / 2).ravel()
    return nodes, h[:, None] * w / 2, np.concatenate([[0], np.nonzero(keep)[0] + 1])


def cumulative_integral(values, weights):
    """int_{t_0}^{t_k} of the sampled integrand at every step end (0 at the start)."""
    per_step = (values.reshape(weights.shape) * weights).sum(1)
    return np.concatenate([[0.0], np.cumsum(per_step)])


# -- the rod frozen in a dwell: finite elements and Ritz ------------------------------------------

def dwell_tip_mass(p, r):
    """The point mass at the pin in a dwell: the pitch curve is the circle of radius r, so the
    roller's rotation there is w_n = d/dt asin(v_E/r) = v_E'/r to first order (phi' = 0,
    theta' = Omega - u'), and J_r w_n^2/2 adds J_r/r^2 to m_r."""
    return p["m_r"] + p["J_r"] / r**2


def dwell_cantilever(p, inner=False):
    """The rod frozen in the outer dwell (pitch radius r = r_b + r_r + S_T), or the inner one
    (r = r_b + r_r): a cantilever of length L = d - r with the Rayleigh term rayleigh rho I and
    the tip mass of ``dwell_tip_mass``, as keyword arguments of fe_cantilever/ritz_cantilever."""
    r = p["r_b"] + p["r_r"] + (0.0 if inner else p["S_T"])
    rho_A, rho_I, EI = section(p)
    return {"L": p["d"] - r, "rho_A": rho_A, "rho_I": p["rayleigh"] * rho_I, "EI": EI,
            "m_tip": dwell_tip_mass(p, r)}


def dwell_frequencies_fe(p, inner=False, elements=40):
    """Natural frequencies [Hz], ascending, of the finite-element cantilever of a dwell."""
    return frequencies_hz(*fe_cantilever(elements=elements, **dwell_cantilever(p, inner)))


def _hermite(xi, h):
    """Cubic Hermite shape functions on an element of length h and their first two
    x-derivatives at xi in [0, 1], dofs (w_1, w_1', w_2, w_2')."""
    N = np.array([1 - 3 * xi**2 + 2 * xi**3, h * (xi - 2 * xi**2 + xi**3),
                  3 * xi**2 - 2 * xi**3, h * (xi**3 - xi**2)])
    N1 = np.array([6 * (xi**2 - xi), h * (1 - 4 * xi + 3 * xi**2),
                   6 * (xi - xi**2), h * (3 * xi**2 - 2 * xi)]) / h
    N2 = np.array([12 * xi - 6, h * (6 * xi - 4), 6 - 12 * xi, h * (6 * xi - 2)]) / h**2
    return N, N1, N2


def fe_cantilever(L, rho_A, rho_I, EI, m_tip, elements):
    """Mass and stiffness of a Rayleigh cantilever of length L on ``elements`` equal Hermite
    cubic elements, clamped at x = 0 (its two dofs removed), a point mass m_tip on the tip
    deflection.  Element matrices by 4-point Gauss quadrature (exact for these degree-6
    integrands): consistent mass rho A int N N^T + rho I int N' N'^T, stiffness E I int N'' N''^T.
    Dofs (w_1, w_1', ..., w_n, w_n') of the nodes x_k = k L/elements, k = 1..elements."""
    h = L / elements
    g, w = np.polynomial.legendre.leggauss(4)
    N, N1, N2 = _hermite((g + 1) / 2, h)
    wq = w * h / 2
    Me = rho_A * (N * wq) @ N.T + rho_I * (N1 * wq) @ N1.T
    Ke = EI * (N2 * wq) @ N2.T
    size = 2 * (elements + 1)
    M, K = np.zeros((size, size)), np.zeros((size, size))
    for e in range(elements):
        block = slice(2 * e, 2 * e + 4)
        M[block, block] += Me
        K[block, block] += Ke
    M[-2, -2] += m_tip
    return M[2:, 2:], K[2:, 2:]


def fe_nodes(L, elements):
    return np.linspace(0.0, L, elements + 1)[1:]


def ritz_cantilever(L, rho_A, rho_I, EI, m_tip, d, n):
    """Mass and stiffness of the same cantilever in the model's N = n polynomials
    (x/d)^2 .. (x/d)^(n+1) (13), by Gauss quadrature over [0, L]."""
    g, w = np.polynomial.legendre.leggauss(n + 3)
    x = (g + 1) / 2 * L
    wq = w * L / 2
    P, P1, P2 = (_powers(x, d, n, k) for k in range(3))
    tip = _powers(np.array(L), d, n, 0)
    M = rho_A * (P * wq) @ P.T + rho_I * (P1 * wq) @ P1.T + m_tip * np.outer(tip, tip)
    K = EI * (P2 * wq) @ P2.T
    return M, K


def frequencies_hz(M, K):
    return np.sqrt(sla.eigh(K, M, eigvals_only=True)) / (2 * np.pi)


def modal_response(M, K, u0, tip, t):
    """tip . u(t) of M u'' + K u = 0 from u(0) = u0, u'(0) = 0, by modal superposition:
    u = sum phi_k (phi_k^T M u0) cos(w_k t), phi_k mass-normalized."""
    lam, V = sla.eigh(K, M)
    q0 = V.T @ (M @ u0)
    return ((tip @ V) * q0) @ np.cos(np.outer(np.sqrt(lam), t))


def tip_load_shape(x, L, v0):
    """Static deflection of a cantilever of length L under a tip force, tip deflection v0:
    v = v0 (3 (x/L)^2 - (x/L)^3)/2, and its slope."""
    s = x / L
    return v0 * (3 * s**2 - s**3) / 2, v0 * (6 * s - 3 * s**2) / (2 * L)


def tip_load_amplitudes(L, v0, d, n):
    """The same shape in the model's polynomials: b_1 (x/d)^2 + b_2 (x/d)^3, b_3.. = 0."""
    b = np.zeros(n)
    b[0] = 1.5 * v0 * (d / L) ** 2
    b[1] = -0.5 * v0 * (d / L) ** 3
    return b

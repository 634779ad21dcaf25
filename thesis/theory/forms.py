"""Closed forms of thesis chapters 3 and 4, written as the thesis prints them.

These are the hand-derived results the generated models are checked against:
they are typed in from the thesis (with the readings stated), never derived
from the models, so that a test comparing the two can fail.
"""
import sympy as sp

T = sp.Symbol("T", real=True)
tau = sp.Symbol("tau", positive=True)
Fa = sp.Symbol("Fa", nonnegative=True)
xi = sp.Symbol("xi", positive=True)
q = sp.Symbol("q", nonnegative=True)
n = sp.Symbol("n", positive=True)

pi = sp.pi

# one DOF, cycloidal rise, constant fictitious angular velocity (sec. 3.3)
u_rise = (-tau**2 / (1 - tau**2) * sp.sin(2 * pi * T) / (2 * pi)
          + tau**3 / (1 - tau**2) * sp.sin(2 * pi * T / tau) / (2 * pi))
"""Positional error u/h_m' during the rise, 0 <= T <= 1 (3.4a)."""

X_rise = T - sp.sin(2 * pi * T) / (2 * pi) + u_rise
"""Follower position during the rise: cycloid (3.2) plus (3.4a)."""

u_dwell = tau**3 / (1 - tau**2) / pi * sp.sin(pi / tau) * sp.cos(pi / tau * (2 * T - 1))
"""Positional error after the rise, T >= 1 (3.4b)."""

U0 = tau**3 / sp.Abs(1 - tau**2) / pi * sp.Abs(sp.sin(pi / tau))
"""Relative residual positional error amplitude (3.5): the absolute value of the factor before
the cosine of (3.4b).  The thesis prints 1 - tau^2 for the one-DOF model's tau < 1, where it is
positive; |1 - tau^2| keeps the amplitude an amplitude for tau > 1 (CAMSHAFT-1 at Fa = 0)."""

U0dd = 4 * pi * tau / sp.Abs(1 - tau**2) * sp.Abs(sp.sin(pi / tau))
"""Relative residual acceleration amplitude (3.6), (2 pi/tau)^2 U0; |1 - tau^2| as in U0."""

decay = sp.exp(-n * 2 * pi * q / sp.sqrt(1 - q**2))
"""Amplitude left after n free vibrations with relative damping q (3.7)."""

# CAMSHAFT-1 (ch. 4)
stiffness_dip = 1 + 4 * Fa
"""c_max/c_min for the cycloid, H'max = 2 (4.19)."""

U0_approx = (tau**3 * (1 + xi * Fa) ** sp.Rational(3, 2) / sp.Abs(1 - tau**2 * (1 + xi * Fa))
             / pi * sp.Abs(sp.sin(pi / (tau * sp.sqrt(1 + xi * Fa)))))
"""Approximate U0 with the stiffness held at c_c/(1 + xi Fa) (4.22); xi = 2 (4.20) or 3/2 (4.21):
(3.5) with tau stretched, an amplitude as (3.5) is (|1 - tau^2 (1 + xi Fa)|; the thesis prints
the denominator for tau below 1, where it is positive)."""

FA_APPROX_MAX = sp.Rational(1, 2)
"""(4.20)-(4.22) assume a small stiffness variation; the thesis puts the limit at Fa < 1/2."""

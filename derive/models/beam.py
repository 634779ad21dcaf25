"""The Rayleigh-beam follower: a translating roller follower in the groove of a rigid disk cam,
its rod a Rayleigh beam whose free length changes as the cam turns (second source paper,
"Transverse vibration analysis of a translating roller-follower cam using cycloidal profile
for RDFD motion", cited as "paper (n)").

Frames and coordinates (paper figs 1, 3; SI units).  Fixed frame: origin at the cam centre,
Y along the follower axis towards the guide, whose exit is at Y = d.  The rod's free part
runs from the guide exit (x = 0, clamped: v = v_x = 0) to the roller pin E at x = x_E(t), so
Y_E = d - x_E (paper (7)).  The cam turns at the constant speed Omega; the pitch-curve point
of cam parameter theta is r(theta) (cos theta, sin theta) in the cam frame with
r = r_b + r_r + S(theta), at (X, Y) = r (sin(Omega t - theta), cos(Omega t - theta)) in the
fixed frame (paper (4), (5)).  Generalized coordinates Q = [b_1 .. b_N, x_E, theta] (16),
deflection v(x, t) = sum b_i (x/d)^(i+1) (13): polynomials that satisfy the clamp, scaled by
d so that every b_i is a length and the matrices of the generated code stay well scaled.

Energies (paper (8)-(12)):

    rod      T = 1/2 rho A int_0^x_E (x_E'^2 + (Dv/Dt)^2) dx + 1/2 rayleigh rho I int_0^x_E (Dv_x/Dt)^2 dx
             U = 1/2 E I int_0^x_E v_xx^2 dx
    roller   T = 1/2 m_r (X_E'^2 + Y_E'^2) + 1/2 J_r w_n^2
    guide    T = 1/2 rho A L_g x_E'^2

with the material derivative D/Dt = d/dt + x_E' d/dx (the rod slides out of the guide at
x_E', so a material point at x moves by x_E' along x), X_E = v(x_E, t) the pin on the rod's
end and Y_E = d - x_E.  The integrals over the moving domain [0, x_E(t)] are done
symbolically here; the equations then follow from Hamilton's principle with the two
constraints adjoined by multipliers (14), i.e. Lagrange's equations of the first kind:
M(Q) Q'' + Phi_Q^T lambda = f(Q, Q', t) (15) (f = -N), Phi_Q Q'' = gamma (19).

Constraints (paper (6), (7)): the pin E is the pitch-curve point of parameter theta,

    Phi_1 = r(theta) sin(Omega t - theta) - v(x_E, t) = 0     (transverse)
    Phi_2 = r(theta) cos(Omega t - theta) + x_E - d = 0        (axial)

For a rigid rod theta = Omega t and x_E = d - r(Omega t).

Modelling choices the paper leaves open (each a parameter where it can be):

* roller rotation: the paper's (12) takes the roller's angular velocity as that of the line
  from its centre E to the contact point C, the common normal.  In the cam frame that normal
  makes the angle theta - phi(theta) with the x axis, phi = atan(S'/r) the pressure angle, so
  in the fixed frame w_n = Omega - theta' (1 - phi'(theta)).  J_r defaults to a uniform disc,
  m_r r_r^2/2 (the paper's value is lost in the scan).  J_r = 0 switches it off.
* rotary inertia of the rod (the Rayleigh term): ``rayleigh`` = 1 keeps it, 0 gives the
  Euler-Bernoulli rod of the frozen-frequency check.
* the rod inside the guide: by default only the free part [0, x_E] carries kinetic energy,
  as the paper integrates; ``L_g`` > 0 adds a length of rod moving with x_E' only (axially).
* Hamilton's principle on the free part as if it were a closed system: the paper's form;
  the momentum carried across x = 0 by the sliding rod is not accounted for.  In the rigid
  limit the axial multiplier is then minus the inertia force of the rigid follower with that
  same Lagrangian, lambda_2 = -[(rho A x_E + m_r + rho A L_g) x_E'' + rho A x_E'^2/2] (the
  sign of M Q'' + Phi_Q^T lambda = f).
* RDFD motion (paper (1), fig. 2): rise over [0, beta_r], outer dwell to pi, fall over
  [pi, pi + beta_r], inner dwell to 2 pi, repeated every revolution; S = S_T R(theta) with R
  the normalized RDFD profile of the chosen cam law (cycloidal by default, any law of the
  library), declared as the model's RDFDProfile with the rise beta_r.  The segment ends are
  located as events.

How the constraints are solved (augmented with Baumgarte's rate w_B, paper (20),
partitioned, the last two coordinates x_E and theta dependent, paper (21)-(27), or projected
after every step) is the
parameter ``formulation``, declared as the model's ConstraintSolver; the multipliers are the
outputs lambda1 (transverse, (6)) and lambda2 (axial, (7)), in N.
"""
from __future__ import annotations

import math

import sympy as sp

from ..model import (Branch, Constraint, ConstraintSolver, Coordinate, Event, Model, Output,
                     Parameter, RDFDProfile, cam_input, time)

t = time("t")
R = cam_input("R")       # normalized RDFD displacement of the cam law, S = S_T R(theta)
x = sp.Symbol("x", real=True, nonnegative=True)   # position along the free rod, from the guide

N_MAX = 6


def _p(name, default, unit, doc, low=0.0, open_low=True, high=float("inf")):
    return Parameter(name, default, unit, doc, low=low, open_low=open_low, high=high)


# paper data (sec. 4): steel rod of radius 5 mm, d = 112 mm, r_b = 26 mm, r_r = 5 mm, m_r = 0.05 kg
Omega = _p("Omega", 240.0, "rad/s", "angular velocity of the cam (paper: 120, 240, 360)")
d = _p("d", 0.112, "m", "distance from the cam centre to the guide exit (paper: 102, 112, 122 mm)")
r_b = _p("r_b", 0.026, "m", "base-circle radius of the cam (paper (3))")
r_r = _p("r_r", 0.005, "m", "roller radius (paper (3))")
S_T = _p("S_T", 0.015, "m", "total rise (paper (1); 8, 15, 22 mm)")
beta_r = _p("beta_r", math.pi / 2, "rad", "cam angle of the rise and of the fall (paper: pi/2)",
            high=math.pi)
a_rod = _p("a_rod", 0.005, "m", "radius of the rod's circular section (paper: 3, 5, 7 mm)")
E = _p("E", 2.1e11, "Pa", "Young's modulus of the rod")
rho = _p("rho", 7800.0, "kg/m^3", "density of the rod")
m_r = _p("m_r", 0.05, "kg", "roller mass (pin included)")
J_r = _p("J_r", 0.05 * 0.005**2 / 2, "kg m^2",
         "roller moment of inertia about its pin (default: uniform disc m_r r_r^2/2)", open_low=False)
rayleigh = _p("rayleigh", 1.0, "1", "1 keeps the rod's rotary inertia (Rayleigh beam), 0 drops it",
              open_low=False, high=1.0)
L_g = _p("L_g", 0.0, "m", "length of rod inside the guide carried axially (0: free part only)",
         open_low=False)
w_B = _p("w_B", 2.0e3, "rad/s", "Baumgarte rate: Phi'' + 2 w_B Phi' + w_B^2 Phi = 0 (augmented form)",
         open_low=False)
formulation = _p("formulation", 0.0, "1", "0: augmented index-1 system with Baumgarte "
                 "stabilization; 1: coordinate partitioning with Newton on (x_E, theta); 2: "
                 "augmented system, projected onto the constraints after every step",
                 open_low=False, high=2.0)

PARAMETERS = (Omega, d, r_b, r_r, S_T, beta_r, a_rod, E, rho, m_r, J_r, rayleigh, L_g, w_B, formulation)


def _coordinates(n: int):
    bs = [Coordinate(f"b{i}", "m", f"amplitude of the assumed mode (x/d)^{i + 1} (13)", scale=1e-5)
          for i in range(1, n + 1)]
    xE = Coordinate("xE", "m", "free length of the rod, guide exit to roller pin E", scale=0.05,
                    initial=d.symbol - r_b.symbol - r_r.symbol)
    th = Coordinate("theta", "rad", "cam parameter of the contact (pitch-curve point of E)",
                    scale=1.0, initial_rate=Omega.symbol)
    return bs, xE, th


def build(n: int) -> Model:
    """The model with N = ``n`` assumed modes (1 <= n <= 6)."""
    if not 1 <= n <= N_MAX:
        raise ValueError(f"modes N={n}: choose 1 to {N_MAX}")
    P = {p.name: p.symbol for p in PARAMETERS}
    bcs, xEc, thc = _coordinates(n)
    b = [c(t) for c in bcs]
    xE, th = xEc(t), thc(t)
    bd = [q.diff(t) for q in b]
    xEd = xE.diff(t)

    A = sp.pi * P["a_rod"] ** 2
    I = sp.pi * P["a_rod"] ** 4 / 4
    v = sum(bi * (x / P["d"]) ** (i + 2) for i, bi in enumerate(b))
    v_x, v_xx = v.diff(x), v.diff(x, 2)
    # material derivatives: the time rate at fixed x plus the sliding x_E' along x
    Dv = sum(q * (x / P["d"]) ** (i + 2) for i, q in enumerate(bd)) + xEd * v_x
    Dv_x = Dv.diff(x)   # D/Dt commutes with d/dx here: x_E' does not depend on x

    def integral(expr):
        return sp.integrate(sp.expand(expr), (x, 0, xE))

    T_rod = (P["rho"] * A * (xE * xEd**2 + integral(Dv**2)) / 2
             + P["rayleigh"] * P["rho"] * I * integral(Dv_x**2) / 2)
    U_rod = P["E"] * I * integral(v_xx**2) / 2
    vE = v.subs(x, xE)
    r = P["r_b"] + P["r_r"] + P["S_T"] * R(th)
    S1 = P["S_T"] * cam_input("R", 1)(th)
    S2 = P["S_T"] * cam_input("R", 2)(th)
    phi = sp.atan(S1 / r)                                      # pressure angle
    # d(phi)/d(theta) written out (r' = S'): the same as phi.diff(theta), but Lagrange's
    # equations come out several times smaller than through the derivative of atan
    phi_theta = (S2 * r - S1**2) / (r**2 + S1**2)
    w_n = P["Omega"] - th.diff(t) * (1 - phi_theta)            # rate of the common normal
    T_roller = P["m_r"] * (vE.diff(t) ** 2 + xEd**2) / 2 + P["J_r"] * w_n**2 / 2
    T_guide = P["rho"] * A * P["L_g"] * xEd**2 / 2

    # the RDFD segment ends theta = 0, beta_r (mod pi) are the zeros of one function
    ends = sp.sin(th) * sp.sin(th - P["beta_r"])
    u = P["Omega"] * t - th
    Phi1 = r * sp.sin(u) - vE                                   # (6)
    Phi2 = r * sp.cos(u) + xE - P["d"]                          # (7)

    return Model(
        name=f"beam{n}",
        title=f"Rayleigh-beam follower in a grooved disk cam, N = {n} assumed modes",
        reference="paper (1)-(20)",
        doc=__doc__,
        time=t,
        time_unit="s",
        coordinates=tuple(bcs) + (xEc, thc),
        kinetic=T_rod + T_roller + T_guide,
        potential=U_rod,
        parameters=PARAMETERS,
        constraints=(
            Constraint("Phi1", Phi1, "lambda1", "N",
                       "multiplier of the first constraint (transverse, (6))"),
            Constraint("Phi2", Phi2, "lambda2", "N",
                       "multiplier of the second constraint (axial, (7))"),
        ),
        profile=RDFDProfile(family="R", rise=P["beta_r"]),
        solver=ConstraintSolver(baumgarte_rate=P["w_B"], formulation=P["formulation"]),
        events=(Event("segment_up", ends, 1, {}, (Branch({}),)),
                Event("segment_down", ends, -1, {}, (Branch({}),))),
        outputs=(
            Output("vE", vE, "m", "transverse deflection of the rod at the roller pin E, v(x_E, t)"),
            Output("Phi1", Phi1, "m", "transverse constraint residual (6)"),
            Output("Phi2", Phi2, "m", "axial constraint residual (7)"),
            Output("S", P["S_T"] * R(th), "m", "follower displacement of the cam law at theta"),
            Output("pressure_angle", phi, "rad", "pressure angle atan(S'/r) at theta"),
            Output("xEdd", xE.diff(t, 2), "m/s^2", "axial acceleration of the roller pin"),
        ),
        options=(("modes", n),),
    )

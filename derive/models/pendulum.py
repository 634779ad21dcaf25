"""A planar pendulum in Cartesian coordinates: the constraint layer's second model.

A point mass m on a massless rigid rod of length L, hinged at the origin, in the vertical
plane; x horizontal, y vertically up (gravity g points to -y), so the mass hangs at
(0, -L).  The coordinates Q = [x, y] are dependent, tied by the rod's length:

    Phi = x^2 + y^2 - L^2 = 0

    kinetic energy     T = m (x'^2 + y'^2)/2
    potential energy   V = m g y
    dissipation        D = c (x'^2 + y'^2)/2     viscous damping of the mass (c = 0: none)

Lagrange's equations of the first kind, M Q'' + Phi_Q^T lambda = f with M = m I,
Phi_Q = [2 x, 2 y] and f = [-c x', -m g - c y']:

    m x'' + 2 x lambda = -c x',     m y'' + 2 y lambda = -m g - c y'.

The rod's tension T_rod (positive when the rod pulls the mass towards the hinge) acts on
the mass as -T_rod (x, y)/L, so the multiplier is lambda = T_rod/(2 L), in N/m (a force
per unit of Phi's m^2 over the m^2/m of Phi_Q).  For the undamped pendulum at the angle
theta from the downward vertical, T_rod = m L theta'^2 + m g cos theta.

The start is the rod at the angle theta0 at rest: x = L sin theta0, y = -L cos theta0,
on the constraint, with consistent (zero) rates.

Solving the constraint (parameter ``formulation``): 0 is the augmented index-1 system with
Baumgarte's stabilization at the rate w_B; 1 is coordinate partitioning with y, the last
coordinate, dependent: y is recovered from x by Newton's method on Phi = 0 (the branch of
the sign y carries), and y' = -x x'/y.  That fails near y = 0, the horizontal rod, where
Phi_y = 2 y vanishes: use the augmented form (formulation 0) for swings that reach the
horizontal (|theta0| >= pi/2); 2 is the augmented system without Baumgarte's terms, the
state projected back onto Phi = 0 and Phi' = 0 after every accepted step.
"""
from __future__ import annotations

import math

import sympy as sp

from ..model import Constraint, ConstraintSolver, Coordinate, Model, Output, Parameter, time

t = time("t")

m = Parameter("m", 1.0, "kg", "mass of the bob", low=0.0, open_low=True)
L = Parameter("L", 1.0, "m", "length of the rod, hinge to bob", low=0.0, open_low=True)
g = Parameter("g", 9.81, "m/s^2", "gravitational acceleration, along -y", low=0.0)
c = Parameter("c", 0.0, "N s/m", "viscous damping of the bob's velocity (0: conservative)",
              low=0.0)
theta0 = Parameter("theta0", 1.0, "rad", "initial angle of the rod from the downward vertical "
                   "(released at rest)", low=-math.pi, high=math.pi, open_low=True, open_high=True)
w_B = Parameter("w_B", 10.0, "rad/s", "Baumgarte rate: Phi'' + 2 w_B Phi' + w_B^2 Phi = 0 "
                "(augmented form)", low=0.0)
formulation = Parameter("formulation", 0.0, "1", "0: augmented index-1 system with Baumgarte "
                        "stabilization; 1: coordinate partitioning with y dependent (not "
                        "near the horizontal rod, y = 0); 2: augmented system, projected onto "
                        "the constraint after every step", low=0.0, high=2.0)

PARAMETERS = (m, L, g, c, theta0, w_B, formulation)


def build() -> Model:
    P = {p.name: p.symbol for p in PARAMETERS}
    xc = Coordinate("x", "m", "horizontal position of the bob", scale=1.0,
                    initial=P["L"] * sp.sin(P["theta0"]))
    yc = Coordinate("y", "m", "vertical position of the bob, up (dependent when partitioned)",
                    scale=1.0, initial=-P["L"] * sp.cos(P["theta0"]))
    x, y = xc(t), yc(t)
    xd, yd = x.diff(t), y.diff(t)
    Phi = x**2 + y**2 - P["L"] ** 2
    kinetic = P["m"] * (xd**2 + yd**2) / 2
    potential = P["m"] * P["g"] * y
    # the rod's pull follows from the equations of motion: x (first) + y (second) eliminates
    # the direction, and x x' + y y' = Phi'/2 keeps the damping term exact off the constraint
    tension = -P["L"] * (P["m"] * (x * x.diff(t, 2) + y * y.diff(t, 2)) + P["m"] * P["g"] * y
                         + P["c"] * (x * xd + y * yd)) / (x**2 + y**2)
    return Model(
        name="pendulum_xy",
        title="Planar pendulum in Cartesian coordinates with its length constraint",
        reference="Lagrange's equations of the first kind; the pendulum's closed forms",
        doc=__doc__,
        time=t,
        time_unit="s",
        coordinates=(xc, yc),
        kinetic=kinetic,
        potential=potential,
        dissipation=P["c"] * (xd**2 + yd**2) / 2,
        parameters=PARAMETERS,
        constraints=(Constraint("rod", Phi, "lambda_rod", "N/m",
                                "multiplier of the rod constraint, T_rod/(2 L) (positive when "
                                "the rod pulls the bob towards the hinge)"),),
        solver=ConstraintSolver(baumgarte_rate=P["w_B"], formulation=P["formulation"]),
        outputs=(
            Output("theta", sp.atan2(x, -y), "rad", "angle of the rod from the downward vertical"),
            Output("E", kinetic + potential, "J", "mechanical energy T + V (V = 0 at the hinge)"),
            Output("Phi", Phi, "m^2", "constraint residual x^2 + y^2 - L^2"),
            Output("tension", tension, "N",
                   "rod tension from the accelerations, equal to 2 L lambda_rod"),
        ),
    )

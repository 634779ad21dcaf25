"""Andrews' squeezing mechanism: seven rigid bodies in a closed loop, the standard test of
integrators for constrained multibody systems.

E. Hairer and G. Wanner, Solving Ordinary Differential Equations II, 2nd ed., sec. VII.7
("Multibody systems", fig. 7.1, data table 7.1, initial values (7.10)-(7.11)), after
M. Schiehlen (ed.), Multibody Systems Handbook (1990); also problem "andrews" of the IVP test
set of F. Mazzia and C. Magherini (Bari), which gives the reference solution at t = 0.03 s
used by tests/test_andrews.py.

The seven bodies move in a plane, driven by the constant torque ``mom`` at the crank (angle
beta) and squeezed by a spring of stiffness ``c0`` and rest length l0; the coordinates are
the seven angles Q = (beta, Theta, gamma, Phi, delta, Omega, epsilon) of fig. 7.1, and the
six constraints close the three loops through the fixed points A and B (Hairer & Wanner
(7.7)).  The mass matrix is that of the book (7.4), so the kinetic energy is
T = Q'^T M(Q) Q'/2; the spring's energy c0 (L - l0)^2/2 with L the distance from its fixed
end C to the point D on body 3; the torque is a generalized force on beta.  Lagrange's
equations of these give the book's f(Q, Q') (7.5) exactly, its Coriolis terms included.

Units: kg, m, s, rad.  The initial values are the consistent ones of the book (7.10): the
mechanism at rest.
"""
import sympy as sp

from camdyn.derive.model import Constraint, ConstraintSolver, Coordinate, Model, Output, Parameter, time

t = time("t")

# table 7.1 of Hairer & Wanner (masses kg, moments of inertia kg m^2, lengths m)
m1, m2, m3, m4, m5, m6, m7 = .04325, .00365, .02373, .00706, .07050, .00706, .05498
i1, i2, i3, i4, i5, i6, i7 = 2.194e-6, 4.410e-7, 5.255e-6, 5.667e-7, 1.169e-5, 5.667e-7, 1.912e-5
xa, ya, xb, yb, xc, yc = -.06934, -.00227, -.03635, .03273, .014, .072
d, da, e, ea, rr, ra = 28e-3, 115e-4, 2e-2, 1421e-5, 7e-3, 92e-5
ss, sa, sb, sc, sd = 35e-3, 1874e-5, 1043e-5, 18e-3, 2e-2
ta, tb, u, ua, ub = 2308e-5, 916e-5, 4e-2, 1228e-5, 449e-5
zf, zt, fa = 2e-2, 4e-2, 1421e-5

mom = Parameter("mom", 0.033, "N m", "driving torque at the crank", low=0.0)
c0 = Parameter("c0", 4530.0, "N/m", "stiffness of the spring", low=0.0)
l0 = Parameter("l0", 0.07785, "m", "rest length of the spring", low=0.0, open_low=True)
w_B = Parameter("w_B", 0.0, "1/s", "Baumgarte rate (formulation 0)", low=0.0)
formulation = Parameter("formulation", 2.0, "1", "0: augmented with Baumgarte's terms; 1: "
                        "partitioned; 2: augmented, projected after every step", low=0.0,
                        high=2.0)

# the book's consistent initial angles (7.10), at rest
INITIAL = (-0.0617138900142764496358948458001, 0.0, 0.455279819163070380255912382449,
           0.222668390165885884674473185609, 0.487364979543842550225598953530,
           -0.222668390165885884674473185609, 1.23054744454982119249735015568)
NAMES = ("beta", "Theta", "gamma", "Phi", "delta", "Omega", "epsilon")


def build() -> Model:
    coords = tuple(Coordinate(n, "rad", f"angle {n} of fig. 7.1", initial=q0)
                   for n, q0 in zip(NAMES, INITIAL))
    be, th, ga, ph, de, om, ep = (c(t) for c in coords)
    qd = sp.Matrix([c(t).diff(t) for c in coords])
    M = sp.zeros(7, 7)
    M[0, 0] = m1 * ra**2 + m2 * (rr**2 - 2 * da * rr * sp.cos(th) + da**2) + i1 + i2
    M[1, 0] = M[0, 1] = m2 * (da**2 - da * rr * sp.cos(th)) + i2
    M[1, 1] = m2 * da**2 + i2
    M[2, 2] = m3 * (sa**2 + sb**2) + i3
    M[3, 3] = m4 * (e - ea)**2 + i4
    M[4, 3] = M[3, 4] = m4 * ((e - ea)**2 + zt * (e - ea) * sp.sin(ph)) + i4
    M[4, 4] = (m4 * (zt**2 + 2 * zt * (e - ea) * sp.sin(ph) + (e - ea)**2)
               + m5 * (ta**2 + tb**2) + i4 + i5)
    M[5, 5] = m6 * (zf - fa)**2 + i6
    M[6, 5] = M[5, 6] = m6 * ((zf - fa)**2 - u * (zf - fa) * sp.sin(om)) + i6
    M[6, 6] = (m6 * ((zf - fa)**2 - 2 * u * (zf - fa) * sp.sin(om) + u**2)
               + m7 * (ua**2 + ub**2) + i6 + i7)
    kinetic = (qd.T * M * qd)[0, 0] / 2
    xd = sd * sp.cos(ga) + sc * sp.sin(ga) + xb
    yd = sd * sp.sin(ga) - sc * sp.cos(ga) + yb
    L = sp.sqrt((xd - xc)**2 + (yd - yc)**2)
    potential = c0.symbol * (L - l0.symbol)**2 / 2
    # the three loops closed at B (body 3) and twice at A (bodies 4-5 and 6-7), (7.7)
    g = (rr * sp.cos(be) - d * sp.cos(be + th) - ss * sp.sin(ga) - xb,
         rr * sp.sin(be) - d * sp.sin(be + th) + ss * sp.cos(ga) - yb,
         rr * sp.cos(be) - d * sp.cos(be + th) - e * sp.sin(ph + de) - zt * sp.cos(de) - xa,
         rr * sp.sin(be) - d * sp.sin(be + th) + e * sp.cos(ph + de) - zt * sp.sin(de) - ya,
         rr * sp.cos(be) - d * sp.cos(be + th) - zf * sp.cos(om + ep) - u * sp.sin(ep) - xa,
         rr * sp.sin(be) - d * sp.sin(be + th) - zf * sp.sin(om + ep) + u * sp.cos(ep) - ya)
    constraints = tuple(Constraint(f"g{k + 1}", gk, f"lambda{k + 1}", "N",
                                   f"multiplier of the loop constraint g{k + 1} (7.7)")
                        for k, gk in enumerate(g))
    return Model(
        name="andrews_squeezer",
        title="Andrews' squeezing mechanism (seven bodies, six loop constraints)",
        reference="Hairer & Wanner, Solving ODEs II, sec. VII.7",
        doc=__doc__, time=t, time_unit="s",
        coordinates=coords, kinetic=kinetic, potential=potential,
        forces=(mom.symbol, 0, 0, 0, 0, 0, 0),
        parameters=(mom, c0, l0, w_B, formulation),
        constraints=constraints,
        solver=ConstraintSolver(baumgarte_rate=w_B.symbol, formulation=formulation.symbol),
        outputs=(Output("spring_length", L, "m", "length of the spring, C to D"),),
    )

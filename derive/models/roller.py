"""Roller vibration: the roller's mass and the contact stiffness between roller and cam, in
series with the follower linkage (thesis sec. 9.2.1).

The thesis leaves the roller massless and the contact rigid in DYNACAM because the contact
stiffness is a hundred to a thousand times that of the linkage: the natural frequencies are
then far apart, the stiffness matrix is badly conditioned, and the explicit integration of
its day could not afford the fast mode.  It expects that this mode hardly affects the
follower (sec. 3.7: the lowest natural frequency dominates) and that the contact force at
impact after backlash is of the order F_b = v_b (m c)^(1/2) (sec. 3.6), of interest for wear
and fatigue of the cam surface.  This model isolates the question on the one-DOF follower of
sec. 3.3: a roller of mass m_r in the groove of a cam at constant speed, the follower linkage
(c, d) between roller and output mass m.

Dimensionless as in sec. 3.3: T = t/t_m, X = x/h_m, R = r/h_m (roller), H = h/h_m, omega =
2 pi/tau the linkage's natural angular frequency, forces per m h_m/t_m^2:

    kinetic energy     1/2 X'^2 + 1/2 mu R'^2                 mu = m_r/m
    potential energy   1/2 omega^2 (R - X)^2                  linkage spring c
    dissipation        q omega (R' - X')^2                    linkage damper d = 2 q sqrt(m c)
    contact            F_c on the lower wall, -F_c on the upper one, a generalized force on R

Contact (the groove's walls at H and H + S, S = s_r/h_m the backlash): the deflection of the
lower wall is delta = H - R, of the upper one delta_u = R - H - S.  The elastic force is
kappa omega^2 delta_s (delta/delta_s)^n, kappa = k_c/c the contact stiffness ratio: n = 1 a
linear spring, n = 10/9 the line contact of a cylindrical roller (Palmgren's fit of Hertz's
line contact, deflection proportional to F^0.9), delta_s the deflection at which its secant
stiffness is kappa omega^2.  The contact damping is that of the contact mode: 2 zeta
sqrt(mu kappa) omega delta' (zeta the damping ratio of the roller on the contact spring
alone); the force is held at zero where the damper would make it tensile, so a damped contact
lets go before its deflection ends.  The contact opens when the deflection ends and closes
when the roller reaches a wall again: mode "contact" = lower, free, upper, switched by events
on the deflections, whose crossings the integrator locates.  Under the tiny overshoot before an opening is located the
elastic law is continued linearly, so it stays real.

Closed forms the tests use: with the roller on its wall the two natural frequencies solve
det(K - w^2 M) = 0 with M = diag(mu, 1), K = omega^2 [[kappa + 1, -1], [-1, 1]]; the fast one
is about omega sqrt((kappa + 1)/mu).  A roller reaching a wall at speed V_b sets the contact
spring ringing with the peak force V_b sqrt(mu kappa) omega (F_b = v_b (m_r k_c)^(1/2) of sec.
3.6 in these units), when the linkage force is small against it and zeta = 0.
"""
import sympy as sp

from ..model import Branch, Coordinate, Event, Mode, Model, Output, Parameter, Residual, cam_input, \
    time

T = time("T")
H = cam_input("H")
X = Coordinate("X", "h_m", "follower output position over the stroke, X = x/h_m")
R = Coordinate("R", "h_m", "roller position over the stroke, R = r/h_m", scale=1.0)

tau = Parameter("tau", 0.15, "1", "period of the linkage's natural vibration over the rise time, "
                "T_e/t_m (3.3)", low=0.0, high=1.0, open_low=True, open_high=True)
q = Parameter("q", 0.0, "1", "relative damping of the linkage, d = 2 q sqrt(m c) (6.47)",
              low=0.0, high=1.0, open_high=True)
mu = Parameter("mu", 0.05, "1", "roller mass over the follower's equivalent mass, m_r/m",
               low=0.0, high=10.0, open_low=True)
kappa = Parameter("kappa", 1000.0, "1", "contact stiffness over linkage stiffness, k_c/c "
                  "(sec. 9.2.1: 100 to 1000)", low=1.0, high=1e7)
zeta = Parameter("zeta", 0.0, "1", "damping ratio of the contact mode, d_c = 2 zeta sqrt(m_r k_c)",
                 low=0.0, high=1.0)
S = Parameter("S", 0.001, "h_m", "backlash of the roller in the groove over the stroke, s_r/h_m",
              low=0.0, high=1.0, open_low=True)
n_c = Parameter("n_c", 1.0, "1", "exponent of the contact law: 1 linear, 10/9 line contact "
                "(Hertz, Palmgren's fit)", low=1.0, high=1.5)
delta_s = Parameter("delta_s", 1e-3, "h_m", "deflection over the stroke at which the contact's "
                    "secant stiffness is kappa c (n_c > 1)", low=0.0, high=1.0, open_low=True)


def build() -> Model:
    x, r, h = X(T), R(T), H(T)
    w = 2 * sp.pi / tau.symbol
    k_c = kappa.symbol * w**2
    d_c = 2 * zeta.symbol * sp.sqrt(mu.symbol * kappa.symbol) * w

    def elastic(delta):
        ratio = delta / delta_s.symbol
        return k_c * delta_s.symbol * sp.Piecewise((ratio ** n_c.symbol, delta > 0), (ratio, True))

    delta = h - r                        # lower wall pressed in
    delta_u = r - h - S.symbol           # upper wall pressed in
    def pressing(force):
        # a damped contact cannot pull: while the wall is pressed in, the force is held at zero
        # where the damper would make it tensile (the roller lets go before the deflection ends)
        return sp.Piecewise((force, force > 0), (0, True))

    F_low = pressing(elastic(delta) + d_c * delta.diff(T))
    F_up = pressing(elastic(delta_u) + d_c * delta_u.diff(T))
    contact = Mode("contact", ("lower", "free", "upper"), "groove wall the roller touches",
                   initial="lower")
    F_c = contact.select(lower=F_low, free=0, upper=-F_up)
    events = (
        Event("contact_open_lower", delta, -1, {"contact": ("lower",)}, (Branch({"contact": "free"}),)),
        Event("contact_hit_lower", delta, 1, {"contact": ("free",)}, (Branch({"contact": "lower"}),)),
        Event("contact_hit_upper", delta_u, 1, {"contact": ("free",)}, (Branch({"contact": "upper"}),)),
        Event("contact_open_upper", delta_u, -1, {"contact": ("upper",)}, (Branch({"contact": "free"}),)),
    )
    return Model(
        name="roller",
        title="Roller vibration: roller mass and contact stiffness in series with the linkage",
        reference="thesis sec. 9.2.1, with the one-DOF follower of sec. 3.3 and the impact of sec. 3.6",
        doc=__doc__,
        time=T,
        time_unit="t_m",
        coordinates=(X, R),
        kinetic=x.diff(T) ** 2 / 2 + mu.symbol * r.diff(T) ** 2 / 2,
        potential=w**2 * (r - x) ** 2 / 2,
        dissipation=q.symbol * w * (r.diff(T) - x.diff(T)) ** 2,
        forces=(sp.Integer(0), F_c),
        parameters=(tau, q, mu, kappa, zeta, S, n_c, delta_s),
        outputs=(
            Output("Xdd", x.diff(T, 2), "h_m/t_m^2", "follower acceleration X''"),
            Output("U", x - h, "h_m", "positional error of the follower, X - H (3.4)"),
            Output("Fc", F_c, "m h_m/t_m^2", "contact force of the cam on the roller (lower wall "
                   "positive)"),
            Output("F_link", w**2 * (r - x) + 2 * q.symbol * w * (r.diff(T) - x.diff(T)),
                   "m h_m/t_m^2", "force in the follower linkage"),
            Output("delta", delta, "h_m", "deflection of the lower wall, H - R"),
            Output("V_rel", r.diff(T) - h.diff(T), "h_m/t_m", "roller velocity relative to the cam, "
                   "R' - H' (the impact velocity v_b when a wall is reached)"),
        ),
        modes=(contact,),
        events=events,
        residual=Residual(error="U", acceleration="Xdd", rise_end=1.0),
    )


def build_bilateral() -> Model:
    """The roller held in a groove without backlash: the contact spring and damper act both
    ways (F_c = kappa omega^2 delta + 2 zeta sqrt(mu kappa) omega delta', linear), so the
    contact never opens and there are no modes or events.  The smooth stiff case of the
    benchmarks: a fast mode of omega sqrt((kappa + 1)/mu) that only rings, undamped at
    zeta = 0, in series with the follower (thesis sec. 9.2.1)."""
    x, r, h = X(T), R(T), H(T)
    w = 2 * sp.pi / tau.symbol
    k_c = kappa.symbol * w**2
    d_c = 2 * zeta.symbol * sp.sqrt(mu.symbol * kappa.symbol) * w
    delta = h - r
    F_c = k_c * delta + d_c * delta.diff(T)
    return Model(
        name="roller_bilateral",
        title="Roller vibration, bilateral contact: roller mass and contact stiffness in series "
              "with the linkage, no backlash",
        reference="thesis sec. 9.2.1, with the one-DOF follower of sec. 3.3",
        doc=build_bilateral.__doc__,
        time=T,
        time_unit="t_m",
        coordinates=(X, R),
        kinetic=x.diff(T) ** 2 / 2 + mu.symbol * r.diff(T) ** 2 / 2,
        potential=w**2 * (r - x) ** 2 / 2,
        dissipation=q.symbol * w * (r.diff(T) - x.diff(T)) ** 2,
        forces=(sp.Integer(0), F_c),
        parameters=(tau, q, mu, kappa, zeta),
        outputs=(
            Output("Xdd", x.diff(T, 2), "h_m/t_m^2", "follower acceleration X''"),
            Output("U", x - h, "h_m", "positional error of the follower, X - H (3.4)"),
            Output("Fc", F_c, "m h_m/t_m^2", "contact force of the cam on the roller"),
            Output("delta", delta, "h_m", "deflection of the contact, H - R"),
        ),
        residual=Residual(error="U", acceleration="Xdd", rise_end=1.0),
    )

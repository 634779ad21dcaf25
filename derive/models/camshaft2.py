"""CAMSHAFT-2: follower and cam angle, thesis ch. 5, figs 5.1-5.3.

The cam is a degree of freedom: it turns with the angle B = beta/beta_m,
driven through the flexible shaft from the input, which turns at constant
speed (B = T nominally).  Dimensionless equations (5.15)-(5.18):

    X'' = (2 pi/tau)^2 (H(B) - X),
    B'' = (2 pi/tau_b)^2 (T - B) - Fv X'' dH/dB,     B(0) = 0, B'(0) = 1,

with the flywheel factor Fv = m_x h_m^2/(J beta_m^2) (5.14) and the shaft
stiffness factor Fa = c_x h_m^2/(k beta_m^2) (5.12b).  Reading taken: (5.19)
is illegible; from T_eb = 2 pi sqrt(J/k), tau_b^2 = tau^2 Fa/Fv.

Derived from energies, the Lagrangian divided by m_x h_m'^2/t_m^2:

    kinetic energy     1/2 X'^2 + 1/(2 Fv) B'^2
    potential energy   1/2 (2 pi/tau)^2 [(H(B) - X)^2 + (T - B)^2/Fa]

The cam input H(B) depends on a state, so its breakpoints (B = 0, 1) are
located as events.  Fv -> 0 is the constant-speed model of ch. 3, Fv -> oo
CAMSHAFT-1 (up to assumption (4.8)).
"""
import sympy as sp

from ..model import Coordinate, Model, Output, Parameter, Residual, cam_input, time

T = time("T")
H = cam_input("H")
X = Coordinate("X", "h_m'", "follower position over the stroke, X = x/h_m'")
B = Coordinate("B", "beta_m", "cam angle over the rise angle, B = beta/beta_m", initial_rate=1)

tau = Parameter("tau", 0.16, "1", "T_ex/t_m of the follower at zero slope (5.7), (5.9)",
                low=0.0, high=10.0, open_low=True)
Fa = Parameter("Fa", 1.5, "1", "shaft stiffness factor c_x h_m^2/(k beta_m^2) (5.12b)",
               low=0.0, high=100.0, open_low=True)
Fv = Parameter("Fv", 10.0, "1", "flywheel factor m_x h_m^2/(J beta_m^2) (5.14)",
               low=0.0, high=1e6, open_low=True)


def build() -> Model:
    x, b = X(T), B(T)
    h = H(b)
    w2 = (2 * sp.pi / tau.symbol) ** 2
    return Model(
        name="camshaft2",
        title="CAMSHAFT-2, follower and cam angle",
        reference="thesis (5.15)-(5.19)",
        doc=__doc__,
        time=T,
        time_unit="t_m",
        coordinates=(X, B),
        kinetic=x.diff(T) ** 2 / 2 + b.diff(T) ** 2 / (2 * Fv.symbol),
        potential=w2 * ((h - x) ** 2 + (T - b) ** 2 / Fa.symbol) / 2,
        parameters=(tau, Fa, Fv),
        outputs=(
            Output("Xdd", x.diff(T, 2), "h_m'/t_m^2", "follower acceleration X''"),
            Output("U", x - h, "h_m'", "positional error X - H(B)"),
            Output("Bdd", b.diff(T, 2), "beta_m/t_m^2", "cam angular acceleration B''"),
            Output("Bdot_dev", b.diff(T) - 1, "1", "variation of the cam's angular velocity B' - 1"),
            Output("windup", T - b, "beta_m", "shaft wind-up T - B"),
            Output("H", h, "h_m'", "nominal displacement at the cam angle"),
            Output("Hd", cam_input("H", 1)(b), "h_m'/beta_m", "cam slope dH/dB"),
        ),
        # the rise ends when the cam, not the input, has turned through it
        residual=Residual(error="U", acceleration="Xdd", rise_end=1.0, rise_state="B"),
    )

"""One DOF with constant fictitious angular velocity, thesis ch. 3, fig. 3.2.

Equation of motion (3.1), m x'' + c x = c h'(t), in the dimensionless form of
sec. 3.3 (T = t/t_m, X = x/h_m', H = h'/h_m', tau = T_e/t_m (3.3)):

    X'' = (2 pi/tau)^2 (H - X).

It is derived from energies, the Lagrangian divided by m h_m'^2/t_m^2:

    kinetic energy     1/2 X'^2
    potential energy   1/2 (2 pi/tau)^2 (H - X)^2      spring c between cam and mass
    dissipation        q (2 pi/tau) (X' - H')^2         d = 2 q sqrt(m c) (6.47)

Reading taken: the damper acts in parallel with the spring (on X' - H'), as
the linkage's own damping does; during the dwell H' = 0 and it is the plain
viscous damper of the decay law (3.7).  q = 0 (the default) is the undamped
model of (3.4)-(3.6).
"""
import sympy as sp

from ..model import Coordinate, Model, Output, Parameter, Residual, cam_input, time

T = time("T")
H = cam_input("H")
X = Coordinate("X", "h_m'", "follower position over the stroke, X = x/h_m'")

tau = Parameter("tau", 0.15, "1", "period of natural vibration over cam rise time, T_e/t_m (3.3)",
                low=0.0, high=1.0, open_low=True, open_high=True)
q = Parameter("q", 0.0, "1", "relative damping, d = 2 q sqrt(m c) (6.47)",
              low=0.0, high=1.0, open_high=True)


def build() -> Model:
    x, h = X(T), H(T)
    w = 2 * sp.pi / tau.symbol  # dimensionless natural angular frequency w_e t_m
    return Model(
        name="one_dof",
        title="One DOF, constant fictitious angular velocity",
        reference="thesis (3.1)-(3.7), fig. 3.2",
        doc=__doc__,
        time=T,
        time_unit="t_m",
        coordinates=(X,),
        kinetic=x.diff(T) ** 2 / 2,
        potential=w**2 * (h - x) ** 2 / 2,
        dissipation=q.symbol * w * (x.diff(T) - h.diff(T)) ** 2,
        parameters=(tau, q),
        outputs=(
            Output("Xdd", x.diff(T, 2), "h_m'/t_m^2", "follower acceleration X''"),
            Output("U", x - h, "h_m'", "positional error u/h_m' = X - H (3.4)"),
            Output("H", h, "h_m'", "nominal displacement (cam law)"),
            Output("Hd", h.diff(T), "h_m'/t_m", "nominal velocity H'"),
            Output("Hdd", h.diff(T, 2), "h_m'/t_m^2", "nominal acceleration H''"),
        ),
        residual=Residual(error="U", acceleration="Xdd", rise_end=1.0),
    )

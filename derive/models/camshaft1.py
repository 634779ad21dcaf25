"""CAMSHAFT-1: one DOF with variable fictitious angular velocity, thesis ch. 4.

Equation of motion (4.15)-(4.17), dimensionless (sec. 4.3.2):

    X'' = (2 pi/tau)^2 (H - X) / (1 + H'^2 Fa),   H = H(T), H' = dH/dT.

Derived from energies: the shaft's tangential flexibility puts the stiffness
c_tan in series with the constant part c_c through the slope tan(alpha)
(4.2)-(4.5), so the overall stiffness is c = c_c/(1 + H'^2 Fa) (4.18) with
the shaft stiffness factor Fa = (c_c/c_tan) tan^2(alpha_me) (4.14), under the
thesis's assumption dh'/dbeta = h'/w_s (4.8) and the constant pitch radius
(4.1).  Divided by m h_m'^2/t_m^2 the energies are

    kinetic energy     1/2 X'^2
    potential energy   1/2 c(T) (H - X)^2,   c(T) = (2 pi/tau)^2/(1 + H'^2 Fa)

and there is no damping (sec. 4.2.4: ignored during the rise, as in ch. 3).
c depends on T only, so Lagrange's equations give (4.15) exactly.  At Fa = 0
the model is the one-DOF model of ch. 3; the stiffness dip is 1 + 4 Fa (4.19)
for the cycloid.
"""
import sympy as sp

from ..model import Coordinate, Model, Output, Parameter, Residual, cam_input, time

T = time("T")
H = cam_input("H")
X = Coordinate("X", "h_m'", "follower position over the stroke, X = x/h_m'")

tau = Parameter("tau", 0.15, "1", "T_e/t_m at zero slope (4.11), (4.12)",
                low=0.0, high=10.0, open_low=True)
Fa = Parameter("Fa", 2.0, "1", "shaft stiffness factor (c_c/c_tan) tan^2 alpha_me (4.14)",
               low=0.0, high=100.0)


def build() -> Model:
    x, h = X(T), H(T)
    w = 2 * sp.pi / tau.symbol
    c = w**2 / (1 + h.diff(T) ** 2 * Fa.symbol)  # (4.18)
    return Model(
        name="camshaft1",
        title="CAMSHAFT-1, one DOF with variable fictitious angular velocity",
        reference="thesis (4.15)-(4.18)",
        doc=__doc__,
        time=T,
        time_unit="t_m",
        coordinates=(X,),
        kinetic=x.diff(T) ** 2 / 2,
        potential=c * (h - x) ** 2 / 2,
        parameters=(tau, Fa),
        outputs=(
            Output("Xdd", x.diff(T, 2), "h_m'/t_m^2", "follower acceleration X''"),
            Output("U", x - h, "h_m'", "positional error X - H"),
            Output("H", h, "h_m'", "nominal displacement (cam law)"),
            Output("Hd", h.diff(T), "h_m'/t_m", "nominal velocity H'"),
            Output("Hdd", h.diff(T, 2), "h_m'/t_m^2", "nominal acceleration H''"),
            Output("c_rel", 1 / (1 + h.diff(T) ** 2 * Fa.symbol), "c_c",
                   "overall stiffness over its maximum, c/c_c (4.18)"),
        ),
        residual=Residual(error="U", acceleration="Xdd", rise_end=1.0),
    )

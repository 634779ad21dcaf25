"""Three-DOF chain at constant fictitious angular velocity, thesis sec. 3.7, figs 3.6 and 3.7.

The cam input H(T) drives mass 1 through spring c1; masses 1, 2, 3 follow in
series through c2 and c3; mass 3 is the free end.  In the thesis's
dimensionless form (sec. 3.3) with masses m_i and stiffnesses c_i relative to
a reference pair (m, c) whose period is tau t_m:

    kinetic energy     1/2 sum m_i X_i'^2
    potential energy   1/2 (2 pi/tau)^2 [c1 (X1 - H)^2 + c2 (X2 - X1)^2 + c3 (X3 - X2)^2]

which is the chain (2.47) with n = 3.  Readings taken: fig. 3.6 is the output
x2 with one more mass (c3, m3) beyond it, which is what the numerators
(-w_ei^2 + c/m) of (3.20), (3.21) require; fig. 3.7, the input "at the head
of the series", is the output at the far end (X3), where the numerators are 1.
With unit masses and stiffnesses the eigenvalues are 0.198, 1.555, 3.247
(sec. 3.7.3).
"""
import sympy as sp

from ..model import Coordinate, Model, Output, Parameter, Residual, cam_input, time

T = time("T")
H = cam_input("H")
X = [Coordinate(f"X{i}", "h_m'", f"position of mass {i} over the stroke") for i in (1, 2, 3)]

tau = Parameter("tau", 0.15, "1", "period of the reference mass-spring pair over t_m",
                low=0.0, high=10.0, open_low=True)
masses = [Parameter(f"m{i}", 1.0, "m", f"mass {i} over the reference mass", low=0.0, open_low=True)
          for i in (1, 2, 3)]
springs = [Parameter(f"c{i}", 1.0, "c", f"stiffness {i} over the reference stiffness", low=0.0,
                     open_low=True) for i in (1, 2, 3)]


def build() -> Model:
    x = [c(T) for c in X]
    h = H(T)
    w2 = (2 * sp.pi / tau.symbol) ** 2
    m = [p.symbol for p in masses]
    c = [p.symbol for p in springs]
    ends = [h, x[0], x[1]]
    return Model(
        name="chain3",
        title="Three-DOF chain, constant fictitious angular velocity",
        reference="thesis sec. 3.7, figs 3.6, 3.7, (2.47)",
        doc=__doc__,
        time=T,
        time_unit="t_m",
        coordinates=tuple(X),
        kinetic=sum(m[i] * x[i].diff(T) ** 2 for i in range(3)) / 2,
        potential=w2 * sum(c[i] * (x[i] - ends[i]) ** 2 for i in range(3)) / 2,
        parameters=(tau, *masses, *springs),
        outputs=(
            Output("U2", x[1] - h, "h_m'", "positional error of mass 2, the output of fig. 3.6"),
            Output("U3", x[2] - h, "h_m'", "positional error of mass 3, the output of fig. 3.7"),
            Output("X2dd", x[1].diff(T, 2), "h_m'/t_m^2", "acceleration of mass 2"),
            Output("X3dd", x[2].diff(T, 2), "h_m'/t_m^2", "acceleration of mass 3"),
            Output("H", h, "h_m'", "nominal displacement (cam law)"),
        ),
        residual=Residual(error="U2", acceleration="X2dd", rise_end=1.0),
    )

"""The asynchronous motor driving a cam mechanism, thesis App. 5 (and sec. 6.7).

Reduced to the camshaft (fig. A.5.2), the speed deviation dw = w - w_s of the
drive obeys the equation of motion

    J_ma dw' = M_ea - M_load                                     (A.5.7)

and the electromagnetic torque lags behind its static value -G_a dw with the
electrical time constant T_el (first-order transfer function (A.5.2), (A.5.6)):

    T_el M_ea' = -G_a dw - M_ea                                  (A.5.6)

With T_m = J_ma/G_a (A.5.11) this is the second-order system (A.5.13); with
T_el -> 0, M_ea = -G_a dw and the first-order model of sec. A.5.4.2.  The load
is the driving torque of the nominal cam motion, M_load = Mc H'(T) H''(T),
T = t/t_m, Mc = m h_m'^2/(w_s t_m^3) (A.2.7), as in the analytic solutions
(A.5.15)-(A.5.33).  Both are first-order states only (no Lagrangian
coordinate).
"""
import sympy as sp

from ..model import FirstOrder, Model, Output, Parameter, cam_input, time

t = time("t")
H = cam_input("H")

J_ma = Parameter("J_ma", 0.05, "kg m^2", "motor inertia reduced to the camshaft, J_m/i_r^2 (A.5.7)",
                 low=0.0, open_low=True)
G_a = Parameter("G_a", 5.0, "N m s/rad", "slope of the linearised torque-speed line, reduced (A.5.4b)",
                low=0.0, open_low=True)
T_el = Parameter("T_el", 8.6e-3, "s", "electrical time constant (A.5.3); thesis: 8.6e-3 s",
                 low=0.0, open_low=True)
t_m = Parameter("t_m", 0.1, "s", "cam rise time", low=0.0, open_low=True)
Mc = Parameter("Mc", 1.0, "N m", "torque scale m h_m'^2/(w_s t_m^3) of the nominal motion (A.2.7)")


def _load(T):
    h = H(T)
    return Mc.symbol * h.diff(T) * h.diff(T, 2)


def build_second_order() -> Model:
    T = t / t_m.symbol
    dw = sp.Function("dw", real=True)(t)
    Mea = sp.Function("Mea", real=True)(t)
    load = _load(sp.Symbol("T_")).subs(sp.Symbol("T_"), T)
    return Model(
        name="motor2",
        title="Asynchronous motor, second order (electrical lag)",
        reference="thesis (A.5.6)-(A.5.13)",
        doc=__doc__,
        time=t,
        time_unit="s",
        coordinates=(),
        kinetic=sp.Integer(0),
        potential=sp.Integer(0),
        parameters=(J_ma, G_a, T_el, t_m, Mc),
        first_order=(
            FirstOrder("dw", "rad/s", "speed deviation of the drive, reduced to the camshaft",
                       (Mea - load) / J_ma.symbol),
            FirstOrder("Mea", "N m", "electromagnetic torque, reduced (A.5.6)",
                       (-G_a.symbol * dw - Mea) / T_el.symbol),
        ),
        outputs=(
            Output("M_load", load, "N m", "driving torque of the nominal cam motion (A.2.7)"),
        ),
    )


def build_first_order() -> Model:
    T = t / t_m.symbol
    dw = sp.Function("dw", real=True)(t)
    load = _load(sp.Symbol("T_")).subs(sp.Symbol("T_"), T)
    return Model(
        name="motor1",
        title="Asynchronous motor, first order (no electrical lag)",
        reference="thesis sec. A.5.4.2",
        doc=__doc__,
        time=t,
        time_unit="s",
        coordinates=(),
        kinetic=sp.Integer(0),
        potential=sp.Integer(0),
        parameters=(J_ma, G_a, t_m, Mc),
        first_order=(
            FirstOrder("dw", "rad/s", "speed deviation of the drive, reduced to the camshaft",
                       (-G_a.symbol * dw - load) / J_ma.symbol),
        ),
        outputs=(
            Output("M_load", load, "N m", "driving torque of the nominal cam motion (A.2.7)"),
        ),
    )

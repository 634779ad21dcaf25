"""The symbolic layer: Lagrange's equations against the printed equations of motion."""
import pytest
import sympy as sp

from camdyn.derive.lagrange import derive
from camdyn.derive.model import (Constraint, ConstraintSolver, Coordinate, Model, Output, Parameter,
                                 cam_input, time)
from camdyn.derive.models import REGISTRY, camshaft1, one_dof

pi = sp.pi


def _acc(model):
    eq = derive(model)
    assert eq.M.shape == (1, 1)
    return sp.simplify(eq.f[0] / eq.M[0, 0])


def test_one_dof_is_3_1():
    """m x'' + c x = c h'(t) (3.1), dimensionless: X'' = (2 pi/tau)^2 (H - X)."""
    m = one_dof.build()
    T, X, H = m.time, one_dof.X(m.time), one_dof.H(m.time)
    tau, q = one_dof.tau.symbol, one_dof.q.symbol
    expected = (2 * pi / tau) ** 2 * (H - X) + 2 * q * (2 * pi / tau) * (H.diff(T) - X.diff(T))
    assert sp.simplify(_acc(m) - expected) == 0
    assert sp.simplify(_acc(m).subs(q, 0) - (2 * pi / tau) ** 2 * (H - X)) == 0


def test_camshaft1_is_4_15():
    """X'' = (2 pi/tau)^2 (H - X) / (1 + H'^2 Fa) (4.15)."""
    m = camshaft1.build()
    T, X, H = m.time, camshaft1.X(m.time), camshaft1.H(m.time)
    tau, Fa = camshaft1.tau.symbol, camshaft1.Fa.symbol
    expected = (2 * pi / tau) ** 2 * (H - X) / (1 + H.diff(T) ** 2 * Fa)
    assert sp.simplify(_acc(m) - expected) == 0
    # at Fa = 0 it is the undamped one-DOF model (3.1)
    one = _acc(one_dof.build()).subs(one_dof.q.symbol, 0)
    assert sp.simplify(_acc(m).subs(Fa, 0) - one.subs(one_dof.tau.symbol, tau)) == 0


def test_one_dof_closed_form_3_4a_solves_the_derived_equation():
    """(3.4a) with the cycloid satisfies the derived equation and starts from rest; (3.4b)
    continues it after T = 1 with matching position and velocity."""
    from camdyn.derive import camlaws
    from camdyn.thesis.theory import forms

    m = one_dof.build()
    T, tau = m.time, one_dof.tau.symbol
    acc = _acc(m).subs(one_dof.q.symbol, 0)
    cyc = camlaws.LAWS["cycloidal"].rise[0]
    Xsym = one_dof.X(T)
    Hf = one_dof.H(T)
    X_rise = forms.X_rise.subs(forms.tau, tau).subs(forms.T, T)
    rise = acc.subs(Hf, cyc).subs(Xsym, X_rise)
    assert sp.simplify(X_rise.diff(T, 2) - rise) == 0
    assert sp.simplify(X_rise.subs(T, 0)) == 0
    assert sp.simplify(X_rise.diff(T).subs(T, 0)) == 0
    X_dwell = 1 + forms.u_dwell.subs(forms.tau, tau).subs(forms.T, T)
    dwell = acc.subs(Hf, 1).subs(Xsym, X_dwell)
    assert sp.simplify(X_dwell.diff(T, 2) - dwell) == 0
    assert sp.simplify(sp.expand_trig(X_dwell.subs(T, 1) - X_rise.subs(T, 1))) == 0
    assert sp.simplify(sp.expand_trig(X_dwell.diff(T).subs(T, 1) - X_rise.diff(T).subs(T, 1))) == 0


def test_3_6_is_3_5_times_omega_squared():
    """The residual motion is harmonic: U0'' = (2 pi/tau)^2 U0, (3.5) and (3.6)."""
    from camdyn.thesis.theory import forms

    assert sp.simplify(forms.U0dd - (2 * pi / forms.tau) ** 2 * forms.U0) == 0


def test_stiffness_dip_4_19_from_the_model():
    """c = c_c/(1 + H'^2 Fa) (4.18): max over min for the cycloid (H'max = 2) is 1 + 4 Fa."""
    from camdyn.derive import camlaws
    from camdyn.thesis.theory import forms

    m = camshaft1.build()
    T = m.time
    c_rel = next(o.expr for o in m.outputs if o.name == "c_rel")
    Hd = camlaws.LAWS["cycloidal"].rise[0].diff(T)
    c_of_T = c_rel.subs(camshaft1.H(T).diff(T), Hd)
    c_max = c_of_T.subs(T, 0)
    crit = sp.solve(sp.diff(Hd, T), T)
    c_min = min((c_of_T.subs(T, t) for t in crit if 0 < t < 1), key=lambda e: e.subs(camshaft1.Fa.symbol, 1))
    dip = sp.simplify(c_max / c_min)
    assert sp.simplify(dip - forms.stiffness_dip.subs(forms.Fa, camshaft1.Fa.symbol)) == 0


def test_averaged_stiffness_4_21():
    """The time average of 1 + H'^2 Fa over the cycloidal rise is 1 + 3/2 Fa (4.21)."""
    from camdyn.derive import camlaws

    T = camlaws.T
    Fa = sp.Symbol("Fa")
    Hd = camlaws.LAWS["cycloidal"].rise[0].diff(T)
    assert sp.simplify(sp.integrate(1 + Hd**2 * Fa, (T, 0, 1)) - (1 + sp.Rational(3, 2) * Fa)) == 0


def _pendulum(**changes):
    t = time("t")
    x, y = Coordinate("xp", "m", "x"), Coordinate("yp", "m", "y")
    L, g = Parameter("L", 1.0, "m", "length", low=0, open_low=True), Parameter("g", 9.81, "m/s^2", "gravity")
    w, form = Parameter("w", 0.0, "1/s", "Baumgarte rate"), Parameter("form", 0.0, "1", "formulation")
    X, Y = x(t), y(t)
    decl = dict(name="pendulum", title="pendulum", reference="test", doc="", time=t, time_unit="s",
                coordinates=(x, y), kinetic=(X.diff(t) ** 2 + Y.diff(t) ** 2) / 2,
                potential=g.symbol * Y, parameters=(L, g, w, form),
                outputs=(Output("yy", Y, "m", "y"),),
                constraints=(Constraint("rod", X**2 + Y**2 - L.symbol**2, "lam", "N/m", "rod"),),
                solver=ConstraintSolver(w.symbol, form.symbol))
    return Model(**(decl | changes)), X, Y, t, g, L


def test_constraint_multiplier_form():
    """A pendulum in Cartesian coordinates: Phi_q and gamma of the multiplier form."""
    model, X, Y, t, g, L = _pendulum()
    eq = derive(model)
    assert eq.M == sp.eye(2)
    assert sp.simplify(eq.f - sp.Matrix([0, -g.symbol])) == sp.zeros(2, 1)
    assert sp.simplify(eq.Phi_q - sp.Matrix([[2 * X, 2 * Y]])) == sp.zeros(1, 2)
    # d2/dt2 (x^2 + y^2) = 2 x x'' + 2 y y'' + 2 x'^2 + 2 y'^2  ->  gamma = -2 (x'^2 + y'^2)
    assert sp.simplify(eq.gamma[0] + 2 * (X.diff(t) ** 2 + Y.diff(t) ** 2)) == 0


def test_constrained_declarations_are_checked():
    """A bare expression as constraint, a constrained model without a solver, a solver naming
    no parameter, a multiplier clashing with an output: refused by name."""
    model, X, Y, t, g, L = _pendulum()
    with pytest.raises(ValueError, match="pendulum: constraint 1 is a .*Constraint\\(name"):
        _pendulum(constraints=(X**2 + Y**2 - L.symbol**2,))
    with pytest.raises(ValueError, match="pendulum: constrained, but no solver"):
        _pendulum(solver=None)
    with pytest.raises(ValueError, match="pendulum: solver formulation=.* is not one of its parameters"):
        _pendulum(solver=ConstraintSolver(model.solver.baumgarte_rate, sp.Symbol("nope")))
    with pytest.raises(ValueError, match="pendulum: names used twice: \\['yy'\\]"):
        _pendulum(constraints=(Constraint("rod", X**2 + Y**2 - L.symbol**2, "yy", "N/m", "rod"),))
    with pytest.raises(ValueError, match="pendulum: a profile or a constraint solver is declared"):
        _pendulum(constraints=())


def test_cam_input_chain_rule():
    """H(B(t)) differentiates to Hd(B) B' (the CAMSHAFT-2 form H(B), (5.15))."""
    t = time("t")
    B = sp.Function("B")(t)
    H = cam_input("H")
    assert (H(B).diff(t) - cam_input("H", 1)(B) * B.diff(t)) == 0
    assert H(B).diff(t, 2).has(cam_input("H", 2)(B))


def test_nonlinear_accelerations_are_refused():
    t = time("t")
    x = Coordinate("x", "m", "x")
    X = x(t)
    k = Parameter("k", 1.0, "1", "k")
    model = Model(name="bad", title="bad", reference="test", doc="", time=t, time_unit="s",
                  coordinates=(x,), kinetic=X.diff(t) ** 2 / 2, potential=k.symbol * X**2 / 2,
                  parameters=(k,), outputs=(), forces=(X.diff(t, 2) ** 2,))
    with pytest.raises(ValueError, match="not linear in the accelerations"):
        derive(model)


def test_declarations_reject_bad_names():
    with pytest.raises(ValueError, match="not usable"):
        Parameter("lambda", 1.0, "1", "a Python keyword")
    with pytest.raises(ValueError, match="not usable"):
        Coordinate("ctx", "m", "the generated code's context")
    with pytest.raises(ValueError, match="not usable"):
        Coordinate("_x", "m", "names starting with _ belong to the generated code")
    with pytest.raises(ValueError, match="outside its own range"):
        Parameter("tau", 2.0, "1", "default out of range", low=0, high=1)


def test_registry_names_match():
    for name, build in REGISTRY.items():
        assert build().name == name

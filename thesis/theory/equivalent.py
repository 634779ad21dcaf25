"""Natural frequencies and equivalent masses of CAMSHAFT-2 (thesis secs 5.5.7, 5.6).

Two groups of relations, each written once here so that the tests and the
check registry compare the generated model with them (thesis/checks/camshaft2_checks.py):

Frozen two-DOF system (sec. 5.5.7): input blocked, small vibrations about a cam
position, the slope dH/dB held constant (5.36).
    (5.36), (5.37)  matrices and frequency equation     :func:`frozen_matrices`, :func:`frequency_polynomial`
    (5.39)  eigenvalues in m_x, c_x, m_beta', c_beta', tan a    :func:`eigenvalues_reduced`
    (5.40)-(5.42)  w_ex^2, w_eb^2 = w_ex^2 Fv/Fa               :func:`w_eb2`
    (5.43)  eigenvalues in w_ex^2, w_eb^2, dH/dB, Fa            :func:`eigenvalues`
    (5.46)  their product w_ex^2 w_eb^2, free of the slope      :func:`eigenvalue_product`
    (4.32)  CAMSHAFT-1's w_ex^2/(1 + (dH/dB)^2 Fa)              :func:`eigenvalue_camshaft1`

Four-DOF camshaft reduced to two DOF (sec. 5.6, fig. 5.9), Rayleigh's method
with the static deflection under a load at m_x as the lowest mode (sec. 4.6):
    (4.3), (4.4)  1/c_c, 1/c_tan          :func:`constant_flexibility`, :func:`tangential_flexibility`
    (5.47)  overall stiffness c                                 :func:`overall_stiffness`
    (4.5)   the same as 1/c_c + tan^2 a/c_tan                   :func:`overall_stiffness_2dof`
    (5.48)  equivalent mass of the four-DOF model (fig. 5.9a)   :func:`equivalent_mass_4dof`
    (5.49)  equivalent mass of the two-DOF model (fig. 5.9b)    :func:`equivalent_mass_2dof`
    (5.50)  follower mass m (and the slope-dependent form)      :func:`follower_mass`
    (5.51)  equivalent cam mass m_tan                           :func:`cam_mass`
    (5.52)  flywheel factor Fv = (m/m_tan) tan^2 a_me           :func:`flywheel_factor`
    (4.14), (5.12a)  shaft stiffness factor Fa                  :func:`shaft_factor`
    (5.53)  lowest eigenvalue c/m_eq in w_ex^2, dH/dB, Fa, Fv   :func:`lowest_eigenvalue_rayleigh`
            and its derivation from (4.38), (5.49)-(5.52)       :func:`rayleigh_4_38_two_dof`

Every function is plain arithmetic on its arguments, so it takes floats, numpy
arrays or SymPy expressions alike (square roots go through :func:`_sqrt`).
Eigenvalues are in units of w_ex^2 unless ``w_ex2`` is given.

Readings taken where the scan is garbled
    (5.19), (5.42): (w_ex/w_eb)^2 = Fa/Fv.  Legible in sec. 5.6 ("the expression
        (w_ex/w_eb)^2 = Fa/Fv"), and it follows from T_eb = 2 pi (m_beta'/c_beta')^(1/2)
        (5.8) with (5.12a) and (5.14a); the generated model uses the same reading
        (tau_b^2 = tau^2 Fa/Fv, derive/models/camshaft2.py).
    (5.43): the scan keeps the structure, 1/2 {w_ex^2 + [1 + (dH/dB)^2 Fa] w_eb^2 +- sqrt({..}^2
        - 4 w_ex^2 w_eb^2)}, but garbles the exponents and the end of the root.  Taken as (5.39)
        with (5.40)-(5.42) inserted, the root being {w_ex^2 + [1 + (dH/dB)^2 Fa] w_eb^2}^2
        - 4 w_ex^2 w_eb^2, which is what the legible part shows and what (5.46) needs.
    (5.47): the reduced stiffnesses c_beta'' = c_beta'/tan^2 a and c_y'' = c_y'/tan^2 a are
        written out, so the overall flexibility is (4.2).
    (5.48): the first mass term is m_x (the output member moves with the full static
        deflection); the bracket multiplies tan^2 a (m_beta'' (1/c_beta'')^2 = m_beta' tan^2 a (1/c_beta')^2).
    (5.50): the thesis prints the slope-dependent follower mass
        m = m_x + m_z' ((1/c_z')/(1/c_c + tan^2 a/c_tan))^2 under "(1)" and then, with tan a = 0,
        m = m_x + m_z' ((1/c_z')/(1/c_c))^2 as (5.50), "the same as found in (4.39)".  Both
        are here: ``tan_alpha=0`` (default) gives (5.50), any other value the form above it.
    (5.53): the left-hand side is w_el^2; the right-hand side is legible:
        w_ex^2 [1 + Fa (dH/dB)^2] / {[1 + Fa (dH/dB)^2]^2 + (Fa^2/Fv) (dH/dB)^2}.
        The thesis's value at Fa = Fv = 2, dH/dB = 2 ("s\\ w_ex^2 ~ 0.101") is read as 9/89.
    (4.32): w_eT^2 = w_ex^2/(1 + H'^2 Fa); at H' = 2, Fa = 2 it gives 1/9 = 0.111, as printed
        in sec. 5.6.
"""
from __future__ import annotations

import numpy as np
import sympy as sp

# -- symbols -------------------------------------------------------------------------------------
slope = sp.Symbol("s", real=True)
"""dH/dB = tan a/tan a_me, the cam slope over its mean (sec. 5.5.7)."""
Fa = sp.Symbol("Fa", positive=True)
Fv = sp.Symbol("Fv", positive=True)
w_ex2_sym = sp.Symbol("w_ex2", positive=True)
tan_a = sp.Symbol("tan_a", nonnegative=True)
tan_me = sp.Symbol("tan_me", positive=True)
m_x, m_z, m_beta, m_y = sp.symbols("m_x m_z m_beta m_y", positive=True)
"""Masses m_x, m_z', m_beta' = J/R'^2, m_y' (reduced at the follower, not yet by tan a)."""
c_x, c_z, c_beta, c_y = sp.symbols("c_x c_z c_beta c_y", positive=True)
"""Stiffnesses c_x, c_z', c_beta' = k/R'^2, c_y'."""
lam = sp.Symbol("lambda")


def _sqrt(x):
    return sp.sqrt(x) if isinstance(x, sp.Basic) else np.sqrt(x)


# -- frozen two-DOF system (sec. 5.5.7) -----------------------------------------------------------
def w_eb2(Fa, Fv, w_ex2=1):
    """Uncoupled shaft eigenvalue w_eb^2 = w_ex^2 Fv/Fa, from (w_ex/w_eb)^2 = Fa/Fv (5.19), (5.42)."""
    return w_ex2 * Fv / Fa


def eigenvalues_reduced(m_x, c_x, m_beta, c_beta, tan_alpha):
    """(w_el^2, w_eh^2) of the frozen system in reduced magnitudes (5.39).

    m_x, c_x: follower mass and stiffness; m_beta' = J/R'^2, c_beta' = k/R'^2: cam inertia and
    shaft stiffness reduced to the pitch circle, not yet by the slope tan a (fig. 5.2b).
    """
    b = c_x / m_x + c_beta / m_beta + c_x * tan_alpha**2 / m_beta
    root = _sqrt(b**2 - 4 * c_beta * c_x / (m_beta * m_x))
    return (b - root) / 2, (b + root) / 2


def eigenvalues(slope, Fa, Fv, w_ex2=1):
    """(w_el^2, w_eh^2) of the frozen CAMSHAFT-2 at the slope dH/dB (5.43):

        1/2 {w_ex^2 + [1 + (dH/dB)^2 Fa] w_eb^2 -+ sqrt([w_ex^2 + (1 + (dH/dB)^2 Fa) w_eb^2]^2
                                                       - 4 w_ex^2 w_eb^2)}

    with w_eb^2 = w_ex^2 Fv/Fa (5.42) (reading: see the module docstring).
    """
    wb2 = w_eb2(Fa, Fv, w_ex2)
    b = w_ex2 + (1 + slope**2 * Fa) * wb2
    root = _sqrt(b**2 - 4 * w_ex2 * wb2)
    return (b - root) / 2, (b + root) / 2


def eigenvalue_product(Fa, Fv, w_ex2=1):
    """w_el^2 w_eh^2 = w_ex^2 w_eb^2 (5.46): c/a of the frequency equation (5.37), no slope in it."""
    return w_ex2 * w_eb2(Fa, Fv, w_ex2)


def eigenvalue_camshaft1(slope, Fa, w_ex2=1):
    """The one-DOF model's eigenvalue w_eT^2 = w_ex^2/(1 + H'^2 Fa) (4.32), massless cam."""
    return w_ex2 / (1 + slope**2 * Fa)


# -- four-DOF camshaft and its two-DOF equivalent (sec. 5.6) -------------------------------------
def constant_flexibility(c_x, c_z):
    """1/c_c = 1/c_x + 1/c_z' (4.3)."""
    return 1 / c_x + 1 / c_z


def tangential_flexibility(c_beta, c_y):
    """1/c_tan = 1/c_beta' + 1/c_y' (4.4)."""
    return 1 / c_beta + 1 / c_y


def overall_stiffness(c_x, c_z, c_beta, c_y, tan_alpha):
    """Overall stiffness c at the slope tan a (5.47), (4.2):

        1/c = 1/c_x + 1/c_z' + 1/c_beta'' + 1/c_y'',  c_beta'' = c_beta'/tan^2 a, c_y'' = c_y'/tan^2 a,

    which is (4.5), 1/c = 1/c_c + tan^2 a/c_tan, with (4.3) and (4.4).
    """
    return 1 / (1 / c_x + 1 / c_z + tan_alpha**2 / c_beta + tan_alpha**2 / c_y)


def equivalent_mass_4dof(m_x, m_z, m_beta, m_y, c_x, c_z, c_beta, c_y, tan_alpha):
    """Equivalent mass of the four-DOF model of fig. 5.9a (5.48).

    The static deflection under a load at m_x moves z' by (1/c_z')/(1/c) x, the cam point by
    (1/c_beta'')/(1/c) x and (1/c_y'')/(1/c) x (parallel branches, sec. 5.6); the masses
    weighed by these ratios squared:

        m_eq = m_x + m_z' ((1/c_z')/(1/c))^2
                   + [m_beta' ((1/c_beta')/(1/c))^2 + m_y' ((1/c_y')/(1/c))^2] tan^2 a
    """
    flex = 1 / overall_stiffness(c_x, c_z, c_beta, c_y, tan_alpha)
    return (m_x + m_z * (1 / c_z / flex) ** 2
            + (m_beta * (1 / c_beta / flex) ** 2 + m_y * (1 / c_y / flex) ** 2) * tan_alpha**2)


def equivalent_mass_2dof(m, m_tan, c_c, c_tan, tan_alpha):
    """Equivalent mass of the two-DOF model of fig. 5.9b (5.49):

        m_eq = m + m_tan ((1/c_tan)/(1/c))^2 tan^2 a,   1/c = 1/c_c + tan^2 a/c_tan (4.5).
    """
    flex = 1 / c_c + tan_alpha**2 / c_tan
    return m + m_tan * (1 / c_tan / flex) ** 2 * tan_alpha**2


def follower_mass(m_x, m_z, c_x, c_z, tan_alpha=0, c_tan=None):
    """Equivalent follower mass (5.50): m = m_x + m_z' ((1/c_z')/(1/c_c))^2, as in (4.39).

    With ``tan_alpha`` non-zero (and ``c_tan`` given) the slope-dependent form the thesis prints
    just before (5.50): m = m_x + m_z' ((1/c_z')/(1/c_c + tan^2 a/c_tan))^2, with which (5.49)
    equals (5.48) exactly; (5.50) drops the slope, "only a slight error" (sec. 5.6 (1)).
    """
    flex = constant_flexibility(c_x, c_z)
    if c_tan is not None:
        flex = flex + tan_alpha**2 / c_tan
    elif not (isinstance(tan_alpha, (int, float)) and tan_alpha == 0):
        raise ValueError("the slope-dependent follower mass needs c_tan")
    return m_x + m_z * (1 / c_z / flex) ** 2


def cam_mass(m_beta, m_y, c_beta, c_y):
    """Equivalent cam mass (5.51): m_tan = m_beta' ((1/c_beta')/(1/c_tan))^2 + m_y' ((1/c_y')/(1/c_tan))^2."""
    flex = tangential_flexibility(c_beta, c_y)
    return m_beta * (1 / c_beta / flex) ** 2 + m_y * (1 / c_y / flex) ** 2


def flywheel_factor(m, m_tan, tan_me):
    """Flywheel factor of the four-DOF model, Fv = (m/m_tan) tan^2 a_me (5.52)."""
    return m / m_tan * tan_me**2


def shaft_factor(c_c, c_tan, tan_me):
    """Shaft stiffness factor Fa = (c_c/c_tan) tan^2 a_me (4.14), (5.12a)."""
    return c_c / c_tan * tan_me**2


def lowest_eigenvalue_rayleigh(slope, Fa, Fv, w_ex2=1):
    """Lowest eigenvalue of fig. 5.9b by Rayleigh with the static deflection (5.53):

        w_el^2 = w_ex^2 [1 + Fa (dH/dB)^2] / {[1 + Fa (dH/dB)^2]^2 + (Fa^2/Fv) (dH/dB)^2},

    i.e. c/m_eq, (4.38) with (4.5), (5.49)-(5.51), tan a = (dH/dB) tan a_me, (4.14) and (5.52);
    w_ex^2 = c_c/m.  A Rayleigh quotient, so never below the lowest root of (5.43).
    """
    g = 1 + Fa * slope**2
    return w_ex2 * g / (g**2 + Fa**2 / Fv * slope**2)


# -- derivations the tests compare with the printed forms ----------------------------------------
def frozen_matrices():
    """(M, K) of the frozen two-DOF system of fig. 5.3 from its energies, coordinates x and the
    reduced cam displacement u = R'' beta (sec. 5.5.7, (5.36)):

        T = 1/2 m_x x'^2 + 1/2 m_beta'' u'^2,  V = 1/2 c_x (u - x)^2 + 1/2 c_beta'' u^2,

    m_beta'' = m_beta'/tan^2 a, c_beta'' = c_beta'/tan^2 a (sec. 5.2.1).  Written from the
    physics, not from (5.36) (whose matrix is garbled), so that a test against (5.39) can fail.
    """
    mb2, cb2 = m_beta / tan_a**2, c_beta / tan_a**2
    M = sp.diag(m_x, mb2)
    K = sp.Matrix([[c_x, -c_x], [-c_x, c_x + cb2]])
    return M, K


def frequency_polynomial():
    """det(K - lambda M) of :func:`frozen_matrices` divided by m_x m_beta'': the frequency
    equation (5.37), monic in lambda."""
    M, K = frozen_matrices()
    return sp.expand(sp.cancel((K - lam * M).det() / (M[0, 0] * M[1, 1])))


def rayleigh_4_38_two_dof():
    """w_el^2 = c/m_eq of fig. 5.9b in dimensionless form, derived: (4.38) with the overall
    stiffness (4.5), the equivalent mass (5.49), tan a = (dH/dB) tan a_me, Fa (4.14) and
    Fv (5.52) solved for c_tan and m_tan; w_ex^2 = c_c/m.  Compare with (5.53)."""
    m, m_tan, c_c, c_tan = sp.symbols("m m_tan c_c c_tan", positive=True)
    ta = slope * tan_me
    expr = overall_stiffness_2dof(c_c, c_tan, ta) / equivalent_mass_2dof(m, m_tan, c_c, c_tan, ta)
    (c_tan_sol,) = sp.solve(sp.Eq(shaft_factor(c_c, c_tan, tan_me), Fa), c_tan)
    (m_tan_sol,) = sp.solve(sp.Eq(flywheel_factor(m, m_tan, tan_me), Fv), m_tan)
    expr = expr.subs({c_tan: c_tan_sol, m_tan: m_tan_sol})
    return sp.simplify(expr.subs(c_c, w_ex2_sym * m))


def overall_stiffness_2dof(c_c, c_tan, tan_alpha):
    """c = 1/(1/c_c + tan^2 a/c_tan) (4.5), the stiffness of fig. 5.9b/c."""
    return 1 / (1 / c_c + tan_alpha**2 / c_tan)

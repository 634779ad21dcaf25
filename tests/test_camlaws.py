"""Cam laws (thesis App. 2): derived pieces against the printed formulas and values."""
import numpy as np
import pytest
import sympy as sp

from camdyn.derive import camlaws
from camdyn.derive.camlaws import LAWS, T, theta
from camdyn.runtime.core import laws as rt_laws
from camdyn.runtime.core.errors import CamdynInputError

from camdyn.thesis.checks.check import matches_printed

pi = sp.pi


def test_cycloid_matches_A_2_8_to_A_2_10():
    law = LAWS["cycloidal"]
    (H,) = law.rise
    assert sp.simplify(H - (T - sp.sin(2 * pi * T) / (2 * pi))) == 0          # (A.2.10)
    assert sp.simplify(H.diff(T) - (1 - sp.cos(2 * pi * T))) == 0             # (A.2.9)
    assert sp.simplify(H.diff(T, 2) - 2 * pi * sp.sin(2 * pi * T)) == 0       # (A.2.8)
    assert sp.simplify(law.amplitude - 2 * pi) == 0


def test_cycloid_jerk_A_2_16():
    """H''' = 4 pi^2 cos 2 pi T: +39.4 at T = 0 and 1, -39.4 at T = 1/2 (printed digits)."""
    jerk = LAWS["cycloidal"].rise[0].diff(T, 3)
    assert matches_printed(float(jerk.subs(T, 0)), "39.4")   # 4 pi^2 = 39.478, truncated
    assert matches_printed(float(jerk.subs(T, 1)), "39.4")
    assert matches_printed(float(jerk.subs(T, sp.Rational(1, 2))), "-39.4")
    assert not matches_printed(float(jerk.subs(T, 0)), "39.6")


def test_cycloid_torque_maximum_at_one_third_A_2_12_to_A_2_14():
    """M ~ H' H'' (A.2.12) has dM/dT = 0 at T = 0, 1/3, 2/3, 1 and its maximum at 1/3."""
    H = LAWS["cycloidal"].rise[0]
    M = H.diff(T) * H.diff(T, 2)
    stationary = sp.solveset(sp.simplify(M.diff(T)), T, sp.Interval(0, 1))
    assert {sp.Rational(0), sp.Rational(1, 3), sp.Rational(2, 3), sp.Rational(1)} <= set(stationary)
    grid = np.linspace(0, 1, 30001)
    Mn = sp.lambdify(T, M)(grid)
    assert abs(grid[np.argmax(Mn)] - 1 / 3) < 1e-4
    # (A.2.14): M_max = (3 sqrt 3 / 2) pi  m h_m^2/(w_s t_m^3) in these units
    assert float(M.subs(T, sp.Rational(1, 3))) == pytest.approx(3 * np.sqrt(3) / 2 * np.pi, rel=1e-12)


def test_modified_sine_peak_A_2_17_symbolic():
    """The amplitude fixed by H(1) = 1 is the printed H''max = pi^2/(2 - 8 theta + 2 pi theta)."""
    law = LAWS["modified-sine"]
    assert sp.simplify(law.amplitude - pi**2 / (2 - 8 * theta + 2 * pi * theta)) == 0
    assert matches_printed(float(law.amplitude.subs(theta, sp.Rational(1, 10))), "5.40")  # fig. 8.7


def test_modified_sine_velocity_and_displacement_A_2_18_to_A_2_20():
    """Each derived piece equals the printed velocity (A.2.18)/(A.2.19) and displacement (A.2.20)."""
    law = LAWS["modified-sine"]
    Hm = pi**2 / (2 - 8 * theta + 2 * pi * theta)
    th = theta
    vel = [2 * th / pi * Hm * (1 - sp.cos(pi * T / (2 * th))),
           Hm * ((1 - 2 * th) / pi * sp.sin(pi * (T - th) / (1 - 2 * th)) + 2 * th / pi),
           2 * th / pi * Hm * (1 + sp.cos(pi * (2 * th - 1 + T) / (2 * th)))]
    disp = [2 * th / pi * Hm * (T - 2 * th / pi * sp.sin(pi * T / (2 * th))),
            Hm * (-((1 - 2 * th) / pi) ** 2 * sp.cos(pi * (T - th) / (1 - 2 * th))
                  + 2 * th / pi * T + (1 - 4 * th) / pi**2),
            Hm * ((2 * th / pi) ** 2 * sp.sin(pi * (2 * th - 1 + T) / (2 * th))
                  + 2 * th / pi * T + (2 - 8 * th) / pi**2)]
    for k in range(3):
        assert sp.simplify(law.rise[k].diff(T) - vel[k]) == 0, f"velocity piece {k}"
        assert sp.simplify(law.rise[k] - disp[k]) == 0, f"displacement piece {k}"


def test_modified_sine_jerk_A_2_21_A_2_22():
    """theta = 0.1: jerk +85 at T = 0 and 1, -21.2 at T = 0.5 (printed digits)."""
    law = LAWS["modified-sine"]
    j = [h.diff(T, 3).subs(theta, sp.Rational(1, 10)) for h in law.rise]
    assert matches_printed(float(j[0].subs(T, 0)), "85")
    assert matches_printed(float(j[2].subs(T, 1)), "85")
    assert matches_printed(float(j[1].subs(T, sp.Rational(1, 2))), "-21.2")


def test_modified_sine_at_quarter_is_the_cycloid():
    """theta = 1/4: the three pieces join into the cycloid (A.2.10)."""
    law = LAWS["modified-sine"]
    cyc = T - sp.sin(2 * pi * T) / (2 * pi)
    for h in law.rise:
        assert sp.simplify(h.subs(theta, sp.Rational(1, 4)) - cyc) == 0


@pytest.mark.parametrize("key", sorted(LAWS))
def test_rise_boundary_and_continuity(key):
    """H(0) = 0, H(1) = 1, H'(0) = H'(1) = 0; H and H' continuous at interior breakpoints."""
    law = LAWS[key]
    sub = {law.parameter.symbol: sp.Rational(1, 10)} if law.parameter else {}
    H = [h.subs(sub) for h in law.rise]
    b = [sp.sympify(x).subs(sub) for x in law.bounds]
    assert sp.simplify(H[0].subs(T, 0)) == 0
    assert sp.simplify(H[-1].subs(T, 1) - 1) == 0
    if key == "uniform":   # the velocity jumps to 1 and back: impulsive acceleration
        assert H[0].diff(T) == 1 and law.amplitude is None
        return
    assert sp.simplify(H[0].diff(T).subs(T, 0)) == 0
    assert sp.simplify(H[-1].diff(T).subs(T, 1)) == 0
    for k in range(1, len(H)):
        for order in (0, 1):
            left = H[k - 1].diff(T, order).subs(T, b[k])
            right = H[k].diff(T, order).subs(T, b[k])
            assert sp.simplify(left - right) == 0


def test_known_peak_accelerations():
    """Amplitudes derived from H(1) = 1 against the classical values of each law."""
    expect = {"3-4-5": 10 / sp.sqrt(3), "parabolic": 4, "simple-harmonic": pi**2 / 2,
              "4-5-6-7": 84 * sp.sqrt(5) / 25, "modified-trapezoid": 8 * pi / (2 + pi)}
    for key, value in expect.items():
        assert sp.simplify(LAWS[key].amplitude - value) == 0, key
    # the classical 3-4-5 displacement
    assert sp.expand(LAWS["3-4-5"].rise[0] - (10 * T**3 - 15 * T**4 + 6 * T**5)) == 0
    assert sp.expand(LAWS["4-5-6-7"].rise[0] - (35 * T**4 - 84 * T**5 + 70 * T**6 - 20 * T**7)) == 0
    # modified trapezoid peak 4.888 (8 pi/(2 + pi))
    assert float(LAWS["modified-trapezoid"].amplitude) == pytest.approx(4.8881, abs=1e-4)


@pytest.mark.parametrize("key", sorted(LAWS))
def test_generated_library_matches_sympy(key, rng):
    """The generated cam-law code equals the symbolic law at random T, to 1e-12."""
    law = LAWS[key]
    par = 0.1 + 0.3 * rng.random() if law.parameter else None
    choice = rt_laws.choose(key, par)
    Ts = np.concatenate([rng.uniform(-0.5, 1.5, 400), law.breakpoints(par)])
    got = choice.evaluate(Ts)
    for order in range(4):
        ref = law.numeric(order, par)(Ts)
        np.testing.assert_allclose(got[:, order], ref, rtol=1e-12, atol=1e-12 * (1 + np.abs(ref).max()))


def test_breakpoints_and_runtime_errors():
    assert rt_laws.choose("modified-sine", 0.1).breakpoints() == pytest.approx([0, 0.1, 0.9, 1])
    assert rt_laws.choose("parabolic").breakpoints() == [0, 0.5, 1]
    with pytest.raises(CamdynInputError, match="theta=0.7 is out of range"):
        rt_laws.choose("modified-sine", 0.7)
    with pytest.raises(CamdynInputError, match="unknown cam law 'sine'"):
        rt_laws.choose("sine")
    with pytest.raises(ValueError, match="unknown cam law"):
        camlaws.get("sine")


def test_law_codes_are_unique_and_those_of_the_compiled_library():
    """A code selects a law in the generated if/elif chains (camdyn/generated/camlaws.pyx) and is
    "stable, never reused": no two laws share one, LAW_BY_CODE maps each back to its law, and each
    is the code under which the checked-in compiled library evaluates the law of that name."""
    codes = {key: law.code for key, law in LAWS.items()}
    assert len(set(codes.values())) == len(codes)
    assert {c: law.key for c, law in camlaws.LAW_BY_CODE.items()} == {c: k for k, c in codes.items()}
    from camdyn.generated import camlaws as lib

    assert {law["key"]: law["code"] for law in lib.LAWS} == codes


# -- polynomial laws by boundary conditions ---------------------------------------------


def test_polynomial_2n1_family_coefficients():
    """H', ..., H^(n) zero at both ends: n = 2 is 3-4-5, n = 3 is 4-5-6-7 (the classical
    coefficients), and H' of the family is proportional to T^n (1 - T)^n (an independent
    form: integrating it and scaling to H(1) = 1 must give the same polynomial)."""
    assert sp.expand(camlaws.polynomial_2n1(2) - (10 * T**3 - 15 * T**4 + 6 * T**5)) == 0
    assert sp.expand(camlaws.polynomial_2n1(3)
                     - (35 * T**4 - 84 * T**5 + 70 * T**6 - 20 * T**7)) == 0
    for n in (2, 3, 4, 5):
        v = sp.integrate(T**n * (1 - T) ** n, (T, 0, T))
        assert sp.expand(camlaws.polynomial_2n1(n) - v / v.subs(T, 1)) == 0, n
    # the registered laws are the builder's members
    assert sp.expand(LAWS["3-4-5"].rise[0] - camlaws.polynomial_2n1(2)) == 0
    assert sp.expand(LAWS["4-5-6-7"].rise[0] - camlaws.polynomial_2n1(3)) == 0


def test_polynomial_peak_accelerations():
    """Peak H'' of 3-4-5 is 10/sqrt 3 = 5.7735 and of 4-5-6-7 84 sqrt 5/25 = 7.5132 (roots of
    H''' in closed form); Norton's tables print 5.7735 and 7.51.  Checked against a dense
    numeric scan of the polynomials, tolerance 1e-9."""
    grid = np.linspace(0, 1, 200001)
    for n, exact, printed in ((2, 10 / sp.sqrt(3), "5.7735"), (3, 84 * sp.sqrt(5) / 25, "7.51")):
        acc = sp.lambdify(T, camlaws.polynomial_2n1(n).diff(T, 2))(grid)
        assert float(exact) == pytest.approx(acc.max(), abs=1e-9)
        assert matches_printed(float(exact), printed)


def test_polynomial_by_general_boundary_conditions():
    """Two conditions: H(0) = 0, H(1) = 1 with H'(0) = H'(1) = 0 give the cubic 3 T^2 - 2 T^3;
    H''(1) = 0 added gives a quartic with that property.  A rise must start from rest."""
    assert sp.expand(camlaws.polynomial_rise({1: 0}, {1: 0}) - (3 * T**2 - 2 * T**3)) == 0
    H = camlaws.polynomial_rise({1: 0}, {1: 0, 2: 0})
    assert sp.degree(H, T) == 4
    assert [H.diff(T, k).subs(T, t) for t, k in ((0, 0), (0, 1), (1, 0), (1, 1), (1, 2))] \
        == [0, 0, 1, 0, 0]
    law = camlaws.polynomial_law("test-quartic", 99, {}, {1: 0, 2: 0})
    assert sp.expand(law.rise[0] - H) == 0
    with pytest.raises(ValueError, match="H'\\(0\\) must be 0"):
        camlaws.polynomial_law("bad", 98, {1: 1}, {1: 0})


# -- sine-constant-cosine acceleration ---------------------------------------------------


def _norton_scca_peak(b, d):
    """Peak acceleration factor of the SCCA family, Norton, Cam Design and Manufacturing
    Handbook, sec. 3 (SCCA): C_a = 4 pi^2/((pi^2 - 8)(b^2 - d^2) - 2 pi (pi - 2) b + pi^2)."""
    return 4 * pi**2 / ((pi**2 - 8) * (b**2 - d**2) - 2 * pi * (pi - 2) * b + pi**2)


def test_scca_peak_matches_the_published_closed_form():
    """The amplitude that H(1) = 1 fixes, derived for symbolic b and d, equals Norton's C_a;
    and so does that of the registered one-parameter law (b = 1/4, d = 3/4 - c)."""
    b, d = sp.symbols("b d", positive=True)
    bounds, acc = camlaws.scca_pieces(b, 1 - b - d, d)
    law = camlaws.CamLaw("scca-test", 97, "", "", bounds, acc)
    assert sp.simplify(law.amplitude - _norton_scca_peak(b, d)) == 0
    c = camlaws.c_scca
    got = LAWS["sine-constant-cosine"].amplitude
    assert sp.simplify(got - _norton_scca_peak(sp.Rational(1, 4), sp.Rational(3, 4) - c)) == 0


@pytest.mark.parametrize("bcd, printed", [
    ((sp.Rational(1, 4), sp.Rational(1, 2), sp.Rational(1, 4)), "4.8881"),   # modified trapezoid
    ((sp.Rational(1, 4), 0, sp.Rational(3, 4)), "5.5280"),                    # modified sine
    ((sp.Rational(1, 2), 0, sp.Rational(1, 2)), "6.2832"),                    # cycloidal
    ((0, 0, 1), "4.9348"),                                                     # simple harmonic
    ((0, 1, 0), "4.0000"),                                                     # constant accel.
])
def test_scca_members_against_norton_table_and_numeric_integration(bcd, printed):
    """Norton's table of the SCCA members prints these C_a to 4 decimals.  Independently of
    SymPy's integration, the unit-amplitude acceleration is integrated twice numerically
    (scipy quad, 1e-12): C_a = 1/H(1) for unit amplitude."""
    from scipy.integrate import quad

    bounds, acc = camlaws.scca_pieces(*bcd)
    law = camlaws.CamLaw("scca-member", 96, "", "", bounds, acc)
    assert matches_printed(float(law.amplitude), printed)
    shape = [sp.lambdify(T, a.subs(camlaws._A, 1)) for a in acc]
    b = [float(x) for x in bounds]

    def a_unit(t):
        k = min(np.searchsorted(b, t, side="right") - 1, len(shape) - 1)
        return float(shape[k](t))

    # H(1) = int_0^1 (1 - s) a(s) ds from rest
    h1 = sum(quad(lambda s: (1 - s) * a_unit(s), b[k], b[k + 1], epsabs=1e-13)[0]
             for k in range(len(shape)))
    assert 1 / h1 == pytest.approx(float(law.amplitude), rel=1e-10)


def test_scca_ends_of_its_parameter():
    """c -> 0 is the thesis's modified sine at theta = 1/8 ((A.2.17): pi^2/(2 - 1 + pi/4)),
    c = 1/2 the modified trapezoid of the library."""
    got = LAWS["sine-constant-cosine"].amplitude
    c = camlaws.c_scca
    ms = LAWS["modified-sine"].amplitude.subs(theta, sp.Rational(1, 8))
    assert sp.simplify(got.subs(c, 0) - ms) == 0
    assert sp.simplify(got.subs(c, sp.Rational(1, 2)) - LAWS["modified-trapezoid"].amplitude) == 0


@pytest.mark.parametrize("n", [0, -1, 2.5, True])
def test_polynomial_2n1_needs_a_whole_n(n):
    """n < 1 or not whole is refused (n = -1 gave the uniform law, 2.5 a TypeError)."""
    with pytest.raises(ValueError, match="whole n >= 1"):
        camlaws.polynomial_2n1(n)


def test_polynomial_2n1_n1_is_the_cubic():
    """n = 1: H' zero at both ends only, H = 3T^2 - 2T^3."""
    assert sp.expand(camlaws.polynomial_2n1(1) - (3 * T**2 - 2 * T**3)) == 0


def test_the_laws_sine_and_cosine_are_libms_to_two_units_in_the_last_place():
    """The laws' own sin and cos (camlaws.pxd: Cody and Waite's reduction to |r| <= pi/4, the
    Taylor series to r^17 and r^18) against NumPy's (libm's) on a million random arguments in
    a law's range, a sweep through several turns, large arguments (libm's own beyond 1e6) and
    the quadrant edges: within 2 units in the last place of the result, or 2.3e-16 absolute
    where the result is near zero."""
    from camdyn.generated import camlaws as compiled

    rng = np.random.default_rng(7)
    x = np.concatenate([rng.uniform(-10.0, 10.0, 10**6), np.linspace(-7.0, 7.0, 100001),
                        rng.uniform(-1e6, 1e6, 10**4), rng.uniform(-1e9, 1e9, 100),
                        np.arange(-8, 9) * np.pi / 4, [0.0, 1e-300, -1e-300]])
    s, c = compiled.law_trig(x)
    for mine, ref in ((s, np.sin(x)), (c, np.cos(x))):
        err = np.abs(mine - ref)
        assert np.all(err <= np.maximum(2 * np.spacing(np.abs(ref)), 2.3e-16))
    assert s[-3] == 0.0 and s[-2] == 1e-300 and c[-3] == 1.0


@pytest.mark.slow
def test_the_laws_sine_and_cosine_polynomials_are_the_fitted_ones():
    """camlaws.pxd's polynomials for sin and cos are those derive/trig_fit.py fits (least
    largest relative error on |r| <= pi/4, Lawson's iteration in 40 digits), to the printed
    digit, and their largest relative errors there are below 1.1e-17 (sin, degree 13) and
    1.2e-18 (cos, degree 14), as the Taylor series of degrees 17 and 18 would give."""
    from pathlib import Path

    from camdyn.derive import trig_fit

    text = (Path(__file__).resolve().parents[1] / "generated" / "camlaws.pxd").read_text()
    for kind, bound in (("sin", 1.1e-17), ("cos", 1.2e-18)):
        c = trig_fit.fit(kind)
        for x in c:
            assert repr(x) in text, (kind, x)
        assert trig_fit.largest_error(kind, c, n=4000) < bound

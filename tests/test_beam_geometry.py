"""Grooved disk cam of the Rayleigh-beam paper: motion, envelope, curvature.

The references below are computed independently of ``camdyn.derive.beam.geometry``:
paper (1) typed into NumPy, the laws' own ``CamLaw.numeric`` scaled by hand, the
polar-curve formulas of textbook differential geometry, finite differences of the
wall points and brute-force distances to the pitch curve.
"""
import numpy as np
import pytest
import sympy as sp

from camdyn.derive import camlaws
from camdyn.derive.beam import geometry as g
from camdyn.derive.beam.geometry import S_T, r, r_b, r_r, theta

pi = sp.pi
rp, rpp = sp.diff(r, theta), sp.diff(r, theta, 2)
P = r * sp.sin(theta) - rp * sp.cos(theta)          # paper (3)
Q = r * sp.cos(theta) + rp * sp.sin(theta)          # paper (3), sign derived (see below)

PAPER = g.CamGeometry()                               # S_T = 15 mm, r_b = 26 mm, r_r = 5 mm

_r0 = sp.Symbol("r0", positive=True)
_r1, _r2 = sp.symbols("r1 r2", real=True)


def is_zero(expr):
    """expr == 0 with r, r', r'' as plain symbols (r > 0), so sqrt(1/x) = 1/sqrt(x)."""
    plain = expr.xreplace({rpp: _r2, rp: _r1, r: _r0})
    zero = sp.zeros(*plain.shape) if hasattr(plain, "shape") else 0
    return sp.expand(plain) == zero or sp.simplify(plain) == zero


def test_P2_plus_Q2_is_r2_plus_r1_2():
    """|pitch tangent|^2: used below to write sqrt(P^2 + Q^2) as sqrt(r^2 + r'^2)."""
    assert sp.trigsimp(sp.expand(P**2 + Q**2)) == r**2 + rp**2
    assert g.pitch_curve().diff(theta) == sp.Matrix([-P, Q])


NORM = sp.sqrt(r**2 + rp**2)          # = sqrt(P^2 + Q^2), test above


def s_paper(th, S_T, order=0):
    """Paper (1) for rise and fall over pi/2, fig. 2 layout, in plain NumPy."""
    beta = np.pi / 2
    th = np.asarray(th, float)
    out = np.zeros_like(th)
    rise = th < beta
    fall = (th >= np.pi) & (th < 1.5 * np.pi)
    dwell = (th >= beta) & (th < np.pi)
    for mask, x, sgn in ((rise, th / beta, 1.0), (fall, (th - np.pi) / beta, -1.0)):
        T = x[mask]
        shape = [T - np.sin(2 * np.pi * T) / (2 * np.pi), 1 - np.cos(2 * np.pi * T),
                 2 * np.pi * np.sin(2 * np.pi * T)][order]
        out[mask] = sgn * S_T * shape / beta ** order
    if order == 0:
        out[fall] += S_T
        out[dwell] = S_T
    return out


def pitch_ref(geom, th, S, S1):
    """Pitch point and tangent from the polar form, with S, S' given."""
    rr = geom.r_b + geom.r_r + S
    c, s = np.cos(th), np.sin(th)
    return np.array([rr * c, rr * s]), np.array([S1 * c - rr * s, S1 * s + rr * c])


# -- motion, paper (1) ---------------------------------------------------------------

def test_rdfd_cycloid_is_paper_1_with_the_fig_2_layout():
    segs = g.rdfd_segments()
    assert [s.name for s in segs] == ["rise", "outer dwell", "fall", "inner dwell"]
    assert [(s.lo, s.hi) for s in segs] == [(0, pi / 2), (pi / 2, pi), (pi, 3 * pi / 2),
                                            (3 * pi / 2, 2 * pi)]
    beta = pi / 2
    rise = S_T * (theta / beta - sp.sin(2 * pi * theta / beta) / (2 * pi))       # paper (1)
    assert sp.simplify(segs[0].S - rise) == 0
    assert sp.simplify(segs[2].S - (S_T - rise.subs(theta, theta - pi))) == 0      # "S_T - rise"
    S = g.rdfd_displacement()
    for at, want in ((0, 0), (pi / 2, S_T), (pi, S_T), (3 * pi / 2, 0), (2 * pi, 0)):
        assert sp.simplify(S.subs(theta, at) - want) == 0


def _jumps(segs, order):
    """Exact jumps of d^order S at every segment end, the 2 pi -> 0 wrap included."""
    out = []
    for a, b in zip(segs, segs[1:] + segs[:1]):
        left = sp.diff(a.S, theta, order).subs(theta, a.hi)
        right = sp.diff(b.S, theta, order).subs(theta, b.lo)
        out.append((left - right).equals(0))
    return out


def test_cycloid_S_S1_S2_continuous_everywhere():
    segs = list(g.rdfd_segments())
    for order in (0, 1, 2):
        assert all(_jumps(segs, order)), order
    assert not all(_jumps(segs, 3))    # the cycloid's jerk does jump (A.2.16)


def test_cycloid_numbers_against_paper_1_in_numpy(rng):
    th = np.concatenate([rng.uniform(0, 2 * np.pi, 400), [0, np.pi / 2, np.pi, 1.5 * np.pi]])
    for order in (0, 1, 2):
        assert np.allclose(PAPER.displacement(th, order), s_paper(th, 0.015, order),
                           rtol=0, atol=1e-15)
    assert PAPER.displacement([0, np.pi / 2, np.pi, 1.5 * np.pi, 2 * np.pi]) == pytest.approx(
        [0, 0.015, 0.015, 0, 0], abs=1e-16)


@pytest.mark.parametrize("law", [("modified-sine", 0.2), "3-4-5", "simple-harmonic", "4-5-6-7"])
def test_other_library_laws(law):
    segs = list(g.rdfd_segments(S_T, law))
    assert all(_jumps(segs, 0)) and all(_jumps(segs, 1))
    S = g.rdfd_displacement(S_T, law)
    for at, want in ((0, 0), (pi / 2, S_T), (pi, S_T), (3 * pi / 2, 0)):
        assert sp.simplify(S.subs(theta, at) - want) == 0
    # numbers against the library's own numeric law, rise and fall scaled by hand
    key, value = law if isinstance(law, tuple) else (law, None)
    geom = g.CamGeometry(rise_law=law)
    th = np.linspace(0, 2 * np.pi, 801)
    H = camlaws.LAWS[key].numeric(0, value)
    beta = np.pi / 2
    want = np.where(th < beta, 0.015 * H(th / beta), 0.0)
    want = np.where((th >= beta) & (th < np.pi), 0.015, want)
    want = np.where((th >= np.pi) & (th < 1.5 * np.pi), 0.015 * (1 - H((th - np.pi) / beta)), want)
    assert np.allclose(geom.displacement(th), want, rtol=0, atol=1e-15)
    # the envelope property holds whatever the law
    w, p = geom.wall(th, "inner"), geom.pitch(th)
    assert np.allclose(np.hypot(*(w - p)), 0.005, rtol=0, atol=1e-12)


def test_simple_harmonic_acceleration_jumps_and_mixed_laws():
    segs = list(g.rdfd_segments(S_T, "simple-harmonic"))
    assert not all(_jumps(segs, 2))
    mixed = list(g.rdfd_segments(S_T, "cycloidal", "3-4-5"))
    assert all(_jumps(mixed, 1))
    assert [s.name for s in mixed] == ["rise", "outer dwell", "fall", "inner dwell"]


def test_law_as_expression_and_bad_inputs():
    T = camlaws.T
    S = g.rdfd_displacement(S_T, 3 * T**2 - 2 * T**3)          # a cubic, written in place
    assert sp.simplify(S.subs(theta, pi / 4) - S_T / 2) == 0
    with pytest.raises(ValueError, match="H\\(1\\) = 1"):
        g.law_pieces(T**2 / 2)
    with pytest.raises(ValueError, match="unknown cam law"):
        g.law_pieces("no-such-law")
    assert [hi for _, hi in g.law_pieces("modified-sine")] == [sp.Rational(1, 10),
                                                              sp.Rational(9, 10), 1]
    with pytest.raises(ValueError, match="outside the range"):
        g.law_pieces(("modified-sine", 0.7))
    with pytest.raises(ValueError, match="fit in one revolution"):
        g.rdfd_segments(beta_rise=pi, dwell_outer=pi / 2, beta_fall=pi)
    with pytest.raises(ValueError, match="positive length"):
        g.CamGeometry(r_b=-0.01)


# -- envelope, paper (2)-(4) --------------------------------------------------------------

def test_walls_solve_the_envelope_conditions():
    F, G = g.roller_family(), g.envelope_condition()
    for side in g.SIDES:
        on = dict(zip((g.X, g.Y), g.groove_walls()[side]))
        assert sp.simplify(F.subs(on)) == 0
        assert sp.simplify(G.subs(on)) == 0


def test_walls_are_pitch_point_minus_plus_r_r_times_the_unit_normal():
    p = g.pitch_curve()
    n = sp.Matrix([Q, P]) / NORM                    # tangent (-P, Q) turned by -90 degrees
    walls = g.groove_walls()
    assert is_zero(walls["inner"] - (p - r_r * n))
    assert is_zero(walls["outer"] - (p + r_r * n))
    assert is_zero(g.outward_normal() - n)


def test_printed_form_2_3_is_the_inner_wall_when_Q_has_a_plus():
    """Reading of the scan: X = r cos th - r_r Q/sqrt(P^2+Q^2), Y = r sin th + (X - r cos th) P/Q.

    With Q = r cos th + S' sin th this is exactly the inner wall (and the outer with
    +r_r).  The scan shows a dash before S' sin th; with a minus the formula misses
    the wall by millimetres during the rise, so that dash is read as a plus.
    """
    def printed(Qx, sign=-1):
        # sqrt(P^2 + Q^2) = NORM (test_P2_plus_Q2_is_r2_plus_r1_2), kept literal for another Q
        norm = NORM if Qx == Q else sp.sqrt(P**2 + Qx**2)
        Xc = r * sp.cos(theta) + sign * r_r * Qx / norm
        return sp.Matrix([Xc, r * sp.sin(theta) + (Xc - r * sp.cos(theta)) * P / Qx])

    walls = g.groove_walls()
    assert is_zero(printed(Q) - walls["inner"])
    assert is_zero(printed(Q, +1) - walls["outer"])
    # the minus reading on the paper cam, mid-rise
    rr_ = g.pitch_radius(g.rdfd_displacement(), r_b, r_r)
    at = {theta: pi / 4, S_T: sp.Rational(15, 1000), r_b: sp.Rational(26, 1000),
          r_r: sp.Rational(5, 1000)}
    minus = g.bind(printed(r * sp.cos(theta) - rp * sp.sin(theta)), rr_)
    miss = (minus - g.bind(walls["inner"], rr_)).subs(at).evalf()
    assert miss.norm() > 1e-3                      # 2.3 mm at theta = pi/4


def test_every_profile_point_is_r_r_from_the_pitch_curve_along_the_common_normal():
    th = np.linspace(0, 2 * np.pi, 2001)
    p, t = pitch_ref(PAPER, th, s_paper(th, 0.015), s_paper(th, 0.015, 1))
    t_hat = t / np.hypot(*t)
    for side, sgn in (("inner", -1), ("outer", +1)):
        d = PAPER.wall(th, side) - p
        assert np.abs(np.hypot(*d) - 0.005).max() < 1e-12                       # on the roller
        assert np.abs(np.einsum("ij,ij->j", d, t_hat)).max() < 1e-12            # along the normal
        assert np.all(sgn * (d[0] * p[0] + d[1] * p[1]) > 0)                    # on its side
        # the wall's own tangent (central differences) is parallel to the pitch tangent
        h = 1e-5
        wt = (PAPER.wall(th + h, side) - PAPER.wall(th - h, side)) / (2 * h)
        wt /= np.hypot(*wt)
        assert np.abs(wt[0] * t_hat[1] - wt[1] * t_hat[0]).max() < 1e-8
        assert np.all(np.einsum("ij,ij->j", wt, t_hat) > 0)


def test_roller_never_cuts_the_walls_of_the_paper_cam():
    """Brute force: no pitch-curve point comes closer than r_r to any wall point."""
    th = np.linspace(0, 2 * np.pi, 1001)
    fine = np.linspace(0, 2 * np.pi, 4001)
    p = PAPER.pitch(fine)
    for side in g.SIDES:
        w = PAPER.wall(th, side)
        dist = np.hypot(w[0][:, None] - p[0][None, :], w[1][:, None] - p[1][None, :])
        assert dist.min() > 0.005 - 1e-12


def test_dwell_arcs_give_circular_walls():
    const = g.pitch_radius(S_T, r_b, r_r)                   # outer dwell: S = S_T
    for side, radius in (("inner", r_b + S_T), ("outer", r_b + S_T + 2 * r_r)):
        w = g.bind(g.groove_walls()[side], const)
        assert sp.trigsimp(sp.expand(w.dot(w) - radius**2)) == 0
    for lo, hi, S, in ((np.pi / 2, np.pi, 0.015), (1.5 * np.pi, 2 * np.pi, 0.0)):
        th = np.linspace(lo, hi, 200)
        for side, radius in (("inner", 0.026 + S), ("outer", 0.026 + S + 0.010)):
            assert np.abs(np.hypot(*PAPER.wall(th, side)) - radius).max() < 1e-12
            assert np.abs(PAPER.wall_radius_of_curvature(th, side) - radius).max() < 1e-12


# -- pressure angle and curvature -------------------------------------------------------

def test_pressure_angle_tan_phi_is_S1_over_r():
    assert sp.simplify(g.tan_pressure_angle() - rp / r) == 0
    th = np.linspace(0, 2 * np.pi, 1441)
    S, S1 = s_paper(th, 0.015), s_paper(th, 0.015, 1)
    phi = PAPER.pressure_angle(th)
    assert np.abs(phi - np.arctan(S1 / (0.031 + S))).max() < 1e-14
    # and from the wall points: angle between (outer - inner)/2 r_r and the radial direction
    n = (PAPER.wall(th, "outer") - PAPER.wall(th, "inner")) / 0.010
    e = np.array([np.cos(th), np.sin(th)])
    assert np.abs(np.arctan2(n[0] * e[1] - n[1] * e[0], np.einsum("ij,ij->j", n, e)) - phi).max() < 1e-12
    assert phi.max() > 0 > phi.min()                                   # rise > 0, fall < 0


def test_pitch_curvature_is_the_polar_closed_form():
    closed = (r**2 + 2 * rp**2 - r * rpp) / (r**2 + rp**2) ** sp.Rational(3, 2)
    assert sp.simplify(g.pitch_curvature() - closed) == 0
    th = np.linspace(0, 2 * np.pi, 1441)
    rr, r1, r2 = 0.031 + s_paper(th, 0.015), s_paper(th, 0.015, 1), s_paper(th, 0.015, 2)
    rho = (rr**2 + r1**2) ** 1.5 / (rr**2 + 2 * r1**2 - rr * r2)
    assert np.abs(PAPER.pitch_radius_of_curvature(th) / rho - 1).max() < 1e-12


def test_wall_curvature_is_rho_p_minus_plus_r_r():
    th = np.linspace(0, 2 * np.pi, 1441)
    rho = PAPER.pitch_radius_of_curvature(th)
    flat = np.abs(rho) > 1.0            # near an inflection both are huge: compare curvatures
    for side, d in (("inner", -0.005), ("outer", 0.005)):
        rho_w = PAPER.wall_radius_of_curvature(th, side)
        assert np.abs(rho_w[~flat] / (rho[~flat] + d) - 1).max() < 1e-12
        assert np.abs(1 / rho_w[flat] - 1 / (rho[flat] + d)).max() < 1e-12


# -- undercut (camdyn.runtime.cam.motion: NumPy on the compiled laws) ----------------------------

def _runtime_cam(geom, law="cycloidal"):
    from camdyn.runtime.cam.motion import RDFD

    return RDFD.of(geom.S_T, geom.r_b, geom.r_r, law, beta_rise=float(geom.beta_rise),
                   dwell_outer=float(geom.dwell_outer), beta_fall=float(geom.beta_fall))


@pytest.mark.parametrize("law", ["cycloidal", "modified-sine", "3-4-5", "4-5-6-7"])
@pytest.mark.parametrize("shape", [dict(S_T=0.015, r_b=0.026, r_r=0.005),
                                   dict(S_T=0.022, r_b=0.002, r_r=0.005, beta_rise=pi / 4,
                                        beta_fall=pi / 4)])
def test_runtime_profile_is_the_symbolic_geometry(law, shape):
    """The run-time cam (S and its first three derivatives from the compiled law library, the
    pitch curvature by the polar formula (r^2 + 2 r1^2 - r r2)/(r^2 + r1^2)^(3/2), r1, r2 the
    derivatives of r in theta) against this module's symbolic RDFD (paper (1)) and the
    curvature of the pitch curve derived by SymPy, on 20001 angles and at the segment ends:
    1e-12 of each quantity's largest magnitude (measured <= 3.5e-14)."""
    geom = g.CamGeometry(rise_law=law, **shape)
    cam = _runtime_cam(geom, law)
    th = np.union1d(np.linspace(0.0, 2 * np.pi, 20001), geom.breakpoints)
    np.testing.assert_allclose(cam.breakpoints, geom.breakpoints, rtol=1e-15, atol=0)
    S = cam.displacement(th)
    for k in range(4):
        want = geom.displacement(th, k)
        assert np.abs(S[k] - want).max() <= 1e-12 * np.abs(want).max(), k
    want = geom.pitch_curvature(th)
    assert np.abs(cam.pitch_curvature(th) - want).max() <= 1e-12 * np.abs(want).max()


def test_paper_cam_has_no_undercut():
    u = _runtime_cam(PAPER).undercut()
    assert not u and u.inner == () and u.outer == ()
    u.check()
    assert u.min_rho_convex > 0.005 and u.min_rho_concave > 0.005
    assert "no undercut" in u.message


def test_tiny_base_circle_big_rise_is_undercut_on_the_concave_parts():
    """r_b = 2 mm, S_T = 22 mm, r_r = 5 mm: the outer wall fails where the rise starts and the fall ends."""
    from camdyn.runtime.cam.motion import UndercutError

    geom = g.CamGeometry(S_T=0.022, r_b=0.002, r_r=0.005)
    u = _runtime_cam(geom).undercut()
    assert u and u.inner == () and len(u.outer) == 2
    assert u.min_rho_concave < 0.005
    _check_intervals(geom, u.outer, "outer")
    with pytest.raises(UndercutError, match="outer wall is undercut"):
        u.check()


def test_fast_rise_undercuts_the_inner_wall_on_a_convex_part():
    """Rise and fall over pi/4: the end of the rise is convex with rho_p < r_r."""
    from camdyn.runtime.cam.motion import UndercutError

    geom = g.CamGeometry(S_T=0.022, r_b=0.002, r_r=0.005, beta_rise=pi / 4, beta_fall=pi / 4)
    u = _runtime_cam(geom).undercut()
    assert len(u.inner) == 2 and u.min_rho_convex < 0.005
    _check_intervals(geom, u.inner, "inner")
    with pytest.raises(UndercutError, match="inner wall is undercut"):
        u.check()


def _check_intervals(geom, spans, side):
    """At the ends rho_p = -/+ r_r; inside, the wall points run backwards (a swallowtail)."""
    sgn = -1 if side == "inner" else 1
    for lo, hi in spans:
        assert geom.pitch_radius_of_curvature(np.array([lo, hi])) == pytest.approx(
            [-sgn * 0.005] * 2, rel=1e-9)
        mid = np.linspace(lo, hi, 50)[1:-1]
        h = 1e-7
        wt = (geom.wall(mid + h, side) - geom.wall(mid - h, side)) / (2 * h)
        _, t = pitch_ref(geom, mid, geom.displacement(mid), geom.displacement(mid, 1))
        assert np.all(np.einsum("ij,ij->j", wt, t) < 0)
        out = np.array([lo - 1e-3, hi + 1e-3])
        wt = (geom.wall(out + h, side) - geom.wall(out - h, side)) / (2 * h)
        _, t = pitch_ref(geom, out, geom.displacement(out), geom.displacement(out, 1))
        assert np.all(np.einsum("ij,ij->j", wt, t) > 0)


def test_sample_grid():
    out = PAPER.sample(361)
    assert out["inner"].shape == (2, 361) and out["rho_outer"].shape == (361,)
    assert out["S"].max() == pytest.approx(0.015, abs=1e-15)

"""Property-based tests (Hypothesis) of the cam laws of thesis App. 2 and of the scene checks.

Cam laws.  Each law is checked twice: as the symbolic law of ``camdyn.derive.camlaws``
(its pieces evaluated in 40-digit mpmath, so the reference carries no rounding of its own)
and as the compiled library that simulations use (``camdyn.runtime.core.laws.choose(...).evaluate``,
the generated ``camlaws`` module).  Properties, for T and theta drawn by Hypothesis:

* the rise joins the dwells, H = 0 before T = 0 and H = 1 after T = 1 (A.2.1)-(A.2.3),
  with every derivative up to the law's order of continuity there, and the first derivative
  that jumps jumps by the closed form of the law (e.g. H''' = 4 pi^2 = 39.4 for the cycloid,
  (A.2.15); H''' = H''max pi/(2 theta), 85 at theta = 0.1, for the modified sine, (A.2.21));
* at the interior breakpoints the pieces meet to their order of continuity and the next
  derivative jumps by its closed form;
* every law here is point-symmetric about T = 1/2: H(T) + H(1 - T) = 1, so H' and H''' are
  even and H'' is odd about T = 1/2;
* the compiled law equals the symbolic one, and the modified sine keeps the printed peak
  H''max = pi^2/(2 - 8 theta + 2 pi theta) at T = theta (A.2.17) and the jerks of (A.2.21),
  (A.2.22) for every theta.

Tolerances are relative to the size of the derivative over the rise (``_scale``): at small
theta the modified sine's jerk is of order 1/theta, so the rounding of each evaluation is too.
theta is drawn from [1e-3, 0.49] inside the declared open range 0 < theta < 1/2.  Below it the
breakpoint 1 - theta, which is not a double, moves H''' by H'''' 1e-16, a fraction
(pi/(2 theta)) 1e-16 of its size, 1e-12 at theta = 1e-4 (and for theta < 1e-16 the piece BC
vanishes in doubles, 1 - theta == 1); above 0.49 the generated AB piece loses accuracy (the
known bug of ``test_modified_sine_near_half_keeps_its_peak``).  Measured worst cases below
are over all laws and 44 theta in [1e-3, 0.49] (scratch scan, not part of the suite).

Scenes.  Any single corruption of a built-in DYNACAM scene (runtime/scenes/*.toml), written
as TOML and read back with ``scene.load``, is refused with a ``CamdynInputError`` whose
one-line message names the offending key, and never raises anything else; a value drawn inside
the declared range is accepted.  The CAMSHAFT-1 study scene (default.toml) is checked the
same way against its own schema in ``report.load_scene``.
"""
from __future__ import annotations

import copy
import datetime
import functools
import math
import string
import subprocess
import sys
import tomllib
from dataclasses import fields
from pathlib import Path

import mpmath
import numpy as np
import pytest
import sympy as sp
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from camdyn.derive.camlaws import LAWS, T, theta
from camdyn.derive.models import dynacam as dynacam_model
from camdyn.runtime.core import laws as rt_laws
from camdyn.runtime.targets import camshaft1_study as report
from camdyn.runtime.targets import scene_files as scenes
from camdyn.runtime.core.errors import CamdynInputError

settings.register_profile("camdyn-fast", max_examples=60, deadline=None, derandomize=True,
                          database=None, suppress_health_check=[HealthCheck.too_slow])
FAST = settings.get_profile("camdyn-fast")
"""Reproducible (derandomized, no example database) and small enough for the fast suite."""

pi = math.pi

# -- cam laws -----------------------------------------------------------------------------

CONTINUITY = {
    # law: (highest continuous derivative where the rise meets the dwells, same at the
    #       interior breakpoints); from the acceleration pieces of App. 2 and the classical laws
    "cycloidal": (2, None),           # H'' = 2 pi sin 2 pi T is 0 at T = 0, 1 (A.2.8)
    "modified-sine": (2, 3),          # OA, AB, BC of (A.2.17) meet with H''' = 0
    "3-4-5": (2, None),
    "simple-harmonic": (1, None),     # H'' = (pi^2/2) cos pi T
    "parabolic": (1, 1),              # H'' = +4, then -4
    "4-5-6-7": (3, None),
    "modified-trapezoid": (2, 3),     # sine ramps meet the constant pieces with zero jerk
    "uniform": (0, None),             # H' jumps to 1: the ramp input (3.8)
    "sine-constant-cosine": (2, 3),   # like the modified trapezoid: zero-jerk joins
    "5-6-7-8-9": (4, None),           # derivatives 1 to 4 zero at both ends
    "polydyne": (2, None),            # H'' = P'' + c P^(4) zero at the ends, H''' is not
}


def _scca_peak(c):
    '''H''max of the SCCA law with b = 1/4, d = 3/4 - c: Norton's C_a =
    4 pi^2/((pi^2 - 8)(b^2 - d^2) - 2 pi (pi - 2) b + pi^2).'''
    b, d = 0.25, 0.75 - c
    return 4 * pi**2 / ((pi**2 - 8) * (b * b - d * d) - 2 * pi * (pi - 2) * b + pi**2)


def _modified_sine_peak(th):
    """H''max of the modified sine, (A.2.17)."""
    return pi**2 / (2 - 8 * th + 2 * pi * th)


def _start_jump(key, th):
    """(k, d^k H/dT^k at T = 0+) for the first derivative k that jumps at the start of the
    rise, from the closed forms of each law (worked by hand, not by camdyn)."""
    if key == "modified-sine":
        return 3, _modified_sine_peak(th) * pi / (2 * th)     # (A.2.21): 85 at theta = 0.1
    if key == "sine-constant-cosine":
        return 3, 4 * pi * _scca_peak(th)                     # H'' = A sin 4 pi T on [0, 1/8]
    if key == "polydyne":   # H''' = P''' + (tau_d/2 pi)^2 P^(5), P = 126 T^5 - ...
        return 3, (th / (2 * pi))**2 * 126 * 120
    trapezoid_peak = 8 * pi / (2 + pi)    # H'' = A sin 4 pi T on the first eighth, classical 4.888
    return {
        "cycloidal": (3, 4 * pi**2),        # (A.2.15): 39.4
        "3-4-5": (3, 60.0),                 # H''' = 60 - 360 T + 360 T^2
        "simple-harmonic": (2, pi**2 / 2),  # H'' = (pi^2/2) cos pi T
        "parabolic": (2, 4.0),
        "4-5-6-7": (4, 840.0),              # H = 35 T^4 - ...: H'''' = 840 at T = 0
        "5-6-7-8-9": (5, 15120.0),          # H = 126 T^5 - ...: H^(5) = 126 * 5! at T = 0
        "modified-trapezoid": (3, 4 * pi * trapezoid_peak),
        "uniform": (1, 1.0),
    }[key]


def _interior_jumps(key, th):
    """[(breakpoint, k, jump of d^k H/dT^k, right minus left)] at the interior breakpoints, k
    one above the order of continuity, from the acceleration pieces written out by hand."""
    if key == "parabolic":
        return [(0.5, 2, -8.0)]
    if key == "modified-sine":
        # H'''' of OA, AB, BC at their joins: -H''max (pi/2 theta)^2 and -+H''max (pi/(1 - 2 theta))^2
        jump = _modified_sine_peak(th) * pi**2 * (1 / (4 * th**2) - 1 / (1 - 2 * th) ** 2)
        return [(th, 4, jump), (1 - th, 4, jump)]
    if key == "modified-trapezoid":
        j = 16 * pi**2 * 8 * pi / (2 + pi)     # (4 pi)^2 A at the ends of each sine ramp
        return [(1 / 8, 4, j), (3 / 8, 4, -j), (5 / 8, 4, -j), (7 / 8, 4, j)]
    if key == "sine-constant-cosine":
        # sine ramps (4 pi)^2 A as above; the cosine piece A cos(pi (T - T0)/d), d = 3/4 - c,
        # has H'''' = -+A (pi/d)^2 at its ends, against 0 on the constant pieces
        a, d = _scca_peak(th), 0.75 - th
        j, k = 16 * pi**2 * a, pi**2 * a / d**2
        return [(1 / 8, 4, j), (1 / 8 + th / 2, 4, -k), (7 / 8 - th / 2, 4, -k), (7 / 8, 4, j)]
    return []


HUGE_INT = st.integers(2**1024, 10**400) | st.integers(-(10**400), -(2**1024))
"""Integers TOML can write but no double can hold."""

THETA = st.floats(1e-3, 0.49)
"""Modified-sine theta inside its declared range 0 < theta < 1/2 (limits: see the module doc)."""


@st.composite
def law_and_theta(draw):
    # the modified sine, the one law with a shape parameter, drawn as often as the others together
    key = draw(st.sampled_from(sorted(LAWS) + ["modified-sine"] * 6))
    return key, (draw(THETA) if LAWS[key].parameter else None)


@functools.cache
def _symbolic(key):
    """mpmath functions (T, theta) of each segment's d^k H/dT^k (dwells included, k = 0..4), of
    the law's own Piecewise (k = 0..3), and of its breakpoints (theta); k = 0..5 for the
    pieces, the degree-9 rise's first jump being in H^(5)."""
    law = LAWS[key]
    par = law.parameter.symbol if law.parameter else theta
    pieces = [[sp.lambdify((T, par), e, "mpmath") for e in law.segment_exprs(k)] for k in range(6)]
    whole = [sp.lambdify((T, par), law.piecewise(k), "mpmath") for k in range(4)]
    bounds = [sp.lambdify(par, b, "mpmath") for b in law.bounds]
    return pieces, whole, bounds


def _mp(f, *args):
    with mpmath.workdps(40):
        return f(*[mpmath.mpf(a) for a in args])


def _piece(key, th, seg, k, t):
    """d^k H/dT^k of the symbolic segment ``seg`` at T = t (a one-sided limit at a breakpoint;
    t may be a 40-digit breakpoint from ``_exact_bounds``)."""
    return float(_mp(_symbolic(key)[0][k][seg], t, th or 0.0))


def _symbolic_law(key, th, t):
    """H, H', H'', H''' of the symbolic law (its Piecewise) at T = t."""
    return np.array([float(_mp(_symbolic(key)[1][k], t, th or 0.0)) for k in range(4)])


def _exact_bounds(key, th):
    """The symbolic breakpoints to 40 digits (1 - theta is not a double)."""
    return [_mp(b, th or 0.0) for b in _symbolic(key)[2]]


def _bounds(key, th):
    return [float(b) for b in _exact_bounds(key, th)]


def _compiled(key, th, ts):
    """Rows H, H', H'', H''' of the compiled law at the times ``ts``."""
    return rt_laws.choose(key, th).evaluate(np.asarray(ts, dtype=float))


@functools.lru_cache(maxsize=4096)
def _scale(key, th):
    """Per order k = 0..5: 1 + the largest |d^k H/dT^k| at the ends and quarter points of every
    piece of the rise, from the symbolic law: the size that rounding scales with."""
    b = _bounds(key, th)
    out = np.ones(6)
    for seg in range(1, len(b)):
        for t in np.linspace(b[seg - 1], b[seg], 5):
            out = np.maximum(out, [1 + abs(_piece(key, th, seg, k, t)) for k in range(6)])
    return tuple(out)


def _close(got, want, scale, tol):
    return abs(got - want) <= tol * scale


@pytest.fixture(scope="module")
def symbolic_laws():
    """Derive every law once (SymPy integration, some 5 s) before the tests that evaluate them."""
    assert all(law.rise for law in LAWS.values())


@pytest.mark.usefixtures("symbolic_laws")
@FAST
@given(law_and_theta())
def test_rise_joins_the_dwells_to_the_declared_order(law):
    """H(0) = 0 and H(1) = 1 (A.2.3) to 1e-12, and d^k H/dT^k continuous into the dwells for k
    up to the declared order (``CONTINUITY``): on the symbolic pieces at T = 0, 1 to 1e-12 of
    the size of the derivative, on the compiled law at T = 0 and at the double below T = 1 to
    1e-9 (one unit in the last place of T moves H^(k) by H^(k+1) 1e-16).  The next derivative
    jumps, at T = 0+ by the closed form of ``_start_jump`` (e.g. (A.2.15), (A.2.21)) and at
    T = 1- by the same times (-1)^(k+1) (symmetry), to 1e-12 relative.  Measured: symbolic
    joins 1e-41 of the size; compiled H(0), H(1-) 7e-15, derivatives 1.5e-13 of the size
    (modified sine, theta = 1e-3, H'' one ulp below T = 1); jumps 2e-16 (symbolic), 4e-16
    (compiled) relative."""
    key, th = law
    order = CONTINUITY[key][0]
    last = len(_bounds(key, th)) - 1        # segment of the last piece of the rise
    s = _scale(key, th)
    for k in range(order + 1):
        after = 1.0 if k == 0 else 0.0
        assert _close(_piece(key, th, 1, k, 0.0), 0.0, s[k], 1e-12), (k, "T = 0")
        assert _close(_piece(key, th, last, k, 1.0), after, s[k], 1e-12), (k, "T = 1")
    k, value = _start_jump(key, th)
    assert _piece(key, th, 1, k, 0.0) == pytest.approx(value, rel=1e-12)
    assert _piece(key, th, last, k, 1.0) == pytest.approx((-1) ** (k + 1) * value, rel=1e-12)

    start, end = _compiled(key, th, [0.0, np.nextafter(1.0, 0.0)])
    assert abs(start[0]) <= 1e-12 and abs(end[0] - 1.0) <= 1e-12
    for k in range(1, min(order, 3) + 1):
        assert _close(start[k], 0.0, s[k], 1e-9) and _close(end[k], 0.0, s[k], 1e-9), k
    k, value = _start_jump(key, th)
    if k <= 3:
        assert start[k] == pytest.approx(value, rel=1e-12)


@pytest.mark.usefixtures("symbolic_laws")
@FAST
@given(law_and_theta())
def test_interior_breakpoints_join_to_the_declared_order(law):
    """At every interior breakpoint (theta and 1 - theta of the modified sine, 1/2 of the
    parabolic law, the eighths of the modified trapezoid) the left and right pieces agree in
    d^k H/dT^k for k up to the declared order: symbolic to 1e-12, compiled (the double below
    the breakpoint against the breakpoint) to 1e-9 of the derivative's size.  The derivative
    one above jumps by the closed form of ``_interior_jumps`` to 1e-9 relative (for the
    modified sine H'''' jumps by H''max pi^2 (1/(4 theta^2) - 1/(1 - 2 theta)^2), zero at theta
    = 1/4, where the law is the cycloid).  The compiled breakpoints equal the symbolic ones.
    Measured: symbolic joins 2e-41 of the size, jumps 4e-16 relative; compiled joins 1e-13 of
    the size (modified sine, theta = 0.49, H'' at theta)."""
    key, th = law
    order = CONTINUITY[key][1]
    b = _bounds(key, th)
    assert rt_laws.choose(key, th).breakpoints() == pytest.approx(b, rel=1e-15, abs=0)
    if order is None:
        assert len(b) == 2
        return
    s = _scale(key, th)
    jumps = _interior_jumps(key, th)
    assert [x for x, _, _ in jumps] == pytest.approx(b[1:-1], rel=1e-15)
    exact = _exact_bounds(key, th)
    for seg, (x, kj, jump) in enumerate(jumps, start=1):
        for k in range(order + 1):
            left, right = _piece(key, th, seg, k, exact[seg]), _piece(key, th, seg + 1, k, exact[seg])
            assert _close(left, right, s[k], 1e-12), (x, k)
        step = _piece(key, th, seg + 1, kj, exact[seg]) - _piece(key, th, seg, kj, exact[seg])
        assert step == pytest.approx(jump, rel=1e-9, abs=1e-9 * s[kj])
        left, right = _compiled(key, th, [np.nextafter(x, -1.0), x])
        for k in range(min(order, 3) + 1):
            assert _close(left[k], right[k], s[k], 1e-9), (x, k)


@pytest.mark.usefixtures("symbolic_laws")
@FAST
@given(law_and_theta(), st.floats(0.5, 1.0))
def test_rise_is_point_symmetric_about_the_middle(law, t):
    """H(T) + H(1 - T) = 1, H'(T) = H'(1 - T), H''(T) = -H''(1 - T), H'''(T) = H'''(1 - T):
    every law here accelerates and decelerates alike (for the modified sine BC mirrors OA in
    (A.2.17)).  T is drawn in [1/2, 1] so that 1 - T is exact.  Derivatives above the order of
    continuity are skipped where T or 1 - T is a breakpoint, where they jump.  Symbolic law and
    compiled law, to 1e-12 of the size of each derivative.  Measured: symbolic 6e-17, compiled
    2e-14 of the size (4-5-6-7, H')."""
    key, th = law
    u = 1.0 - t
    on_break = {t, u} & set(_bounds(key, th))
    orders = range(4) if not on_break else range(min(3, min(c for c in CONTINUITY[key] if c is not None)) + 1)
    s = _scale(key, th)
    mirrored = (lambda h, k: 1.0 - h if k == 0 else (-1) ** (k + 1) * h)
    for rows in (np.array([_symbolic_law(key, th, t), _symbolic_law(key, th, u)]), _compiled(key, th, [t, u])):
        for k in orders:
            assert _close(rows[0, k], mirrored(rows[1, k], k), s[k], 1e-12), (k, rows)


@st.composite
def law_theta_and_time(draw):
    key, th = draw(law_and_theta())
    # breakpoints drawn on purpose: there the segment lookup decides which piece is used
    t = draw(st.floats(-0.5, 1.5) | st.sampled_from(rt_laws.choose(key, th).breakpoints()))
    return key, th, t


@pytest.mark.usefixtures("symbolic_laws")
@settings(FAST, max_examples=150)
@given(law_theta_and_time())
def test_compiled_law_equals_the_symbolic_law(case):
    """The generated library (``choose(key, theta).evaluate``) against the symbolic law's own
    Piecewise in 40-digit arithmetic, H to H''', at random T in [-0.5, 1.5] and at the
    breakpoints (a breakpoint belongs to the segment that starts there), to 1e-12 of the size
    of each derivative.  Measured: 1.0e-13 of the size (modified sine, theta = 0.49, H'' at
    T = theta)."""
    key, th, t = case
    s = _scale(key, th)
    got = _compiled(key, th, [t])[0]
    want = _symbolic_law(key, th, t)
    for k in range(4):
        assert _close(got[k], want[k], s[k], 1e-12), (k, got, want)


@pytest.mark.usefixtures("symbolic_laws")
@FAST
@given(law_and_theta(), st.floats(max_value=-math.ulp(0.0)) | st.floats(min_value=1.0))
def test_dwells_before_and_after_the_rise(law, t):
    """T < 0: H = H' = H'' = H''' = 0; T >= 1 (infinity included): H = 1 and the derivatives 0,
    exactly, in the compiled and the symbolic law (thesis App. 2: dwell before and after the
    rise)."""
    key, th = law
    want = [0.0, 0.0, 0.0, 0.0] if t < 0 else [1.0, 0.0, 0.0, 0.0]
    assert list(_compiled(key, th, [t])[0]) == want
    assert list(_symbolic_law(key, th, t)) == want


@FAST
@given(THETA, st.floats(0.0, 1.0))
def test_modified_sine_follows_A_2_17_A_2_21_A_2_22(th, t):
    """Compiled modified sine at any theta: H'' at T = theta is the printed H''max =
    pi^2/(2 - 8 theta + 2 pi theta) (A.2.17) (5.40 at theta = 0.1) and nowhere larger, H''' at
    T = 0 is H''max pi/(2 theta) (A.2.21) (85 at theta = 0.1) and at T = 1/2 it is
    -H''max pi/(1 - 2 theta) (A.2.22) (-21.2 at theta = 0.1).  Relative 1e-12 (the peak bound:
    H'' <= H''max (1 + 1e-12)).  Measured: peak and H'''(1/2) 1.1e-13 (theta = 0.49), H'''(0)
    4e-16; on a grid of 2001 T the peak is never exceeded."""
    peak = _modified_sine_peak(th)
    at_theta, at_0, at_half, at_t = _compiled("modified-sine", th, [th, 0.0, 0.5, t])
    assert at_theta[2] == pytest.approx(peak, rel=1e-12)
    assert at_0[3] == pytest.approx(peak * pi / (2 * th), rel=1e-12)
    assert at_half[3] == pytest.approx(-peak * pi / (1 - 2 * th), rel=1e-12)
    assert abs(at_t[2]) <= peak * (1 + 1e-12)


def test_modified_sine_near_half_keeps_its_peak():
    """theta = 1/2 - 1e-9 is inside the declared range 0 < theta < 1/2.  H'' at T = theta must be
    H''max = pi^2/(2 - 8 theta + 2 pi theta) (A.2.17), 8.6455; relative 1e-9.  The compiled law
    once returned 0 there: its AB piece formed (1 - 2 theta)^2 as 4 theta^2 - 4 theta + 1, whose
    cancellation grew as 1e-16/(1 - 2 theta)^2 (1e-12 at theta = 0.499, 0.11 at 1/2 - 1e-8); the
    acceleration and jerk are now generated from the declared acceleration (derive/camlaws.py)."""
    th = 0.5 - 1e-9
    assert _compiled("modified-sine", th, [th])[0][2] == pytest.approx(_modified_sine_peak(th), rel=1e-9)


@FAST
@given(st.sampled_from(sorted(LAWS)),
       st.none() | st.floats(0.0, 0.5, exclude_min=True, exclude_max=True)
       | st.floats(allow_nan=False).filter(lambda v: not 0 < v < 0.5) | st.just(math.nan)
       | st.integers() | HUGE_INT | st.booleans()
       | st.text(string.ascii_letters + " ", max_size=8) | st.lists(st.floats(), max_size=2))
def test_law_choice_takes_a_theta_only_inside_its_range(key, th):
    """``choose(law, theta)``, the check behind a scene's law and theta and a run's law argument:
    no theta gives the law's default; a theta is taken only by the law that has a shape
    parameter and only as a number inside its declared open range 0 < theta < 1/2 (A.2.17);
    anything else raises CamdynInputError naming theta, never another exception."""
    spec = LAWS[key].parameter
    inside = isinstance(th, (int, float)) and spec is not None and spec.low < th < spec.high
    name = "theta" if spec is None else spec.symbol.name
    if th is None or inside:
        choice = rt_laws.choose(key, th)
        want = (spec.default if th is None else float(th)) if spec is not None else 0.0
        assert (choice.key, choice.par) == (key, want)
        return
    with pytest.raises(CamdynInputError, match=rf"\b{name}\b"):
        rt_laws.choose(key, th)


# -- scenes: a small TOML writer (tomllib only reads) ------------------------------------

def _toml_string(s: str) -> str:
    out = []
    for ch in s:
        if ch in '"\\':
            out.append("\\" + ch)
        elif ord(ch) < 0x20 or ord(ch) == 0x7F:
            out.append(f"\\u{ord(ch):04x}")
        else:
            out.append(ch)
    return '"' + "".join(out) + '"'


def _toml_value(v) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        return "nan" if math.isnan(v) else ("inf" if v > 0 else "-inf") if math.isinf(v) else repr(v)
    if isinstance(v, str):
        return _toml_string(v)
    if isinstance(v, (datetime.date, datetime.time)):
        return v.isoformat()
    if isinstance(v, list):
        return "[" + ", ".join(_toml_value(x) for x in v) + "]"
    return "{" + ", ".join(f"{_toml_string(k)} = {_toml_value(x)}" for k, x in v.items()) + "}"


def _toml(data: dict) -> str:
    """A TOML document: top-level values first, then one [table] per table."""
    lines = [f"{_toml_string(k)} = {_toml_value(v)}" for k, v in data.items() if not isinstance(v, dict)]
    for name, table in data.items():
        if isinstance(table, dict):
            lines.append(f"[{_toml_string(name)}]")
            lines += [f"{_toml_string(k)} = {_toml_value(v)}" for k, v in table.items()]
    return "\n".join(lines) + "\n"


SCENE_DIR = Path(scenes.builtin("indexing")).parent
# the DYNACAM scenes (the others are the CAMSHAFT-1 study, below, and the beam follower)
SCENES = sorted(p.stem for p in SCENE_DIR.glob("*.toml")
                if tomllib.loads(p.read_text()).get("kind") == "dynacam")


@functools.cache
def _scene_data(name):
    return tomllib.loads((SCENE_DIR / f"{name}.toml").read_text())


@functools.cache
def _specs(name):
    """The declared parameters (name -> Parameter) of the scene's variant, beta_0 excepted."""
    opts = dynacam_model.Options(**_scene_data(name)["options"])
    return {p.name: p for p in dynacam_model.build(opts).parameters if p.name != "beta_0"}


@pytest.fixture(scope="module")
def scene_file(tmp_path_factory):
    path = tmp_path_factory.mktemp("scenes") / "scene.toml"

    def write(data):
        path.write_text(_toml(data))
        return path
    return write


def _refused(load, path, token):
    """Load must raise CamdynInputError with a one-line message that contains ``token``."""
    with pytest.raises(CamdynInputError) as info:
        load(path)
    message = str(info.value)
    assert token in message, (token, message)
    assert "\n" not in message, message
    return message


# -- scenes: strategies -------------------------------------------------------------------

KEY_TEXT = st.text(st.characters(blacklist_categories=("Cs", "Cc", "Zl", "Zp")), min_size=1, max_size=12)
"""Keys as a TOML quoted key may spell them (printable: messages are one line)."""

WRONG_TYPE = (st.text(max_size=8) | st.booleans() | st.dates() | st.times()
              | st.lists(st.integers(-9, 9) | st.floats(allow_nan=False) | st.text(max_size=3), max_size=3)
              | st.dictionaries(KEY_TEXT, st.integers(-9, 9), max_size=2))
"""Values of the wrong kind for a number."""

ANY_VALUE = st.integers(-(2**63), 2**63 - 1) | st.floats() | WRONG_TYPE


def _outside(low, high, open_low=False, open_high=False):
    """Numbers outside [low, high] (the ends excluded where the range is open there), the
    non-finite ones and integers beyond any double."""
    parts = [st.sampled_from([math.nan, math.inf, -math.inf]), HUGE_INT]
    if low > -math.inf:
        parts.append(st.floats(max_value=low, exclude_max=True))
        parts.append(st.integers(max_value=math.floor(low) if open_low else math.ceil(low) - 1))
        if open_low:
            parts.append(st.sampled_from([low, -0.0] if low == 0 else [low]))
    if high < math.inf:
        parts.append(st.floats(min_value=high, exclude_min=True))
        parts.append(st.integers(min_value=math.ceil(high) if open_high else math.floor(high) + 1))
        if open_high:
            parts.append(st.just(high))
    return st.one_of(parts)


def _inside(low, high, open_low=False, open_high=False):
    """Finite numbers inside the range, floats and integers."""
    floats = st.floats(None if low == -math.inf else low, None if high == math.inf else high,
                       exclude_min=open_low and low > -math.inf, exclude_max=open_high and high < math.inf,
                       allow_nan=False, allow_infinity=False)
    lo = -(2**63) if low == -math.inf else math.floor(low) + 1 if open_low else math.ceil(low)
    hi = 2**63 - 1 if high == math.inf else math.ceil(high) - 1 if open_high else math.floor(high)
    ints = st.integers(max(lo, -(2**63)), min(hi, 2**63 - 1))
    return floats | ints if lo <= hi else floats


def _invalid_parameter(spec):
    return _outside(spec.low, spec.high, spec.open_low, spec.open_high) | WRONG_TYPE


OPTION_KEYS = sorted(f.name for f in fields(dynacam_model.Options))
CHOICES = dynacam_model.Options.CHOICES


def _invalid_option(key):
    others = st.integers() | st.floats() | st.dates() | st.lists(st.text(max_size=3), max_size=2) \
        | st.dictionaries(KEY_TEXT, st.booleans(), max_size=2)
    if key in CHOICES:
        return st.text(max_size=12).filter(lambda v: v not in CHOICES[key]) | st.booleans() | others
    return st.text(max_size=6) | others


RUN_RANGES = {"T_start": (-5.0, 0.0), "T_end": (1.0, 50.0), "rtol": (1e-13, 1e-2)}
"""The run settings' ranges, restated from runtime/targets/scene_files.py (_RUN; T in units of the rise)."""


@st.composite
def corrupted_scene(draw):
    """(scene data with one corruption, the key its refusal must name)."""
    name = draw(st.sampled_from(SCENES))
    data = copy.deepcopy(_scene_data(name))
    specs = _specs(name)
    kind = draw(st.sampled_from([
        "parameter", "parameter-missing", "parameter-unknown", "option", "option-unknown",
        "run", "run-method", "run-unknown", "top-unknown", "law", "theta", "theta-not-taken",
        "table-missing", "table-type"]))
    if kind == "parameter":
        key = draw(st.sampled_from(sorted(specs)))
        data["parameters"][key] = draw(_invalid_parameter(specs[key]))
        return data, f"parameters.{key}"
    if kind == "parameter-missing":
        key = draw(st.sampled_from(sorted(specs)))
        del data["parameters"][key]
        return data, f"parameters.{key}"
    if kind == "parameter-unknown":
        key = draw(KEY_TEXT.filter(lambda k: k not in specs))
        data["parameters"][key] = draw(ANY_VALUE)
        return data, f"parameters.{key}"
    if kind == "option":
        key = draw(st.sampled_from(OPTION_KEYS))
        data["options"][key] = draw(_invalid_option(key))
        return data, f"options.{key}"
    if kind == "option-unknown":
        key = draw(KEY_TEXT.filter(lambda k: k not in OPTION_KEYS))
        data["options"][key] = draw(ANY_VALUE)
        return data, f"options.{key}"
    if kind == "run":
        key = draw(st.sampled_from(sorted(RUN_RANGES)))
        data["run"][key] = draw(_outside(*RUN_RANGES[key]) | WRONG_TYPE)
        return data, f"run.{key}"
    if kind == "run-method":
        data["run"]["method"] = draw(st.text(max_size=8).filter(lambda v: v != "dp54") | WRONG_TYPE
                                     | st.integers() | st.floats())
        return data, "run.method"
    if kind == "run-unknown":
        key = draw(KEY_TEXT.filter(lambda k: k not in RUN_RANGES and k != "method"))
        data["run"][key] = draw(ANY_VALUE)
        return data, f"run.{key}"
    if kind == "top-unknown":
        # a bare-key name of four or more characters, so that finding it in the message means it
        key = draw(st.from_regex(r"[A-Za-z_][A-Za-z0-9_-]{3,11}", fullmatch=True)
                   .filter(lambda k: k not in {"title", "reference", "note", "law", "theta", "options",
                                               "parameters", "run", "modes"}))
        data[key] = draw(ANY_VALUE)
        return data, key
    if kind == "law":
        data["law"] = draw(st.text(max_size=20).filter(lambda v: v not in LAWS) | WRONG_TYPE
                           | st.integers() | st.floats())
        return data, "law"
    if kind == "theta":
        data["law"] = "modified-sine"
        data["theta"] = draw(_outside(0.0, 0.5, True, True) | WRONG_TYPE)
        return data, "theta"
    if kind == "theta-not-taken":
        data["law"] = draw(st.sampled_from(sorted(k for k, law in LAWS.items() if law.parameter is None)))
        data["theta"] = draw(st.floats(0.0, 0.5, exclude_min=True, exclude_max=True))
        return data, "theta"
    if kind == "table-missing":
        table = draw(st.sampled_from(["options", "parameters"]))
        del data[table]
        return data, f"[{table}]"
    table = draw(st.sampled_from(["options", "parameters", "run", "modes"]))
    data[table] = draw(st.integers() | st.text(max_size=5) | st.lists(st.integers(), max_size=2)
                       | (st.dictionaries(KEY_TEXT, st.integers() | st.booleans(), min_size=1, max_size=2)
                          if table == "modes" else st.booleans()))
    return data, f"[{table}]"


# -- scenes: tests ------------------------------------------------------------------------

@pytest.mark.parametrize("name", SCENES)
def test_builtin_scene_reads_back_through_the_toml_writer(name, scene_file):
    """The test's TOML writer is faithful: every built-in scene written out and loaded gives the
    scene loaded from the shipped file (same variant, parameters, law, run settings)."""
    want = scenes.load(SCENE_DIR / f"{name}.toml")
    got = scenes.load(scene_file(_scene_data(name)))
    assert (got.variant, got.parameters, got.law, got.theta, got.T_start, got.T_end, got.rtol) == \
        (want.variant, want.parameters, want.law, want.theta, want.T_start, want.T_end, want.rtol)
    assert tomllib.loads(_toml(_scene_data(name))) == _scene_data(name)


@settings(FAST, max_examples=120)
@given(corrupted_scene())
def test_any_single_corruption_is_refused_by_name(scene_file, case):
    """Every corruption of ``corrupted_scene`` (a parameter negative, zero where its range is
    open, beyond its range, NaN, +-inf, an integer no double holds, a string, bool, date, list
    or table; a parameter removed; an unknown key at top level or in [options], [parameters],
    [run]; an option not among its choices or of the wrong type; run.T_start, T_end, rtol
    outside their ranges or of the wrong type, run.method not dp54; law or theta invalid; a
    table missing or not a table) makes ``scene.load`` raise CamdynInputError with a one-line
    message containing the key (e.g. ``parameters.c_x``), and nothing else."""
    data, token = case
    _refused(scenes.load, scene_file(data), token)


@st.composite
def bad_parameter(draw):
    """(scene, parameter, a value its declaration refuses)."""
    name = draw(st.sampled_from(SCENES))
    key = draw(st.sampled_from(sorted(_specs(name))))
    return name, key, draw(_invalid_parameter(_specs(name)[key]))


@settings(FAST, max_examples=40)
@given(bad_parameter())
@example(("spring_loaded", "c_x", math.inf))
@example(("spring_loaded", "c_x", -math.inf))
@example(("indexing", "q_x", math.nan))
@example(("indexing", "m_x", 0.0))
@example(("indexing", "m_x", -0.0))
@example(("indexing", "q_b", 1.5))
@example(("indexing", "s_r", 10**400))
@example(("fig8_1a", "J", "heavy"))
@example(("fig8_1a", "k", True))
@example(("fig8_1b", "h_m", [0.03]))
@example(("indexing_squeeze", "V_T", {"value": 1.0}))
@example(("spring_loaded", "T_el", datetime.date(1973, 1, 1)))
def test_a_parameter_outside_its_declared_range_is_refused_by_name(scene_file, case):
    """A parameter set to a number outside its declared range (``Parameter.low``, ``high``,
    open or closed ends: negative, zero where the range is open, beyond a finite upper end),
    to NaN or +-inf, to an integer no double holds, or to a string, bool, list, table or date,
    is refused with a one-line CamdynInputError naming ``parameters.<name>``.  The explicit
    examples make sure every kind is tried on every run."""
    name, key, value = case
    data = copy.deepcopy(_scene_data(name))
    data["parameters"][key] = value
    _refused(scenes.load, scene_file(data), f"parameters.{key}")


@st.composite
def valid_parameter_change(draw):
    name = draw(st.sampled_from(SCENES))
    key = draw(st.sampled_from(sorted(_specs(name))))
    spec = _specs(name)[key]
    return name, key, draw(_inside(spec.low, spec.high, spec.open_low, spec.open_high))


@settings(FAST, max_examples=30)
@given(valid_parameter_change())
def test_a_parameter_inside_its_declared_range_is_accepted(scene_file, case):
    """A parameter set to any finite value inside its declared range (``Parameter.low``, ``high``,
    open or closed ends, in camdyn.derive.models.dynacam) is accepted and kept as that float."""
    name, key, value = case
    data = copy.deepcopy(_scene_data(name))
    data["parameters"][key] = value
    assert scenes.load(scene_file(data)).parameters[key] == float(value)


@settings(FAST, max_examples=30)
@given(st.sampled_from(SCENES), _inside(*RUN_RANGES["T_start"]), _inside(*RUN_RANGES["T_end"]),
       _inside(*RUN_RANGES["rtol"]))
def test_run_settings_inside_their_ranges_are_accepted(scene_file, name, t_start, t_end, rtol):
    """run.T_start in [-5, 0], T_end in [0, 50], rtol in [1e-13, 1e-2] are accepted when
    T_end > T_start, and refused naming run.T_end otherwise."""
    data = copy.deepcopy(_scene_data(name))
    data["run"] = {"T_start": t_start, "T_end": t_end, "rtol": rtol, "method": "dp54"}
    path = scene_file(data)
    if t_end > t_start:
        sc = scenes.load(path)
        assert (sc.T_start, sc.T_end, sc.rtol) == (float(t_start), float(t_end), float(rtol))
    else:
        _refused(scenes.load, path, "run.T_end")


@settings(FAST, max_examples=30)
@given(st.sampled_from(SCENES), st.sampled_from(sorted(LAWS)), st.floats(0.0, 0.5, exclude_min=True, exclude_max=True))
def test_every_law_and_a_theta_inside_its_range_are_accepted(scene_file, name, key, th):
    """law = any cam-law name is accepted; theta with it only for the law that has a shape
    parameter (the modified sine, 0 < theta < 1/2, (A.2.17)), kept as given."""
    data = copy.deepcopy(_scene_data(name))
    data["law"] = key
    if LAWS[key].parameter is not None:
        data["theta"] = th
    sc = scenes.load(scene_file(data))
    assert (sc.law, sc.theta) == (key, th if LAWS[key].parameter is not None else None)


@FAST
@given(st.sampled_from(SCENES), st.binary(max_size=8), st.integers(0, 10**6))
def test_scene_file_with_bytes_spliced_in_is_refused_or_loaded(scene_file, name, junk, where):
    """A scene file with arbitrary bytes inserted anywhere (often not UTF-8, often not TOML, now
    and then a changed value) either loads or is refused with CamdynInputError: never another
    exception."""
    text = (SCENE_DIR / f"{name}.toml").read_bytes()
    at = where % (len(text) + 1)
    path = scene_file({})
    path.write_bytes(text[:at] + junk + text[at:])
    try:
        scenes.load(path)
    except CamdynInputError as exc:
        assert "\n" not in str(exc)


def test_a_folder_is_refused_as_a_scene_file(tmp_path):
    """A folder given as the scene file is refused with CamdynInputError naming it."""
    folder = tmp_path / "scene.toml"
    folder.mkdir()
    _refused(scenes.load, folder, str(folder))


def test_camdyn_simulate_names_the_bad_key_with_status_2(tmp_path):
    """``camdyn simulate bad.toml`` (the installed entry point) on the spring-loaded scene with
    c_x an integer of 400 digits: exit status 2, one line on stderr naming parameters.c_x,
    nothing on stdout."""
    data = copy.deepcopy(_scene_data("spring_loaded"))
    data["parameters"]["c_x"] = 10**400
    bad = tmp_path / "bad.toml"
    bad.write_text(_toml(data))
    camdyn = Path(sys.executable).with_name("camdyn")
    proc = subprocess.run([str(camdyn), "simulate", str(bad), "--json"], capture_output=True,
                          text=True, timeout=120)
    assert proc.returncode == 2, proc.stderr
    lines = proc.stderr.splitlines()
    assert len(lines) == 1 and "parameters.c_x" in lines[0], proc.stderr
    assert proc.stdout == ""


# -- the CAMSHAFT-1 study scene of `camdyn run` (default.toml, report.load_scene) ---------

DEFAULT = tomllib.loads((SCENE_DIR / "default.toml").read_text())


def _schema_leaves(schema=scenes.STUDY_SCHEMA, prefix=""):
    """(dotted name, kind) of every key of the report schema, tables included."""
    for key, kind in schema.items():
        path = prefix + key
        yield path, kind
        if isinstance(kind, dict):
            yield from _schema_leaves(kind, path + ".")


LEAVES = dict(_schema_leaves())


def _bad_for(kind):
    """Values the report schema refuses for a key of this kind (integers beyond a double are
    left out: see test_default_scene_refuses_an_integer_no_double_holds)."""
    nonfinite = st.sampled_from([math.nan, math.inf, -math.inf])
    if isinstance(kind, dict):
        return st.integers() | st.text(max_size=4) | st.lists(st.integers(), max_size=2)
    if kind is float:
        return nonfinite | WRONG_TYPE
    if kind is int:
        return st.integers(max_value=0) | st.floats() | WRONG_TYPE
    if kind is list:
        return (st.just([]) | st.integers() | st.floats() | st.text(max_size=4)
                | st.lists(st.text(max_size=3) | st.booleans() | st.dates(), min_size=1, max_size=3))
    return st.integers() | st.floats() | st.booleans() | st.lists(st.integers(), max_size=2)


def _table(data, dotted):
    *parents, key = dotted.split(".")
    for p in parents:
        data = data[p]
    return data, key


@st.composite
def corrupted_default(draw):
    data = copy.deepcopy(DEFAULT)
    dotted = draw(st.sampled_from(sorted(LEAVES)))
    table, key = _table(data, dotted)
    kind = draw(st.sampled_from(["value", "missing", "unknown"]))
    if kind == "value":
        table[key] = draw(_bad_for(LEAVES[dotted]))
        return data, dotted
    if kind == "missing":
        del table[key]
        return data, dotted
    prefix = dotted.rsplit(".", 1)[0] + "." if "." in dotted else ""
    new = draw(st.from_regex(r"[A-Za-z_][A-Za-z0-9_]{3,11}", fullmatch=True).filter(lambda k: k not in table))
    table[new] = draw(ANY_VALUE)
    return data, prefix + new


def test_default_scene_reads_back_through_the_toml_writer(scene_file):
    """The unchanged CAMSHAFT-1 study scene, written by the test's TOML writer, passes
    ``report.load_scene`` and reads back equal."""
    assert report.load_scene(str(scene_file(DEFAULT))) == DEFAULT


@FAST
@given(corrupted_default())
def test_default_scene_corruption_is_refused_by_name(scene_file, case):
    """The CAMSHAFT-1 study scene (default.toml) against its schema (scene.STUDY_SCHEMA): any key
    removed, set to a value of the wrong kind (a non-finite or non-number float, an integer
    below 1 or not an integer for n_tau, an empty list or one with a non-number for Fa, a
    non-string title or law, a table that is not a table) or an unknown key added at any
    level makes ``report.load_scene`` raise CamdynInputError with a one-line message that
    contains the dotted key (e.g. ``study.graphs.n_tau``)."""
    data, token = case
    _refused(report.load_scene, str(scene_file(data)), token)


def test_default_scene_refuses_an_integer_no_double_holds(scene_file):
    """study.response.tau = 10^400 (TOML integers have no size limit in tomllib) must be refused
    by name like any other bad number (report.load_scene once raised OverflowError here)."""
    data = copy.deepcopy(DEFAULT)
    data["study"]["response"]["tau"] = 10**400
    _refused(report.load_scene, str(scene_file(data)), "study.response.tau")

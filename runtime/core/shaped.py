"""Rises shaped by the user: a piecewise polynomial H(T), 0 <= T <= 1, from H = 0 to H = 1,
with the dwells of a plain law before and after it (thesis App. 2's normalisation: T = t/t_m,
H = s/stroke).  The generated library evaluates it (law code ``camlaws.SHAPED``), so every
model, scene, sweep and profile takes it where it takes a law of the library.

Three ways to shape one:

* :func:`blend` - polynomial segments between blend points, each the polynomial of least
  degree that meets the conditions at its two ends (the boundary-condition method of cam
  design, e.g. Norton, *Cam Design and Manufacturing Handbook*, ch. 5).  At each point the
  orders 0..3 (H, H', H'', H''') are given a value or "match": at an inner point "match"
  takes the value the segment on the left arrives with, at T = 0 and T = 1 that of the dwell.
* :func:`bspline` - a clamped B-spline of degree k on uniform knots through control values
  c_0 = 0 .. c_n = 1 (de Boor, *A Practical Guide to Splines*): equal first (or last) control
  values j + 1 times give H' .. H^(j) zero at that end.
* :func:`table` - H sampled at points T_i (a file of angle and lift), interpolated by the
  quintic spline with H' = H'' = 0 at both ends (continuous to H'''').  How well the table
  fixes each derivative is estimated by the spline through every second point: where that
  differs by more than a limit in a derivative a model uses, the table is refused by name
  (:meth:`Shaped.check_for`).

A rise is stored as breaks b_0 = 0 < ... < b_N = 1 and the coefficients of each piece in
powers of T - b_i.  Its segments (the breakpoints a run stops at, as a plain law's) end where
H, H', H'' or H''' jumps; a spline's smooth knots lie inside one segment.
"""
from __future__ import annotations

import csv
import functools
import math
import tomllib
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.polynomial import polynomial as P

from camdyn.generated import camlaws as _lib

from .errors import CamdynInputError, on_disk

ORDERS = ("H", "H'", "H''", "H'''")
"""The derivatives a blend point may fix, by order."""
MAX_DEGREE = 15
"""Highest degree of a piece (the library's Horner loop takes any; beyond this the
conditions of a blend are ill-conditioned in the power basis)."""
JUMP = 1e-9
"""A derivative jumps at a break when its two sides differ by more than this times the
derivative's largest value over the rise."""
TABLE_SUFFIXES = (".csv", ".txt", ".dat")
"""Files read as a table of (angle, lift); a .toml file is a blend or a B-spline."""
MAX_LAW_BYTES = 8 << 20
"""The largest law file read (8 MiB, some 200 000 rows of a table): the fit of a table grows
with its rows, and a device or a stray large file is refused before it is read."""
ROUGH_LIMIT = 0.01
"""Default largest estimated error of a table's derivative, relative to its largest value,
for the derivatives a model uses (:meth:`Shaped.check_for`)."""


@dataclass(frozen=True)
class Shaped:
    """A piecewise polynomial rise (see the module's docstring)."""

    name: str
    breaks: tuple
    coefs: tuple            # per piece: D + 1 coefficients, ascending powers of T - b_i
    ends: tuple             # segment ends e_1 < ... < e_S = 1
    first: tuple            # first piece of each segment, then N
    errors: tuple = (0.0, 0.0, 0.0, 0.0)
    """Estimated error of H .. H''' relative to each one's largest value over the rise (a
    table's; 0 for a rise given exactly)."""

    key = "shaped"
    code = _lib.SHAPED

    @property
    def par(self) -> float:
        """The slot of the library that describes this rise in this process (written on first
        use, so a rise sent to another process registers itself there again)."""
        return float(_lib.shaped_slot(self.ends, self.first, self.breaks, np.array(self.coefs)))

    def breakpoints(self) -> list[float]:
        return [0.0, *self.ends]

    def breakpoints_between(self, lo: float, hi: float) -> list[float]:
        return [b for b in self.breakpoints() if lo < b < hi]

    def evaluate(self, T) -> np.ndarray:
        """Columns H, H', H'', H''' at the times T, from the generated library."""
        return _lib.evaluate(self.code, self.par, T)

    @property
    def continuity(self) -> int:
        """Highest order k such that H .. H^(k) are continuous over the whole cam motion,
        dwells included (-1 when H itself jumps, as no rise here does)."""
        c, b = np.array(self.coefs), self.breaks
        peaks = self.peaks()
        jumps = set()
        for k in range(4):
            start = math.factorial(k) * c[0, k]
            end = P.polyval(b[-1] - b[-2], P.polyder(c[-1], k)) - (1.0 if k == 0 else 0.0)
            if max(abs(start), abs(end)) > JUMP * max(peaks[k], 1.0):
                jumps.add(k)
        jumps |= _jumps(b, c, peaks)[1]
        return min(jumps, default=4) - 1

    def peaks(self) -> tuple:
        """Largest |H|, |H'|, |H''|, |H'''| over the rise (16 points a piece)."""
        return tuple(float(v) for v in _peaks(self.breaks, np.array(self.coefs)))

    def characteristics(self) -> dict:
        """VDI 2143's characteristic values of the rise, C_v = H'max, C_a = |H''|max,
        C_j = |H'''|max, C_Mdyn = max H'H'', each where it is reached (T) and with its error:
        the table's estimate times the value (zero for a rise given exactly) and the rounding
        of the roots that locate it.  C_a and C_j are None (an impulse) where H' or H''
        jumps, dwells included."""
        c = [np.array(row) for row in self.coefs]
        b = self.breaks
        smooth = self.continuity

        def peak(poly_of, sign_free: bool):
            best, at = -np.inf, 0.0
            for i, row in enumerate(c):
                p = poly_of(row)
                dp = P.polyder(p)
                x = [0.0, b[i + 1] - b[i]]
                if dp.size > 1 and np.any(dp):
                    r = P.polyroots(np.trim_zeros(dp, "b")) if np.any(dp[1:]) else []
                    x += [v.real for v in r if abs(v.imag) < 1e-9 and 0.0 < v.real < x[1]]
                vals = P.polyval(np.array(x), p)
                vals = np.abs(vals) if sign_free else vals
                k = int(np.argmax(vals))
                if vals[k] > best:
                    best, at = float(vals[k]), b[i] + x[k]
            return best, at

        e = self.errors
        out = {}
        for name, poly_of, sign_free, err, ok in (
                ("C_v", lambda r: P.polyder(r, 1), False, e[1], True),
                ("C_a", lambda r: P.polyder(r, 2), True, e[2], smooth >= 1),
                ("C_j", lambda r: P.polyder(r, 3), True, e[3], smooth >= 2),
                ("C_Mdyn", lambda r: P.polymul(P.polyder(r, 1), P.polyder(r, 2)), False,
                 e[1] + e[2], smooth >= 1)):
            if not ok:
                out[name] = {"value": None, "error": None, "at_T": None}
                continue
            v, at = peak(poly_of, sign_free)
            out[name] = {"value": v, "error": abs(v) * (err + 1e-12), "at_T": float(at)}
        return out

    def check_for(self, model_name: str, order: int, limit: float = ROUGH_LIMIT) -> None:
        """Refuse this rise for a model whose equations use H .. H^(order) when the estimated
        error of one of them exceeds ``limit`` of its largest value (a table too rough)."""
        for k in range(min(order, 3) + 1):
            if self.errors[k] > limit:
                raise CamdynInputError(
                    f"{self.name}: too rough for {model_name}, which uses {ORDERS[order]}: "
                    f"{ORDERS[k]} is known to {self.errors[k]:.1%} of its largest value "
                    f"(allowed {limit:.1%}; the splines through every point and every second "
                    f"point differ by that); give more points or more digits (a lift whose H' or H'' "
                    f"jumps, against the dwells at T = 0 or 1 or inside, stays this rough however "
                    f"many points it has: a table's spline cannot follow a jump)")

    def warnings(self) -> list[str]:
        """What a run with this rise should say about it."""
        if not any(self.errors):
            return []
        return [f"{self.name}: the table fixes H to {self.errors[0]:.1e}, H' to "
                f"{self.errors[1]:.1e}, H'' to {self.errors[2]:.1e} and H''' to "
                f"{self.errors[3]:.1e} of their largest values (spline through every second "
                f"point against every point)"]


def _peaks(breaks, coefs) -> np.ndarray:
    """Largest |H^(k)|, k = 0..3, on 16 points of each piece."""
    u = np.linspace(0.0, 1.0, 16)
    peaks = np.zeros(4)
    for i, c in enumerate(coefs):
        x = u * (breaks[i + 1] - breaks[i])
        for k in range(4):
            peaks[k] = max(peaks[k], np.abs(P.polyval(x, P.polyder(c, k))).max())
    return peaks


def _jumps(breaks, coefs, peaks) -> tuple:
    """(inner breaks where H .. H''' jump, the orders that jump there)."""
    where, orders = [], set()
    for i in range(1, len(breaks) - 1):
        x = breaks[i] - breaks[i - 1]
        bad = {k for k in range(4)
               if abs(P.polyval(x, P.polyder(coefs[i - 1], k)) - math.factorial(k) * coefs[i][k])
               > JUMP * max(peaks[k], 1e-300)}
        if bad:
            where.append(i)
            orders |= bad
    return where, orders


def _segments(breaks, coefs) -> tuple:
    """(ends, first): the breaks where H .. H''' jump are segment ends (and 1)."""
    where, _ = _jumps(breaks, coefs, _peaks(breaks, coefs))
    ends = tuple(float(breaks[i]) for i in where) + (1.0,)
    first = (0, *where, len(coefs))
    return ends, first


def from_pieces(name: str, breaks, coefs, errors=(0.0, 0.0, 0.0, 0.0)) -> Shaped:
    """A :class:`Shaped` rise from its breaks and ascending coefficients, checked: breaks from
    0 to 1 increasing, H(0) = 0 and H(1) = 1 to 1e-9, finite coefficients."""
    b = np.asarray(breaks, dtype=float)
    width = max(len(c) for c in coefs)
    if width - 1 > MAX_DEGREE:
        raise CamdynInputError(f"{name}: a piece of degree {width - 1}; at most {MAX_DEGREE}")
    c = np.zeros((len(coefs), max(width, 4)))
    for i, row in enumerate(coefs):
        c[i, :len(row)] = row
    if b.ndim != 1 or b.size != c.shape[0] + 1 or b.size < 2:
        raise CamdynInputError(f"{name}: {c.shape[0]} pieces need {c.shape[0] + 1} breaks, "
                               f"got {b.size}")
    if not (np.all(np.isfinite(b)) and np.all(np.isfinite(c))):
        raise CamdynInputError(f"{name}: breaks and coefficients must be finite numbers")
    if b[0] != 0.0 or b[-1] != 1.0 or np.any(np.diff(b) <= 0):
        raise CamdynInputError(f"{name}: the breaks must rise from T = 0 to T = 1")
    h0, h1 = c[0, 0], P.polyval(b[-1] - b[-2], c[-1])
    if abs(h0) > 1e-9 or abs(h1 - 1.0) > 1e-9:
        raise CamdynInputError(f"{name}: a rise goes from H = 0 at T = 0 to H = 1 at T = 1, "
                               f"this one from {h0:.6g} to {h1:.6g}")
    c[0, 0] = 0.0
    ends, first = _segments(b, c)
    return Shaped(name, tuple(float(x) for x in b), tuple(tuple(float(v) for v in row) for row in c),
                  ends, first, tuple(float(e) for e in errors))


# -- blend segments ---------------------------------------------------------------------

def _condition(name: str, where: str, key: str, value):
    if isinstance(value, str) and value.strip().lower() == "match":
        return "match"
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise CamdynInputError(f"{name}: {key} at {where} must be a number or \"match\", "
                               f"got {value!r}") from None
    if not math.isfinite(v):
        raise CamdynInputError(f"{name}: {key} at {where} must be finite, got {value!r}")
    return v


def blend(points, name: str = "blend") -> Shaped:
    """A rise of polynomial segments between blend points.

    ``points``: a sequence of mappings, each with ``T`` (0 first, 1 last, increasing) and any of
    ``H``, ``H'``, ``H''``, ``H'''`` set to a number or ``"match"``.  Segment i runs from point
    i to point i + 1; its polynomial has as many coefficients as conditions: those of point i
    (a "match" there takes the left side's value: the segment before, or the dwell at T = 0)
    and the numbers of point i + 1 (at T = 1 a "match" is the dwell's value, H = 1 and zero
    derivatives).  Solved left to right, so a later segment never changes an earlier one."""
    pts = list(points)
    if len(pts) < 2:
        raise CamdynInputError(f"{name}: a blend needs at least two points (T = 0 and T = 1)")
    Ts, conds = [], []
    for k, p in enumerate(pts):
        if not isinstance(p, dict) or "T" not in p:
            raise CamdynInputError(f"{name}: point {k + 1} needs T and conditions such as "
                                   f"H = 0.5, H' = \"match\"")
        unknown = sorted(set(p) - {"T", *ORDERS})
        if unknown:
            raise CamdynInputError(f"{name}: point {k + 1} has {', '.join(unknown)}; a point "
                                   f"takes T and {', '.join(ORDERS)}")
        T = _condition(name, f"point {k + 1}", "T", p["T"])
        if T == "match":
            raise CamdynInputError(f"{name}: T at point {k + 1} must be a number")
        Ts.append(T)
        conds.append({ORDERS.index(key): _condition(name, f"T = {T:g}", key, v)
                      for key, v in p.items() if key != "T"})
    if Ts[0] != 0.0 or Ts[-1] != 1.0 or any(b <= a for a, b in zip(Ts, Ts[1:])):
        raise CamdynInputError(f"{name}: the points' T must rise from 0 to 1, got "
                               f"{', '.join(f'{t:g}' for t in Ts)}")
    dwell_end = {0: 1.0, 1: 0.0, 2: 0.0, 3: 0.0}
    coefs = []
    prev = None
    for i in range(len(Ts) - 1):
        L = Ts[i + 1] - Ts[i]
        rows, rhs = [], []
        for order, v in sorted(conds[i].items()):
            if v == "match":
                v = 0.0 if prev is None else P.polyval(prev[1], P.polyder(prev[0], order))
            rows.append((0.0, order))
            rhs.append(v)
        for order, v in sorted(conds[i + 1].items()):
            if v == "match":
                if i + 1 < len(Ts) - 1:
                    continue          # the next segment's start condition
                v = dwell_end[order]
            rows.append((L, order))
            rhs.append(v)
        n = len(rows)
        where = f"segment {Ts[i]:g} <= T <= {Ts[i + 1]:g}"
        if n == 0:
            raise CamdynInputError(f"{name}: {where} has no conditions")
        if n - 1 > MAX_DEGREE:
            raise CamdynInputError(f"{name}: {where} has {n} conditions (degree {n - 1}); at "
                                   f"most {MAX_DEGREE + 1}")
        A = np.array([[math.perm(j, order) * x ** (j - order) if j >= order else 0.0
                       for j in range(n)] for x, order in rows])
        if np.linalg.matrix_rank(A) < n:
            raise CamdynInputError(f"{name}: the conditions of {where} do not fix one "
                                   f"polynomial (give H or a lower derivative at each end)")
        c = np.linalg.solve(A, np.array(rhs))
        coefs.append(c)
        prev = (c, L)
    return from_pieces(name, Ts, coefs)


# -- B-spline -----------------------------------------------------------------------------

def bspline(control, degree: int = 5, name: str = "B-spline") -> Shaped:
    """A clamped B-spline of ``degree`` on uniform knots over [0, 1] through the control values
    (the first 0, the last 1)."""
    from scipy.interpolate import BSpline, PPoly

    try:
        c = np.asarray([float(v) for v in control])
        k = int(degree)
    except (TypeError, ValueError):
        raise CamdynInputError(f"{name}: control values must be numbers and the degree an "
                               f"integer") from None
    if not 1 <= k <= MAX_DEGREE:
        raise CamdynInputError(f"{name}: degree={k} is out of range: 1 <= degree <= {MAX_DEGREE}")
    if c.size < k + 1:
        raise CamdynInputError(f"{name}: degree {k} needs at least {k + 1} control values, "
                               f"got {c.size}")
    if not np.all(np.isfinite(c)):
        raise CamdynInputError(f"{name}: control values must be finite")
    inner = np.linspace(0.0, 1.0, c.size - k + 1)
    t = np.concatenate([np.zeros(k), inner, np.ones(k)])
    pp = PPoly.from_spline(BSpline(t, c, k))
    return _from_ppoly(pp, name)


def _from_ppoly(pp, name: str, errors=(0.0, 0.0, 0.0, 0.0)) -> Shaped:
    """SciPy's PPoly (descending powers, possibly empty intervals) on [0, 1] as a Shaped."""
    x, c = pp.x, pp.c
    keep = [i for i in range(len(x) - 1) if x[i + 1] > x[i] and x[i] >= 0.0 and x[i + 1] <= 1.0]
    breaks = [float(x[keep[0]])] + [float(x[i + 1]) for i in keep]
    coefs = [c[::-1, i] for i in keep]
    return from_pieces(name, breaks, coefs, errors)


# -- a table of H(T) ----------------------------------------------------------------------

def _quintic(T, H):
    from scipy.interpolate import PPoly, make_interp_spline

    bc = [(1, 0.0), (2, 0.0)]
    return PPoly.from_spline(make_interp_spline(T, H, k=5, bc_type=(bc, bc)))


def table(T, H, name: str = "table") -> Shaped:
    """The rise through the points (T_i, H_i) - any units: T is scaled to 0..1 over the first
    and last points and H to 0..1 from the first to the last value - with its error estimate
    (see the module's docstring).  At least 8 points, T strictly increasing."""
    try:
        t = np.asarray(T, dtype=float).ravel()
        h = np.asarray(H, dtype=float).ravel()
    except (TypeError, ValueError):
        raise CamdynInputError(f"{name}: the table must hold numbers") from None
    if t.size != h.size or t.size < 8:
        raise CamdynInputError(f"{name}: a table needs at least 8 points of (angle, lift), "
                               f"got {min(t.size, h.size)}")
    if not (np.all(np.isfinite(t)) and np.all(np.isfinite(h))):
        raise CamdynInputError(f"{name}: the table holds a value that is not a finite number")
    bad = np.nonzero(np.diff(t) <= 0)[0]
    if bad.size:
        raise CamdynInputError(f"{name}: the angles must increase; row {bad[0] + 2} "
                               f"({t[bad[0] + 1]:g}) does not exceed the one before")
    if h[-1] == h[0]:
        raise CamdynInputError(f"{name}: the lift must change from the first row to the last")
    t = (t - t[0]) / (t[-1] - t[0])
    t[-1] = 1.0
    h = (h - h[0]) / (h[-1] - h[0])
    full = _quintic(t, h)
    # every second point, the last kept: the error of the coarser spline bounds the finer one's
    idx = np.unique(np.r_[np.arange(0, t.size, 2), t.size - 1])
    half = _quintic(t[idx], h[idx])
    x = np.linspace(0.0, 1.0, 20 * t.size + 1)
    errors = []
    for k in range(4):
        a = full.derivative(k)(x) if k else full(x)
        b = half.derivative(k)(x) if k else half(x)
        errors.append(float(np.max(np.abs(a - b)) / max(np.max(np.abs(a)), 1e-300)))
    return _from_ppoly(full, name, errors)


def read_table(path: Path) -> tuple[np.ndarray, np.ndarray]:
    """Two numeric columns (angle, lift) of a CSV or whitespace-separated file; a first row of
    names and lines starting with # are skipped."""
    rows = []
    header = True                         # the first line that is not a comment may be names
    text = read_text(path)
    if "\x00" in text:                    # valid UTF-8 but binary all the same
        raise CamdynInputError(f"law file {path.name}: not a text file (it holds NUL bytes); "
                               f"a table is lines of angle and lift")
    comma = "," in text
    for n, line in enumerate(text.splitlines(), 1):
        s = line.strip()
        if not s or s.startswith("#"):
            continue
        cells = next(csv.reader([s])) if comma else s.split()
        try:
            values = [float(v) for v in cells[:2]]
        except ValueError:
            if header:
                header = False
                continue
            raise CamdynInputError(f"{path.name}: line {n} is not two numbers: {s!r}") from None
        header = False
        if len(values) < 2:
            raise CamdynInputError(f"{path.name}: line {n} has one column; give angle and lift")
        rows.append(values)
    if not rows:
        raise CamdynInputError(f"{path.name}: no rows of (angle, lift) found"
                               + (" (the file is empty)" if not text.strip() else ""))
    a = np.array(rows)
    return a[:, 0], a[:, 1]


# -- files --------------------------------------------------------------------------------

def load(path) -> Shaped:
    """A shaped rise from a file: .csv/.txt/.dat a table of (angle, lift); .toml a blend
    ([[point]] tables) or a B-spline ([bspline] with control and degree).

    Every Simulator and check that is given the file's name asks for it (a residual with
    its error estimate builds two, a profile reads it for the cam and its warnings): the
    rise is read and fitted once per version of the file (its path, size and time)."""
    p = Path(path)
    what = on_disk(p)
    if what is None:
        raise CamdynInputError(f"law file {str(path)!r} not found")
    if what != "file":      # never opened: a named pipe would block, /dev/zero never end
        raise CamdynInputError(f"law file {str(path)!r} is a {what}, not a file: a table "
                               f"(.csv, .txt, .dat) or a shaped rise (.toml)")
    st = p.stat()
    if st.st_size > MAX_LAW_BYTES:
        raise CamdynInputError(f"law file {str(path)!r}: {st.st_size} bytes is too large for a "
                               f"rise (at most {MAX_LAW_BYTES} bytes, some 200 000 rows)")
    return _load(p.resolve(), st.st_size, st.st_mtime_ns)


def read_text(p: Path) -> str:
    """The text of a law file, or one line naming it and what is wrong: it cannot be read
    (no permission), or is not text (not UTF-8: a binary file, or a text in another
    encoding)."""
    try:
        return p.read_text(encoding="utf-8")
    except UnicodeDecodeError as exc:
        raise CamdynInputError(
            f"law file {p.name}: not a UTF-8 text file (byte {exc.object[exc.start]:#04x} at "
            f"offset {exc.start}); a law file is text: a table of angle and lift or a TOML "
            f"rise") from None
    except OSError as exc:
        raise CamdynInputError(f"law file {p.name}: cannot be read: "
                               f"{exc.strerror or exc}") from None


@functools.lru_cache(maxsize=64)
def _load(p: Path, size: int, mtime_ns: int) -> Shaped:
    if p.suffix.lower() in TABLE_SUFFIXES:
        T, H = read_table(p)
        return table(T, H, name=p.name)
    if p.suffix.lower() == ".toml":
        text = read_text(p)
        if not text.strip():
            raise CamdynInputError(f"{p.name}: the file is empty; give either [[point]] "
                                   f"tables (a blend) or one [bspline] table")
        try:
            spec = tomllib.loads(text)
        except ValueError as exc:   # not TOML (a NUL byte, an integer of 4300 digits too)
            raise CamdynInputError(f"{p.name}: not valid TOML ({exc})") from None
        if "point" in spec and "bspline" not in spec:
            if not isinstance(spec["point"], list):
                raise CamdynInputError(f"{p.name}: point must be [[point]] tables, each with T "
                                       f"and conditions such as H = 0.5")
            return blend(spec["point"], name=p.name)
        if "bspline" in spec and "point" not in spec:
            b = spec["bspline"]
            if not isinstance(b, dict) or "control" not in b:
                raise CamdynInputError(f"{p.name}: [bspline] needs control = [0, ..., 1]")
            if not isinstance(b["control"], list):
                raise CamdynInputError(f"{p.name}: [bspline] control must be a list of "
                                       f"numbers [0, ..., 1], got {b['control']!r}")
            return bspline(b["control"], b.get("degree", 5), name=p.name)
        raise CamdynInputError(f"{p.name}: give either [[point]] tables (a blend) or one "
                               f"[bspline] table")
    raise CamdynInputError(f"law file {p.name}: a table (.csv, .txt, .dat) or a shaped rise "
                           f"(.toml)")


def is_law_file(text: str) -> bool:
    """Whether a --law argument names a file rather than a law of the library."""
    return Path(text).suffix.lower() in (*TABLE_SUFFIXES, ".toml")

# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True, initializedcheck=False
#
# GENERATED FILE - DO NOT EDIT.  Written by `camdyn derive` from camdyn/derive/camlaws.py;
# edit that and regenerate.  `camdyn derive --check` fails while this file is stale.
# Derivation key: sha256:038530a315671603e7bdc5160370fa5f680c2994e93b557388cab4c326d4a5e1
# Text hash: sha256:0af6b60a13c1d60b0511578c6ea8124aa018549f87f63b058c8d748b434856ff
#
# Cam laws of thesis App. 2 and common industrial laws, H(T) and its first three
# derivatives per segment.  Segment 0 is the dwell before the rise (T < 0),
# segments 1..K the pieces of the rise, K + 1 the dwell after it (T >= 1).
# Segments are closed on the left.  `par` is the law's shape parameter
# (theta of the modified sine, c of the sine-constant-cosine law); laws without one ignore it.
#
#   0  cycloidal            Cycloidal, (A.2.8)-(A.2.11); H''max = 2*pi
#   1  modified-sine        Modified sine, (A.2.17)-(A.2.20); H''max = pi**2/(2*(-4*theta + pi*theta + 1))
#   2  3-4-5                3-4-5 polynomial, H = 10 T^3 - 15 T^4 + 6 T^5; H''max = 10*sqrt(3)/3
#   3  simple-harmonic      Simple harmonic, H = (1 - cos pi T)/2; H''max = pi**2/2
#   4  parabolic            Parabolic (constant acceleration), H'' = +-4; H''max = 4
#   5  4-5-6-7              4-5-6-7 polynomial, H = 35 T^4 - 84 T^5 + 70 T^6 - 20 T^7; H''max = 84*sqrt(5)/25
#   6  modified-trapezoid   Modified trapezoid, jerk-limited, eighths of the rise; H''max = 8*pi/(2 + pi)
#   7  uniform              Uniform motion (constant velocity), H = T; ramp input (3.8); H''max = impulsive
#   8  sine-constant-cosine Sine-constant-cosine acceleration (SCCA, b = 1/4), Norton SCCA, b = 1/4, d = 3/4 - c; H''max = 8*pi**2/(-2*pi**2*c**2 + 16*c**2 - 24*c + 3*pi**2*c + 2*pi + 8)
#   9  polydyne             Polydyne (one-DOF compensated degree-9 rise), H = P9 + (tau_d/2 pi)^2 P9'', P9 with P' to P^(4) zero at both ends; H''max = 1
#   10 5-6-7-8-9            5-6-7-8-9 polynomial, H = 126 T^5 - 420 T^6 + 540 T^7 - 315 T^8 + 70 T^9; H''max = 1215*sqrt(7)/343

#
#   1000 (turn)               dwell-rise-dwell-return over a full cam turn, periodic in T
#        (below); `par` is the slot of camlaw_turns that describes it.
#   1001 (shaped)             a rise shaped by the user, piecewise polynomial in T (below);
#        `par` is the slot of camlaw_shaped that describes it.

from libc.math cimport INFINITY, M_PI, cos, floor, pow, sin

# -- sine and cosine of the laws ----------------------------------------------------------
# The trigonometric laws evaluate sin and cos at every stage of a step, and libm's general
# routines (any argument, several code paths, no inlining) cost several times the few
# operations a law's argument needs: x = k pi/2 + r, |r| <= pi/4, with pi/2 split in three
# parts of 30 bits (Cody and Waite's reduction: k * part exact for |k| < 2^23), then
# polynomials in z = r^2 of least largest relative error on |r| <= pi/4, fitted for this
# library (derive/trig_fit.py): sin r = r + r z P(z), degree 13, within 1.1e-17, and
# cos r = 1 - z/2 + z^2 Q(z), degree 14, within 1.1e-18 (the Taylor series needs degrees 17
# and 18 for that).  Each is summed in Estrin's scheme (pairs of terms side by side, then
# pairs of pairs) rather than Horner's: the stages of a step wait on these sums, and a few
# levels of products finish sooner than six nested ones.  Always inlined, so that sin and
# cos of one argument share the reduction and both sums.  Within 2 units in the last place
# of libm's (tests/test_camlaws.py); beyond |x| = 1e6 libm's own.
cdef extern from *:
    """
    #include <math.h>
    static inline __attribute__((always_inline)) double camlaw_trig_(double x, int want_cos) {
        if (!(x > -1e6 && x < 1e6))
            return want_cos ? cos(x) : sin(x);
        long k = (long)(x * 0.6366197723675814 + (x >= 0.0 ? 0.5 : -0.5));
        double kd = (double)k;
        double r = ((x - kd * 1.570796325802803) - kd * 9.920935791635221e-10)
                   - kd * 5.170182981794105e-19;
        double z = r * r, z2 = z * z, z4 = z2 * z2;
        double s = r + r * z * ((-0.1666666666666663 + z * 0.008333333333322118)
                                + z2 * (-0.0001984126982958973 + z * 2.755731362144534e-06)
                                + z4 * (-2.5050747771327193e-08 + z * 1.5896230608868629e-10));
        double c = 1.0 - 0.5 * z + z2 * ((0.041666666666666595 + z * -0.0013888888888873056)
                                         + z2 * (2.4801587288851697e-05
                                                 + z * -2.7557314179295777e-07)
                                         + z4 * (2.087570084197554e-09
                                                 + z * -1.1358536526119406e-11));
        long q = (k + (want_cos ? 1 : 0)) & 3;   /* cos x = sin(x + pi/2) */
        double v = (q & 1) ? c : s;
        return (q & 2) ? -v : v;
    }
    static inline __attribute__((always_inline)) double camlaw_sin(double x) {
        return camlaw_trig_(x, 0);
    }
    static inline __attribute__((always_inline)) double camlaw_cos(double x) {
        return camlaw_trig_(x, 1);
    }
    """
    double camlaw_sin(double x) noexcept nogil
    double camlaw_cos(double x) noexcept nogil


# -- dwell-rise-dwell-return over a full cam turn (law code 1000) -----------------
# A plain law is one rise.  Law 1000 strings a rise law, an upper dwell, a return law
# run backwards (H = 1 - H_ret) and a lower dwell into one turn of period P, in units of the
# rise (T = 1 is the end of the rise), and repeats it for T >= 0; T < 0 is the dwell before the
# first rise, segment 0, as for a plain law.  Segment 1 + k S + l is piece l of turn k
# (S pieces per turn: the rise's, the upper dwell if any, the return's, the lower dwell if
# any), so that crossing a breakpoint is still `segment += 1`.  A turn is described by a
# slot of camlaw_turns (written once by camlaws.turn_slot(), then only read), whose index is
# the law's `par`: the one double the model ABI passes per cam input.
cdef double camlaw_turns[256][13]
# slot fields: 0 rise law, 1 its par, 2 return law, 3 its par, 4 period P, 5 K_rise pieces,
# 6 start of the return 1 + d_up, 7 return length r, 8 start of the lower dwell, 9 K_return
# pieces, 10 S segments per turn, 11 1.0 if there is an upper dwell, 12 1.0 if a lower one


# -- a rise shaped by the user (law code 1001) ------------------------------------------
# H(T) on [0, 1] is a piecewise polynomial (blend segments, a B-spline, a spline through a
# table: camdyn.runtime.core.shaped builds it), dwells before and after as for a plain law.
# Its segments are the intervals between the points where H loses smoothness the model
# needs, segment s = 1..S ending at e_s (e_S = 1); each holds one or more polynomial pieces
# b_i <= T < b_(i+1), found by bisection, so a spline through a long table steps as one
# segment.  Slot fields: 0 offset of its data in camlaw_shaped_pool, 1 S, 2 pieces N,
# 3 degree D.  The data: e_1..e_S; the first piece of segments 1..S+1 (the last: N); the
# breaks b_0..b_N; the coefficients of each piece in powers of T - b_i, D + 1 a piece.
cdef double camlaw_shaped[64][4]
cdef double camlaw_shaped_pool[262144]


cdef inline int _shaped_segment(const double* q, double T) noexcept nogil:
    cdef const double* e = &camlaw_shaped_pool[<int>q[0]]
    cdef int s, S = <int>q[1]
    if T < 0.0:
        return 0
    for s in range(S):
        if T < e[s]:
            return s + 1
    return S + 1


cdef inline double _shaped_lo(const double* q, int seg) noexcept nogil:
    if seg <= 1:
        return 0.0
    if seg > <int>q[1] + 1:
        return INFINITY
    return camlaw_shaped_pool[<int>q[0] + seg - 2]


cdef inline void _shaped_horner(const double* q, int seg, double T, double* d, int n) noexcept nogil:
    """d[k] = d^k H/dT^k, k < n (n <= 5), with the piece of segment `seg` that holds T (the
    segment's first or last piece beyond its ends, as a plain law's formula)."""
    cdef const double* p = &camlaw_shaped_pool[<int>q[0]]
    cdef int S = <int>q[1], N = <int>q[2], D = <int>q[3]
    cdef const double* b = p + 2 * S + 1
    cdef const double* c
    cdef int lo, hi, mid, k
    cdef double x, h0, h1, h2, h3, h4
    if seg <= 0 or seg > S:
        d[0] = 0.0 if seg <= 0 else 1.0
        for k in range(1, n):
            d[k] = 0.0
        return
    lo = <int>p[S + seg - 1]
    hi = <int>p[S + seg] - 1
    while lo < hi:
        mid = (lo + hi + 1) >> 1
        if b[mid] <= T:
            lo = mid
        else:
            hi = mid - 1
    x = T - b[lo]
    c = b + N + 1 + lo * (D + 1)
    # Horner's scheme carried to the fourth derivative: h_k = p^(k)(x)/k!
    h0 = c[D]
    h1 = h2 = h3 = h4 = 0.0
    for k in range(D - 1, -1, -1):
        h4 = h4 * x + h3
        h3 = h3 * x + h2
        h2 = h2 * x + h1
        h1 = h1 * x + h0
        h0 = h0 * x + c[k]
    d[0] = h0
    d[1] = h1
    d[2] = 2.0 * h2
    d[3] = 6.0 * h3
    if n > 4:
        d[4] = 24.0 * h4


cdef inline int camlaw_segment(int law, double par, double T) noexcept nogil:
    """Segment of `law` that contains T (right-continuous); -1 for an unknown law."""
    if law == 1000:
        return _turn_segment(&camlaw_turns[<int>par][0], T)
    return _plain_segment(law, par, T)


cdef inline int _plain_segment(int law, double par, double T) noexcept nogil:
    if law == 1001:
        return _shaped_segment(&camlaw_shaped[<int>par][0], T)
    if law == 0:  # cycloidal
        if T < 0.0:
            return 0
        if T < 1.0:
            return 1
        return 2
    elif law == 1:  # modified-sine
        if T < 0.0:
            return 0
        if T < par:
            return 1
        if T < 1.0 - par:
            return 2
        if T < 1.0:
            return 3
        return 4
    elif law == 2:  # 3-4-5
        if T < 0.0:
            return 0
        if T < 1.0:
            return 1
        return 2
    elif law == 3:  # simple-harmonic
        if T < 0.0:
            return 0
        if T < 1.0:
            return 1
        return 2
    elif law == 4:  # parabolic
        if T < 0.0:
            return 0
        if T < 1.0/2.0:
            return 1
        if T < 1.0:
            return 2
        return 3
    elif law == 5:  # 4-5-6-7
        if T < 0.0:
            return 0
        if T < 1.0:
            return 1
        return 2
    elif law == 6:  # modified-trapezoid
        if T < 0.0:
            return 0
        if T < 1.0/8.0:
            return 1
        if T < 3.0/8.0:
            return 2
        if T < 5.0/8.0:
            return 3
        if T < 7.0/8.0:
            return 4
        if T < 1.0:
            return 5
        return 6
    elif law == 7:  # uniform
        if T < 0.0:
            return 0
        if T < 1.0:
            return 1
        return 2
    elif law == 8:  # sine-constant-cosine
        if T < 0.0:
            return 0
        if T < 1.0/8.0:
            return 1
        if T < 0.5*par + 1.0/8.0:
            return 2
        if T < 7.0/8.0 - 0.5*par:
            return 3
        if T < 7.0/8.0:
            return 4
        if T < 1.0:
            return 5
        return 6
    elif law == 9:  # polydyne
        if T < 0.0:
            return 0
        if T < 1.0:
            return 1
        return 2
    elif law == 10:  # 5-6-7-8-9
        if T < 0.0:
            return 0
        if T < 1.0:
            return 1
        return 2
    return -1


cdef inline bint camlaw_dwell(int law, double par, int seg) noexcept nogil:
    """True in the dwell segments (before and after the rise), where H is constant."""
    if seg == 0:
        return True
    if law == 1001:
        return seg == <int>camlaw_shaped[<int>par][1] + 1
    if law == 0:
        return seg == 2
    elif law == 1:
        return seg == 4
    elif law == 2:
        return seg == 2
    elif law == 3:
        return seg == 2
    elif law == 4:
        return seg == 3
    elif law == 5:
        return seg == 2
    elif law == 6:
        return seg == 6
    elif law == 7:
        return seg == 2
    elif law == 8:
        return seg == 6
    elif law == 9:
        return seg == 2
    elif law == 10:
        return seg == 2
    return False


cdef inline double camlaw_lo(int law, double par, int seg) noexcept nogil:
    """Lower end of segment `seg` (-inf for the dwell before the rise)."""
    if seg <= 0:
        return -INFINITY
    if law == 1000:
        return _turn_lo(&camlaw_turns[<int>par][0], seg)
    return _plain_lo(law, par, seg)


cdef inline double _plain_lo(int law, double par, int seg) noexcept nogil:
    if seg <= 0:
        return -INFINITY
    if law == 1001:
        return _shaped_lo(&camlaw_shaped[<int>par][0], seg)
    if law == 0:
        if seg == 1:
            return 0.0
        elif seg == 2:
            return 1.0
    elif law == 1:
        if seg == 1:
            return 0.0
        elif seg == 2:
            return par
        elif seg == 3:
            return 1.0 - par
        elif seg == 4:
            return 1.0
    elif law == 2:
        if seg == 1:
            return 0.0
        elif seg == 2:
            return 1.0
    elif law == 3:
        if seg == 1:
            return 0.0
        elif seg == 2:
            return 1.0
    elif law == 4:
        if seg == 1:
            return 0.0
        elif seg == 2:
            return 1.0/2.0
        elif seg == 3:
            return 1.0
    elif law == 5:
        if seg == 1:
            return 0.0
        elif seg == 2:
            return 1.0
    elif law == 6:
        if seg == 1:
            return 0.0
        elif seg == 2:
            return 1.0/8.0
        elif seg == 3:
            return 3.0/8.0
        elif seg == 4:
            return 5.0/8.0
        elif seg == 5:
            return 7.0/8.0
        elif seg == 6:
            return 1.0
    elif law == 7:
        if seg == 1:
            return 0.0
        elif seg == 2:
            return 1.0
    elif law == 8:
        if seg == 1:
            return 0.0
        elif seg == 2:
            return 1.0/8.0
        elif seg == 3:
            return 0.5*par + 1.0/8.0
        elif seg == 4:
            return 7.0/8.0 - 0.5*par
        elif seg == 5:
            return 7.0/8.0
        elif seg == 6:
            return 1.0
    elif law == 9:
        if seg == 1:
            return 0.0
        elif seg == 2:
            return 1.0
    elif law == 10:
        if seg == 1:
            return 0.0
        elif seg == 2:
            return 1.0
    return INFINITY


cdef inline double camlaw_hi(int law, double par, int seg) noexcept nogil:
    """Upper end of segment `seg` (+inf for the dwell after the rise)."""
    return camlaw_lo(law, par, seg + 1)


cdef inline double camlaw_dwell_value(int seg) noexcept nogil:
    """H in a dwell: 0 before the rise, 1 after it."""
    return 0.0 if seg == 0 else 1.0


cdef inline void camlaw_eval(int law, double par, int seg, double T, double* out) noexcept nogil:
    """out[k] = d^k H/dT^k, k = 0..3, evaluated with the formula of segment `seg`.

    The segment is given, not looked up, so that an integration step that ends
    on a breakpoint keeps using the formula of the segment it started in.
    """
    if law == 1000:
        _turn_eval(&camlaw_turns[<int>par][0], seg, T, out)
    else:
        _plain_eval(law, par, seg, T, out)


cdef inline int _turn_piece(const double* q, int seg, int* k, int* j) noexcept nogil:
    """Where segment `seg` (>= 1) of a turn lies: returns 1 rise, 2 upper dwell, 3 return,
    4 lower dwell; k the turn, j the piece of the rise or return law (1..K)."""
    cdef int S = <int>q[10], m = seg - 1, l
    k[0] = m // S
    l = m % S
    j[0] = 0
    if l < <int>q[5]:
        j[0] = l + 1
        return 1
    l -= <int>q[5]
    if q[11] > 0.0:
        if l == 0:
            return 2
        l -= 1
    if l < <int>q[9]:
        j[0] = l + 1
        return 3
    return 4


cdef inline int _turn_segment(const double* q, double T) noexcept nogil:
    """The last segment whose lower end (_turn_lo, the same floating-point expressions as the
    breakpoints of camdyn.runtime.core.laws.Turn) is <= T, so that a breakpoint itself belongs to
    the segment it starts."""
    if T < 0.0:
        return 0
    cdef double P = q[4]
    cdef int S = <int>q[10], k = <int>floor(T / P), l
    while k > 0 and k * P > T:
        k -= 1
    while (k + 1) * P <= T:
        k += 1
    for l in range(S, 1, -1):
        if _turn_lo(q, k * S + l) <= T:
            return k * S + l
    return k * S + 1


cdef inline double _turn_lo(const double* q, int seg) noexcept nogil:
    cdef int k, j
    cdef int kind = _turn_piece(q, seg, &k, &j)
    cdef double t0 = k * q[4]
    if kind == 1:
        return t0 + _plain_lo(<int>q[0], q[1], j)
    if kind == 2:
        return t0 + 1.0
    if kind == 3:
        return t0 + (q[6] + q[7] * _plain_lo(<int>q[2], q[3], j))
    return t0 + q[8]


cdef inline void _turn_eval(const double* q, int seg, double T, double* out) noexcept nogil:
    cdef int k, j, kind
    cdef double r, h[4]
    if seg <= 0:
        out[0] = out[1] = out[2] = out[3] = 0.0
        return
    kind = _turn_piece(q, seg, &k, &j)
    T -= k * q[4]
    if kind == 1:
        _plain_eval(<int>q[0], q[1], j, T, out)
    elif kind == 3:
        # the return law run backwards: H = 1 - H_ret(u), u = (T - start)/r, so each
        # derivative is -H_ret^(n)/r^n
        r = q[7]
        _plain_eval(<int>q[2], q[3], j, (T - q[6]) / r, h)
        out[0] = 1.0 - h[0]
        out[1] = -h[1] / r
        out[2] = -h[2] / (r * r)
        out[3] = -h[3] / (r * r * r)
    else:
        out[0] = 1.0 if kind == 2 else 0.0
        out[1] = out[2] = out[3] = 0.0


cdef inline void _plain_eval(int law, double par, int seg, double T, double* out) noexcept nogil:
    cdef double c0, c1, c2, c3, c4, c5, c6, c7, c8, c9, c10, c11, c12, c13, c14, c15, c16, c17, c18, c19
    if law == 0:  # cycloidal
        if seg == 0:
            out[0] = 0.0
            out[1] = 0.0
            out[2] = 0.0
            out[3] = 0.0
        elif seg == 1:
            c0 = 6.283185307179586
            c1 = T*c0
            c2 = camlaw_sin(c1)
            c3 = camlaw_cos(c1)
            out[0] = T - 0.15915494309189535*c2
            out[1] = 1.0 - c3
            out[2] = c0*c2
            out[3] = 39.47841760435743*c3
        elif seg == 2:
            out[0] = 1.0
            out[1] = 0.0
            out[2] = 0.0
            out[3] = 0.0
        else:
            out[0] = out[1] = out[2] = out[3] = 0.0
    elif law == 1:  # modified-sine
        if seg == 0:
            out[0] = 0.0
            out[1] = 0.0
            out[2] = 0.0
            out[3] = 0.0
        elif seg == 1:
            c0 = 3.141592653589793*par
            c1 = (1.0/(c0 - 4.0*par + 1.0))
            c2 = 3.141592653589793*T
            c3 = (1.0/(par))
            c4 = 0.5*c2*c3
            c5 = camlaw_sin(c4)
            c6 = camlaw_cos(c4)
            out[0] = c1*par*(c2 - 2.0*c5*par)
            out[1] = -c0*c1*(c6 - 1.0)
            out[2] = 4.934802200544679*c1*c5
            out[3] = 7.751569170074955*c1*c3*c6
        elif seg == 2:
            c0 = 2.0*par
            c1 = (1.0/(c0 - 1.0))
            c2 = 3.141592653589793*c1*(T - par)
            c3 = camlaw_cos(c2)
            c4 = 4.0*(par*par)
            c5 = 4.0*par
            c6 = 3.141592653589793*par
            c7 = 1.0 - c5
            c8 = 0.5*(1.0/(c6 + c7))
            c9 = c1*camlaw_sin(c2)
            out[0] = c8*(2.0*T*c6 - c3*c4 + c3*c5 - c3 + c7)
            out[1] = 3.141592653589793*c8*(c0 + c4*c9 - c5*c9 + c9)
            out[2] = 9.869604401089358*c3*c8
            out[3] = -31.00627668029982*c8*c9
        elif seg == 3:
            c0 = 3.141592653589793*par
            c1 = 1.0 - 4.0*par
            c2 = (1.0/(c0 + c1))
            c3 = T - 1.0
            c4 = (1.0/(par))
            c5 = 1.5707963267948966*c4
            c6 = c3*c5
            c7 = c5*(c3 + 2.0*par)
            out[0] = c2*(T*c0 + c1 - 2.0*(par*par)*camlaw_sin(c6))
            out[1] = -c0*c2*(camlaw_cos(c6) - 1.0)
            out[2] = -4.934802200544679*c2*camlaw_sin(c7)
            out[3] = -7.751569170074955*c2*c4*camlaw_cos(c7)
        elif seg == 4:
            out[0] = 1.0
            out[1] = 0.0
            out[2] = 0.0
            out[3] = 0.0
        else:
            out[0] = out[1] = out[2] = out[3] = 0.0
    elif law == 2:  # 3-4-5
        if seg == 0:
            out[0] = 0.0
            out[1] = 0.0
            out[2] = 0.0
            out[3] = 0.0
        elif seg == 1:
            c0 = (T*T)
            c1 = -15.0*T + 6.0*c0 + 10.0
            c2 = 4.0*T
            c3 = -3.0*T + 2.0*c0 + 1.0
            out[0] = (T*T*T)*c1
            out[1] = 3.0*c0*(T*(c2 - 5.0) + c1)
            out[2] = 60.0*T*c3
            out[3] = 60.0*T*(c2 - 3.0) + 60.0*c3
        elif seg == 2:
            out[0] = 1.0
            out[1] = 0.0
            out[2] = 0.0
            out[3] = 0.0
        else:
            out[0] = out[1] = out[2] = out[3] = 0.0
    elif law == 3:  # simple-harmonic
        if seg == 0:
            out[0] = 0.0
            out[1] = 0.0
            out[2] = 0.0
            out[3] = 0.0
        elif seg == 1:
            c0 = 3.141592653589793*T
            c1 = camlaw_cos(c0)
            c2 = 0.5*camlaw_sin(c0)
            out[0] = 1.0/2.0 - 0.5*c1
            out[1] = 3.141592653589793*c2
            out[2] = 4.934802200544679*c1
            out[3] = -31.00627668029982*c2
        elif seg == 2:
            out[0] = 1.0
            out[1] = 0.0
            out[2] = 0.0
            out[3] = 0.0
        else:
            out[0] = out[1] = out[2] = out[3] = 0.0
    elif law == 4:  # parabolic
        if seg == 0:
            out[0] = 0.0
            out[1] = 0.0
            out[2] = 0.0
            out[3] = 0.0
        elif seg == 1:
            out[0] = 2.0*(T*T)
            out[1] = 4.0*T
            out[2] = 4.0
            out[3] = 0.0
        elif seg == 2:
            out[0] = -2.0*(T*T) + 4.0*T - 1.0
            out[1] = 4.0*(1.0 - T)
            out[2] = -4.0
            out[3] = 0.0
        elif seg == 3:
            out[0] = 1.0
            out[1] = 0.0
            out[2] = 0.0
            out[3] = 0.0
        else:
            out[0] = out[1] = out[2] = out[3] = 0.0
    elif law == 5:  # 4-5-6-7
        if seg == 0:
            out[0] = 0.0
            out[1] = 0.0
            out[2] = 0.0
            out[3] = 0.0
        elif seg == 1:
            c0 = (T*T)
            c1 = (T*T*T)
            c2 = 84.0*T - 70.0*c0 + 20.0*c1 - 35.0
            c3 = 4.0*T - 5.0*c0 + 2.0*c1 - 1.0
            out[0] = -(T*T*T*T)*c2
            out[1] = -4.0*c1*(T*(-35.0*T + 15.0*c0 + 21.0) + c2)
            out[2] = -420.0*c0*c3
            out[3] = -840.0*T*(T*(-5.0*T + 3.0*c0 + 2.0) + c3)
        elif seg == 2:
            out[0] = 1.0
            out[1] = 0.0
            out[2] = 0.0
            out[3] = 0.0
        else:
            out[0] = out[1] = out[2] = out[3] = 0.0
    elif law == 6:  # modified-trapezoid
        if seg == 0:
            out[0] = 0.0
            out[1] = 0.0
            out[2] = 0.0
            out[3] = 0.0
        elif seg == 1:
            c0 = (1.0/(2.0 + M_PI))
            c1 = 12.566370614359172*T
            c2 = camlaw_sin(c1)
            c3 = camlaw_cos(c1)
            out[0] = 0.15915494309189535*c0*(c1 - c2)
            out[1] = -2.0*c0*(c3 - 1.0)
            out[2] = 25.132741228718345*c0*c2
            out[3] = 315.82734083485946*c0*c3
        elif seg == 2:
            c0 = (1.0/(2.0 + M_PI))
            c1 = (M_PI*M_PI)
            c2 = 3.141592653589793*T
            out[0] = 0.019894367886486918*c0*(64.0*(T*T)*c1 - 16.0*T*c1 + c1 + 32.0*c2 - 8.0)
            out[1] = c0*(8.0*c2 - 3.141592653589793 + 2.0)
            out[2] = 25.132741228718345*c0
            out[3] = 0.0
        elif seg == 3:
            c0 = (1.0/(2.0 + M_PI))
            c1 = 4.0*T
            c2 = 3.141592653589793*c1
            c3 = (M_PI*M_PI)
            c4 = 3.141592653589793*(c1 - 3.0/2.0)
            out[0] = 0.15915494309189535*c0*(c1*c3 + c2 - c3 + camlaw_sin(c2))
            out[1] = 2.0*c0*(camlaw_cos(c2) + 1.0 + M_PI)
            out[2] = 25.132741228718345*c0*camlaw_cos(c4)
            out[3] = -32.0*c0*c3*camlaw_sin(c4)
        elif seg == 4:
            c0 = (1.0/(2.0 + M_PI))
            c1 = (M_PI*M_PI)
            c2 = 2.0 + 21.991148575128552
            out[0] = -0.019894367886486918*c0*(64.0*(T*T)*c1 - 50.26548245743669*T*c2 + 33.0*c1 - 8.0)
            out[1] = -c0*(25.132741228718345*T - c2)
            out[2] = -25.132741228718345*c0
            out[3] = 0.0
        elif seg == 5:
            c0 = (1.0/(2.0 + M_PI))
            c1 = (M_PI*M_PI)
            c2 = 4.0*T
            c3 = 3.141592653589793*c2
            c4 = 3.141592653589793*(c2 - 7.0/2.0)
            out[0] = 0.3183098861837907*c0*(6.283185307179586*T + c1 - 0.5*camlaw_sin(c3))
            out[1] = -2.0*c0*(camlaw_cos(c3) - 1.0)
            out[2] = -25.132741228718345*c0*camlaw_cos(c4)
            out[3] = 32.0*c0*c1*camlaw_sin(c4)
        elif seg == 6:
            out[0] = 1.0
            out[1] = 0.0
            out[2] = 0.0
            out[3] = 0.0
        else:
            out[0] = out[1] = out[2] = out[3] = 0.0
    elif law == 7:  # uniform
        if seg == 0:
            out[0] = 0.0
            out[1] = 0.0
            out[2] = 0.0
            out[3] = 0.0
        elif seg == 1:
            out[0] = T
            out[1] = 1.0
            out[2] = 0.0
            out[3] = 0.0
        elif seg == 2:
            out[0] = 1.0
            out[1] = 0.0
            out[2] = 0.0
            out[3] = 0.0
        else:
            out[0] = out[1] = out[2] = out[3] = 0.0
    elif law == 8:  # sine-constant-cosine
        if seg == 0:
            out[0] = 0.0
            out[1] = 0.0
            out[2] = 0.0
            out[3] = 0.0
        elif seg == 1:
            c0 = 6.283185307179586
            c1 = 12.566370614359172*T
            c2 = camlaw_sin(c1)
            c3 = (par*par)
            c4 = (M_PI*M_PI)
            c5 = (1.0/(3.0*par*c4 - 24.0*par + c0 - 2.0*c3*c4 + 16.0*c3 + 8.0))
            c6 = camlaw_cos(c1)
            out[0] = c5*(T*c0 - 0.5*c2)
            out[1] = c0*c5*(1.0 - c6)
            out[2] = 8.0*c2*c4*c5
            out[3] = 992.2008537695942*c5*c6
        elif seg == 2:
            c0 = (M_PI*M_PI)
            c1 = 3.141592653589793*T
            c2 = (par*par)
            c3 = (1.0/(3.0*par*c0 - 24.0*par - 2.0*c0*c2 + 16.0*c2 + 6.283185307179586 + 8.0))
            out[0] = 0.0625*c3*(64.0*(T*T)*c0 - 16.0*T*c0 + c0 + 32.0*c1 - 8.0)
            out[1] = 3.141592653589793*c3*(8.0*c1 - 3.141592653589793 + 2.0)
            out[2] = 8.0*c0*c3
            out[3] = 0.0
        elif seg == 3:
            c0 = 6.283185307179586
            c1 = (M_PI*M_PI)
            c2 = par*c1
            c3 = (par*par)
            c4 = -24.0*par - 2.0*c1*c3 + 16.0*c3 + 8.0
            c5 = (1.0/(c0 + 3.0*c2 + c4))
            c6 = 4.0*par - 3.0
            c7 = 4.0*T
            c8 = 3.141592653589793*(2.0*par - c7 + 1.0/2.0)/c6
            c9 = (1.0/(par - 3.0/4.0))
            c10 = 3.141592653589793*c9*(-T + 0.5*par + 1.0/8.0)
            c11 = 8.0*c5
            out[0] = 0.5*c5*(8.0*T*c2 - c2 + c4 - (c6*c6)*camlaw_cos(c8) + 3.141592653589793*c7)
            out[1] = c0*c5*(par*c0 - c6*camlaw_sin(c8) + 1.0)
            out[2] = c1*c11*camlaw_cos(c10)
            out[3] = 31.00627668029982*c11*c9*camlaw_sin(c10)
        elif seg == 4:
            c0 = (par*par)
            c1 = (M_PI*M_PI)
            c2 = par*c1
            c3 = (1.0/(-24.0*par - 2.0*c0*c1 + 16.0*c0 + 3.0*c2 + 6.283185307179586 + 8.0))
            c4 = 3.141592653589793*T
            out[0] = -0.0625*c3*(64.0*(T*T)*c1 - 112.0*T*c1 + 384.0*par + 32.0*c0*c1 - 256.0*c0 + 49.0*c1 - 48.0*c2 - 32.0*c4 - 136.0)
            out[1] = 3.141592653589793*c3*(-8.0*c4 + 2.0 + 21.991148575128552)
            out[2] = -8.0*c1*c3
            out[3] = 0.0
        elif seg == 5:
            c0 = 6.283185307179586
            c1 = (par*par)
            c2 = (M_PI*M_PI)
            c3 = c1*c2
            c4 = par*c2
            c5 = 24.0*par
            c6 = 16.0*c1
            c7 = -c5 + c6
            c8 = (1.0/(c0 - 2.0*c3 + 3.0*c4 + c7 + 8.0))
            c9 = 4.0*T
            c10 = 3.141592653589793*c9
            c11 = 4.0*par - 3.0
            c12 = -1.0
            c13 = 3.141592653589793*(c9 - 7.0/2.0)
            out[0] = 0.5*c8*(c10 + c12*c5 - c12*c6 - 9.0*c12 - 4.0*c3 + 6.0*c4 + c7 - camlaw_sin(c10) + 7.0)
            out[1] = c0*c8*(1.0 - camlaw_cos(c10))
            out[2] = -8.0*c2*c8*camlaw_cos(c13)
            out[3] = 992.2008537695942*c8*camlaw_sin(c13)
        elif seg == 6:
            out[0] = 1.0
            out[1] = 0.0
            out[2] = 0.0
            out[3] = 0.0
        else:
            out[0] = out[1] = out[2] = out[3] = 0.0
    elif law == 9:  # polydyne
        if seg == 0:
            out[0] = 0.0
            out[1] = 0.0
            out[2] = 0.0
            out[3] = 0.0
        elif seg == 1:
            c0 = (M_PI*M_PI)
            c1 = (1.0/(c0))
            c2 = (T*T*T)
            c3 = (par*par)
            c4 = 3150.0*c3
            c5 = 2.0*T - 9.0
            c6 = (((T*T)*(T*T))*T)*c0
            c7 = c5*c6
            c8 = (T*T)
            c9 = c0 + 45.0*c3
            c10 = c8*c9
            c11 = 2.0*c0 + 21.0*c3
            c12 = c11*c2
            c13 = (T*T*T*T)
            c14 = 3.0*c0 + 7.0*c3
            c15 = c13*c14
            c16 = T*c3
            c17 = c8*(-5.0*T + 2.0*c13 - 7.0*c2 + 9.0*c8 + 1.0)
            c18 = 3.0*c1
            c19 = c18*c3*(-10.0*T + 14.0*c13 - 35.0*c2 + 30.0*c8 + 1.0)
            out[0] = c1*c2*(-T*c4 + 126.0*c10 - 210.0*c12 + 180.0*c15 + 630.0*c3 + 35.0*c7)
            out[1] = c1*c8*(T*(252.0*T*c9 + 175.0*c0*c13*c5 - 630.0*c11*c8 + 720.0*c14*c2 - c4 + 70.0*c6) + 378.0*c10 - 630.0*c12 + 540.0*c15 - 9450.0*c16 + 1890.0*c3 + 105.0*c7)
            out[2] = 1260.0*T*(2.0*c17 + c19)
            out[3] = 1260.0*c16*c18*(60.0*T + 56.0*c2 - 105.0*c8 - 10.0) + 7560.0*c17 + 1260.0*c19 + 2520.0*c2*(18.0*T + 8.0*c2 - 21.0*c8 - 5.0)
        elif seg == 2:
            out[0] = 1.0
            out[1] = 0.0
            out[2] = 0.0
            out[3] = 0.0
        else:
            out[0] = out[1] = out[2] = out[3] = 0.0
    elif law == 10:  # 5-6-7-8-9
        if seg == 0:
            out[0] = 0.0
            out[1] = 0.0
            out[2] = 0.0
            out[3] = 0.0
        elif seg == 1:
            c0 = (T*T)
            c1 = (T*T*T)
            c2 = (T*T*T*T)
            c3 = -420.0*T + 540.0*c0 - 315.0*c1 + 70.0*c2 + 126.0
            out[0] = (((T*T)*(T*T))*T)*c3
            out[1] = 5.0*c2*(T*(216.0*T - 189.0*c0 + 56.0*c1 - 84.0) + c3)
            out[2] = 2520.0*c1*(-5.0*T + 9.0*c0 - 7.0*c1 + 2.0*c2 + 1.0)
            out[3] = 2520.0*c0*(T*(18.0*T - 21.0*c0 + 8.0*c1 - 5.0) - 15.0*T + 27.0*c0 - 21.0*c1 + 6.0*c2 + 3.0)
        elif seg == 2:
            out[0] = 1.0
            out[1] = 0.0
            out[2] = 0.0
            out[3] = 0.0
        else:
            out[0] = out[1] = out[2] = out[3] = 0.0
    elif law == 1001:
        _shaped_horner(&camlaw_shaped[<int>par][0], seg, T, out, 4)
    else:
        out[0] = out[1] = out[2] = out[3] = 0.0


cdef inline double camlaw_d4(int law, double par, int seg, double T) noexcept nogil:
    """d^4 H/dT^4 with the formula of segment `seg`: what the exact Jacobian of a model whose
    equations carry H''' needs (a constrained model's cam profile, camdyn.derive.dae)."""
    cdef int k, j, kind
    cdef double r
    cdef const double* q
    if law != 1000:
        return _plain_d4(law, par, seg, T)
    if seg <= 0:
        return 0.0
    q = &camlaw_turns[<int>par][0]
    kind = _turn_piece(q, seg, &k, &j)
    T -= k * q[4]
    if kind == 1:
        return _plain_d4(<int>q[0], q[1], j, T)
    if kind == 3:
        # the return law run backwards, as in _turn_eval
        r = q[7]
        return -_plain_d4(<int>q[2], q[3], j, (T - q[6]) / r) / (r * r * r * r)
    return 0.0


cdef inline double _plain_d4(int law, double par, int seg, double T) noexcept nogil:
    cdef double d[5]
    cdef double c0, c1, c2
    if law == 0:  # cycloidal
        if seg == 0:
            return 0.0
        elif seg == 1:
            return -248.05021344239856*camlaw_sin(6.283185307179586*T)
        elif seg == 2:
            return 0.0
    elif law == 1:  # modified-sine
        if seg == 0:
            return 0.0
        elif seg == 1:
            return -12.176136379250305*camlaw_sin(1.5707963267948966*T/par)/((par*par)*(-4.0*par + 3.141592653589793*par + 1.0))
        elif seg == 2:
            c0 = 2.0*par - 1.0
            return -48.70454551700122*camlaw_cos(3.141592653589793*(T - par)/c0)/((c0*c0)*(-4.0*par + 3.141592653589793*par + 1.0))
        elif seg == 3:
            return 12.176136379250305*camlaw_sin(1.5707963267948966*(T + 2.0*par - 1.0)/par)/((par*par)*(-4.0*par + 3.141592653589793*par + 1.0))
        elif seg == 4:
            return 0.0
    elif law == 2:  # 3-4-5
        if seg == 0:
            return 0.0
        elif seg == 1:
            return 360.0*(2.0*T - 1.0)
        elif seg == 2:
            return 0.0
    elif law == 3:  # simple-harmonic
        if seg == 0:
            return 0.0
        elif seg == 1:
            return -48.70454551700122*camlaw_cos(3.141592653589793*T)
        elif seg == 2:
            return 0.0
    elif law == 4:  # parabolic
        if seg == 0:
            return 0.0
        elif seg == 1:
            return 0.0
        elif seg == 2:
            return 0.0
        elif seg == 3:
            return 0.0
    elif law == 5:  # 4-5-6-7
        if seg == 0:
            return 0.0
        elif seg == 1:
            c0 = 4.0*T
            c1 = (T*T)
            return -1680.0*(T*T*T) - 840.0*c0*(-5.0*T + 3.0*c1 + 2.0) - 840.0*c0 - 840.0*c1*(6.0*T - 5.0) + 4200.0*c1 + 840.0
        elif seg == 2:
            return 0.0
    elif law == 6:  # modified-trapezoid
        if seg == 0:
            return 0.0
        elif seg == 1:
            return -771.9015648404994*camlaw_sin(12.566370614359172*T)
        elif seg == 2:
            return 0.0
        elif seg == 3:
            return -771.9015648404994*camlaw_cos(3.141592653589793*(4.0*T - 3.0/2.0))
        elif seg == 4:
            return 0.0
        elif seg == 5:
            return 771.9015648404994*camlaw_cos(3.141592653589793*(4.0*T - 7.0/2.0))
        elif seg == 6:
            return 0.0
    elif law == 7:  # uniform
        if seg == 0:
            return 0.0
        elif seg == 1:
            return 0.0
        elif seg == 2:
            return 0.0
    elif law == 8:  # sine-constant-cosine
        if seg == 0:
            return 0.0
        elif seg == 1:
            c0 = (par*par)
            c1 = (M_PI*M_PI)
            return -12468.363652352313*camlaw_sin(12.566370614359172*T)/(3.0*par*c1 - 24.0*par - 2.0*c0*c1 + 16.0*c0 + 6.283185307179586 + 8.0)
        elif seg == 2:
            return 0.0
        elif seg == 3:
            c0 = par - 3.0/4.0
            c1 = (par*par)
            c2 = (M_PI*M_PI)
            return -779.2727282720195*camlaw_cos(3.141592653589793*(-T + 0.5*par + 1.0/8.0)/c0)/((c0*c0)*(3.0*par*c2 - 24.0*par - 2.0*c1*c2 + 16.0*c1 + 6.283185307179586 + 8.0))
        elif seg == 4:
            return 0.0
        elif seg == 5:
            c0 = (par*par)
            c1 = (M_PI*M_PI)
            return 12468.363652352313*camlaw_cos(3.141592653589793*(4.0*T - 7.0/2.0))/(3.0*par*c1 - 24.0*par - 2.0*c0*c1 + 16.0*c0 + 6.283185307179586 + 8.0)
        elif seg == 6:
            return 0.0
    elif law == 9:  # polydyne
        if seg == 0:
            return 0.0
        elif seg == 1:
            c0 = (T*T*T)
            c1 = (T*T)
            c2 = 0.10132118364233778*(par*par)
            return 22680.0*T*c2*(-35.0*T + 28.0*c1 + 10.0) + 15120.0*T*(2.0*(T*T*T*T) - 5.0*T - 7.0*c0 + 9.0*c1 + 1.0) + 15120.0*c0*(-7.0*T + 4.0*c1 + 3.0) + 15120.0*c1*(18.0*T + 8.0*c0 - 21.0*c1 - 5.0) + 7560.0*c2*(60.0*T + 56.0*c0 - 105.0*c1 - 10.0)
        elif seg == 2:
            return 0.0
    elif law == 10:  # 5-6-7-8-9
        if seg == 0:
            return 0.0
        elif seg == 1:
            c0 = (T*T)
            c1 = (T*T*T)
            return 15120.0*T*(2.0*(T*T*T*T) + T*(18.0*T - 21.0*c0 + 8.0*c1 - 5.0) - 5.0*T + c0*(-7.0*T + 4.0*c0 + 3.0) + 9.0*c0 - 7.0*c1 + 1.0)
        elif seg == 2:
            return 0.0
    if law == 1001:
        _shaped_horner(&camlaw_shaped[<int>par][0], seg, T, d, 5)
        return d[4]
    return 0.0

# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True, initializedcheck=False
#
# GENERATED FILE - DO NOT EDIT.  Written by `camdyn derive` from camdyn/derive/camlaws.py;
# edit that and regenerate.  `camdyn derive --check` fails while this file is stale.
# Derivation key: sha256:038530a315671603e7bdc5160370fa5f680c2994e93b557388cab4c326d4a5e1
# Text hash: sha256:5c73cb904afa1b0992a09802f9d716540dca923d7165b98fbf6bbb5506f8614c
#
# Python access to the generated cam-law library (camlaws.pxd): evaluation on
# arrays, segment lookup and breakpoints.  Compiled models cimport the .pxd.

import json

import numpy as np

from libc.math cimport M_PI

_LAWS_JSON = """
[
 {
  "amplitude": "2*pi",
  "bounds": [
   "0.0",
   "1.0"
  ],
  "code": 0,
  "key": "cycloidal",
  "parameter": null,
  "reference": "(A.2.8)-(A.2.11)",
  "title": "Cycloidal"
 },
 {
  "amplitude": "pi**2/(2*(-4*theta + pi*theta + 1))",
  "bounds": [
   "0.0",
   "par",
   "1.0 - par",
   "1.0"
  ],
  "code": 1,
  "key": "modified-sine",
  "parameter": {
   "default": 0.1,
   "doc": "fraction of the rise to the acceleration peak (thesis fig. A.2.3: 0.1)",
   "high": 0.5,
   "low": 0.0,
   "name": "theta"
  },
  "reference": "(A.2.17)-(A.2.20)",
  "title": "Modified sine"
 },
 {
  "amplitude": "10*sqrt(3)/3",
  "bounds": [
   "0.0",
   "1.0"
  ],
  "code": 2,
  "key": "3-4-5",
  "parameter": null,
  "reference": "H = 10 T^3 - 15 T^4 + 6 T^5",
  "title": "3-4-5 polynomial"
 },
 {
  "amplitude": "pi**2/2",
  "bounds": [
   "0.0",
   "1.0"
  ],
  "code": 3,
  "key": "simple-harmonic",
  "parameter": null,
  "reference": "H = (1 - cos pi T)/2",
  "title": "Simple harmonic"
 },
 {
  "amplitude": "4",
  "bounds": [
   "0.0",
   "1.0/2.0",
   "1.0"
  ],
  "code": 4,
  "key": "parabolic",
  "parameter": null,
  "reference": "H'' = +-4",
  "title": "Parabolic (constant acceleration)"
 },
 {
  "amplitude": "84*sqrt(5)/25",
  "bounds": [
   "0.0",
   "1.0"
  ],
  "code": 5,
  "key": "4-5-6-7",
  "parameter": null,
  "reference": "H = 35 T^4 - 84 T^5 + 70 T^6 - 20 T^7",
  "title": "4-5-6-7 polynomial"
 },
 {
  "amplitude": "8*pi/(2 + pi)",
  "bounds": [
   "0.0",
   "1.0/8.0",
   "3.0/8.0",
   "5.0/8.0",
   "7.0/8.0",
   "1.0"
  ],
  "code": 6,
  "key": "modified-trapezoid",
  "parameter": null,
  "reference": "jerk-limited, eighths of the rise",
  "title": "Modified trapezoid"
 },
 {
  "amplitude": "None",
  "bounds": [
   "0.0",
   "1.0"
  ],
  "code": 7,
  "key": "uniform",
  "parameter": null,
  "reference": "H = T; ramp input (3.8)",
  "title": "Uniform motion (constant velocity)"
 },
 {
  "amplitude": "8*pi**2/(-2*pi**2*c**2 + 16*c**2 - 24*c + 3*pi**2*c + 2*pi + 8)",
  "bounds": [
   "0.0",
   "1.0/8.0",
   "0.5*par + 1.0/8.0",
   "7.0/8.0 - 0.5*par",
   "7.0/8.0",
   "1.0"
  ],
  "code": 8,
  "key": "sine-constant-cosine",
  "parameter": {
   "default": 0.25,
   "doc": "fraction of the rise at constant acceleration, b = 1/4, d = 3/4 - c",
   "high": 0.75,
   "low": 0.0,
   "name": "c"
  },
  "reference": "Norton SCCA, b = 1/4, d = 3/4 - c",
  "title": "Sine-constant-cosine acceleration (SCCA, b = 1/4)"
 },
 {
  "amplitude": "1",
  "bounds": [
   "0.0",
   "1.0"
  ],
  "code": 9,
  "key": "polydyne",
  "parameter": {
   "default": 0.15,
   "doc": "design tau T_e/t_m (3.3) at which the one-DOF output follows the degree-9 rise exactly",
   "high": 1.0,
   "low": 0.0,
   "name": "tau_d"
  },
  "reference": "H = P9 + (tau_d/2 pi)^2 P9'', P9 with P' to P^(4) zero at both ends",
  "title": "Polydyne (one-DOF compensated degree-9 rise)"
 },
 {
  "amplitude": "1215*sqrt(7)/343",
  "bounds": [
   "0.0",
   "1.0"
  ],
  "code": 10,
  "key": "5-6-7-8-9",
  "parameter": null,
  "reference": "H = 126 T^5 - 420 T^6 + 540 T^7 - 315 T^8 + 70 T^9",
  "title": "5-6-7-8-9 polynomial"
 }
]
"""
LAWS = json.loads(_LAWS_JSON)
"""Per law: key, code, title, reference, bounds (as code), parameter, amplitude."""

TURN = 1000
"""Law code of a dwell-rise-dwell-return turn (see camlaws.pxd); its par is a slot index."""
TURN_SLOTS = 256

_turn_index = {}


def turn_slot(int rise, double rise_par, int ret, double ret_par, double up, double r,
              double low):
    """Slot of camlaw_turns describing one turn: the rise law (length 1), an upper dwell
    `up`, the return law over length `r` and a lower dwell `low`, all in units of the rise.

    Equal turns share a slot and a written slot never changes, so runs in other threads keep
    reading what they were given.  The caller checks the values (camdyn.runtime.core.laws)."""
    spec = (rise, rise_par, ret, ret_par, up, r, low)
    if spec in _turn_index:
        return _turn_index[spec]
    if len(_turn_index) >= TURN_SLOTS:
        raise RuntimeError(f"more than {TURN_SLOTS} different cam turns in one process")
    k_rise, k_ret = len(breakpoints(rise, rise_par)) - 1, len(breakpoints(ret, ret_par)) - 1
    cdef int s = len(_turn_index)
    cdef double* q = &camlaw_turns[s][0]
    q[0], q[1], q[2], q[3] = rise, rise_par, ret, ret_par
    q[4] = 1.0 + up + r + low
    q[5], q[6], q[7], q[8], q[9] = k_rise, 1.0 + up, r, 1.0 + up + r, k_ret
    q[11], q[12] = (1.0 if up > 0.0 else 0.0), (1.0 if low > 0.0 else 0.0)
    q[10] = k_rise + k_ret + q[11] + q[12]
    _turn_index[spec] = s
    return s


SHAPED = 1001
"""Law code of a rise shaped by the user (see camlaws.pxd); its par is a slot index."""
SHAPED_SLOTS = 64
SHAPED_POOL = 262144

_shaped_index = {}
_shaped_used = 0


def shaped_slot(ends, first, breaks, coefs):
    """Slot of camlaw_shaped describing a piecewise polynomial rise: segment ends e_1..e_S
    (e_S = 1), the first piece of each segment and N after them, the breaks b_0 = 0 < ... <
    b_N = 1, and an (N, D + 1) array of coefficients in powers of T - b_i.

    Equal rises share a slot and a written slot never changes, so runs in other threads keep
    reading what they were given.  The caller checks the values (camdyn.runtime.core.shaped)."""
    global _shaped_used
    e = np.ascontiguousarray(ends, dtype=float).ravel()
    f = np.ascontiguousarray(first, dtype=float).ravel()
    b = np.ascontiguousarray(breaks, dtype=float).ravel()
    c = np.ascontiguousarray(coefs, dtype=float)
    cdef int S = e.shape[0], N = b.shape[0] - 1, D = c.shape[1] - 1
    if f.shape[0] != S + 1 or c.shape[0] != N or S < 1 or N < 1:
        raise ValueError("shaped_slot: inconsistent sizes")
    key = (e.tobytes(), f.tobytes(), b.tobytes(), c.tobytes(), D)
    if key in _shaped_index:
        return _shaped_index[key]
    data = np.concatenate([e, f, b, c.ravel()])
    if len(_shaped_index) >= SHAPED_SLOTS:
        raise RuntimeError(f"more than {SHAPED_SLOTS} different shaped rises in one process")
    if _shaped_used + data.shape[0] > SHAPED_POOL:
        raise RuntimeError(f"the shaped rises of this process need more than {SHAPED_POOL} "
                           f"numbers (breaks and coefficients)")
    cdef int slot = len(_shaped_index), i
    cdef double[::1] v = data
    for i in range(v.shape[0]):
        camlaw_shaped_pool[_shaped_used + i] = v[i]
    camlaw_shaped[slot][0] = _shaped_used
    camlaw_shaped[slot][1] = S
    camlaw_shaped[slot][2] = N
    camlaw_shaped[slot][3] = D
    _shaped_used += v.shape[0]
    _shaped_index[key] = slot
    return slot


def law_trig(x):
    """(sin x, cos x) as the laws compute them (camlaw_sin, camlaw_cos of camlaws.pxd), for
    checking them against libm's."""
    cdef double[::1] v = np.ascontiguousarray(x, dtype=float).ravel()
    out = np.empty((2, v.shape[0]))
    cdef double[:, ::1] o = out
    cdef Py_ssize_t i
    for i in range(v.shape[0]):
        o[0, i] = camlaw_sin(v[i])
        o[1, i] = camlaw_cos(v[i])
    return out[0], out[1]


def evaluate(int law, double par, T):
    """Array (len(T), 4) of H, H', H'', H''' of `law` at the times T."""
    cdef double[::1] t = np.ascontiguousarray(T, dtype=float).ravel()
    res = np.empty((t.shape[0], 4))
    cdef double[:, ::1] r = res
    cdef Py_ssize_t i
    cdef int seg
    for i in range(t.shape[0]):
        seg = camlaw_segment(law, par, t[i])
        camlaw_eval(law, par, seg, t[i], &r[i, 0])
    return res


def segment(int law, double par, double T):
    """Segment index of `law` at T (see camlaws.pxd)."""
    return camlaw_segment(law, par, T)


def breakpoints(int law, double par):
    """Breakpoints 0 = b0 < ... < bK = 1 of the rise of `law`."""
    cdef int i
    if law == SHAPED:
        return [0.0] + [camlaw_shaped_pool[<int>camlaw_shaped[<int>par][0] + i]
                        for i in range(<int>camlaw_shaped[<int>par][1])]
    if law == 0:  # cycloidal
        return [0.0, 1.0]
    elif law == 1:  # modified-sine
        return [0.0, par, 1.0 - par, 1.0]
    elif law == 2:  # 3-4-5
        return [0.0, 1.0]
    elif law == 3:  # simple-harmonic
        return [0.0, 1.0]
    elif law == 4:  # parabolic
        return [0.0, 1.0/2.0, 1.0]
    elif law == 5:  # 4-5-6-7
        return [0.0, 1.0]
    elif law == 6:  # modified-trapezoid
        return [0.0, 1.0/8.0, 3.0/8.0, 5.0/8.0, 7.0/8.0, 1.0]
    elif law == 7:  # uniform
        return [0.0, 1.0]
    elif law == 8:  # sine-constant-cosine
        return [0.0, 1.0/8.0, 0.5*par + 1.0/8.0, 7.0/8.0 - 0.5*par, 7.0/8.0, 1.0]
    elif law == 9:  # polydyne
        return [0.0, 1.0]
    elif law == 10:  # 5-6-7-8-9
        return [0.0, 1.0]
    raise ValueError(f"unknown cam law code {law}")

# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True, initializedcheck=False
#
# GENERATED FILE - DO NOT EDIT.  Written by `camdyn derive` from camdyn/derive/models/roller.py;
# edit that and regenerate.  `camdyn derive --check` fails while this file is stale.
# Derivation key: sha256:8451f1a139571df882047720feb29f78a89fb680ec4cef80b08a1b54c36b6282
# Text hash: sha256:c8c3dc43278890ea5b46b82e90190700ce5c7a252e656ffb10e91e7d464fde09
#
# Roller vibration, bilateral contact: roller mass and contact stiffness in series with the linkage, no backlash (thesis sec. 9.2.1, with the one-DOF follower of sec. 3.3)
# Source hash: sha256:e9e5870f5ef080f71b3082004a824cdf8c772265063561f75e0f0fbbf4258b5a
#
# The roller held in a groove without backlash: the contact spring and damper act both
#     ways (F_c = kappa omega^2 delta + 2 zeta sqrt(mu kappa) omega delta', linear), so the
#     contact never opens and there are no modes or events.  The smooth stiff case of the
#     benchmarks: a fast mode of omega sqrt((kappa + 1)/mu) that only rings, undamped at
#     zeta = 0, in series with the follower (thesis sec. 9.2.1).

import json

from cpython.pycapsule cimport PyCapsule_New
from libc.math cimport sqrt

from camdyn.runtime.engine.abi cimport *
from camdyn.generated.camlaws cimport (camlaw_dwell, camlaw_dwell_value, camlaw_eval, camlaw_hi,
                                       camlaw_lo, camlaw_segment)

# sizes, known when the integration loops (loops.pxi) are compiled into this module
cdef enum:
    _NQ = 2                  # second-order coordinates
    _NS = 4                  # states: q, q', first-order states
    _NCAM = 1                # cam input instances (one segment mode each)
    _NM = 1                  # modes: cam segments, then the force elements' modes
    _NE = 0                  # events
    _NQ1 = 2                 # array sizes that must not be zero
    _NE1 = 1
    _JAC_SYMBOLIC = 1           # jacobian() is derived symbolically: the implicit loops use it
    _FT_SYMBOLIC = 1            # jacobian() also gives df/dt
    _PROJECTS = 0               # no constraints: nothing to project after a step (project())

cdef int _EDIR[_NE1]    # crossing direction of each event: +1 upward, -1 downward



cdef void prepare(Ctx* ctx) noexcept nogil:
    """Parameter-only subexpressions, once per run, into ctx.k."""
    cdef double tau = ctx.p[0]
    cdef double q = ctx.p[1]
    cdef double mu = ctx.p[2]
    cdef double kappa = ctx.p[3]
    cdef double zeta = ctx.p[4]
    cdef double _c0 = 39.47841760435743*(1.0/(tau*tau))
    cdef double _c1 = 12.566370614359172*(1.0/(tau))
    cdef double _c2 = _c1*q
    cdef double _c3 = kappa + 1.0
    cdef double _c4 = (1.0/(mu))
    cdef double _c5 = _c0*_c4
    cdef double _c6 = _c4*q
    cdef double _c7 = sqrt(mu)
    cdef double _c8 = sqrt(kappa)*zeta
    cdef double _c9 = _c8/_c7
    cdef double _c10 = _c7*_c8
    ctx.k[0] = _c0  # _k0
    ctx.k[1] = _c2  # _k1
    ctx.k[2] = _c3  # _k2
    ctx.k[3] = -kappa  # _k3
    ctx.k[4] = -_c5  # _k4
    ctx.k[5] = -_c1*(_c6 + _c9)  # _k5
    ctx.k[6] = _c1*_c6  # _k6
    ctx.k[7] = _c1*_c9  # _k7
    ctx.k[8] = _c0*kappa  # _k8
    ctx.k[9] = _c1*_c10  # _k9
    ctx.k[10] = -_c0  # _k10
    ctx.k[11] = -_c2  # _k11
    ctx.k[12] = _c5  # _k12
    ctx.k[13] = -_c3*_c5  # _k13
    ctx.k[14] = -_c1*_c4*(_c10 + q)  # _k14
    ctx.k[15] = _c5*kappa  # _k15


cdef inline void rhs(double t, const double* _y, double* _dy, Ctx* ctx) noexcept nogil:
    """dy/dt: q', q'' from M q'' = f, and the rates of the first-order states; specialised for cam inputs in a dwell."""
    cdef double tau = ctx.p[0]
    cdef double q = ctx.p[1]
    cdef double mu = ctx.p[2]
    cdef double kappa = ctx.p[3]
    cdef double zeta = ctx.p[4]
    cdef double _k0 = ctx.k[0]
    cdef double _k1 = ctx.k[1]
    cdef double _k2 = ctx.k[2]
    cdef double _k3 = ctx.k[3]
    cdef double _k4 = ctx.k[4]
    cdef double _k5 = ctx.k[5]
    cdef double _k6 = ctx.k[6]
    cdef double _k7 = ctx.k[7]
    cdef double _k8 = ctx.k[8]
    cdef double _k9 = ctx.k[9]
    cdef double _k10 = ctx.k[10]
    cdef double _k11 = ctx.k[11]
    cdef double _k12 = ctx.k[12]
    cdef double _k13 = ctx.k[13]
    cdef double _k14 = ctx.k[14]
    cdef double _k15 = ctx.k[15]
    cdef double X = _y[0]
    cdef double R = _y[1]
    cdef double Xd = _y[2]
    cdef double Rd = _y[3]
    cdef double _cam0[4]  # H(T) and its derivatives
    cdef int _v = ctx.variant
    cdef double* _c
    cdef double _a
    if _v & 1:
        _cam0[0] = ctx.cache[1]  # H in the dwell, set by refresh()
    else:
        # the stages of a step share arguments (RK4: t + h/2 twice, t + h for the next
        # k1): the last evaluation is kept in ctx.cache and reused
        _a = t
        _c = &ctx.cache[0]
        if _a == _c[0]:
            _cam0[0], _cam0[1], _cam0[2], _cam0[3] = _c[1], _c[2], _c[3], _c[4]
        else:
            camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], _a, _cam0)
            _c[0], _c[1], _c[2], _c[3], _c[4] = _a, _cam0[0], _cam0[1], _cam0[2], _cam0[3]

    cdef double _s0_0, _s1_0
    _dy[0] = Xd
    _dy[1] = Rd
    if _v == 0:
        _s0_0 = -X
        _dy[2] = _k0*(R + _s0_0) + _k1*(Rd - Xd)
        _dy[3] = Rd*_k5 + Xd*_k6 + _cam0[1]*_k7 + _k4*(R*_k2 + _cam0[0]*_k3 + _s0_0)
    elif _v == 1:  # in a dwell: 0
        _s1_0 = -X
        _dy[2] = _k0*(R + _s1_0) + _k1*(Rd - Xd)
        _dy[3] = Rd*_k5 + Xd*_k6 + _k4*(R*_k2 + _cam0[0]*_k3 + _s1_0)


cdef void outputs(double t, const double* _y, double* _out, Ctx* ctx) noexcept nogil:
    """The named outputs (Xdd, U, Fc, delta)."""
    cdef double _dy[4]
    rhs(t, _y, _dy, ctx)
    cdef double tau = ctx.p[0]
    cdef double q = ctx.p[1]
    cdef double mu = ctx.p[2]
    cdef double kappa = ctx.p[3]
    cdef double zeta = ctx.p[4]
    cdef double _k0 = ctx.k[0]
    cdef double _k1 = ctx.k[1]
    cdef double _k2 = ctx.k[2]
    cdef double _k3 = ctx.k[3]
    cdef double _k4 = ctx.k[4]
    cdef double _k5 = ctx.k[5]
    cdef double _k6 = ctx.k[6]
    cdef double _k7 = ctx.k[7]
    cdef double _k8 = ctx.k[8]
    cdef double _k9 = ctx.k[9]
    cdef double _k10 = ctx.k[10]
    cdef double _k11 = ctx.k[11]
    cdef double _k12 = ctx.k[12]
    cdef double _k13 = ctx.k[13]
    cdef double _k14 = ctx.k[14]
    cdef double _k15 = ctx.k[15]
    cdef double X = _y[0]
    cdef double R = _y[1]
    cdef double Xd = _y[2]
    cdef double Rd = _y[3]
    cdef double Xdd = _dy[2]
    cdef double Rdd = _dy[3]
    cdef double _cam0[4]  # H(T) and its derivatives
    cdef double* _c
    # rhs() has just evaluated this input at the same argument and kept it (outside a dwell)
    _c = &ctx.cache[0]
    if _c[0] == t:
        _cam0[0], _cam0[1], _cam0[2], _cam0[3] = _c[1], _c[2], _c[3], _c[4]
    else:
        camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], t, _cam0)

    cdef double _o0 = -_cam0[0]
    cdef double _o1 = R + _o0
    _out[0] = _dy[2]  # Xdd
    _out[1] = X + _o0  # U
    _out[2] = -_k8*_o1 - _k9*(Rd - _cam0[1])  # Fc
    _out[3] = -_o1  # delta


cdef void mass_stiffness(double t, const double* _y, double* _Mm, double* _Km, Ctx* ctx) noexcept nogil:
    """Mass matrix M and stiffness K = -df/dq (row-major, n x n) at (t, y), for frozen analyses."""
    cdef double tau = ctx.p[0]
    cdef double q = ctx.p[1]
    cdef double mu = ctx.p[2]
    cdef double kappa = ctx.p[3]
    cdef double zeta = ctx.p[4]
    cdef double _k0 = ctx.k[0]
    cdef double _k1 = ctx.k[1]
    cdef double _k2 = ctx.k[2]
    cdef double _k3 = ctx.k[3]
    cdef double _k4 = ctx.k[4]
    cdef double _k5 = ctx.k[5]
    cdef double _k6 = ctx.k[6]
    cdef double _k7 = ctx.k[7]
    cdef double _k8 = ctx.k[8]
    cdef double _k9 = ctx.k[9]
    cdef double _k10 = ctx.k[10]
    cdef double _k11 = ctx.k[11]
    cdef double _k12 = ctx.k[12]
    cdef double _k13 = ctx.k[13]
    cdef double _k14 = ctx.k[14]
    cdef double _k15 = ctx.k[15]
    cdef double X = _y[0]
    cdef double R = _y[1]
    cdef double Xd = _y[2]
    cdef double Rd = _y[3]
    cdef double _cam0[4]  # H(T) and its derivatives
    camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], t, _cam0)

    cdef double _m0 = 39.47841760435743*(1.0/(tau*tau))
    cdef double _m1 = -_m0
    _Mm[0] = 1.0
    _Mm[1] = 0.0
    _Mm[2] = 0.0
    _Mm[3] = mu
    _Km[0] = _m0
    _Km[1] = _m1
    _Km[2] = _m1
    _Km[3] = _m0*(kappa + 1.0)


cdef void jacobian(double t, const double* _y, double* _J, double* _ft, Ctx* ctx) noexcept nogil:
    """d(dy/dt)/dy at (t, y), row-major _NS x _NS, derived symbolically (CSE'd): the Jacobian
    of the general right-hand side in the current modes, a cam input in a dwell taking its
    dwell values.
    With _ft not NULL also df/dt there (_NS values), derived the same way."""
    cdef double tau = ctx.p[0]
    cdef double q = ctx.p[1]
    cdef double mu = ctx.p[2]
    cdef double kappa = ctx.p[3]
    cdef double zeta = ctx.p[4]
    cdef double _k0 = ctx.k[0]
    cdef double _k1 = ctx.k[1]
    cdef double _k2 = ctx.k[2]
    cdef double _k3 = ctx.k[3]
    cdef double _k4 = ctx.k[4]
    cdef double _k5 = ctx.k[5]
    cdef double _k6 = ctx.k[6]
    cdef double _k7 = ctx.k[7]
    cdef double _k8 = ctx.k[8]
    cdef double _k9 = ctx.k[9]
    cdef double _k10 = ctx.k[10]
    cdef double _k11 = ctx.k[11]
    cdef double _k12 = ctx.k[12]
    cdef double _k13 = ctx.k[13]
    cdef double _k14 = ctx.k[14]
    cdef double _k15 = ctx.k[15]
    cdef double X = _y[0]
    cdef double R = _y[1]
    cdef double Xd = _y[2]
    cdef double Rd = _y[3]
    cdef double _cam0[4]  # H(T) and its derivatives
    camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], t, _cam0)

    cdef int _k
    cdef double _ftl[4]
    for _k in range(16):
        _J[_k] = 0.0
    for _k in range(4):
        _ftl[_k] = 0.0
    for _k in range(2):
        _J[_k * 5 + 2] = 1.0  # d q'/d q'
    _J[8] = _k10
    _J[9] = _k0
    _J[10] = _k11
    _J[11] = _k1
    _J[12] = _k12
    _J[13] = _k13
    _J[14] = _k6
    _J[15] = _k14
    _ftl[3] = _cam0[1]*_k15 + _cam0[2]*_k7
    if _ft != NULL:
        for _k in range(4):
            _ft[_k] = _ftl[_k]


cdef void refresh(Ctx* ctx) noexcept nogil:
    """ctx.variant from the modes (bit i set when cam input i sits in a dwell); the cam
    cache is emptied, its entries belong to the old segments."""
    ctx.variant = 0
    ctx.cache[0] = 0.0 / 0.0
    ctx.cache[1] = camlaw_dwell_value(ctx.mode[0])
    if camlaw_dwell(ctx.law[0], ctx.law_par[0], ctx.mode[0]):
        ctx.variant |= 1


cdef inline bint _lti_now(Ctx* ctx) noexcept nogil:
    """Whether y' = A y + c with A and c constant in the segments now in force, so that the
    loops may step over the interval exactly (derive/codegen.py, _linear_in_dwell): every cam input in a dwell."""
    return camlaw_dwell(ctx.law[0], ctx.law_par[0], ctx.mode[0])


cdef void update_modes(double t, const double* _y, Ctx* ctx) noexcept nogil:
    """Segment of every cam input at (t, y); the force elements keep their modes."""
    cdef double tau = ctx.p[0]
    cdef double q = ctx.p[1]
    cdef double mu = ctx.p[2]
    cdef double kappa = ctx.p[3]
    cdef double zeta = ctx.p[4]
    cdef double _k0 = ctx.k[0]
    cdef double _k1 = ctx.k[1]
    cdef double _k2 = ctx.k[2]
    cdef double _k3 = ctx.k[3]
    cdef double _k4 = ctx.k[4]
    cdef double _k5 = ctx.k[5]
    cdef double _k6 = ctx.k[6]
    cdef double _k7 = ctx.k[7]
    cdef double _k8 = ctx.k[8]
    cdef double _k9 = ctx.k[9]
    cdef double _k10 = ctx.k[10]
    cdef double _k11 = ctx.k[11]
    cdef double _k12 = ctx.k[12]
    cdef double _k13 = ctx.k[13]
    cdef double _k14 = ctx.k[14]
    cdef double _k15 = ctx.k[15]
    cdef double X = _y[0]
    cdef double R = _y[1]
    cdef double Xd = _y[2]
    cdef double Rd = _y[3]

    ctx.mode[0] = camlaw_segment(ctx.law[0], ctx.law_par[0], t)
    refresh(ctx)


cdef void events(double t, const double* _y, double* _g, Ctx* ctx) noexcept nogil:
    """Event functions; an event not armed in the current modes reads 1 (never crosses)."""
    pass


cdef void on_event(int _e, double t, double* _y, Ctx* ctx) noexcept nogil:
    """What event k does: new modes (and state resets) at its crossing."""
    pass


cdef void rhs_ptr(double t, const double* _y, double* _dy, Ctx* ctx) noexcept nogil:
    rhs(t, _y, _dy, ctx)


cdef inline int project(double t, double* _y, Ctx* ctx) noexcept nogil:
    """No constraints to project onto (ModelC.project is NULL)."""
    return 0


# the integration loops of camdyn.runtime, compiled here with rhs() inlined
include "camdyn/runtime/engine/loops.pxi"


def initial_state(p):
    """The default initial state for the parameter vector p (manifest order)."""
    cdef double tau = p[0]
    cdef double q = p[1]
    cdef double mu = p[2]
    cdef double kappa = p[3]
    cdef double zeta = p[4]
    return [0.0, 0.0, 0.0, 0.0]


def cam_time_affine(p):
    """Per cam input, (a, b) with argument a t + b, or None when it depends on the state."""
    cdef double tau = p[0]
    cdef double q = p[1]
    cdef double mu = p[2]
    cdef double kappa = p[3]
    cdef double zeta = p[4]
    return [(1.0, 0.0)]


cdef ModelC _model
_model.abi_version = CAMDYN_ABI
_model.n_q = _NQ
_model.n_states = _NS
_model.n_params = 5
_model.n_outputs = 4
_model.n_families = 1
_model.n_instances = _NCAM
_model.n_modes = _NM
_model.n_events = _NE
_model.n_const = 16
_model.n_cache = 5
_model.prepare = prepare
_model.rhs = rhs_ptr
_model.outputs = outputs
_model.update_modes = update_modes
_model.refresh = refresh
_model.events = events
_model.on_event = on_event
_model.mass_stiffness = mass_stiffness
_model.jac = jacobian
_model.project = NULL
_model.run = run_loops
_model.dense_fill = dense_fill

MODEL = PyCapsule_New(<void*>&_model, b"camdyn.ModelC", NULL)
"""The model's C interface for camdyn.runtime (a PyCapsule holding a ModelC*)."""

_MANIFEST_JSON = """
{
 "cam_families": [
  "H"
 ],
 "cam_instances": [
  {
   "argument": "T",
   "family": "H",
   "order": 1,
   "time_affine": true
  }
 ],
 "events": [],
 "jacobian": "symbolic",
 "modes": [],
 "n_q": 2,
 "name": "roller_bilateral",
 "options": [],
 "outputs": [
  {
   "doc": "follower acceleration X''",
   "name": "Xdd",
   "unit": "h_m/t_m^2"
  },
  {
   "doc": "positional error of the follower, X - H (3.4)",
   "name": "U",
   "unit": "h_m"
  },
  {
   "doc": "contact force of the cam on the roller",
   "name": "Fc",
   "unit": "m h_m/t_m^2"
  },
  {
   "doc": "deflection of the contact, H - R",
   "name": "delta",
   "unit": "h_m"
  }
 ],
 "parameters": [
  {
   "default": 0.15,
   "doc": "period of the linkage's natural vibration over the rise time, T_e/t_m (3.3)",
   "high": 1.0,
   "low": 0.0,
   "name": "tau",
   "open_high": true,
   "open_low": true,
   "range": "0 < tau < 1",
   "unit": "1"
  },
  {
   "default": 0.0,
   "doc": "relative damping of the linkage, d = 2 q sqrt(m c) (6.47)",
   "high": 1.0,
   "low": 0.0,
   "name": "q",
   "open_high": true,
   "open_low": false,
   "range": "0 <= q < 1",
   "unit": "1"
  },
  {
   "default": 0.05,
   "doc": "roller mass over the follower's equivalent mass, m_r/m",
   "high": 10.0,
   "low": 0.0,
   "name": "mu",
   "open_high": false,
   "open_low": true,
   "range": "0 < mu <= 10",
   "unit": "1"
  },
  {
   "default": 1000.0,
   "doc": "contact stiffness over linkage stiffness, k_c/c (sec. 9.2.1: 100 to 1000)",
   "high": 10000000.0,
   "low": 1.0,
   "name": "kappa",
   "open_high": false,
   "open_low": false,
   "range": "1 <= kappa <= 1e+07",
   "unit": "1"
  },
  {
   "default": 0.0,
   "doc": "damping ratio of the contact mode, d_c = 2 zeta sqrt(m_r k_c)",
   "high": 1.0,
   "low": 0.0,
   "name": "zeta",
   "open_high": false,
   "open_low": false,
   "range": "0 <= zeta <= 1",
   "unit": "1"
  }
 ],
 "reference": "thesis sec. 9.2.1, with the one-DOF follower of sec. 3.3",
 "residual": {
  "acceleration": "Xdd",
  "error": "U",
  "rise_end": 1.0,
  "rise_state": ""
 },
 "source_hash": "sha256:e9e5870f5ef080f71b3082004a824cdf8c772265063561f75e0f0fbbf4258b5a",
 "states": [
  {
   "doc": "follower output position over the stroke, X = x/h_m",
   "initial": 0.0,
   "name": "X",
   "scale": 1.0,
   "unit": "h_m"
  },
  {
   "doc": "roller position over the stroke, R = r/h_m",
   "initial": 0.0,
   "name": "R",
   "scale": 1.0,
   "unit": "h_m"
  },
  {
   "doc": "rate of X",
   "initial": 0.0,
   "name": "Xd",
   "scale": 1.0,
   "unit": "h_m/t_m"
  },
  {
   "doc": "rate of R",
   "initial": 0.0,
   "name": "Rd",
   "scale": 1.0,
   "unit": "h_m/t_m"
  }
 ],
 "time": {
  "name": "T",
  "unit": "t_m"
 },
 "time_derivative": "symbolic",
 "title": "Roller vibration, bilateral contact: roller mass and contact stiffness in series with the linkage, no backlash"
}
"""
MANIFEST = json.loads(_MANIFEST_JSON)
"""States, parameters (defaults, units, ranges), outputs, cam inputs, modes, events, source hash."""

# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True, initializedcheck=False
#
# GENERATED FILE - DO NOT EDIT.  Written by `camdyn derive` from camdyn/derive/models/camshaft2.py;
# edit that and regenerate.  `camdyn derive --check` fails while this file is stale.
# Derivation key: sha256:27d7cc9e477a8b74c24b4c905ac9e49433d464e01d1e1825b4ddaefbc0dfea99
# Text hash: sha256:289a06a9f24dd74bfa3700eab322abf4713affd88b738ecb65578e3c776405c8
#
# CAMSHAFT-2, follower and cam angle (thesis (5.15)-(5.19))
# Source hash: sha256:ba85420c7d793b48841104cb2caceda457d7114297efae4aa828a6d651b0c422
#
# CAMSHAFT-2: follower and cam angle, thesis ch. 5, figs 5.1-5.3.
#
# The cam is a degree of freedom: it turns with the angle B = beta/beta_m,
# driven through the flexible shaft from the input, which turns at constant
# speed (B = T nominally).  Dimensionless equations (5.15)-(5.18):
#
#     X'' = (2 pi/tau)^2 (H(B) - X),
#     B'' = (2 pi/tau_b)^2 (T - B) - Fv X'' dH/dB,     B(0) = 0, B'(0) = 1,
#
# with the flywheel factor Fv = m_x h_m^2/(J beta_m^2) (5.14) and the shaft
# stiffness factor Fa = c_x h_m^2/(k beta_m^2) (5.12b).  Reading taken: (5.19)
# is illegible; from T_eb = 2 pi sqrt(J/k), tau_b^2 = tau^2 Fa/Fv.
#
# Derived from energies, the Lagrangian divided by m_x h_m'^2/t_m^2:
#
#     kinetic energy     1/2 X'^2 + 1/(2 Fv) B'^2
#     potential energy   1/2 (2 pi/tau)^2 [(H(B) - X)^2 + (T - B)^2/Fa]
#
# The cam input H(B) depends on a state, so its breakpoints (B = 0, 1) are
# located as events.  Fv -> 0 is the constant-speed model of ch. 3, Fv -> oo
# CAMSHAFT-1 (up to assumption (4.8)).

import json

from cpython.pycapsule cimport PyCapsule_New

from camdyn.runtime.engine.abi cimport *
from camdyn.generated.camlaws cimport (camlaw_dwell, camlaw_dwell_value, camlaw_eval, camlaw_hi,
                                       camlaw_lo, camlaw_segment)

# sizes, known when the integration loops (loops.pxi) are compiled into this module
cdef enum:
    _NQ = 2                  # second-order coordinates
    _NS = 4                  # states: q, q', first-order states
    _NCAM = 1                # cam input instances (one segment mode each)
    _NM = 1                  # modes: cam segments, then the force elements' modes
    _NE = 2                  # events
    _NQ1 = 2                 # array sizes that must not be zero
    _NE1 = 2
    _JAC_SYMBOLIC = 1           # jacobian() is derived symbolically: the implicit loops use it
    _FT_SYMBOLIC = 1            # jacobian() also gives df/dt
    _PROJECTS = 0               # no constraints: nothing to project after a step (project())

cdef int _EDIR[_NE1]    # crossing direction of each event: +1 upward, -1 downward
_EDIR[0] = 1  # cam0_hi
_EDIR[1] = -1  # cam0_lo



cdef void prepare(Ctx* ctx) noexcept nogil:
    """Parameter-only subexpressions, once per run, into ctx.k."""
    cdef double tau = ctx.p[0]
    cdef double Fa = ctx.p[1]
    cdef double Fv = ctx.p[2]
    cdef double _c0 = 39.47841760435743*(1.0/(tau*tau))
    cdef double _c1 = Fv*_c0
    cdef double _c2 = _c1/Fa
    ctx.k[0] = _c0  # _k0
    ctx.k[1] = _c2  # _k1
    ctx.k[2] = -_c0  # _k2
    ctx.k[3] = _c1  # _k3
    ctx.k[4] = -_c1  # _k4
    ctx.k[5] = -_c2  # _k5


cdef inline void rhs(double t, const double* _y, double* _dy, Ctx* ctx) noexcept nogil:
    """dy/dt: q', q'' from M q'' = f, and the rates of the first-order states; specialised for cam inputs in a dwell."""
    cdef double tau = ctx.p[0]
    cdef double Fa = ctx.p[1]
    cdef double Fv = ctx.p[2]
    cdef double _k0 = ctx.k[0]
    cdef double _k1 = ctx.k[1]
    cdef double _k2 = ctx.k[2]
    cdef double _k3 = ctx.k[3]
    cdef double _k4 = ctx.k[4]
    cdef double _k5 = ctx.k[5]
    cdef double X = _y[0]
    cdef double B = _y[1]
    cdef double Xd = _y[2]
    cdef double Bd = _y[3]
    cdef double _cam0[4]  # H(B) and its derivatives
    cdef int _v = ctx.variant
    cdef double* _c
    cdef double _a
    if _v & 1:
        _cam0[0] = ctx.cache[1]  # H in the dwell, set by refresh()
    else:
        # the stages of a step share arguments (RK4: t + h/2 twice, t + h for the next
        # k1): the last evaluation is kept in ctx.cache and reused
        _a = B
        _c = &ctx.cache[0]
        if _a == _c[0]:
            _cam0[0], _cam0[1], _cam0[2], _cam0[3] = _c[1], _c[2], _c[3], _c[4]
        else:
            camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], _a, _cam0)
            _c[0], _c[1], _c[2], _c[3], _c[4] = _a, _cam0[0], _cam0[1], _cam0[2], _cam0[3]

    cdef double _s0_0
    _dy[0] = Xd
    _dy[1] = Bd
    if _v == 0:
        _s0_0 = X - _cam0[0]
        _dy[2] = -_k0*_s0_0
        _dy[3] = _k1*(-B + Fa*_cam0[1]*_s0_0 + t)
    elif _v == 1:  # in a dwell: 0
        _dy[2] = -_k0*(X - _cam0[0])
        _dy[3] = -_k1*(B - t)


cdef void outputs(double t, const double* _y, double* _out, Ctx* ctx) noexcept nogil:
    """The named outputs (Xdd, U, Bdd, Bdot_dev, windup, H, Hd)."""
    cdef double _dy[4]
    rhs(t, _y, _dy, ctx)
    cdef double tau = ctx.p[0]
    cdef double Fa = ctx.p[1]
    cdef double Fv = ctx.p[2]
    cdef double _k0 = ctx.k[0]
    cdef double _k1 = ctx.k[1]
    cdef double _k2 = ctx.k[2]
    cdef double _k3 = ctx.k[3]
    cdef double _k4 = ctx.k[4]
    cdef double _k5 = ctx.k[5]
    cdef double X = _y[0]
    cdef double B = _y[1]
    cdef double Xd = _y[2]
    cdef double Bd = _y[3]
    cdef double Xdd = _dy[2]
    cdef double Bdd = _dy[3]
    cdef double _cam0[4]  # H(B) and its derivatives
    cdef double* _c
    # rhs() has just evaluated this input at the same argument and kept it (outside a dwell)
    _c = &ctx.cache[0]
    if _c[0] == B:
        _cam0[0], _cam0[1], _cam0[2], _cam0[3] = _c[1], _c[2], _c[3], _c[4]
    else:
        camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], B, _cam0)

    _out[0] = _dy[2]  # Xdd
    _out[1] = X - _cam0[0]  # U
    _out[2] = _dy[3]  # Bdd
    _out[3] = Bd - 1.0  # Bdot_dev
    _out[4] = -B + t  # windup
    _out[5] = _cam0[0]  # H
    _out[6] = _cam0[1]  # Hd


cdef void mass_stiffness(double t, const double* _y, double* _Mm, double* _Km, Ctx* ctx) noexcept nogil:
    """Mass matrix M and stiffness K = -df/dq (row-major, n x n) at (t, y), for frozen analyses."""
    cdef double tau = ctx.p[0]
    cdef double Fa = ctx.p[1]
    cdef double Fv = ctx.p[2]
    cdef double _k0 = ctx.k[0]
    cdef double _k1 = ctx.k[1]
    cdef double _k2 = ctx.k[2]
    cdef double _k3 = ctx.k[3]
    cdef double _k4 = ctx.k[4]
    cdef double _k5 = ctx.k[5]
    cdef double X = _y[0]
    cdef double B = _y[1]
    cdef double Xd = _y[2]
    cdef double Bd = _y[3]
    cdef double _cam0[4]  # H(B) and its derivatives
    camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], B, _cam0)

    cdef double _m0 = 39.47841760435743*(1.0/(tau*tau))
    cdef double _m1 = -_cam0[1]*_m0
    _Mm[0] = 1.0
    _Mm[1] = 0.0
    _Mm[2] = 0.0
    _Mm[3] = (1.0/(Fv))
    _Km[0] = _m0
    _Km[1] = _m1
    _Km[2] = _m1
    _Km[3] = _m0*(Fa*(_cam0[1]*_cam0[1]) - Fa*_cam0[2]*(X - _cam0[0]) + 1.0)/Fa


cdef void jacobian(double t, const double* _y, double* _J, double* _ft, Ctx* ctx) noexcept nogil:
    """d(dy/dt)/dy at (t, y), row-major _NS x _NS, derived symbolically (CSE'd): the Jacobian
    of the general right-hand side in the current modes, a cam input in a dwell taking its
    dwell values.
    With _ft not NULL also df/dt there (_NS values), derived the same way."""
    cdef double tau = ctx.p[0]
    cdef double Fa = ctx.p[1]
    cdef double Fv = ctx.p[2]
    cdef double _k0 = ctx.k[0]
    cdef double _k1 = ctx.k[1]
    cdef double _k2 = ctx.k[2]
    cdef double _k3 = ctx.k[3]
    cdef double _k4 = ctx.k[4]
    cdef double _k5 = ctx.k[5]
    cdef double X = _y[0]
    cdef double B = _y[1]
    cdef double Xd = _y[2]
    cdef double Bd = _y[3]
    cdef double _cam0[4]  # H(B) and its derivatives
    camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], B, _cam0)

    cdef int _k
    cdef double _ftl[4]
    for _k in range(16):
        _J[_k] = 0.0
    for _k in range(4):
        _ftl[_k] = 0.0
    for _k in range(2):
        _J[_k * 5 + 2] = 1.0  # d q'/d q'
    _J[8] = _k2
    _J[9] = _cam0[1]*_k0
    _J[12] = _cam0[1]*_k3
    _J[13] = (_cam0[1]*_cam0[1])*_k4 + _cam0[2]*_k3*(X - _cam0[0]) + _k5
    _ftl[3] = _k1
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
    loops may step over the interval exactly (derive/codegen.py, _linear_in_dwell): never."""
    return False


cdef void update_modes(double t, const double* _y, Ctx* ctx) noexcept nogil:
    """Segment of every cam input at (t, y); the force elements keep their modes."""
    cdef double tau = ctx.p[0]
    cdef double Fa = ctx.p[1]
    cdef double Fv = ctx.p[2]
    cdef double _k0 = ctx.k[0]
    cdef double _k1 = ctx.k[1]
    cdef double _k2 = ctx.k[2]
    cdef double _k3 = ctx.k[3]
    cdef double _k4 = ctx.k[4]
    cdef double _k5 = ctx.k[5]
    cdef double X = _y[0]
    cdef double B = _y[1]
    cdef double Xd = _y[2]
    cdef double Bd = _y[3]

    ctx.mode[0] = camlaw_segment(ctx.law[0], ctx.law_par[0], B)
    refresh(ctx)


cdef void events(double t, const double* _y, double* _g, Ctx* ctx) noexcept nogil:
    """Event functions; an event not armed in the current modes reads 1 (never crosses)."""
    cdef double tau = ctx.p[0]
    cdef double Fa = ctx.p[1]
    cdef double Fv = ctx.p[2]
    cdef double _k0 = ctx.k[0]
    cdef double _k1 = ctx.k[1]
    cdef double _k2 = ctx.k[2]
    cdef double _k3 = ctx.k[3]
    cdef double _k4 = ctx.k[4]
    cdef double _k5 = ctx.k[5]
    cdef double X = _y[0]
    cdef double B = _y[1]
    cdef double Xd = _y[2]
    cdef double Bd = _y[3]
    cdef double _cam0[4]  # H(B) and its derivatives
    camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], B, _cam0)

    _g[0] = (B) - camlaw_hi(ctx.law[0], ctx.law_par[0], ctx.mode[0])  # cam0_hi: next segment
    _g[1] = (B) - camlaw_lo(ctx.law[0], ctx.law_par[0], ctx.mode[0])  # cam0_lo: previous segment


cdef void on_event(int _e, double t, double* _y, Ctx* ctx) noexcept nogil:
    """What event k does: new modes (and state resets) at its crossing."""
    cdef double tau = ctx.p[0]
    cdef double Fa = ctx.p[1]
    cdef double Fv = ctx.p[2]
    cdef double _k0 = ctx.k[0]
    cdef double _k1 = ctx.k[1]
    cdef double _k2 = ctx.k[2]
    cdef double _k3 = ctx.k[3]
    cdef double _k4 = ctx.k[4]
    cdef double _k5 = ctx.k[5]
    cdef double X = _y[0]
    cdef double B = _y[1]
    cdef double Xd = _y[2]
    cdef double Bd = _y[3]
    cdef double _cam0[4]  # H(B) and its derivatives
    camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], B, _cam0)

    if _e == 0:  # cam0_hi
        ctx.mode[0] += 1
    elif _e == 1:  # cam0_lo
        ctx.mode[0] += -1
    refresh(ctx)


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
    cdef double Fa = p[1]
    cdef double Fv = p[2]
    return [0.0, 0.0, 0.0, 1.0]


def cam_time_affine(p):
    """Per cam input, (a, b) with argument a t + b, or None when it depends on the state."""
    cdef double tau = p[0]
    cdef double Fa = p[1]
    cdef double Fv = p[2]
    return [None]


cdef ModelC _model
_model.abi_version = CAMDYN_ABI
_model.n_q = _NQ
_model.n_states = _NS
_model.n_params = 3
_model.n_outputs = 7
_model.n_families = 1
_model.n_instances = _NCAM
_model.n_modes = _NM
_model.n_events = _NE
_model.n_const = 6
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
   "argument": "B",
   "family": "H",
   "order": 2,
   "time_affine": false
  }
 ],
 "events": [
  "cam0_hi",
  "cam0_lo"
 ],
 "jacobian": "symbolic",
 "modes": [],
 "n_q": 2,
 "name": "camshaft2",
 "options": [],
 "outputs": [
  {
   "doc": "follower acceleration X''",
   "name": "Xdd",
   "unit": "h_m'/t_m^2"
  },
  {
   "doc": "positional error X - H(B)",
   "name": "U",
   "unit": "h_m'"
  },
  {
   "doc": "cam angular acceleration B''",
   "name": "Bdd",
   "unit": "beta_m/t_m^2"
  },
  {
   "doc": "variation of the cam's angular velocity B' - 1",
   "name": "Bdot_dev",
   "unit": "1"
  },
  {
   "doc": "shaft wind-up T - B",
   "name": "windup",
   "unit": "beta_m"
  },
  {
   "doc": "nominal displacement at the cam angle",
   "name": "H",
   "unit": "h_m'"
  },
  {
   "doc": "cam slope dH/dB",
   "name": "Hd",
   "unit": "h_m'/beta_m"
  }
 ],
 "parameters": [
  {
   "default": 0.16,
   "doc": "T_ex/t_m of the follower at zero slope (5.7), (5.9)",
   "high": 10.0,
   "low": 0.0,
   "name": "tau",
   "open_high": false,
   "open_low": true,
   "range": "0 < tau <= 10",
   "unit": "1"
  },
  {
   "default": 1.5,
   "doc": "shaft stiffness factor c_x h_m^2/(k beta_m^2) (5.12b)",
   "high": 100.0,
   "low": 0.0,
   "name": "Fa",
   "open_high": false,
   "open_low": true,
   "range": "0 < Fa <= 100",
   "unit": "1"
  },
  {
   "default": 10.0,
   "doc": "flywheel factor m_x h_m^2/(J beta_m^2) (5.14)",
   "high": 1000000.0,
   "low": 0.0,
   "name": "Fv",
   "open_high": false,
   "open_low": true,
   "range": "0 < Fv <= 1e+06",
   "unit": "1"
  }
 ],
 "reference": "thesis (5.15)-(5.19)",
 "residual": {
  "acceleration": "Xdd",
  "error": "U",
  "rise_end": 1.0,
  "rise_state": "B"
 },
 "source_hash": "sha256:ba85420c7d793b48841104cb2caceda457d7114297efae4aa828a6d651b0c422",
 "states": [
  {
   "doc": "follower position over the stroke, X = x/h_m'",
   "initial": 0.0,
   "name": "X",
   "scale": 1.0,
   "unit": "h_m'"
  },
  {
   "doc": "cam angle over the rise angle, B = beta/beta_m",
   "initial": 0.0,
   "name": "B",
   "scale": 1.0,
   "unit": "beta_m"
  },
  {
   "doc": "rate of X",
   "initial": 0.0,
   "name": "Xd",
   "scale": 1.0,
   "unit": "h_m'/t_m"
  },
  {
   "doc": "rate of B",
   "initial": 1.0,
   "name": "Bd",
   "scale": 1.0,
   "unit": "beta_m/t_m"
  }
 ],
 "time": {
  "name": "T",
  "unit": "t_m"
 },
 "time_derivative": "symbolic",
 "title": "CAMSHAFT-2, follower and cam angle"
}
"""
MANIFEST = json.loads(_MANIFEST_JSON)
"""States, parameters (defaults, units, ranges), outputs, cam inputs, modes, events, source hash."""

# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True, initializedcheck=False
#
# GENERATED FILE - DO NOT EDIT.  Written by `camdyn derive` from camdyn/derive/models/one_dof.py;
# edit that and regenerate.  `camdyn derive --check` fails while this file is stale.
# Derivation key: sha256:0bb5d5cf8a8a48dcbdb8dc5f6f56d5241af67877c1a6e656972089da9b4a68af
# Text hash: sha256:449fcbfeb2dd64d561db06958d37cf25b3cfb72bf32332a5ac72f532c4d3a62a
#
# One DOF, constant fictitious angular velocity (thesis (3.1)-(3.7), fig. 3.2)
# Source hash: sha256:7be31bd6aed90cb3c3dd785c585a5abdada86ed4b0a88d608d7b6508231d5b38
#
# One DOF with constant fictitious angular velocity, thesis ch. 3, fig. 3.2.
#
# Equation of motion (3.1), m x'' + c x = c h'(t), in the dimensionless form of
# sec. 3.3 (T = t/t_m, X = x/h_m', H = h'/h_m', tau = T_e/t_m (3.3)):
#
#     X'' = (2 pi/tau)^2 (H - X).
#
# It is derived from energies, the Lagrangian divided by m h_m'^2/t_m^2:
#
#     kinetic energy     1/2 X'^2
#     potential energy   1/2 (2 pi/tau)^2 (H - X)^2      spring c between cam and mass
#     dissipation        q (2 pi/tau) (X' - H')^2         d = 2 q sqrt(m c) (6.47)
#
# Reading taken: the damper acts in parallel with the spring (on X' - H'), as
# the linkage's own damping does; during the dwell H' = 0 and it is the plain
# viscous damper of the decay law (3.7).  q = 0 (the default) is the undamped
# model of (3.4)-(3.6).

import json

from cpython.pycapsule cimport PyCapsule_New

from camdyn.runtime.engine.abi cimport *
from camdyn.generated.camlaws cimport (camlaw_dwell, camlaw_dwell_value, camlaw_eval, camlaw_hi,
                                       camlaw_lo, camlaw_segment)

# sizes, known when the integration loops (loops.pxi) are compiled into this module
cdef enum:
    _NQ = 1                  # second-order coordinates
    _NS = 2                  # states: q, q', first-order states
    _NCAM = 1                # cam input instances (one segment mode each)
    _NM = 1                  # modes: cam segments, then the force elements' modes
    _NE = 0                  # events
    _NQ1 = 1                 # array sizes that must not be zero
    _NE1 = 1
    _JAC_SYMBOLIC = 1           # jacobian() is derived symbolically: the implicit loops use it
    _FT_SYMBOLIC = 1            # jacobian() also gives df/dt
    _PROJECTS = 0               # no constraints: nothing to project after a step (project())

cdef int _EDIR[_NE1]    # crossing direction of each event: +1 upward, -1 downward



cdef void prepare(Ctx* ctx) noexcept nogil:
    """Parameter-only subexpressions, once per run, into ctx.k."""
    cdef double tau = ctx.p[0]
    cdef double q = ctx.p[1]
    cdef double _c0 = 39.47841760435743*(1.0/(tau*tau))
    cdef double _c1 = 12.566370614359172*q/tau
    ctx.k[0] = _c0  # _k0
    ctx.k[1] = _c1  # _k1
    ctx.k[2] = -_c1  # _k2
    ctx.k[3] = -_c0  # _k3


cdef inline void rhs(double t, const double* _y, double* _dy, Ctx* ctx) noexcept nogil:
    """dy/dt: q', q'' from M q'' = f, and the rates of the first-order states; specialised for cam inputs in a dwell."""
    cdef double tau = ctx.p[0]
    cdef double q = ctx.p[1]
    cdef double _k0 = ctx.k[0]
    cdef double _k1 = ctx.k[1]
    cdef double _k2 = ctx.k[2]
    cdef double _k3 = ctx.k[3]
    cdef double X = _y[0]
    cdef double Xd = _y[1]
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

    _dy[0] = Xd
    if _v == 0:
        _dy[1] = -_k0*(X - _cam0[0]) - _k1*(Xd - _cam0[1])
    elif _v == 1:  # in a dwell: 0
        _dy[1] = Xd*_k2 - _k0*(X - _cam0[0])


cdef void outputs(double t, const double* _y, double* _out, Ctx* ctx) noexcept nogil:
    """The named outputs (Xdd, U, H, Hd, Hdd)."""
    cdef double _dy[2]
    rhs(t, _y, _dy, ctx)
    cdef double tau = ctx.p[0]
    cdef double q = ctx.p[1]
    cdef double _k0 = ctx.k[0]
    cdef double _k1 = ctx.k[1]
    cdef double _k2 = ctx.k[2]
    cdef double _k3 = ctx.k[3]
    cdef double X = _y[0]
    cdef double Xd = _y[1]
    cdef double Xdd = _dy[1]
    cdef double _cam0[4]  # H(T) and its derivatives
    cdef double* _c
    # rhs() has just evaluated this input at the same argument and kept it (outside a dwell)
    _c = &ctx.cache[0]
    if _c[0] == t:
        _cam0[0], _cam0[1], _cam0[2], _cam0[3] = _c[1], _c[2], _c[3], _c[4]
    else:
        camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], t, _cam0)

    _out[0] = _dy[1]  # Xdd
    _out[1] = X - _cam0[0]  # U
    _out[2] = _cam0[0]  # H
    _out[3] = _cam0[1]  # Hd
    _out[4] = _cam0[2]  # Hdd


cdef void mass_stiffness(double t, const double* _y, double* _Mm, double* _Km, Ctx* ctx) noexcept nogil:
    """Mass matrix M and stiffness K = -df/dq (row-major, n x n) at (t, y), for frozen analyses."""
    cdef double tau = ctx.p[0]
    cdef double q = ctx.p[1]
    cdef double _k0 = ctx.k[0]
    cdef double _k1 = ctx.k[1]
    cdef double _k2 = ctx.k[2]
    cdef double _k3 = ctx.k[3]
    cdef double X = _y[0]
    cdef double Xd = _y[1]
    cdef double _cam0[4]  # H(T) and its derivatives
    camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], t, _cam0)

    _Mm[0] = 1.0
    _Km[0] = 39.47841760435743*(1.0/(tau*tau))


cdef void jacobian(double t, const double* _y, double* _J, double* _ft, Ctx* ctx) noexcept nogil:
    """d(dy/dt)/dy at (t, y), row-major _NS x _NS, derived symbolically (CSE'd): the Jacobian
    of the general right-hand side in the current modes, a cam input in a dwell taking its
    dwell values.
    With _ft not NULL also df/dt there (_NS values), derived the same way."""
    cdef double tau = ctx.p[0]
    cdef double q = ctx.p[1]
    cdef double _k0 = ctx.k[0]
    cdef double _k1 = ctx.k[1]
    cdef double _k2 = ctx.k[2]
    cdef double _k3 = ctx.k[3]
    cdef double X = _y[0]
    cdef double Xd = _y[1]
    cdef double _cam0[4]  # H(T) and its derivatives
    camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], t, _cam0)

    cdef int _k
    cdef double _ftl[2]
    for _k in range(4):
        _J[_k] = 0.0
    for _k in range(2):
        _ftl[_k] = 0.0
    for _k in range(1):
        _J[_k * 3 + 1] = 1.0  # d q'/d q'
    _J[2] = _k3
    _J[3] = _k2
    _ftl[1] = _cam0[1]*_k0 + _cam0[2]*_k1
    if _ft != NULL:
        for _k in range(2):
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
    cdef double _k0 = ctx.k[0]
    cdef double _k1 = ctx.k[1]
    cdef double _k2 = ctx.k[2]
    cdef double _k3 = ctx.k[3]
    cdef double X = _y[0]
    cdef double Xd = _y[1]

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
    return [0.0, 0.0]


def cam_time_affine(p):
    """Per cam input, (a, b) with argument a t + b, or None when it depends on the state."""
    cdef double tau = p[0]
    cdef double q = p[1]
    return [(1.0, 0.0)]


cdef ModelC _model
_model.abi_version = CAMDYN_ABI
_model.n_q = _NQ
_model.n_states = _NS
_model.n_params = 2
_model.n_outputs = 5
_model.n_families = 1
_model.n_instances = _NCAM
_model.n_modes = _NM
_model.n_events = _NE
_model.n_const = 4
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
   "order": 2,
   "time_affine": true
  }
 ],
 "events": [],
 "jacobian": "symbolic",
 "modes": [],
 "n_q": 1,
 "name": "one_dof",
 "options": [],
 "outputs": [
  {
   "doc": "follower acceleration X''",
   "name": "Xdd",
   "unit": "h_m'/t_m^2"
  },
  {
   "doc": "positional error u/h_m' = X - H (3.4)",
   "name": "U",
   "unit": "h_m'"
  },
  {
   "doc": "nominal displacement (cam law)",
   "name": "H",
   "unit": "h_m'"
  },
  {
   "doc": "nominal velocity H'",
   "name": "Hd",
   "unit": "h_m'/t_m"
  },
  {
   "doc": "nominal acceleration H''",
   "name": "Hdd",
   "unit": "h_m'/t_m^2"
  }
 ],
 "parameters": [
  {
   "default": 0.15,
   "doc": "period of natural vibration over cam rise time, T_e/t_m (3.3)",
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
   "doc": "relative damping, d = 2 q sqrt(m c) (6.47)",
   "high": 1.0,
   "low": 0.0,
   "name": "q",
   "open_high": true,
   "open_low": false,
   "range": "0 <= q < 1",
   "unit": "1"
  }
 ],
 "reference": "thesis (3.1)-(3.7), fig. 3.2",
 "residual": {
  "acceleration": "Xdd",
  "error": "U",
  "rise_end": 1.0,
  "rise_state": ""
 },
 "source_hash": "sha256:7be31bd6aed90cb3c3dd785c585a5abdada86ed4b0a88d608d7b6508231d5b38",
 "states": [
  {
   "doc": "follower position over the stroke, X = x/h_m'",
   "initial": 0.0,
   "name": "X",
   "scale": 1.0,
   "unit": "h_m'"
  },
  {
   "doc": "rate of X",
   "initial": 0.0,
   "name": "Xd",
   "scale": 1.0,
   "unit": "h_m'/t_m"
  }
 ],
 "time": {
  "name": "T",
  "unit": "t_m"
 },
 "time_derivative": "symbolic",
 "title": "One DOF, constant fictitious angular velocity"
}
"""
MANIFEST = json.loads(_MANIFEST_JSON)
"""States, parameters (defaults, units, ranges), outputs, cam inputs, modes, events, source hash."""

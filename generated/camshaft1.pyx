# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True, initializedcheck=False
#
# GENERATED FILE - DO NOT EDIT.  Written by `camdyn derive` from camdyn/derive/models/camshaft1.py;
# edit that and regenerate.  `camdyn derive --check` fails while this file is stale.
# Derivation key: sha256:e799c175dceebebc6d4efbf9b4794ac51116b0a373eb25bbc0494d44af79e93f
# Text hash: sha256:b8989cc2c3389c2cf3059db74cf0df70636963716cbe35570f8a49daee82a519
#
# CAMSHAFT-1, one DOF with variable fictitious angular velocity (thesis (4.15)-(4.18))
# Source hash: sha256:0967543da0f352acab2824c9a32218d1be61c185b8c772967bbcece4be157c13
#
# CAMSHAFT-1: one DOF with variable fictitious angular velocity, thesis ch. 4.
#
# Equation of motion (4.15)-(4.17), dimensionless (sec. 4.3.2):
#
#     X'' = (2 pi/tau)^2 (H - X) / (1 + H'^2 Fa),   H = H(T), H' = dH/dT.
#
# Derived from energies: the shaft's tangential flexibility puts the stiffness
# c_tan in series with the constant part c_c through the slope tan(alpha)
# (4.2)-(4.5), so the overall stiffness is c = c_c/(1 + H'^2 Fa) (4.18) with
# the shaft stiffness factor Fa = (c_c/c_tan) tan^2(alpha_me) (4.14), under the
# thesis's assumption dh'/dbeta = h'/w_s (4.8) and the constant pitch radius
# (4.1).  Divided by m h_m'^2/t_m^2 the energies are
#
#     kinetic energy     1/2 X'^2
#     potential energy   1/2 c(T) (H - X)^2,   c(T) = (2 pi/tau)^2/(1 + H'^2 Fa)
#
# and there is no damping (sec. 4.2.4: ignored during the rise, as in ch. 3).
# c depends on T only, so Lagrange's equations give (4.15) exactly.  At Fa = 0
# the model is the one-DOF model of ch. 3; the stiffness dip is 1 + 4 Fa (4.19)
# for the cycloid.

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
    cdef double Fa = ctx.p[1]
    cdef double _c0 = 9.869604401089358*(1.0/(tau*tau))
    cdef double _c1 = 4.0*_c0
    ctx.k[0] = _c1  # _k0
    ctx.k[1] = -_c1  # _k1
    ctx.k[2] = -8.0*Fa*_c0  # _k2


cdef inline void rhs(double t, const double* _y, double* _dy, Ctx* ctx) noexcept nogil:
    """dy/dt: q', q'' from M q'' = f, and the rates of the first-order states; specialised for cam inputs in a dwell."""
    cdef double tau = ctx.p[0]
    cdef double Fa = ctx.p[1]
    cdef double _k0 = ctx.k[0]
    cdef double _k1 = ctx.k[1]
    cdef double _k2 = ctx.k[2]
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
        _dy[1] = -_k0*(X - _cam0[0])/(Fa*(_cam0[1]*_cam0[1]) + 1.0)
    elif _v == 1:  # in a dwell: 0
        _dy[1] = -_k0*(X - _cam0[0])


cdef void outputs(double t, const double* _y, double* _out, Ctx* ctx) noexcept nogil:
    """The named outputs (Xdd, U, H, Hd, Hdd, c_rel)."""
    cdef double _dy[2]
    rhs(t, _y, _dy, ctx)
    cdef double tau = ctx.p[0]
    cdef double Fa = ctx.p[1]
    cdef double _k0 = ctx.k[0]
    cdef double _k1 = ctx.k[1]
    cdef double _k2 = ctx.k[2]
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
    _out[5] = (1.0/(Fa*(_cam0[1]*_cam0[1]) + 1.0))  # c_rel


cdef void mass_stiffness(double t, const double* _y, double* _Mm, double* _Km, Ctx* ctx) noexcept nogil:
    """Mass matrix M and stiffness K = -df/dq (row-major, n x n) at (t, y), for frozen analyses."""
    cdef double tau = ctx.p[0]
    cdef double Fa = ctx.p[1]
    cdef double _k0 = ctx.k[0]
    cdef double _k1 = ctx.k[1]
    cdef double _k2 = ctx.k[2]
    cdef double X = _y[0]
    cdef double Xd = _y[1]
    cdef double _cam0[4]  # H(T) and its derivatives
    camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], t, _cam0)

    _Mm[0] = 1.0
    _Km[0] = 39.47841760435743*1.0/((tau*tau)*(Fa*(_cam0[1]*_cam0[1]) + 1.0))


cdef void jacobian(double t, const double* _y, double* _J, double* _ft, Ctx* ctx) noexcept nogil:
    """d(dy/dt)/dy at (t, y), row-major _NS x _NS, derived symbolically (CSE'd): the Jacobian
    of the general right-hand side in the current modes, a cam input in a dwell taking its
    dwell values.
    With _ft not NULL also df/dt there (_NS values), derived the same way."""
    cdef double tau = ctx.p[0]
    cdef double Fa = ctx.p[1]
    cdef double _k0 = ctx.k[0]
    cdef double _k1 = ctx.k[1]
    cdef double _k2 = ctx.k[2]
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
    cdef double _j0 = (1.0/(Fa*(_cam0[1]*_cam0[1]) + 1.0))
    _J[2] = _j0*_k1
    _ftl[1] = _cam0[1]*_j0*(-_cam0[2]*_j0*_k2*(X - _cam0[0]) + _k0)
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
    cdef double Fa = ctx.p[1]
    cdef double _k0 = ctx.k[0]
    cdef double _k1 = ctx.k[1]
    cdef double _k2 = ctx.k[2]
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
    cdef double Fa = p[1]
    return [0.0, 0.0]


def cam_time_affine(p):
    """Per cam input, (a, b) with argument a t + b, or None when it depends on the state."""
    cdef double tau = p[0]
    cdef double Fa = p[1]
    return [(1.0, 0.0)]


cdef ModelC _model
_model.abi_version = CAMDYN_ABI
_model.n_q = _NQ
_model.n_states = _NS
_model.n_params = 2
_model.n_outputs = 6
_model.n_families = 1
_model.n_instances = _NCAM
_model.n_modes = _NM
_model.n_events = _NE
_model.n_const = 3
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
 "name": "camshaft1",
 "options": [],
 "outputs": [
  {
   "doc": "follower acceleration X''",
   "name": "Xdd",
   "unit": "h_m'/t_m^2"
  },
  {
   "doc": "positional error X - H",
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
  },
  {
   "doc": "overall stiffness over its maximum, c/c_c (4.18)",
   "name": "c_rel",
   "unit": "c_c"
  }
 ],
 "parameters": [
  {
   "default": 0.15,
   "doc": "T_e/t_m at zero slope (4.11), (4.12)",
   "high": 10.0,
   "low": 0.0,
   "name": "tau",
   "open_high": false,
   "open_low": true,
   "range": "0 < tau <= 10",
   "unit": "1"
  },
  {
   "default": 2.0,
   "doc": "shaft stiffness factor (c_c/c_tan) tan^2 alpha_me (4.14)",
   "high": 100.0,
   "low": 0.0,
   "name": "Fa",
   "open_high": false,
   "open_low": false,
   "range": "0 <= Fa <= 100",
   "unit": "1"
  }
 ],
 "reference": "thesis (4.15)-(4.18)",
 "residual": {
  "acceleration": "Xdd",
  "error": "U",
  "rise_end": 1.0,
  "rise_state": ""
 },
 "source_hash": "sha256:0967543da0f352acab2824c9a32218d1be61c185b8c772967bbcece4be157c13",
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
 "title": "CAMSHAFT-1, one DOF with variable fictitious angular velocity"
}
"""
MANIFEST = json.loads(_MANIFEST_JSON)
"""States, parameters (defaults, units, ranges), outputs, cam inputs, modes, events, source hash."""

# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True, initializedcheck=False
#
# GENERATED FILE - DO NOT EDIT.  Written by `camdyn derive` from camdyn/derive/models/motor.py;
# edit that and regenerate.  `camdyn derive --check` fails while this file is stale.
# Derivation key: sha256:d8a357eafd8fc0a0a4f21b243b756e8da6f27f6adff0639756d249c37a70df0c
# Text hash: sha256:3b9d59b44052bc11abd6416896262b10d1e9d0fce11aa60c0b6bcf13a571bb4a
#
# Asynchronous motor, first order (no electrical lag) (thesis sec. A.5.4.2)
# Source hash: sha256:5315b62110449092ed4fbe9bea35b87a6d10bad4792d9ef82b7feb5db7eda537
#
# The asynchronous motor driving a cam mechanism, thesis App. 5 (and sec. 6.7).
#
# Reduced to the camshaft (fig. A.5.2), the speed deviation dw = w - w_s of the
# drive obeys the equation of motion
#
#     J_ma dw' = M_ea - M_load                                     (A.5.7)
#
# and the electromagnetic torque lags behind its static value -G_a dw with the
# electrical time constant T_el (first-order transfer function (A.5.2), (A.5.6)):
#
#     T_el M_ea' = -G_a dw - M_ea                                  (A.5.6)
#
# With T_m = J_ma/G_a (A.5.11) this is the second-order system (A.5.13); with
# T_el -> 0, M_ea = -G_a dw and the first-order model of sec. A.5.4.2.  The load
# is the driving torque of the nominal cam motion, M_load = Mc H'(T) H''(T),
# T = t/t_m, Mc = m h_m'^2/(w_s t_m^3) (A.2.7), as in the analytic solutions
# (A.5.15)-(A.5.33).  Both are first-order states only (no Lagrangian
# coordinate).

import json

from cpython.pycapsule cimport PyCapsule_New

from camdyn.runtime.engine.abi cimport *
from camdyn.generated.camlaws cimport (camlaw_dwell, camlaw_dwell_value, camlaw_eval, camlaw_hi,
                                       camlaw_lo, camlaw_segment)

# sizes, known when the integration loops (loops.pxi) are compiled into this module
cdef enum:
    _NQ = 0                  # second-order coordinates
    _NS = 1                  # states: q, q', first-order states
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
    cdef double J_ma = ctx.p[0]
    cdef double G_a = ctx.p[1]
    cdef double t_m = ctx.p[2]
    cdef double Mc = ctx.p[3]
    cdef double _c0 = (1.0/(J_ma))
    cdef double _c1 = Mc*_c0
    ctx.k[0] = -G_a*_c0  # _k0
    ctx.k[1] = -_c1  # _k1
    ctx.k[2] = -_c1/t_m  # _k2


cdef inline void rhs(double t, const double* _y, double* _dy, Ctx* ctx) noexcept nogil:
    """dy/dt: q', q'' from M q'' = f, and the rates of the first-order states; specialised for cam inputs in a dwell."""
    cdef double J_ma = ctx.p[0]
    cdef double G_a = ctx.p[1]
    cdef double t_m = ctx.p[2]
    cdef double Mc = ctx.p[3]
    cdef double _k0 = ctx.k[0]
    cdef double _k1 = ctx.k[1]
    cdef double _k2 = ctx.k[2]
    cdef double dw = _y[0]
    cdef double _cam0[4]  # H(t/t_m) and its derivatives
    cdef int _v = ctx.variant
    cdef double* _c
    cdef double _a
    if _v & 1:
        _cam0[0] = ctx.cache[1]  # H in the dwell, set by refresh()
    else:
        # the stages of a step share arguments (RK4: t + h/2 twice, t + h for the next
        # k1): the last evaluation is kept in ctx.cache and reused
        _a = t/t_m
        _c = &ctx.cache[0]
        if _a == _c[0]:
            _cam0[0], _cam0[1], _cam0[2], _cam0[3] = _c[1], _c[2], _c[3], _c[4]
        else:
            camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], _a, _cam0)
            _c[0], _c[1], _c[2], _c[3], _c[4] = _a, _cam0[0], _cam0[1], _cam0[2], _cam0[3]

    if _v == 0:
        _dy[0] = _cam0[1]*_cam0[2]*_k1 + _k0*dw
    elif _v == 1:  # in a dwell: 0
        _dy[0] = _k0*dw


cdef void outputs(double t, const double* _y, double* _out, Ctx* ctx) noexcept nogil:
    """The named outputs (M_load)."""
    cdef double _dy[1]
    rhs(t, _y, _dy, ctx)
    cdef double J_ma = ctx.p[0]
    cdef double G_a = ctx.p[1]
    cdef double t_m = ctx.p[2]
    cdef double Mc = ctx.p[3]
    cdef double _k0 = ctx.k[0]
    cdef double _k1 = ctx.k[1]
    cdef double _k2 = ctx.k[2]
    cdef double dw = _y[0]
    cdef double _cam0[4]  # H(t/t_m) and its derivatives
    cdef double* _c
    # rhs() has just evaluated this input at the same argument and kept it (outside a dwell)
    _c = &ctx.cache[0]
    if _c[0] == t/t_m:
        _cam0[0], _cam0[1], _cam0[2], _cam0[3] = _c[1], _c[2], _c[3], _c[4]
    else:
        camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], t/t_m, _cam0)

    _out[0] = Mc*_cam0[1]*_cam0[2]  # M_load


cdef void mass_stiffness(double t, const double* _y, double* _Mm, double* _Km, Ctx* ctx) noexcept nogil:
    """Mass matrix M and stiffness K = -df/dq (row-major, n x n) at (t, y), for frozen analyses."""
    cdef double J_ma = ctx.p[0]
    cdef double G_a = ctx.p[1]
    cdef double t_m = ctx.p[2]
    cdef double Mc = ctx.p[3]
    cdef double _k0 = ctx.k[0]
    cdef double _k1 = ctx.k[1]
    cdef double _k2 = ctx.k[2]
    cdef double dw = _y[0]
    cdef double _cam0[4]  # H(t/t_m) and its derivatives
    camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], t/t_m, _cam0)



cdef void jacobian(double t, const double* _y, double* _J, double* _ft, Ctx* ctx) noexcept nogil:
    """d(dy/dt)/dy at (t, y), row-major _NS x _NS, derived symbolically (CSE'd): the Jacobian
    of the general right-hand side in the current modes, a cam input in a dwell taking its
    dwell values.
    With _ft not NULL also df/dt there (_NS values), derived the same way."""
    cdef double J_ma = ctx.p[0]
    cdef double G_a = ctx.p[1]
    cdef double t_m = ctx.p[2]
    cdef double Mc = ctx.p[3]
    cdef double _k0 = ctx.k[0]
    cdef double _k1 = ctx.k[1]
    cdef double _k2 = ctx.k[2]
    cdef double dw = _y[0]
    cdef double _cam0[4]  # H(t/t_m) and its derivatives
    camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], t/t_m, _cam0)

    cdef int _k
    cdef double _ftl[1]
    for _k in range(1):
        _J[_k] = 0.0
    for _k in range(1):
        _ftl[_k] = 0.0
    for _k in range(0):
        _J[_k * 2 + 0] = 1.0  # d q'/d q'
    _J[0] = _k0
    _ftl[0] = _k2*(_cam0[1]*_cam0[3] + (_cam0[2]*_cam0[2]))
    if _ft != NULL:
        for _k in range(1):
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
    cdef double J_ma = ctx.p[0]
    cdef double G_a = ctx.p[1]
    cdef double t_m = ctx.p[2]
    cdef double Mc = ctx.p[3]
    cdef double _k0 = ctx.k[0]
    cdef double _k1 = ctx.k[1]
    cdef double _k2 = ctx.k[2]
    cdef double dw = _y[0]

    ctx.mode[0] = camlaw_segment(ctx.law[0], ctx.law_par[0], t/t_m)
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
    cdef double J_ma = p[0]
    cdef double G_a = p[1]
    cdef double t_m = p[2]
    cdef double Mc = p[3]
    return [0.0]


def cam_time_affine(p):
    """Per cam input, (a, b) with argument a t + b, or None when it depends on the state."""
    cdef double J_ma = p[0]
    cdef double G_a = p[1]
    cdef double t_m = p[2]
    cdef double Mc = p[3]
    return [((1.0/(t_m)), 0.0)]


cdef ModelC _model
_model.abi_version = CAMDYN_ABI
_model.n_q = _NQ
_model.n_states = _NS
_model.n_params = 4
_model.n_outputs = 1
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
   "argument": "t/t_m",
   "family": "H",
   "order": 2,
   "time_affine": true
  }
 ],
 "events": [],
 "jacobian": "symbolic",
 "modes": [],
 "n_q": 0,
 "name": "motor1",
 "options": [],
 "outputs": [
  {
   "doc": "driving torque of the nominal cam motion (A.2.7)",
   "name": "M_load",
   "unit": "N m"
  }
 ],
 "parameters": [
  {
   "default": 0.05,
   "doc": "motor inertia reduced to the camshaft, J_m/i_r^2 (A.5.7)",
   "high": null,
   "low": 0.0,
   "name": "J_ma",
   "open_high": false,
   "open_low": true,
   "range": "0 < J_ma",
   "unit": "kg m^2"
  },
  {
   "default": 5.0,
   "doc": "slope of the linearised torque-speed line, reduced (A.5.4b)",
   "high": null,
   "low": 0.0,
   "name": "G_a",
   "open_high": false,
   "open_low": true,
   "range": "0 < G_a",
   "unit": "N m s/rad"
  },
  {
   "default": 0.1,
   "doc": "cam rise time",
   "high": null,
   "low": 0.0,
   "name": "t_m",
   "open_high": false,
   "open_low": true,
   "range": "0 < t_m",
   "unit": "s"
  },
  {
   "default": 1.0,
   "doc": "torque scale m h_m'^2/(w_s t_m^3) of the nominal motion (A.2.7)",
   "high": null,
   "low": null,
   "name": "Mc",
   "open_high": false,
   "open_low": false,
   "range": "Mc finite",
   "unit": "N m"
  }
 ],
 "reference": "thesis sec. A.5.4.2",
 "residual": null,
 "source_hash": "sha256:5315b62110449092ed4fbe9bea35b87a6d10bad4792d9ef82b7feb5db7eda537",
 "states": [
  {
   "doc": "speed deviation of the drive, reduced to the camshaft",
   "initial": 0.0,
   "name": "dw",
   "scale": 1.0,
   "unit": "rad/s"
  }
 ],
 "time": {
  "name": "t",
  "unit": "s"
 },
 "time_derivative": "symbolic",
 "title": "Asynchronous motor, first order (no electrical lag)"
}
"""
MANIFEST = json.loads(_MANIFEST_JSON)
"""States, parameters (defaults, units, ranges), outputs, cam inputs, modes, events, source hash."""

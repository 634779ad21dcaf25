# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True, initializedcheck=False
#
# GENERATED FILE - DO NOT EDIT.  Written by `camdyn derive` from camdyn/derive/models/chain3.py;
# edit that and regenerate.  `camdyn derive --check` fails while this file is stale.
# Derivation key: sha256:ab7936016e175d92861888d8347ea9fe7420f5ab150188d2d7a3389a9115ed56
# Text hash: sha256:f908254f39e8c5bfb660b921ec1ce1b4daf18910bab85069c1d69925cfa6d792
#
# Three-DOF chain, constant fictitious angular velocity (thesis sec. 3.7, figs 3.6, 3.7, (2.47))
# Source hash: sha256:a1735f89202c97c2b444182398f9af26803e80bf78837315ac6167321477d309
#
# Three-DOF chain at constant fictitious angular velocity, thesis sec. 3.7, figs 3.6 and 3.7.
#
# The cam input H(T) drives mass 1 through spring c1; masses 1, 2, 3 follow in
# series through c2 and c3; mass 3 is the free end.  In the thesis's
# dimensionless form (sec. 3.3) with masses m_i and stiffnesses c_i relative to
# a reference pair (m, c) whose period is tau t_m:
#
#     kinetic energy     1/2 sum m_i X_i'^2
#     potential energy   1/2 (2 pi/tau)^2 [c1 (X1 - H)^2 + c2 (X2 - X1)^2 + c3 (X3 - X2)^2]
#
# which is the chain (2.47) with n = 3.  Readings taken: fig. 3.6 is the output
# x2 with one more mass (c3, m3) beyond it, which is what the numerators
# (-w_ei^2 + c/m) of (3.20), (3.21) require; fig. 3.7, the input "at the head
# of the series", is the output at the far end (X3), where the numerators are 1.
# With unit masses and stiffnesses the eigenvalues are 0.198, 1.555, 3.247
# (sec. 3.7.3).

import json

from cpython.pycapsule cimport PyCapsule_New

from camdyn.runtime.engine.abi cimport *
from camdyn.generated.camlaws cimport (camlaw_dwell, camlaw_dwell_value, camlaw_eval, camlaw_hi,
                                       camlaw_lo, camlaw_segment)

# sizes, known when the integration loops (loops.pxi) are compiled into this module
cdef enum:
    _NQ = 3                  # second-order coordinates
    _NS = 6                  # states: q, q', first-order states
    _NCAM = 1                # cam input instances (one segment mode each)
    _NM = 1                  # modes: cam segments, then the force elements' modes
    _NE = 0                  # events
    _NQ1 = 3                 # array sizes that must not be zero
    _NE1 = 1
    _JAC_SYMBOLIC = 1           # jacobian() is derived symbolically: the implicit loops use it
    _FT_SYMBOLIC = 1            # jacobian() also gives df/dt
    _PROJECTS = 0               # no constraints: nothing to project after a step (project())

cdef int _EDIR[_NE1]    # crossing direction of each event: +1 upward, -1 downward



cdef void prepare(Ctx* ctx) noexcept nogil:
    """Parameter-only subexpressions, once per run, into ctx.k."""
    cdef double tau = ctx.p[0]
    cdef double m1 = ctx.p[1]
    cdef double m2 = ctx.p[2]
    cdef double m3 = ctx.p[3]
    cdef double c1 = ctx.p[4]
    cdef double c2 = ctx.p[5]
    cdef double c3 = ctx.p[6]
    cdef double _c0 = 39.47841760435743*(1.0/(tau*tau))
    cdef double _c1 = _c0/m1
    cdef double _c2 = -_c1*(c1 + c2)
    cdef double _c3 = _c0/m2
    cdef double _c4 = -_c3*(c2 + c3)
    cdef double _c5 = _c0*c3/m3
    ctx.k[0] = _c1*c2  # _k0
    ctx.k[1] = _c1*c1  # _k1
    ctx.k[2] = _c2  # _k2
    ctx.k[3] = _c3*c2  # _k3
    ctx.k[4] = _c3*c3  # _k4
    ctx.k[5] = _c4  # _k5
    ctx.k[6] = _c5  # _k6
    ctx.k[7] = _c2  # _k7
    ctx.k[8] = _c4  # _k8
    ctx.k[9] = -_c5  # _k9


cdef inline void rhs(double t, const double* _y, double* _dy, Ctx* ctx) noexcept nogil:
    """dy/dt: q', q'' from M q'' = f, and the rates of the first-order states."""
    cdef double tau = ctx.p[0]
    cdef double m1 = ctx.p[1]
    cdef double m2 = ctx.p[2]
    cdef double m3 = ctx.p[3]
    cdef double c1 = ctx.p[4]
    cdef double c2 = ctx.p[5]
    cdef double c3 = ctx.p[6]
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
    cdef double X1 = _y[0]
    cdef double X2 = _y[1]
    cdef double X3 = _y[2]
    cdef double X1d = _y[3]
    cdef double X2d = _y[4]
    cdef double X3d = _y[5]
    cdef double _cam0[4]  # H(T) and its derivatives
    camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], t, _cam0)

    _dy[0] = X1d
    _dy[1] = X2d
    _dy[2] = X3d
    _dy[3] = X1*_k2 + X2*_k0 + _cam0[0]*_k1
    _dy[4] = X1*_k3 + X2*_k5 + X3*_k4
    _dy[5] = _k6*(X2 - X3)


cdef void outputs(double t, const double* _y, double* _out, Ctx* ctx) noexcept nogil:
    """The named outputs (U2, U3, X2dd, X3dd, H)."""
    cdef double _dy[6]
    rhs(t, _y, _dy, ctx)
    cdef double tau = ctx.p[0]
    cdef double m1 = ctx.p[1]
    cdef double m2 = ctx.p[2]
    cdef double m3 = ctx.p[3]
    cdef double c1 = ctx.p[4]
    cdef double c2 = ctx.p[5]
    cdef double c3 = ctx.p[6]
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
    cdef double X1 = _y[0]
    cdef double X2 = _y[1]
    cdef double X3 = _y[2]
    cdef double X1d = _y[3]
    cdef double X2d = _y[4]
    cdef double X3d = _y[5]
    cdef double X1dd = _dy[3]
    cdef double X2dd = _dy[4]
    cdef double X3dd = _dy[5]
    cdef double _cam0[4]  # H(T) and its derivatives
    camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], t, _cam0)

    cdef double _o0 = -_cam0[0]
    _out[0] = X2 + _o0  # U2
    _out[1] = X3 + _o0  # U3
    _out[2] = _dy[4]  # X2dd
    _out[3] = _dy[5]  # X3dd
    _out[4] = _cam0[0]  # H


cdef void mass_stiffness(double t, const double* _y, double* _Mm, double* _Km, Ctx* ctx) noexcept nogil:
    """Mass matrix M and stiffness K = -df/dq (row-major, n x n) at (t, y), for frozen analyses."""
    cdef double tau = ctx.p[0]
    cdef double m1 = ctx.p[1]
    cdef double m2 = ctx.p[2]
    cdef double m3 = ctx.p[3]
    cdef double c1 = ctx.p[4]
    cdef double c2 = ctx.p[5]
    cdef double c3 = ctx.p[6]
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
    cdef double X1 = _y[0]
    cdef double X2 = _y[1]
    cdef double X3 = _y[2]
    cdef double X1d = _y[3]
    cdef double X2d = _y[4]
    cdef double X3d = _y[5]
    cdef double _cam0[4]  # H(T) and its derivatives
    camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], t, _cam0)

    cdef double _m0 = 39.47841760435743*(1.0/(tau*tau))
    cdef double _m1 = -_m0*c2
    cdef double _m2 = _m0*c3
    cdef double _m3 = -_m2
    _Mm[0] = m1
    _Mm[1] = 0.0
    _Mm[2] = 0.0
    _Mm[3] = 0.0
    _Mm[4] = m2
    _Mm[5] = 0.0
    _Mm[6] = 0.0
    _Mm[7] = 0.0
    _Mm[8] = m3
    _Km[0] = _m0*(c1 + c2)
    _Km[1] = _m1
    _Km[2] = 0.0
    _Km[3] = _m1
    _Km[4] = _m0*(c2 + c3)
    _Km[5] = _m3
    _Km[6] = 0.0
    _Km[7] = _m3
    _Km[8] = _m2


cdef void jacobian(double t, const double* _y, double* _J, double* _ft, Ctx* ctx) noexcept nogil:
    """d(dy/dt)/dy at (t, y), row-major _NS x _NS, derived symbolically (CSE'd): the Jacobian
    of the general right-hand side in the current modes, a cam input in a dwell taking its
    dwell values.
    With _ft not NULL also df/dt there (_NS values), derived the same way."""
    cdef double tau = ctx.p[0]
    cdef double m1 = ctx.p[1]
    cdef double m2 = ctx.p[2]
    cdef double m3 = ctx.p[3]
    cdef double c1 = ctx.p[4]
    cdef double c2 = ctx.p[5]
    cdef double c3 = ctx.p[6]
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
    cdef double X1 = _y[0]
    cdef double X2 = _y[1]
    cdef double X3 = _y[2]
    cdef double X1d = _y[3]
    cdef double X2d = _y[4]
    cdef double X3d = _y[5]
    cdef double _cam0[4]  # H(T) and its derivatives
    camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], t, _cam0)

    cdef int _k
    cdef double _ftl[6]
    for _k in range(36):
        _J[_k] = 0.0
    for _k in range(6):
        _ftl[_k] = 0.0
    for _k in range(3):
        _J[_k * 7 + 3] = 1.0  # d q'/d q'
    _J[18] = _k7
    _J[19] = _k0
    _J[24] = _k3
    _J[25] = _k8
    _J[26] = _k4
    _J[31] = _k6
    _J[32] = _k9
    _ftl[3] = _cam0[1]*_k1
    if _ft != NULL:
        for _k in range(6):
            _ft[_k] = _ftl[_k]


cdef void refresh(Ctx* ctx) noexcept nogil:
    """ctx.variant from the modes (bit i set when cam input i sits in a dwell); the cam
    cache is emptied, its entries belong to the old segments."""
    ctx.variant = 0
    ctx.cache[0] = 0.0 / 0.0
    ctx.cache[1] = camlaw_dwell_value(ctx.mode[0])


cdef inline bint _lti_now(Ctx* ctx) noexcept nogil:
    """Whether y' = A y + c with A and c constant in the segments now in force, so that the
    loops may step over the interval exactly (derive/codegen.py, _linear_in_dwell): every cam input in a dwell."""
    return camlaw_dwell(ctx.law[0], ctx.law_par[0], ctx.mode[0])


cdef void update_modes(double t, const double* _y, Ctx* ctx) noexcept nogil:
    """Segment of every cam input at (t, y); the force elements keep their modes."""
    cdef double tau = ctx.p[0]
    cdef double m1 = ctx.p[1]
    cdef double m2 = ctx.p[2]
    cdef double m3 = ctx.p[3]
    cdef double c1 = ctx.p[4]
    cdef double c2 = ctx.p[5]
    cdef double c3 = ctx.p[6]
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
    cdef double X1 = _y[0]
    cdef double X2 = _y[1]
    cdef double X3 = _y[2]
    cdef double X1d = _y[3]
    cdef double X2d = _y[4]
    cdef double X3d = _y[5]

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
    cdef double m1 = p[1]
    cdef double m2 = p[2]
    cdef double m3 = p[3]
    cdef double c1 = p[4]
    cdef double c2 = p[5]
    cdef double c3 = p[6]
    return [0.0, 0.0, 0.0, 0.0, 0.0, 0.0]


def cam_time_affine(p):
    """Per cam input, (a, b) with argument a t + b, or None when it depends on the state."""
    cdef double tau = p[0]
    cdef double m1 = p[1]
    cdef double m2 = p[2]
    cdef double m3 = p[3]
    cdef double c1 = p[4]
    cdef double c2 = p[5]
    cdef double c3 = p[6]
    return [(1.0, 0.0)]


cdef ModelC _model
_model.abi_version = CAMDYN_ABI
_model.n_q = _NQ
_model.n_states = _NS
_model.n_params = 7
_model.n_outputs = 5
_model.n_families = 1
_model.n_instances = _NCAM
_model.n_modes = _NM
_model.n_events = _NE
_model.n_const = 10
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
   "order": 0,
   "time_affine": true
  }
 ],
 "events": [],
 "jacobian": "symbolic",
 "modes": [],
 "n_q": 3,
 "name": "chain3",
 "options": [],
 "outputs": [
  {
   "doc": "positional error of mass 2, the output of fig. 3.6",
   "name": "U2",
   "unit": "h_m'"
  },
  {
   "doc": "positional error of mass 3, the output of fig. 3.7",
   "name": "U3",
   "unit": "h_m'"
  },
  {
   "doc": "acceleration of mass 2",
   "name": "X2dd",
   "unit": "h_m'/t_m^2"
  },
  {
   "doc": "acceleration of mass 3",
   "name": "X3dd",
   "unit": "h_m'/t_m^2"
  },
  {
   "doc": "nominal displacement (cam law)",
   "name": "H",
   "unit": "h_m'"
  }
 ],
 "parameters": [
  {
   "default": 0.15,
   "doc": "period of the reference mass-spring pair over t_m",
   "high": 10.0,
   "low": 0.0,
   "name": "tau",
   "open_high": false,
   "open_low": true,
   "range": "0 < tau <= 10",
   "unit": "1"
  },
  {
   "default": 1.0,
   "doc": "mass 1 over the reference mass",
   "high": null,
   "low": 0.0,
   "name": "m1",
   "open_high": false,
   "open_low": true,
   "range": "0 < m1",
   "unit": "m"
  },
  {
   "default": 1.0,
   "doc": "mass 2 over the reference mass",
   "high": null,
   "low": 0.0,
   "name": "m2",
   "open_high": false,
   "open_low": true,
   "range": "0 < m2",
   "unit": "m"
  },
  {
   "default": 1.0,
   "doc": "mass 3 over the reference mass",
   "high": null,
   "low": 0.0,
   "name": "m3",
   "open_high": false,
   "open_low": true,
   "range": "0 < m3",
   "unit": "m"
  },
  {
   "default": 1.0,
   "doc": "stiffness 1 over the reference stiffness",
   "high": null,
   "low": 0.0,
   "name": "c1",
   "open_high": false,
   "open_low": true,
   "range": "0 < c1",
   "unit": "c"
  },
  {
   "default": 1.0,
   "doc": "stiffness 2 over the reference stiffness",
   "high": null,
   "low": 0.0,
   "name": "c2",
   "open_high": false,
   "open_low": true,
   "range": "0 < c2",
   "unit": "c"
  },
  {
   "default": 1.0,
   "doc": "stiffness 3 over the reference stiffness",
   "high": null,
   "low": 0.0,
   "name": "c3",
   "open_high": false,
   "open_low": true,
   "range": "0 < c3",
   "unit": "c"
  }
 ],
 "reference": "thesis sec. 3.7, figs 3.6, 3.7, (2.47)",
 "residual": {
  "acceleration": "X2dd",
  "error": "U2",
  "rise_end": 1.0,
  "rise_state": ""
 },
 "source_hash": "sha256:a1735f89202c97c2b444182398f9af26803e80bf78837315ac6167321477d309",
 "states": [
  {
   "doc": "position of mass 1 over the stroke",
   "initial": 0.0,
   "name": "X1",
   "scale": 1.0,
   "unit": "h_m'"
  },
  {
   "doc": "position of mass 2 over the stroke",
   "initial": 0.0,
   "name": "X2",
   "scale": 1.0,
   "unit": "h_m'"
  },
  {
   "doc": "position of mass 3 over the stroke",
   "initial": 0.0,
   "name": "X3",
   "scale": 1.0,
   "unit": "h_m'"
  },
  {
   "doc": "rate of X1",
   "initial": 0.0,
   "name": "X1d",
   "scale": 1.0,
   "unit": "h_m'/t_m"
  },
  {
   "doc": "rate of X2",
   "initial": 0.0,
   "name": "X2d",
   "scale": 1.0,
   "unit": "h_m'/t_m"
  },
  {
   "doc": "rate of X3",
   "initial": 0.0,
   "name": "X3d",
   "scale": 1.0,
   "unit": "h_m'/t_m"
  }
 ],
 "time": {
  "name": "T",
  "unit": "t_m"
 },
 "time_derivative": "symbolic",
 "title": "Three-DOF chain, constant fictitious angular velocity"
}
"""
MANIFEST = json.loads(_MANIFEST_JSON)
"""States, parameters (defaults, units, ranges), outputs, cam inputs, modes, events, source hash."""

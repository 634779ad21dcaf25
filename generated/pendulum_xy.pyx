# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True, initializedcheck=False
#
# GENERATED FILE - DO NOT EDIT.  Written by `camdyn derive` from camdyn/derive/models/pendulum.py;
# edit that and regenerate.  `camdyn derive --check` fails while this file is stale.
# Derivation key: sha256:57a162afdd64f529b34bace08a6dad6cb22e179bac321d9d9ac3cd3b46604e93
# Text hash: sha256:4b69d0bdf00490927a9cec43e01961fe0306d6a590dd5f44795e457fb420210f
#
# Planar pendulum in Cartesian coordinates with its length constraint (Lagrange's equations of the first kind; the pendulum's closed forms)
# Source hash: sha256:161a1c58ca2d37fcefd956520d1151d5da9a8e1578200587452bf241fc0d81e3
#
# A planar pendulum in Cartesian coordinates: the constraint layer's second model.
#
# A point mass m on a massless rigid rod of length L, hinged at the origin, in the vertical
# plane; x horizontal, y vertically up (gravity g points to -y), so the mass hangs at
# (0, -L).  The coordinates Q = [x, y] are dependent, tied by the rod's length:
#
#     Phi = x^2 + y^2 - L^2 = 0
#
#     kinetic energy     T = m (x'^2 + y'^2)/2
#     potential energy   V = m g y
#     dissipation        D = c (x'^2 + y'^2)/2     viscous damping of the mass (c = 0: none)
#
# Lagrange's equations of the first kind, M Q'' + Phi_Q^T lambda = f with M = m I,
# Phi_Q = [2 x, 2 y] and f = [-c x', -m g - c y']:
#
#     m x'' + 2 x lambda = -c x',     m y'' + 2 y lambda = -m g - c y'.
#
# The rod's tension T_rod (positive when the rod pulls the mass towards the hinge) acts on
# the mass as -T_rod (x, y)/L, so the multiplier is lambda = T_rod/(2 L), in N/m (a force
# per unit of Phi's m^2 over the m^2/m of Phi_Q).  For the undamped pendulum at the angle
# theta from the downward vertical, T_rod = m L theta'^2 + m g cos theta.
#
# The start is the rod at the angle theta0 at rest: x = L sin theta0, y = -L cos theta0,
# on the constraint, with consistent (zero) rates.
#
# Solving the constraint (parameter ``formulation``): 0 is the augmented index-1 system with
# Baumgarte's stabilization at the rate w_B; 1 is coordinate partitioning with y, the last
# coordinate, dependent: y is recovered from x by Newton's method on Phi = 0 (the branch of
# the sign y carries), and y' = -x x'/y.  That fails near y = 0, the horizontal rod, where
# Phi_y = 2 y vanishes: use the augmented form (formulation 0) for swings that reach the
# horizontal (|theta0| >= pi/2); 2 is the augmented system without Baumgarte's terms, the
# state projected back onto Phi = 0 and Phi' = 0 after every accepted step.

import json

from cpython.pycapsule cimport PyCapsule_New
from libc.math cimport atan2, cos, fabs, sin

from camdyn.runtime.engine.abi cimport *
from camdyn.runtime.engine.linalg cimport lu_factor, lu_solve, solve_inplace

# sizes, known when the integration loops (loops.pxi) are compiled into this module
cdef enum:
    _NQ = 2                  # coordinates Q
    _NC = 1                  # constraints Phi
    _NA = 3                  # unknowns of the augmented system: Q'', lambda
    _ND = 1                  # independent coordinates, beside the _NC dependent ones (_partition)
    _NS = 4                 # states: Q, Q'
    _NCAM = 0
    _NM = 0
    _NE = 0
    _NQ1 = 2
    _NE1 = 1
    _JAC_SYMBOLIC = 1           # jacobian() is exact: A^-1 d(b - A x)/dy at fixed x
    _FT_SYMBOLIC = 1            # and so is its df/dt
    _PROJECTS = 1               # the loops call project() after every accepted step

# the declared coordinate partition (ConstraintSolver.dependent): the dependent coordinates,
# then the independent ones; a run may choose another (Ctx.part, _partition)
cdef int _PART[_NQ]
_PART[0] = 1  # y, dependent
_PART[1] = 0  # x

cdef int _EDIR[_NE1]    # crossing direction of each event: +1 upward, -1 downward



cdef void prepare(Ctx* ctx) noexcept nogil:
    """Parameter-only subexpressions, once per run, into ctx.k."""
    cdef double m = ctx.p[0]
    cdef double L = ctx.p[1]
    cdef double g = ctx.p[2]
    cdef double c = ctx.p[3]
    cdef double theta0 = ctx.p[4]
    cdef double w_B = ctx.p[5]
    cdef double formulation = ctx.p[6]
    cdef double _c0 = g*m
    ctx.k[0] = -c  # _k0
    ctx.k[1] = -_c0  # _k1
    ctx.k[2] = -(L*L)  # _k2
    ctx.k[3] = 0.5*m  # _k3
    ctx.k[4] = _c0  # _k4
    ctx.k[5] = -L  # _k5


cdef inline void _system(double t, const double* _y, double* _A, double* _b, double* _ph,
                         double* _phd, Ctx* ctx) noexcept nogil:
    """The augmented matrix [[M, Phi_Q^T], [Phi_Q, 0]] (row-major, _NA x _NA), the right side
    [f; gamma], and Phi, Phi' at (t, Q, Q')."""
    cdef double m = ctx.p[0]
    cdef double L = ctx.p[1]
    cdef double g = ctx.p[2]
    cdef double c = ctx.p[3]
    cdef double theta0 = ctx.p[4]
    cdef double w_B = ctx.p[5]
    cdef double formulation = ctx.p[6]
    cdef double _k0 = ctx.k[0]
    cdef double _k1 = ctx.k[1]
    cdef double _k2 = ctx.k[2]
    cdef double _k3 = ctx.k[3]
    cdef double _k4 = ctx.k[4]
    cdef double _k5 = ctx.k[5]
    cdef double x = _y[0]
    cdef double y = _y[1]
    cdef double xd = _y[2]
    cdef double yd = _y[3]

    _A[0] = m
    _A[1] = 0.0
    _A[2] = 2.0*x
    _A[3] = 0.0
    _A[4] = m
    _A[5] = 2.0*y
    _A[6] = 2.0*x
    _A[7] = 2.0*y
    _A[8] = 0.0
    _b[0] = _k0*xd
    _b[1] = _k0*yd + _k1
    _b[2] = -2.0*((xd*xd) + (yd*yd))
    _ph[0] = _k2 + (x*x) + (y*y)
    _phd[0] = 0.0 + _A[6] * xd + _A[7] * yd


cdef inline void _constraints(double t, const double* _y, double* _g, double* _J, double* _gt,
                              Ctx* ctx) noexcept nogil:
    """Phi, Phi_Q (row-major, _NC x _NQ) and dPhi/dt at (t, Q)."""
    cdef double m = ctx.p[0]
    cdef double L = ctx.p[1]
    cdef double g = ctx.p[2]
    cdef double c = ctx.p[3]
    cdef double theta0 = ctx.p[4]
    cdef double w_B = ctx.p[5]
    cdef double formulation = ctx.p[6]
    cdef double _k0 = ctx.k[0]
    cdef double _k1 = ctx.k[1]
    cdef double _k2 = ctx.k[2]
    cdef double _k3 = ctx.k[3]
    cdef double _k4 = ctx.k[4]
    cdef double _k5 = ctx.k[5]
    cdef double x = _y[0]
    cdef double y = _y[1]
    cdef double xd = _y[2]
    cdef double yd = _y[3]

    _g[0] = _k2 + (x*x) + (y*y)
    _J[0] = 2.0*x
    _J[1] = 2.0*y
    _gt[0] = 0.0


cdef inline const int* _partition(Ctx* ctx) noexcept nogil:
    """The run's coordinate partition: _NC dependent coordinates, then _ND independent ones
    (Ctx.part), or the declared one."""
    return ctx.part if ctx.part != NULL else _PART


cdef inline int _recover(double t, const double* _y, double* _yc, Ctx* ctx) noexcept nogil:
    """Coordinate partitioning: the state with its dependent coordinates recovered from the
    independent ones by Newton's method on Phi = 0, started from the values the state carries,
    and their rates from Phi_Q Q' = -dPhi/dt.  0; 1 without convergence, 2 where Phi_Q
    restricted to the dependent coordinates is singular."""
    cdef double _g[_NC]
    cdef double _J[_NC * _NQ]
    cdef double _gt[_NC]
    cdef double _D[_NC * _NC]
    cdef const int* _dep = _partition(ctx)
    cdef const int* _ind = _dep + _NC
    cdef int i, j, it
    cdef double step
    for i in range(_NS):
        _yc[i] = _y[i]
    for it in range(30):
        _constraints(t, _yc, _g, _J, _gt, ctx)
        for i in range(_NC):
            _g[i] = -_g[i]
            for j in range(_NC):
                _D[i * _NC + j] = _J[i * _NQ + _dep[j]]
        if solve_inplace(_NC, _D, _g) != 0:
            return 2
        step = 0.0
        for j in range(_NC):
            _yc[_dep[j]] += _g[j]
            step = max(step, fabs(_g[j]) / (1.0 + fabs(_yc[_dep[j]])))
        if step < 1e-15:
            break
    else:
        return 1
    _constraints(t, _yc, _g, _J, _gt, ctx)
    for i in range(_NC):
        _g[i] = -_gt[i]
        for j in range(_ND):
            _g[i] -= _J[i * _NQ + _ind[j]] * _yc[_NQ + _ind[j]]
        for j in range(_NC):
            _D[i * _NC + j] = _J[i * _NQ + _dep[j]]
    if solve_inplace(_NC, _D, _g) != 0:
        return 2
    for j in range(_NC):
        _yc[_NQ + _dep[j]] = _g[j]
    return 0


cdef inline int _formulation(Ctx* ctx) noexcept nogil:
    """0 augmented with Baumgarte's terms, 1 partitioned, 2 projection (ConstraintSolver)."""
    cdef double v = ctx.p[6]  # formulation
    return 2 if v > 1.5 else 1 if v > 0.5 else 0


cdef inline int _prepared(double t, double* _yc, const double* _y, double* _A, double* _acc,
                          double* w, Ctx* ctx) noexcept nogil:
    """The augmented system at the state the formulation solves it at (_yc: the state itself,
    or its partitioned recovery), with Baumgarte's terms in the right side _acc where they
    apply (formulation 0; their rate into w, else 0).  0, or 1 if the recovery failed."""
    cdef double _ph[_NC]
    cdef double _phd[_NC]
    cdef int i, form = _formulation(ctx)
    w[0] = ctx.p[5] if form == 0 else 0.0  # w_B
    if form == 1:
        if _recover(t, _y, _yc, ctx) != 0:
            return 1
    else:
        for i in range(_NS):
            _yc[i] = _y[i]
    _system(t, _yc, _A, _acc, _ph, _phd, ctx)
    for i in range(_NC):
        _acc[_NQ + i] -= 2.0 * w[0] * _phd[i] + w[0] * w[0] * _ph[i]
    return 0


cdef inline int _solve(double t, double* _yc, const double* _y, double* _acc, Ctx* ctx) noexcept nogil:
    """Q'' and lambda into _acc, and in _yc the state they belong to (_prepared)."""
    cdef double _A[_NA * _NA]
    cdef double w
    if _prepared(t, _yc, _y, _A, _acc, &w, ctx) != 0:
        return 1
    return solve_inplace(_NA, _A, _acc)


cdef inline void rhs(double t, const double* _y, double* _dy, Ctx* ctx) noexcept nogil:
    """dy/dt = [Q', Q''] from the augmented system."""
    cdef double _yc[_NS]
    cdef double _acc[_NA]
    cdef int i
    if _solve(t, _yc, _y, _acc, ctx) != 0:
        for i in range(_NS):
            _dy[i] = 0.0 / 0.0  # the integrator reports non-finite values
        return
    for i in range(_NQ):
        _dy[i] = _yc[_NQ + i]
        _dy[_NQ + i] = _acc[i]


cdef void outputs(double t, const double* _y, double* _out, Ctx* ctx) noexcept nogil:
    """The named outputs (theta, E, Phi, tension, lambda_rod), at the recovered state when partitioned."""
    cdef double _yc[_NS]
    cdef double _acc[_NA]
    cdef int i
    if _solve(t, _yc, _y, _acc, ctx) != 0:
        for i in range(_NA):
            _acc[i] = 0.0 / 0.0
    cdef double m = ctx.p[0]
    cdef double L = ctx.p[1]
    cdef double g = ctx.p[2]
    cdef double c = ctx.p[3]
    cdef double theta0 = ctx.p[4]
    cdef double w_B = ctx.p[5]
    cdef double formulation = ctx.p[6]
    cdef double _k0 = ctx.k[0]
    cdef double _k1 = ctx.k[1]
    cdef double _k2 = ctx.k[2]
    cdef double _k3 = ctx.k[3]
    cdef double _k4 = ctx.k[4]
    cdef double _k5 = ctx.k[5]
    cdef double x = _yc[0]
    cdef double y = _yc[1]
    cdef double xd = _yc[2]
    cdef double yd = _yc[3]

    cdef double _o0 = _k4*y
    cdef double _o1 = (x*x) + (y*y)
    _out[0] = atan2(x, -y)  # theta
    _out[1] = _k3*((xd*xd) + (yd*yd)) + _o0  # E
    _out[2] = _k2 + _o1  # Phi
    _out[3] = _k5*(_o0 + c*(x*xd + y*yd) + m*(x*_acc[0] + y*_acc[1]))/_o1  # tension
    _out[4] = _acc[2]  # lambda_rod


cdef void mass_stiffness(double t, const double* _y, double* _Mm, double* _Km, Ctx* ctx) noexcept nogil:
    """Mass matrix M at (t, y); K is not formed for constrained models (NaN): frozen analyses
    linearize the constrained right-hand side instead."""
    cdef double _A[_NA * _NA]
    cdef double _b[_NA]
    cdef double _ph[_NC]
    cdef double _phd[_NC]
    cdef int i, j
    _system(t, _y, _A, _b, _ph, _phd, ctx)
    for i in range(_NQ):
        for j in range(_NQ):
            _Mm[i * _NQ + j] = _A[i * _NA + j]
            _Km[i * _NQ + j] = 0.0 / 0.0


cdef double _SCALE[_NS]  # typical magnitude of each state (manifest "scale"): the projection's step test
_SCALE[0] = 1.0
_SCALE[1] = 1.0
_SCALE[2] = 1.0
_SCALE[3] = 1.0


cdef inline void _jac_parts(double t, const double* _y, const double* _acc, double* _R,
                            double* _Rt, double* _CQ, double* _Ct, Ctx* ctx) noexcept nogil:
    """With x = [Q''; lambda] = _acc held fixed: d(b - A x)/dy (row-major _NA x _NS) and
    d(b - A x)/dt, b without Baumgarte's terms; dC/dQ (_NC x _NQ) and dC/dt of the velocity
    constraint C = Phi_Q Q' + Phi_t (camdyn.derive.dae._jacobian_parts)."""
    cdef double m = ctx.p[0]
    cdef double L = ctx.p[1]
    cdef double g = ctx.p[2]
    cdef double c = ctx.p[3]
    cdef double theta0 = ctx.p[4]
    cdef double w_B = ctx.p[5]
    cdef double formulation = ctx.p[6]
    cdef double _k0 = ctx.k[0]
    cdef double _k1 = ctx.k[1]
    cdef double _k2 = ctx.k[2]
    cdef double _k3 = ctx.k[3]
    cdef double _k4 = ctx.k[4]
    cdef double _k5 = ctx.k[5]
    cdef double x = _y[0]
    cdef double y = _y[1]
    cdef double xd = _y[2]
    cdef double yd = _y[3]

    cdef double _j0 = -2.0*_acc[2]
    _R[0] = _j0
    _R[1] = 0.0
    _R[2] = _k0
    _R[3] = 0.0
    _R[4] = 0.0
    _R[5] = _j0
    _R[6] = 0.0
    _R[7] = _k0
    _R[8] = -2.0*_acc[0]
    _R[9] = -2.0*_acc[1]
    _R[10] = -4.0*xd
    _R[11] = -4.0*yd
    _Rt[0] = 0.0
    _Rt[1] = 0.0
    _Rt[2] = 0.0
    _CQ[0] = 2.0*xd
    _CQ[1] = 2.0*yd
    _Ct[0] = 0.0


cdef void jacobian(double t, const double* _y, double* _J, double* _ft, Ctx* ctx) noexcept nogil:
    """d(dy/dt)/dy at (t, y), row-major _NS x _NS, and df/dt into _ft unless NULL: exact (the
    manifest says "symbolic").  The accelerations x = [Q''; lambda] solve A x = b, so
    dx/dy = A^-1 d(b - A x)/dy at fixed x (_jac_parts), one LU of A for all columns, plus
    Baumgarte's terms b_c -= 2 w C + w^2 Phi in formulation 0.  Partitioned (formulation 1),
    the right-hand side is that of the recovered state, and the chain rule goes through the
    recovery: dQ_d/dQ_i = Z = -Phi_d^-1 Phi_i, dQ'_d/dQ'_i = Z, dQ'_d/dQ_i = -Phi_d^-1 dC/dQ
    [I; Z] (Phi_d, Phi_i: the columns of Phi_Q of the dependent and independent
    coordinates); the dependent coordinates' own columns are zero, as they only start the
    recovery's Newton iteration."""
    cdef double _yc[_NS]
    cdef double _acc[_NA]
    cdef double _A[_NA * _NA]
    cdef double _R[_NA * _NS]
    cdef double _Rt[_NA]
    cdef double _CQ[_NC * _NQ]
    cdef double _Ct[_NC]
    cdef double _g[_NC]
    cdef double _P[_NC * _NQ]
    cdef double _gt[_NC]
    cdef double _G[_NQ * (_NS + 1)]   # dQ''/dy (columns 0.._NS-1) and dQ''/dt (column _NS)
    cdef double _col[_NA]
    cdef double _D[_NC * _NC]
    cdef double _Z[_NC * _ND]         # dQ_d/dQ_i
    cdef double _U[_NC * _ND]         # dQ'_d/dQ_i
    cdef double _zt[_NC]              # dQ_d/dt
    cdef double _ut[_NC]              # dQ'_d/dt
    cdef int _piv[_NA]
    cdef int _pd[_NC]
    cdef const int* _dep = _partition(ctx)
    cdef const int* _ind = _dep + _NC
    cdef int i, j, k, c, form = _formulation(ctx)
    cdef double w, v
    if _prepared(t, _yc, _y, _A, _acc, &w, ctx) != 0 or lu_factor(_NA, _A, _piv) != 0:
        for i in range(_NS * _NS):
            _J[i] = 0.0 / 0.0
        if _ft != NULL:
            for i in range(_NS):
                _ft[i] = 0.0 / 0.0
        return
    lu_solve(_NA, _A, _piv, _acc)
    _jac_parts(t, _yc, _acc, _R, _Rt, _CQ, _Ct, ctx)
    _constraints(t, _yc, _g, _P, _gt, ctx)
    if w != 0.0:
        for k in range(_NC):
            for j in range(_NQ):
                _R[(_NQ + k) * _NS + j] -= 2.0 * w * _CQ[k * _NQ + j] + w * w * _P[k * _NQ + j]
                _R[(_NQ + k) * _NS + _NQ + j] -= 2.0 * w * _P[k * _NQ + j]
            _Rt[_NQ + k] -= 2.0 * w * _Ct[k] + w * w * _gt[k]
    for c in range(_NS + 1):
        for i in range(_NA):
            _col[i] = _R[i * _NS + c] if c < _NS else _Rt[i]
        lu_solve(_NA, _A, _piv, _col)
        for i in range(_NQ):
            _G[i * (_NS + 1) + c] = _col[i]
    for i in range(_NS * _NS):
        _J[i] = 0.0
    if form != 1:
        for i in range(_NQ):
            _J[i * _NS + _NQ + i] = 1.0
            for j in range(_NS):
                _J[(_NQ + i) * _NS + j] = _G[i * (_NS + 1) + j]
        if _ft != NULL:
            for i in range(_NQ):
                _ft[i] = 0.0
                _ft[_NQ + i] = _G[i * (_NS + 1) + _NS]
        return
    # partitioned: Z, dQ_d/dt, then U and dQ'_d/dt through dC/dQ
    for i in range(_NC):
        for k in range(_NC):
            _D[i * _NC + k] = _P[i * _NQ + _dep[k]]
    if lu_factor(_NC, _D, _pd) != 0:
        for i in range(_NS * _NS):
            _J[i] = 0.0 / 0.0
        return
    for j in range(_ND):
        for i in range(_NC):
            _col[i] = -_P[i * _NQ + _ind[j]]
        lu_solve(_NC, _D, _pd, _col)
        for k in range(_NC):
            _Z[k * _ND + j] = _col[k]
    for i in range(_NC):
        _zt[i] = -_gt[i]
    lu_solve(_NC, _D, _pd, _zt)
    for j in range(_ND):
        for i in range(_NC):
            v = _CQ[i * _NQ + _ind[j]]
            for k in range(_NC):
                v += _CQ[i * _NQ + _dep[k]] * _Z[k * _ND + j]
            _col[i] = -v
        lu_solve(_NC, _D, _pd, _col)
        for k in range(_NC):
            _U[k * _ND + j] = _col[k]
    for i in range(_NC):
        v = _Ct[i]
        for k in range(_NC):
            v += _CQ[i * _NQ + _dep[k]] * _zt[k]
        _ut[i] = -v
    lu_solve(_NC, _D, _pd, _ut)
    for j in range(_ND):
        _J[_ind[j] * _NS + _NQ + _ind[j]] = 1.0
        for k in range(_NC):
            _J[_dep[k] * _NS + _ind[j]] = _U[k * _ND + j]
            _J[_dep[k] * _NS + _NQ + _ind[j]] = _Z[k * _ND + j]
    for i in range(_NQ):
        for j in range(_ND):
            # through Q_i itself, Q_d (Z) and Q'_d (U); and for Q'_i through Q'_d (Z)
            v = _G[i * (_NS + 1) + _ind[j]]
            for k in range(_NC):
                v += (_G[i * (_NS + 1) + _dep[k]] * _Z[k * _ND + j]
                      + _G[i * (_NS + 1) + _NQ + _dep[k]] * _U[k * _ND + j])
            _J[(_NQ + i) * _NS + _ind[j]] = v
            v = _G[i * (_NS + 1) + _NQ + _ind[j]]
            for k in range(_NC):
                v += _G[i * (_NS + 1) + _NQ + _dep[k]] * _Z[k * _ND + j]
            _J[(_NQ + i) * _NS + _NQ + _ind[j]] = v
    if _ft != NULL:
        for i in range(_NS):
            _ft[i] = 0.0
        for k in range(_NC):
            _ft[_dep[k]] = _ut[k]
        for i in range(_NQ):
            v = _G[i * (_NS + 1) + _NS]
            for k in range(_NC):
                v += (_G[i * (_NS + 1) + _dep[k]] * _zt[k]
                      + _G[i * (_NS + 1) + _NQ + _dep[k]] * _ut[k])
            _ft[_NQ + i] = v


cdef int project(double t, double* _y, Ctx* ctx) noexcept nogil:
    """Formulation 2: the state y projected onto the constraints, in place; 1, or -1 if the
    iteration did not converge; 0 in the other formulations, which leave y alone.

    Positions: Gauss-Newton steps dQ minimizing dQ^T M dQ subject to Phi + Phi_Q dQ = 0,
    i.e. [[M, Phi_Q^T], [Phi_Q, 0]] [dQ; mu] = [0; -Phi], until the step (relative to each
    coordinate's scale and size) is below 1e-13 or stops shrinking; then the rates: dQ' minimizing dQ'^T M dQ' subject to Phi_Q (Q' + dQ') = -Phi_t,
    the same matrix with [0; -(Phi_Q Q' + Phi_t)].  The mass metric, not the Euclidean one:
    it is independent of the coordinates' units (modal amplitudes in m beside a cam
    angle in rad) and removes the least kinetic energy from the rates, and its matrix is
    the augmented system the right-hand side already forms."""
    cdef double _A[_NA * _NA]
    cdef double _b[_NA]
    cdef double _ph[_NC]
    cdef double _phd[_NC]
    cdef int i, it
    cdef double step = 0.0, prev = 1e300
    if _formulation(ctx) != 2:
        return 0
    for it in range(10):
        _system(t, _y, _A, _b, _ph, _phd, ctx)
        for i in range(_NQ):
            _b[i] = 0.0
        for i in range(_NC):
            _b[_NQ + i] = -_ph[i]
        if solve_inplace(_NA, _A, _b) != 0:
            return -1
        step = 0.0
        for i in range(_NQ):
            _y[i] += _b[i]
            step = max(step, fabs(_b[i]) / (_SCALE[i] + fabs(_y[i])))
        # converged, or no longer shrinking: at the level of the augmented solve's rounding
        # (modal amplitudes: 1e-10 of their scale), where Newton's steps are noise
        if step < 1e-13 or step > 0.5 * prev:
            break
        prev = step
    if step >= 1e-6:    # diverging, or stuck far from the constraints
        return -1
    _system(t, _y, _A, _b, _ph, _phd, ctx)
    for i in range(_NQ):
        _b[i] = 0.0
    for i in range(_NC):
        _b[_NQ + i] = -_phd[i]
    if solve_inplace(_NA, _A, _b) != 0:
        return -1
    for i in range(_NQ):
        _y[_NQ + i] += _b[i]
    return 1


cdef void refresh(Ctx* ctx) noexcept nogil:
    """No modes: a cam profile is evaluated afresh at every call."""
    ctx.variant = 0


cdef void update_modes(double t, const double* _y, Ctx* ctx) noexcept nogil:
    refresh(ctx)


cdef void events(double t, const double* _y, double* _g, Ctx* ctx) noexcept nogil:
    """Breakpoints: the segment ends of a cam profile, when the model declares them."""
    pass


cdef void on_event(int _e, double t, double* _y, Ctx* ctx) noexcept nogil:
    """A segment end switches nothing: the step just ends there."""
    refresh(ctx)


cdef void rhs_ptr(double t, const double* _y, double* _dy, Ctx* ctx) noexcept nogil:
    rhs(t, _y, _dy, ctx)


cdef int project_ptr(double t, double* _y, Ctx* ctx) noexcept nogil:
    return project(t, _y, ctx)


cdef inline bint _lti_now(Ctx* ctx) noexcept nogil:
    """A constrained model's loops never step over an interval exactly: its right-hand side
    is the solution of the constrained system, with a projection or stabilization."""
    return False


# the integration loops of camdyn.runtime, compiled here with rhs() inlined
include "camdyn/runtime/engine/loops.pxi"


def initial_state(p):
    """The default initial state for the parameter vector p (manifest order)."""
    cdef double m = p[0]
    cdef double L = p[1]
    cdef double g = p[2]
    cdef double c = p[3]
    cdef double theta0 = p[4]
    cdef double w_B = p[5]
    cdef double formulation = p[6]
    return [L*sin(theta0), -L*cos(theta0), 0.0, 0.0]


def cam_time_affine(p):
    """No cam input with a time-affine argument: a profile follows a state of the model."""
    return []


def consistent_state(double[::1] p, double[::1] k, int[::1] law, double[::1] law_par,
                     int[::1] mode, double t, double[::1] y, double[::1] out,
                     const int[::1] part=None):
    """The state y with its dependent coordinates and their rates recovered from the
    independent ones (Newton's method on Phi = 0, then Phi_Q Q' = -dPhi/dt), into out;
    returns (_recover's status: 0, 1 without convergence, 2 singular; the largest |Phi| and
    |Phi'| of y itself).
    ``k``: n_const + n_cache + 1 doubles of scratch, ``mode``: the modes buffer, ``part``:
    the coordinate partition (Ctx.part, checked by the caller), None for the declared one."""
    cdef Ctx ctx
    cdef double _g[_NC]
    cdef double _J[_NC * _NQ]
    cdef double _gt[_NC]
    cdef double phi = 0.0, phid = 0.0, v
    cdef int i, j, status
    ctx.p = &p[0]
    ctx.k = &k[0]
    ctx.cache = &k[6]
    ctx.law = &law[0]
    ctx.law_par = &law_par[0]
    ctx.mode = &mode[0]
    ctx.variant = 0
    ctx.part = NULL if part is None else &part[0]
    prepare(&ctx)
    update_modes(t, &y[0], &ctx)
    _constraints(t, &y[0], _g, _J, _gt, &ctx)
    for i in range(_NC):
        v = _gt[i]
        for j in range(_NQ):
            v += _J[i * _NQ + j] * y[_NQ + j]
        phi = max(phi, fabs(_g[i]))
        phid = max(phid, fabs(v))
    status = _recover(t, &y[0], &out[0], &ctx)
    return status, phi, phid


cdef ModelC _model
_model.abi_version = CAMDYN_ABI
_model.n_q = _NQ
_model.n_states = _NS
_model.n_params = 7
_model.n_outputs = 5
_model.n_families = 0
_model.n_instances = _NCAM
_model.n_modes = _NM
_model.n_events = _NE
_model.n_const = 6
_model.n_cache = 0
_model.prepare = prepare
_model.rhs = rhs_ptr
_model.outputs = outputs
_model.update_modes = update_modes
_model.refresh = refresh
_model.events = events
_model.on_event = on_event
_model.mass_stiffness = mass_stiffness
_model.jac = jacobian
_model.project = project_ptr
_model.run = run_loops
_model.dense_fill = dense_fill

MODEL = PyCapsule_New(<void*>&_model, b"camdyn.ModelC", NULL)
"""The model's C interface for camdyn.runtime (a PyCapsule holding a ModelC*)."""

_MANIFEST_JSON = """
{
 "cam_families": [],
 "cam_instances": [],
 "cam_profile": null,
 "constraints": [
  {
   "multiplier": "lambda_rod",
   "name": "rod"
  }
 ],
 "dependent": [
  "y"
 ],
 "events": [],
 "jacobian": "symbolic",
 "modes": [],
 "n_constraints": 1,
 "n_q": 2,
 "name": "pendulum_xy",
 "options": [],
 "outputs": [
  {
   "doc": "angle of the rod from the downward vertical",
   "name": "theta",
   "unit": "rad"
  },
  {
   "doc": "mechanical energy T + V (V = 0 at the hinge)",
   "name": "E",
   "unit": "J"
  },
  {
   "doc": "constraint residual x^2 + y^2 - L^2",
   "name": "Phi",
   "unit": "m^2"
  },
  {
   "doc": "rod tension from the accelerations, equal to 2 L lambda_rod",
   "name": "tension",
   "unit": "N"
  },
  {
   "doc": "multiplier of the rod constraint, T_rod/(2 L) (positive when the rod pulls the bob towards the hinge)",
   "name": "lambda_rod",
   "unit": "N/m"
  }
 ],
 "parameters": [
  {
   "default": 1.0,
   "doc": "mass of the bob",
   "high": null,
   "low": 0.0,
   "name": "m",
   "open_high": false,
   "open_low": true,
   "range": "0 < m",
   "unit": "kg"
  },
  {
   "default": 1.0,
   "doc": "length of the rod, hinge to bob",
   "high": null,
   "low": 0.0,
   "name": "L",
   "open_high": false,
   "open_low": true,
   "range": "0 < L",
   "unit": "m"
  },
  {
   "default": 9.81,
   "doc": "gravitational acceleration, along -y",
   "high": null,
   "low": 0.0,
   "name": "g",
   "open_high": false,
   "open_low": false,
   "range": "0 <= g",
   "unit": "m/s^2"
  },
  {
   "default": 0.0,
   "doc": "viscous damping of the bob's velocity (0: conservative)",
   "high": null,
   "low": 0.0,
   "name": "c",
   "open_high": false,
   "open_low": false,
   "range": "0 <= c",
   "unit": "N s/m"
  },
  {
   "default": 1.0,
   "doc": "initial angle of the rod from the downward vertical (released at rest)",
   "high": 3.141592653589793,
   "low": -3.141592653589793,
   "name": "theta0",
   "open_high": true,
   "open_low": true,
   "range": "-3.14159 < theta0 < 3.14159",
   "unit": "rad"
  },
  {
   "default": 10.0,
   "doc": "Baumgarte rate: Phi'' + 2 w_B Phi' + w_B^2 Phi = 0 (augmented form)",
   "high": null,
   "low": 0.0,
   "name": "w_B",
   "open_high": false,
   "open_low": false,
   "range": "0 <= w_B",
   "unit": "rad/s"
  },
  {
   "default": 0.0,
   "doc": "0: augmented index-1 system with Baumgarte stabilization; 1: coordinate partitioning with y dependent (not near the horizontal rod, y = 0); 2: augmented system, projected onto the constraint after every step",
   "high": 2.0,
   "low": 0.0,
   "name": "formulation",
   "open_high": false,
   "open_low": false,
   "range": "0 <= formulation <= 2",
   "unit": "1"
  }
 ],
 "reference": "Lagrange's equations of the first kind; the pendulum's closed forms",
 "residual": null,
 "solver": {
  "baumgarte_rate": "w_B",
  "formulation": "formulation"
 },
 "source_hash": "sha256:161a1c58ca2d37fcefd956520d1151d5da9a8e1578200587452bf241fc0d81e3",
 "states": [
  {
   "doc": "horizontal position of the bob",
   "initial": "L*sin(theta0)",
   "name": "x",
   "scale": 1.0,
   "unit": "m"
  },
  {
   "doc": "vertical position of the bob, up (dependent when partitioned)",
   "initial": "-L*cos(theta0)",
   "name": "y",
   "scale": 1.0,
   "unit": "m"
  },
  {
   "doc": "rate of x",
   "initial": 0.0,
   "name": "xd",
   "scale": 1.0,
   "unit": "m/s"
  },
  {
   "doc": "rate of y",
   "initial": 0.0,
   "name": "yd",
   "scale": 1.0,
   "unit": "m/s"
  }
 ],
 "time": {
  "name": "t",
  "unit": "s"
 },
 "time_derivative": "symbolic",
 "title": "Planar pendulum in Cartesian coordinates with its length constraint"
}
"""
MANIFEST = json.loads(_MANIFEST_JSON)
"""States, parameters (defaults, units, ranges), outputs, the cam profile, events, source hash."""

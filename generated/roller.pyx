# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True, initializedcheck=False
#
# GENERATED FILE - DO NOT EDIT.  Written by `camdyn derive` from camdyn/derive/models/roller.py;
# edit that and regenerate.  `camdyn derive --check` fails while this file is stale.
# Derivation key: sha256:e6620442bd73111ecbc2daa864c6fec718985336c0d3757818b8724f739fc52a
# Text hash: sha256:dfd1edccb913aecbf81c5dcafbd0ef53af8a325647b66c95c429ad01efee1ac1
#
# Roller vibration: roller mass and contact stiffness in series with the linkage (thesis sec. 9.2.1, with the one-DOF follower of sec. 3.3 and the impact of sec. 3.6)
# Source hash: sha256:27e1ce034622d3d74be6f8876c4c36db202e6589f148e1c301e5f081e69de353
#
# Roller vibration: the roller's mass and the contact stiffness between roller and cam, in
# series with the follower linkage (thesis sec. 9.2.1).
#
# The thesis leaves the roller massless and the contact rigid in DYNACAM because the contact
# stiffness is a hundred to a thousand times that of the linkage: the natural frequencies are
# then far apart, the stiffness matrix is badly conditioned, and the explicit integration of
# its day could not afford the fast mode.  It expects that this mode hardly affects the
# follower (sec. 3.7: the lowest natural frequency dominates) and that the contact force at
# impact after backlash is of the order F_b = v_b (m c)^(1/2) (sec. 3.6), of interest for wear
# and fatigue of the cam surface.  This model isolates the question on the one-DOF follower of
# sec. 3.3: a roller of mass m_r in the groove of a cam at constant speed, the follower linkage
# (c, d) between roller and output mass m.
#
# Dimensionless as in sec. 3.3: T = t/t_m, X = x/h_m, R = r/h_m (roller), H = h/h_m, omega =
# 2 pi/tau the linkage's natural angular frequency, forces per m h_m/t_m^2:
#
#     kinetic energy     1/2 X'^2 + 1/2 mu R'^2                 mu = m_r/m
#     potential energy   1/2 omega^2 (R - X)^2                  linkage spring c
#     dissipation        q omega (R' - X')^2                    linkage damper d = 2 q sqrt(m c)
#     contact            F_c on the lower wall, -F_c on the upper one, a generalized force on R
#
# Contact (the groove's walls at H and H + S, S = s_r/h_m the backlash): the deflection of the
# lower wall is delta = H - R, of the upper one delta_u = R - H - S.  The elastic force is
# kappa omega^2 delta_s (delta/delta_s)^n, kappa = k_c/c the contact stiffness ratio: n = 1 a
# linear spring, n = 10/9 the line contact of a cylindrical roller (Palmgren's fit of Hertz's
# line contact, deflection proportional to F^0.9), delta_s the deflection at which its secant
# stiffness is kappa omega^2.  The contact damping is that of the contact mode: 2 zeta
# sqrt(mu kappa) omega delta' (zeta the damping ratio of the roller on the contact spring
# alone); the force is held at zero where the damper would make it tensile, so a damped contact
# lets go before its deflection ends.  The contact opens when the deflection ends and closes
# when the roller reaches a wall again: mode "contact" = lower, free, upper, switched by events
# on the deflections, whose crossings the integrator locates.  Under the tiny overshoot before an opening is located the
# elastic law is continued linearly, so it stays real.
#
# Closed forms the tests use: with the roller on its wall the two natural frequencies solve
# det(K - w^2 M) = 0 with M = diag(mu, 1), K = omega^2 [[kappa + 1, -1], [-1, 1]]; the fast one
# is about omega sqrt((kappa + 1)/mu).  A roller reaching a wall at speed V_b sets the contact
# spring ringing with the peak force V_b sqrt(mu kappa) omega (F_b = v_b (m_r k_c)^(1/2) of sec.
# 3.6 in these units), when the linkage force is small against it and zeta = 0.

import json

from cpython.pycapsule cimport PyCapsule_New
from libc.math cimport pow, sqrt

from camdyn.runtime.engine.abi cimport *
from camdyn.generated.camlaws cimport (camlaw_dwell, camlaw_dwell_value, camlaw_eval, camlaw_hi,
                                       camlaw_lo, camlaw_segment)

# sizes, known when the integration loops (loops.pxi) are compiled into this module
cdef enum:
    _NQ = 2                  # second-order coordinates
    _NS = 4                  # states: q, q', first-order states
    _NCAM = 1                # cam input instances (one segment mode each)
    _NM = 2                  # modes: cam segments, then the force elements' modes
    _NE = 4                  # events
    _NQ1 = 2                 # array sizes that must not be zero
    _NE1 = 4
    _JAC_SYMBOLIC = 1           # jacobian() is derived symbolically: the implicit loops use it
    _FT_SYMBOLIC = 1            # jacobian() also gives df/dt
    _PROJECTS = 0               # no constraints: nothing to project after a step (project())

cdef int _EDIR[_NE1]    # crossing direction of each event: +1 upward, -1 downward
_EDIR[0] = -1  # contact_open_lower
_EDIR[1] = 1  # contact_hit_lower
_EDIR[2] = 1  # contact_hit_upper
_EDIR[3] = -1  # contact_open_upper



cdef void prepare(Ctx* ctx) noexcept nogil:
    """Parameter-only subexpressions, once per run, into ctx.k."""
    cdef double tau = ctx.p[0]
    cdef double q = ctx.p[1]
    cdef double mu = ctx.p[2]
    cdef double kappa = ctx.p[3]
    cdef double zeta = ctx.p[4]
    cdef double S = ctx.p[5]
    cdef double n_c = ctx.p[6]
    cdef double delta_s = ctx.p[7]
    cdef double _c0 = 39.47841760435743*(1.0/(tau*tau))
    cdef double _c1 = 12.566370614359172*(1.0/(tau))
    cdef double _c2 = _c1*q
    cdef double _c3 = (1.0/(delta_s))
    cdef double _c4 = _c0*kappa
    cdef double _c5 = _c4*delta_s
    cdef double _c6 = _c1*sqrt(kappa)*sqrt(mu)*zeta
    cdef double _c7 = S*_c4
    cdef double _c8 = (1.0/(mu))
    cdef double _c9 = _c3*n_c
    ctx.k[0] = _c0  # _k0
    ctx.k[1] = _c2  # _k1
    ctx.k[2] = -_c0  # _k2
    ctx.k[3] = -_c2  # _k3
    ctx.k[4] = _c3  # _k4
    ctx.k[5] = -_c3  # _k5
    ctx.k[6] = _c5  # _k6
    ctx.k[7] = -_c6  # _k7
    ctx.k[8] = _c6  # _k8
    ctx.k[9] = -_c4  # _k9
    ctx.k[10] = _c4  # _k10
    ctx.k[11] = -S*_c3  # _k11
    ctx.k[12] = _c7  # _k12
    ctx.k[13] = _c8  # _k13
    ctx.k[14] = -_c5  # _k14
    ctx.k[15] = -_c7  # _k15
    ctx.k[16] = -S  # _k16
    ctx.k[17] = _c0*_c8  # _k17
    ctx.k[18] = -_c9  # _k18
    ctx.k[19] = _c9  # _k19
    ctx.k[20] = _c2*_c8  # _k20


cdef inline void rhs(double t, const double* _y, double* _dy, Ctx* ctx) noexcept nogil:
    """dy/dt: q', q'' from M q'' = f, and the rates of the first-order states; specialised for cam inputs in a dwell."""
    cdef double tau = ctx.p[0]
    cdef double q = ctx.p[1]
    cdef double mu = ctx.p[2]
    cdef double kappa = ctx.p[3]
    cdef double zeta = ctx.p[4]
    cdef double S = ctx.p[5]
    cdef double n_c = ctx.p[6]
    cdef double delta_s = ctx.p[7]
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
    cdef double _k16 = ctx.k[16]
    cdef double _k17 = ctx.k[17]
    cdef double _k18 = ctx.k[18]
    cdef double _k19 = ctx.k[19]
    cdef double _k20 = ctx.k[20]
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

    cdef double _s0_0, _s0_1, _s0_2, _s0_3, _s0_4, _s0_5, _s0_6, _s0_7, _s1_0, _s1_1, _s1_2, _s1_3, _s1_4, _s1_5, _s1_6, _s1_7
    _dy[0] = Xd
    _dy[1] = Rd
    if _v == 0:
        _s0_0 = R*_k5 + _cam0[0]*_k4
        _s0_1 = pow(_s0_0, n_c)
        _s0_2 = (R - _cam0[0] < 0.0)
        _s0_3 = Rd*_k7 + _cam0[1]*_k8
        _s0_4 = Rd*_k8 + _cam0[1]*_k7
        _s0_5 = R*_k4 + _cam0[0]*_k5 + _k11
        _s0_6 = pow(_s0_5, n_c)
        _s0_7 = (-R + S + _cam0[0] < 0.0)
        _dy[2] = _k0*(R - X) + _k1*(Rd - Xd)
        _dy[3] = _k13*(R*_k2 + Rd*_k3 + X*_k0 + Xd*_k1 + ((((_k6*((_s0_1) if (_s0_2) else (_s0_0)) + _s0_3) if ((((_k6*_s0_1 + _s0_3 > 0.0)) if (_s0_2) else ((R*_k10 + _cam0[0]*_k9 + _s0_4 < 0.0)))) else (0.0))) if ((ctx.mode[1] == 0.0)) else (((0.0) if ((ctx.mode[1] == 1.0)) else (-((_k6*((_s0_6) if (_s0_7) else (_s0_5)) + _s0_4) if ((((_k6*_s0_6 + _s0_4 > 0.0)) if (_s0_7) else ((R*_k9 + _cam0[0]*_k10 + _k12 + _s0_3 < 0.0)))) else (0.0)))))))
    elif _v == 1:  # in a dwell: 0
        _s1_0 = R*_k5 + _cam0[0]*_k4
        _s1_1 = pow(_s1_0, n_c)
        _s1_2 = (R - _cam0[0] < 0.0)
        _s1_3 = Rd*_k8
        _s1_4 = R*_k10 + _cam0[0]*_k9 + _s1_3
        _s1_5 = R*_k4 + _cam0[0]*_k5 + _k11
        _s1_6 = pow(_s1_5, n_c)
        _s1_7 = (-R + S + _cam0[0] < 0.0)
        _dy[2] = _k0*(R - X) + _k1*(Rd - Xd)
        _dy[3] = _k13*(R*_k2 + Rd*_k3 + X*_k0 + Xd*_k1 + ((((Rd*_k7 + _k6*((_s1_1) if (_s1_2) else (_s1_0))) if ((((_k14*_s1_1 + _s1_3 < 0.0)) if (_s1_2) else ((_s1_4 < 0.0)))) else (0.0))) if ((ctx.mode[1] == 0.0)) else (((0.0) if ((ctx.mode[1] == 1.0)) else (-((_k6*((_s1_6) if (_s1_7) else (_s1_5)) + _s1_3) if ((((_k6*_s1_6 + _s1_3 > 0.0)) if (_s1_7) else ((_k15 + _s1_4 > 0.0)))) else (0.0)))))))


cdef void outputs(double t, const double* _y, double* _out, Ctx* ctx) noexcept nogil:
    """The named outputs (Xdd, U, Fc, F_link, delta, V_rel)."""
    cdef double _dy[4]
    rhs(t, _y, _dy, ctx)
    cdef double tau = ctx.p[0]
    cdef double q = ctx.p[1]
    cdef double mu = ctx.p[2]
    cdef double kappa = ctx.p[3]
    cdef double zeta = ctx.p[4]
    cdef double S = ctx.p[5]
    cdef double n_c = ctx.p[6]
    cdef double delta_s = ctx.p[7]
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
    cdef double _k16 = ctx.k[16]
    cdef double _k17 = ctx.k[17]
    cdef double _k18 = ctx.k[18]
    cdef double _k19 = ctx.k[19]
    cdef double _k20 = ctx.k[20]
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
    cdef double _o1 = Rd - _cam0[1]
    cdef double _o2 = _k8*_o1
    cdef double _o3 = -_o2
    cdef double _o4 = R + _o0
    cdef double _o5 = -_k4*_o4
    cdef double _o6 = pow(_o5, n_c)
    cdef double _o7 = (_o4 < 0.0)
    cdef double _o8 = _k16 + _o4
    cdef double _o9 = _k4*_o8
    cdef double _o10 = pow(_o9, n_c)
    cdef double _o11 = (-R + S + _cam0[0] < 0.0)
    _out[0] = _dy[2]  # Xdd
    _out[1] = X + _o0  # U
    _out[2] = ((((_k6*((_o6) if (_o7) else (_o5)) + _o3) if ((((_k6*_o6 + _o3 > 0.0)) if (_o7) else ((_k10*_o4 + _o2 < 0.0)))) else (0.0))) if ((ctx.mode[1] == 0.0)) else (((0.0) if ((ctx.mode[1] == 1.0)) else (-((_k6*((_o10) if (_o11) else (_o9)) + _o2) if ((((_k6*_o10 + _o2 > 0.0)) if (_o11) else ((_k10*_o8 + _o2 > 0.0)))) else (0.0))))))  # Fc
    _out[3] = _k0*(R - X) + _k1*(Rd - Xd)  # F_link
    _out[4] = -_o4  # delta
    _out[5] = _o1  # V_rel


cdef void mass_stiffness(double t, const double* _y, double* _Mm, double* _Km, Ctx* ctx) noexcept nogil:
    """Mass matrix M and stiffness K = -df/dq (row-major, n x n) at (t, y), for frozen analyses."""
    cdef double tau = ctx.p[0]
    cdef double q = ctx.p[1]
    cdef double mu = ctx.p[2]
    cdef double kappa = ctx.p[3]
    cdef double zeta = ctx.p[4]
    cdef double S = ctx.p[5]
    cdef double n_c = ctx.p[6]
    cdef double delta_s = ctx.p[7]
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
    cdef double _k16 = ctx.k[16]
    cdef double _k17 = ctx.k[17]
    cdef double _k18 = ctx.k[18]
    cdef double _k19 = ctx.k[19]
    cdef double _k20 = ctx.k[20]
    cdef double X = _y[0]
    cdef double R = _y[1]
    cdef double Xd = _y[2]
    cdef double Rd = _y[3]
    cdef double _cam0[4]  # H(T) and its derivatives
    camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], t, _cam0)

    _Mm[0] = 1.0
    _Mm[1] = 0.0
    _Mm[2] = 0.0
    _Mm[3] = mu
    _Km[0] = 0.0 / 0.0
    _Km[1] = 0.0 / 0.0
    _Km[2] = 0.0 / 0.0
    _Km[3] = 0.0 / 0.0


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
    cdef double S = ctx.p[5]
    cdef double n_c = ctx.p[6]
    cdef double delta_s = ctx.p[7]
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
    cdef double _k16 = ctx.k[16]
    cdef double _k17 = ctx.k[17]
    cdef double _k18 = ctx.k[18]
    cdef double _k19 = ctx.k[19]
    cdef double _k20 = ctx.k[20]
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
    cdef double _j0 = R*_k5 + _cam0[0]*_k4
    cdef double _j1 = pow(_j0, n_c)
    cdef double _j2 = _j1/_j0
    cdef double _j3 = (R - _cam0[0] < 0.0)
    cdef double _j4 = Rd*_k7 + _cam0[1]*_k8
    cdef double _j5 = Rd*_k8 + _cam0[1]*_k7
    cdef double _j6 = (((_j1*_k6 + _j4 > 0.0)) if (_j3) else ((R*_k10 + _cam0[0]*_k9 + _j5 < 0.0)))
    cdef double _j7 = (ctx.mode[1] == 0.0)
    cdef double _j8 = (ctx.mode[1] == 1.0)
    cdef double _j9 = R*_k4 + _cam0[0]*_k5 + _k11
    cdef double _j10 = pow(_j9, n_c)
    cdef double _j11 = _j10/_j9
    cdef double _j12 = (-R + S + _cam0[0] < 0.0)
    cdef double _j13 = (((_j10*_k6 + _j5 > 0.0)) if (_j12) else ((R*_k9 + _cam0[0]*_k10 + _j4 + _k12 < 0.0)))
    _J[8] = _k2
    _J[9] = _k0
    _J[10] = _k3
    _J[11] = _k1
    _J[12] = _k17
    _J[13] = _k13*(_k2 + ((((_k6*((_j2*_k18) if (_j3) else (_k5))) if (_j6) else (0.0))) if (_j7) else (((0.0) if (_j8) else (-((_k6*((_j11*_k19) if (_j12) else (_k4))) if (_j13) else (0.0)))))))
    _J[14] = _k20
    _J[15] = _k13*(_k3 + ((((_k7) if (_j6) else (0.0))) if (_j7) else (((0.0) if (_j8) else (-((_k8) if (_j13) else (0.0)))))))
    _ftl[3] = _k13*(_cam0[1]*((((_k6*((_j2*_k19) if (_j3) else (_k4))) if (_j6) else (0.0))) if (_j7) else (((0.0) if (_j8) else (-((_k6*((_j11*_k18) if (_j12) else (_k5))) if (_j13) else (0.0)))))) + _cam0[2]*((((_k8) if (_j6) else (0.0))) if (_j7) else (((0.0) if (_j8) else (-((_k7) if (_j13) else (0.0)))))))
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
    cdef double q = ctx.p[1]
    cdef double mu = ctx.p[2]
    cdef double kappa = ctx.p[3]
    cdef double zeta = ctx.p[4]
    cdef double S = ctx.p[5]
    cdef double n_c = ctx.p[6]
    cdef double delta_s = ctx.p[7]
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
    cdef double _k16 = ctx.k[16]
    cdef double _k17 = ctx.k[17]
    cdef double _k18 = ctx.k[18]
    cdef double _k19 = ctx.k[19]
    cdef double _k20 = ctx.k[20]
    cdef double X = _y[0]
    cdef double R = _y[1]
    cdef double Xd = _y[2]
    cdef double Rd = _y[3]

    ctx.mode[0] = camlaw_segment(ctx.law[0], ctx.law_par[0], t)
    refresh(ctx)


cdef void events(double t, const double* _y, double* _g, Ctx* ctx) noexcept nogil:
    """Event functions; an event not armed in the current modes reads 1 (never crosses)."""
    cdef double tau = ctx.p[0]
    cdef double q = ctx.p[1]
    cdef double mu = ctx.p[2]
    cdef double kappa = ctx.p[3]
    cdef double zeta = ctx.p[4]
    cdef double S = ctx.p[5]
    cdef double n_c = ctx.p[6]
    cdef double delta_s = ctx.p[7]
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
    cdef double _k16 = ctx.k[16]
    cdef double _k17 = ctx.k[17]
    cdef double _k18 = ctx.k[18]
    cdef double _k19 = ctx.k[19]
    cdef double _k20 = ctx.k[20]
    cdef double X = _y[0]
    cdef double R = _y[1]
    cdef double Xd = _y[2]
    cdef double Rd = _y[3]
    cdef double _cam0[4]  # H(T) and its derivatives
    camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], t, _cam0)

    _g[0] = (-R + _cam0[0]) if (ctx.mode[1] == 0.0) else 1.0  # contact_open_lower
    _g[1] = (-R + _cam0[0]) if (ctx.mode[1] == 1.0) else 1.0  # contact_hit_lower
    _g[2] = (R - S - _cam0[0]) if (ctx.mode[1] == 1.0) else 1.0  # contact_hit_upper
    _g[3] = (R - S - _cam0[0]) if (ctx.mode[1] == 2.0) else 1.0  # contact_open_upper


cdef void on_event(int _e, double t, double* _y, Ctx* ctx) noexcept nogil:
    """What event k does: new modes (and state resets) at its crossing."""
    cdef double tau = ctx.p[0]
    cdef double q = ctx.p[1]
    cdef double mu = ctx.p[2]
    cdef double kappa = ctx.p[3]
    cdef double zeta = ctx.p[4]
    cdef double S = ctx.p[5]
    cdef double n_c = ctx.p[6]
    cdef double delta_s = ctx.p[7]
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
    cdef double _k16 = ctx.k[16]
    cdef double _k17 = ctx.k[17]
    cdef double _k18 = ctx.k[18]
    cdef double _k19 = ctx.k[19]
    cdef double _k20 = ctx.k[20]
    cdef double X = _y[0]
    cdef double R = _y[1]
    cdef double Xd = _y[2]
    cdef double Rd = _y[3]
    cdef double _cam0[4]  # H(T) and its derivatives
    camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], t, _cam0)

    if _e == 0:  # contact_open_lower
        if True:
            ctx.mode[1] = 1  # contact = free
    elif _e == 1:  # contact_hit_lower
        if True:
            ctx.mode[1] = 0  # contact = lower
    elif _e == 2:  # contact_hit_upper
        if True:
            ctx.mode[1] = 2  # contact = upper
    elif _e == 3:  # contact_open_upper
        if True:
            ctx.mode[1] = 1  # contact = free
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
    cdef double q = p[1]
    cdef double mu = p[2]
    cdef double kappa = p[3]
    cdef double zeta = p[4]
    cdef double S = p[5]
    cdef double n_c = p[6]
    cdef double delta_s = p[7]
    return [0.0, 0.0, 0.0, 0.0]


def cam_time_affine(p):
    """Per cam input, (a, b) with argument a t + b, or None when it depends on the state."""
    cdef double tau = p[0]
    cdef double q = p[1]
    cdef double mu = p[2]
    cdef double kappa = p[3]
    cdef double zeta = p[4]
    cdef double S = p[5]
    cdef double n_c = p[6]
    cdef double delta_s = p[7]
    return [(1.0, 0.0)]


cdef ModelC _model
_model.abi_version = CAMDYN_ABI
_model.n_q = _NQ
_model.n_states = _NS
_model.n_params = 8
_model.n_outputs = 6
_model.n_families = 1
_model.n_instances = _NCAM
_model.n_modes = _NM
_model.n_events = _NE
_model.n_const = 21
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
 "events": [
  "contact_open_lower",
  "contact_hit_lower",
  "contact_hit_upper",
  "contact_open_upper"
 ],
 "jacobian": "symbolic",
 "modes": [
  {
   "doc": "groove wall the roller touches",
   "initial": "lower",
   "name": "contact",
   "values": [
    "lower",
    "free",
    "upper"
   ]
  }
 ],
 "n_q": 2,
 "name": "roller",
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
   "doc": "contact force of the cam on the roller (lower wall positive)",
   "name": "Fc",
   "unit": "m h_m/t_m^2"
  },
  {
   "doc": "force in the follower linkage",
   "name": "F_link",
   "unit": "m h_m/t_m^2"
  },
  {
   "doc": "deflection of the lower wall, H - R",
   "name": "delta",
   "unit": "h_m"
  },
  {
   "doc": "roller velocity relative to the cam, R' - H' (the impact velocity v_b when a wall is reached)",
   "name": "V_rel",
   "unit": "h_m/t_m"
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
  },
  {
   "default": 0.001,
   "doc": "backlash of the roller in the groove over the stroke, s_r/h_m",
   "high": 1.0,
   "low": 0.0,
   "name": "S",
   "open_high": false,
   "open_low": true,
   "range": "0 < S <= 1",
   "unit": "h_m"
  },
  {
   "default": 1.0,
   "doc": "exponent of the contact law: 1 linear, 10/9 line contact (Hertz, Palmgren's fit)",
   "high": 1.5,
   "low": 1.0,
   "name": "n_c",
   "open_high": false,
   "open_low": false,
   "range": "1 <= n_c <= 1.5",
   "unit": "1"
  },
  {
   "default": 0.001,
   "doc": "deflection over the stroke at which the contact's secant stiffness is kappa c (n_c > 1)",
   "high": 1.0,
   "low": 0.0,
   "name": "delta_s",
   "open_high": false,
   "open_low": true,
   "range": "0 < delta_s <= 1",
   "unit": "h_m"
  }
 ],
 "reference": "thesis sec. 9.2.1, with the one-DOF follower of sec. 3.3 and the impact of sec. 3.6",
 "residual": {
  "acceleration": "Xdd",
  "error": "U",
  "rise_end": 1.0,
  "rise_state": ""
 },
 "source_hash": "sha256:27e1ce034622d3d74be6f8876c4c36db202e6589f148e1c301e5f081e69de353",
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
 "title": "Roller vibration: roller mass and contact stiffness in series with the linkage"
}
"""
MANIFEST = json.loads(_MANIFEST_JSON)
"""States, parameters (defaults, units, ranges), outputs, cam inputs, modes, events, source hash."""

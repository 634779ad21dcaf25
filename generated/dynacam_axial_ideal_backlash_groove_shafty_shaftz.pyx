# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True, initializedcheck=False
#
# GENERATED FILE - DO NOT EDIT.  Written by `camdyn derive` from camdyn/derive/models/dynacam.py;
# edit that and regenerate.  `camdyn derive --check` fails while this file is stale.
# Derivation key: sha256:159c7f50d80a2c75184b677da59c6c6202bab3b611397ac06da78beb42ef0aae
# Text hash: sha256:311f4b9e1708123eb07cee528157ee848ed8b8ecb010a5071df4b70292d348d2
#
# DYNACAM, cam mechanism with four degrees of freedom and drive (thesis ch. 6, figs 6.1, 6.2, 6.15, 6.18)
# Source hash: sha256:20057f71b91ba1e26afc2d2e794ae3ecfcc9a5b84e3371830277eacbb8275d82
#
# This variant:
#   cam = axial: axial (globoidal) cam, constant pitch radius R_b (6.21)
#   motor = constant: camshaft input turning at the constant speed omega_s (ideal drive)
#   gear = backlash: reduction gear with backlash s_g, dry contact (6.1), fig. 6.3
#   roller = groove: roller in a groove with backlash s_r, dry contact (6.27), fig. 6.10
#   shaft_y = yes: tangential shaft deflection y (6.12), (6.16)
#   shaft_z = yes: shaft deflection z along the follower (6.11), (6.15)
#   cam_friction = no: no friction on the cam
#   linkage_friction = no: no friction in the linkage
#   spring = no: no follower spring
#   external = no: no external force
#   flat_face = no: a roller on the cam
#   rocker = no: translating follower
#
# DYNACAM: the cam mechanism with four degrees of freedom and its drive, thesis ch. 6.
#
# Degrees of freedom (figs 6.1, 6.2, all reduced to the output member, SI units):
# the cam angle beta, the shaft's tangential deflection y (6.12), (6.16), its
# deflection z along the follower (6.11), (6.15), and the follower output x
# (6.42), (6.44); plus, as first-order states, the asynchronous motor
# (A.5.6)-(A.5.9), and the massless gear wheel or roller in a squeeze film
# (6.9), (6.41).
#
# Smooth mechanics from energies:
#
#     kinetic energy     1/2 J beta'^2 + 1/2 m_y y'^2 + 1/2 m_z z'^2 + 1/2 m_x x'^2
#     potential energy   1/2 c_y y^2 + 1/2 c_z z^2 [+ F_0 x + 1/2 c_s x^2, follower spring (6.45)]
#     dissipation        1/2 d_y y'^2 + 1/2 d_z z'^2,   d = 2 q sqrt(m c) (6.47)
#
# The nonsmooth laws are force elements with modes and events:
#
# * the roller: the cam contact point moves by h_c = h(beta) - y tan(alpha) - z
#   (6.22), tan(alpha) = (dh/dbeta)/R(beta) (6.20), R = R_b + h (radial cam) or
#   R_b (axial) (6.21).  On a rocker (option ``rocker``, a radial cam) h is the roller
#   centre's arc l_a psi and the same first-order reasoning gives h_c = h - y i_y - z i_z
#   with ratios of the rocker's geometry (:func:`_rocker`); for the translating follower
#   they are tan(alpha) and 1, (6.22) again.  A flat face square to the follower's motion
#   (option ``flat_face``) is not moved by a sideways shift of the cam: i_y = 0, i_z = 1, and
#   the angle it sees is beta itself.  A flat face on the rocker's arm (both options) swings
#   with the arm; h is its swing reduced to the arc at l_a, and its ratios come from the
#   face's support distance (:func:`_rocker_flat`).  The linkage spring-damper (c_x, d_x) carries
#   F_x = c_x delta + d_x delta', delta = h_c - x, while the roller touches
#   (6.42).  Contact law taken here, with zero viscosity: the roller is massless
#   and the spring-damper engages when the roller reaches a wall (delta = 0 or
#   the far groove wall delta = -s_r) and releases when it leaves it again;
#   these crossings are events.  So a spring-loaded follower can jump (mode
#   "free"), a positive-drive cam traverses its groove backlash s_r, and the
#   "impact" is the sudden engagement of the linkage stiffness, the ramp input
#   of sec. 3.6.  With the squeeze film (A.4.11) instead the roller position is
#   a state, h_r' = h_c' - F_x/(V_R gap^(-3/2)) on the compressed side (6.41);
# * the reduction gear: the shaft torque M = k (phi_r - beta) + d_b (phi_r' - beta')
#   (6.10) with the gear output phi_r either the input phi (rigid), within the
#   backlash s_g with the same contact law (dry), or in a squeeze film (6.9);
# * Coulomb friction on the cam (6.13) and in the linkage (6.43): modes slip
#   forward, stick, slip backward; sticking holds the velocity at zero while
#   the other forces stay within the friction limit;
# * the worm gear passes the torque with efficiency tan(a)/tan(a + mu) when the
#   motor drives and tan(a - mu)/tan(a) when it is driven (6.71), (6.72).
#
# The option set of a variant (which of these elements and degrees of freedom
# it has) is in its manifest; a scene generates only what it asks for.

import json

from cpython.pycapsule cimport PyCapsule_New
from libc.math cimport sqrt

from camdyn.runtime.engine.abi cimport *
from camdyn.generated.camlaws cimport (camlaw_dwell, camlaw_dwell_value, camlaw_eval, camlaw_hi,
                                       camlaw_lo, camlaw_segment)

# sizes, known when the integration loops (loops.pxi) are compiled into this module
cdef enum:
    _NQ = 4                  # second-order coordinates
    _NS = 8                  # states: q, q', first-order states
    _NCAM = 1                # cam input instances (one segment mode each)
    _NM = 3                  # modes: cam segments, then the force elements' modes
    _NE = 10                  # events
    _NQ1 = 4                 # array sizes that must not be zero
    _NE1 = 10
    _JAC_SYMBOLIC = 1           # jacobian() is derived symbolically: the implicit loops use it
    _FT_SYMBOLIC = 1            # jacobian() also gives df/dt
    _PROJECTS = 0               # no constraints: nothing to project after a step (project())

cdef int _EDIR[_NE1]    # crossing direction of each event: +1 upward, -1 downward
_EDIR[0] = -1  # gear_lift_drive
_EDIR[1] = 1  # gear_hit_drive
_EDIR[2] = -1  # gear_hit_back
_EDIR[3] = 1  # gear_lift_back
_EDIR[4] = -1  # roller_leave_lower
_EDIR[5] = 1  # roller_hit_lower
_EDIR[6] = 1  # roller_hit_upper
_EDIR[7] = -1  # roller_leave_upper
_EDIR[8] = 1  # cam0_hi
_EDIR[9] = -1  # cam0_lo



cdef void prepare(Ctx* ctx) noexcept nogil:
    """Parameter-only subexpressions, once per run, into ctx.k."""
    cdef double h_m = ctx.p[0]
    cdef double beta_m = ctx.p[1]
    cdef double beta_0 = ctx.p[2]
    cdef double R_b = ctx.p[3]
    cdef double omega_s = ctx.p[4]
    cdef double J = ctx.p[5]
    cdef double k = ctx.p[6]
    cdef double q_b = ctx.p[7]
    cdef double m_x = ctx.p[8]
    cdef double c_x = ctx.p[9]
    cdef double q_x = ctx.p[10]
    cdef double m_y = ctx.p[11]
    cdef double c_y = ctx.p[12]
    cdef double q_y = ctx.p[13]
    cdef double m_z = ctx.p[14]
    cdef double c_z = ctx.p[15]
    cdef double q_z = ctx.p[16]
    cdef double s_g = ctx.p[17]
    cdef double s_r = ctx.p[18]
    cdef double _c0 = c_x*h_m
    cdef double _c1 = 2.0*sqrt(c_x)*sqrt(m_x)*q_x
    cdef double _c2 = (1.0/(beta_m))
    cdef double _c3 = (1.0/(R_b))
    cdef double _c4 = _c2*h_m
    cdef double _c5 = _c3*_c4
    cdef double _c6 = (beta_m*beta_m)
    cdef double _c7 = _c3*h_m/_c6
    cdef double _c8 = 2.0*sqrt(J)*sqrt(k)*q_b
    cdef double _c9 = _c8*omega_s
    cdef double _c10 = (1.0/(J))
    cdef double _c11 = (1.0/(m_y))
    cdef double _c12 = (1.0/(m_z))
    cdef double _c13 = (1.0/(m_x))
    cdef double _c14 = (1.0/(h_m))
    cdef double _c15 = (1.0/(omega_s*omega_s))
    ctx.k[0] = -c_x  # _k0
    ctx.k[1] = _c0  # _k1
    ctx.k[2] = -_c1  # _k2
    ctx.k[3] = -_c0*_c2*_c3  # _k3
    ctx.k[4] = _c1*_c4  # _k4
    ctx.k[5] = -_c1*_c5  # _k5
    ctx.k[6] = -_c1*_c7  # _k6
    ctx.k[7] = c_x*s_r  # _k7
    ctx.k[8] = -_c4  # _k8
    ctx.k[9] = _c7  # _k9
    ctx.k[10] = -k  # _k10
    ctx.k[11] = k*omega_s  # _k11
    ctx.k[12] = -_c8  # _k12
    ctx.k[13] = _c9  # _k13
    ctx.k[14] = _c9 + k*s_g  # _k14
    ctx.k[15] = _c10  # _k15
    ctx.k[16] = -_c11*c_y  # _k16
    ctx.k[17] = -2.0*sqrt(c_y)*q_y/sqrt(m_y)  # _k17
    ctx.k[18] = _c11*_c5  # _k18
    ctx.k[19] = -c_z  # _k19
    ctx.k[20] = -2.0*sqrt(c_z)*sqrt(m_z)*q_z  # _k20
    ctx.k[21] = _c12  # _k21
    ctx.k[22] = _c13  # _k22
    ctx.k[23] = -beta_0  # _k23
    ctx.k[24] = _c2  # _k24
    ctx.k[25] = _c14*_c15*_c6  # _k25
    ctx.k[26] = _c15*beta_m  # _k26
    ctx.k[27] = -h_m  # _k27
    ctx.k[28] = _c14  # _k28
    ctx.k[29] = _c8  # _k29
    ctx.k[30] = _c4  # _k30
    ctx.k[31] = -_c7  # _k31
    ctx.k[32] = -_c5  # _k32
    ctx.k[33] = _c1  # _k33
    ctx.k[34] = -s_r  # _k34
    ctx.k[35] = _c5  # _k35
    ctx.k[36] = -_c3  # _k36
    ctx.k[37] = (1.0/(omega_s))  # _k37
    ctx.k[38] = -s_g  # _k38
    ctx.k[39] = _c10*_c2  # _k39
    ctx.k[40] = -_c10*_c4  # _k40
    ctx.k[41] = _c10*_c7  # _k41
    ctx.k[42] = _c11*_c2  # _k42
    ctx.k[43] = _c11*_c7  # _k43
    ctx.k[44] = _c12*_c2  # _k44
    ctx.k[45] = _c13*_c2  # _k45


cdef inline void rhs(double t, const double* _y, double* _dy, Ctx* ctx) noexcept nogil:
    """dy/dt: q', q'' from M q'' = f, and the rates of the first-order states; specialised for cam inputs in a dwell."""
    cdef double h_m = ctx.p[0]
    cdef double beta_m = ctx.p[1]
    cdef double beta_0 = ctx.p[2]
    cdef double R_b = ctx.p[3]
    cdef double omega_s = ctx.p[4]
    cdef double J = ctx.p[5]
    cdef double k = ctx.p[6]
    cdef double q_b = ctx.p[7]
    cdef double m_x = ctx.p[8]
    cdef double c_x = ctx.p[9]
    cdef double q_x = ctx.p[10]
    cdef double m_y = ctx.p[11]
    cdef double c_y = ctx.p[12]
    cdef double q_y = ctx.p[13]
    cdef double m_z = ctx.p[14]
    cdef double c_z = ctx.p[15]
    cdef double q_z = ctx.p[16]
    cdef double s_g = ctx.p[17]
    cdef double s_r = ctx.p[18]
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
    cdef double _k21 = ctx.k[21]
    cdef double _k22 = ctx.k[22]
    cdef double _k23 = ctx.k[23]
    cdef double _k24 = ctx.k[24]
    cdef double _k25 = ctx.k[25]
    cdef double _k26 = ctx.k[26]
    cdef double _k27 = ctx.k[27]
    cdef double _k28 = ctx.k[28]
    cdef double _k29 = ctx.k[29]
    cdef double _k30 = ctx.k[30]
    cdef double _k31 = ctx.k[31]
    cdef double _k32 = ctx.k[32]
    cdef double _k33 = ctx.k[33]
    cdef double _k34 = ctx.k[34]
    cdef double _k35 = ctx.k[35]
    cdef double _k36 = ctx.k[36]
    cdef double _k37 = ctx.k[37]
    cdef double _k38 = ctx.k[38]
    cdef double _k39 = ctx.k[39]
    cdef double _k40 = ctx.k[40]
    cdef double _k41 = ctx.k[41]
    cdef double _k42 = ctx.k[42]
    cdef double _k43 = ctx.k[43]
    cdef double _k44 = ctx.k[44]
    cdef double _k45 = ctx.k[45]
    cdef double beta = _y[0]
    cdef double y = _y[1]
    cdef double z = _y[2]
    cdef double x = _y[3]
    cdef double betad = _y[4]
    cdef double yd = _y[5]
    cdef double zd = _y[6]
    cdef double xd = _y[7]
    cdef double _cam0[4]  # H(beta/beta_m - beta_0/beta_m) and its derivatives
    cdef int _v = ctx.variant
    cdef double* _c
    cdef double _a
    if _v & 1:
        _cam0[0] = ctx.cache[1]  # H in the dwell, set by refresh()
    else:
        # the stages of a step share arguments (RK4: t + h/2 twice, t + h for the next
        # k1): the last evaluation is kept in ctx.cache and reused
        _a = beta/beta_m - beta_0/beta_m
        _c = &ctx.cache[0]
        if _a == _c[0]:
            _cam0[0], _cam0[1], _cam0[2], _cam0[3] = _c[1], _c[2], _c[3], _c[4]
        else:
            camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], _a, _cam0)
            _c[0], _c[1], _c[2], _c[3], _c[4] = _a, _cam0[0], _cam0[1], _cam0[2], _cam0[3]

    cdef double _s0_0, _s0_1, _s0_2, _s0_3, _s0_4, _s1_0, _s1_1, _s1_2
    _dy[0] = betad
    _dy[1] = yd
    _dy[2] = zd
    _dy[3] = xd
    if _v == 0:
        _s0_0 = _k10*beta + _k11*t + _k12*betad
        _s0_1 = _cam0[2]*y
        _s0_2 = _cam0[0]*_k1 + _cam0[1]*_k3*y + _cam0[1]*_k4*betad + _cam0[1]*_k5*yd + _k0*x + _k0*z + _k2*xd + _k2*zd + _k6*_s0_1*betad
        _s0_3 = ((_s0_2) if ((ctx.mode[2] == 0.0)) else (((0.0) if ((ctx.mode[2] == 1.0)) else (_k7 + _s0_2))))
        _s0_4 = _cam0[1]*_s0_3
        _dy[4] = _k15*(_k8*_s0_4 + _k9*_s0_1*_s0_3 + ((_k13 + _s0_0) if ((ctx.mode[1] == 0.0)) else (((0.0) if ((ctx.mode[1] == 1.0)) else (_k14 + _s0_0)))))
        _dy[5] = _k16*y + _k17*yd + _k18*_s0_4
        _dy[6] = _k21*(_k19*z + _k20*zd + _s0_3)
        _dy[7] = _k22*_s0_3
    elif _v == 1:  # in a dwell: 0
        _s1_0 = _k10*beta + _k11*t + _k12*betad
        _s1_1 = _cam0[0]*_k1 + _k0*x + _k0*z + _k2*xd + _k2*zd
        _s1_2 = ((_s1_1) if ((ctx.mode[2] == 0.0)) else (((0.0) if ((ctx.mode[2] == 1.0)) else (_k7 + _s1_1))))
        _dy[4] = _k15*((_k13 + _s1_0) if ((ctx.mode[1] == 0.0)) else (((0.0) if ((ctx.mode[1] == 1.0)) else (_k14 + _s1_0))))
        _dy[5] = _k16*y + _k17*yd
        _dy[6] = _k21*(_k19*z + _k20*zd + _s1_2)
        _dy[7] = _k22*_s1_2


cdef void outputs(double t, const double* _y, double* _out, Ctx* ctx) noexcept nogil:
    """The named outputs (B, Xdd, Bdd, U, xdd, torque, Fx, speed_var, tan_alpha, gear_gap, roller_gap)."""
    cdef double _dy[8]
    rhs(t, _y, _dy, ctx)
    cdef double h_m = ctx.p[0]
    cdef double beta_m = ctx.p[1]
    cdef double beta_0 = ctx.p[2]
    cdef double R_b = ctx.p[3]
    cdef double omega_s = ctx.p[4]
    cdef double J = ctx.p[5]
    cdef double k = ctx.p[6]
    cdef double q_b = ctx.p[7]
    cdef double m_x = ctx.p[8]
    cdef double c_x = ctx.p[9]
    cdef double q_x = ctx.p[10]
    cdef double m_y = ctx.p[11]
    cdef double c_y = ctx.p[12]
    cdef double q_y = ctx.p[13]
    cdef double m_z = ctx.p[14]
    cdef double c_z = ctx.p[15]
    cdef double q_z = ctx.p[16]
    cdef double s_g = ctx.p[17]
    cdef double s_r = ctx.p[18]
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
    cdef double _k21 = ctx.k[21]
    cdef double _k22 = ctx.k[22]
    cdef double _k23 = ctx.k[23]
    cdef double _k24 = ctx.k[24]
    cdef double _k25 = ctx.k[25]
    cdef double _k26 = ctx.k[26]
    cdef double _k27 = ctx.k[27]
    cdef double _k28 = ctx.k[28]
    cdef double _k29 = ctx.k[29]
    cdef double _k30 = ctx.k[30]
    cdef double _k31 = ctx.k[31]
    cdef double _k32 = ctx.k[32]
    cdef double _k33 = ctx.k[33]
    cdef double _k34 = ctx.k[34]
    cdef double _k35 = ctx.k[35]
    cdef double _k36 = ctx.k[36]
    cdef double _k37 = ctx.k[37]
    cdef double _k38 = ctx.k[38]
    cdef double _k39 = ctx.k[39]
    cdef double _k40 = ctx.k[40]
    cdef double _k41 = ctx.k[41]
    cdef double _k42 = ctx.k[42]
    cdef double _k43 = ctx.k[43]
    cdef double _k44 = ctx.k[44]
    cdef double _k45 = ctx.k[45]
    cdef double beta = _y[0]
    cdef double y = _y[1]
    cdef double z = _y[2]
    cdef double x = _y[3]
    cdef double betad = _y[4]
    cdef double yd = _y[5]
    cdef double zd = _y[6]
    cdef double xd = _y[7]
    cdef double betadd = _dy[4]
    cdef double ydd = _dy[5]
    cdef double zdd = _dy[6]
    cdef double xdd = _dy[7]
    cdef double _cam0[4]  # H(beta/beta_m - beta_0/beta_m) and its derivatives
    cdef double* _c
    # rhs() has just evaluated this input at the same argument and kept it (outside a dwell)
    _c = &ctx.cache[0]
    if _c[0] == beta/beta_m - beta_0/beta_m:
        _cam0[0], _cam0[1], _cam0[2], _cam0[3] = _c[1], _c[2], _c[3], _c[4]
    else:
        camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], beta/beta_m - beta_0/beta_m, _cam0)

    cdef double _o0 = _cam0[0]*_k27 + x
    cdef double _o1 = _k29*(betad - omega_s)
    cdef double _o2 = (ctx.mode[1] == 0.0)
    cdef double _o3 = (ctx.mode[1] == 1.0)
    cdef double _o4 = _k33*(_cam0[1]*_k32*yd + betad*(_cam0[1]*_k30 + _cam0[2]*_k31*y) - xd - zd)
    cdef double _o5 = (ctx.mode[2] == 0.0)
    cdef double _o6 = (ctx.mode[2] == 1.0)
    cdef double _o7 = _cam0[1]*_k35
    cdef double _o8 = _o0 + _o7*y + z
    _out[0] = _k24*(_k23 + beta)  # B
    _out[1] = _k25*_dy[7]  # Xdd
    _out[2] = _k26*_dy[4]  # Bdd
    _out[3] = _k28*_o0  # U
    _out[4] = _dy[7]  # xdd
    _out[5] = ((_k10*beta + _k11*t - _o1) if (_o2) else (((0.0) if (_o3) else (-_o1 + k*(-beta + omega_s*t + s_g)))))  # torque
    _out[6] = ((_cam0[0]*_k1 + _cam0[1]*_k3*y + _k0*x + _k0*z + _o4) if (_o5) else (((0.0) if (_o6) else (_k0*(_k34 + _o8) + _o4))))  # Fx
    _out[7] = _k37*(_k36*yd + betad) - 1.0  # speed_var
    _out[8] = _o7  # tan_alpha
    _out[9] = ((0.0) if (_o2) else (((-beta + omega_s*t) if (_o3) else (_k38))))  # gear_gap
    _out[10] = ((0.0) if (_o5) else (((_o8) if (_o6) else (s_r))))  # roller_gap


cdef void mass_stiffness(double t, const double* _y, double* _Mm, double* _Km, Ctx* ctx) noexcept nogil:
    """Mass matrix M and stiffness K = -df/dq (row-major, n x n) at (t, y), for frozen analyses."""
    cdef double h_m = ctx.p[0]
    cdef double beta_m = ctx.p[1]
    cdef double beta_0 = ctx.p[2]
    cdef double R_b = ctx.p[3]
    cdef double omega_s = ctx.p[4]
    cdef double J = ctx.p[5]
    cdef double k = ctx.p[6]
    cdef double q_b = ctx.p[7]
    cdef double m_x = ctx.p[8]
    cdef double c_x = ctx.p[9]
    cdef double q_x = ctx.p[10]
    cdef double m_y = ctx.p[11]
    cdef double c_y = ctx.p[12]
    cdef double q_y = ctx.p[13]
    cdef double m_z = ctx.p[14]
    cdef double c_z = ctx.p[15]
    cdef double q_z = ctx.p[16]
    cdef double s_g = ctx.p[17]
    cdef double s_r = ctx.p[18]
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
    cdef double _k21 = ctx.k[21]
    cdef double _k22 = ctx.k[22]
    cdef double _k23 = ctx.k[23]
    cdef double _k24 = ctx.k[24]
    cdef double _k25 = ctx.k[25]
    cdef double _k26 = ctx.k[26]
    cdef double _k27 = ctx.k[27]
    cdef double _k28 = ctx.k[28]
    cdef double _k29 = ctx.k[29]
    cdef double _k30 = ctx.k[30]
    cdef double _k31 = ctx.k[31]
    cdef double _k32 = ctx.k[32]
    cdef double _k33 = ctx.k[33]
    cdef double _k34 = ctx.k[34]
    cdef double _k35 = ctx.k[35]
    cdef double _k36 = ctx.k[36]
    cdef double _k37 = ctx.k[37]
    cdef double _k38 = ctx.k[38]
    cdef double _k39 = ctx.k[39]
    cdef double _k40 = ctx.k[40]
    cdef double _k41 = ctx.k[41]
    cdef double _k42 = ctx.k[42]
    cdef double _k43 = ctx.k[43]
    cdef double _k44 = ctx.k[44]
    cdef double _k45 = ctx.k[45]
    cdef double beta = _y[0]
    cdef double y = _y[1]
    cdef double z = _y[2]
    cdef double x = _y[3]
    cdef double betad = _y[4]
    cdef double yd = _y[5]
    cdef double zd = _y[6]
    cdef double xd = _y[7]
    cdef double _cam0[4]  # H(beta/beta_m - beta_0/beta_m) and its derivatives
    camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], beta/beta_m - beta_0/beta_m, _cam0)

    _Mm[0] = J
    _Mm[1] = 0.0
    _Mm[2] = 0.0
    _Mm[3] = 0.0
    _Mm[4] = 0.0
    _Mm[5] = m_y
    _Mm[6] = 0.0
    _Mm[7] = 0.0
    _Mm[8] = 0.0
    _Mm[9] = 0.0
    _Mm[10] = m_z
    _Mm[11] = 0.0
    _Mm[12] = 0.0
    _Mm[13] = 0.0
    _Mm[14] = 0.0
    _Mm[15] = m_x
    _Km[0] = 0.0 / 0.0
    _Km[1] = 0.0 / 0.0
    _Km[2] = 0.0 / 0.0
    _Km[3] = 0.0 / 0.0
    _Km[4] = 0.0 / 0.0
    _Km[5] = 0.0 / 0.0
    _Km[6] = 0.0 / 0.0
    _Km[7] = 0.0 / 0.0
    _Km[8] = 0.0 / 0.0
    _Km[9] = 0.0 / 0.0
    _Km[10] = 0.0 / 0.0
    _Km[11] = 0.0 / 0.0
    _Km[12] = 0.0 / 0.0
    _Km[13] = 0.0 / 0.0
    _Km[14] = 0.0 / 0.0
    _Km[15] = 0.0 / 0.0


cdef void jacobian(double t, const double* _y, double* _J, double* _ft, Ctx* ctx) noexcept nogil:
    """d(dy/dt)/dy at (t, y), row-major _NS x _NS, derived symbolically (CSE'd): the Jacobian
    of the general right-hand side in the current modes, a cam input in a dwell taking its
    dwell values.
    With _ft not NULL also df/dt there (_NS values), derived the same way."""
    cdef double h_m = ctx.p[0]
    cdef double beta_m = ctx.p[1]
    cdef double beta_0 = ctx.p[2]
    cdef double R_b = ctx.p[3]
    cdef double omega_s = ctx.p[4]
    cdef double J = ctx.p[5]
    cdef double k = ctx.p[6]
    cdef double q_b = ctx.p[7]
    cdef double m_x = ctx.p[8]
    cdef double c_x = ctx.p[9]
    cdef double q_x = ctx.p[10]
    cdef double m_y = ctx.p[11]
    cdef double c_y = ctx.p[12]
    cdef double q_y = ctx.p[13]
    cdef double m_z = ctx.p[14]
    cdef double c_z = ctx.p[15]
    cdef double q_z = ctx.p[16]
    cdef double s_g = ctx.p[17]
    cdef double s_r = ctx.p[18]
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
    cdef double _k21 = ctx.k[21]
    cdef double _k22 = ctx.k[22]
    cdef double _k23 = ctx.k[23]
    cdef double _k24 = ctx.k[24]
    cdef double _k25 = ctx.k[25]
    cdef double _k26 = ctx.k[26]
    cdef double _k27 = ctx.k[27]
    cdef double _k28 = ctx.k[28]
    cdef double _k29 = ctx.k[29]
    cdef double _k30 = ctx.k[30]
    cdef double _k31 = ctx.k[31]
    cdef double _k32 = ctx.k[32]
    cdef double _k33 = ctx.k[33]
    cdef double _k34 = ctx.k[34]
    cdef double _k35 = ctx.k[35]
    cdef double _k36 = ctx.k[36]
    cdef double _k37 = ctx.k[37]
    cdef double _k38 = ctx.k[38]
    cdef double _k39 = ctx.k[39]
    cdef double _k40 = ctx.k[40]
    cdef double _k41 = ctx.k[41]
    cdef double _k42 = ctx.k[42]
    cdef double _k43 = ctx.k[43]
    cdef double _k44 = ctx.k[44]
    cdef double _k45 = ctx.k[45]
    cdef double beta = _y[0]
    cdef double y = _y[1]
    cdef double z = _y[2]
    cdef double x = _y[3]
    cdef double betad = _y[4]
    cdef double yd = _y[5]
    cdef double zd = _y[6]
    cdef double xd = _y[7]
    cdef double _cam0[4]  # H(beta/beta_m - beta_0/beta_m) and its derivatives
    camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], beta/beta_m - beta_0/beta_m, _cam0)

    cdef int _k
    cdef double _ftl[8]
    for _k in range(64):
        _J[_k] = 0.0
    for _k in range(8):
        _ftl[_k] = 0.0
    for _k in range(4):
        _J[_k * 9 + 4] = 1.0  # d q'/d q'
    cdef double _j0 = (ctx.mode[1] == 0.0)
    cdef double _j1 = (ctx.mode[1] == 1.0)
    cdef double _j2 = _cam0[1]*_k8
    cdef double _j3 = _k9*y
    cdef double _j4 = _cam0[2]*_j3
    cdef double _j5 = (ctx.mode[2] == 0.0)
    cdef double _j6 = (ctx.mode[2] == 1.0)
    cdef double _j7 = ((_k1) if (_j5) else (((0.0) if (_j6) else (_k1))))
    cdef double _j8 = _cam0[1]*_j7
    cdef double _j9 = _k6*betad
    cdef double _j10 = _j9*y
    cdef double _j11 = ((_j10) if (_j5) else (((0.0) if (_j6) else (_j10))))
    cdef double _j12 = _k3*y
    cdef double _j13 = _k4*betad
    cdef double _j14 = _k5*yd
    cdef double _j15 = _cam0[0]*_k1 + _cam0[1]*_j12 + _cam0[1]*_j13 + _cam0[1]*_j14 + _cam0[2]*_j10 + _k0*x + _k0*z + _k2*xd + _k2*zd
    cdef double _j16 = ((_j15) if (_j5) else (((0.0) if (_j6) else (_j15 + _k7))))
    cdef double _j17 = _j12 + _j13 + _j14
    cdef double _j18 = ((_j17) if (_j5) else (((0.0) if (_j6) else (_j17))))
    cdef double _j19 = _cam0[2]*_j18
    cdef double _j20 = _cam0[1]*_k3 + _cam0[2]*_j9
    cdef double _j21 = ((_j20) if (_j5) else (((0.0) if (_j6) else (_j20))))
    cdef double _j22 = _cam0[1]*_k40
    cdef double _j23 = _cam0[2]*_k41
    cdef double _j24 = _j23*y
    cdef double _j25 = _j22 + _j24
    cdef double _j26 = ((_k0) if (_j5) else (((0.0) if (_j6) else (_k0))))
    cdef double _j27 = _j25*_j26
    cdef double _j28 = _cam0[1]*_k4 + _cam0[2]*_k6*y
    cdef double _j29 = ((_j28) if (_j5) else (((0.0) if (_j6) else (_j28))))
    cdef double _j30 = _cam0[1]*_k5
    cdef double _j31 = ((_j30) if (_j5) else (((0.0) if (_j6) else (_j30))))
    cdef double _j32 = ((_k2) if (_j5) else (((0.0) if (_j6) else (_k2))))
    cdef double _j33 = _j25*_j32
    cdef double _j34 = _cam0[3]*_j11
    cdef double _j35 = _cam0[1]*_k18
    cdef double _j36 = _j26*_j35
    cdef double _j37 = _j32*_j35
    cdef double _j38 = _j19 + _j34 + _j8
    cdef double _j39 = _j26*_k22
    cdef double _j40 = _j32*_k22
    _J[32] = _cam0[2]*_k39*(_j16*_k8 + _j18*_j2 + _j19*_j3) + _cam0[3]*_k39*(_j11*_j2 + _j11*_j4 + _j16*_j3) + _j8*_k39*(_j2 + _j4) + _k15*((_k10) if (_j0) else (((0.0) if (_j1) else (_k10))))
    _J[33] = _j16*_j23 + _j21*_j22 + _j21*_j24
    _J[34] = _j27
    _J[35] = _j27
    _J[36] = _k15*(_j2*_j29 + _j29*_j4 + ((_k12) if (_j0) else (((0.0) if (_j1) else (_k12)))))
    _J[37] = _j25*_j31
    _J[38] = _j33
    _J[39] = _j33
    _J[40] = (_cam0[1]*_cam0[1])*_j7*_k43 + _cam0[1]*_j34*_k43 + _cam0[2]*_k35*_k42*(_cam0[1]*_j18 + _j16)
    _J[41] = _j21*_j35 + _k16
    _J[42] = _j36
    _J[43] = _j36
    _J[44] = _j29*_j35
    _J[45] = _j31*_j35 + _k17
    _J[46] = _j37
    _J[47] = _j37
    _J[48] = _j38*_k44
    _J[49] = _j21*_k21
    _J[50] = _k21*(_j26 + _k19)
    _J[51] = _j26*_k21
    _J[52] = _j29*_k21
    _J[53] = _j31*_k21
    _J[54] = _k21*(_j32 + _k20)
    _J[55] = _j32*_k21
    _J[56] = _j38*_k45
    _J[57] = _j21*_k22
    _J[58] = _j39
    _J[59] = _j39
    _J[60] = _j29*_k22
    _J[61] = _j31*_k22
    _J[62] = _j40
    _J[63] = _j40
    _ftl[4] = _k15*((_k11) if (_j0) else (((0.0) if (_j1) else (_k11))))
    if _ft != NULL:
        for _k in range(8):
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
    cdef double h_m = ctx.p[0]
    cdef double beta_m = ctx.p[1]
    cdef double beta_0 = ctx.p[2]
    cdef double R_b = ctx.p[3]
    cdef double omega_s = ctx.p[4]
    cdef double J = ctx.p[5]
    cdef double k = ctx.p[6]
    cdef double q_b = ctx.p[7]
    cdef double m_x = ctx.p[8]
    cdef double c_x = ctx.p[9]
    cdef double q_x = ctx.p[10]
    cdef double m_y = ctx.p[11]
    cdef double c_y = ctx.p[12]
    cdef double q_y = ctx.p[13]
    cdef double m_z = ctx.p[14]
    cdef double c_z = ctx.p[15]
    cdef double q_z = ctx.p[16]
    cdef double s_g = ctx.p[17]
    cdef double s_r = ctx.p[18]
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
    cdef double _k21 = ctx.k[21]
    cdef double _k22 = ctx.k[22]
    cdef double _k23 = ctx.k[23]
    cdef double _k24 = ctx.k[24]
    cdef double _k25 = ctx.k[25]
    cdef double _k26 = ctx.k[26]
    cdef double _k27 = ctx.k[27]
    cdef double _k28 = ctx.k[28]
    cdef double _k29 = ctx.k[29]
    cdef double _k30 = ctx.k[30]
    cdef double _k31 = ctx.k[31]
    cdef double _k32 = ctx.k[32]
    cdef double _k33 = ctx.k[33]
    cdef double _k34 = ctx.k[34]
    cdef double _k35 = ctx.k[35]
    cdef double _k36 = ctx.k[36]
    cdef double _k37 = ctx.k[37]
    cdef double _k38 = ctx.k[38]
    cdef double _k39 = ctx.k[39]
    cdef double _k40 = ctx.k[40]
    cdef double _k41 = ctx.k[41]
    cdef double _k42 = ctx.k[42]
    cdef double _k43 = ctx.k[43]
    cdef double _k44 = ctx.k[44]
    cdef double _k45 = ctx.k[45]
    cdef double beta = _y[0]
    cdef double y = _y[1]
    cdef double z = _y[2]
    cdef double x = _y[3]
    cdef double betad = _y[4]
    cdef double yd = _y[5]
    cdef double zd = _y[6]
    cdef double xd = _y[7]

    ctx.mode[0] = camlaw_segment(ctx.law[0], ctx.law_par[0], beta/beta_m - beta_0/beta_m)
    refresh(ctx)


cdef void events(double t, const double* _y, double* _g, Ctx* ctx) noexcept nogil:
    """Event functions; an event not armed in the current modes reads 1 (never crosses)."""
    cdef double h_m = ctx.p[0]
    cdef double beta_m = ctx.p[1]
    cdef double beta_0 = ctx.p[2]
    cdef double R_b = ctx.p[3]
    cdef double omega_s = ctx.p[4]
    cdef double J = ctx.p[5]
    cdef double k = ctx.p[6]
    cdef double q_b = ctx.p[7]
    cdef double m_x = ctx.p[8]
    cdef double c_x = ctx.p[9]
    cdef double q_x = ctx.p[10]
    cdef double m_y = ctx.p[11]
    cdef double c_y = ctx.p[12]
    cdef double q_y = ctx.p[13]
    cdef double m_z = ctx.p[14]
    cdef double c_z = ctx.p[15]
    cdef double q_z = ctx.p[16]
    cdef double s_g = ctx.p[17]
    cdef double s_r = ctx.p[18]
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
    cdef double _k21 = ctx.k[21]
    cdef double _k22 = ctx.k[22]
    cdef double _k23 = ctx.k[23]
    cdef double _k24 = ctx.k[24]
    cdef double _k25 = ctx.k[25]
    cdef double _k26 = ctx.k[26]
    cdef double _k27 = ctx.k[27]
    cdef double _k28 = ctx.k[28]
    cdef double _k29 = ctx.k[29]
    cdef double _k30 = ctx.k[30]
    cdef double _k31 = ctx.k[31]
    cdef double _k32 = ctx.k[32]
    cdef double _k33 = ctx.k[33]
    cdef double _k34 = ctx.k[34]
    cdef double _k35 = ctx.k[35]
    cdef double _k36 = ctx.k[36]
    cdef double _k37 = ctx.k[37]
    cdef double _k38 = ctx.k[38]
    cdef double _k39 = ctx.k[39]
    cdef double _k40 = ctx.k[40]
    cdef double _k41 = ctx.k[41]
    cdef double _k42 = ctx.k[42]
    cdef double _k43 = ctx.k[43]
    cdef double _k44 = ctx.k[44]
    cdef double _k45 = ctx.k[45]
    cdef double beta = _y[0]
    cdef double y = _y[1]
    cdef double z = _y[2]
    cdef double x = _y[3]
    cdef double betad = _y[4]
    cdef double yd = _y[5]
    cdef double zd = _y[6]
    cdef double xd = _y[7]
    cdef double _cam0[4]  # H(beta/beta_m - beta_0/beta_m) and its derivatives
    camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], beta/beta_m - beta_0/beta_m, _cam0)

    _g[0] = (-beta + omega_s*t) if (ctx.mode[1] == 0.0) else 1.0  # gear_lift_drive
    _g[1] = (-beta + omega_s*t) if (ctx.mode[1] == 1.0) else 1.0  # gear_hit_drive
    _g[2] = (-beta + omega_s*t + s_g) if (ctx.mode[1] == 1.0) else 1.0  # gear_hit_back
    _g[3] = (-beta + omega_s*t + s_g) if (ctx.mode[1] == 2.0) else 1.0  # gear_lift_back
    _g[4] = (_cam0[0]*h_m - x - z - _cam0[1]*h_m*y/(R_b*beta_m)) if (ctx.mode[2] == 0.0) else 1.0  # roller_leave_lower
    _g[5] = (_cam0[0]*h_m - x - z - _cam0[1]*h_m*y/(R_b*beta_m)) if (ctx.mode[2] == 1.0) else 1.0  # roller_hit_lower
    _g[6] = (-_cam0[0]*h_m - s_r + x + z + _cam0[1]*h_m*y/(R_b*beta_m)) if (ctx.mode[2] == 1.0) else 1.0  # roller_hit_upper
    _g[7] = (-_cam0[0]*h_m - s_r + x + z + _cam0[1]*h_m*y/(R_b*beta_m)) if (ctx.mode[2] == 2.0) else 1.0  # roller_leave_upper
    _g[8] = (beta/beta_m - beta_0/beta_m) - camlaw_hi(ctx.law[0], ctx.law_par[0], ctx.mode[0])  # cam0_hi: next segment
    _g[9] = (beta/beta_m - beta_0/beta_m) - camlaw_lo(ctx.law[0], ctx.law_par[0], ctx.mode[0])  # cam0_lo: previous segment


cdef void on_event(int _e, double t, double* _y, Ctx* ctx) noexcept nogil:
    """What event k does: new modes (and state resets) at its crossing."""
    cdef double h_m = ctx.p[0]
    cdef double beta_m = ctx.p[1]
    cdef double beta_0 = ctx.p[2]
    cdef double R_b = ctx.p[3]
    cdef double omega_s = ctx.p[4]
    cdef double J = ctx.p[5]
    cdef double k = ctx.p[6]
    cdef double q_b = ctx.p[7]
    cdef double m_x = ctx.p[8]
    cdef double c_x = ctx.p[9]
    cdef double q_x = ctx.p[10]
    cdef double m_y = ctx.p[11]
    cdef double c_y = ctx.p[12]
    cdef double q_y = ctx.p[13]
    cdef double m_z = ctx.p[14]
    cdef double c_z = ctx.p[15]
    cdef double q_z = ctx.p[16]
    cdef double s_g = ctx.p[17]
    cdef double s_r = ctx.p[18]
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
    cdef double _k21 = ctx.k[21]
    cdef double _k22 = ctx.k[22]
    cdef double _k23 = ctx.k[23]
    cdef double _k24 = ctx.k[24]
    cdef double _k25 = ctx.k[25]
    cdef double _k26 = ctx.k[26]
    cdef double _k27 = ctx.k[27]
    cdef double _k28 = ctx.k[28]
    cdef double _k29 = ctx.k[29]
    cdef double _k30 = ctx.k[30]
    cdef double _k31 = ctx.k[31]
    cdef double _k32 = ctx.k[32]
    cdef double _k33 = ctx.k[33]
    cdef double _k34 = ctx.k[34]
    cdef double _k35 = ctx.k[35]
    cdef double _k36 = ctx.k[36]
    cdef double _k37 = ctx.k[37]
    cdef double _k38 = ctx.k[38]
    cdef double _k39 = ctx.k[39]
    cdef double _k40 = ctx.k[40]
    cdef double _k41 = ctx.k[41]
    cdef double _k42 = ctx.k[42]
    cdef double _k43 = ctx.k[43]
    cdef double _k44 = ctx.k[44]
    cdef double _k45 = ctx.k[45]
    cdef double beta = _y[0]
    cdef double y = _y[1]
    cdef double z = _y[2]
    cdef double x = _y[3]
    cdef double betad = _y[4]
    cdef double yd = _y[5]
    cdef double zd = _y[6]
    cdef double xd = _y[7]
    cdef double _cam0[4]  # H(beta/beta_m - beta_0/beta_m) and its derivatives
    camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], beta/beta_m - beta_0/beta_m, _cam0)

    if _e == 0:  # gear_lift_drive
        if True:
            ctx.mode[1] = 1  # gear = free
    elif _e == 1:  # gear_hit_drive
        if True:
            ctx.mode[1] = 0  # gear = drive
    elif _e == 2:  # gear_hit_back
        if True:
            ctx.mode[1] = 2  # gear = back
    elif _e == 3:  # gear_lift_back
        if True:
            ctx.mode[1] = 1  # gear = free
    elif _e == 4:  # roller_leave_lower
        if True:
            ctx.mode[2] = 1  # roller = free
    elif _e == 5:  # roller_hit_lower
        if True:
            ctx.mode[2] = 0  # roller = lower
    elif _e == 6:  # roller_hit_upper
        if True:
            ctx.mode[2] = 2  # roller = upper
    elif _e == 7:  # roller_leave_upper
        if True:
            ctx.mode[2] = 1  # roller = free
    elif _e == 8:  # cam0_hi
        ctx.mode[0] += 1
    elif _e == 9:  # cam0_lo
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
    cdef double h_m = p[0]
    cdef double beta_m = p[1]
    cdef double beta_0 = p[2]
    cdef double R_b = p[3]
    cdef double omega_s = p[4]
    cdef double J = p[5]
    cdef double k = p[6]
    cdef double q_b = p[7]
    cdef double m_x = p[8]
    cdef double c_x = p[9]
    cdef double q_x = p[10]
    cdef double m_y = p[11]
    cdef double c_y = p[12]
    cdef double q_y = p[13]
    cdef double m_z = p[14]
    cdef double c_z = p[15]
    cdef double q_z = p[16]
    cdef double s_g = p[17]
    cdef double s_r = p[18]
    return [0.0, 0.0, 0.0, 0.0, omega_s, 0.0, 0.0, 0.0]


def cam_time_affine(p):
    """Per cam input, (a, b) with argument a t + b, or None when it depends on the state."""
    cdef double h_m = p[0]
    cdef double beta_m = p[1]
    cdef double beta_0 = p[2]
    cdef double R_b = p[3]
    cdef double omega_s = p[4]
    cdef double J = p[5]
    cdef double k = p[6]
    cdef double q_b = p[7]
    cdef double m_x = p[8]
    cdef double c_x = p[9]
    cdef double q_x = p[10]
    cdef double m_y = p[11]
    cdef double c_y = p[12]
    cdef double q_y = p[13]
    cdef double m_z = p[14]
    cdef double c_z = p[15]
    cdef double q_z = p[16]
    cdef double s_g = p[17]
    cdef double s_r = p[18]
    return [None]


cdef ModelC _model
_model.abi_version = CAMDYN_ABI
_model.n_q = _NQ
_model.n_states = _NS
_model.n_params = 19
_model.n_outputs = 11
_model.n_families = 1
_model.n_instances = _NCAM
_model.n_modes = _NM
_model.n_events = _NE
_model.n_const = 46
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
   "argument": "beta/beta_m - beta_0/beta_m",
   "family": "H",
   "order": 2,
   "time_affine": false
  }
 ],
 "events": [
  "gear_lift_drive",
  "gear_hit_drive",
  "gear_hit_back",
  "gear_lift_back",
  "roller_leave_lower",
  "roller_hit_lower",
  "roller_hit_upper",
  "roller_leave_upper",
  "cam0_hi",
  "cam0_lo"
 ],
 "jacobian": "symbolic",
 "modes": [
  {
   "doc": "flank of the reduction gear in contact",
   "initial": "drive",
   "name": "gear",
   "values": [
    "drive",
    "free",
    "back"
   ]
  },
  {
   "doc": "groove wall the roller touches",
   "initial": "lower",
   "name": "roller",
   "values": [
    "lower",
    "free",
    "upper"
   ]
  }
 ],
 "n_q": 4,
 "name": "dynacam_axial_ideal_backlash_groove_shafty_shaftz",
 "options": [
  [
   "cam",
   "axial"
  ],
  [
   "cam_friction",
   false
  ],
  [
   "external",
   false
  ],
  [
   "flat_face",
   false
  ],
  [
   "gear",
   "backlash"
  ],
  [
   "linkage_friction",
   false
  ],
  [
   "motor",
   "constant"
  ],
  [
   "rocker",
   false
  ],
  [
   "roller",
   "groove"
  ],
  [
   "shaft_y",
   true
  ],
  [
   "shaft_z",
   true
  ],
  [
   "spring",
   false
  ]
 ],
 "outputs": [
  {
   "doc": "cam angle over the rise angle (6.17)",
   "name": "B",
   "unit": "1"
  },
  {
   "doc": "follower acceleration x'' t_m^2/h_m",
   "name": "Xdd",
   "unit": "1"
  },
  {
   "doc": "cam angular acceleration beta'' t_m^2/beta_m",
   "name": "Bdd",
   "unit": "1"
  },
  {
   "doc": "positional error over the stroke, (x - h(beta))/h_m",
   "name": "U",
   "unit": "1"
  },
  {
   "doc": "follower acceleration",
   "name": "xdd",
   "unit": "m/s^2"
  },
  {
   "doc": "shaft torque driving the cam (6.10)",
   "name": "torque",
   "unit": "N m"
  },
  {
   "doc": "force between cam and follower linkage (6.42)",
   "name": "Fx",
   "unit": "N"
  },
  {
   "doc": "variation of the fictitious angular velocity seen by the roller (2.54)",
   "name": "speed_var",
   "unit": "1"
  },
  {
   "doc": "cam slope (6.20); a rocker's ratio i_y (_rocker, _rocker_flat), 0 for a translating flat face",
   "name": "tan_alpha",
   "unit": "1"
  },
  {
   "doc": "input minus gear output angle (6.1): 0 on the driving flank, -s_g on the other",
   "name": "gear_gap",
   "unit": "rad"
  },
  {
   "doc": "roller position in the groove over the cam wall: 0 lower wall, s_r upper",
   "name": "roller_gap",
   "unit": "m"
  }
 ],
 "parameters": [
  {
   "default": 0.015,
   "doc": "stroke of the output member (reduced)",
   "high": null,
   "low": 0.0,
   "name": "h_m",
   "open_high": false,
   "open_low": true,
   "range": "0 < h_m",
   "unit": "m"
  },
  {
   "default": 0.436,
   "doc": "cam angle of the rise (within one turn)",
   "high": 6.283185307179586,
   "low": 0.0,
   "name": "beta_m",
   "open_high": false,
   "open_low": true,
   "range": "0 < beta_m <= 6.28319",
   "unit": "rad"
  },
  {
   "default": 0.0,
   "doc": "cam angle where the rise starts",
   "high": null,
   "low": -100.0,
   "name": "beta_0",
   "open_high": false,
   "open_low": false,
   "range": "-100 <= beta_0",
   "unit": "rad"
  },
  {
   "default": 0.0675,
   "doc": "base pitch radius (reduced) (6.21)",
   "high": null,
   "low": 0.0,
   "name": "R_b",
   "open_high": false,
   "open_low": true,
   "range": "0 < R_b",
   "unit": "m"
  },
  {
   "default": 4.95,
   "doc": "nominal angular velocity of the camshaft",
   "high": null,
   "low": 0.0,
   "name": "omega_s",
   "open_high": false,
   "open_low": true,
   "range": "0 < omega_s",
   "unit": "rad/s"
  },
  {
   "default": 0.01,
   "doc": "polar moment of inertia of the cam, reduced to the output member",
   "high": null,
   "low": 0.0,
   "name": "J",
   "open_high": false,
   "open_low": true,
   "range": "0 < J",
   "unit": "kg m^2"
  },
  {
   "default": 1000.0,
   "doc": "torsional stiffness between gear and cam (6.10)",
   "high": null,
   "low": 0.0,
   "name": "k",
   "open_high": false,
   "open_low": true,
   "range": "0 < k",
   "unit": "N m/rad"
  },
  {
   "default": 0.05,
   "doc": "relative damping of the torsion (6.47)",
   "high": 1.0,
   "low": 0.0,
   "name": "q_b",
   "open_high": false,
   "open_low": false,
   "range": "0 <= q_b <= 1",
   "unit": "1"
  },
  {
   "default": 1.46,
   "doc": "equivalent follower mass",
   "high": null,
   "low": 0.0,
   "name": "m_x",
   "open_high": false,
   "open_low": true,
   "range": "0 < m_x",
   "unit": "kg"
  },
  {
   "default": 376000.0,
   "doc": "linkage stiffness at the roller (6.42)",
   "high": null,
   "low": 0.0,
   "name": "c_x",
   "open_high": false,
   "open_low": true,
   "range": "0 < c_x",
   "unit": "N/m"
  },
  {
   "default": 0.023,
   "doc": "relative damping of the linkage (6.47)",
   "high": 1.0,
   "low": 0.0,
   "name": "q_x",
   "open_high": false,
   "open_low": false,
   "range": "0 <= q_x <= 1",
   "unit": "1"
  },
  {
   "default": 0.1,
   "doc": "cam mass in the tangential direction (6.16)",
   "high": null,
   "low": 0.0,
   "name": "m_y",
   "open_high": false,
   "open_low": true,
   "range": "0 < m_y",
   "unit": "kg"
  },
  {
   "default": 1000000.0,
   "doc": "tangential shaft stiffness (6.12)",
   "high": null,
   "low": 0.0,
   "name": "c_y",
   "open_high": false,
   "open_low": true,
   "range": "0 < c_y",
   "unit": "N/m"
  },
  {
   "default": 0.05,
   "doc": "relative damping, tangential (6.47)",
   "high": 1.0,
   "low": 0.0,
   "name": "q_y",
   "open_high": false,
   "open_low": false,
   "range": "0 <= q_y <= 1",
   "unit": "1"
  },
  {
   "default": 0.1,
   "doc": "cam mass along the follower (6.15)",
   "high": null,
   "low": 0.0,
   "name": "m_z",
   "open_high": false,
   "open_low": true,
   "range": "0 < m_z",
   "unit": "kg"
  },
  {
   "default": 1000000.0,
   "doc": "shaft stiffness along the follower (6.11)",
   "high": null,
   "low": 0.0,
   "name": "c_z",
   "open_high": false,
   "open_low": true,
   "range": "0 < c_z",
   "unit": "N/m"
  },
  {
   "default": 0.05,
   "doc": "relative damping along the follower (6.47)",
   "high": 1.0,
   "low": 0.0,
   "name": "q_z",
   "open_high": false,
   "open_low": false,
   "range": "0 <= q_z <= 1",
   "unit": "1"
  },
  {
   "default": 0.01,
   "doc": "backlash of the reduction gear, reduced to the camshaft (6.1)",
   "high": null,
   "low": 0.0,
   "name": "s_g",
   "open_high": false,
   "open_low": true,
   "range": "0 < s_g",
   "unit": "rad"
  },
  {
   "default": 0.00013,
   "doc": "backlash of the roller in its groove (6.27)",
   "high": null,
   "low": 0.0,
   "name": "s_r",
   "open_high": false,
   "open_low": true,
   "range": "0 < s_r",
   "unit": "m"
  }
 ],
 "reference": "thesis ch. 6, figs 6.1, 6.2, 6.15, 6.18",
 "residual": {
  "acceleration": "Xdd",
  "error": "U",
  "rise_end": 1.0,
  "rise_state": "B"
 },
 "source_hash": "sha256:20057f71b91ba1e26afc2d2e794ae3ecfcc9a5b84e3371830277eacbb8275d82",
 "states": [
  {
   "doc": "cam angle",
   "initial": 0.0,
   "name": "beta",
   "scale": 1.0,
   "unit": "rad"
  },
  {
   "doc": "tangential deflection of the camshaft",
   "initial": 0.0,
   "name": "y",
   "scale": 1e-05,
   "unit": "m"
  },
  {
   "doc": "deflection of the camshaft along the follower",
   "initial": 0.0,
   "name": "z",
   "scale": 1e-05,
   "unit": "m"
  },
  {
   "doc": "follower output position",
   "initial": 0.0,
   "name": "x",
   "scale": 0.01,
   "unit": "m"
  },
  {
   "doc": "rate of beta",
   "initial": "omega_s",
   "name": "betad",
   "scale": 1.0,
   "unit": "rad/s"
  },
  {
   "doc": "rate of y",
   "initial": 0.0,
   "name": "yd",
   "scale": 1e-05,
   "unit": "m/s"
  },
  {
   "doc": "rate of z",
   "initial": 0.0,
   "name": "zd",
   "scale": 1e-05,
   "unit": "m/s"
  },
  {
   "doc": "rate of x",
   "initial": 0.0,
   "name": "xd",
   "scale": 0.01,
   "unit": "m/s"
  }
 ],
 "time": {
  "name": "t",
  "unit": "s"
 },
 "time_derivative": "symbolic",
 "title": "DYNACAM, cam mechanism with four degrees of freedom and drive"
}
"""
MANIFEST = json.loads(_MANIFEST_JSON)
"""States, parameters (defaults, units, ranges), outputs, cam inputs, modes, events, source hash."""

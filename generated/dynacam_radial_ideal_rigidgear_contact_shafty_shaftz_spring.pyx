# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True, initializedcheck=False
#
# GENERATED FILE - DO NOT EDIT.  Written by `camdyn derive` from camdyn/derive/models/dynacam.py;
# edit that and regenerate.  `camdyn derive --check` fails while this file is stale.
# Derivation key: sha256:0e67ff9cd47ffa7ba832144e5c1f2e4a1b921d6d4221cc624fd4231af4ecfece
# Text hash: sha256:a0552da3374aad3ea6ad5d24a31b8de51b408a53f657d7b7a935d79dcac221f3
#
# DYNACAM, cam mechanism with four degrees of freedom and drive (thesis ch. 6, figs 6.1, 6.2, 6.15, 6.18)
# Source hash: sha256:867dd035dc54b325f8953e03cc7d949fb8cd037bf2718ead15175ebffbfdee71
#
# This variant:
#   cam = radial: radial disk cam, pitch radius R_b + h (6.21)
#   motor = constant: camshaft input turning at the constant speed omega_s (ideal drive)
#   gear = rigid: reduction gear without backlash: the shaft torsion k, d_b alone (6.10)
#   roller = contact: roller held on the cam by the follower spring; it may lift off (6.42)
#   shaft_y = yes: tangential shaft deflection y (6.12), (6.16)
#   shaft_z = yes: shaft deflection z along the follower (6.11), (6.15)
#   cam_friction = no: no friction on the cam
#   linkage_friction = no: no friction in the linkage
#   spring = yes: follower spring with preload F_0 (6.45)
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
    _NM = 2                  # modes: cam segments, then the force elements' modes
    _NE = 4                  # events
    _NQ1 = 4                 # array sizes that must not be zero
    _NE1 = 4
    _JAC_SYMBOLIC = 1           # jacobian() is derived symbolically: the implicit loops use it
    _FT_SYMBOLIC = 1            # jacobian() also gives df/dt
    _PROJECTS = 0               # no constraints: nothing to project after a step (project())

cdef int _EDIR[_NE1]    # crossing direction of each event: +1 upward, -1 downward
_EDIR[0] = -1  # roller_lift
_EDIR[1] = 1  # roller_land
_EDIR[2] = 1  # cam0_hi
_EDIR[3] = -1  # cam0_lo



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
    cdef double F_0 = ctx.p[17]
    cdef double c_s = ctx.p[18]
    cdef double _c0 = (1.0/(J))
    cdef double _c1 = _c0*k
    cdef double _c2 = c_x*h_m
    cdef double _c3 = sqrt(c_x)*sqrt(m_x)*q_x
    cdef double _c4 = 2.0*_c3
    cdef double _c5 = (1.0/(beta_m))
    cdef double _c6 = _c5*h_m
    cdef double _c7 = (beta_m*beta_m)
    cdef double _c8 = R_b*_c7
    cdef double _c9 = (h_m*h_m)
    cdef double _c10 = _c7*_c9
    cdef double _c11 = 2.0*_c8*h_m
    cdef double _c12 = 2.0*_c9
    cdef double _c13 = _c12*_c3
    cdef double _c14 = _c0*h_m
    cdef double _c15 = sqrt(J)
    cdef double _c16 = 2.0*sqrt(k)*q_b
    cdef double _c17 = _c16/_c15
    cdef double _c18 = (1.0/(m_y))
    cdef double _c19 = _c18*h_m
    cdef double _c20 = (1.0/(m_z))
    cdef double _c21 = (1.0/(m_x))
    cdef double _c22 = (1.0/(h_m))
    cdef double _c23 = (1.0/(omega_s*omega_s))
    cdef double _c24 = (1.0/(_c7))
    cdef double _c25 = _c9*beta_m
    cdef double _c26 = 2.0*_c10
    ctx.k[0] = -_c1  # _k0
    ctx.k[1] = _c1*omega_s  # _k1
    ctx.k[2] = -c_x  # _k2
    ctx.k[3] = _c2  # _k3
    ctx.k[4] = -_c4  # _k4
    ctx.k[5] = R_b*beta_m  # _k5
    ctx.k[6] = beta_m*h_m  # _k6
    ctx.k[7] = -_c2  # _k7
    ctx.k[8] = -_c4*h_m  # _k8
    ctx.k[9] = _c4*_c6  # _k9
    ctx.k[10] = _c8  # _k10
    ctx.k[11] = _c7*h_m  # _k11
    ctx.k[12] = (R_b*R_b)*_c7  # _k12
    ctx.k[13] = _c10  # _k13
    ctx.k[14] = _c11  # _k14
    ctx.k[15] = _c13  # _k15
    ctx.k[16] = -_c14*_c5  # _k16
    ctx.k[17] = -_c17  # _k17
    ctx.k[18] = _c17*omega_s  # _k18
    ctx.k[19] = _c14  # _k19
    ctx.k[20] = -_c0*_c9  # _k20
    ctx.k[21] = -_c18*c_y  # _k21
    ctx.k[22] = _c19  # _k22
    ctx.k[23] = -2.0*sqrt(c_y)*q_y/sqrt(m_y)  # _k23
    ctx.k[24] = -c_z  # _k24
    ctx.k[25] = -2.0*sqrt(c_z)*sqrt(m_z)*q_z  # _k25
    ctx.k[26] = _c20  # _k26
    ctx.k[27] = -F_0  # _k27
    ctx.k[28] = -c_s  # _k28
    ctx.k[29] = _c21  # _k29
    ctx.k[30] = -beta_0  # _k30
    ctx.k[31] = _c5  # _k31
    ctx.k[32] = _c22*_c23*_c7  # _k32
    ctx.k[33] = _c23*beta_m  # _k33
    ctx.k[34] = -h_m  # _k34
    ctx.k[35] = _c22  # _k35
    ctx.k[36] = -k  # _k36
    ctx.k[37] = k*omega_s  # _k37
    ctx.k[38] = _c15*_c16  # _k38
    ctx.k[39] = -_c2*_c5  # _k39
    ctx.k[40] = _c6  # _k40
    ctx.k[41] = _c24*_c9  # _k41
    ctx.k[42] = -_c24*h_m  # _k42
    ctx.k[43] = -_c6  # _k43
    ctx.k[44] = _c4  # _k44
    ctx.k[45] = (1.0/(omega_s))  # _k45
    ctx.k[46] = _c25*c_x  # _k46
    ctx.k[47] = _c13*beta_m  # _k47
    ctx.k[48] = _c26*_c3  # _k48
    ctx.k[49] = -_c26  # _k49
    ctx.k[50] = -_c11  # _k50
    ctx.k[51] = -_c9  # _k51
    ctx.k[52] = -_c10  # _k52
    ctx.k[53] = _c0*_c5  # _k53
    ctx.k[54] = 4.0*_c3*_c9  # _k54
    ctx.k[55] = -_c12  # _k55
    ctx.k[56] = -_c25  # _k56
    ctx.k[57] = _c18*_c5  # _k57
    ctx.k[58] = _c19*_c5  # _k58
    ctx.k[59] = _c20*_c5  # _k59
    ctx.k[60] = _c21*_c5  # _k60


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
    cdef double F_0 = ctx.p[17]
    cdef double c_s = ctx.p[18]
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
    cdef double _k46 = ctx.k[46]
    cdef double _k47 = ctx.k[47]
    cdef double _k48 = ctx.k[48]
    cdef double _k49 = ctx.k[49]
    cdef double _k50 = ctx.k[50]
    cdef double _k51 = ctx.k[51]
    cdef double _k52 = ctx.k[52]
    cdef double _k53 = ctx.k[53]
    cdef double _k54 = ctx.k[54]
    cdef double _k55 = ctx.k[55]
    cdef double _k56 = ctx.k[56]
    cdef double _k57 = ctx.k[57]
    cdef double _k58 = ctx.k[58]
    cdef double _k59 = ctx.k[59]
    cdef double _k60 = ctx.k[60]
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

    cdef double _s0_0, _s0_1, _s0_2, _s0_3, _s0_4, _s0_5, _s0_6, _s0_7, _s1_0
    _dy[0] = betad
    _dy[1] = yd
    _dy[2] = zd
    _dy[3] = xd
    if _v == 0:
        _s0_0 = (1.0/(_cam0[0]*_k6 + _k5))
        _s0_1 = _cam0[1]*_s0_0
        _s0_2 = betad*y
        _s0_3 = _cam0[2]/(_cam0[0]*_k11 + _k10)
        _s0_4 = (_cam0[1]*_cam0[1])/((_cam0[0]*_cam0[0])*_k13 + _cam0[0]*_k14 + _k12)
        _s0_5 = ((_cam0[0]*_k3 + _cam0[1]*_k9*betad + _k15*_s0_2*_s0_4 + _k2*x + _k2*z + _k4*xd + _k4*zd + _k7*_s0_1*y + _k8*_s0_1*yd + _k8*_s0_2*_s0_3) if ((ctx.mode[1] == 0.0)) else (0.0))
        _s0_6 = _cam0[1]*_s0_5
        _s0_7 = _s0_5*y
        _dy[4] = _k0*beta + _k1*t + _k16*_s0_6 + _k17*betad + _k18 + _k19*_s0_3*_s0_7 + _k20*_s0_4*_s0_7
        _dy[5] = _k21*y + _k22*_s0_0*_s0_6 + _k23*yd
        _dy[6] = _k26*(_k24*z + _k25*zd + _s0_5)
        _dy[7] = _k29*(_k27 + _k28*x + _s0_5)
    elif _v == 1:  # in a dwell: 0
        _s1_0 = ((_cam0[0]*_k3 + _k2*x + _k2*z + _k4*xd + _k4*zd) if ((ctx.mode[1] == 0.0)) else (0.0))
        _dy[4] = _k0*beta + _k1*t + _k17*betad + _k18
        _dy[5] = _k21*y + _k23*yd
        _dy[6] = _k26*(_k24*z + _k25*zd + _s1_0)
        _dy[7] = _k29*(_k27 + _k28*x + _s1_0)


cdef void outputs(double t, const double* _y, double* _out, Ctx* ctx) noexcept nogil:
    """The named outputs (B, Xdd, Bdd, U, xdd, torque, Fx, speed_var, tan_alpha, roller_gap)."""
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
    cdef double F_0 = ctx.p[17]
    cdef double c_s = ctx.p[18]
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
    cdef double _k46 = ctx.k[46]
    cdef double _k47 = ctx.k[47]
    cdef double _k48 = ctx.k[48]
    cdef double _k49 = ctx.k[49]
    cdef double _k50 = ctx.k[50]
    cdef double _k51 = ctx.k[51]
    cdef double _k52 = ctx.k[52]
    cdef double _k53 = ctx.k[53]
    cdef double _k54 = ctx.k[54]
    cdef double _k55 = ctx.k[55]
    cdef double _k56 = ctx.k[56]
    cdef double _k57 = ctx.k[57]
    cdef double _k58 = ctx.k[58]
    cdef double _k59 = ctx.k[59]
    cdef double _k60 = ctx.k[60]
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

    cdef double _o0 = _cam0[0]*_k34 + x
    cdef double _o1 = R_b + _cam0[0]*h_m
    cdef double _o2 = (1.0/(_o1))
    cdef double _o3 = _o2*y
    cdef double _o4 = _o2*yd
    cdef double _o5 = _cam0[1]*_k40
    cdef double _o6 = _o2*_o5
    _out[0] = _k31*(_k30 + beta)  # B
    _out[1] = _k32*_dy[7]  # Xdd
    _out[2] = _k33*_dy[4]  # Bdd
    _out[3] = _k35*_o0  # U
    _out[4] = _dy[7]  # xdd
    _out[5] = _k36*beta + _k37*t - _k38*(betad - omega_s)  # torque
    _out[6] = ((_cam0[0]*_k3 + _cam0[1]*_k39*_o3 + _k2*x + _k2*z + _k44*(_cam0[1]*_k43*_o4 + betad*((_cam0[1]*_cam0[1])*_k41*y/(_o1*_o1) + _cam0[2]*_k42*_o3 + _o5) - xd - zd)) if ((ctx.mode[1] == 0.0)) else (0.0))  # Fx
    _out[7] = _k45*(-_o4 + betad) - 1.0  # speed_var
    _out[8] = _o6  # tan_alpha
    _out[9] = _o0 + _o6*y + z  # roller_gap


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
    cdef double F_0 = ctx.p[17]
    cdef double c_s = ctx.p[18]
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
    cdef double _k46 = ctx.k[46]
    cdef double _k47 = ctx.k[47]
    cdef double _k48 = ctx.k[48]
    cdef double _k49 = ctx.k[49]
    cdef double _k50 = ctx.k[50]
    cdef double _k51 = ctx.k[51]
    cdef double _k52 = ctx.k[52]
    cdef double _k53 = ctx.k[53]
    cdef double _k54 = ctx.k[54]
    cdef double _k55 = ctx.k[55]
    cdef double _k56 = ctx.k[56]
    cdef double _k57 = ctx.k[57]
    cdef double _k58 = ctx.k[58]
    cdef double _k59 = ctx.k[59]
    cdef double _k60 = ctx.k[60]
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
    cdef double F_0 = ctx.p[17]
    cdef double c_s = ctx.p[18]
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
    cdef double _k46 = ctx.k[46]
    cdef double _k47 = ctx.k[47]
    cdef double _k48 = ctx.k[48]
    cdef double _k49 = ctx.k[49]
    cdef double _k50 = ctx.k[50]
    cdef double _k51 = ctx.k[51]
    cdef double _k52 = ctx.k[52]
    cdef double _k53 = ctx.k[53]
    cdef double _k54 = ctx.k[54]
    cdef double _k55 = ctx.k[55]
    cdef double _k56 = ctx.k[56]
    cdef double _k57 = ctx.k[57]
    cdef double _k58 = ctx.k[58]
    cdef double _k59 = ctx.k[59]
    cdef double _k60 = ctx.k[60]
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
    cdef double _j0 = _cam0[0]*_k11 + _k10
    cdef double _j1 = (1.0/(_j0))
    cdef double _j2 = _j1*y
    cdef double _j3 = _k8*betad
    cdef double _j4 = _j2*_j3
    cdef double _j5 = (ctx.mode[1] == 0.0)
    cdef double _j6 = ((_j4) if (_j5) else (0.0))
    cdef double _j7 = _j2*h_m
    cdef double _j8 = (_cam0[1]*_cam0[1])
    cdef double _j9 = (_cam0[0]*_cam0[0])*_k13 + _cam0[0]*_k14 + _k12
    cdef double _j10 = (1.0/(_j9))
    cdef double _j11 = _j10*_j8
    cdef double _j12 = _j11*_k51*y
    cdef double _j13 = _k9*betad
    cdef double _j14 = _cam0[0]*_k6 + _k5
    cdef double _j15 = (1.0/(_j14))
    cdef double _j16 = _j15*_k7
    cdef double _j17 = _j16*y
    cdef double _j18 = _j15*_k8
    cdef double _j19 = _j18*yd
    cdef double _j20 = _j11*_k15
    cdef double _j21 = _j20*betad
    cdef double _j22 = ((_cam0[0]*_k3 + _cam0[1]*_j13 + _cam0[1]*_j17 + _cam0[1]*_j19 + _cam0[2]*_j4 + _j21*y + _k2*x + _k2*z + _k4*xd + _k4*zd) if (_j5) else (0.0))
    cdef double _j23 = betad*y
    cdef double _j24 = _cam0[1]*_j10
    cdef double _j25 = ((_j13 + _j17 + _j19 + _j23*_j24*_k54) if (_j5) else (0.0))
    cdef double _j26 = _cam0[1]*_j25
    cdef double _j27 = _cam0[2]*_j25
    cdef double _j28 = _j22*y
    cdef double _j29 = _cam0[1]/(_j14*_j14)
    cdef double _j30 = _cam0[2]/(_j0*_j0)
    cdef double _j31 = _j8*(_cam0[0]*_k49 + _k50)/(_j9*_j9)
    cdef double _j32 = ((_j23*_j30*_k48 + _j23*_j31*_k15 + _j29*_k46*y + _j29*_k47*yd + _k3) if (_j5) else (0.0))
    cdef double _j33 = _cam0[1]*_j32
    cdef double _j34 = _j32*h_m
    cdef double _j35 = _cam0[2]*_j2
    cdef double _j36 = _cam0[2]*_j1
    cdef double _j37 = ((_cam0[1]*_j16 + _j21 + _j3*_j36) if (_j5) else (0.0))
    cdef double _j38 = _cam0[1]*_k16
    cdef double _j39 = _j35*_k19
    cdef double _j40 = _j11*_k20
    cdef double _j41 = _j40*y
    cdef double _j42 = ((_k2) if (_j5) else (0.0))
    cdef double _j43 = _j38 + _j39 + _j41
    cdef double _j44 = _j42*_j43
    cdef double _j45 = ((_cam0[1]*_k9 + _j20*y + _j35*_k8) if (_j5) else (0.0))
    cdef double _j46 = ((_cam0[1]*_j18) if (_j5) else (0.0))
    cdef double _j47 = ((_k4) if (_j5) else (0.0))
    cdef double _j48 = _j43*_j47
    cdef double _j49 = _cam0[3]*_j6
    cdef double _j50 = _cam0[1]*_j15*_k22
    cdef double _j51 = _j42*_j50
    cdef double _j52 = _j47*_j50
    cdef double _j53 = _j27 + _j33 + _j49
    cdef double _j54 = _j47*_k29
    _J[32] = _cam0[1]*_k53*(_j12*_j32 + _j28*_j30*_k52 + _j28*_j31*_k51 + _j33*_k43 + _j34*_j35) + _cam0[2]*_k53*(_j12*_j25 + _j22*_k43 + _j24*_j28*_k55 + _j26*_k43 + _j27*_j7) + _cam0[3]*_k53*(_cam0[1]*_j6*_k43 + _cam0[2]*_j6*_j7 + _j12*_j6 + _j22*_j7) + _k0
    _J[33] = _j22*_j36*_k19 + _j22*_j40 + _j37*_j38 + _j37*_j39 + _j37*_j41
    _J[34] = _j44
    _J[35] = _j44
    _J[36] = _j38*_j45 + _j39*_j45 + _j41*_j45 + _k17
    _J[37] = _j43*_j46
    _J[38] = _j48
    _J[39] = _j48
    _J[40] = _j15*(_cam0[1]*_j49*_k58 + _cam0[2]*_k57*h_m*(_j22 + _j26) + _j8*_k57*(_j15*_j22*_k56 + _j34))
    _J[41] = _j37*_j50 + _k21
    _J[42] = _j51
    _J[43] = _j51
    _J[44] = _j45*_j50
    _J[45] = _j46*_j50 + _k23
    _J[46] = _j52
    _J[47] = _j52
    _J[48] = _j53*_k59
    _J[49] = _j37*_k26
    _J[50] = _k26*(_j42 + _k24)
    _J[51] = _j42*_k26
    _J[52] = _j45*_k26
    _J[53] = _j46*_k26
    _J[54] = _k26*(_j47 + _k25)
    _J[55] = _j47*_k26
    _J[56] = _j53*_k60
    _J[57] = _j37*_k29
    _J[58] = _j42*_k29
    _J[59] = _k29*(_j42 + _k28)
    _J[60] = _j45*_k29
    _J[61] = _j46*_k29
    _J[62] = _j54
    _J[63] = _j54
    _ftl[4] = _k1
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
    cdef double F_0 = ctx.p[17]
    cdef double c_s = ctx.p[18]
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
    cdef double _k46 = ctx.k[46]
    cdef double _k47 = ctx.k[47]
    cdef double _k48 = ctx.k[48]
    cdef double _k49 = ctx.k[49]
    cdef double _k50 = ctx.k[50]
    cdef double _k51 = ctx.k[51]
    cdef double _k52 = ctx.k[52]
    cdef double _k53 = ctx.k[53]
    cdef double _k54 = ctx.k[54]
    cdef double _k55 = ctx.k[55]
    cdef double _k56 = ctx.k[56]
    cdef double _k57 = ctx.k[57]
    cdef double _k58 = ctx.k[58]
    cdef double _k59 = ctx.k[59]
    cdef double _k60 = ctx.k[60]
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
    cdef double F_0 = ctx.p[17]
    cdef double c_s = ctx.p[18]
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
    cdef double _k46 = ctx.k[46]
    cdef double _k47 = ctx.k[47]
    cdef double _k48 = ctx.k[48]
    cdef double _k49 = ctx.k[49]
    cdef double _k50 = ctx.k[50]
    cdef double _k51 = ctx.k[51]
    cdef double _k52 = ctx.k[52]
    cdef double _k53 = ctx.k[53]
    cdef double _k54 = ctx.k[54]
    cdef double _k55 = ctx.k[55]
    cdef double _k56 = ctx.k[56]
    cdef double _k57 = ctx.k[57]
    cdef double _k58 = ctx.k[58]
    cdef double _k59 = ctx.k[59]
    cdef double _k60 = ctx.k[60]
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

    _g[0] = (_cam0[0]*h_m - _cam0[1]*h_m*y/(beta_m*(R_b + _cam0[0]*h_m)) - x - z) if (ctx.mode[1] == 0.0) else 1.0  # roller_lift
    _g[1] = (_cam0[0]*h_m - _cam0[1]*h_m*y/(beta_m*(R_b + _cam0[0]*h_m)) - x - z) if (ctx.mode[1] == 1.0) else 1.0  # roller_land
    _g[2] = (beta/beta_m - beta_0/beta_m) - camlaw_hi(ctx.law[0], ctx.law_par[0], ctx.mode[0])  # cam0_hi: next segment
    _g[3] = (beta/beta_m - beta_0/beta_m) - camlaw_lo(ctx.law[0], ctx.law_par[0], ctx.mode[0])  # cam0_lo: previous segment


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
    cdef double F_0 = ctx.p[17]
    cdef double c_s = ctx.p[18]
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
    cdef double _k46 = ctx.k[46]
    cdef double _k47 = ctx.k[47]
    cdef double _k48 = ctx.k[48]
    cdef double _k49 = ctx.k[49]
    cdef double _k50 = ctx.k[50]
    cdef double _k51 = ctx.k[51]
    cdef double _k52 = ctx.k[52]
    cdef double _k53 = ctx.k[53]
    cdef double _k54 = ctx.k[54]
    cdef double _k55 = ctx.k[55]
    cdef double _k56 = ctx.k[56]
    cdef double _k57 = ctx.k[57]
    cdef double _k58 = ctx.k[58]
    cdef double _k59 = ctx.k[59]
    cdef double _k60 = ctx.k[60]
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

    if _e == 0:  # roller_lift
        if True:
            ctx.mode[1] = 1  # roller = free
    elif _e == 1:  # roller_land
        if True:
            ctx.mode[1] = 0  # roller = contact
    elif _e == 2:  # cam0_hi
        ctx.mode[0] += 1
    elif _e == 3:  # cam0_lo
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
    cdef double F_0 = p[17]
    cdef double c_s = p[18]
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
    cdef double F_0 = p[17]
    cdef double c_s = p[18]
    return [None]


cdef ModelC _model
_model.abi_version = CAMDYN_ABI
_model.n_q = _NQ
_model.n_states = _NS
_model.n_params = 19
_model.n_outputs = 10
_model.n_families = 1
_model.n_instances = _NCAM
_model.n_modes = _NM
_model.n_events = _NE
_model.n_const = 61
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
  "roller_lift",
  "roller_land",
  "cam0_hi",
  "cam0_lo"
 ],
 "jacobian": "symbolic",
 "modes": [
  {
   "doc": "roller on the cam or lifted off (follower jump)",
   "initial": "contact",
   "name": "roller",
   "values": [
    "contact",
    "free"
   ]
  }
 ],
 "n_q": 4,
 "name": "dynacam_radial_ideal_rigidgear_contact_shafty_shaftz_spring",
 "options": [
  [
   "cam",
   "radial"
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
   "rigid"
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
   "contact"
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
   true
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
   "doc": "gap between roller and cam (negative: pressed)",
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
   "default": 100.0,
   "doc": "follower spring preload at x = 0 (6.45)",
   "high": null,
   "low": 0.0,
   "name": "F_0",
   "open_high": false,
   "open_low": false,
   "range": "0 <= F_0",
   "unit": "N"
  },
  {
   "default": 10000.0,
   "doc": "follower spring stiffness (6.45)",
   "high": null,
   "low": 0.0,
   "name": "c_s",
   "open_high": false,
   "open_low": false,
   "range": "0 <= c_s",
   "unit": "N/m"
  }
 ],
 "reference": "thesis ch. 6, figs 6.1, 6.2, 6.15, 6.18",
 "residual": {
  "acceleration": "Xdd",
  "error": "U",
  "rise_end": 1.0,
  "rise_state": "B"
 },
 "source_hash": "sha256:867dd035dc54b325f8953e03cc7d949fb8cd037bf2718ead15175ebffbfdee71",
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

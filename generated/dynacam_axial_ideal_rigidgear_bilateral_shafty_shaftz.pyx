# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True, initializedcheck=False
#
# GENERATED FILE - DO NOT EDIT.  Written by `camdyn derive` from camdyn/derive/models/dynacam.py;
# edit that and regenerate.  `camdyn derive --check` fails while this file is stale.
# Derivation key: sha256:e8b336daddfda7a42f60230a691a8a8bbb211c37433c6dde467e364c7a3f531b
# Text hash: sha256:d0f3146c487ee19c4d504ea6c2ebaaa97b30d0db1df42123ad26e2575aab3c11
#
# DYNACAM, cam mechanism with four degrees of freedom and drive (thesis ch. 6, figs 6.1, 6.2, 6.15, 6.18)
# Source hash: sha256:49317c049a0ae9e98c0d7ae0ad124c65edf3d683e584e9f2f1cb4e86f914b1c0
#
# This variant:
#   cam = axial: axial (globoidal) cam, constant pitch radius R_b (6.21)
#   motor = constant: camshaft input turning at the constant speed omega_s (ideal drive)
#   gear = rigid: reduction gear without backlash: the shaft torsion k, d_b alone (6.10)
#   roller = bilateral: roller held on both sides: the linkage spring always carries (6.42)
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
    _NM = 1                  # modes: cam segments, then the force elements' modes
    _NE = 2                  # events
    _NQ1 = 4                 # array sizes that must not be zero
    _NE1 = 2
    _JAC_SYMBOLIC = 1           # jacobian() is derived symbolically: the implicit loops use it
    _FT_SYMBOLIC = 1            # jacobian() also gives df/dt
    _PROJECTS = 0               # no constraints: nothing to project after a step (project())

cdef int _EDIR[_NE1]    # crossing direction of each event: +1 upward, -1 downward
_EDIR[0] = 1  # cam0_hi
_EDIR[1] = -1  # cam0_lo



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
    cdef double _c0 = (1.0/(J))
    cdef double _c1 = _c0*k
    cdef double _c2 = sqrt(J)
    cdef double _c3 = 2.0*sqrt(k)*q_b
    cdef double _c4 = _c3/_c2
    cdef double _c5 = (h_m*h_m)
    cdef double _c6 = _c5*c_x
    cdef double _c7 = (1.0/(R_b))
    cdef double _c8 = (beta_m*beta_m)
    cdef double _c9 = (1.0/(_c8))
    cdef double _c10 = _c7*_c9
    cdef double _c11 = _c0*_c10
    cdef double _c12 = c_x*h_m
    cdef double _c13 = _c10*h_m
    cdef double _c14 = sqrt(m_x)
    cdef double _c15 = sqrt(c_x)*q_x
    cdef double _c16 = _c14*_c15
    cdef double _c17 = 2.0*_c16
    cdef double _c18 = _c0*_c17
    cdef double _c19 = _c17*_c5
    cdef double _c20 = (1.0/(beta_m))
    cdef double _c21 = _c20*h_m
    cdef double _c22 = _c0*_c21
    cdef double _c23 = (beta_m*beta_m*beta_m)
    cdef double _c24 = (1.0/(_c23))
    cdef double _c25 = (R_b*R_b)
    cdef double _c26 = (1.0/(_c25))
    cdef double _c27 = _c0*_c26
    cdef double _c28 = _c27*_c5
    cdef double _c29 = _c24*_c28
    cdef double _c30 = (1.0/(beta_m*beta_m*beta_m*beta_m))
    cdef double _c31 = _c28*_c30
    cdef double _c32 = _c5*_c9
    cdef double _c33 = _c24*_c7
    cdef double _c34 = 4.0*_c16
    cdef double _c35 = _c34*_c5
    cdef double _c36 = (1.0/(m_y))
    cdef double _c37 = _c26*_c36
    cdef double _c38 = _c32*_c37
    cdef double _c39 = _c21*_c7
    cdef double _c40 = _c36*_c39
    cdef double _c41 = _c10*_c36
    cdef double _c42 = (1.0/(m_z))
    cdef double _c43 = -_c42*(c_x + c_z)
    cdef double _c44 = _c12*_c42
    cdef double _c45 = 2.0*_c42
    cdef double _c46 = _c16*_c45
    cdef double _c47 = sqrt(m_z)
    cdef double _c48 = sqrt(c_z)*q_z
    cdef double _c49 = (1.0/(m_x))
    cdef double _c50 = _c12*_c49
    cdef double _c51 = 2.0*_c15/_c14
    cdef double _c52 = (1.0/(h_m))
    cdef double _c53 = (1.0/(omega_s*omega_s))
    cdef double _c54 = _c12*_c20
    cdef double _c55 = _c54*_c7
    cdef double _c56 = _c23*_c25
    cdef double _c57 = R_b*_c8
    cdef double _c58 = _c57*_c6
    cdef double _c59 = _c17*h_m
    cdef double _c60 = _c5*beta_m
    cdef double _c61 = _c30*_c37
    cdef double _c62 = _c20*_c44
    cdef double _c63 = _c59*beta_m
    cdef double _c64 = _c33*_c42
    cdef double _c65 = _c20*_c50
    ctx.k[0] = -_c1  # _k0
    ctx.k[1] = _c1*omega_s  # _k1
    ctx.k[2] = -_c4  # _k2
    ctx.k[3] = _c4*omega_s  # _k3
    ctx.k[4] = _c11*_c6  # _k4
    ctx.k[5] = -_c11*_c12  # _k5
    ctx.k[6] = -_c13*_c18  # _k6
    ctx.k[7] = _c11*_c19  # _k7
    ctx.k[8] = -_c12  # _k8
    ctx.k[9] = _c17  # _k9
    ctx.k[10] = _c22  # _k10
    ctx.k[11] = -_c29  # _k11
    ctx.k[12] = -_c17*_c31  # _k12
    ctx.k[13] = -_c18*_c32  # _k13
    ctx.k[14] = _c0*_c33*_c35  # _k14
    ctx.k[15] = -_c36*c_y  # _k15
    ctx.k[16] = -2.0*sqrt(c_y)*q_y/sqrt(m_y)  # _k16
    ctx.k[17] = -_c38  # _k17
    ctx.k[18] = -c_x  # _k18
    ctx.k[19] = _c12  # _k19
    ctx.k[20] = -_c17  # _k20
    ctx.k[21] = _c40  # _k21
    ctx.k[22] = -_c19*_c24*_c37  # _k22
    ctx.k[23] = _c19*_c41  # _k23
    ctx.k[24] = -_c42*c_x  # _k24
    ctx.k[25] = _c43  # _k25
    ctx.k[26] = _c44  # _k26
    ctx.k[27] = -_c46  # _k27
    ctx.k[28] = -2.0*_c16*_c42 - 2.0*_c48/_c47  # _k28
    ctx.k[29] = -_c39*_c42  # _k29
    ctx.k[30] = -_c13*_c46  # _k30
    ctx.k[31] = _c21*_c46  # _k31
    ctx.k[32] = -_c49*c_x  # _k32
    ctx.k[33] = _c50  # _k33
    ctx.k[34] = -_c51  # _k34
    ctx.k[35] = -_c39*_c49  # _k35
    ctx.k[36] = -_c13*_c51  # _k36
    ctx.k[37] = _c21*_c51  # _k37
    ctx.k[38] = -beta_0  # _k38
    ctx.k[39] = _c20  # _k39
    ctx.k[40] = _c52*_c53*_c8  # _k40
    ctx.k[41] = _c53*beta_m  # _k41
    ctx.k[42] = -h_m  # _k42
    ctx.k[43] = _c52  # _k43
    ctx.k[44] = -k  # _k44
    ctx.k[45] = k*omega_s  # _k45
    ctx.k[46] = _c2*_c3  # _k46
    ctx.k[47] = -_c55  # _k47
    ctx.k[48] = _c21  # _k48
    ctx.k[49] = -_c13  # _k49
    ctx.k[50] = -_c39  # _k50
    ctx.k[51] = -_c7  # _k51
    ctx.k[52] = (1.0/(omega_s))  # _k52
    ctx.k[53] = _c39  # _k53
    ctx.k[54] = -_c56*_c6  # _k54
    ctx.k[55] = _c58  # _k55
    ctx.k[56] = _c27/(((beta_m*beta_m)*(beta_m*beta_m))*beta_m)  # _k56
    ctx.k[57] = 2.0*_c58  # _k57
    ctx.k[58] = _c35*_c57  # _k58
    ctx.k[59] = _c12*_c56  # _k59
    ctx.k[60] = _c56*_c59  # _k60
    ctx.k[61] = -_c60  # _k61
    ctx.k[62] = -_c25*_c35*_c8  # _k62
    ctx.k[63] = R_b*_c34*_c60  # _k63
    ctx.k[64] = -_c12*_c57  # _k64
    ctx.k[65] = -_c57*_c59  # _k65
    ctx.k[66] = -_c35  # _k66
    ctx.k[67] = -_c29*c_x  # _k67
    ctx.k[68] = -_c31*_c34  # _k68
    ctx.k[69] = _c0*_c54  # _k69
    ctx.k[70] = -_c17*_c29  # _k70
    ctx.k[71] = _c17*_c22  # _k71
    ctx.k[72] = -2.0*_c60  # _k72
    ctx.k[73] = -_c19  # _k73
    ctx.k[74] = _c61  # _k74
    ctx.k[75] = _c41*_c6  # _k75
    ctx.k[76] = -_c19*_c61  # _k76
    ctx.k[77] = -_c38*c_x  # _k77
    ctx.k[78] = -_c36*_c55  # _k78
    ctx.k[79] = -_c17*_c38  # _k79
    ctx.k[80] = -_c17*_c40  # _k80
    ctx.k[81] = _c62  # _k81
    ctx.k[82] = -_c12*beta_m  # _k82
    ctx.k[83] = -_c63  # _k83
    ctx.k[84] = R_b*_c63  # _k84
    ctx.k[85] = _c64  # _k85
    ctx.k[86] = -_c59*_c64  # _k86
    ctx.k[87] = -_c62*_c7  # _k87
    ctx.k[88] = _c43  # _k88
    ctx.k[89] = -_c39*_c46  # _k89
    ctx.k[90] = -_c45*(_c16 + _c47*_c48)  # _k90
    ctx.k[91] = _c65  # _k91
    ctx.k[92] = _c33*_c49  # _k92
    ctx.k[93] = -_c33*_c51*h_m  # _k93
    ctx.k[94] = -_c65*_c7  # _k94
    ctx.k[95] = -_c39*_c51  # _k95


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
    cdef double _k61 = ctx.k[61]
    cdef double _k62 = ctx.k[62]
    cdef double _k63 = ctx.k[63]
    cdef double _k64 = ctx.k[64]
    cdef double _k65 = ctx.k[65]
    cdef double _k66 = ctx.k[66]
    cdef double _k67 = ctx.k[67]
    cdef double _k68 = ctx.k[68]
    cdef double _k69 = ctx.k[69]
    cdef double _k70 = ctx.k[70]
    cdef double _k71 = ctx.k[71]
    cdef double _k72 = ctx.k[72]
    cdef double _k73 = ctx.k[73]
    cdef double _k74 = ctx.k[74]
    cdef double _k75 = ctx.k[75]
    cdef double _k76 = ctx.k[76]
    cdef double _k77 = ctx.k[77]
    cdef double _k78 = ctx.k[78]
    cdef double _k79 = ctx.k[79]
    cdef double _k80 = ctx.k[80]
    cdef double _k81 = ctx.k[81]
    cdef double _k82 = ctx.k[82]
    cdef double _k83 = ctx.k[83]
    cdef double _k84 = ctx.k[84]
    cdef double _k85 = ctx.k[85]
    cdef double _k86 = ctx.k[86]
    cdef double _k87 = ctx.k[87]
    cdef double _k88 = ctx.k[88]
    cdef double _k89 = ctx.k[89]
    cdef double _k90 = ctx.k[90]
    cdef double _k91 = ctx.k[91]
    cdef double _k92 = ctx.k[92]
    cdef double _k93 = ctx.k[93]
    cdef double _k94 = ctx.k[94]
    cdef double _k95 = ctx.k[95]
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

    cdef double _s0_0, _s0_1, _s0_2, _s0_3, _s0_4, _s0_5, _s0_6, _s0_7, _s0_8, _s0_9, _s0_10
    _dy[0] = betad
    _dy[1] = yd
    _dy[2] = zd
    _dy[3] = xd
    if _v == 0:
        _s0_0 = _k4*y
        _s0_1 = _cam0[2]*y
        _s0_2 = _k5*_s0_1
        _s0_3 = _k6*_s0_1
        _s0_4 = (_cam0[1]*_cam0[1])
        _s0_5 = _s0_4*betad
        _s0_6 = _cam0[1]*betad
        _s0_7 = _s0_1*_s0_6
        _s0_8 = _k9*yd + c_x*y
        _s0_9 = _cam0[1]*_s0_8
        _s0_10 = _s0_1*betad
        _dy[4] = _cam0[0]*_cam0[2]*_s0_0 + _cam0[1]*_k10*(_cam0[0]*_k8 + _k9*xd + _k9*zd + c_x*x + c_x*z) + (_cam0[2]*_cam0[2])*_k12*betad*(y*y) + _k0*beta + _k1*t + _k11*_s0_1*_s0_9 + _k13*_s0_5 + _k14*_s0_7 + _k2*betad + _k3 + _k7*_s0_4*yd + _s0_0*_s0_4 + _s0_2*x + _s0_2*z + _s0_3*xd + _s0_3*zd
        _dy[5] = _cam0[1]*_k21*(_cam0[0]*_k19 + _k18*x + _k18*z + _k20*xd + _k20*zd) + _k15*y + _k16*yd + _k17*_s0_4*_s0_8 + _k22*_s0_7 + _k23*_s0_5
        _dy[6] = _cam0[0]*_k26 + _k24*x + _k25*z + _k27*xd + _k28*zd + _k29*_s0_9 + _k30*_s0_10 + _k31*_s0_6
        _dy[7] = _cam0[0]*_k33 + _k32*x + _k32*z + _k34*xd + _k34*zd + _k35*_s0_9 + _k36*_s0_10 + _k37*_s0_6
    elif _v == 1:  # in a dwell: 0
        _dy[4] = _k0*beta + _k1*t + _k2*betad + _k3
        _dy[5] = _k15*y + _k16*yd
        _dy[6] = _cam0[0]*_k26 + _k24*x + _k25*z + _k27*xd + _k28*zd
        _dy[7] = _cam0[0]*_k33 + _k32*x + _k32*z + _k34*xd + _k34*zd


cdef void outputs(double t, const double* _y, double* _out, Ctx* ctx) noexcept nogil:
    """The named outputs (B, Xdd, Bdd, U, xdd, torque, Fx, speed_var, tan_alpha)."""
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
    cdef double _k61 = ctx.k[61]
    cdef double _k62 = ctx.k[62]
    cdef double _k63 = ctx.k[63]
    cdef double _k64 = ctx.k[64]
    cdef double _k65 = ctx.k[65]
    cdef double _k66 = ctx.k[66]
    cdef double _k67 = ctx.k[67]
    cdef double _k68 = ctx.k[68]
    cdef double _k69 = ctx.k[69]
    cdef double _k70 = ctx.k[70]
    cdef double _k71 = ctx.k[71]
    cdef double _k72 = ctx.k[72]
    cdef double _k73 = ctx.k[73]
    cdef double _k74 = ctx.k[74]
    cdef double _k75 = ctx.k[75]
    cdef double _k76 = ctx.k[76]
    cdef double _k77 = ctx.k[77]
    cdef double _k78 = ctx.k[78]
    cdef double _k79 = ctx.k[79]
    cdef double _k80 = ctx.k[80]
    cdef double _k81 = ctx.k[81]
    cdef double _k82 = ctx.k[82]
    cdef double _k83 = ctx.k[83]
    cdef double _k84 = ctx.k[84]
    cdef double _k85 = ctx.k[85]
    cdef double _k86 = ctx.k[86]
    cdef double _k87 = ctx.k[87]
    cdef double _k88 = ctx.k[88]
    cdef double _k89 = ctx.k[89]
    cdef double _k90 = ctx.k[90]
    cdef double _k91 = ctx.k[91]
    cdef double _k92 = ctx.k[92]
    cdef double _k93 = ctx.k[93]
    cdef double _k94 = ctx.k[94]
    cdef double _k95 = ctx.k[95]
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

    _out[0] = _k39*(_k38 + beta)  # B
    _out[1] = _k40*_dy[7]  # Xdd
    _out[2] = _k41*_dy[4]  # Bdd
    _out[3] = _k43*(_cam0[0]*_k42 + x)  # U
    _out[4] = _dy[7]  # xdd
    _out[5] = _k44*beta + _k45*t - _k46*(betad - omega_s)  # torque
    _out[6] = _cam0[0]*_k19 + _cam0[1]*_k47*y + _k18*x + _k18*z + _k9*(_cam0[1]*_k50*yd + betad*(_cam0[1]*_k48 + _cam0[2]*_k49*y) - xd - zd)  # Fx
    _out[7] = _k52*(_k51*yd + betad) - 1.0  # speed_var
    _out[8] = _cam0[1]*_k53  # tan_alpha


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
    cdef double _k61 = ctx.k[61]
    cdef double _k62 = ctx.k[62]
    cdef double _k63 = ctx.k[63]
    cdef double _k64 = ctx.k[64]
    cdef double _k65 = ctx.k[65]
    cdef double _k66 = ctx.k[66]
    cdef double _k67 = ctx.k[67]
    cdef double _k68 = ctx.k[68]
    cdef double _k69 = ctx.k[69]
    cdef double _k70 = ctx.k[70]
    cdef double _k71 = ctx.k[71]
    cdef double _k72 = ctx.k[72]
    cdef double _k73 = ctx.k[73]
    cdef double _k74 = ctx.k[74]
    cdef double _k75 = ctx.k[75]
    cdef double _k76 = ctx.k[76]
    cdef double _k77 = ctx.k[77]
    cdef double _k78 = ctx.k[78]
    cdef double _k79 = ctx.k[79]
    cdef double _k80 = ctx.k[80]
    cdef double _k81 = ctx.k[81]
    cdef double _k82 = ctx.k[82]
    cdef double _k83 = ctx.k[83]
    cdef double _k84 = ctx.k[84]
    cdef double _k85 = ctx.k[85]
    cdef double _k86 = ctx.k[86]
    cdef double _k87 = ctx.k[87]
    cdef double _k88 = ctx.k[88]
    cdef double _k89 = ctx.k[89]
    cdef double _k90 = ctx.k[90]
    cdef double _k91 = ctx.k[91]
    cdef double _k92 = ctx.k[92]
    cdef double _k93 = ctx.k[93]
    cdef double _k94 = ctx.k[94]
    cdef double _k95 = ctx.k[95]
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

    cdef double _m0 = _cam0[2]*c_x
    cdef double _m1 = _m0*x
    cdef double _m2 = (1.0/(beta_m*beta_m))
    cdef double _m3 = _m2*h_m
    cdef double _m4 = _m0*z
    cdef double _m5 = (h_m*h_m)
    cdef double _m6 = _m2*_m5
    cdef double _m7 = _cam0[0]*_m0
    cdef double _m8 = (_cam0[1]*_cam0[1])*c_x
    cdef double _m9 = _m6*_m8
    cdef double _m10 = c_x*y
    cdef double _m11 = _m10*h_m
    cdef double _m12 = (1.0/(R_b))
    cdef double _m13 = (1.0/(beta_m*beta_m*beta_m))
    cdef double _m14 = _m12*_m13
    cdef double _m15 = _cam0[3]*_m14
    cdef double _m16 = _m11*_m15
    cdef double _m17 = _m10*_m5
    cdef double _m18 = _cam0[1]*_cam0[2]
    cdef double _m19 = _m14*_m18
    cdef double _m20 = sqrt(c_x)*sqrt(m_x)*q_x
    cdef double _m21 = 2.0*_m20
    cdef double _m22 = _cam0[2]*_m21
    cdef double _m23 = _m22*xd
    cdef double _m24 = _m22*zd
    cdef double _m25 = _cam0[1]*c_x
    cdef double _m26 = (1.0/(R_b*R_b))
    cdef double _m27 = _m26*_m5
    cdef double _m28 = _m27*(y*y)
    cdef double _m29 = (1.0/(beta_m*beta_m*beta_m*beta_m))
    cdef double _m30 = _cam0[3]*_m29
    cdef double _m31 = (_cam0[2]*_cam0[2])
    cdef double _m32 = _m29*_m31
    cdef double _m33 = 4.0*_m20
    cdef double _m34 = _m33*_m5
    cdef double _m35 = _m18*betad
    cdef double _m36 = _m15*_m21*h_m*y
    cdef double _m37 = _m21*yd
    cdef double _m38 = _m27*_m37*y
    cdef double _m39 = _cam0[1]*_m30
    cdef double _m40 = betad*y
    cdef double _m41 = _m12*_m34*_m40
    cdef double _m42 = (1.0/(beta_m))
    cdef double _m43 = _m12*_m42
    cdef double _m44 = _cam0[1]*_cam0[2]*_m43
    cdef double _m45 = _m44*h_m
    cdef double _m46 = _m12*_m3
    cdef double _m47 = _m31*_m46
    cdef double _m48 = _m42*h_m
    cdef double _m49 = _m1 + 2.0*_m11*_m44 + _m23 + _m24 - _m33*_m35*_m48 + _m4 - _m7*h_m - _m8*h_m
    cdef double _m50 = _m48*c_x*(-_cam0[1] + _cam0[2]*_m12*_m42*y)
    cdef double _m51 = _m21*_m40
    cdef double _m52 = _cam0[3]*_m51
    cdef double _m53 = _m22*betad
    cdef double _m54 = _m25*_m43*h_m
    cdef double _m55 = _m25*beta_m
    cdef double _m56 = -_m46*(R_b*_m53 + R_b*_m55 - _cam0[2]*(_m10 + _m37) - _m42*_m52)
    cdef double _m57 = _m46*(_m53 + _m55)
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
    _Km[0] = -_cam0[0]*_m15*_m17 + _cam0[2]*_cam0[3]*_m28*_m33*betad/(((beta_m*beta_m)*(beta_m*beta_m))*beta_m) - _m1*_m3 + _m13*_m34*_m35 + _m16*x + _m16*z - 3.0*_m17*_m19 - _m19*_m34*yd - _m23*_m3 - _m24*_m3 + _m25*_m28*_m30 + _m28*_m32*c_x - _m3*_m4 + _m32*_m38 - _m32*_m41 + _m36*xd + _m36*zd + _m38*_m39 - _m39*_m41 + _m6*_m7 + _m9 + k
    _Km[1] = _m46*(_m33*_m40*_m47 + _m37*_m45 + _m49)
    _Km[2] = _m50
    _Km[3] = _m50
    _Km[4] = _m46*(_cam0[1]*_m46*_m52 + _m33*_m45*yd + _m47*_m51 + _m49)
    _Km[5] = _cam0[1]*_m13*_m27*_m53 + _m26*_m9 + c_y
    _Km[6] = _m54
    _Km[7] = _m54
    _Km[8] = _m56
    _Km[9] = _m57
    _Km[10] = c_x + c_z
    _Km[11] = c_x
    _Km[12] = _m56
    _Km[13] = _m57
    _Km[14] = c_x
    _Km[15] = c_x


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
    cdef double _k61 = ctx.k[61]
    cdef double _k62 = ctx.k[62]
    cdef double _k63 = ctx.k[63]
    cdef double _k64 = ctx.k[64]
    cdef double _k65 = ctx.k[65]
    cdef double _k66 = ctx.k[66]
    cdef double _k67 = ctx.k[67]
    cdef double _k68 = ctx.k[68]
    cdef double _k69 = ctx.k[69]
    cdef double _k70 = ctx.k[70]
    cdef double _k71 = ctx.k[71]
    cdef double _k72 = ctx.k[72]
    cdef double _k73 = ctx.k[73]
    cdef double _k74 = ctx.k[74]
    cdef double _k75 = ctx.k[75]
    cdef double _k76 = ctx.k[76]
    cdef double _k77 = ctx.k[77]
    cdef double _k78 = ctx.k[78]
    cdef double _k79 = ctx.k[79]
    cdef double _k80 = ctx.k[80]
    cdef double _k81 = ctx.k[81]
    cdef double _k82 = ctx.k[82]
    cdef double _k83 = ctx.k[83]
    cdef double _k84 = ctx.k[84]
    cdef double _k85 = ctx.k[85]
    cdef double _k86 = ctx.k[86]
    cdef double _k87 = ctx.k[87]
    cdef double _k88 = ctx.k[88]
    cdef double _k89 = ctx.k[89]
    cdef double _k90 = ctx.k[90]
    cdef double _k91 = ctx.k[91]
    cdef double _k92 = ctx.k[92]
    cdef double _k93 = ctx.k[93]
    cdef double _k94 = ctx.k[94]
    cdef double _k95 = ctx.k[95]
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
    cdef double _j0 = _cam0[2]*y
    cdef double _j1 = _k9*yd + c_x*y
    cdef double _j2 = _cam0[1]*_j1
    cdef double _j3 = _j0*betad
    cdef double _j4 = _cam0[1]*betad
    cdef double _j5 = _cam0[0]*_k55 + _j4*_k63 + _k64*x + _k64*z + _k65*xd + _k65*zd
    cdef double _j6 = _cam0[3]*y
    cdef double _j7 = _cam0[1]*y
    cdef double _j8 = _cam0[2]*_k5
    cdef double _j9 = _cam0[2]*_k6
    cdef double _j10 = (_cam0[1]*_cam0[1])
    cdef double _j11 = _cam0[2]*_j4
    cdef double _j12 = _cam0[1]*_j0
    cdef double _j13 = (_cam0[2]*_cam0[2])
    cdef double _j14 = _cam0[1]*_k69 + _j0*_k5
    cdef double _j15 = _cam0[1]*_k71 + _j0*_k6
    cdef double _j16 = _cam0[1]*_k78
    cdef double _j17 = _cam0[1]*_k80
    cdef double _j18 = _j6*betad
    cdef double _j19 = _cam0[2]*(_k82*y + _k83*yd + _k84*betad)
    cdef double _j20 = _cam0[2]*betad
    _J[32] = _cam0[1]*_k56*(_cam0[1]*_k54 + _j0*_k55) + _cam0[2]*_k56*(_cam0[0]*_k54 + _cam0[1]*_k58*yd + _j0*_j1*_k61 + _j3*_k63 + _j4*_k62 + _j7*_k57 + _k59*x + _k59*z + _k60*xd + _k60*zd) + _j6*_k56*(_j2*_k61 + _j3*_k66 + _j5) + _k0
    _J[33] = _cam0[0]*_cam0[2]*_k4 + _cam0[2]*_j2*_k11 + _j10*_k4 + _j11*_k14 + _j12*_k67 + _j13*_k68*betad*y + _j8*x + _j8*z + _j9*xd + _j9*zd
    _J[34] = _j14
    _J[35] = _j14
    _J[36] = _j10*_k13 + _j12*_k14 + _j13*_k12*(y*y) + _k2
    _J[37] = _cam0[1]*(_cam0[1]*_k7 + _j0*_k70)
    _J[38] = _j15
    _J[39] = _j15
    _J[40] = _cam0[2]*_k74*(_j2*_k72 + _j3*_k73 + _j5) + _cam0[3]*_j7*_k76*betad + _j10*_k75
    _J[41] = _j10*_k77 + _j11*_k22 + _k15
    _J[42] = _j16
    _J[43] = _j16
    _J[44] = _cam0[1]*(_cam0[1]*_k23 + _j0*_k22)
    _J[45] = _j10*_k79 + _k16
    _J[46] = _j17
    _J[47] = _j17
    _J[48] = _cam0[1]*_k81 + _j18*_k86 + _j19*_k85
    _J[49] = _cam0[1]*_k87 + _j20*_k30
    _J[50] = _k88
    _J[51] = _k24
    _J[52] = _cam0[1]*_k31 + _j0*_k30
    _J[53] = _cam0[1]*_k89
    _J[54] = _k90
    _J[55] = _k27
    _J[56] = _cam0[1]*_k91 + _j18*_k93 + _j19*_k92
    _J[57] = _cam0[1]*_k94 + _j20*_k36
    _J[58] = _k32
    _J[59] = _k32
    _J[60] = _cam0[1]*_k37 + _j0*_k36
    _J[61] = _cam0[1]*_k95
    _J[62] = _k34
    _J[63] = _k34
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
    cdef double _k61 = ctx.k[61]
    cdef double _k62 = ctx.k[62]
    cdef double _k63 = ctx.k[63]
    cdef double _k64 = ctx.k[64]
    cdef double _k65 = ctx.k[65]
    cdef double _k66 = ctx.k[66]
    cdef double _k67 = ctx.k[67]
    cdef double _k68 = ctx.k[68]
    cdef double _k69 = ctx.k[69]
    cdef double _k70 = ctx.k[70]
    cdef double _k71 = ctx.k[71]
    cdef double _k72 = ctx.k[72]
    cdef double _k73 = ctx.k[73]
    cdef double _k74 = ctx.k[74]
    cdef double _k75 = ctx.k[75]
    cdef double _k76 = ctx.k[76]
    cdef double _k77 = ctx.k[77]
    cdef double _k78 = ctx.k[78]
    cdef double _k79 = ctx.k[79]
    cdef double _k80 = ctx.k[80]
    cdef double _k81 = ctx.k[81]
    cdef double _k82 = ctx.k[82]
    cdef double _k83 = ctx.k[83]
    cdef double _k84 = ctx.k[84]
    cdef double _k85 = ctx.k[85]
    cdef double _k86 = ctx.k[86]
    cdef double _k87 = ctx.k[87]
    cdef double _k88 = ctx.k[88]
    cdef double _k89 = ctx.k[89]
    cdef double _k90 = ctx.k[90]
    cdef double _k91 = ctx.k[91]
    cdef double _k92 = ctx.k[92]
    cdef double _k93 = ctx.k[93]
    cdef double _k94 = ctx.k[94]
    cdef double _k95 = ctx.k[95]
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
    cdef double _k61 = ctx.k[61]
    cdef double _k62 = ctx.k[62]
    cdef double _k63 = ctx.k[63]
    cdef double _k64 = ctx.k[64]
    cdef double _k65 = ctx.k[65]
    cdef double _k66 = ctx.k[66]
    cdef double _k67 = ctx.k[67]
    cdef double _k68 = ctx.k[68]
    cdef double _k69 = ctx.k[69]
    cdef double _k70 = ctx.k[70]
    cdef double _k71 = ctx.k[71]
    cdef double _k72 = ctx.k[72]
    cdef double _k73 = ctx.k[73]
    cdef double _k74 = ctx.k[74]
    cdef double _k75 = ctx.k[75]
    cdef double _k76 = ctx.k[76]
    cdef double _k77 = ctx.k[77]
    cdef double _k78 = ctx.k[78]
    cdef double _k79 = ctx.k[79]
    cdef double _k80 = ctx.k[80]
    cdef double _k81 = ctx.k[81]
    cdef double _k82 = ctx.k[82]
    cdef double _k83 = ctx.k[83]
    cdef double _k84 = ctx.k[84]
    cdef double _k85 = ctx.k[85]
    cdef double _k86 = ctx.k[86]
    cdef double _k87 = ctx.k[87]
    cdef double _k88 = ctx.k[88]
    cdef double _k89 = ctx.k[89]
    cdef double _k90 = ctx.k[90]
    cdef double _k91 = ctx.k[91]
    cdef double _k92 = ctx.k[92]
    cdef double _k93 = ctx.k[93]
    cdef double _k94 = ctx.k[94]
    cdef double _k95 = ctx.k[95]
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

    _g[0] = (beta/beta_m - beta_0/beta_m) - camlaw_hi(ctx.law[0], ctx.law_par[0], ctx.mode[0])  # cam0_hi: next segment
    _g[1] = (beta/beta_m - beta_0/beta_m) - camlaw_lo(ctx.law[0], ctx.law_par[0], ctx.mode[0])  # cam0_lo: previous segment


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
    cdef double _k61 = ctx.k[61]
    cdef double _k62 = ctx.k[62]
    cdef double _k63 = ctx.k[63]
    cdef double _k64 = ctx.k[64]
    cdef double _k65 = ctx.k[65]
    cdef double _k66 = ctx.k[66]
    cdef double _k67 = ctx.k[67]
    cdef double _k68 = ctx.k[68]
    cdef double _k69 = ctx.k[69]
    cdef double _k70 = ctx.k[70]
    cdef double _k71 = ctx.k[71]
    cdef double _k72 = ctx.k[72]
    cdef double _k73 = ctx.k[73]
    cdef double _k74 = ctx.k[74]
    cdef double _k75 = ctx.k[75]
    cdef double _k76 = ctx.k[76]
    cdef double _k77 = ctx.k[77]
    cdef double _k78 = ctx.k[78]
    cdef double _k79 = ctx.k[79]
    cdef double _k80 = ctx.k[80]
    cdef double _k81 = ctx.k[81]
    cdef double _k82 = ctx.k[82]
    cdef double _k83 = ctx.k[83]
    cdef double _k84 = ctx.k[84]
    cdef double _k85 = ctx.k[85]
    cdef double _k86 = ctx.k[86]
    cdef double _k87 = ctx.k[87]
    cdef double _k88 = ctx.k[88]
    cdef double _k89 = ctx.k[89]
    cdef double _k90 = ctx.k[90]
    cdef double _k91 = ctx.k[91]
    cdef double _k92 = ctx.k[92]
    cdef double _k93 = ctx.k[93]
    cdef double _k94 = ctx.k[94]
    cdef double _k95 = ctx.k[95]
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
    return [None]


cdef ModelC _model
_model.abi_version = CAMDYN_ABI
_model.n_q = _NQ
_model.n_states = _NS
_model.n_params = 17
_model.n_outputs = 9
_model.n_families = 1
_model.n_instances = _NCAM
_model.n_modes = _NM
_model.n_events = _NE
_model.n_const = 96
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
   "order": 3,
   "time_affine": false
  }
 ],
 "events": [
  "cam0_hi",
  "cam0_lo"
 ],
 "jacobian": "symbolic",
 "modes": [],
 "n_q": 4,
 "name": "dynacam_axial_ideal_rigidgear_bilateral_shafty_shaftz",
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
   "bilateral"
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
  }
 ],
 "reference": "thesis ch. 6, figs 6.1, 6.2, 6.15, 6.18",
 "residual": {
  "acceleration": "Xdd",
  "error": "U",
  "rise_end": 1.0,
  "rise_state": "B"
 },
 "source_hash": "sha256:49317c049a0ae9e98c0d7ae0ad124c65edf3d683e584e9f2f1cb4e86f914b1c0",
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

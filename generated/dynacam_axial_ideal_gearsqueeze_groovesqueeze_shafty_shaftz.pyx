# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True, initializedcheck=False
#
# GENERATED FILE - DO NOT EDIT.  Written by `camdyn derive` from camdyn/derive/models/dynacam.py;
# edit that and regenerate.  `camdyn derive --check` fails while this file is stale.
# Derivation key: sha256:1a0c30eca760f7128261ff63e929c02562480301dccf8a745e26e32aea5e0ca1
# Text hash: sha256:37e190c31ae978656a9afae5e89896ad8ef0cfb1d2c499be9860021c2f3c12ac
#
# DYNACAM, cam mechanism with four degrees of freedom and drive (thesis ch. 6, figs 6.1, 6.2, 6.15, 6.18)
# Source hash: sha256:87cc6f632d9fab7e7beb98a5f275e3a12bd3d22974d3c67011929413b944c3cb
#
# This variant:
#   cam = axial: axial (globoidal) cam, constant pitch radius R_b (6.21)
#   motor = constant: camshaft input turning at the constant speed omega_s (ideal drive)
#   gear = squeeze: reduction gear with backlash s_g and a squeeze film between the teeth (6.5)-(6.9)
#   roller = groove-squeeze: roller in a groove with backlash s_r and a squeeze film (6.37)-(6.41)
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
from libc.math cimport pow, sqrt

from camdyn.runtime.engine.abi cimport *
from camdyn.generated.camlaws cimport (camlaw_dwell, camlaw_dwell_value, camlaw_eval, camlaw_hi,
                                       camlaw_lo, camlaw_segment)

# sizes, known when the integration loops (loops.pxi) are compiled into this module
cdef enum:
    _NQ = 4                  # second-order coordinates
    _NS = 10                  # states: q, q', first-order states
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
    cdef double s_g = ctx.p[17]
    cdef double V_T = ctx.p[18]
    cdef double s_r = ctx.p[19]
    cdef double V_R = ctx.p[20]
    cdef double _c0 = sqrt(J)
    cdef double _c1 = 2.0*sqrt(k)*q_b
    cdef double _c2 = _c0*_c1
    cdef double _c3 = (1.0/(J))
    cdef double _c4 = _c3*k
    cdef double _c5 = V_T*_c4
    cdef double _c6 = (1.0/(R_b))
    cdef double _c7 = (1.0/(beta_m))
    cdef double _c8 = _c7*h_m
    cdef double _c9 = _c6*_c8
    cdef double _c10 = sqrt(m_x)
    cdef double _c11 = sqrt(c_x)
    cdef double _c12 = 2.0*_c11*q_x
    cdef double _c13 = _c10*_c12
    cdef double _c14 = (beta_m*beta_m)
    cdef double _c15 = (1.0/(_c14))
    cdef double _c16 = _c15*_c6*h_m
    cdef double _c17 = V_R*beta_m
    cdef double _c18 = _c13*beta_m
    cdef double _c19 = V_R*c_x
    cdef double _c20 = _c19*h_m
    cdef double _c21 = _c20*_c3
    cdef double _c22 = _c1/_c0
    cdef double _c23 = V_T*_c22
    cdef double _c24 = V_R*_c14
    cdef double _c25 = _c13*_c14
    cdef double _c26 = R_b*_c25
    cdef double _c27 = (h_m*h_m)
    cdef double _c28 = V_R*_c13
    cdef double _c29 = _c27*_c28
    cdef double _c30 = _c29*_c3
    cdef double _c31 = _c28*h_m
    cdef double _c32 = _c3*_c31
    cdef double _c33 = (beta_m*beta_m*beta_m*beta_m)
    cdef double _c34 = (R_b*R_b)
    cdef double _c35 = V_R*_c34
    cdef double _c36 = _c13*_c34
    cdef double _c37 = (beta_m*beta_m*beta_m)
    cdef double _c38 = R_b*_c37
    cdef double _c39 = 4.0*_c10*_c11*_c27*q_x
    cdef double _c40 = V_R*_c39
    cdef double _c41 = _c3*_c40
    cdef double _c42 = (1.0/(m_y))
    cdef double _c43 = R_b*_c18
    cdef double _c44 = _c20*_c42
    cdef double _c45 = _c25*_c34
    cdef double _c46 = _c29*_c42
    cdef double _c47 = (1.0/(m_z))
    cdef double _c48 = _c19*_c47
    cdef double _c49 = _c28*_c47
    cdef double _c50 = _c49*h_m
    cdef double _c51 = (1.0/(m_x))
    cdef double _c52 = _c19*_c51
    cdef double _c53 = _c12/_c10
    cdef double _c54 = V_R*_c53
    cdef double _c55 = _c54*h_m
    cdef double _c56 = (1.0/(h_m))
    cdef double _c57 = (omega_s*omega_s)
    cdef double _c58 = (1.0/(_c57))
    cdef double _c59 = 0.5*h_m
    cdef double _c60 = 0.5*_c27
    cdef double _c61 = (V_R*V_R)
    cdef double _c62 = _c61*c_x
    cdef double _c63 = _c62*h_m
    cdef double _c64 = _c63*beta_m
    cdef double _c65 = R_b*_c14
    cdef double _c66 = _c63*_c65
    cdef double _c67 = _c61*h_m
    cdef double _c68 = _c18*_c67
    cdef double _c69 = _c27*_c61
    cdef double _c70 = _c25*_c69
    cdef double _c71 = _c26*_c69
    cdef double _c72 = _c26*_c67
    cdef double _c73 = _c13*_c61
    cdef double _c74 = _c27*_c34*_c73
    cdef double _c75 = _c33*_c74
    cdef double _c76 = _c38*_c39*_c61
    cdef double _c77 = _c37*_c74
    cdef double _c78 = 0.5*s_r
    cdef double _c79 = _c3*_c64
    cdef double _c80 = _c3*_c66
    cdef double _c81 = 0.5*omega_s
    cdef double _c82 = (V_T*V_T)
    cdef double _c83 = _c4*_c82
    cdef double _c84 = _c22*_c82
    cdef double _c85 = R_b*_c64
    cdef double _c86 = _c43*_c67
    cdef double _c87 = _c45*_c69
    cdef double _c88 = _c42*_c7
    cdef double _c89 = _c42*_c85
    cdef double _c90 = _c47*_c62
    cdef double _c91 = _c51*_c62
    cdef double _c92 = _c53*_c61
    cdef double _c93 = _c92*h_m
    cdef double _c94 = _c93*beta_m
    cdef double _c95 = 1.5*_c9
    cdef double _c96 = 1.5*h_m
    cdef double _c97 = 1.5*omega_s
    ctx.k[0] = -omega_s  # _k0
    ctx.k[1] = -k  # _k1
    ctx.k[2] = -_c2*omega_s  # _k2
    ctx.k[3] = _c2  # _k3
    ctx.k[4] = _c5  # _k4
    ctx.k[5] = -_c5  # _k5
    ctx.k[6] = -h_m  # _k6
    ctx.k[7] = _c9  # _k7
    ctx.k[8] = -c_x  # _k8
    ctx.k[9] = _c13  # _k9
    ctx.k[10] = -_c13*_c8  # _k10
    ctx.k[11] = _c13*_c9  # _k11
    ctx.k[12] = _c13*_c16  # _k12
    ctx.k[13] = -_c9  # _k13
    ctx.k[14] = -s_r  # _k14
    ctx.k[15] = _c17  # _k15
    ctx.k[16] = _c18  # _k16
    ctx.k[17] = _c21  # _k17
    ctx.k[18] = -_c21  # _k18
    ctx.k[19] = -_c23  # _k19
    ctx.k[20] = _c23*omega_s  # _k20
    ctx.k[21] = R_b*_c24  # _k21
    ctx.k[22] = _c26  # _k22
    ctx.k[23] = _c24  # _k23
    ctx.k[24] = _c25  # _k24
    ctx.k[25] = -_c30  # _k25
    ctx.k[26] = _c32  # _k26
    ctx.k[27] = _c30  # _k27
    ctx.k[28] = -_c32  # _k28
    ctx.k[29] = _c33*_c35  # _k29
    ctx.k[30] = _c33*_c36  # _k30
    ctx.k[31] = _c35*_c37  # _k31
    ctx.k[32] = _c36*_c37  # _k32
    ctx.k[33] = V_R*_c38  # _k33
    ctx.k[34] = _c13*_c38  # _k34
    ctx.k[35] = _c41  # _k35
    ctx.k[36] = -_c42*c_y  # _k36
    ctx.k[37] = -2.0*sqrt(c_y)*q_y/sqrt(m_y)  # _k37
    ctx.k[38] = R_b*_c17  # _k38
    ctx.k[39] = _c43  # _k39
    ctx.k[40] = _c44  # _k40
    ctx.k[41] = -_c44  # _k41
    ctx.k[42] = -_c31*_c42  # _k42
    ctx.k[43] = _c24*_c34  # _k43
    ctx.k[44] = _c45  # _k44
    ctx.k[45] = -_c46  # _k45
    ctx.k[46] = _c46  # _k46
    ctx.k[47] = -_c47*c_z  # _k47
    ctx.k[48] = -2.0*sqrt(c_z)*q_z/sqrt(m_z)  # _k48
    ctx.k[49] = _c48  # _k49
    ctx.k[50] = -_c48  # _k50
    ctx.k[51] = -_c49  # _k51
    ctx.k[52] = -_c50  # _k52
    ctx.k[53] = _c50  # _k53
    ctx.k[54] = _c52  # _k54
    ctx.k[55] = -_c52  # _k55
    ctx.k[56] = -_c54  # _k56
    ctx.k[57] = -_c55  # _k57
    ctx.k[58] = _c55  # _k58
    ctx.k[59] = _c8  # _k59
    ctx.k[60] = -_c16  # _k60
    ctx.k[61] = -_c13  # _k61
    ctx.k[62] = -beta_0  # _k62
    ctx.k[63] = _c7  # _k63
    ctx.k[64] = _c14*_c56*_c58  # _k64
    ctx.k[65] = _c58*beta_m  # _k65
    ctx.k[66] = _c56  # _k66
    ctx.k[67] = -_c6  # _k67
    ctx.k[68] = (1.0/(omega_s))  # _k68
    ctx.k[69] = _c59  # _k69
    ctx.k[70] = -_c60  # _k70
    ctx.k[71] = _c6*_c60*_c7  # _k71
    ctx.k[72] = -_c59*s_r  # _k72
    ctx.k[73] = _c20  # _k73
    ctx.k[74] = -_c20  # _k74
    ctx.k[75] = _c64  # _k75
    ctx.k[76] = -_c64  # _k76
    ctx.k[77] = -_c29  # _k77
    ctx.k[78] = _c31  # _k78
    ctx.k[79] = _c29  # _k79
    ctx.k[80] = -_c31  # _k80
    ctx.k[81] = _c66  # _k81
    ctx.k[82] = -_c66  # _k82
    ctx.k[83] = -_c68  # _k83
    ctx.k[84] = _c70  # _k84
    ctx.k[85] = _c40  # _k85
    ctx.k[86] = -_c71  # _k86
    ctx.k[87] = _c72  # _k87
    ctx.k[88] = _c75  # _k88
    ctx.k[89] = -_c76  # _k89
    ctx.k[90] = _c77  # _k90
    ctx.k[91] = _c3*_c7  # _k91
    ctx.k[92] = -_c15*_c60/_c34  # _k92
    ctx.k[93] = -0.5*_c9  # _k93
    ctx.k[94] = _c78*_c9  # _k94
    ctx.k[95] = -_c40  # _k95
    ctx.k[96] = _c79  # _k96
    ctx.k[97] = -_c79  # _k97
    ctx.k[98] = -_c41  # _k98
    ctx.k[99] = _c80  # _k99
    ctx.k[100] = -_c80  # _k100
    ctx.k[101] = -_c3*_c68  # _k101
    ctx.k[102] = _c3*_c70  # _k102
    ctx.k[103] = -_c3*_c71  # _k103
    ctx.k[104] = _c3*_c72  # _k104
    ctx.k[105] = _c3*_c75  # _k105
    ctx.k[106] = -_c3*_c76  # _k106
    ctx.k[107] = _c3*_c77  # _k107
    ctx.k[108] = _c78  # _k108
    ctx.k[109] = _c81  # _k109
    ctx.k[110] = 0.5*s_g  # _k110
    ctx.k[111] = _c83  # _k111
    ctx.k[112] = -_c83  # _k112
    ctx.k[113] = -_c84*omega_s  # _k113
    ctx.k[114] = _c84  # _k114
    ctx.k[115] = _c85  # _k115
    ctx.k[116] = -_c85  # _k116
    ctx.k[117] = _c86  # _k117
    ctx.k[118] = _c87  # _k118
    ctx.k[119] = _c88  # _k119
    ctx.k[120] = -_c29*_c88  # _k120
    ctx.k[121] = _c89  # _k121
    ctx.k[122] = -_c89  # _k122
    ctx.k[123] = -_c42*_c71  # _k123
    ctx.k[124] = _c42*_c86  # _k124
    ctx.k[125] = _c42*_c87  # _k125
    ctx.k[126] = _c42*_c77  # _k126
    ctx.k[127] = _c19  # _k127
    ctx.k[128] = -_c19  # _k128
    ctx.k[129] = _c62  # _k129
    ctx.k[130] = -_c62  # _k130
    ctx.k[131] = -_c28  # _k131
    ctx.k[132] = _c73  # _k132
    ctx.k[133] = _c47*_c7  # _k133
    ctx.k[134] = -_c49*_c8  # _k134
    ctx.k[135] = _c90  # _k135
    ctx.k[136] = -_c90  # _k136
    ctx.k[137] = _c47*_c73  # _k137
    ctx.k[138] = -_c47*_c68  # _k138
    ctx.k[139] = _c47*_c86  # _k139
    ctx.k[140] = _c47*_c72  # _k140
    ctx.k[141] = _c51*_c7  # _k141
    ctx.k[142] = -_c54*_c8  # _k142
    ctx.k[143] = _c91  # _k143
    ctx.k[144] = -_c91  # _k144
    ctx.k[145] = _c92  # _k145
    ctx.k[146] = -_c94  # _k146
    ctx.k[147] = R_b*_c94  # _k147
    ctx.k[148] = _c65*_c93  # _k148
    ctx.k[149] = -_c95  # _k149
    ctx.k[150] = _c95  # _k150
    ctx.k[151] = _c96  # _k151
    ctx.k[152] = -_c96  # _k152
    ctx.k[153] = V_R*_c7  # _k153
    ctx.k[154] = -0.5*_c57  # _k154
    ctx.k[155] = -_c81*s_g  # _k155
    ctx.k[156] = _c97  # _k156
    ctx.k[157] = -_c97  # _k157


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
    cdef double V_T = ctx.p[18]
    cdef double s_r = ctx.p[19]
    cdef double V_R = ctx.p[20]
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
    cdef double _k96 = ctx.k[96]
    cdef double _k97 = ctx.k[97]
    cdef double _k98 = ctx.k[98]
    cdef double _k99 = ctx.k[99]
    cdef double _k100 = ctx.k[100]
    cdef double _k101 = ctx.k[101]
    cdef double _k102 = ctx.k[102]
    cdef double _k103 = ctx.k[103]
    cdef double _k104 = ctx.k[104]
    cdef double _k105 = ctx.k[105]
    cdef double _k106 = ctx.k[106]
    cdef double _k107 = ctx.k[107]
    cdef double _k108 = ctx.k[108]
    cdef double _k109 = ctx.k[109]
    cdef double _k110 = ctx.k[110]
    cdef double _k111 = ctx.k[111]
    cdef double _k112 = ctx.k[112]
    cdef double _k113 = ctx.k[113]
    cdef double _k114 = ctx.k[114]
    cdef double _k115 = ctx.k[115]
    cdef double _k116 = ctx.k[116]
    cdef double _k117 = ctx.k[117]
    cdef double _k118 = ctx.k[118]
    cdef double _k119 = ctx.k[119]
    cdef double _k120 = ctx.k[120]
    cdef double _k121 = ctx.k[121]
    cdef double _k122 = ctx.k[122]
    cdef double _k123 = ctx.k[123]
    cdef double _k124 = ctx.k[124]
    cdef double _k125 = ctx.k[125]
    cdef double _k126 = ctx.k[126]
    cdef double _k127 = ctx.k[127]
    cdef double _k128 = ctx.k[128]
    cdef double _k129 = ctx.k[129]
    cdef double _k130 = ctx.k[130]
    cdef double _k131 = ctx.k[131]
    cdef double _k132 = ctx.k[132]
    cdef double _k133 = ctx.k[133]
    cdef double _k134 = ctx.k[134]
    cdef double _k135 = ctx.k[135]
    cdef double _k136 = ctx.k[136]
    cdef double _k137 = ctx.k[137]
    cdef double _k138 = ctx.k[138]
    cdef double _k139 = ctx.k[139]
    cdef double _k140 = ctx.k[140]
    cdef double _k141 = ctx.k[141]
    cdef double _k142 = ctx.k[142]
    cdef double _k143 = ctx.k[143]
    cdef double _k144 = ctx.k[144]
    cdef double _k145 = ctx.k[145]
    cdef double _k146 = ctx.k[146]
    cdef double _k147 = ctx.k[147]
    cdef double _k148 = ctx.k[148]
    cdef double _k149 = ctx.k[149]
    cdef double _k150 = ctx.k[150]
    cdef double _k151 = ctx.k[151]
    cdef double _k152 = ctx.k[152]
    cdef double _k153 = ctx.k[153]
    cdef double _k154 = ctx.k[154]
    cdef double _k155 = ctx.k[155]
    cdef double _k156 = ctx.k[156]
    cdef double _k157 = ctx.k[157]
    cdef double beta = _y[0]
    cdef double y = _y[1]
    cdef double z = _y[2]
    cdef double x = _y[3]
    cdef double betad = _y[4]
    cdef double yd = _y[5]
    cdef double zd = _y[6]
    cdef double xd = _y[7]
    cdef double phir = _y[8]
    cdef double hr = _y[9]
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

    cdef double _s0_0, _s0_1, _s0_2, _s0_3, _s0_4, _s0_5, _s0_6, _s0_7, _s0_8, _s0_9, _s0_10, _s0_11, _s0_12, _s0_13, _s0_14, _s0_15, _s0_16, _s0_17, _s0_18, _s0_19, _s0_20, _s0_21, _s0_22, _s0_23, _s0_24, _s0_25, _s0_26, _s0_27, _s0_28, _s0_29, _s0_30, _s0_31, _s0_32, _s0_33, _s0_34, _s0_35, _s0_36, _s0_37, _s0_38, _s0_39, _s0_40, _s0_41, _s0_42, _s0_43, _s0_44, _s0_45, _s0_46, _s0_47, _s0_48, _s0_49, _s0_50, _s0_51, _s0_52, _s0_53, _s0_54, _s0_55, _s0_56, _s0_57, _s1_0, _s1_1, _s1_2, _s1_3, _s1_4, _s1_5, _s1_6, _s1_7, _s1_8, _s1_9, _s1_10, _s1_11, _s1_12, _s1_13, _s1_14, _s1_15, _s1_16, _s1_17, _s1_18, _s1_19, _s1_20, _s1_21, _s1_22, _s1_23, _s1_24, _s1_25, _s1_26, _s1_27
    _dy[0] = betad
    _dy[1] = yd
    _dy[2] = zd
    _dy[3] = xd
    if _v == 0:
        _s0_0 = _k0*t
        _s0_1 = _s0_0 + phir
        _s0_2 = sqrt(_s0_1)
        _s0_3 = -phir
        _s0_4 = omega_s*t
        _s0_5 = _s0_3 + _s0_4
        _s0_6 = (_s0_5 < -1.0/1000000000000.0)
        _s0_7 = _s0_5 + s_g
        _s0_8 = sqrt(_s0_7)
        _s0_9 = (_s0_7 > 1.0/1000000000000.0)
        _s0_10 = (((((1.0/(_s0_0*_s0_2 + _s0_2*phir))) if (_s0_6) else (1e+18))) if ((_k1*phir + _k2 + _k3*betad + beta*k < 0.0)) else ((((1.0/(_s0_4*_s0_8 - _s0_8*phir + _s0_8*s_g))) if (_s0_9) else (1e+18))))
        _s0_11 = _s0_10/(V_T*_s0_10 + _k3)
        _s0_12 = _cam0[0]*_k6
        _s0_13 = _cam0[1]*y
        _s0_14 = _k7*_s0_13
        _s0_15 = _s0_12 + _s0_14 + hr + z
        _s0_16 = sqrt(_s0_15)
        _s0_17 = (_s0_15 > 1.0/1000000000000.0)
        _s0_18 = _cam0[1]*betad
        _s0_19 = _cam0[1]*yd
        _s0_20 = _cam0[2]*y
        _s0_21 = _s0_20*betad
        _s0_22 = _cam0[0]*h_m
        _s0_23 = _k13*_s0_13
        _s0_24 = _s0_22 + _s0_23 - hr + s_r - z
        _s0_25 = sqrt(_s0_24)
        _s0_26 = (_k14 + _s0_15 < -1.0/1000000000000.0)
        _s0_27 = (((((1.0/(_s0_12*_s0_16 + _s0_14*_s0_16 + _s0_16*hr + _s0_16*z))) if (_s0_17) else (1e+18))) if ((_k10*_s0_18 + _k11*_s0_19 + _k12*_s0_21 + _k8*hr + _k9*xd + _k9*zd + c_x*x < 0.0)) else ((((1.0/(_s0_22*_s0_25 + _s0_23*_s0_25 - _s0_25*hr + _s0_25*s_r - _s0_25*z))) if (_s0_26) else (1e+18))))
        _s0_28 = (1.0/(_k15*_s0_27 + _k16))
        _s0_29 = _cam0[1]*_s0_27
        _s0_30 = _s0_28*_s0_29
        _s0_31 = _k26*_s0_30
        _s0_32 = (1.0/(_k21*_s0_27 + _k22))
        _s0_33 = _s0_20*_s0_27*_s0_32
        _s0_34 = _k28*_s0_33
        _s0_35 = (_cam0[1]*_cam0[1])*_s0_27
        _s0_36 = _s0_35*betad
        _s0_37 = _s0_35*yd
        _s0_38 = _k25*_s0_27
        _s0_39 = _cam0[2]*_s0_13
        _s0_40 = _s0_39/(_k31*_s0_27 + _k32)
        _s0_41 = _s0_27*betad
        _s0_42 = (1.0/(_k38*_s0_27 + _k39))
        _s0_43 = _s0_29*_s0_42
        _s0_44 = _k42*_s0_43
        _s0_45 = _s0_27/(V_R*_s0_27 + _k9)
        _s0_46 = _s0_45*hr
        _s0_47 = _s0_45*x
        _s0_48 = _k51*_s0_45
        _s0_49 = _k52*_s0_27
        _s0_50 = _s0_19*_s0_42
        _s0_51 = _s0_18*_s0_27*_s0_28
        _s0_52 = _s0_21*_s0_32
        _s0_53 = _k56*_s0_45
        _s0_54 = _k57*_s0_27
        _s0_55 = _k3*(-betad + omega_s) + k*(-_s0_3 - beta)
        _s0_56 = _k13*_s0_19 + betad*(_cam0[1]*_k59 + _k60*_s0_20) - zd
        _s0_57 = _k9*(_s0_56 - xd) + c_x*(hr - x)
        _dy[4] = (_cam0[2]*_cam0[2])*_s0_38*betad*(y*y)/(_k29*_s0_27 + _k30) + _k17*_s0_30*x + _k17*_s0_33*hr + _k18*_s0_30*hr + _k18*_s0_33*x + _k19*_s0_11*betad + _k20*_s0_11 + _k25*_s0_36/(_k23*_s0_27 + _k24) + _k27*_s0_32*_s0_37 + _k35*_s0_39*_s0_41/(_k33*_s0_27 + _k34) + _k4*_s0_11*phir + _k5*_s0_11*beta + _s0_31*xd + _s0_31*zd + _s0_34*xd + _s0_34*zd + _s0_38*_s0_40*yd
        _dy[5] = _k36*y + _k37*yd + _k40*_s0_43*hr + _k41*_s0_43*x + _k45*_s0_37/(_k43*_s0_27 + _k44) + _k45*_s0_40*_s0_41 + _k46*_s0_32*_s0_36 + _s0_44*xd + _s0_44*zd
        _dy[6] = _k47*z + _k48*zd + _k49*_s0_46 + _k50*_s0_47 + _k53*_s0_51 + _s0_48*xd + _s0_48*zd + _s0_49*_s0_50 + _s0_49*_s0_52
        _dy[7] = _k54*_s0_46 + _k55*_s0_47 + _k58*_s0_51 + _s0_50*_s0_54 + _s0_52*_s0_54 + _s0_53*xd + _s0_53*zd
        _dy[8] = -_s0_55/(V_T*((((pow(_s0_1, -3.0/2.0)) if (_s0_6) else (1e+18))) if ((_s0_55 > 0.0)) else (((pow(_s0_7, -3.0/2.0)) if (_s0_9) else (1e+18)))) + _k3) + omega_s
        _dy[9] = _s0_56 - _s0_57/(V_R*((((pow(_s0_15, -3.0/2.0)) if (_s0_17) else (1e+18))) if ((_s0_57 > 0.0)) else (((pow(_s0_24, -3.0/2.0)) if (_s0_26) else (1e+18)))) + _k9)
    elif _v == 1:  # in a dwell: 0
        _s1_0 = _k0*t
        _s1_1 = _s1_0 + phir
        _s1_2 = sqrt(_s1_1)
        _s1_3 = -phir
        _s1_4 = omega_s*t
        _s1_5 = _s1_3 + _s1_4
        _s1_6 = (_s1_5 < -1.0/1000000000000.0)
        _s1_7 = _s1_5 + s_g
        _s1_8 = sqrt(_s1_7)
        _s1_9 = (_s1_7 > 1.0/1000000000000.0)
        _s1_10 = (((((1.0/(_s1_0*_s1_2 + _s1_2*phir))) if (_s1_6) else (1e+18))) if ((_k1*phir + _k2 + _k3*betad + beta*k < 0.0)) else ((((1.0/(_s1_4*_s1_8 - _s1_8*phir + _s1_8*s_g))) if (_s1_9) else (1e+18))))
        _s1_11 = _s1_10/(V_T*_s1_10 + _k3)
        _s1_12 = _cam0[0]*_k6
        _s1_13 = _s1_12 + hr + z
        _s1_14 = sqrt(_s1_13)
        _s1_15 = (_s1_13 > 1.0/1000000000000.0)
        _s1_16 = _cam0[0]*h_m
        _s1_17 = _s1_16 - hr + s_r - z
        _s1_18 = sqrt(_s1_17)
        _s1_19 = (_s1_17 > 1.0/1000000000000.0)
        _s1_20 = (((((1.0/(_s1_12*_s1_14 + _s1_14*hr + _s1_14*z))) if (_s1_15) else (1e+18))) if ((_k8*hr + _k9*xd + _k9*zd + c_x*x < 0.0)) else ((((1.0/(_s1_16*_s1_18 - _s1_18*hr + _s1_18*s_r - _s1_18*z))) if (_s1_19) else (1e+18))))
        _s1_21 = _s1_20/(V_R*_s1_20 + _k9)
        _s1_22 = _s1_21*hr
        _s1_23 = _s1_21*x
        _s1_24 = _k51*_s1_21
        _s1_25 = _k56*_s1_21
        _s1_26 = _k3*(-betad + omega_s) + k*(-_s1_3 - beta)
        _s1_27 = _k61*xd + _k61*zd + c_x*(hr - x)
        _dy[4] = _k19*_s1_11*betad + _k20*_s1_11 + _k4*_s1_11*phir + _k5*_s1_11*beta
        _dy[5] = _k36*y + _k37*yd
        _dy[6] = _k47*z + _k48*zd + _k49*_s1_22 + _k50*_s1_23 + _s1_24*xd + _s1_24*zd
        _dy[7] = _k54*_s1_22 + _k55*_s1_23 + _s1_25*xd + _s1_25*zd
        _dy[8] = -_s1_26/(V_T*((((pow(_s1_1, -3.0/2.0)) if (_s1_6) else (1e+18))) if ((_s1_26 > 0.0)) else (((pow(_s1_7, -3.0/2.0)) if (_s1_9) else (1e+18)))) + _k3) + omega_s
        _dy[9] = -_s1_27/(V_R*((((pow(_s1_13, -3.0/2.0)) if (_s1_15) else (1e+18))) if ((_s1_27 > 0.0)) else (((pow(_s1_17, -3.0/2.0)) if (_s1_19) else (1e+18)))) + _k9) - zd


cdef void outputs(double t, const double* _y, double* _out, Ctx* ctx) noexcept nogil:
    """The named outputs (B, Xdd, Bdd, U, xdd, torque, Fx, speed_var, tan_alpha, gear_gap, roller_gap)."""
    cdef double _dy[10]
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
    cdef double V_T = ctx.p[18]
    cdef double s_r = ctx.p[19]
    cdef double V_R = ctx.p[20]
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
    cdef double _k96 = ctx.k[96]
    cdef double _k97 = ctx.k[97]
    cdef double _k98 = ctx.k[98]
    cdef double _k99 = ctx.k[99]
    cdef double _k100 = ctx.k[100]
    cdef double _k101 = ctx.k[101]
    cdef double _k102 = ctx.k[102]
    cdef double _k103 = ctx.k[103]
    cdef double _k104 = ctx.k[104]
    cdef double _k105 = ctx.k[105]
    cdef double _k106 = ctx.k[106]
    cdef double _k107 = ctx.k[107]
    cdef double _k108 = ctx.k[108]
    cdef double _k109 = ctx.k[109]
    cdef double _k110 = ctx.k[110]
    cdef double _k111 = ctx.k[111]
    cdef double _k112 = ctx.k[112]
    cdef double _k113 = ctx.k[113]
    cdef double _k114 = ctx.k[114]
    cdef double _k115 = ctx.k[115]
    cdef double _k116 = ctx.k[116]
    cdef double _k117 = ctx.k[117]
    cdef double _k118 = ctx.k[118]
    cdef double _k119 = ctx.k[119]
    cdef double _k120 = ctx.k[120]
    cdef double _k121 = ctx.k[121]
    cdef double _k122 = ctx.k[122]
    cdef double _k123 = ctx.k[123]
    cdef double _k124 = ctx.k[124]
    cdef double _k125 = ctx.k[125]
    cdef double _k126 = ctx.k[126]
    cdef double _k127 = ctx.k[127]
    cdef double _k128 = ctx.k[128]
    cdef double _k129 = ctx.k[129]
    cdef double _k130 = ctx.k[130]
    cdef double _k131 = ctx.k[131]
    cdef double _k132 = ctx.k[132]
    cdef double _k133 = ctx.k[133]
    cdef double _k134 = ctx.k[134]
    cdef double _k135 = ctx.k[135]
    cdef double _k136 = ctx.k[136]
    cdef double _k137 = ctx.k[137]
    cdef double _k138 = ctx.k[138]
    cdef double _k139 = ctx.k[139]
    cdef double _k140 = ctx.k[140]
    cdef double _k141 = ctx.k[141]
    cdef double _k142 = ctx.k[142]
    cdef double _k143 = ctx.k[143]
    cdef double _k144 = ctx.k[144]
    cdef double _k145 = ctx.k[145]
    cdef double _k146 = ctx.k[146]
    cdef double _k147 = ctx.k[147]
    cdef double _k148 = ctx.k[148]
    cdef double _k149 = ctx.k[149]
    cdef double _k150 = ctx.k[150]
    cdef double _k151 = ctx.k[151]
    cdef double _k152 = ctx.k[152]
    cdef double _k153 = ctx.k[153]
    cdef double _k154 = ctx.k[154]
    cdef double _k155 = ctx.k[155]
    cdef double _k156 = ctx.k[156]
    cdef double _k157 = ctx.k[157]
    cdef double beta = _y[0]
    cdef double y = _y[1]
    cdef double z = _y[2]
    cdef double x = _y[3]
    cdef double betad = _y[4]
    cdef double yd = _y[5]
    cdef double zd = _y[6]
    cdef double xd = _y[7]
    cdef double phir = _y[8]
    cdef double hr = _y[9]
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

    cdef double _o0 = _cam0[0]*_k6
    cdef double _o1 = -phir
    cdef double _o2 = _o1 + omega_s*t
    cdef double _o3 = _k3*(betad - omega_s) + k*(_o1 + beta)
    cdef double _o4 = _o2 + s_g
    cdef double _o5 = V_T*((((pow(_k0*t + phir, -3.0/2.0)) if ((_o2 < -1.0/1000000000000.0)) else (1e+18))) if ((_o3 < 0.0)) else (((pow(_o4, -3.0/2.0)) if ((_o4 > 1.0/1000000000000.0)) else (1e+18))))
    cdef double _o6 = _cam0[1]*_k7
    cdef double _o7 = _o0 + _o6*y + hr + z
    cdef double _o8 = _cam0[1]*_k13
    cdef double _o9 = _k9*(_o8*yd + betad*(_cam0[1]*_k59 + _cam0[2]*_k60*y) - xd - zd) + c_x*(hr - x)
    cdef double _o10 = V_R*((((pow(_o7, -3.0/2.0)) if ((_o7 > 1.0/1000000000000.0)) else (1e+18))) if ((_o9 > 0.0)) else (((pow(_cam0[0]*h_m + _o8*y - hr + s_r - z, -3.0/2.0)) if ((_k14 + _o7 < -1.0/1000000000000.0)) else (1e+18))))
    _out[0] = _k63*(_k62 + beta)  # B
    _out[1] = _k64*_dy[7]  # Xdd
    _out[2] = _k65*_dy[4]  # Bdd
    _out[3] = _k66*(_o0 + x)  # U
    _out[4] = _dy[7]  # xdd
    _out[5] = -_o3*_o5/(_k3 + _o5)  # torque
    _out[6] = _o10*_o9/(_k9 + _o10)  # Fx
    _out[7] = _k68*(_k67*yd + betad) - 1.0  # speed_var
    _out[8] = _o6  # tan_alpha
    _out[9] = _o2  # gear_gap
    _out[10] = _o7  # roller_gap


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
    cdef double V_T = ctx.p[18]
    cdef double s_r = ctx.p[19]
    cdef double V_R = ctx.p[20]
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
    cdef double _k96 = ctx.k[96]
    cdef double _k97 = ctx.k[97]
    cdef double _k98 = ctx.k[98]
    cdef double _k99 = ctx.k[99]
    cdef double _k100 = ctx.k[100]
    cdef double _k101 = ctx.k[101]
    cdef double _k102 = ctx.k[102]
    cdef double _k103 = ctx.k[103]
    cdef double _k104 = ctx.k[104]
    cdef double _k105 = ctx.k[105]
    cdef double _k106 = ctx.k[106]
    cdef double _k107 = ctx.k[107]
    cdef double _k108 = ctx.k[108]
    cdef double _k109 = ctx.k[109]
    cdef double _k110 = ctx.k[110]
    cdef double _k111 = ctx.k[111]
    cdef double _k112 = ctx.k[112]
    cdef double _k113 = ctx.k[113]
    cdef double _k114 = ctx.k[114]
    cdef double _k115 = ctx.k[115]
    cdef double _k116 = ctx.k[116]
    cdef double _k117 = ctx.k[117]
    cdef double _k118 = ctx.k[118]
    cdef double _k119 = ctx.k[119]
    cdef double _k120 = ctx.k[120]
    cdef double _k121 = ctx.k[121]
    cdef double _k122 = ctx.k[122]
    cdef double _k123 = ctx.k[123]
    cdef double _k124 = ctx.k[124]
    cdef double _k125 = ctx.k[125]
    cdef double _k126 = ctx.k[126]
    cdef double _k127 = ctx.k[127]
    cdef double _k128 = ctx.k[128]
    cdef double _k129 = ctx.k[129]
    cdef double _k130 = ctx.k[130]
    cdef double _k131 = ctx.k[131]
    cdef double _k132 = ctx.k[132]
    cdef double _k133 = ctx.k[133]
    cdef double _k134 = ctx.k[134]
    cdef double _k135 = ctx.k[135]
    cdef double _k136 = ctx.k[136]
    cdef double _k137 = ctx.k[137]
    cdef double _k138 = ctx.k[138]
    cdef double _k139 = ctx.k[139]
    cdef double _k140 = ctx.k[140]
    cdef double _k141 = ctx.k[141]
    cdef double _k142 = ctx.k[142]
    cdef double _k143 = ctx.k[143]
    cdef double _k144 = ctx.k[144]
    cdef double _k145 = ctx.k[145]
    cdef double _k146 = ctx.k[146]
    cdef double _k147 = ctx.k[147]
    cdef double _k148 = ctx.k[148]
    cdef double _k149 = ctx.k[149]
    cdef double _k150 = ctx.k[150]
    cdef double _k151 = ctx.k[151]
    cdef double _k152 = ctx.k[152]
    cdef double _k153 = ctx.k[153]
    cdef double _k154 = ctx.k[154]
    cdef double _k155 = ctx.k[155]
    cdef double _k156 = ctx.k[156]
    cdef double _k157 = ctx.k[157]
    cdef double beta = _y[0]
    cdef double y = _y[1]
    cdef double z = _y[2]
    cdef double x = _y[3]
    cdef double betad = _y[4]
    cdef double yd = _y[5]
    cdef double zd = _y[6]
    cdef double xd = _y[7]
    cdef double phir = _y[8]
    cdef double hr = _y[9]
    cdef double _cam0[4]  # H(beta/beta_m - beta_0/beta_m) and its derivatives
    camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], beta/beta_m - beta_0/beta_m, _cam0)

    cdef double _m0 = 2.0*sqrt(J)*sqrt(k)*q_b
    cdef double _m1 = omega_s*t
    cdef double _m2 = _m1 - phir
    cdef double _m3 = sqrt(-_m2)
    cdef double _m4 = _m2 + s_g
    cdef double _m5 = sqrt(_m4)
    cdef double _m6 = V_T*(((((1.0/(-_m1*_m3 + _m3*phir))) if ((_m2 < -1.0/1000000000000.0)) else (1e+18))) if ((_m0*betad - _m0*omega_s + beta*k - k*phir < 0.0)) else ((((1.0/(_m1*_m5 - _m5*phir + _m5*s_g))) if ((_m4 > 1.0/1000000000000.0)) else (1e+18))))
    cdef double _m7 = c_x*hr
    cdef double _m8 = sqrt(c_x)
    cdef double _m9 = sqrt(m_x)
    cdef double _m10 = _m8*_m9*q_x
    cdef double _m11 = 2.0*_m10
    cdef double _m12 = _m11*beta_m
    cdef double _m13 = _cam0[0]*h_m
    cdef double _m14 = (1.0/(beta_m))
    cdef double _m15 = _cam0[1]*_m14
    cdef double _m16 = _m15*h_m
    cdef double _m17 = (1.0/(R_b))
    cdef double _m18 = _m17*y
    cdef double _m19 = _m16*_m18
    cdef double _m20 = -_m13 + _m19 + hr + z
    cdef double _m21 = sqrt(_m20)
    cdef double _m22 = _m16*_m21
    cdef double _m23 = -_m13*_m21 + _m18*_m22 + _m21*hr + _m21*z
    cdef double _m24 = (_m20 > 1.0/1000000000000.0)
    cdef double _m25 = c_x*x
    cdef double _m26 = _m11*xd
    cdef double _m27 = _m11*zd
    cdef double _m28 = _m11*betad
    cdef double _m29 = _m16*_m17
    cdef double _m30 = _m11*yd
    cdef double _m31 = (beta_m*beta_m)
    cdef double _m32 = (1.0/(_m31))
    cdef double _m33 = _cam0[2]*_m18*_m32*h_m
    cdef double _m34 = (-_m16*_m28 + _m25 + _m26 + _m27 + _m28*_m33 + _m29*_m30 - _m7 < 0.0)
    cdef double _m35 = _m20 - s_r
    cdef double _m36 = sqrt(-_m35)
    cdef double _m37 = _m16*_m36
    cdef double _m38 = _cam0[0]*_m36*h_m - _m18*_m37 - _m36*hr + _m36*s_r - _m36*z
    cdef double _m39 = (_m35 < -1.0/1000000000000.0)
    cdef double _m40 = (((((1.0/(_m23))) if (_m24) else (1e+18))) if (_m34) else ((((1.0/(_m38))) if (_m39) else (1e+18))))
    cdef double _m41 = V_R*_m40
    cdef double _m42 = _m41*beta_m
    cdef double _m43 = _m12 + _m42
    cdef double _m44 = (1.0/(_m43))
    cdef double _m45 = _m44*h_m
    cdef double _m46 = _m14*_m41
    cdef double _m47 = _cam0[2]*_m46
    cdef double _m48 = _m45*_m47
    cdef double _m49 = _m25*h_m
    cdef double _m50 = _m49*y
    cdef double _m51 = _m11*_m31
    cdef double _m52 = R_b*_m51
    cdef double _m53 = _m31*_m41
    cdef double _m54 = R_b*_m53 + _m52
    cdef double _m55 = (1.0/(_m54))
    cdef double _m56 = _cam0[3]*_m46*_m55
    cdef double _m57 = _m7*h_m
    cdef double _m58 = _m57*y
    cdef double _m59 = _m51 + _m53
    cdef double _m60 = (1.0/(_m59))
    cdef double _m61 = (h_m*h_m)
    cdef double _m62 = _m61*betad
    cdef double _m63 = _cam0[2]*_m41
    cdef double _m64 = 4.0*_m10
    cdef double _m65 = _m15*_m64
    cdef double _m66 = _m63*_m65
    cdef double _m67 = _m26*h_m
    cdef double _m68 = _m56*y
    cdef double _m69 = _m27*h_m
    cdef double _m70 = _m61*yd
    cdef double _m71 = _cam0[2]*_m55
    cdef double _m72 = _m41*_m71
    cdef double _m73 = _m65*_m72
    cdef double _m74 = (beta_m*beta_m*beta_m)
    cdef double _m75 = R_b*_m74
    cdef double _m76 = _m11*_m75 + _m41*_m75
    cdef double _m77 = _m64/_m76
    cdef double _m78 = _m62*y
    cdef double _m79 = _m41*_m78
    cdef double _m80 = _cam0[3]*_m15
    cdef double _m81 = (_cam0[2]*_cam0[2])
    cdef double _m82 = _m46*_m81
    cdef double _m83 = (R_b*R_b)
    cdef double _m84 = _m11*_m83
    cdef double _m85 = _m74*_m84
    cdef double _m86 = _m41*_m83
    cdef double _m87 = _m74*_m86 + _m85
    cdef double _m88 = (1.0/(_m87))
    cdef double _m89 = _m61*_m88
    cdef double _m90 = _m30*_m89
    cdef double _m91 = _m41*_m80*y
    cdef double _m92 = _m82*y
    cdef double _m93 = (y*y)
    cdef double _m94 = (beta_m*beta_m*beta_m*beta_m)
    cdef double _m95 = _m84*_m94
    cdef double _m96 = _m86*_m94 + _m95
    cdef double _m97 = (1.0/(_m96))
    cdef double _m98 = (1.0/(_m23*_m23))
    cdef double _m99 = (1.0/(_m21))
    cdef double _m100 = -0.5*_cam0[2]*_m17*_m32*h_m*y + 0.5*_m15*h_m
    cdef double _m101 = -_m100
    cdef double _m102 = _m101*_m99
    cdef double _m103 = (1.0/(_m38*_m38))
    cdef double _m104 = (1.0/(_m36))
    cdef double _m105 = _m100*_m104
    cdef double _m106 = ((((_m98*(_cam0[0]*_m101*_m99*h_m + _cam0[1]*_m14*_m21*h_m - _m102*_m19 - _m102*hr - _m102*z - _m21*_m33)) if (_m24) else (0.0))) if (_m34) else (((_m103*(-_m105*_m13 + _m105*_m19 + _m105*hr - _m105*s_r + _m105*z + _m33*_m36 - _m37)) if (_m39) else (0.0))))
    cdef double _m107 = _m106*_m7
    cdef double _m108 = V_R*_cam0[1]
    cdef double _m109 = _m108*_m45
    cdef double _m110 = _m106*_m25
    cdef double _m111 = _m110*h_m
    cdef double _m112 = V_R*_m71*y
    cdef double _m113 = _m106*_m109
    cdef double _m114 = _m107*h_m
    cdef double _m115 = _m106*_m112
    cdef double _m116 = _m106*_m28
    cdef double _m117 = (_cam0[1]*_cam0[1])
    cdef double _m118 = V_R*_m61
    cdef double _m119 = _m117*_m118
    cdef double _m120 = _m119*_m60
    cdef double _m121 = _m106*_m30
    cdef double _m122 = _m119*_m55
    cdef double _m123 = _m106*_m62
    cdef double _m124 = _cam0[2]*y
    cdef double _m125 = _m108*_m124
    cdef double _m126 = _m125*_m77
    cdef double _m127 = _m125*_m89
    cdef double _m128 = _m81*_m97
    cdef double _m129 = _m118*_m128*_m93
    cdef double _m130 = (V_R*V_R)
    cdef double _m131 = _m130*_m40
    cdef double _m132 = _m111*_m131
    cdef double _m133 = (1.0/(_m43*_m43))
    cdef double _m134 = _cam0[1]*beta_m
    cdef double _m135 = _m133*_m134
    cdef double _m136 = _m131*_m135
    cdef double _m137 = _m106*_m136
    cdef double _m138 = R_b*_m131
    cdef double _m139 = _m114*_m138
    cdef double _m140 = (1.0/(_m54*_m54))
    cdef double _m141 = _m140*_m31
    cdef double _m142 = _m124*_m141
    cdef double _m143 = R_b*_m132
    cdef double _m144 = _m117*_m131
    cdef double _m145 = _m123*_m144
    cdef double _m146 = _m51/(_m59*_m59)
    cdef double _m147 = _m142*_m67
    cdef double _m148 = _m106*_m138
    cdef double _m149 = _m142*_m69
    cdef double _m150 = _m140*_m52
    cdef double _m151 = _m144*_m70
    cdef double _m152 = _m106*_m151
    cdef double _m153 = _m106*_m131
    cdef double _m154 = _m124*_m153
    cdef double _m155 = (1.0/(_m76*_m76))
    cdef double _m156 = _cam0[1]*_m62
    cdef double _m157 = _m155*_m156*_m64*_m75
    cdef double _m158 = _m85/(_m87*_m87)
    cdef double _m159 = _m154*_m158
    cdef double _m160 = _cam0[1]*_m70
    cdef double _m161 = _m131*_m81*_m93*_m95/(_m96*_m96)
    cdef double _m162 = _m72*h_m
    cdef double _m163 = _cam0[1]*_m63
    cdef double _m164 = 0.5*_m99
    cdef double _m165 = _m164*hr
    cdef double _m166 = _m164*z
    cdef double _m167 = _m117*_m32*y/_m83
    cdef double _m168 = 0.5*_m104
    cdef double _m169 = _m168*hr
    cdef double _m170 = _m168*s_r
    cdef double _m171 = _m168*z
    cdef double _m172 = _m168*_m61
    cdef double _m173 = ((((_m98*(0.5*_cam0[0]*_cam0[1]*_m14*_m17*_m61*_m99 - _m164*_m167*_m61 - _m165*_m29 - _m166*_m29 - _m17*_m22)) if (_m24) else (0.0))) if (_m34) else (((_m103*(_cam0[0]*_m15*_m17*_m172 - _m167*_m172 - _m169*_m29 + _m17*_m37 + _m170*_m29 - _m171*_m29)) if (_m39) else (0.0))))
    cdef double _m174 = _m109*_m173
    cdef double _m175 = _m112*_m173
    cdef double _m176 = _m122*_m30
    cdef double _m177 = _m173*_m62
    cdef double _m178 = _m136*_m173
    cdef double _m179 = _m138*_m173
    cdef double _m180 = _cam0[2]*_m141
    cdef double _m181 = _m179*_m180
    cdef double _m182 = _m144*_m146
    cdef double _m183 = _m124*_m131
    cdef double _m184 = _m173*_m183
    cdef double _m185 = _m158*_m160
    cdef double _m186 = ((((_m98*(0.5*_cam0[0]*_m99*h_m - _m164*_m19 - _m165 - _m166 - _m21)) if (_m24) else (0.0))) if (_m34) else (((_m103*(_m13*_m168 - _m168*_m19 - _m169 + _m170 - _m171 + _m36)) if (_m39) else (0.0))))
    cdef double _m187 = _m109*_m186
    cdef double _m188 = _m112*_m186
    cdef double _m189 = _m186*_m62
    cdef double _m190 = _m138*_m186
    cdef double _m191 = _m183*_m186
    cdef double _m192 = _m41*c_x
    cdef double _m193 = _cam0[1]*_m192*h_m
    cdef double _m194 = R_b*_m12
    cdef double _m195 = R_b*_m42 + _m194
    cdef double _m196 = (1.0/(_m195))
    cdef double _m197 = _m196*_m47
    cdef double _m198 = _m51*_m83
    cdef double _m199 = _m198 + _m53*_m83
    cdef double _m200 = (1.0/(_m199))
    cdef double _m201 = _m28*_m89
    cdef double _m202 = _m108*_m196
    cdef double _m203 = _m106*_m202
    cdef double _m204 = _m119*_m200
    cdef double _m205 = (1.0/(_m195*_m195))
    cdef double _m206 = _m134*_m205
    cdef double _m207 = _m138*_m206
    cdef double _m208 = _m106*_m207
    cdef double _m209 = _m198/(_m199*_m199)
    cdef double _m210 = _m173*_m202
    cdef double _m211 = _m122*_m28
    cdef double _m212 = _m173*_m207
    cdef double _m213 = _m151*_m209
    cdef double _m214 = _m156*_m158
    cdef double _m215 = _m186*_m202
    cdef double _m216 = _m186*_m207
    cdef double _m217 = _m30*h_m
    cdef double _m218 = _m28*h_m
    cdef double _m219 = _m11 + _m41
    cdef double _m220 = (1.0/(_m219))
    cdef double _m221 = V_R*_m220
    cdef double _m222 = _m221*_m7
    cdef double _m223 = _m106*_m221
    cdef double _m224 = (1.0/(_m219*_m219))
    cdef double _m225 = _m131*_m224
    cdef double _m226 = _m106*_m225
    cdef double _m227 = _cam0[1]*h_m
    cdef double _m228 = _m153*_m227
    cdef double _m229 = _m12*_m133*betad
    cdef double _m230 = _m194*_m205*yd
    cdef double _m231 = _m150*betad*h_m
    cdef double _m232 = -_m106*_m222 + _m107*_m225 + _m110*_m221 - _m110*_m225 + _m112*_m116*h_m - _m113*_m28 + _m121*_m202*h_m - _m154*_m231 + _m197*_m217 + _m218*_m68 + _m223*_m26 + _m223*_m27 - _m226*_m26 - _m226*_m27 + _m228*_m229 - _m228*_m230 - _m28*_m48
    cdef double _m233 = _m221*_m25
    cdef double _m234 = _m173*_m221
    cdef double _m235 = _m173*_m225
    cdef double _m236 = _m131*_m227
    cdef double _m237 = _m229*_m236
    cdef double _m238 = _m230*_m236
    cdef double _m239 = _m183*_m231
    cdef double _m240 = _m162*_m28 - _m173*_m222 + _m173*_m233 + _m173*_m237 - _m173*_m238 - _m173*_m239 - _m174*_m28 + _m175*_m218 + _m210*_m217 + _m234*_m26 + _m234*_m27 - _m235*_m25 - _m235*_m26 - _m235*_m27 + _m235*_m7
    cdef double _m241 = _m186*_m222
    cdef double _m242 = _m186*_m221
    cdef double _m243 = _m187*_m28
    cdef double _m244 = _m186*_m225
    cdef double _m245 = _m244*_m25
    cdef double _m246 = _m244*_m26
    cdef double _m247 = _m244*_m27
    cdef double _m248 = _m186*_m238
    cdef double _m249 = _m186*_m239
    cdef double _m250 = _m192*_m220
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
    _Km[0] = _cam0[3]*_m47*_m62*_m64*_m93*_m97 + _m107*_m109 - _m109*_m110 + _m111*_m112 - _m112*_m114 - _m113*_m26 - _m113*_m27 - _m114*_m136 + _m115*_m67 + _m115*_m69 + _m116*_m120 + _m116*_m129 - _m121*_m122 + _m121*_m127 - _m123*_m126 - _m123*_m161 + _m132*_m135 + _m137*_m67 + _m137*_m69 + _m139*_m142 - _m142*_m143 - _m145*_m146 - _m147*_m148 - _m148*_m149 + _m150*_m152 + _m154*_m157 - _m159*_m160 - _m25*_m48 - _m26*_m48 - _m27*_m48 + _m48*_m7 + _m50*_m56 - _m56*_m58 + _m6*k/(_m0 + _m6) + _m60*_m62*_m66 + _m67*_m68 + _m68*_m69 - _m70*_m73 - _m77*_m78*_m82 - _m77*_m79*_m80 + _m90*_m91 + _m90*_m92
    _Km[1] = _m120*_m173*_m28 + _m125*_m173*_m90 - _m126*_m177 + _m128*_m64*_m79 + _m129*_m173*_m28 - _m147*_m179 - _m149*_m179 + _m150*_m151*_m173 - _m156*_m63*_m77 + _m157*_m184 - _m161*_m177 + _m162*_m26 + _m162*_m27 + _m163*_m90 - _m173*_m176 - _m174*_m25 - _m174*_m26 - _m174*_m27 + _m174*_m7 + _m175*_m49 - _m175*_m57 + _m175*_m67 + _m175*_m69 - _m177*_m182 + _m178*_m49 - _m178*_m57 + _m178*_m67 + _m178*_m69 - _m181*_m50 + _m181*_m58 - _m184*_m185 + _m49*_m72 - _m57*_m72
    _Km[2] = 4.0*R_b*_cam0[1]*_cam0[2]*_m130*_m155*_m186*_m40*_m61*_m74*_m8*_m9*betad*q_x*y + R_b*_cam0[2]*_m130*_m140*_m186*_m31*_m40*c_x*h_m*hr*y + 2.0*R_b*_m117*_m130*_m140*_m186*_m31*_m40*_m61*_m8*_m9*q_x*yd + 2.0*V_R*_cam0[1]*_cam0[2]*_m186*_m61*_m8*_m88*_m9*q_x*y*yd + V_R*_cam0[1]*_m186*_m44*c_x*h_m*hr + 2.0*V_R*_cam0[2]*_m186*_m55*_m8*_m9*h_m*q_x*xd*y + 2.0*V_R*_cam0[2]*_m186*_m55*_m8*_m9*h_m*q_x*y*zd + V_R*_cam0[2]*_m186*_m55*c_x*h_m*x*y + 2.0*V_R*_m117*_m186*_m60*_m61*_m8*_m9*betad*q_x + 2.0*V_R*_m186*_m61*_m8*_m81*_m9*_m93*_m97*betad*q_x + 2.0*_cam0[1]*_m130*_m133*_m186*_m40*_m8*_m9*beta_m*h_m*q_x*xd + 2.0*_cam0[1]*_m130*_m133*_m186*_m40*_m8*_m9*beta_m*h_m*q_x*zd + _cam0[1]*_m130*_m133*_m186*_m40*beta_m*c_x*h_m*x - _m126*_m189 - _m136*_m186*_m57 - _m147*_m190 - _m149*_m190 - _m161*_m189 - _m176*_m186 - _m180*_m190*_m50 - _m182*_m189 - _m185*_m191 - _m187*_m25 - _m187*_m26 - _m187*_m27 - _m188*_m57
    _Km[3] = V_R*_cam0[2]*_m40*_m55*c_x*h_m*y - _m193*_m44
    _Km[4] = _m111*_m202 - _m114*_m202 - _m116*_m122 + _m116*_m127 + _m121*_m204 + _m139*_m206 - _m143*_m206 + _m145*_m150 - _m152*_m209 - _m156*_m159 + _m197*_m49 - _m197*_m57 + _m197*_m67 + _m197*_m69 + _m200*_m66*_m70 + _m201*_m91 + _m201*_m92 + _m203*_m67 + _m203*_m69 - _m208*_m67 - _m208*_m69 - _m62*_m73
    _Km[5] = _m125*_m173*_m201 + _m144*_m150*_m177 + _m163*_m201 + _m173*_m204*_m30 - _m173*_m211 - _m173*_m213 - _m184*_m214 + _m210*_m49 - _m210*_m57 + _m210*_m67 + _m210*_m69 - _m212*_m49 + _m212*_m57 - _m212*_m67 - _m212*_m69 + c_y
    _Km[6] = R_b*_cam0[1]*_m130*_m186*_m205*_m40*beta_m*c_x*h_m*hr + 2.0*R_b*_m117*_m130*_m140*_m186*_m31*_m40*_m61*_m8*_m9*betad*q_x + 2.0*V_R*_cam0[1]*_cam0[2]*_m186*_m61*_m8*_m88*_m9*betad*q_x*y + 2.0*V_R*_cam0[1]*_m186*_m196*_m8*_m9*h_m*q_x*xd + 2.0*V_R*_cam0[1]*_m186*_m196*_m8*_m9*h_m*q_x*zd + V_R*_cam0[1]*_m186*_m196*c_x*h_m*x + 2.0*V_R*_m117*_m186*_m200*_m61*_m8*_m9*q_x*yd - _m186*_m211 - _m186*_m213 - _m191*_m214 - _m215*_m57 - _m216*_m49 - _m216*_m67 - _m216*_m69
    _Km[7] = _m193*_m196
    _Km[8] = _m232
    _Km[9] = _m240
    _Km[10] = _m186*_m233 + _m186*_m237 + _m188*_m218 + _m215*_m217 - _m241 + _m242*_m26 + _m242*_m27 - _m243 + _m244*_m7 - _m245 - _m246 - _m247 - _m248 - _m249 + c_z
    _Km[11] = _m250
    _Km[12] = _m232
    _Km[13] = _m240
    _Km[14] = 2.0*V_R*_cam0[1]*_m186*_m196*_m8*_m9*h_m*q_x*yd + 2.0*V_R*_cam0[2]*_m186*_m55*_m8*_m9*betad*h_m*q_x*y + 2.0*V_R*_m186*_m220*_m8*_m9*q_x*xd + 2.0*V_R*_m186*_m220*_m8*_m9*q_x*zd + V_R*_m186*_m220*c_x*x + 2.0*_cam0[1]*_m130*_m133*_m186*_m40*_m8*_m9*beta_m*betad*h_m*q_x + _m130*_m186*_m224*_m40*c_x*hr - _m241 - _m243 - _m245 - _m246 - _m247 - _m248 - _m249
    _Km[15] = _m250


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
    cdef double V_T = ctx.p[18]
    cdef double s_r = ctx.p[19]
    cdef double V_R = ctx.p[20]
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
    cdef double _k96 = ctx.k[96]
    cdef double _k97 = ctx.k[97]
    cdef double _k98 = ctx.k[98]
    cdef double _k99 = ctx.k[99]
    cdef double _k100 = ctx.k[100]
    cdef double _k101 = ctx.k[101]
    cdef double _k102 = ctx.k[102]
    cdef double _k103 = ctx.k[103]
    cdef double _k104 = ctx.k[104]
    cdef double _k105 = ctx.k[105]
    cdef double _k106 = ctx.k[106]
    cdef double _k107 = ctx.k[107]
    cdef double _k108 = ctx.k[108]
    cdef double _k109 = ctx.k[109]
    cdef double _k110 = ctx.k[110]
    cdef double _k111 = ctx.k[111]
    cdef double _k112 = ctx.k[112]
    cdef double _k113 = ctx.k[113]
    cdef double _k114 = ctx.k[114]
    cdef double _k115 = ctx.k[115]
    cdef double _k116 = ctx.k[116]
    cdef double _k117 = ctx.k[117]
    cdef double _k118 = ctx.k[118]
    cdef double _k119 = ctx.k[119]
    cdef double _k120 = ctx.k[120]
    cdef double _k121 = ctx.k[121]
    cdef double _k122 = ctx.k[122]
    cdef double _k123 = ctx.k[123]
    cdef double _k124 = ctx.k[124]
    cdef double _k125 = ctx.k[125]
    cdef double _k126 = ctx.k[126]
    cdef double _k127 = ctx.k[127]
    cdef double _k128 = ctx.k[128]
    cdef double _k129 = ctx.k[129]
    cdef double _k130 = ctx.k[130]
    cdef double _k131 = ctx.k[131]
    cdef double _k132 = ctx.k[132]
    cdef double _k133 = ctx.k[133]
    cdef double _k134 = ctx.k[134]
    cdef double _k135 = ctx.k[135]
    cdef double _k136 = ctx.k[136]
    cdef double _k137 = ctx.k[137]
    cdef double _k138 = ctx.k[138]
    cdef double _k139 = ctx.k[139]
    cdef double _k140 = ctx.k[140]
    cdef double _k141 = ctx.k[141]
    cdef double _k142 = ctx.k[142]
    cdef double _k143 = ctx.k[143]
    cdef double _k144 = ctx.k[144]
    cdef double _k145 = ctx.k[145]
    cdef double _k146 = ctx.k[146]
    cdef double _k147 = ctx.k[147]
    cdef double _k148 = ctx.k[148]
    cdef double _k149 = ctx.k[149]
    cdef double _k150 = ctx.k[150]
    cdef double _k151 = ctx.k[151]
    cdef double _k152 = ctx.k[152]
    cdef double _k153 = ctx.k[153]
    cdef double _k154 = ctx.k[154]
    cdef double _k155 = ctx.k[155]
    cdef double _k156 = ctx.k[156]
    cdef double _k157 = ctx.k[157]
    cdef double beta = _y[0]
    cdef double y = _y[1]
    cdef double z = _y[2]
    cdef double x = _y[3]
    cdef double betad = _y[4]
    cdef double yd = _y[5]
    cdef double zd = _y[6]
    cdef double xd = _y[7]
    cdef double phir = _y[8]
    cdef double hr = _y[9]
    cdef double _cam0[4]  # H(beta/beta_m - beta_0/beta_m) and its derivatives
    camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], beta/beta_m - beta_0/beta_m, _cam0)

    cdef int _k
    cdef double _ftl[10]
    for _k in range(100):
        _J[_k] = 0.0
    for _k in range(10):
        _ftl[_k] = 0.0
    for _k in range(4):
        _J[_k * 11 + 4] = 1.0  # d q'/d q'
    cdef double _j0 = _k0*t
    cdef double _j1 = _j0 + phir
    cdef double _j2 = sqrt(_j1)
    cdef double _j3 = _j0*_j2 + _j2*phir
    cdef double _j4 = -phir
    cdef double _j5 = omega_s*t
    cdef double _j6 = _j4 + _j5
    cdef double _j7 = (_j6 < -1.0/1000000000000.0)
    cdef double _j8 = (_k1*phir + _k2 + _k3*betad + beta*k < 0.0)
    cdef double _j9 = _j6 + s_g
    cdef double _j10 = sqrt(_j9)
    cdef double _j11 = _j10*_j5 - _j10*phir + _j10*s_g
    cdef double _j12 = (_j9 > 1.0/1000000000000.0)
    cdef double _j13 = (((((1.0/(_j3))) if (_j7) else (1e+18))) if (_j8) else ((((1.0/(_j11))) if (_j12) else (1e+18))))
    cdef double _j14 = V_T*_j13 + _k3
    cdef double _j15 = (1.0/(_j14))
    cdef double _j16 = _j13*_j15
    cdef double _j17 = _k73*hr
    cdef double _j18 = _cam0[0]*_k6
    cdef double _j19 = _k7*y
    cdef double _j20 = _cam0[1]*_j19
    cdef double _j21 = _j18 + _j20 + hr + z
    cdef double _j22 = sqrt(_j21)
    cdef double _j23 = _j18*_j22 + _j20*_j22 + _j22*hr + _j22*z
    cdef double _j24 = (_j21 > 1.0/1000000000000.0)
    cdef double _j25 = _cam0[1]*betad
    cdef double _j26 = _cam0[1]*_k11
    cdef double _j27 = _cam0[2]*betad
    cdef double _j28 = _k12*y
    cdef double _j29 = (_j25*_k10 + _j26*yd + _j27*_j28 + _k8*hr + _k9*xd + _k9*zd + c_x*x < 0.0)
    cdef double _j30 = _cam0[0]*h_m
    cdef double _j31 = _cam0[1]*_k13
    cdef double _j32 = _j31*y
    cdef double _j33 = _j30 + _j32 - hr + s_r - z
    cdef double _j34 = sqrt(_j33)
    cdef double _j35 = _j30*_j34 + _j32*_j34 - _j34*hr + _j34*s_r - _j34*z
    cdef double _j36 = (_j21 + _k14 < -1.0/1000000000000.0)
    cdef double _j37 = (((((1.0/(_j23))) if (_j24) else (1e+18))) if (_j29) else ((((1.0/(_j35))) if (_j36) else (1e+18))))
    cdef double _j38 = _j37*_k21 + _k22
    cdef double _j39 = (1.0/(_j38))
    cdef double _j40 = _j37*_j39
    cdef double _j41 = _j40*y
    cdef double _j42 = _k74*x
    cdef double _j43 = _j41*_k80
    cdef double _j44 = _cam0[1]*_j37
    cdef double _j45 = _j37*_k31 + _k32
    cdef double _j46 = (1.0/(_j45))
    cdef double _j47 = _j46*yd
    cdef double _j48 = _j47*_k77
    cdef double _j49 = _j37*_k85
    cdef double _j50 = _j25*_j49
    cdef double _j51 = _j37*_k33 + _k34
    cdef double _j52 = (1.0/(_j51))
    cdef double _j53 = _j52*y
    cdef double _j54 = _j37*_k95
    cdef double _j55 = (y*y)
    cdef double _j56 = _j37*_k29 + _k30
    cdef double _j57 = (1.0/(_j56))
    cdef double _j58 = _j55*_j57
    cdef double _j59 = _k73*x
    cdef double _j60 = (1.0/(_j23*_j23))
    cdef double _j61 = (1.0/(_j22))
    cdef double _j62 = _cam0[0]*_k70
    cdef double _j63 = _j61*_k69
    cdef double _j64 = _cam0[1]*_j61
    cdef double _j65 = _k71*y
    cdef double _j66 = (1.0/(_j35*_j35))
    cdef double _j67 = (1.0/(_j34))
    cdef double _j68 = _j67*_k69
    cdef double _j69 = _j65*_j67
    cdef double _j70 = ((((_j60*(_j22*h_m + _j61*_j62 + _j63*hr + _j63*z + _j64*_j65)) if (_j24) else (0.0))) if (_j29) else (((_j66*(_cam0[1]*_j69 + _j34*_k6 + _j62*_j67 + _j67*_k72 + _j68*hr + _j68*z)) if (_j36) else (0.0))))
    cdef double _j71 = _j37*_k15 + _k16
    cdef double _j72 = (1.0/(_j71))
    cdef double _j73 = _cam0[1]*_j72
    cdef double _j74 = _j70*_j73
    cdef double _j75 = _k74*hr
    cdef double _j76 = _j74*_k78
    cdef double _j77 = _j17*_j70
    cdef double _j78 = _cam0[2]*y
    cdef double _j79 = _j39*_j78
    cdef double _j80 = _j70*_j79
    cdef double _j81 = _j80*_k80
    cdef double _j82 = (_cam0[1]*_cam0[1])
    cdef double _j83 = _j70*_j82
    cdef double _j84 = _j37*_k23 + _k24
    cdef double _j85 = (1.0/(_j84))
    cdef double _j86 = _k77*betad
    cdef double _j87 = _j85*_j86
    cdef double _j88 = _j39*yd
    cdef double _j89 = _j88*_k79
    cdef double _j90 = _j70*_j78
    cdef double _j91 = _cam0[1]*_j48
    cdef double _j92 = _j25*_j52*_k85
    cdef double _j93 = (_cam0[2]*_cam0[2])
    cdef double _j94 = _j58*_j93
    cdef double _j95 = _j86*_j94
    cdef double _j96 = _j70*hr
    cdef double _j97 = (1.0/(_j71*_j71))
    cdef double _j98 = _j44*_j97
    cdef double _j99 = _j98*_k75
    cdef double _j100 = _j70*_j98
    cdef double _j101 = _k76*x
    cdef double _j102 = _j100*_k83
    cdef double _j103 = _j70*x
    cdef double _j104 = (1.0/(_j38*_j38))
    cdef double _j105 = _j37*_j78
    cdef double _j106 = _j104*_j105
    cdef double _j107 = _j106*_k81
    cdef double _j108 = _j106*_k82
    cdef double _j109 = _j70*xd
    cdef double _j110 = _j106*_k87
    cdef double _j111 = _j110*zd
    cdef double _j112 = _j37*_j82
    cdef double _j113 = _j112*_j70
    cdef double _j114 = betad/(_j84*_j84)
    cdef double _j115 = _j114*_k84
    cdef double _j116 = _j104*yd
    cdef double _j117 = _j116*_k86
    cdef double _j118 = _j25*_j70
    cdef double _j119 = _j105/(_j51*_j51)
    cdef double _j120 = _j119*_k89
    cdef double _j121 = _j70*yd
    cdef double _j122 = (1.0/(_j45*_j45))
    cdef double _j123 = _j44*_j78
    cdef double _j124 = _j122*_j123
    cdef double _j125 = _j124*_k90
    cdef double _j126 = _j93*betad
    cdef double _j127 = _j126*_j37*_j55/(_j56*_j56)
    cdef double _j128 = _j127*_k88
    cdef double _j129 = _j37*_j72
    cdef double _j130 = _j129*_k78
    cdef double _j131 = _k93*y
    cdef double _j132 = _j131*_j61
    cdef double _j133 = _j55*_k92
    cdef double _j134 = _j67*_k94
    cdef double _j135 = _j131*_j67
    cdef double _j136 = _cam0[1]*_j67
    cdef double _j137 = ((((_j60*(_cam0[0]*_j61*_j65 + _j132*hr + _j132*z + _j133*_j64 + _j22*_k13*y)) if (_j24) else (0.0))) if (_j29) else (((_j66*(_cam0[0]*_j69 + _j133*_j136 + _j134*y + _j135*hr + _j135*z + _j19*_j34)) if (_j36) else (0.0))))
    cdef double _j138 = _j137*_j73
    cdef double _j139 = _j138*_k78
    cdef double _j140 = _j137*_j79
    cdef double _j141 = _j140*_k80
    cdef double _j142 = _j137*_j82
    cdef double _j143 = _j137*_j78
    cdef double _j144 = _j137*hr
    cdef double _j145 = _j137*_j98
    cdef double _j146 = _j145*_k83
    cdef double _j147 = _j137*x
    cdef double _j148 = _j112*_j137
    cdef double _j149 = _j137*_j25
    cdef double _j150 = _cam0[2]*_j40
    cdef double _j151 = _k17*hr
    cdef double _j152 = _k18*x
    cdef double _j153 = _j150*_k28
    cdef double _j154 = _j37*_k25
    cdef double _j155 = _cam0[1]*_j154
    cdef double _j156 = _j52*_k35
    cdef double _j157 = _j25*_j37
    cdef double _j158 = _cam0[2]*_j157
    cdef double _j159 = _j37*y
    cdef double _j160 = _cam0[0]*_k71
    cdef double _j161 = _j64*_k93
    cdef double _j162 = _j82*_k92*y
    cdef double _j163 = _j136*_k93
    cdef double _j164 = ((((_j60*(_j160*_j64 + _j161*hr + _j161*z + _j162*_j61 + _j22*_j31)) if (_j24) else (0.0))) if (_j29) else (((_j66*(_cam0[1]*_j134 + _cam0[1]*_j34*_k7 + _j136*_j160 + _j162*_j67 + _j163*hr + _j163*z)) if (_j36) else (0.0))))
    cdef double _j165 = _j164*_j73
    cdef double _j166 = _k17*x
    cdef double _j167 = _k18*hr
    cdef double _j168 = _j165*_k26
    cdef double _j169 = _j164*_j79
    cdef double _j170 = _j169*_k28
    cdef double _j171 = _j164*_j82
    cdef double _j172 = _j85*_k25
    cdef double _j173 = _j172*betad
    cdef double _j174 = _j88*_k27
    cdef double _j175 = _j164*_k25
    cdef double _j176 = _cam0[1]*_j47*_j78
    cdef double _j177 = _j164*_j25
    cdef double _j178 = _j156*_j78
    cdef double _j179 = _j94*betad
    cdef double _j180 = _j164*_j98
    cdef double _j181 = _j180*_k101
    cdef double _j182 = _k96*hr
    cdef double _j183 = _k97*x
    cdef double _j184 = _j106*_j164
    cdef double _j185 = _k100*hr
    cdef double _j186 = _j184*_k104
    cdef double _j187 = _k99*x
    cdef double _j188 = _j112*_j164
    cdef double _j189 = _j114*_k102
    cdef double _j190 = _j116*_k103
    cdef double _j191 = _j119*_k106
    cdef double _j192 = _j124*_k107*yd
    cdef double _j193 = _j127*_k105
    cdef double _j194 = 0.5*_j61
    cdef double _j195 = 0.5*_j67
    cdef double _j196 = ((((_j60*(_cam0[0]*_j61*_k69 + _cam0[1]*_j61*_k93*y - _j194*hr - _j194*z - _j22)) if (_j24) else (0.0))) if (_j29) else (((_j66*(_cam0[0]*_j68 + _j131*_j136 - _j195*hr - _j195*z + _j34 + _j67*_k108)) if (_j36) else (0.0))))
    cdef double _j197 = _j196*_j73
    cdef double _j198 = _j197*_k26
    cdef double _j199 = _j196*_j79
    cdef double _j200 = _j199*_k28
    cdef double _j201 = _j196*_j82
    cdef double _j202 = _j196*_k25
    cdef double _j203 = _j196*_j25
    cdef double _j204 = _j196*_j98
    cdef double _j205 = _j204*_k101
    cdef double _j206 = _j106*_j196
    cdef double _j207 = _j206*_k104
    cdef double _j208 = _j112*_j196
    cdef double _j209 = _j151*_j199 + _j152*_j199 + _j166*_j197 + _j167*_j197 + _j173*_j201 + _j174*_j201 + _j176*_j202 + _j178*_j203 + _j179*_j202 + _j182*_j204 + _j183*_j204 + _j185*_j206 + _j187*_j206 + _j189*_j208 + _j190*_j208 + _j191*_j203 + _j192*_j196 + _j193*_j196 + _j198*xd + _j198*zd + _j200*xd + _j200*zd + _j205*xd + _j205*zd + _j207*xd + _j207*zd
    cdef double _j210 = _cam0[1]*_j129
    cdef double _j211 = _cam0[2]*_j41
    cdef double _j212 = _j112*_j39
    cdef double _j213 = _j46*_j78
    cdef double _j214 = _j210*_k26 + _j211*_k28
    cdef double _j215 = (1.0/(_j3*_j3))
    cdef double _j216 = (1.0/(_j2))
    cdef double _j217 = 0.5*phir
    cdef double _j218 = (1.0/(_j11*_j11))
    cdef double _j219 = (1.0/(_j10))
    cdef double _j220 = ((((_j215*(-_j2 - _j216*_j217 + _j216*_k109*t)) if (_j7) else (0.0))) if (_j8) else (((_j218*(_j10 - _j217*_j219 + _j219*_k109*t + _j219*_k110)) if (_j12) else (0.0))))
    cdef double _j221 = _j15*_k20
    cdef double _j222 = _j15*_j220
    cdef double _j223 = _k19*betad
    cdef double _j224 = _k4*phir
    cdef double _j225 = _k5*beta
    cdef double _j226 = _j13/(_j14*_j14)
    cdef double _j227 = _j226*_k113
    cdef double _j228 = _j220*_j226
    cdef double _j229 = _k111*beta
    cdef double _j230 = _k112*phir
    cdef double _j231 = _k114*betad
    cdef double _j232 = _j37*_k38 + _k39
    cdef double _j233 = (1.0/(_j232))
    cdef double _j234 = _cam0[1]*_j233
    cdef double _j235 = _j234*_j70
    cdef double _j236 = _j235*_k80
    cdef double _j237 = _j37*_k43 + _k44
    cdef double _j238 = (1.0/(_j237))
    cdef double _j239 = _j238*yd
    cdef double _j240 = _j239*_k77
    cdef double _j241 = _j39*betad
    cdef double _j242 = _j241*_k79
    cdef double _j243 = _j213*_k77
    cdef double _j244 = _j44/(_j232*_j232)
    cdef double _j245 = _j244*_k115
    cdef double _j246 = _j244*_k116
    cdef double _j247 = _j244*_k117
    cdef double _j248 = _j247*zd
    cdef double _j249 = yd/(_j237*_j237)
    cdef double _j250 = _j249*_k118
    cdef double _j251 = _j104*betad
    cdef double _j252 = _j251*_k86
    cdef double _j253 = _j105*_j122
    cdef double _j254 = _j253*_k90
    cdef double _j255 = _j233*_j37
    cdef double _j256 = _j255*_k80
    cdef double _j257 = _j159*_j27
    cdef double _j258 = _j137*_j234
    cdef double _j259 = _j258*_k80
    cdef double _j260 = _j137*_j247
    cdef double _j261 = _j46*_k45
    cdef double _j262 = _j164*_j234
    cdef double _j263 = _k40*hr
    cdef double _j264 = _k41*x
    cdef double _j265 = _j262*_k42
    cdef double _j266 = _j238*_k45
    cdef double _j267 = _j266*yd
    cdef double _j268 = _j241*_k46
    cdef double _j269 = _j213*_k45
    cdef double _j270 = _j164*_j244
    cdef double _j271 = _k121*x
    cdef double _j272 = _k122*hr
    cdef double _j273 = _j270*_k124
    cdef double _j274 = _j251*_k123
    cdef double _j275 = _j249*_k125
    cdef double _j276 = _j253*_k126
    cdef double _j277 = _j196*_j234
    cdef double _j278 = _j277*_k42
    cdef double _j279 = _j196*_j244
    cdef double _j280 = _j279*_k124
    cdef double _j281 = _j201*_j267 + _j201*_j268 + _j203*_j269 + _j203*_j276 + _j208*_j274 + _j208*_j275 + _j263*_j277 + _j264*_j277 + _j271*_j279 + _j272*_j279 + _j278*xd + _j278*zd + _j280*xd + _j280*zd
    cdef double _j282 = _cam0[1]*_j255
    cdef double _j283 = _j282*_k42
    cdef double _j284 = _cam0[3]*_j41*betad
    cdef double _j285 = V_R*_j37 + _k9
    cdef double _j286 = (1.0/(_j285))
    cdef double _j287 = _j286*_j70
    cdef double _j288 = _k127*hr
    cdef double _j289 = _k128*x
    cdef double _j290 = _j287*_k131
    cdef double _j291 = _j25*_j72
    cdef double _j292 = _j291*_k78
    cdef double _j293 = _j27*_j39*y
    cdef double _j294 = _j293*_k80
    cdef double _j295 = _j37/(_j285*_j285)
    cdef double _j296 = _j295*_j70
    cdef double _j297 = _k129*x
    cdef double _j298 = _k130*hr
    cdef double _j299 = _j296*_k132
    cdef double _j300 = _j157*_j97
    cdef double _j301 = _j300*_k83
    cdef double _j302 = _j104*_j257
    cdef double _j303 = _j302*_k87
    cdef double _j304 = _cam0[1]*(_j121*_j247 + _j236*yd + _j287*_j288 + _j287*_j289 + _j290*xd + _j290*zd + _j292*_j70 + _j294*_j70 + _j296*_j297 + _j296*_j298 + _j299*xd + _j299*zd + _j301*_j70 + _j303*_j70)
    cdef double _j305 = _j137*_j286
    cdef double _j306 = _j305*_k131
    cdef double _j307 = _j137*_j295
    cdef double _j308 = _j307*_k132
    cdef double _j309 = _cam0[2]*(_j130*betad + _j137*_j292 + _j137*_j294 + _j137*_j301 + _j137*_j303 + _j256*yd + _j259*yd + _j260*yd + _j288*_j305 + _j289*_j305 + _j297*_j307 + _j298*_j307 + _j306*xd + _j306*zd + _j308*xd + _j308*zd)
    cdef double _j310 = _j27*_j40
    cdef double _j311 = _j164*_j286
    cdef double _j312 = _k49*hr
    cdef double _j313 = _k50*x
    cdef double _j314 = _j311*_k51
    cdef double _j315 = _k52*yd
    cdef double _j316 = _j291*_k53
    cdef double _j317 = _j293*_k52
    cdef double _j318 = _j164*_j295
    cdef double _j319 = _k135*x
    cdef double _j320 = _k136*hr
    cdef double _j321 = _j318*_k137
    cdef double _j322 = _j300*_k138
    cdef double _j323 = _k139*yd
    cdef double _j324 = _j302*_k140
    cdef double _j325 = _j196*_j286
    cdef double _j326 = _j325*_k51
    cdef double _j327 = _j196*_j295
    cdef double _j328 = _j327*_k137
    cdef double _j329 = _j196*_j316 + _j196*_j317 + _j196*_j322 + _j196*_j324 + _j277*_j315 + _j279*_j323 + _j312*_j325 + _j313*_j325 + _j319*_j327 + _j320*_j327 + _j326*xd + _j326*zd + _j328*xd + _j328*zd
    cdef double _j330 = _j286*_j37
    cdef double _j331 = _j330*_k51
    cdef double _j332 = _k54*hr
    cdef double _j333 = _k55*x
    cdef double _j334 = _j311*_k56
    cdef double _j335 = _k57*yd
    cdef double _j336 = _j291*_k58
    cdef double _j337 = _j293*_k57
    cdef double _j338 = _k143*x
    cdef double _j339 = _k144*hr
    cdef double _j340 = _j318*_k145
    cdef double _j341 = _j300*_k146
    cdef double _j342 = _k147*yd
    cdef double _j343 = _j302*_k148
    cdef double _j344 = _j325*_k56
    cdef double _j345 = _j327*_k145
    cdef double _j346 = _j196*_j336 + _j196*_j337 + _j196*_j341 + _j196*_j343 + _j277*_j335 + _j279*_j342 + _j325*_j332 + _j325*_j333 + _j327*_j338 + _j327*_j339 + _j344*xd + _j344*zd + _j345*xd + _j345*zd
    cdef double _j347 = _j330*_k56
    cdef double _j348 = _k3*(-betad + omega_s) + k*(-_j4 - beta)
    cdef double _j349 = (_j348 > 0.0)
    cdef double _j350 = V_T*((((pow(_j1, -3.0/2.0)) if (_j7) else (1e+18))) if (_j349) else (((pow(_j9, -3.0/2.0)) if (_j12) else (1e+18)))) + _k3
    cdef double _j351 = (1.0/(_j350))
    cdef double _j352 = pow(_j1, -5.0/2.0)
    cdef double _j353 = pow(_j9, -5.0/2.0)
    cdef double _j354 = V_T*_j348/(_j350*_j350)
    cdef double _j355 = _k60*y
    cdef double _j356 = _k13*yd
    cdef double _j357 = _cam0[1]*_k59 + _cam0[2]*_j355
    cdef double _j358 = _k9*(_cam0[1]*_j356 + _j357*betad - xd - zd) + c_x*(hr - x)
    cdef double _j359 = (_j358 > 0.0)
    cdef double _j360 = V_R*((((pow(_j21, -3.0/2.0)) if (_j24) else (1e+18))) if (_j359) else (((pow(_j33, -3.0/2.0)) if (_j36) else (1e+18)))) + _k9
    cdef double _j361 = (1.0/(_j360))
    cdef double _j362 = pow(_j21, -5.0/2.0)
    cdef double _j363 = pow(_j33, -5.0/2.0)
    cdef double _j364 = _j358/(_j360*_j360)
    cdef double _j365 = _j356 + _k59*betad
    cdef double _j366 = _j361*_k61
    cdef double _j367 = _j362*_k149
    cdef double _j368 = _j363*_k150
    cdef double _j369 = V_R*_j364
    cdef double _j370 = _j369*((((-1.5*_j362) if (_j24) else (0.0))) if (_j359) else (((1.5*_j363) if (_j36) else (0.0))))
    cdef double _j371 = _j361*_k9
    cdef double _j372 = _k109*phir
    cdef double _j373 = _k154*t
    cdef double _j374 = ((((_j215*(_j2*omega_s + _j216*_j372 + _j216*_j373)) if (_j7) else (0.0))) if (_j8) else (((_j218*(_j10*_k0 + _j219*_j372 + _j219*_j373 + _j219*_k155)) if (_j12) else (0.0))))
    cdef double _j375 = _j15*_j374
    cdef double _j376 = _j226*_j374
    _J[40] = _cam0[1]*_k91*(_j100*_j101 + _j102*xd + _j102*zd + _j103*_j107 + _j108*_j96 + _j109*_j110 + _j111*_j70 + _j113*_j115 + _j113*_j117 + _j118*_j120 + _j121*_j125 + _j128*_j70 + _j42*_j80 + _j59*_j74 + _j70*_j95 + _j74*_j75 + _j76*xd + _j76*zd + _j77*_j79 + _j81*xd + _j81*zd + _j83*_j87 + _j83*_j89 + _j90*_j91 + _j90*_j92 + _j96*_j99) + _cam0[2]*_k91*(_cam0[1]*_j49*_j88 + _j101*_j145 + _j105*_j48 + _j107*_j147 + _j108*_j144 + _j110*_j137*xd + _j111*_j137 + _j115*_j148 + _j117*_j148 + _j120*_j149 + _j125*_j137*yd + _j128*_j137 + _j129*_j59 + _j129*_j75 + _j130*xd + _j130*zd + _j137*_j95 + _j138*_j59 + _j138*_j75 + _j139*xd + _j139*zd + _j140*_j17 + _j140*_j42 + _j141*xd + _j141*zd + _j142*_j87 + _j142*_j89 + _j143*_j91 + _j143*_j92 + _j144*_j99 + _j146*xd + _j146*zd + _j25*_j54*_j85 + _j27*_j49*_j53) + _cam0[3]*_k91*(_j17*_j41 + _j27*_j54*_j58 + _j41*_j42 + _j43*xd + _j43*zd + _j44*_j48*y + _j50*_j53) + _j16*_k5
    _J[41] = _cam0[2]*_j155*_j47 + _j126*_j159*_j57*_k98 + _j150*_j151 + _j150*_j152 + _j151*_j169 + _j152*_j169 + _j153*xd + _j153*zd + _j156*_j158 + _j164*_j192 + _j164*_j193 + _j165*_j166 + _j165*_j167 + _j168*xd + _j168*zd + _j170*xd + _j170*zd + _j171*_j173 + _j171*_j174 + _j175*_j176 + _j175*_j179 + _j177*_j178 + _j177*_j191 + _j180*_j182 + _j180*_j183 + _j181*xd + _j181*zd + _j184*_j185 + _j184*_j187 + _j186*xd + _j186*zd + _j188*_j189 + _j188*_j190
    _J[42] = _j209
    _J[43] = _j210*_k17 + _j211*_k18
    _J[44] = _j112*_j172 + _j123*_j156 + _j154*_j94 + _j16*_k19
    _J[45] = _j155*_j213 + _j212*_k27
    _J[46] = _j214
    _J[47] = _j214
    _J[48] = _j16*_k4 + _j220*_j221 + _j220*_j227 + _j222*_j223 + _j222*_j224 + _j222*_j225 + _j228*_j229 + _j228*_j230 + _j228*_j231
    _J[49] = _j209 + _j210*_k18 + _j211*_k17
    _J[50] = _cam0[1]*_k119*(_j103*_j245 + _j109*_j247 + _j113*_j250 + _j113*_j252 + _j118*_j243 + _j118*_j254 + _j234*_j77 + _j235*_j42 + _j236*xd + _j236*zd + _j240*_j83 + _j242*_j83 + _j246*_j96 + _j248*_j70) + _cam0[2]*_k119*(_cam0[1]*_j239*_j54 + _j137*_j248 + _j142*_j240 + _j142*_j242 + _j144*_j246 + _j147*_j245 + _j148*_j250 + _j148*_j252 + _j149*_j243 + _j149*_j254 + _j17*_j255 + _j17*_j258 + _j255*_j42 + _j256*xd + _j256*zd + _j257*_j46*_k77 + _j258*_j42 + _j259*xd + _j259*zd + _j260*xd + _j39*_j50) + _cam0[3]*_j157*_j46*_k120*y
    _J[51] = _j158*_j261 + _j171*_j267 + _j171*_j268 + _j177*_j269 + _j177*_j276 + _j188*_j274 + _j188*_j275 + _j262*_j263 + _j262*_j264 + _j265*xd + _j265*zd + _j270*_j271 + _j270*_j272 + _j273*xd + _j273*zd + _k36
    _J[52] = _j281
    _J[53] = _j282*_k41
    _J[54] = _j123*_j261 + _j212*_k46
    _J[55] = _j112*_j266 + _k37
    _J[56] = _j283
    _J[57] = _j283
    _J[59] = _j281 + _j282*_k40
    _J[60] = _j284*_k134 + _j304*_k133 + _j309*_k133
    _J[61] = _j164*_j316 + _j164*_j317 + _j164*_j322 + _j164*_j324 + _j262*_j315 + _j270*_j323 + _j310*_k52 + _j311*_j312 + _j311*_j313 + _j314*xd + _j314*zd + _j318*_j319 + _j318*_j320 + _j321*xd + _j321*zd
    _J[62] = _j329 + _k47
    _J[63] = _j330*_k50
    _J[64] = _j210*_k53 + _j211*_k52
    _J[65] = _j282*_k52
    _J[66] = _j331 + _k48
    _J[67] = _j331
    _J[69] = _j329 + _j330*_k49
    _J[70] = _j284*_k142 + _j304*_k141 + _j309*_k141
    _J[71] = _j164*_j336 + _j164*_j337 + _j164*_j341 + _j164*_j343 + _j262*_j335 + _j270*_j342 + _j310*_k57 + _j311*_j332 + _j311*_j333 + _j318*_j338 + _j318*_j339 + _j334*xd + _j334*zd + _j340*xd + _j340*zd
    _J[72] = _j346
    _J[73] = _j330*_k55
    _J[74] = _j210*_k58 + _j211*_k57
    _J[75] = _j282*_k57
    _J[76] = _j347
    _J[77] = _j347
    _J[79] = _j330*_k54 + _j346
    _J[80] = _j351*k
    _J[84] = _j351*_k3
    _J[88] = _j351*_k1 + _j354*((((-1.5*_j352) if (_j7) else (0.0))) if (_j349) else (((1.5*_j353) if (_j12) else (0.0))))
    _J[90] = _cam0[1]*_j364*_k153*((((_j362*_k151) if (_j24) else (0.0))) if (_j359) else (((_j363*_k152) if (_j36) else (0.0)))) + _cam0[2]*_k63*(_j365*_j366 + _j365 + _j369*((((_j367*y) if (_j24) else (0.0))) if (_j359) else (((_j368*y) if (_j36) else (0.0))))) + _cam0[3]*_k63*(_j28*_j361*betad + _j355*betad)
    _J[91] = _j27*_j361*_k12 + _j27*_k60 + _j369*((((_cam0[1]*_j367) if (_j24) else (0.0))) if (_j359) else (((_cam0[1]*_j368) if (_j36) else (0.0))))
    _J[92] = _j370
    _J[93] = _j361*c_x
    _J[94] = _j357*_j366 + _j357
    _J[95] = _j26*_j361 + _j31
    _J[96] = _j371 - 1.0
    _J[97] = _j371
    _J[99] = _j361*_k8 + _j370
    _ftl[4] = _j221*_j374 + _j223*_j375 + _j224*_j375 + _j225*_j375 + _j227*_j374 + _j229*_j376 + _j230*_j376 + _j231*_j376
    _ftl[8] = _j354*((((_j352*_k156) if (_j7) else (0.0))) if (_j349) else (((_j353*_k157) if (_j12) else (0.0))))
    if _ft != NULL:
        for _k in range(10):
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
    cdef double V_T = ctx.p[18]
    cdef double s_r = ctx.p[19]
    cdef double V_R = ctx.p[20]
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
    cdef double _k96 = ctx.k[96]
    cdef double _k97 = ctx.k[97]
    cdef double _k98 = ctx.k[98]
    cdef double _k99 = ctx.k[99]
    cdef double _k100 = ctx.k[100]
    cdef double _k101 = ctx.k[101]
    cdef double _k102 = ctx.k[102]
    cdef double _k103 = ctx.k[103]
    cdef double _k104 = ctx.k[104]
    cdef double _k105 = ctx.k[105]
    cdef double _k106 = ctx.k[106]
    cdef double _k107 = ctx.k[107]
    cdef double _k108 = ctx.k[108]
    cdef double _k109 = ctx.k[109]
    cdef double _k110 = ctx.k[110]
    cdef double _k111 = ctx.k[111]
    cdef double _k112 = ctx.k[112]
    cdef double _k113 = ctx.k[113]
    cdef double _k114 = ctx.k[114]
    cdef double _k115 = ctx.k[115]
    cdef double _k116 = ctx.k[116]
    cdef double _k117 = ctx.k[117]
    cdef double _k118 = ctx.k[118]
    cdef double _k119 = ctx.k[119]
    cdef double _k120 = ctx.k[120]
    cdef double _k121 = ctx.k[121]
    cdef double _k122 = ctx.k[122]
    cdef double _k123 = ctx.k[123]
    cdef double _k124 = ctx.k[124]
    cdef double _k125 = ctx.k[125]
    cdef double _k126 = ctx.k[126]
    cdef double _k127 = ctx.k[127]
    cdef double _k128 = ctx.k[128]
    cdef double _k129 = ctx.k[129]
    cdef double _k130 = ctx.k[130]
    cdef double _k131 = ctx.k[131]
    cdef double _k132 = ctx.k[132]
    cdef double _k133 = ctx.k[133]
    cdef double _k134 = ctx.k[134]
    cdef double _k135 = ctx.k[135]
    cdef double _k136 = ctx.k[136]
    cdef double _k137 = ctx.k[137]
    cdef double _k138 = ctx.k[138]
    cdef double _k139 = ctx.k[139]
    cdef double _k140 = ctx.k[140]
    cdef double _k141 = ctx.k[141]
    cdef double _k142 = ctx.k[142]
    cdef double _k143 = ctx.k[143]
    cdef double _k144 = ctx.k[144]
    cdef double _k145 = ctx.k[145]
    cdef double _k146 = ctx.k[146]
    cdef double _k147 = ctx.k[147]
    cdef double _k148 = ctx.k[148]
    cdef double _k149 = ctx.k[149]
    cdef double _k150 = ctx.k[150]
    cdef double _k151 = ctx.k[151]
    cdef double _k152 = ctx.k[152]
    cdef double _k153 = ctx.k[153]
    cdef double _k154 = ctx.k[154]
    cdef double _k155 = ctx.k[155]
    cdef double _k156 = ctx.k[156]
    cdef double _k157 = ctx.k[157]
    cdef double beta = _y[0]
    cdef double y = _y[1]
    cdef double z = _y[2]
    cdef double x = _y[3]
    cdef double betad = _y[4]
    cdef double yd = _y[5]
    cdef double zd = _y[6]
    cdef double xd = _y[7]
    cdef double phir = _y[8]
    cdef double hr = _y[9]

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
    cdef double V_T = ctx.p[18]
    cdef double s_r = ctx.p[19]
    cdef double V_R = ctx.p[20]
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
    cdef double _k96 = ctx.k[96]
    cdef double _k97 = ctx.k[97]
    cdef double _k98 = ctx.k[98]
    cdef double _k99 = ctx.k[99]
    cdef double _k100 = ctx.k[100]
    cdef double _k101 = ctx.k[101]
    cdef double _k102 = ctx.k[102]
    cdef double _k103 = ctx.k[103]
    cdef double _k104 = ctx.k[104]
    cdef double _k105 = ctx.k[105]
    cdef double _k106 = ctx.k[106]
    cdef double _k107 = ctx.k[107]
    cdef double _k108 = ctx.k[108]
    cdef double _k109 = ctx.k[109]
    cdef double _k110 = ctx.k[110]
    cdef double _k111 = ctx.k[111]
    cdef double _k112 = ctx.k[112]
    cdef double _k113 = ctx.k[113]
    cdef double _k114 = ctx.k[114]
    cdef double _k115 = ctx.k[115]
    cdef double _k116 = ctx.k[116]
    cdef double _k117 = ctx.k[117]
    cdef double _k118 = ctx.k[118]
    cdef double _k119 = ctx.k[119]
    cdef double _k120 = ctx.k[120]
    cdef double _k121 = ctx.k[121]
    cdef double _k122 = ctx.k[122]
    cdef double _k123 = ctx.k[123]
    cdef double _k124 = ctx.k[124]
    cdef double _k125 = ctx.k[125]
    cdef double _k126 = ctx.k[126]
    cdef double _k127 = ctx.k[127]
    cdef double _k128 = ctx.k[128]
    cdef double _k129 = ctx.k[129]
    cdef double _k130 = ctx.k[130]
    cdef double _k131 = ctx.k[131]
    cdef double _k132 = ctx.k[132]
    cdef double _k133 = ctx.k[133]
    cdef double _k134 = ctx.k[134]
    cdef double _k135 = ctx.k[135]
    cdef double _k136 = ctx.k[136]
    cdef double _k137 = ctx.k[137]
    cdef double _k138 = ctx.k[138]
    cdef double _k139 = ctx.k[139]
    cdef double _k140 = ctx.k[140]
    cdef double _k141 = ctx.k[141]
    cdef double _k142 = ctx.k[142]
    cdef double _k143 = ctx.k[143]
    cdef double _k144 = ctx.k[144]
    cdef double _k145 = ctx.k[145]
    cdef double _k146 = ctx.k[146]
    cdef double _k147 = ctx.k[147]
    cdef double _k148 = ctx.k[148]
    cdef double _k149 = ctx.k[149]
    cdef double _k150 = ctx.k[150]
    cdef double _k151 = ctx.k[151]
    cdef double _k152 = ctx.k[152]
    cdef double _k153 = ctx.k[153]
    cdef double _k154 = ctx.k[154]
    cdef double _k155 = ctx.k[155]
    cdef double _k156 = ctx.k[156]
    cdef double _k157 = ctx.k[157]
    cdef double beta = _y[0]
    cdef double y = _y[1]
    cdef double z = _y[2]
    cdef double x = _y[3]
    cdef double betad = _y[4]
    cdef double yd = _y[5]
    cdef double zd = _y[6]
    cdef double xd = _y[7]
    cdef double phir = _y[8]
    cdef double hr = _y[9]
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
    cdef double s_g = ctx.p[17]
    cdef double V_T = ctx.p[18]
    cdef double s_r = ctx.p[19]
    cdef double V_R = ctx.p[20]
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
    cdef double _k96 = ctx.k[96]
    cdef double _k97 = ctx.k[97]
    cdef double _k98 = ctx.k[98]
    cdef double _k99 = ctx.k[99]
    cdef double _k100 = ctx.k[100]
    cdef double _k101 = ctx.k[101]
    cdef double _k102 = ctx.k[102]
    cdef double _k103 = ctx.k[103]
    cdef double _k104 = ctx.k[104]
    cdef double _k105 = ctx.k[105]
    cdef double _k106 = ctx.k[106]
    cdef double _k107 = ctx.k[107]
    cdef double _k108 = ctx.k[108]
    cdef double _k109 = ctx.k[109]
    cdef double _k110 = ctx.k[110]
    cdef double _k111 = ctx.k[111]
    cdef double _k112 = ctx.k[112]
    cdef double _k113 = ctx.k[113]
    cdef double _k114 = ctx.k[114]
    cdef double _k115 = ctx.k[115]
    cdef double _k116 = ctx.k[116]
    cdef double _k117 = ctx.k[117]
    cdef double _k118 = ctx.k[118]
    cdef double _k119 = ctx.k[119]
    cdef double _k120 = ctx.k[120]
    cdef double _k121 = ctx.k[121]
    cdef double _k122 = ctx.k[122]
    cdef double _k123 = ctx.k[123]
    cdef double _k124 = ctx.k[124]
    cdef double _k125 = ctx.k[125]
    cdef double _k126 = ctx.k[126]
    cdef double _k127 = ctx.k[127]
    cdef double _k128 = ctx.k[128]
    cdef double _k129 = ctx.k[129]
    cdef double _k130 = ctx.k[130]
    cdef double _k131 = ctx.k[131]
    cdef double _k132 = ctx.k[132]
    cdef double _k133 = ctx.k[133]
    cdef double _k134 = ctx.k[134]
    cdef double _k135 = ctx.k[135]
    cdef double _k136 = ctx.k[136]
    cdef double _k137 = ctx.k[137]
    cdef double _k138 = ctx.k[138]
    cdef double _k139 = ctx.k[139]
    cdef double _k140 = ctx.k[140]
    cdef double _k141 = ctx.k[141]
    cdef double _k142 = ctx.k[142]
    cdef double _k143 = ctx.k[143]
    cdef double _k144 = ctx.k[144]
    cdef double _k145 = ctx.k[145]
    cdef double _k146 = ctx.k[146]
    cdef double _k147 = ctx.k[147]
    cdef double _k148 = ctx.k[148]
    cdef double _k149 = ctx.k[149]
    cdef double _k150 = ctx.k[150]
    cdef double _k151 = ctx.k[151]
    cdef double _k152 = ctx.k[152]
    cdef double _k153 = ctx.k[153]
    cdef double _k154 = ctx.k[154]
    cdef double _k155 = ctx.k[155]
    cdef double _k156 = ctx.k[156]
    cdef double _k157 = ctx.k[157]
    cdef double beta = _y[0]
    cdef double y = _y[1]
    cdef double z = _y[2]
    cdef double x = _y[3]
    cdef double betad = _y[4]
    cdef double yd = _y[5]
    cdef double zd = _y[6]
    cdef double xd = _y[7]
    cdef double phir = _y[8]
    cdef double hr = _y[9]
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
    cdef double s_g = p[17]
    cdef double V_T = p[18]
    cdef double s_r = p[19]
    cdef double V_R = p[20]
    return [0.0, 0.0, 0.0, 0.0, omega_s, 0.0, 0.0, 0.0, 0.0, 0.0]


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
    cdef double V_T = p[18]
    cdef double s_r = p[19]
    cdef double V_R = p[20]
    return [None]


cdef ModelC _model
_model.abi_version = CAMDYN_ABI
_model.n_q = _NQ
_model.n_states = _NS
_model.n_params = 21
_model.n_outputs = 11
_model.n_families = 1
_model.n_instances = _NCAM
_model.n_modes = _NM
_model.n_events = _NE
_model.n_const = 158
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
 "name": "dynacam_axial_ideal_gearsqueeze_groovesqueeze_shafty_shaftz",
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
   "squeeze"
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
   "groove-squeeze"
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
   "doc": "roller over the cam wall: 0 lower wall, s_r upper",
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
   "default": 0.001,
   "doc": "squeeze coefficient of the gear teeth (6.6), with R_b^(1/2)",
   "high": null,
   "low": 0.0,
   "name": "V_T",
   "open_high": false,
   "open_low": true,
   "range": "0 < V_T",
   "unit": "N m s rad^(1/2)"
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
  },
  {
   "default": 1e-05,
   "doc": "squeeze coefficient of the roller (6.38)",
   "high": null,
   "low": 0.0,
   "name": "V_R",
   "open_high": false,
   "open_low": true,
   "range": "0 < V_R",
   "unit": "N s m^(1/2)"
  }
 ],
 "reference": "thesis ch. 6, figs 6.1, 6.2, 6.15, 6.18",
 "residual": {
  "acceleration": "Xdd",
  "error": "U",
  "rise_end": 1.0,
  "rise_state": "B"
 },
 "source_hash": "sha256:87cc6f632d9fab7e7beb98a5f275e3a12bd3d22974d3c67011929413b944c3cb",
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
  },
  {
   "doc": "angle of the gear output wheel (6.1)",
   "initial": 0.0,
   "name": "phir",
   "scale": 1.0,
   "unit": "rad"
  },
  {
   "doc": "roller position (6.41)",
   "initial": 0.0,
   "name": "hr",
   "scale": 0.01,
   "unit": "m"
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

# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True, initializedcheck=False
#
# GENERATED FILE - DO NOT EDIT.  Written by `camdyn derive` from camdyn/derive/models/dynacam.py;
# edit that and regenerate.  `camdyn derive --check` fails while this file is stale.
# Derivation key: sha256:7252927a9dbdd188b15df1f870caf5ab6388d097330be120ac4a906511383c59
# Text hash: sha256:794c566b528a87a327eac37b03f06e309294b34afb9daf4e68dfb1e2f750bf31
#
# DYNACAM, cam mechanism with four degrees of freedom and drive (thesis ch. 6, figs 6.1, 6.2, 6.15, 6.18)
# Source hash: sha256:17a2d5a7d7f49c908f0cc60227fa5d7ea6df0fff82762a03baea1b9af6239c3b
#
# This variant:
#   cam = radial: radial disk cam, pitch radius R_b + h (6.21)
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
    cdef double _c0 = (R_b*R_b)
    cdef double _c1 = (h_m*h_m)
    cdef double _c2 = 2.0*h_m
    cdef double _c3 = R_b*_c2
    cdef double _c4 = (R_b*R_b*R_b)
    cdef double _c5 = (h_m*h_m*h_m)
    cdef double _c6 = 3.0*_c0*h_m
    cdef double _c7 = R_b*_c1
    cdef double _c8 = (h_m*h_m*h_m*h_m)
    cdef double _c9 = 4.0*h_m
    cdef double _c10 = _c4*_c9
    cdef double _c11 = R_b*_c5
    cdef double _c12 = _c0*_c1
    cdef double _c13 = c_x*h_m
    cdef double _c14 = sqrt(m_x)
    cdef double _c15 = sqrt(c_x)*q_x
    cdef double _c16 = _c14*_c15
    cdef double _c17 = 2.0*_c16
    cdef double _c18 = _c16*_c2
    cdef double _c19 = (beta_m*beta_m)
    cdef double _c20 = _c19*h_m
    cdef double _c21 = k*omega_s
    cdef double _c22 = sqrt(J)
    cdef double _c23 = 2.0*sqrt(k)*q_b
    cdef double _c24 = _c22*_c23
    cdef double _c25 = (beta_m*beta_m*beta_m*beta_m)
    cdef double _c26 = (beta_m*beta_m*beta_m)
    cdef double _c27 = _c26*h_m
    cdef double _c28 = _c5*beta_m
    cdef double _c29 = _c1*_c19
    cdef double _c30 = _c1*beta_m
    cdef double _c31 = _c17*_c8
    cdef double _c32 = 2.0*_c1
    cdef double _c33 = _c16*_c32
    cdef double _c34 = 2.0*_c29
    cdef double _c35 = _c16*_c34
    cdef double _c36 = _c16*_c5
    cdef double _c37 = 4.0*_c16
    cdef double _c38 = (1.0/(J))
    cdef double _c39 = (1.0/(_c25))
    cdef double _c40 = _c38*_c39
    cdef double _c41 = sqrt(m_y)
    cdef double _c42 = 2.0*sqrt(c_y)*q_y
    cdef double _c43 = _c41*_c42
    cdef double _c44 = _c17*_c5
    cdef double _c45 = 2.0*_c30
    cdef double _c46 = _c16*_c45
    cdef double _c47 = (1.0/(_c26))
    cdef double _c48 = (1.0/(m_y))
    cdef double _c49 = _c47*_c48
    cdef double _c50 = c_x + c_z
    cdef double _c51 = sqrt(m_z)
    cdef double _c52 = sqrt(c_z)*q_z
    cdef double _c53 = _c16 + _c51*_c52
    cdef double _c54 = beta_m*h_m
    cdef double _c55 = (1.0/(_c19))
    cdef double _c56 = (1.0/(m_z))
    cdef double _c57 = _c55*_c56
    cdef double _c58 = (1.0/(m_x))
    cdef double _c59 = _c55*_c58
    cdef double _c60 = _c23/_c22
    cdef double _c61 = -_c50*_c56
    cdef double _c62 = 2.0*_c56
    cdef double _c63 = _c16*_c62
    cdef double _c64 = _c15/_c14
    cdef double _c65 = 2.0*_c64
    cdef double _c66 = (1.0/(beta_m))
    cdef double _c67 = (1.0/(h_m))
    cdef double _c68 = (1.0/(omega_s*omega_s))
    cdef double _c69 = _c13*_c66
    cdef double _c70 = _c66*h_m
    cdef double _c71 = 3.0*_c5
    cdef double _c72 = 6.0*_c7
    cdef double _c73 = 4.0*_c8
    cdef double _c74 = 12.0*_c12
    cdef double _c75 = 12.0*_c11
    cdef double _c76 = _c1*_c26
    cdef double _c77 = _c19*_c5
    cdef double _c78 = _c16*_c73
    cdef double _c79 = 8.0*_c16
    cdef double _c80 = _c1*_c37
    cdef double _c81 = _c13*_c19
    cdef double _c82 = _c39*_c48
    cdef double _c83 = _c47*_c56
    ctx.k[0] = _c0  # _k0
    ctx.k[1] = _c1  # _k1
    ctx.k[2] = _c3  # _k2
    ctx.k[3] = _c4  # _k3
    ctx.k[4] = _c5  # _k4
    ctx.k[5] = _c6  # _k5
    ctx.k[6] = 3.0*_c7  # _k6
    ctx.k[7] = (R_b*R_b*R_b*R_b)  # _k7
    ctx.k[8] = _c8  # _k8
    ctx.k[9] = _c10  # _k9
    ctx.k[10] = 4.0*_c11  # _k10
    ctx.k[11] = 6.0*_c12  # _k11
    ctx.k[12] = _c13  # _k12
    ctx.k[13] = -c_x  # _k13
    ctx.k[14] = -_c17  # _k14
    ctx.k[15] = _c18  # _k15
    ctx.k[16] = _c20  # _k16
    ctx.k[17] = -k  # _k17
    ctx.k[18] = _c21  # _k18
    ctx.k[19] = -_c24  # _k19
    ctx.k[20] = _c24*omega_s  # _k20
    ctx.k[21] = _c25  # _k21
    ctx.k[22] = -_c13  # _k22
    ctx.k[23] = _c17  # _k23
    ctx.k[24] = _c27  # _k24
    ctx.k[25] = _c28  # _k25
    ctx.k[26] = _c29  # _k26
    ctx.k[27] = _c16*_c9  # _k27
    ctx.k[28] = -_c30  # _k28
    ctx.k[29] = -_c31  # _k29
    ctx.k[30] = -_c33  # _k30
    ctx.k[31] = -_c35  # _k31
    ctx.k[32] = 4.0*_c36  # _k32
    ctx.k[33] = _c30*_c37  # _k33
    ctx.k[34] = _c40  # _k34
    ctx.k[35] = _c43  # _k35
    ctx.k[36] = -_c26  # _k36
    ctx.k[37] = -_c20  # _k37
    ctx.k[38] = _c44  # _k38
    ctx.k[39] = _c46  # _k39
    ctx.k[40] = _c49  # _k40
    ctx.k[41] = _c50  # _k41
    ctx.k[42] = 2.0*_c53  # _k42
    ctx.k[43] = -_c19  # _k43
    ctx.k[44] = -_c54  # _k44
    ctx.k[45] = -_c18  # _k45
    ctx.k[46] = _c33  # _k46
    ctx.k[47] = _c17*_c54  # _k47
    ctx.k[48] = _c57  # _k48
    ctx.k[49] = _c59  # _k49
    ctx.k[50] = -_c38*k  # _k50
    ctx.k[51] = _c21*_c38  # _k51
    ctx.k[52] = -_c60  # _k52
    ctx.k[53] = _c60*omega_s  # _k53
    ctx.k[54] = -_c48*c_y  # _k54
    ctx.k[55] = -_c42/_c41  # _k55
    ctx.k[56] = -_c56*c_x  # _k56
    ctx.k[57] = _c61  # _k57
    ctx.k[58] = _c13*_c56  # _k58
    ctx.k[59] = -_c63  # _k59
    ctx.k[60] = -2.0*_c16*_c56 - 2.0*_c52/_c51  # _k60
    ctx.k[61] = -_c58*c_x  # _k61
    ctx.k[62] = _c13*_c58  # _k62
    ctx.k[63] = -_c65  # _k63
    ctx.k[64] = -beta_0  # _k64
    ctx.k[65] = _c66  # _k65
    ctx.k[66] = _c19*_c67*_c68  # _k66
    ctx.k[67] = _c68*beta_m  # _k67
    ctx.k[68] = -h_m  # _k68
    ctx.k[69] = _c67  # _k69
    ctx.k[70] = _c24  # _k70
    ctx.k[71] = -_c69  # _k71
    ctx.k[72] = _c70  # _k72
    ctx.k[73] = _c1*_c55  # _k73
    ctx.k[74] = -_c55*h_m  # _k74
    ctx.k[75] = -_c70  # _k75
    ctx.k[76] = (1.0/(omega_s))  # _k76
    ctx.k[77] = _c32  # _k77
    ctx.k[78] = _c71  # _k78
    ctx.k[79] = _c72  # _k79
    ctx.k[80] = _c73  # _k80
    ctx.k[81] = _c74  # _k81
    ctx.k[82] = _c75  # _k82
    ctx.k[83] = _c25*h_m  # _k83
    ctx.k[84] = _c76  # _k84
    ctx.k[85] = _c8*beta_m  # _k85
    ctx.k[86] = _c77  # _k86
    ctx.k[87] = -_c28  # _k87
    ctx.k[88] = _c29*c_x  # _k88
    ctx.k[89] = -_c76*c_x  # _k89
    ctx.k[90] = -_c77*c_x  # _k90
    ctx.k[91] = -_c17*(((h_m*h_m)*(h_m*h_m))*h_m)  # _k91
    ctx.k[92] = -_c44  # _k92
    ctx.k[93] = -_c17*_c77  # _k93
    ctx.k[94] = _c78  # _k94
    ctx.k[95] = -_c10  # _k95
    ctx.k[96] = -_c73  # _k96
    ctx.k[97] = -_c74  # _k97
    ctx.k[98] = -_c75  # _k98
    ctx.k[99] = -_c6  # _k99
    ctx.k[100] = -_c71  # _k100
    ctx.k[101] = -_c72  # _k101
    ctx.k[102] = -_c32  # _k102
    ctx.k[103] = -_c3  # _k103
    ctx.k[104] = -_c40*h_m  # _k104
    ctx.k[105] = 2.0*_c13  # _k105
    ctx.k[106] = _c34  # _k106
    ctx.k[107] = 3.0*_c28  # _k107
    ctx.k[108] = -_c79*_c8  # _k108
    ctx.k[109] = -_c28*_c79  # _k109
    ctx.k[110] = -_c29*_c37  # _k110
    ctx.k[111] = 8.0*_c36  # _k111
    ctx.k[112] = _c38/(((beta_m*beta_m)*(beta_m*beta_m))*beta_m)  # _k112
    ctx.k[113] = -_c80  # _k113
    ctx.k[114] = _c28*c_x  # _k114
    ctx.k[115] = -_c30*c_x  # _k115
    ctx.k[116] = -_c78  # _k116
    ctx.k[117] = _c13*_c26  # _k117
    ctx.k[118] = -_c81  # _k118
    ctx.k[119] = -_c24*_c25  # _k119
    ctx.k[120] = -_c28*_c37  # _k120
    ctx.k[121] = _c35  # _k121
    ctx.k[122] = _c17*_c28  # _k122
    ctx.k[123] = -_c46  # _k123
    ctx.k[124] = -_c17*_c20  # _k124
    ctx.k[125] = _c17*_c27  # _k125
    ctx.k[126] = -_c27  # _k126
    ctx.k[127] = _c31  # _k127
    ctx.k[128] = -_c49*h_m  # _k128
    ctx.k[129] = -_c45  # _k129
    ctx.k[130] = 6.0*_c36  # _k130
    ctx.k[131] = _c82  # _k131
    ctx.k[132] = -_c33*_c82  # _k132
    ctx.k[133] = -_c26*c_y  # _k133
    ctx.k[134] = -_c48*_c69  # _k134
    ctx.k[135] = -_c26*_c43  # _k135
    ctx.k[136] = -_c17*_c48*_c70  # _k136
    ctx.k[137] = _c81  # _k137
    ctx.k[138] = -_c57*h_m  # _k138
    ctx.k[139] = _c80  # _k139
    ctx.k[140] = _c83  # _k140
    ctx.k[141] = -_c18*_c83  # _k141
    ctx.k[142] = -_c13*beta_m  # _k142
    ctx.k[143] = _c61  # _k143
    ctx.k[144] = -_c63*_c70  # _k144
    ctx.k[145] = -_c53*_c62  # _k145
    ctx.k[146] = -_c59*h_m  # _k146
    ctx.k[147] = _c47*_c58  # _k147
    ctx.k[148] = -_c2*_c47*_c64  # _k148
    ctx.k[149] = -_c65*_c70  # _k149


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

    cdef double _s0_0, _s0_1, _s0_2, _s0_3, _s0_4, _s0_5, _s0_6, _s0_7, _s0_8, _s0_9, _s0_10, _s0_11, _s0_12, _s0_13, _s0_14, _s0_15, _s0_16, _s0_17, _s0_18, _s0_19, _s0_20, _s0_21, _s0_22, _s0_23, _s0_24, _s0_25, _s0_26, _s0_27, _s0_28, _s0_29, _s0_30, _s0_31, _s0_32, _s0_33, _s0_34, _s0_35, _s0_36
    _dy[0] = betad
    _dy[1] = yd
    _dy[2] = zd
    _dy[3] = xd
    if _v == 0:
        _s0_0 = (_cam0[0]*_cam0[0])
        _s0_1 = (_cam0[0]*_cam0[0]*_cam0[0])
        _s0_2 = (_cam0[0]*_cam0[0]*_cam0[0]*_cam0[0])*_k8 + _cam0[0]*_k9 + _k10*_s0_1 + _k11*_s0_0 + _k7
        _s0_3 = (y*y)
        _s0_4 = _cam0[0]*_k5 + _k3 + _k4*_s0_1 + _k6*_s0_0
        _s0_5 = _cam0[0]*_k2 + _k0 + _k1*_s0_0
        _s0_6 = R_b + _cam0[0]*h_m
        _s0_7 = _s0_5*_s0_6
        _s0_8 = _s0_4*_s0_7
        _s0_9 = (_cam0[1]*_cam0[1])
        _s0_10 = _s0_9*betad
        _s0_11 = _k23*yd
        _s0_12 = c_x*y
        _s0_13 = _s0_11 + _s0_12
        _s0_14 = (_cam0[1]*_cam0[1]*_cam0[1])*_s0_7*y
        _s0_15 = _s0_2*_s0_4
        _s0_16 = _s0_6*betad
        _s0_17 = _k30*_s0_16
        _s0_18 = _cam0[1]*_s0_5
        _s0_19 = _cam0[2]*y
        _s0_20 = _s0_19*betad
        _s0_21 = _s0_2*_s0_8
        _s0_22 = _k28*_s0_4
        _s0_23 = _s0_6*y
        _s0_24 = _cam0[0]*_k22 + _k23*xd + c_x*x
        _s0_25 = _k23*zd + _s0_24 + c_x*z
        _s0_26 = _s0_25*_s0_4
        _s0_27 = _s0_6*_s0_9
        _s0_28 = _s0_18*_s0_26
        _s0_29 = _k12*y
        _s0_30 = _k13*_s0_19
        _s0_31 = _k14*_s0_19
        _s0_32 = _s0_4*_s0_5
        _s0_33 = 1.0/(_s0_5*_s0_6)
        _s0_34 = _s0_33/_s0_4
        _s0_35 = _k43*_s0_7
        _s0_36 = _k44*_s0_13*_s0_18 + _k45*_s0_20*_s0_5 + _k46*_s0_10*_s0_23 + _k47*_s0_16*_s0_18
        _dy[4] = _k34*_s0_34*((_cam0[1]*_cam0[1]*_cam0[1]*_cam0[1])*_k29*_s0_3*_s0_8*betad + _cam0[1]*_s0_2*_s0_22*_s0_23*(_cam0[2]*_s0_11 + _cam0[2]*_s0_12 + _k27*_s0_10) + (_cam0[2]*_cam0[2])*_s0_15*_s0_17*_s0_3 + _cam0[2]*_k32*_s0_10*_s0_2*_s0_3*_s0_7 + _k16*_s0_2*_s0_32*(_cam0[0]*_cam0[2]*_s0_29 + _k15*_s0_9*yd + _s0_29*_s0_9 + _s0_30*x + _s0_30*z + _s0_31*xd + _s0_31*zd) + _k21*_s0_21*(_k17*beta + _k18*t + _k19*betad + _k20) + _k24*_s0_2*_s0_28*_s0_6 + _k25*_s0_13*_s0_14*_s0_2 + _k26*_s0_2*_s0_26*_s0_27*y + _k31*_s0_10*_s0_21 + _k33*_s0_15*_s0_18*_s0_20)/_s0_2
        _dy[5] = _k40*_s0_34*(_cam0[1]*_s0_17*_s0_19*_s0_4 + _k36*_s0_8*(_k35*yd + c_y*y) + _k37*_s0_28 + _k38*_s0_14*betad + _k39*_s0_10*_s0_32 + _s0_13*_s0_22*_s0_27)
        _dy[6] = _k48*_s0_33*(_s0_35*(_k41*z + _k42*zd + _s0_24) + _s0_36)
        _dy[7] = _k49*_s0_33*(_s0_25*_s0_35 + _s0_36)
    elif _v == 1:  # in a dwell: 0
        _dy[4] = _k50*beta + _k51*t + _k52*betad + _k53
        _dy[5] = _k54*y + _k55*yd
        _dy[6] = _cam0[0]*_k58 + _k56*x + _k57*z + _k59*xd + _k60*zd
        _dy[7] = _cam0[0]*_k62 + _k61*x + _k61*z + _k63*xd + _k63*zd


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

    cdef double _o0 = R_b + _cam0[0]*h_m
    cdef double _o1 = (1.0/(_o0))
    cdef double _o2 = _o1*y
    cdef double _o3 = _o1*yd
    cdef double _o4 = _cam0[1]*_k72
    _out[0] = _k65*(_k64 + beta)  # B
    _out[1] = _k66*_dy[7]  # Xdd
    _out[2] = _k67*_dy[4]  # Bdd
    _out[3] = _k69*(_cam0[0]*_k68 + x)  # U
    _out[4] = _dy[7]  # xdd
    _out[5] = _k17*beta + _k18*t - _k70*(betad - omega_s)  # torque
    _out[6] = _cam0[0]*_k12 + _cam0[1]*_k71*_o2 + _k13*x + _k13*z + _k23*(_cam0[1]*_k75*_o3 + betad*((_cam0[1]*_cam0[1])*_k73*y/(_o0*_o0) + _cam0[2]*_k74*_o2 + _o4) - xd - zd)  # Fx
    _out[7] = _k76*(-_o3 + betad) - 1.0  # speed_var
    _out[8] = _o1*_o4  # tan_alpha


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

    cdef double _m0 = (beta_m*beta_m)
    cdef double _m1 = (1.0/(_m0))
    cdef double _m2 = _cam0[2]*_m1*c_x*h_m
    cdef double _m3 = (h_m*h_m)
    cdef double _m4 = (_cam0[1]*_cam0[1])
    cdef double _m5 = sqrt(c_x)
    cdef double _m6 = sqrt(m_x)
    cdef double _m7 = _m5*_m6*q_x
    cdef double _m8 = 2.0*_m7
    cdef double _m9 = _m8*xd
    cdef double _m10 = _cam0[2]*h_m
    cdef double _m11 = _m1*_m10
    cdef double _m12 = _m8*zd
    cdef double _m13 = (beta_m*beta_m*beta_m)
    cdef double _m14 = (1.0/(beta_m))
    cdef double _m15 = R_b*_m0
    cdef double _m16 = _cam0[0]*h_m
    cdef double _m17 = _m0*_m16 + _m15
    cdef double _m18 = (1.0/(_m17))
    cdef double _m19 = x*y
    cdef double _m20 = _cam0[2]*_m3*c_x
    cdef double _m21 = (1.0/(_m17*_m17))
    cdef double _m22 = _cam0[1]*beta_m
    cdef double _m23 = _m21*_m22
    cdef double _m24 = _m20*_m23
    cdef double _m25 = y*z
    cdef double _m26 = (_cam0[1]*_cam0[1]*_cam0[1])
    cdef double _m27 = (h_m*h_m*h_m)
    cdef double _m28 = _cam0[0]*_m3
    cdef double _m29 = _m14*c_x
    cdef double _m30 = _m18*_m29
    cdef double _m31 = _cam0[2]*y
    cdef double _m32 = _cam0[1]*_m3
    cdef double _m33 = _m31*_m32
    cdef double _m34 = 2.0*y
    cdef double _m35 = _m7*xd
    cdef double _m36 = _cam0[2]*_m23*_m3
    cdef double _m37 = _m7*zd
    cdef double _m38 = _m34*_m36
    cdef double _m39 = _m14*_m18
    cdef double _m40 = _m7*yd
    cdef double _m41 = _cam0[2]*_m32
    cdef double _m42 = 4.0*_m40*_m41
    cdef double _m43 = _m7*betad
    cdef double _m44 = 4.0*_m43
    cdef double _m45 = _m44*y
    cdef double _m46 = R_b*_m13
    cdef double _m47 = _m13*_m16 + _m46
    cdef double _m48 = (1.0/(_m47))
    cdef double _m49 = _m14*_m48
    cdef double _m50 = (_cam0[2]*_cam0[2])
    cdef double _m51 = _m3*_m50
    cdef double _m52 = _m45*_m51
    cdef double _m53 = (R_b*R_b)
    cdef double _m54 = _m0*_m53
    cdef double _m55 = 2.0*_m16
    cdef double _m56 = (_cam0[0]*_cam0[0])
    cdef double _m57 = _m3*_m56
    cdef double _m58 = _m0*_m57 + _m15*_m55 + _m54
    cdef double _m59 = (1.0/(_m58))
    cdef double _m60 = _cam0[2]*_m29*_m59
    cdef double _m61 = 2.0*_m32*_m60
    cdef double _m62 = (y*y)
    cdef double _m63 = _m13*_m53
    cdef double _m64 = _m13*_m57 + _m46*_m55 + _m63
    cdef double _m65 = (1.0/(_m64))
    cdef double _m66 = _m14*_m59
    cdef double _m67 = _m33*_m66
    cdef double _m68 = 4.0*_m67
    cdef double _m69 = (beta_m*beta_m*beta_m*beta_m)
    cdef double _m70 = _m53*_m69
    cdef double _m71 = _m57*_m69
    cdef double _m72 = R_b*_m55*_m69 + _m70 + _m71
    cdef double _m73 = (1.0/(_m72))
    cdef double _m74 = _m3*_m4
    cdef double _m75 = _m74*c_x
    cdef double _m76 = (1.0/(_m58*_m58))
    cdef double _m77 = R_b*beta_m
    cdef double _m78 = _cam0[1]*h_m
    cdef double _m79 = 2.0*_m78
    cdef double _m80 = 2.0*_m28
    cdef double _m81 = -_m22*_m80 - _m77*_m79
    cdef double _m82 = _m76*_m81
    cdef double _m83 = _m82*y
    cdef double _m84 = _m75*_m83
    cdef double _m85 = _cam0[1]*_m0
    cdef double _m86 = -_m15*_m79 - _m80*_m85
    cdef double _m87 = (1.0/(_m64*_m64))
    cdef double _m88 = 3.0*_m27
    cdef double _m89 = (R_b*R_b*R_b)
    cdef double _m90 = _m13*_m89
    cdef double _m91 = (_cam0[0]*_cam0[0]*_cam0[0])
    cdef double _m92 = _m27*_m91
    cdef double _m93 = 3.0*_m16
    cdef double _m94 = _m13*_m92 + 3.0*_m46*_m57 + _m63*_m93 + _m90
    cdef double _m95 = (1.0/(_m94))
    cdef double _m96 = _m4*_m95
    cdef double _m97 = _cam0[2]*_m62
    cdef double _m98 = _m74*_m83
    cdef double _m99 = _m27*_m31
    cdef double _m100 = 6.0*_m96*_m99
    cdef double _m101 = _cam0[1]*_m27
    cdef double _m102 = _m69*_m89
    cdef double _m103 = _m69*_m92
    cdef double _m104 = 3.0*R_b*_m71 + _m102 + _m103 + _m70*_m93
    cdef double _m105 = (1.0/(_m104))
    cdef double _m106 = 8.0*_m105*_m43
    cdef double _m107 = _m14*_m62
    cdef double _m108 = _m27*_m4*_m44
    cdef double _m109 = _cam0[1]*_m13
    cdef double _m110 = (h_m*h_m*h_m*h_m)
    cdef double _m111 = (R_b*R_b*R_b*R_b)*_m69 + 4.0*R_b*_m103 + (_cam0[0]*_cam0[0]*_cam0[0]*_cam0[0])*_m110*_m69 + 4.0*_m102*_m16 + 6.0*_m57*_m70
    cdef double _m112 = (1.0/(_m111))
    cdef double _m113 = _m27*c_x
    cdef double _m114 = 3.0*_m78
    cdef double _m115 = _cam0[1]*_m28
    cdef double _m116 = 6.0*_m115
    cdef double _m117 = _m56*_m88
    cdef double _m118 = (-_m114*_m54 - _m116*_m15 - _m117*_m85)/(_m94*_m94)
    cdef double _m119 = _m8*yd
    cdef double _m120 = _m26*y
    cdef double _m121 = _m118*_m120*_m27
    cdef double _m122 = (_cam0[1]*_cam0[1]*_cam0[1]*_cam0[1])
    cdef double _m123 = 4.0*_m110
    cdef double _m124 = _m18*c_x
    cdef double _m125 = _m10*x
    cdef double _m126 = _cam0[2]*_m28
    cdef double _m127 = _m10*_m18
    cdef double _m128 = _m41*_m44
    cdef double _m129 = _cam0[0]*_m113*_m4
    cdef double _m130 = _cam0[1]*_m34
    cdef double _m131 = _m130*_m65
    cdef double _m132 = _m59*_m75
    cdef double _m133 = _m41*_m65
    cdef double _m134 = _m59*_m74
    cdef double _m135 = _m26*_m27
    cdef double _m136 = 2.0*_m95
    cdef double _m137 = _m135*_m136
    cdef double _m138 = _m29*_m78
    cdef double _m139 = _cam0[2]*_m18*c_x*h_m*y - _m132*y - _m138
    cdef double _m140 = _m16*beta_m + _m77
    cdef double _m141 = (1.0/(_m140))
    cdef double _m142 = _m141*_m29
    cdef double _m143 = (1.0/(_m140*_m140))
    cdef double _m144 = _m143*_m75
    cdef double _m145 = _m14*_m141
    cdef double _m146 = _m10*_m145
    cdef double _m147 = _m143*_m74
    cdef double _m148 = _m8*betad
    cdef double _m149 = _m130*_m3
    cdef double _m150 = _m14*_m43
    cdef double _m151 = _m141*_m78*c_x
    cdef double _m152 = 2.0*_cam0[2]*_m14*_m141*_m5*_m6*h_m*q_x*yd + _cam0[2]*_m14*_m141*c_x*h_m*y + 2.0*_cam0[3]*_m14*_m18*_m5*_m6*betad*h_m*q_x*y - _m11*_m148 - _m119*_m147 - _m138 - _m144*y - _m148*_m98 - _m38*_m43 - _m44*_m67
    cdef double _m153 = _m127*_m148 - _m134*_m148 + _m151
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
    _Km[0] = 2.0*_cam0[0]*_cam0[1]*_cam0[2]*_m14*_m27*_m59*c_x*y + _cam0[0]*_cam0[1]*_cam0[2]*_m21*_m27*beta_m*c_x*y + _cam0[0]*_cam0[2]*_m1*_m3*c_x + _cam0[0]*_m27*_m4*_m76*_m81*c_x*y + 2.0*_cam0[1]*_cam0[2]*_m3*_m5*_m6*_m86*_m87*q_x*y*yd + _cam0[1]*_cam0[2]*_m3*_m62*_m86*_m87*c_x + 4.0*_cam0[1]*_cam0[2]*_m3*_m5*_m6*betad*q_x/_m13 + 2.0*_cam0[1]*_cam0[3]*_m14*_m3*_m5*_m6*_m65*q_x*y*yd + _cam0[1]*_cam0[3]*_m14*_m3*_m62*_m65*c_x + 4.0*_cam0[2]*_cam0[3]*_m14*_m3*_m5*_m6*_m62*_m73*betad*q_x + 4.0*_cam0[2]*_m0*_m27*_m4*_m5*_m6*betad*q_x*y/(_m47*_m47) + 8.0*_cam0[2]*_m110*_m112*_m14*_m26*_m5*_m6*_m62*betad*q_x + 12.0*_cam0[2]*_m14*_m27*_m4*_m5*_m6*_m65*betad*q_x*y - _cam0[3]*_m105*_m107*_m108 + 2.0*_cam0[3]*_m14*_m18*_m5*_m6*h_m*q_x*xd*y + 2.0*_cam0[3]*_m14*_m18*_m5*_m6*h_m*q_x*y*zd + _cam0[3]*_m14*_m18*c_x*h_m*x*y + _cam0[3]*_m14*_m18*c_x*h_m*y*z - _cam0[3]*_m28*_m30*y - _cam0[3]*_m32*_m45*_m49 + _m1*_m3*_m4*c_x - _m100*_m14*_m40 - _m101*_m106*_m107*_m50 - _m11*_m12 - _m11*_m9 + 2.0*_m110*_m122*_m5*_m6*_m62*betad*q_x*(-12.0*_m101*_m46*_m56 - _m109*_m123*_m91 - 12.0*_m115*_m63 - 4.0*_m78*_m90)/(_m111*_m111) - _m113*_m118*_m26*_m62 - _m119*_m121 - _m12*_m98 + _m14*_m26*_m27*_m59*c_x*y + 2.0*_m14*_m3*_m5*_m50*_m6*_m65*q_x*y*yd + _m14*_m3*_m50*_m62*_m65*c_x - _m19*_m24 - _m19*_m61 - _m2*x - _m2*z + 2.0*_m21*_m26*_m27*_m5*_m6*beta_m*q_x*yd + _m21*_m26*_m27*beta_m*c_x*y - _m24*_m25 - _m25*_m61 + 4.0*_m26*_m27*_m5*_m6*_m86*_m87*betad*q_x*y - _m29*_m88*_m96*_m97 + 2.0*_m3*_m5*_m50*_m6*_m62*betad*q_x*(-_m109*_m80 - _m46*_m79)/(_m72*_m72) - 3.0*_m30*_m33 - _m34*_m35*_m36 - _m35*_m68 - _m37*_m38 - _m37*_m68 - _m39*_m42 - _m49*_m52 - _m84*x - _m84*z - _m9*_m98 + k - _m108*_m97*(-_m109*_m117 - _m114*_m63 - _m116*_m46)/(_m104*_m104)
    _Km[1] = _m10*_m124*z - _m106*_m4*_m99 + _m112*_m122*_m123*_m43*y - _m113*_m120*_m136 + _m119*_m133 + _m12*_m127 - _m12*_m134 + _m124*_m125 - _m124*_m126 + _m127*_m9 - _m128*_m48 + _m129*_m59 + _m131*_m20 - _m132*x - _m132*z - _m134*_m9 + _m135*_m44*_m65 - _m137*_m40 - _m18*_m75 + _m52*_m73
    _Km[2] = _m139
    _Km[3] = _m139
    _Km[4] = _cam0[2]*_m149*_m43*_m86*_m87 + _cam0[3]*_m131*_m150*_m3 + _m10*_m142*z - _m100*_m150 + _m119*_m74*_m82 + _m12*_m146 - _m12*_m147 - _m121*_m148 + _m125*_m142 - _m126*_m142 - _m128*_m39 + _m129*_m143 + _m135*_m148*_m21*beta_m - _m144*x - _m144*z - _m145*_m75 + _m146*_m9 - _m147*_m9 + _m149*_m60 + _m150*_m34*_m51*_m65 + _m42*_m66 + _m84
    _Km[5] = _m132 + _m133*_m148 - _m137*_m43 + c_y
    _Km[6] = _m151
    _Km[7] = _m151
    _Km[8] = _m152
    _Km[9] = _m153
    _Km[10] = c_x + c_z
    _Km[11] = c_x
    _Km[12] = _m152
    _Km[13] = _m153
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
    cdef double _j0 = (_cam0[1]*_cam0[1])
    cdef double _j1 = _j0*betad
    cdef double _j2 = (_cam0[0]*_cam0[0])
    cdef double _j3 = (_cam0[0]*_cam0[0]*_cam0[0])
    cdef double _j4 = (_cam0[0]*_cam0[0]*_cam0[0]*_cam0[0])*_k8 + _cam0[0]*_k9 + _j2*_k11 + _j3*_k10 + _k7
    cdef double _j5 = (y*y)
    cdef double _j6 = _j4*_j5
    cdef double _j7 = _j1*_j6
    cdef double _j8 = R_b + _cam0[0]*h_m
    cdef double _j9 = _cam0[0]*_k2 + _j2*_k1 + _k0
    cdef double _j10 = _j8*_j9
    cdef double _j11 = _j10*_k32
    cdef double _j12 = _cam0[0]*_k5 + _j2*_k6 + _j3*_k4 + _k3
    cdef double _j13 = _j12*_j4
    cdef double _j14 = _j8*betad
    cdef double _j15 = _j14*_k113
    cdef double _j16 = _cam0[2]*_j5
    cdef double _j17 = _j12*_j9
    cdef double _j18 = _j17*_j4
    cdef double _j19 = _cam0[1]*y
    cdef double _j20 = _k33*betad
    cdef double _j21 = _j19*_j20
    cdef double _j22 = _k23*yd
    cdef double _j23 = c_x*y
    cdef double _j24 = _j22 + _j23
    cdef double _j25 = _j8*_k28
    cdef double _j26 = _j19*_j25
    cdef double _j27 = _cam0[0]*_k12
    cdef double _j28 = _j27*y
    cdef double _j29 = _k13*y
    cdef double _j30 = _j29*x
    cdef double _j31 = _j29*z
    cdef double _j32 = _k14*y
    cdef double _j33 = _j32*xd
    cdef double _j34 = _j32*zd
    cdef double _j35 = _j18*_k16
    cdef double _j36 = (1.0/(_j12))
    cdef double _j37 = (1.0/(_j8))
    cdef double _j38 = (1.0/(_j9))
    cdef double _j39 = _j37*_j38
    cdef double _j40 = _j36*_j39
    cdef double _j41 = (1.0/(_j4))
    cdef double _j42 = _j41*_k112
    cdef double _j43 = (_cam0[1]*_cam0[1]*_cam0[1])
    cdef double _j44 = _j10*_j12
    cdef double _j45 = _j5*betad
    cdef double _j46 = _j10*_j4
    cdef double _j47 = _j13*_j8
    cdef double _j48 = _j1*y
    cdef double _j49 = _j0*y
    cdef double _j50 = _cam0[2]*_j18
    cdef double _j51 = _j50*y
    cdef double _j52 = _j4*_j44
    cdef double _j53 = _cam0[1]*_j52
    cdef double _j54 = _cam0[2]*_j22 + _cam0[2]*_j23 + _j1*_k27
    cdef double _j55 = _j13*_j54
    cdef double _j56 = _cam0[0]*_k22 + _k23*xd + c_x*x
    cdef double _j57 = _j56 + _k23*zd + c_x*z
    cdef double _j58 = _j12*_j57
    cdef double _j59 = _j4*_j8
    cdef double _j60 = _j57*_k24
    cdef double _j61 = _cam0[2]*_j40
    cdef double _j62 = _j38/(_j8*_j8)
    cdef double _j63 = _j36*_j62
    cdef double _j64 = (_cam0[1]*_cam0[1]*_cam0[1]*_cam0[1])
    cdef double _j65 = _j45*_j64
    cdef double _j66 = _j44*_k29
    cdef double _j67 = _cam0[2]*_j7
    cdef double _j68 = _j43*y
    cdef double _j69 = _j4*_j68
    cdef double _j70 = _j24*_j69
    cdef double _j71 = _j70*_k25
    cdef double _j72 = (_cam0[2]*_cam0[2])
    cdef double _j73 = _j13*_j72
    cdef double _j74 = _j5*_j73
    cdef double _j75 = _j14*_k30
    cdef double _j76 = _j1*_k31
    cdef double _j77 = _j19*_j55
    cdef double _j78 = _j4*_j57
    cdef double _j79 = _j78*y
    cdef double _j80 = _j0*_j12
    cdef double _j81 = _j8*_j80
    cdef double _j82 = _j81*_k26
    cdef double _j83 = _k17*beta + _k18*t + _k19*betad + _k20
    cdef double _j84 = _j83*_k21
    cdef double _j85 = _j0*_k12
    cdef double _j86 = _k16*(_cam0[2]*_j28 + _cam0[2]*_j30 + _cam0[2]*_j31 + _cam0[2]*_j33 + _cam0[2]*_j34 + _j0*_k15*yd + _j85*y)
    cdef double _j87 = _j10*_j71 + _j11*_j67 + _j18*_j86 + _j21*_j50 + _j25*_j77 + _j52*_j76 + _j52*_j84 + _j53*_j60 + _j65*_j66 + _j74*_j75 + _j79*_j82
    cdef double _j88 = _j41*_j87
    cdef double _j89 = _j37*(_cam0[0]*_k102 + _k103)/(_j9*_j9)
    cdef double _j90 = _j36*_j89
    cdef double _j91 = _j88*_k34
    cdef double _j92 = _j39*(_cam0[0]*_k101 + _j2*_k100 + _k99)/(_j12*_j12)
    cdef double _j93 = _j40*_k34
    cdef double _j94 = _cam0[0]*_k77 + _k2
    cdef double _j95 = _j8*_j94
    cdef double _j96 = _j12*_j95
    cdef double _j97 = _j65*_k29
    cdef double _j98 = _cam0[0]*_k79 + _j2*_k78 + _k5
    cdef double _j99 = _j10*_j98
    cdef double _j100 = _cam0[0]*_k81 + _j2*_k82 + _j3*_k80 + _k9
    cdef double _j101 = _j10*_j100
    cdef double _j102 = _j24*_k25
    cdef double _j103 = _j72*_j75
    cdef double _j104 = _j100*_j12
    cdef double _j105 = _j4*_j81
    cdef double _j106 = _j12*_j94
    cdef double _j107 = _cam0[2]*_j4
    cdef double _j108 = _j9*betad
    cdef double _j109 = _cam0[2]*_j19
    cdef double _j110 = _j100*_j17
    cdef double _j111 = _k88*y
    cdef double _j112 = _j4*_k31
    cdef double _j113 = _j1*_j112
    cdef double _j114 = _j100*_j44
    cdef double _j115 = _j25*_j98
    cdef double _j116 = _j4*_j54
    cdef double _j117 = _j4*_j84
    cdef double _j118 = _cam0[1]*_j9
    cdef double _j119 = _j118*_j12
    cdef double _j120 = _cam0[1]*_j94
    cdef double _j121 = _j120*_j58
    cdef double _j122 = _cam0[1]*_j98
    cdef double _j123 = _j4*_j86
    cdef double _j124 = _j9*_j98
    cdef double _j125 = _j41*_j93
    cdef double _j126 = _cam0[1]*_k65
    cdef double _j127 = _j10*_j69
    cdef double _j128 = _j10*_j48
    cdef double _j129 = _j109*_j47
    cdef double _j130 = _j10*_j43
    cdef double _j131 = _j119*_j20
    cdef double _j132 = _cam0[1]*_j12
    cdef double _j133 = _cam0[2]*_k13
    cdef double _j134 = _cam0[2]*_k14
    cdef double _j135 = _j125*(_j105*_j111 + _j51*_k118 + _j53*_k117)
    cdef double _j136 = _j8*_k30
    cdef double _j137 = _j0*_j17
    cdef double _j138 = _j4*_k121
    cdef double _j139 = _j125*(_j138*_j81*y + _j51*_k124 + _j53*_k125)
    cdef double _j140 = _cam0[3]*betad
    cdef double _j141 = _cam0[2]*_j12
    cdef double _j142 = _j132*_j8
    cdef double _j143 = _j9*_k37
    cdef double _j144 = _j143*_j57
    cdef double _j145 = _j12*_j144
    cdef double _j146 = _k38*y
    cdef double _j147 = _j130*betad
    cdef double _j148 = _j14*_j19
    cdef double _j149 = _j1*_k39
    cdef double _j150 = _j24*_j80
    cdef double _j151 = _k35*yd + c_y*y
    cdef double _j152 = _j151*_k36
    cdef double _j153 = _cam0[1]*_j145 + _j141*_j148*_k30 + _j146*_j147 + _j149*_j17 + _j150*_j25 + _j152*_j44
    cdef double _j154 = _j153*_k40
    cdef double _j155 = _j141*_j19
    cdef double _j156 = _cam0[2]*_k30
    cdef double _j157 = _j40*_k40
    cdef double _j158 = _cam0[1]*_j37
    cdef double _j159 = _j158*_k134
    cdef double _j160 = _j158*_k136
    cdef double _j161 = _j140*_j37*y
    cdef double _j162 = _j10*_k47
    cdef double _j163 = _j162*betad
    cdef double _j164 = _j24*_k44
    cdef double _j165 = _j164*_j9
    cdef double _j166 = _cam0[2]*_j39*(_j148*_k139 + _j163 + _j165)
    cdef double _j167 = _j56 + _k41*z + _k42*zd
    cdef double _j168 = _j167*_k43
    cdef double _j169 = _cam0[2]*_k45
    cdef double _j170 = _j108*_j169
    cdef double _j171 = _j8*_k46
    cdef double _j172 = _j1*_j171
    cdef double _j173 = _cam0[1]*_j163 + _cam0[1]*_j165 + _j170*y + _j172*y
    cdef double _j174 = _j10*_j168 + _j173
    cdef double _j175 = _j169*y
    cdef double _j176 = _j1*_j146 + _j10*_k137 + _j118*_k39*betad + _j120*_j14*_k47 + _j120*_j164 + _j175*_j94*betad
    cdef double _j177 = _j39*_k48
    cdef double _j178 = _j118*_k142 + _j170 + _j172
    cdef double _j179 = _cam0[1]*_j162 + _j171*_j49 + _j175*_j9
    cdef double _j180 = _j57*_k43
    cdef double _j181 = _j10*_j180 + _j173
    cdef double _j182 = _j39*_k49
    _J[32] = _cam0[3]*_j40*_j42*(_j11*_j7 + _j13*_j15*_j16 + _j13*_j24*_j26 + _j18*_j21 + _j35*(_j28 + _j30 + _j31 + _j33 + _j34)) + _j126*(_j125*(_cam0[1]*_j114*_j60 + _cam0[2]*_j110*_j21 + _j1*_j101*_j16*_k32 + _j1*_j18*_k93 + _j10*_j122*_j78*_k24 + _j100*_j57*_j82*y + _j101*_j102*_j68 + _j103*_j104*_j5 + _j103*_j6*_j98 + _j104*_j26*_j54 + _j105*_k90*y + _j106*_j107*_j21 + _j106*_j123 + _j108*_j109*_j4*_j98*_k33 + _j110*_j86 + _j111*_j50 + _j113*_j96 + _j113*_j99 + _j114*_j76 + _j114*_j84 + _j115*_j116*_j19 + _j117*_j96 + _j117*_j99 + _j119*_j78*_k84 + _j121*_j59*_k24 + _j123*_j124 + _j17*_j65*_k91 + _j18*_j83*_k83 + _j45*_j73*_k92 + _j49*_j78*_j8*_j98*_k26 + _j53*_k89 + _j67*_j9*_k94 + _j67*_j95*_k32 + _j70*_j9*_k85 + _j71*_j95 + _j77*_k87 + _j79*_j80*_k86 + _j96*_j97 + _j97*_j99) + _j63*_j88*_k104 + _j90*_j91 + _j91*_j92 + _j87*_j93*(_cam0[0]*_k97 + _j2*_k98 + _j3*_k96 + _k95)/(_j4*_j4)) + _j42*_j61*(_cam0[1]*_cam0[2]*_j45*_j46*_k111 + _j19*_j58*_j59*_k106 + _j20*_j51 + _j24*_j46*_j49*_k107 + _j25*_j55*y + _j35*(_cam0[1]*_k27*yd + _j19*_k105) + _j43*_j44*_j45*_k108 + _j47*_j48*_k109 + _j52*_j60 + _j53*_k110*betad) + _k50
    _J[33] = _j125*(_j102*_j130*_j4 + _j107*_j128*_k111 + _j107*_j131 + _j116*_j132*_j25 + _j127*_k114 + _j129*_k115 + _j15*_j73*y + _j35*(_cam0[2]*_j27 + _j133*x + _j133*z + _j134*xd + _j134*zd + _j85) + _j44*_j64*_k116*betad*y + _j78*_j82)
    _J[34] = _j135
    _J[35] = _j135
    _J[36] = _j125*(_cam0[2]*_j0*_j11*_j6 + _j10*_j112*_j80 + _j136*_j74 + _j19*_j50*_k33 + _j47*_j68*_k120 + _j5*_j64*_j66 + _j52*_k119)
    _J[37] = _j125*(_j127*_k122 + _j129*_k123 + _j137*_j138)
    _J[38] = _j139
    _J[39] = _j139
    _J[40] = _j126*(_j153*_j63*_k128 + _j154*_j90 + _j154*_j92 + _j157*(_j0*_j115*_j24 + _j106*_j149 + _j108*_j68*_k127 + _j119*_k88 + _j121*_k37 + _j122*_j144 + _j124*_j149 + _j146*_j43*_j95*betad + _j148*_j156*_j98 + _j150*_k87 + _j151*_j17*_k126 + _j152*_j96 + _j152*_j99 + _j155*_k92*betad)) + _j140*_j19*_j38*_k132 + _j61*_k131*(_j128*_k130 + _j131 + _j141*_j75*y + _j142*_j24*_k129 + _j145)
    _J[41] = _j157*(_j142*_j156*betad + _j147*_k38 + _j44*_k133 + _j81*_k115)
    _J[42] = _j159
    _J[43] = _j159
    _J[44] = _j157*(_j130*_j146 + _j136*_j155 + _j137*_k39)
    _J[45] = _j157*(_j44*_k135 + _j81*_k123)
    _J[46] = _j160
    _J[47] = _j160
    _J[48] = _j126*(_j174*_j62*_k138 + _j174*_j89*_k48 + _j177*(_j143*_j167 + _j168*_j95 + _j176)) + _j161*_k141 + _j166*_k140
    _J[49] = _j177*_j178
    _J[50] = _k143
    _J[51] = _k56
    _J[52] = _j177*_j179
    _J[53] = _j158*_k144
    _J[54] = _k145
    _J[55] = _k59
    _J[56] = _j126*(_j181*_j62*_k146 + _j181*_j89*_k49 + _j182*(_j144 + _j176 + _j180*_j95)) + _j161*_k148 + _j166*_k147
    _J[57] = _j178*_j182
    _J[58] = _k61
    _J[59] = _k61
    _J[60] = _j179*_j182
    _J[61] = _j158*_k149
    _J[62] = _k63
    _J[63] = _k63
    _ftl[4] = _k51
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
_model.n_const = 150
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
 "name": "dynacam_radial_ideal_rigidgear_bilateral_shafty_shaftz",
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
 "source_hash": "sha256:17a2d5a7d7f49c908f0cc60227fa5d7ea6df0fff82762a03baea1b9af6239c3b",
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

# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True, initializedcheck=False
#
# GENERATED FILE - DO NOT EDIT.  Written by `camdyn derive` from camdyn/derive/models/beam.py;
# edit that and regenerate.  `camdyn derive --check` fails while this file is stale.
# Derivation key: sha256:e0da0f68451cde1096c4c49f48f3a47dbcc88cb44add291edc9e28857583b13d
# Text hash: sha256:f549a0c7b221eb5a22ad0562c6c761fd036cde33fa76cd7e37075d81920bed10
#
# Rayleigh-beam follower in a grooved disk cam, N = 1 assumed modes (paper (1)-(20))
# Source hash: sha256:c16b3556f450993e2cc9f2fd4a99c60d51901b4ed16007df3788e4358514ae33
#
# The Rayleigh-beam follower: a translating roller follower in the groove of a rigid disk cam,
# its rod a Rayleigh beam whose free length changes as the cam turns (second source paper,
# "Transverse vibration analysis of a translating roller-follower cam using cycloidal profile
# for RDFD motion", cited as "paper (n)").
#
# Frames and coordinates (paper figs 1, 3; SI units).  Fixed frame: origin at the cam centre,
# Y along the follower axis towards the guide, whose exit is at Y = d.  The rod's free part
# runs from the guide exit (x = 0, clamped: v = v_x = 0) to the roller pin E at x = x_E(t), so
# Y_E = d - x_E (paper (7)).  The cam turns at the constant speed Omega; the pitch-curve point
# of cam parameter theta is r(theta) (cos theta, sin theta) in the cam frame with
# r = r_b + r_r + S(theta), at (X, Y) = r (sin(Omega t - theta), cos(Omega t - theta)) in the
# fixed frame (paper (4), (5)).  Generalized coordinates Q = [b_1 .. b_N, x_E, theta] (16),
# deflection v(x, t) = sum b_i (x/d)^(i+1) (13): polynomials that satisfy the clamp, scaled by
# d so that every b_i is a length and the matrices of the generated code stay well scaled.
#
# Energies (paper (8)-(12)):
#
#     rod      T = 1/2 rho A int_0^x_E (x_E'^2 + (Dv/Dt)^2) dx + 1/2 rayleigh rho I int_0^x_E (Dv_x/Dt)^2 dx
#              U = 1/2 E I int_0^x_E v_xx^2 dx
#     roller   T = 1/2 m_r (X_E'^2 + Y_E'^2) + 1/2 J_r w_n^2
#     guide    T = 1/2 rho A L_g x_E'^2
#
# with the material derivative D/Dt = d/dt + x_E' d/dx (the rod slides out of the guide at
# x_E', so a material point at x moves by x_E' along x), X_E = v(x_E, t) the pin on the rod's
# end and Y_E = d - x_E.  The integrals over the moving domain [0, x_E(t)] are done
# symbolically here; the equations then follow from Hamilton's principle with the two
# constraints adjoined by multipliers (14), i.e. Lagrange's equations of the first kind:
# M(Q) Q'' + Phi_Q^T lambda = f(Q, Q', t) (15) (f = -N), Phi_Q Q'' = gamma (19).
#
# Constraints (paper (6), (7)): the pin E is the pitch-curve point of parameter theta,
#
#     Phi_1 = r(theta) sin(Omega t - theta) - v(x_E, t) = 0     (transverse)
#     Phi_2 = r(theta) cos(Omega t - theta) + x_E - d = 0        (axial)
#
# For a rigid rod theta = Omega t and x_E = d - r(Omega t).
#
# Modelling choices the paper leaves open (each a parameter where it can be):
#
# * roller rotation: the paper's (12) takes the roller's angular velocity as that of the line
#   from its centre E to the contact point C, the common normal.  In the cam frame that normal
#   makes the angle theta - phi(theta) with the x axis, phi = atan(S'/r) the pressure angle, so
#   in the fixed frame w_n = Omega - theta' (1 - phi'(theta)).  J_r defaults to a uniform disc,
#   m_r r_r^2/2 (the paper's value is lost in the scan).  J_r = 0 switches it off.
# * rotary inertia of the rod (the Rayleigh term): ``rayleigh`` = 1 keeps it, 0 gives the
#   Euler-Bernoulli rod of the frozen-frequency check.
# * the rod inside the guide: by default only the free part [0, x_E] carries kinetic energy,
#   as the paper integrates; ``L_g`` > 0 adds a length of rod moving with x_E' only (axially).
# * Hamilton's principle on the free part as if it were a closed system: the paper's form;
#   the momentum carried across x = 0 by the sliding rod is not accounted for.  In the rigid
#   limit the axial multiplier is then minus the inertia force of the rigid follower with that
#   same Lagrangian, lambda_2 = -[(rho A x_E + m_r + rho A L_g) x_E'' + rho A x_E'^2/2] (the
#   sign of M Q'' + Phi_Q^T lambda = f).
# * RDFD motion (paper (1), fig. 2): rise over [0, beta_r], outer dwell to pi, fall over
#   [pi, pi + beta_r], inner dwell to 2 pi, repeated every revolution; S = S_T R(theta) with R
#   the normalized RDFD profile of the chosen cam law (cycloidal by default, any law of the
#   library), declared as the model's RDFDProfile with the rise beta_r.  The segment ends are
#   located as events.
#
# How the constraints are solved (augmented with Baumgarte's rate w_B, paper (20),
# partitioned, the last two coordinates x_E and theta dependent, paper (21)-(27), or projected
# after every step) is the
# parameter ``formulation``, declared as the model's ConstraintSolver; the multipliers are the
# outputs lambda1 (transverse, (6)) and lambda2 (axial, (7)), in N.

import json

from cpython.pycapsule cimport PyCapsule_New
from libc.math cimport atan, cos, fabs, fmod, M_PI, sin

from camdyn.runtime.engine.abi cimport *
from camdyn.generated.camlaws cimport camlaw_d4, camlaw_eval, camlaw_segment
from camdyn.runtime.engine.linalg cimport lu_factor, lu_solve, solve_inplace

# sizes, known when the integration loops (loops.pxi) are compiled into this module
cdef enum:
    _NQ = 3                  # coordinates Q
    _NC = 2                  # constraints Phi
    _NA = 5                  # unknowns of the augmented system: Q'', lambda
    _ND = 1                  # independent coordinates, beside the _NC dependent ones (_partition)
    _NS = 6                 # states: Q, Q'
    _NCAM = 0
    _NM = 0
    _NE = 2
    _NQ1 = 3
    _NE1 = 2
    _JAC_SYMBOLIC = 1           # jacobian() is exact: A^-1 d(b - A x)/dy at fixed x
    _FT_SYMBOLIC = 1            # and so is its df/dt
    _PROJECTS = 1               # the loops call project() after every accepted step

# the declared coordinate partition (ConstraintSolver.dependent): the dependent coordinates,
# then the independent ones; a run may choose another (Ctx.part, _partition)
cdef int _PART[_NQ]
_PART[0] = 1  # xE, dependent
_PART[1] = 2  # theta, dependent
_PART[2] = 0  # b1

cdef int _EDIR[_NE1]    # crossing direction of each event: +1 upward, -1 downward
_EDIR[0] = 1  # segment_up
_EDIR[1] = -1  # segment_down



cdef inline void _profile(Ctx* ctx, double th, double beta, double* out, bint fourth) noexcept nogil:
    """R(theta) and its derivatives dR/dtheta^k, k = 1..3 (and 4 into out[4] if ``fourth``: the
    exact Jacobian's), of the rise-dwell-fall-dwell (RDFD) motion with the cam law ctx.law[0],
    period 2 pi: rise on [0, beta), outer dwell to pi, fall on [pi, pi + beta), inner dwell
    to 2 pi."""
    cdef int seg
    cdef double u = fmod(th, 2.0 * M_PI)
    cdef double h[4]
    cdef double s = 1.0, T
    cdef bint fall = False
    if u < 0.0:
        u += 2.0 * M_PI
    if u >= M_PI:
        u -= M_PI
        fall = True
    if u < beta:
        T = u / beta
        seg = camlaw_segment(ctx.law[0], ctx.law_par[0], T)
        camlaw_eval(ctx.law[0], ctx.law_par[0], seg, T, h)
        if fall:
            s = -1.0
            h[0] -= 1.0
        out[0] = s * h[0]
        out[1] = s * h[1] / beta
        out[2] = s * h[2] / (beta * beta)
        out[3] = s * h[3] / (beta * beta * beta)
        if fourth:
            out[4] = s * camlaw_d4(ctx.law[0], ctx.law_par[0], seg, T) / (beta * beta * beta * beta)
    else:
        out[0] = 0.0 if fall else 1.0
        out[1] = 0.0
        out[2] = 0.0
        out[3] = 0.0
        out[4] = 0.0


cdef void prepare(Ctx* ctx) noexcept nogil:
    """Parameter-only subexpressions, once per run, into ctx.k."""
    cdef double Omega = ctx.p[0]
    cdef double d = ctx.p[1]
    cdef double r_b = ctx.p[2]
    cdef double r_r = ctx.p[3]
    cdef double S_T = ctx.p[4]
    cdef double beta_r = ctx.p[5]
    cdef double a_rod = ctx.p[6]
    cdef double E = ctx.p[7]
    cdef double rho = ctx.p[8]
    cdef double m_r = ctx.p[9]
    cdef double J_r = ctx.p[10]
    cdef double rayleigh = ctx.p[11]
    cdef double L_g = ctx.p[12]
    cdef double w_B = ctx.p[13]
    cdef double formulation = ctx.p[14]
    cdef double _c0 = (a_rod*a_rod*a_rod*a_rod)
    cdef double _c1 = 3.141592653589793*rho
    cdef double _c2 = _c0*_c1*rayleigh
    cdef double _c3 = _c1*(a_rod*a_rod)
    cdef double _c4 = (d*d*d*d)
    cdef double _c5 = (1.0/(_c4))
    cdef double _c6 = 4.0*m_r
    cdef double _c7 = 0.5*_c5
    cdef double _c8 = _c5*_c6
    cdef double _c9 = _c3*_c5
    cdef double _c10 = _c2*_c5
    cdef double _c11 = (r_b*r_b*r_b*r_b)
    cdef double _c12 = (r_r*r_r*r_r*r_r)
    cdef double _c13 = (r_r*r_r*r_r)
    cdef double _c14 = (r_b*r_b*r_b)
    cdef double _c15 = (r_b*r_b)
    cdef double _c16 = (r_r*r_r)
    cdef double _c17 = _c11 + _c12 + 4.0*_c13*r_b + 4.0*_c14*r_r + 6.0*_c15*_c16
    cdef double _c18 = (S_T*S_T*S_T*S_T)
    cdef double _c19 = 2.0*_c18
    cdef double _c20 = _c15 + _c16 + 2.0*r_b*r_r
    cdef double _c21 = (S_T*S_T)
    cdef double _c22 = 2.0*_c21
    cdef double _c23 = _c13 + _c14 + 3.0*_c15*r_r + 3.0*_c16*r_b
    cdef double _c24 = 4.0*S_T
    cdef double _c25 = _c23*_c24
    cdef double _c26 = r_b + r_r
    cdef double _c27 = (S_T*S_T*S_T)
    cdef double _c28 = _c26*_c27
    cdef double _c29 = 4.0*_c28
    cdef double _c30 = _c20*_c21
    cdef double _c31 = J_r*_c18
    cdef double _c32 = 2.0*S_T
    cdef double _c33 = _c26*_c32
    cdef double _c34 = J_r*_c21
    cdef double _c35 = 2.0*_c34
    cdef double _c36 = _c20*_c34
    cdef double _c37 = J_r*_c33
    cdef double _c38 = J_r*_c19
    cdef double _c39 = J_r*_c28
    cdef double _c40 = 2.0*_c39
    cdef double _c41 = (1.0/(d*d))
    cdef double _c42 = 2.0*_c41
    cdef double _c43 = 3.141592653589793*E*_c0
    cdef double _c44 = 3.0*_c3
    cdef double _c45 = 2.0*_c3
    cdef double _c46 = 3.0*_c2
    cdef double _c47 = 0.3333333333333333*_c5
    cdef double _c48 = _c5*m_r
    cdef double _c49 = J_r*_c26
    cdef double _c50 = (((r_r*r_r)*(r_r*r_r))*r_r)
    cdef double _c51 = (((r_b*r_b)*(r_b*r_b))*r_b)
    cdef double _c52 = (((S_T*S_T)*(S_T*S_T))*(S_T*S_T))
    cdef double _c53 = _c17*_c21
    cdef double _c54 = _c18*_c20
    cdef double _c55 = 6.0*S_T*(5.0*_c11*r_r + 5.0*_c12*r_b + 10.0*_c13*_c15 + 10.0*_c14*_c16 + _c50 + _c51)
    cdef double _c56 = (((S_T*S_T)*(S_T*S_T))*S_T)
    cdef double _c57 = _c26*_c56
    cdef double _c58 = 6.0*_c57
    cdef double _c59 = _c23*_c27
    cdef double _c60 = 12.0*_c59
    cdef double _c61 = J_r*_c52
    cdef double _c62 = _c49*_c56
    cdef double _c63 = 4.0*_c61
    cdef double _c64 = 4.0*_c31
    cdef double _c65 = _c20*_c64
    cdef double _c66 = 4.0*_c62
    cdef double _c67 = _c20*_c35
    cdef double _c68 = J_r*_c59
    cdef double _c69 = 8.0*_c62
    cdef double _c70 = J_r*_c29
    cdef double _c71 = 6.0*_c31
    cdef double _c72 = (Omega*Omega)
    cdef double _c73 = _c26*_c72
    cdef double _c74 = S_T*_c72
    cdef double _c75 = Omega*_c26
    cdef double _c76 = 2.0*_c75
    cdef double _c77 = Omega*_c32
    cdef double _c78 = 24.0*m_r
    cdef double _c79 = 6.0*_c52
    cdef double _c80 = 12.0*_c52
    cdef double _c81 = 12.0*_c62
    cdef double _c82 = _c20*_c31
    cdef double _c83 = 12.0*_c82
    cdef double _c84 = Omega*S_T
    cdef double _c85 = (Omega*Omega*Omega)
    cdef double _c86 = _c26*_c85
    cdef double _c87 = S_T*_c85
    cdef double _c88 = 2.0*_c73
    cdef double _c89 = 2.0*_c74
    ctx.k[0] = 0.3333333333333333*_c2  # _k0
    ctx.k[1] = 0.2*_c3  # _k1
    ctx.k[2] = _c5  # _k2
    ctx.k[3] = _c6  # _k3
    ctx.k[4] = _c2  # _k4
    ctx.k[5] = _c3  # _k5
    ctx.k[6] = _c7  # _k6
    ctx.k[7] = L_g*_c3 + m_r  # _k7
    ctx.k[8] = _c8  # _k8
    ctx.k[9] = 1.3333333333333333*_c9  # _k9
    ctx.k[10] = _c10  # _k10
    ctx.k[11] = _c17  # _k11
    ctx.k[12] = _c18  # _k12
    ctx.k[13] = _c19  # _k13
    ctx.k[14] = _c20*_c22  # _k14
    ctx.k[15] = _c25  # _k15
    ctx.k[16] = _c29  # _k16
    ctx.k[17] = 6.0*_c30  # _k17
    ctx.k[18] = _c31  # _k18
    ctx.k[19] = _c20  # _k19
    ctx.k[20] = _c21  # _k20
    ctx.k[21] = _c33  # _k21
    ctx.k[22] = _c35  # _k22
    ctx.k[23] = _c36  # _k23
    ctx.k[24] = -_c35  # _k24
    ctx.k[25] = -_c37  # _k25
    ctx.k[26] = -_c38  # _k26
    ctx.k[27] = -_c40  # _k27
    ctx.k[28] = _c40  # _k28
    ctx.k[29] = -_c41  # _k29
    ctx.k[30] = -_c42  # _k30
    ctx.k[31] = _c26  # _k31
    ctx.k[32] = -12.0*m_r  # _k32
    ctx.k[33] = -6.0*m_r  # _k33
    ctx.k[34] = -3.0*_c43  # _k34
    ctx.k[35] = -_c44  # _k35
    ctx.k[36] = -_c45  # _k36
    ctx.k[37] = -_c46  # _k37
    ctx.k[38] = _c47  # _k38
    ctx.k[39] = -_c8  # _k39
    ctx.k[40] = -_c43*_c7  # _k40
    ctx.k[41] = -8.0*_c48  # _k41
    ctx.k[42] = -0.5*_c3  # _k42
    ctx.k[43] = -_c45*_c5  # _k43
    ctx.k[44] = -_c2*_c7  # _k44
    ctx.k[45] = -2.6666666666666665*_c9  # _k45
    ctx.k[46] = -2.0*_c10  # _k46
    ctx.k[47] = _c34  # _k47
    ctx.k[48] = S_T*_c49  # _k48
    ctx.k[49] = -_c34  # _k49
    ctx.k[50] = _c38  # _k50
    ctx.k[51] = 15.0*_c11*_c16 + 15.0*_c12*_c15 + 20.0*_c13*_c14 + 6.0*_c50*r_b + 6.0*_c51*r_r + (((r_b*r_b)*(r_b*r_b))*(r_b*r_b)) + (((r_r*r_r)*(r_r*r_r))*(r_r*r_r))  # _k51
    ctx.k[52] = _c52  # _k52
    ctx.k[53] = 3.0*_c52  # _k53
    ctx.k[54] = 3.0*_c53  # _k54
    ctx.k[55] = 3.0*_c54  # _k55
    ctx.k[56] = _c55  # _k56
    ctx.k[57] = _c58  # _k57
    ctx.k[58] = 15.0*_c53  # _k58
    ctx.k[59] = 15.0*_c54  # _k59
    ctx.k[60] = 20.0*_c59  # _k60
    ctx.k[61] = _c60  # _k61
    ctx.k[62] = 12.0*_c57  # _k62
    ctx.k[63] = 18.0*_c54  # _k63
    ctx.k[64] = 2.0*_c61  # _k64
    ctx.k[65] = 2.0*_c62  # _k65
    ctx.k[66] = _c39  # _k66
    ctx.k[67] = -_c31  # _k67
    ctx.k[68] = -_c39  # _k68
    ctx.k[69] = -_c36  # _k69
    ctx.k[70] = -_c63  # _k70
    ctx.k[71] = -_c65  # _k71
    ctx.k[72] = -_c66  # _k72
    ctx.k[73] = -_c67  # _k73
    ctx.k[74] = 2.0*_c68  # _k74
    ctx.k[75] = _c20*_c38  # _k75
    ctx.k[76] = -_c69  # _k76
    ctx.k[77] = -_c70  # _k77
    ctx.k[78] = _c66  # _k78
    ctx.k[79] = _c20*_c71  # _k79
    ctx.k[80] = 6.0*_c62  # _k80
    ctx.k[81] = _c73  # _k81
    ctx.k[82] = _c42  # _k82
    ctx.k[83] = _c74  # _k83
    ctx.k[84] = -S_T  # _k84
    ctx.k[85] = -_c76  # _k85
    ctx.k[86] = _c32  # _k86
    ctx.k[87] = 4.0*_c41  # _k87
    ctx.k[88] = -_c77  # _k88
    ctx.k[89] = -_c32  # _k89
    ctx.k[90] = _c77  # _k90
    ctx.k[91] = -d  # _k91
    ctx.k[92] = -Omega  # _k92
    ctx.k[93] = _c41  # _k93
    ctx.k[94] = -_c7  # _k94
    ctx.k[95] = -2.0*_c48  # _k95
    ctx.k[96] = -_c43*_c5  # _k96
    ctx.k[97] = -_c9  # _k97
    ctx.k[98] = -0.6666666666666666*_c9  # _k98
    ctx.k[99] = -_c10  # _k99
    ctx.k[100] = -_c78  # _k100
    ctx.k[101] = -9.0*_c3  # _k101
    ctx.k[102] = -4.0*_c3  # _k102
    ctx.k[103] = 0.4*_c3  # _k103
    ctx.k[104] = -_c5  # _k104
    ctx.k[105] = -3.0*_c5  # _k105
    ctx.k[106] = _c45  # _k106
    ctx.k[107] = -4.0*_c9  # _k107
    ctx.k[108] = _c78  # _k108
    ctx.k[109] = 8.0*_c3  # _k109
    ctx.k[110] = 6.0*_c2  # _k110
    ctx.k[111] = -_c47  # _k111
    ctx.k[112] = -16.0*_c48  # _k112
    ctx.k[113] = -8.0*_c9  # _k113
    ctx.k[114] = _c4*_c44  # _k114
    ctx.k[115] = _c46  # _k115
    ctx.k[116] = 12.0*_c3  # _k116
    ctx.k[117] = -_c3  # _k117
    ctx.k[118] = -_c25  # _k118
    ctx.k[119] = -4.0*_c18  # _k119
    ctx.k[120] = -12.0*_c30  # _k120
    ctx.k[121] = -12.0*_c28  # _k121
    ctx.k[122] = -_c29  # _k122
    ctx.k[123] = -_c22  # _k123
    ctx.k[124] = -_c33  # _k124
    ctx.k[125] = -8.0*_c61  # _k125
    ctx.k[126] = -_c64  # _k126
    ctx.k[127] = -_c55  # _k127
    ctx.k[128] = -_c79  # _k128
    ctx.k[129] = -60.0*_c59  # _k129
    ctx.k[130] = -60.0*_c54  # _k130
    ctx.k[131] = -30.0*_c53  # _k131
    ctx.k[132] = -30.0*_c57  # _k132
    ctx.k[133] = -_c80  # _k133
    ctx.k[134] = -_c60  # _k134
    ctx.k[135] = -_c58  # _k135
    ctx.k[136] = -36.0*_c54  # _k136
    ctx.k[137] = -36.0*_c57  # _k137
    ctx.k[138] = _c63  # _k138
    ctx.k[139] = J_r*_c79  # _k139
    ctx.k[140] = _c81  # _k140
    ctx.k[141] = 4.0*_c34  # _k141
    ctx.k[142] = _c64  # _k142
    ctx.k[143] = -4.0*_c30  # _k143
    ctx.k[144] = -8.0*_c28  # _k144
    ctx.k[145] = _c70  # _k145
    ctx.k[146] = 3.0*_c31  # _k146
    ctx.k[147] = _c71  # _k147
    ctx.k[148] = 6.0*_c39  # _k148
    ctx.k[149] = 10.0*_c61  # _k149
    ctx.k[150] = 10.0*_c62  # _k150
    ctx.k[151] = -J_r*_c80  # _k151
    ctx.k[152] = -_c83  # _k152
    ctx.k[153] = -_c81  # _k153
    ctx.k[154] = -12.0*_c54  # _k154
    ctx.k[155] = -6.0*_c53  # _k155
    ctx.k[156] = -24.0*_c59  # _k156
    ctx.k[157] = -24.0*_c57  # _k157
    ctx.k[158] = -24.0*_c62  # _k158
    ctx.k[159] = _c67  # _k159
    ctx.k[160] = 4.0*_c68  # _k160
    ctx.k[161] = _c83  # _k161
    ctx.k[162] = _c37  # _k162
    ctx.k[163] = -8.0*_c82  # _k163
    ctx.k[164] = -4.0*_c36  # _k164
    ctx.k[165] = _c65  # _k165
    ctx.k[166] = -16.0*_c62  # _k166
    ctx.k[167] = -8.0*_c39  # _k167
    ctx.k[168] = _c69  # _k168
    ctx.k[169] = -_c26  # _k169
    ctx.k[170] = -_c73  # _k170
    ctx.k[171] = -_c74  # _k171
    ctx.k[172] = _c76  # _k172
    ctx.k[173] = 2.0*_c26  # _k173
    ctx.k[174] = _c24  # _k174
    ctx.k[175] = -_c24  # _k175
    ctx.k[176] = _c84  # _k176
    ctx.k[177] = -_c84  # _k177
    ctx.k[178] = _c86  # _k178
    ctx.k[179] = _c87  # _k179
    ctx.k[180] = _c75  # _k180
    ctx.k[181] = -_c88  # _k181
    ctx.k[182] = -_c89  # _k182
    ctx.k[183] = _c89  # _k183
    ctx.k[184] = -_c86  # _k184
    ctx.k[185] = -_c87  # _k185
    ctx.k[186] = -_c75  # _k186
    ctx.k[187] = _c88  # _k187
    ctx.k[188] = -_c72  # _k188


cdef inline void _system(double t, const double* _y, double* _A, double* _b, double* _ph,
                         double* _phd, Ctx* ctx) noexcept nogil:
    """The augmented matrix [[M, Phi_Q^T], [Phi_Q, 0]] (row-major, _NA x _NA), the right side
    [f; gamma], and Phi, Phi' at (t, Q, Q')."""
    cdef double Omega = ctx.p[0]
    cdef double d = ctx.p[1]
    cdef double r_b = ctx.p[2]
    cdef double r_r = ctx.p[3]
    cdef double S_T = ctx.p[4]
    cdef double beta_r = ctx.p[5]
    cdef double a_rod = ctx.p[6]
    cdef double E = ctx.p[7]
    cdef double rho = ctx.p[8]
    cdef double m_r = ctx.p[9]
    cdef double J_r = ctx.p[10]
    cdef double rayleigh = ctx.p[11]
    cdef double L_g = ctx.p[12]
    cdef double w_B = ctx.p[13]
    cdef double formulation = ctx.p[14]
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
    cdef double _k158 = ctx.k[158]
    cdef double _k159 = ctx.k[159]
    cdef double _k160 = ctx.k[160]
    cdef double _k161 = ctx.k[161]
    cdef double _k162 = ctx.k[162]
    cdef double _k163 = ctx.k[163]
    cdef double _k164 = ctx.k[164]
    cdef double _k165 = ctx.k[165]
    cdef double _k166 = ctx.k[166]
    cdef double _k167 = ctx.k[167]
    cdef double _k168 = ctx.k[168]
    cdef double _k169 = ctx.k[169]
    cdef double _k170 = ctx.k[170]
    cdef double _k171 = ctx.k[171]
    cdef double _k172 = ctx.k[172]
    cdef double _k173 = ctx.k[173]
    cdef double _k174 = ctx.k[174]
    cdef double _k175 = ctx.k[175]
    cdef double _k176 = ctx.k[176]
    cdef double _k177 = ctx.k[177]
    cdef double _k178 = ctx.k[178]
    cdef double _k179 = ctx.k[179]
    cdef double _k180 = ctx.k[180]
    cdef double _k181 = ctx.k[181]
    cdef double _k182 = ctx.k[182]
    cdef double _k183 = ctx.k[183]
    cdef double _k184 = ctx.k[184]
    cdef double _k185 = ctx.k[185]
    cdef double _k186 = ctx.k[186]
    cdef double _k187 = ctx.k[187]
    cdef double _k188 = ctx.k[188]
    cdef double b1 = _y[0]
    cdef double xE = _y[1]
    cdef double theta = _y[2]
    cdef double b1d = _y[3]
    cdef double xEd = _y[4]
    cdef double thetad = _y[5]
    cdef double _cam0[5]
    _profile(ctx, theta, beta_r, _cam0, 0)

    cdef double _s0 = (xE*xE*xE)
    cdef double _s1 = (xE*xE)
    cdef double _s2 = _s1*b1
    cdef double _s3 = _k6*_s2*(_k3*xE + _k4 + _k5*_s1)
    cdef double _s4 = (b1*b1)
    cdef double _s5 = _s4*xE
    cdef double _s6 = _s1*_s4
    cdef double _s7 = (_cam0[0]*_cam0[0])
    cdef double _s8 = (_cam0[1]*_cam0[1])
    cdef double _s9 = (1.0/(_cam0[0]*_k21 + _k19 + _k20*_s7 + _k20*_s8))
    cdef double _s10 = _cam0[2]*_s9
    cdef double _s11 = (_cam0[1]*_cam0[1]*_cam0[1]*_cam0[1])
    cdef double _s12 = (_cam0[0]*_cam0[0]*_cam0[0])
    cdef double _s13 = (_cam0[0]*_cam0[0]*_cam0[0]*_cam0[0])
    cdef double _s14 = _cam0[0]*_s8
    cdef double _s15 = _s7*_s8
    cdef double _s16 = (1.0/(_cam0[0]*_k15 + _k11 + _k12*_s11 + _k12*_s13 + _k13*_s15 + _k14*_s8 + _k16*_s12 + _k16*_s14 + _k17*_s7))
    cdef double _s17 = _k18*_s16
    cdef double _s18 = (_cam0[2]*_cam0[2])
    cdef double _s19 = _s16*_s18
    cdef double _s20 = _cam0[0]*_s19
    cdef double _s21 = _cam0[2]*_s16
    cdef double _s22 = _k27*_s21
    cdef double _s23 = _k26*_s21
    cdef double _s24 = _s18*_s7
    cdef double _s25 = _k29*_s1
    cdef double _s26 = b1*xE
    cdef double _s27 = Omega*t - theta
    cdef double _s28 = sin(_s27)
    cdef double _s29 = S_T*_cam0[1]
    cdef double _s30 = S_T*_cam0[0]
    cdef double _s31 = _k31 + _s30
    cdef double _s32 = cos(_s27)
    cdef double _s33 = _s31*_s32
    cdef double _s34 = _s28*_s31
    cdef double _s35 = b1d*xEd
    cdef double _s36 = _s35*xE
    cdef double _s37 = (xEd*xEd)
    cdef double _s38 = _s0*_s35
    cdef double _s39 = _s37*b1
    cdef double _s40 = (thetad*thetad)
    cdef double _s41 = _cam0[3]*_s40
    cdef double _s42 = _s41*_s9
    cdef double _s43 = _cam0[1]*_s40
    cdef double _s44 = _s21*_s43
    cdef double _s45 = _s21*_s41
    cdef double _s46 = (_cam0[1]*_cam0[1]*_cam0[1])*_s40
    cdef double _s47 = _s16*_s46
    cdef double _s48 = _cam0[2]*_s46
    cdef double _s49 = (1.0/((((_cam0[0]*_cam0[0])*(_cam0[0]*_cam0[0]))*(_cam0[0]*_cam0[0]))*_k52 + (((_cam0[0]*_cam0[0])*(_cam0[0]*_cam0[0]))*_cam0[0])*_k57 + _cam0[0]*_k56 + _cam0[0]*_k57*_s11 + (((_cam0[1]*_cam0[1])*(_cam0[1]*_cam0[1]))*(_cam0[1]*_cam0[1]))*_k52 + _k51 + _k53*_s11*_s7 + _k53*_s13*_s8 + _k54*_s8 + _k55*_s11 + _k58*_s7 + _k59*_s13 + _k60*_s12 + _k61*_s14 + _k62*_s12*_s8 + _k63*_s15))
    cdef double _s50 = _s40*_s49
    cdef double _s51 = (((_cam0[1]*_cam0[1])*(_cam0[1]*_cam0[1]))*_cam0[1])*_s50
    cdef double _s52 = _k64*_s51
    cdef double _s53 = _cam0[1]*_s50
    cdef double _s54 = _s18*_s53
    cdef double _s55 = (_cam0[2]*_cam0[2]*_cam0[2])*_s53
    cdef double _s56 = _s48*_s49
    cdef double _s57 = _s18*_s46*_s49
    cdef double _s58 = _cam0[0]*_k83
    cdef double _s59 = _k85*thetad
    cdef double _s60 = _k88*thetad
    cdef double _s61 = _cam0[0]*_s60
    cdef double _s62 = _cam0[1]*_s32
    cdef double _s63 = _k31*_s40
    cdef double _s64 = _s28*_s40
    cdef double _s65 = _cam0[2]*_k84
    cdef double _s66 = _s32*_s40
    _A[0] = _k2*_s0*(_k0 + _k1*_s1 + m_r*xE)
    _A[1] = _s3
    _A[2] = 0.0
    _A[3] = _s25
    _A[4] = 0.0
    _A[5] = _s3
    _A[6] = _k10*_s5 + _k5*xE + _k7 + _k8*_s6 + _k9*_s0*_s4
    _A[7] = 0.0
    _A[8] = _k30*_s26
    _A[9] = 1.0
    _A[10] = 0.0
    _A[11] = 0.0
    _A[12] = J_r + _cam0[0]*_k24*_s10 + _k22*_s8*_s9 + _k23*_s19 + _k25*_s10 + _k28*_s20 + _s11*_s17 + _s14*_s23 + _s17*_s24 + _s22*_s8
    _A[13] = _s28*_s29 - _s33
    _A[14] = _s29*_s32 + _s34
    _A[15] = _s25
    _A[16] = _k30*_s26
    _A[17] = _s28*_s29 - _s33
    _A[18] = 0.0
    _A[19] = 0.0
    _A[20] = 0.0
    _A[21] = 1.0
    _A[22] = _s29*_s32 + _s34
    _A[23] = 0.0
    _A[24] = 0.0
    _b[0] = _k38*xE*(_k32*_s1*_s35 + _k33*_s26*_s37 + _k34*b1 + _k35*_s38 + _k36*_s1*_s39 + _k37*_s36)
    _b[1] = _k39*_s37*_s5 + _k40*_s4 + _k41*_s2*_s35 + _k42*_s37 + _k43*_s37*_s6 + _k44*_s37*_s4 + _k45*_s38*b1 + _k46*_s26*_s35
    _b[2] = _cam0[0]*_k47*_s42 + _cam0[0]*_k50*_s47 + _cam0[0]*_k70*_s57 + _cam0[0]*_k76*_s56 + _cam0[0]*_k77*_s44 + _cam0[0]*_k78*_s55 + _cam0[0]*_k79*_s54 + _cam0[0]*_s22*_s41 + _cam0[0]*_s52 + _cam0[2]*_s52 + _k28*_s47 + _k48*_s42 + _k49*_s10*_s43 + _k64*_s12*_s54 + _k64*_s55*_s7 + _k65*_s51 + _k66*_s16*_s41*_s8 + _k67*_s20*_s43 + _k67*_s45*_s7 + _k68*_s19*_s43 + _k69*_s45 + _k70*_s56*_s7 + _k71*_s56 + _k72*_s57 + _k73*_s44 + _k74*_s54 + _k75*_s55 + _k80*_s24*_s53 + _s14*_s17*_s41 + _s17*_s48 + _s23*_s43*_s7
    _b[3] = _k81*_s28 + _k82*_s39 + _k86*_s40*_s62 + _k87*_s36 + _s28*_s58 + _s28*_s59 + _s28*_s61 + _s28*_s63 + _s30*_s64 + _s60*_s62 + _s64*_s65
    _ph[0] = _s25*b1 + _s34
    _phd[0] = Omega*_s33 + _A[15] * b1d + _A[16] * xEd + _A[17] * thetad
    _b[4] = _cam0[1]*_k89*_s64 + _cam0[1]*_k90*_s28*thetad + _k81*_s32 + _s30*_s66 + _s32*_s58 + _s32*_s59 + _s32*_s61 + _s32*_s63 + _s65*_s66
    _ph[1] = _k91 + _s33 + xE
    _phd[1] = _k92*_s34 + _A[20] * b1d + _A[21] * xEd + _A[22] * thetad


cdef inline void _constraints(double t, const double* _y, double* _g, double* _J, double* _gt,
                              Ctx* ctx) noexcept nogil:
    """Phi, Phi_Q (row-major, _NC x _NQ) and dPhi/dt at (t, Q)."""
    cdef double Omega = ctx.p[0]
    cdef double d = ctx.p[1]
    cdef double r_b = ctx.p[2]
    cdef double r_r = ctx.p[3]
    cdef double S_T = ctx.p[4]
    cdef double beta_r = ctx.p[5]
    cdef double a_rod = ctx.p[6]
    cdef double E = ctx.p[7]
    cdef double rho = ctx.p[8]
    cdef double m_r = ctx.p[9]
    cdef double J_r = ctx.p[10]
    cdef double rayleigh = ctx.p[11]
    cdef double L_g = ctx.p[12]
    cdef double w_B = ctx.p[13]
    cdef double formulation = ctx.p[14]
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
    cdef double _k158 = ctx.k[158]
    cdef double _k159 = ctx.k[159]
    cdef double _k160 = ctx.k[160]
    cdef double _k161 = ctx.k[161]
    cdef double _k162 = ctx.k[162]
    cdef double _k163 = ctx.k[163]
    cdef double _k164 = ctx.k[164]
    cdef double _k165 = ctx.k[165]
    cdef double _k166 = ctx.k[166]
    cdef double _k167 = ctx.k[167]
    cdef double _k168 = ctx.k[168]
    cdef double _k169 = ctx.k[169]
    cdef double _k170 = ctx.k[170]
    cdef double _k171 = ctx.k[171]
    cdef double _k172 = ctx.k[172]
    cdef double _k173 = ctx.k[173]
    cdef double _k174 = ctx.k[174]
    cdef double _k175 = ctx.k[175]
    cdef double _k176 = ctx.k[176]
    cdef double _k177 = ctx.k[177]
    cdef double _k178 = ctx.k[178]
    cdef double _k179 = ctx.k[179]
    cdef double _k180 = ctx.k[180]
    cdef double _k181 = ctx.k[181]
    cdef double _k182 = ctx.k[182]
    cdef double _k183 = ctx.k[183]
    cdef double _k184 = ctx.k[184]
    cdef double _k185 = ctx.k[185]
    cdef double _k186 = ctx.k[186]
    cdef double _k187 = ctx.k[187]
    cdef double _k188 = ctx.k[188]
    cdef double b1 = _y[0]
    cdef double xE = _y[1]
    cdef double theta = _y[2]
    cdef double b1d = _y[3]
    cdef double xEd = _y[4]
    cdef double thetad = _y[5]
    cdef double _cam0[5]
    _profile(ctx, theta, beta_r, _cam0, 0)

    cdef double _p0 = _k29*(xE*xE)
    cdef double _p1 = S_T*_cam0[0] + _k31
    cdef double _p2 = Omega*t - theta
    cdef double _p3 = sin(_p2)
    cdef double _p4 = _p1*_p3
    cdef double _p5 = cos(_p2)
    cdef double _p6 = _p1*_p5
    cdef double _p7 = S_T*_cam0[1]
    _g[0] = _p0*b1 + _p4
    _g[1] = _k91 + _p6 + xE
    _J[0] = _p0
    _J[1] = _k30*b1*xE
    _J[2] = _p3*_p7 - _p6
    _J[3] = 0.0
    _J[4] = 1.0
    _J[5] = _p4 + _p5*_p7
    _gt[0] = Omega*_p6
    _gt[1] = _k92*_p4


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
    cdef double v = ctx.p[14]  # formulation
    return 2 if v > 1.5 else 1 if v > 0.5 else 0


cdef inline int _prepared(double t, double* _yc, const double* _y, double* _A, double* _acc,
                          double* w, Ctx* ctx) noexcept nogil:
    """The augmented system at the state the formulation solves it at (_yc: the state itself,
    or its partitioned recovery), with Baumgarte's terms in the right side _acc where they
    apply (formulation 0; their rate into w, else 0).  0, or 1 if the recovery failed."""
    cdef double _ph[_NC]
    cdef double _phd[_NC]
    cdef int i, form = _formulation(ctx)
    w[0] = ctx.p[13] if form == 0 else 0.0  # w_B
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
    """The named outputs (vE, Phi1, Phi2, S, pressure_angle, xEdd, lambda1, lambda2), at the recovered state when partitioned."""
    cdef double _yc[_NS]
    cdef double _acc[_NA]
    cdef int i
    if _solve(t, _yc, _y, _acc, ctx) != 0:
        for i in range(_NA):
            _acc[i] = 0.0 / 0.0
    cdef double Omega = ctx.p[0]
    cdef double d = ctx.p[1]
    cdef double r_b = ctx.p[2]
    cdef double r_r = ctx.p[3]
    cdef double S_T = ctx.p[4]
    cdef double beta_r = ctx.p[5]
    cdef double a_rod = ctx.p[6]
    cdef double E = ctx.p[7]
    cdef double rho = ctx.p[8]
    cdef double m_r = ctx.p[9]
    cdef double J_r = ctx.p[10]
    cdef double rayleigh = ctx.p[11]
    cdef double L_g = ctx.p[12]
    cdef double w_B = ctx.p[13]
    cdef double formulation = ctx.p[14]
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
    cdef double _k158 = ctx.k[158]
    cdef double _k159 = ctx.k[159]
    cdef double _k160 = ctx.k[160]
    cdef double _k161 = ctx.k[161]
    cdef double _k162 = ctx.k[162]
    cdef double _k163 = ctx.k[163]
    cdef double _k164 = ctx.k[164]
    cdef double _k165 = ctx.k[165]
    cdef double _k166 = ctx.k[166]
    cdef double _k167 = ctx.k[167]
    cdef double _k168 = ctx.k[168]
    cdef double _k169 = ctx.k[169]
    cdef double _k170 = ctx.k[170]
    cdef double _k171 = ctx.k[171]
    cdef double _k172 = ctx.k[172]
    cdef double _k173 = ctx.k[173]
    cdef double _k174 = ctx.k[174]
    cdef double _k175 = ctx.k[175]
    cdef double _k176 = ctx.k[176]
    cdef double _k177 = ctx.k[177]
    cdef double _k178 = ctx.k[178]
    cdef double _k179 = ctx.k[179]
    cdef double _k180 = ctx.k[180]
    cdef double _k181 = ctx.k[181]
    cdef double _k182 = ctx.k[182]
    cdef double _k183 = ctx.k[183]
    cdef double _k184 = ctx.k[184]
    cdef double _k185 = ctx.k[185]
    cdef double _k186 = ctx.k[186]
    cdef double _k187 = ctx.k[187]
    cdef double _k188 = ctx.k[188]
    cdef double b1 = _yc[0]
    cdef double xE = _yc[1]
    cdef double theta = _yc[2]
    cdef double b1d = _yc[3]
    cdef double xEd = _yc[4]
    cdef double thetad = _yc[5]
    cdef double _cam0[5]
    _profile(ctx, theta, beta_r, _cam0, 0)

    cdef double _o0 = b1*(xE*xE)
    cdef double _o1 = S_T*_cam0[0]
    cdef double _o2 = _k31 + _o1
    cdef double _o3 = Omega*t - theta
    _out[0] = _k93*_o0  # vE
    _out[1] = _k29*_o0 + _o2*sin(_o3)  # Phi1
    _out[2] = _k91 + _o2*cos(_o3) + xE  # Phi2
    _out[3] = _o1  # S
    _out[4] = atan(S_T*_cam0[1]/_o2)  # pressure_angle
    _out[5] = _acc[1]  # xEdd
    _out[6] = _acc[3]  # lambda1
    _out[7] = _acc[4]  # lambda2


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
_SCALE[0] = 1e-05
_SCALE[1] = 0.05
_SCALE[2] = 1.0
_SCALE[3] = 1e-05
_SCALE[4] = 0.05
_SCALE[5] = 1.0


cdef inline void _jac_parts(double t, const double* _y, const double* _acc, double* _R,
                            double* _Rt, double* _CQ, double* _Ct, Ctx* ctx) noexcept nogil:
    """With x = [Q''; lambda] = _acc held fixed: d(b - A x)/dy (row-major _NA x _NS) and
    d(b - A x)/dt, b without Baumgarte's terms; dC/dQ (_NC x _NQ) and dC/dt of the velocity
    constraint C = Phi_Q Q' + Phi_t (camdyn.derive.dae._jacobian_parts)."""
    cdef double Omega = ctx.p[0]
    cdef double d = ctx.p[1]
    cdef double r_b = ctx.p[2]
    cdef double r_r = ctx.p[3]
    cdef double S_T = ctx.p[4]
    cdef double beta_r = ctx.p[5]
    cdef double a_rod = ctx.p[6]
    cdef double E = ctx.p[7]
    cdef double rho = ctx.p[8]
    cdef double m_r = ctx.p[9]
    cdef double J_r = ctx.p[10]
    cdef double rayleigh = ctx.p[11]
    cdef double L_g = ctx.p[12]
    cdef double w_B = ctx.p[13]
    cdef double formulation = ctx.p[14]
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
    cdef double _k158 = ctx.k[158]
    cdef double _k159 = ctx.k[159]
    cdef double _k160 = ctx.k[160]
    cdef double _k161 = ctx.k[161]
    cdef double _k162 = ctx.k[162]
    cdef double _k163 = ctx.k[163]
    cdef double _k164 = ctx.k[164]
    cdef double _k165 = ctx.k[165]
    cdef double _k166 = ctx.k[166]
    cdef double _k167 = ctx.k[167]
    cdef double _k168 = ctx.k[168]
    cdef double _k169 = ctx.k[169]
    cdef double _k170 = ctx.k[170]
    cdef double _k171 = ctx.k[171]
    cdef double _k172 = ctx.k[172]
    cdef double _k173 = ctx.k[173]
    cdef double _k174 = ctx.k[174]
    cdef double _k175 = ctx.k[175]
    cdef double _k176 = ctx.k[176]
    cdef double _k177 = ctx.k[177]
    cdef double _k178 = ctx.k[178]
    cdef double _k179 = ctx.k[179]
    cdef double _k180 = ctx.k[180]
    cdef double _k181 = ctx.k[181]
    cdef double _k182 = ctx.k[182]
    cdef double _k183 = ctx.k[183]
    cdef double _k184 = ctx.k[184]
    cdef double _k185 = ctx.k[185]
    cdef double _k186 = ctx.k[186]
    cdef double _k187 = ctx.k[187]
    cdef double _k188 = ctx.k[188]
    cdef double b1 = _y[0]
    cdef double xE = _y[1]
    cdef double theta = _y[2]
    cdef double b1d = _y[3]
    cdef double xEd = _y[4]
    cdef double thetad = _y[5]
    cdef double _cam0[5]
    _profile(ctx, theta, beta_r, _cam0, 1)

    cdef double _j0 = (xE*xE)
    cdef double _j1 = _j0*_k5 + _k3*xE + _k4
    cdef double _j2 = _j1*_acc[1]
    cdef double _j3 = _j0*_k94
    cdef double _j4 = (xEd*xEd)
    cdef double _j5 = _j4*_k33
    cdef double _j6 = _j0*_j4
    cdef double _j7 = _k38*xE
    cdef double _j8 = _k37*xEd
    cdef double _j9 = b1d*xE
    cdef double _j10 = _j9*xEd
    cdef double _j11 = b1d*xEd
    cdef double _j12 = _j0*_j11
    cdef double _j13 = b1*xE
    cdef double _j14 = _j13*_j4
    cdef double _j15 = (xE*xE*xE)
    cdef double _j16 = _k104*_acc[0]
    cdef double _j17 = _j11*_j15
    cdef double _j18 = _j6*b1
    cdef double _j19 = _k99*xEd
    cdef double _j20 = _j0*b1
    cdef double _j21 = _j20*_k94*(_k106*xE + _k3)
    cdef double _j22 = _k82*_acc[3]
    cdef double _j23 = _j22*xE + _k96*b1
    cdef double _j24 = _j0*_k32
    cdef double _j25 = _j15*_k35
    cdef double _j26 = _j13*xEd
    cdef double _j27 = _j20*xEd
    cdef double _j28 = _j15*b1
    cdef double _j29 = _k111*_acc[1]
    cdef double _j30 = _k46*b1
    cdef double _j31 = (b1*b1)
    cdef double _j32 = _j31*xE
    cdef double _j33 = _j0*_j31
    cdef double _j34 = _j28*_k45
    cdef double _j35 = Omega*t - theta
    cdef double _j36 = cos(_j35)
    cdef double _j37 = _j36*_k84
    cdef double _j38 = S_T*_cam0[0]
    cdef double _j39 = _j38 + _k31
    cdef double _j40 = sin(_j35)
    cdef double _j41 = _j39*_j40
    cdef double _j42 = _cam0[1]*_j37 - _j41
    cdef double _j43 = S_T*_j40
    cdef double _j44 = _j36*_j39
    cdef double _j45 = _cam0[1]*_j43 - _j44
    cdef double _j46 = (_cam0[0]*_cam0[0])
    cdef double _j47 = (_cam0[1]*_cam0[1])
    cdef double _j48 = _cam0[0]*_k21 + _j46*_k20 + _j47*_k20 + _k19
    cdef double _j49 = (1.0/(_j48))
    cdef double _j50 = (thetad*thetad)
    cdef double _j51 = _j49*_j50
    cdef double _j52 = _j51*_k47
    cdef double _j53 = (_cam0[0]*_cam0[0]*_cam0[0])
    cdef double _j54 = (_cam0[0]*_cam0[0]*_cam0[0]*_cam0[0])
    cdef double _j55 = (_cam0[1]*_cam0[1]*_cam0[1]*_cam0[1])
    cdef double _j56 = _cam0[0]*_j47
    cdef double _j57 = _j46*_j47
    cdef double _j58 = _cam0[0]*_k15 + _j46*_k17 + _j47*_k14 + _j53*_k16 + _j54*_k12 + _j55*_k12 + _j56*_k16 + _j57*_k13 + _k11
    cdef double _j59 = (1.0/(_j58))
    cdef double _j60 = _cam0[2]*_j59
    cdef double _j61 = _j50*_k69
    cdef double _j62 = _cam0[0]*_j60
    cdef double _j63 = _j50*_k27
    cdef double _j64 = _j47*_j59
    cdef double _j65 = _j50*_j64
    cdef double _j66 = _j56*_j59
    cdef double _j67 = _j50*_j66
    cdef double _j68 = _j46*_j60
    cdef double _j69 = _j50*_k67
    cdef double _j70 = _j49*_k24
    cdef double _j71 = _cam0[1]*_j49
    cdef double _j72 = _j50*_k49
    cdef double _j73 = _j50*_k73
    cdef double _j74 = _cam0[1]*_j59
    cdef double _j75 = _cam0[3]*_j59
    cdef double _j76 = (_cam0[1]*_cam0[1]*_cam0[1])
    cdef double _j77 = _j59*_j76
    cdef double _j78 = _j50*_j77
    cdef double _j79 = (((_cam0[0]*_cam0[0])*(_cam0[0]*_cam0[0]))*_cam0[0])
    cdef double _j80 = _cam0[0]*_j55
    cdef double _j81 = _j47*_j53
    cdef double _j82 = (((_cam0[0]*_cam0[0])*(_cam0[0]*_cam0[0]))*(_cam0[0]*_cam0[0]))*_k52 + _cam0[0]*_k56 + (((_cam0[1]*_cam0[1])*(_cam0[1]*_cam0[1]))*(_cam0[1]*_cam0[1]))*_k52 + _j46*_j55*_k53 + _j46*_k58 + _j47*_j54*_k53 + _j47*_k54 + _j53*_k60 + _j54*_k59 + _j55*_k55 + _j56*_k61 + _j57*_k63 + _j79*_k57 + _j80*_k57 + _j81*_k62 + _k51
    cdef double _j83 = (1.0/(_j82))
    cdef double _j84 = _j50*_j83
    cdef double _j85 = _j76*_j84
    cdef double _j86 = _cam0[0]*_cam0[1]
    cdef double _j87 = _j86*_k77
    cdef double _j88 = _cam0[0]*_j50
    cdef double _j89 = _j88*_k27
    cdef double _j90 = _cam0[0]*_j76
    cdef double _j91 = _j84*_j90
    cdef double _j92 = _cam0[1]*_k160
    cdef double _j93 = _cam0[2]*_j84
    cdef double _j94 = _cam0[1]*_j60
    cdef double _j95 = _cam0[1]*_j46
    cdef double _j96 = _j50*_k26
    cdef double _j97 = _j95*_j96
    cdef double _j98 = _j46*_j76
    cdef double _j99 = _j98*_k70
    cdef double _j100 = _j86*_k161
    cdef double _j101 = _j60*_j86
    cdef double _j102 = _cam0[1]*_j53
    cdef double _j103 = _j102*_k138
    cdef double _j104 = _j95*_k140
    cdef double _j105 = (((_cam0[1]*_cam0[1])*(_cam0[1]*_cam0[1]))*_cam0[1])
    cdef double _j106 = _j84*_k64
    cdef double _j107 = (_cam0[2]*_cam0[2])
    cdef double _j108 = _j107*_j84
    cdef double _j109 = _j108*_k79
    cdef double _j110 = _cam0[2]*_k76
    cdef double _j111 = _cam0[2]*_k125
    cdef double _j112 = _cam0[1]*_j109 + _j105*_j106 + _j108*_j86*_k140 + _j108*_j95*_k139 + _j110*_j85 + _j111*_j91
    cdef double _j113 = _cam0[2]*_j70
    cdef double _j114 = (1.0/(_j48*_j48))
    cdef double _j115 = _j114*(_cam0[0]*_k123 + _k124)
    cdef double _j116 = _cam0[2]*_j115
    cdef double _j117 = _j107*_j59
    cdef double _j118 = _cam0[0]*_j117
    cdef double _j119 = _j47*_j60
    cdef double _j120 = (1.0/(_j58*_j58))
    cdef double _j121 = _j120*(_cam0[0]*_k120 + _j46*_k121 + _j47*_k122 + _j53*_k119 + _j56*_k119 + _k118)
    cdef double _j122 = _j55*_k18
    cdef double _j123 = _j107*_k23
    cdef double _j124 = _j107*_j121
    cdef double _j125 = _cam0[0]*_k28
    cdef double _j126 = _cam0[2]*_j47
    cdef double _j127 = _j126*_k27
    cdef double _j128 = _cam0[2]*_j121
    cdef double _j129 = _j56*_k26
    cdef double _j130 = _j46*_k18
    cdef double _j131 = _j40*_k84
    cdef double _j132 = S_T*_j36
    cdef double _j133 = _j60*_k77
    cdef double _j134 = _cam0[1]*_j133
    cdef double _j135 = _j117*_j50
    cdef double _j136 = (_cam0[2]*_cam0[2]*_cam0[2])
    cdef double _j137 = _j136*_j84
    cdef double _j138 = _j137*_k78
    cdef double _j139 = _cam0[3]*_j50
    cdef double _j140 = _j139*_k27
    cdef double _j141 = _j121*_j50
    cdef double _j142 = _j76*_k28
    cdef double _j143 = _cam0[0]*_k131 + _j46*_k129 + _j47*_k134 + _j53*_k130 + _j54*_k132 + _j55*_k135 + _j56*_k136 + _j57*_k137 + _j79*_k128 + _j80*_k128 + _j81*_k133 + _k127
    cdef double _j144 = (1.0/(_j82*_j82))
    cdef double _j145 = _j105*_j144
    cdef double _j146 = _j143*_j145
    cdef double _j147 = _j50*_k65
    cdef double _j148 = _j101*_k126
    cdef double _j149 = _j139*_k26
    cdef double _j150 = _j146*_k64
    cdef double _j151 = _cam0[1]*_j73
    cdef double _j152 = _cam0[1]*_j50
    cdef double _j153 = _j152*_k68
    cdef double _j154 = _j143*_j144
    cdef double _j155 = _j107*_j154
    cdef double _j156 = _j152*_k74
    cdef double _j157 = _j154*_j50
    cdef double _j158 = _cam0[1]*_j136
    cdef double _j159 = _j158*_k75
    cdef double _j160 = _cam0[3]*_j61
    cdef double _j161 = _cam0[2]*_j76
    cdef double _j162 = _j161*_k18
    cdef double _j163 = _cam0[2]*_j50
    cdef double _j164 = _j161*_k71
    cdef double _j165 = _j121*_j139
    cdef double _j166 = _j47*_k66
    cdef double _j167 = _j155*_j50
    cdef double _j168 = _j76*_k72
    cdef double _j169 = _cam0[2]*_j141
    cdef double _j170 = _j69*_j86
    cdef double _j171 = _j136*_j157
    cdef double _j172 = _j86*_k78
    cdef double _j173 = _j86*_k79
    cdef double _j174 = _cam0[3]*_j89
    cdef double _j175 = _j110*_j90
    cdef double _j176 = _j56*_k18
    cdef double _j177 = _j90*_k70
    cdef double _j178 = _j95*_k64
    cdef double _j179 = _j102*_k64
    cdef double _j180 = _j95*_k80
    cdef double _j181 = _j139*_j46*_k67
    cdef double _j182 = _cam0[2]*_j114
    cdef double _j183 = _j50*_k50
    cdef double _j184 = _j120*(_cam0[1]*_k143 + _j76*_k119 + _j86*_k144 + _j95*_k119)
    cdef double _j185 = _cam0[2]*_j184
    cdef double _j186 = _j184*_j50
    cdef double _j187 = _j107*_j184
    cdef double _j188 = _j139*_j184
    cdef double _j189 = _j55*_j84
    cdef double _j190 = _cam0[1]*_j54*_k128 + _cam0[1]*_k155 + _j102*_k157 + _j105*_k128 + _j76*_k154 + _j86*_k156 + _j90*_k157 + _j95*_k136 + _j98*_k133
    cdef double _j191 = _j145*_j190
    cdef double _j192 = _j191*_k64
    cdef double _j193 = _j144*_j190
    cdef double _j194 = _j107*_j193
    cdef double _j195 = _j193*_j50
    cdef double _j196 = _j194*_j50
    cdef double _j197 = _j136*_j195
    cdef double _j198 = _j77*_k142
    cdef double _j199 = _cam0[3]*thetad
    cdef double _j200 = _j199*_j49
    cdef double _j201 = _cam0[1]*thetad
    cdef double _j202 = _j77*thetad
    cdef double _j203 = _j83*thetad
    cdef double _j204 = _j105*_j203
    cdef double _j205 = _j204*_k138
    cdef double _j206 = _j107*_j203
    cdef double _j207 = _j136*_j203
    cdef double _j208 = _k82*_acc[1]
    cdef double _j209 = _k87*xEd
    cdef double _j210 = _cam0[0]*_j36
    cdef double _j211 = _j36*thetad
    cdef double _j212 = _j210*thetad
    cdef double _j213 = _k88*thetad
    cdef double _j214 = _j213*_j40
    cdef double _j215 = _j36*_j50
    cdef double _j216 = _j132*_j50
    cdef double _j217 = _j37*_j50
    cdef double _j218 = _j40*_j50
    cdef double _j219 = _j131*_j50
    cdef double _j220 = _j215*_k86
    cdef double _j221 = _j213*_j36
    cdef double _j222 = _j131*_acc[2] + _j221
    cdef double _j223 = _j40*_k83
    cdef double _j224 = _j40*_k85
    cdef double _j225 = _cam0[0]*_j40
    cdef double _j226 = _cam0[1]*_k88
    cdef double _j227 = _j40*thetad
    cdef double _j228 = _j225*thetad
    cdef double _j229 = _cam0[1]*_j211
    cdef double _j230 = _cam0[2]*_k89
    cdef double _j231 = _cam0[1]*_j227
    cdef double _j232 = _j36*_k176
    cdef double _j233 = Omega*_j41
    cdef double _j234 = _cam0[1]*_j232 + _j233
    cdef double _j235 = _j40*_k177
    cdef double _j236 = Omega*_j44
    cdef double _j237 = _cam0[1]*_j235 + _j236
    cdef double _j238 = _k30*xEd
    cdef double _j239 = _j43*thetad
    _R[0] = _j2*_j3 + _j7*(_j5*xE + _j6*_k36 + _k34)
    _R[1] = _j0*_k105*_acc[0]*(_j0*_k1 + _k0 + m_r*xE) + _j12*_k39 + _j13*_j2*_k104 + _j14*_k95 + _j15*_j16*(_k103*xE + m_r) + _j17*_k97 + _j18*_k98 + _j19*_j9 + _j21*_acc[1] + _j23 + _j7*(_j10*_k100 + _j12*_k101 + _j14*_k102 + _j5*b1 + _j8*b1d)
    _R[2] = 0.0
    _R[3] = _j7*(_j24*xEd + _j25*xEd + _j8*xE)
    _R[4] = _j7*(_j24*b1d + _j25*b1d + _j26*_k32 + _j27*_k102 + _j9*_k37)
    _R[5] = 0.0
    _R[6] = _j1*_j3*_acc[0] + _j10*_k46 + _j12*_k41 + _j14*_k41 + _j17*_k45 + _j18*_k107 + _j23 + _j29*(_j13*_k110 + _j20*_k108 + _j28*_k109) + _j4*_k99*b1
    _R[7] = _j1*_j13*_j16 + _j10*_k112*b1 + _j11*_j20*_k113 + _j11*_j30 + _j21*_acc[0] + _j22*b1 + _j29*(_j31*_k115 + _j32*_k108 + _j33*_k116 + _k114) + _j31*_j4*_k39 + _j32*_j4*_k107
    _R[8] = 0.0
    _R[9] = _j26*_k46 + _j27*_k41 + _j34*xEd
    _R[10] = _j19*_j31 + _j20*_k41*b1d + _j30*_j9 + _j32*_k41*xEd + _j33*_k107*xEd + _j34*b1d + _k117*xEd
    _R[11] = 0.0
    _R[12] = 0.0
    _R[13] = 0.0
    _R[14] = _cam0[1]*(_cam0[1]*_j116*_j72 + _cam0[1]*_j135*_k67 + _cam0[1]*_j138 + _cam0[2]*_j157*_j99 + _cam0[3]*_j115*_j88*_k47 + _cam0[3]*_j52 + _cam0[3]*_j65*_k18 + _j108*_j76*_k70 + _j112 + _j115*_j139*_k48 + _j124*_j153 + _j124*_j170 + _j128*_j151 + _j128*_j160 + _j128*_j174 + _j128*_j181 + _j131*_acc[4] + _j132*_acc[3] + _j134*_j50 + _j137*_j86*_k138 + _j140*_j60 + _j141*_j142 + _j141*_j162 + _j141*_j90*_k50 + _j146*_j147 + _j148*_j50 + _j149*_j62 + _j150*_j163 + _j150*_j88 + _j155*_j156 + _j157*_j159 + _j157*_j164 + _j157*_j175 + _j165*_j166 + _j165*_j176 + _j167*_j168 + _j167*_j173 + _j167*_j177 + _j167*_j179 + _j167*_j180 + _j169*_j87 + _j169*_j95*_k26 + _j171*_j172 + _j171*_j178 + _j78*_k50 - _acc[2]*(_cam0[0]*_j116*_k24 + _j113 + _j115*_j47*_k22 + _j116*_k25 + _j117*_k28 + _j118*_k50 + _j119*_k26 + _j121*_j122 + _j121*_j123 + _j121*_j127 + _j124*_j125 + _j124*_j130 + _j128*_j129)) + _cam0[2]*(_cam0[0]*_j109 + _cam0[0]*_j138 + _cam0[1]*_j114*_j140 + _cam0[2]*_j186*_j87 + _cam0[2]*_j189*_k149 + _cam0[2]*_j51*_k49 + _j106*_j107*_j53 + _j106*_j136*_j46 + _j108*_j46*_k80 + _j108*_j47*_k153 + _j108*_j56*_k151 + _j108*_k74 + _j114*_j149*_j86 + _j118*_j69 + _j119*_j50*_k146 + _j126*_j84*_k152 + _j131*_acc[3] + _j133*_j88 + _j135*_k68 + _j137*_k75 + _j139*_j74*_k28 + _j142*_j186 + _j147*_j191 + _j151*_j185 + _j153*_j187 + _j156*_j194 + _j159*_j195 + _j160*_j185 + _j162*_j186 + _j163*_j192 + _j163*_j193*_j99 + _j164*_j195 + _j166*_j188 + _j168*_j196 + _j170*_j187 + _j172*_j197 + _j173*_j196 + _j174*_j185 + _j175*_j195 + _j176*_j188 + _j177*_j196 + _j178*_j197 + _j179*_j196 + _j180*_j196 + _j181*_j185 + _j182*_j183*_j47 + _j183*_j184*_j90 + _j183*_j75*_j86 + _j185*_j97 + _j189*_k150 + _j192*_j88 + _j37*_acc[4] + _j56*_j93*_k158 + _j57*_j93*_k151 + _j60*_j73 + _j65*_k148 + _j67*_k147 + _j68*_j96 + _j80*_j84*_k149 - _acc[2]*(_cam0[1]*_j182*_k145 + _j114*_j76*_k126 + _j122*_j184 + _j123*_j184 + _j125*_j187 + _j127*_j184 + _j129*_j185 + _j130*_j187 + _j134 + _j148 + _j182*_j86*_k142 + _j198 + _j71*_k141)) + _cam0[3]*(_j100*_j93 + _j101*_j96 + _j103*_j93 + _j104*_j93 + _j112 + _j46*_j69*_j75 + _j50*_j59*_j87 + _j59*_j97 + _j61*_j75 + _j63*_j94 + _j71*_j72 + _j73*_j74 + _j75*_j89 + _j78*_k18 + _j84*_j99 + _j85*_k71 + _j91*_k76 + _j92*_j93 - _acc[2]*(_cam0[0]*_j70 + _j49*_k25 + _j60*_k159 + _j62*_k145 + _j64*_k27 + _j66*_k26 + _j68*_k50)) + _cam0[4]*(_cam0[0]*_j52 + _j51*_k48 + _j60*_j61 + _j62*_j63 + _j65*_k66 + _j67*_k18 + _j68*_j69) - _j42*_acc[3] - _j45*_acc[4]
    _R[15] = 0.0
    _R[16] = 0.0
    _R[17] = _cam0[0]*_j133*_j199 + _cam0[0]*_j198*thetad + _cam0[0]*_j200*_k22 + _cam0[0]*_j205 + _cam0[2]*_j202*_k50 + _cam0[2]*_j203*_j90*_k166 + _cam0[2]*_j205 + _j100*_j206 + _j101*_k167*thetad + _j103*_j206 + _j104*_j206 + _j111*_j203*_j98 + _j113*_j201 + _j117*_j201*_k27 + _j117*_j86*_k26*thetad + _j158*_j203*_k165 + _j161*_j203*_k163 + _j199*_j60*_k73 + _j199*_j64*_k28 + _j199*_j66*_k50 + _j199*_j68*_k26 + _j200*_k162 + _j202*_k145 + _j204*_k78 + _j206*_j76*_k76 + _j206*_j90*_k125 + _j206*_j92 + _j207*_j86*_k168 + _j207*_j95*_k138 + _j60*_j95*_k126*thetad + _j94*_k164*thetad
    _R[18] = _j208*xE + _j4*_k82
    _R[19] = _j208*b1 + _j209*b1d + _k82*_acc[0]*xE
    _R[20] = _cam0[0]*_j217 + _cam0[1]*_j214 + _cam0[1]*_j218*_k86 + _cam0[1]*(_j132*_acc[2] + _j214 + _j223 + _j43*_j50) + _cam0[2]*_j216 + _cam0[2]*(_j220 + _j222) + _cam0[3]*_j219 + _j210*_k171 + _j211*_k172 + _j212*_k90 + _j215*_k169 + _j36*_k170 - _j42*_acc[2]
    _R[21] = _j209*xE
    _R[22] = _j209*b1 + _j9*_k87
    _R[23] = _j224 + _j225*_k88 + _j226*_j36 + _j227*_j230 + _j227*_k173 + _j228*_k86 + _j229*_k174
    _R[24] = 0.0
    _R[25] = 0.0
    _R[26] = _cam0[0]*_j214 + _cam0[0]*_j223 + _cam0[1]*_j220 + _cam0[1]*_j221 + _cam0[1]*(_j216 + _j222 + _j36*_k83) + _cam0[2]*_j219 + _cam0[2]*(_j218*_k89 + _j227*_k90 + _j37*_acc[2]) + _cam0[3]*_j217 + _j218*_j38 + _j218*_k31 + _j224*thetad + _j40*_k81 - _j45*_acc[2]
    _R[27] = 0.0
    _R[28] = 0.0
    _R[29] = _cam0[1]*_j40*_k90 + _j210*_k88 + _j211*_j230 + _j211*_k173 + _j212*_k86 + _j231*_k175 + _j36*_k85
    _Rt[0] = 0.0
    _Rt[1] = 0.0
    _Rt[2] = -_j234*_acc[3] - _j237*_acc[4]
    _Rt[3] = _cam0[2]*_j215*_k177 + _j210*_k179 + _j211*_k181 + _j212*_k182 + _j215*_k180 + _j218*_j226 + _j231*_k183 + _j232*_j88 - _j234*_acc[2] + _j36*_k178
    _Rt[4] = _cam0[2]*_j218*_k176 + _j215*_j226 + _j218*_k186 + _j225*_k185 + _j227*_k187 + _j228*_k183 + _j229*_k183 + _j235*_j88 - _j237*_acc[2] + _j40*_k184
    _CQ[0] = _j238*xE
    _CQ[1] = _j238*b1 + _j9*_k30
    _CQ[2] = _cam0[1]*(_j232 + _j37*thetad) + _cam0[2]*_j239 + _j233 + _j42*thetad
    _CQ[3] = 0.0
    _CQ[4] = 0.0
    _CQ[5] = _cam0[1]*(_j235 + _j239) + _cam0[2]*_j132*thetad + _j236 + _j45*thetad
    _Ct[0] = _j234*thetad + _j41*_k188
    _Ct[1] = _j237*thetad + _j44*_k188


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
    cdef double Omega = ctx.p[0]
    cdef double d = ctx.p[1]
    cdef double r_b = ctx.p[2]
    cdef double r_r = ctx.p[3]
    cdef double S_T = ctx.p[4]
    cdef double beta_r = ctx.p[5]
    cdef double a_rod = ctx.p[6]
    cdef double E = ctx.p[7]
    cdef double rho = ctx.p[8]
    cdef double m_r = ctx.p[9]
    cdef double J_r = ctx.p[10]
    cdef double rayleigh = ctx.p[11]
    cdef double L_g = ctx.p[12]
    cdef double w_B = ctx.p[13]
    cdef double formulation = ctx.p[14]
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
    cdef double _k158 = ctx.k[158]
    cdef double _k159 = ctx.k[159]
    cdef double _k160 = ctx.k[160]
    cdef double _k161 = ctx.k[161]
    cdef double _k162 = ctx.k[162]
    cdef double _k163 = ctx.k[163]
    cdef double _k164 = ctx.k[164]
    cdef double _k165 = ctx.k[165]
    cdef double _k166 = ctx.k[166]
    cdef double _k167 = ctx.k[167]
    cdef double _k168 = ctx.k[168]
    cdef double _k169 = ctx.k[169]
    cdef double _k170 = ctx.k[170]
    cdef double _k171 = ctx.k[171]
    cdef double _k172 = ctx.k[172]
    cdef double _k173 = ctx.k[173]
    cdef double _k174 = ctx.k[174]
    cdef double _k175 = ctx.k[175]
    cdef double _k176 = ctx.k[176]
    cdef double _k177 = ctx.k[177]
    cdef double _k178 = ctx.k[178]
    cdef double _k179 = ctx.k[179]
    cdef double _k180 = ctx.k[180]
    cdef double _k181 = ctx.k[181]
    cdef double _k182 = ctx.k[182]
    cdef double _k183 = ctx.k[183]
    cdef double _k184 = ctx.k[184]
    cdef double _k185 = ctx.k[185]
    cdef double _k186 = ctx.k[186]
    cdef double _k187 = ctx.k[187]
    cdef double _k188 = ctx.k[188]
    cdef double b1 = _y[0]
    cdef double xE = _y[1]
    cdef double theta = _y[2]
    cdef double b1d = _y[3]
    cdef double xEd = _y[4]
    cdef double thetad = _y[5]
    cdef double _cam0[5]
    _profile(ctx, theta, beta_r, _cam0, 0)

    _g[0] = -sin(theta)*sin(beta_r - theta)  # segment_up
    _g[1] = -sin(theta)*sin(beta_r - theta)  # segment_down


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
    cdef double Omega = p[0]
    cdef double d = p[1]
    cdef double r_b = p[2]
    cdef double r_r = p[3]
    cdef double S_T = p[4]
    cdef double beta_r = p[5]
    cdef double a_rod = p[6]
    cdef double E = p[7]
    cdef double rho = p[8]
    cdef double m_r = p[9]
    cdef double J_r = p[10]
    cdef double rayleigh = p[11]
    cdef double L_g = p[12]
    cdef double w_B = p[13]
    cdef double formulation = p[14]
    return [0.0, d - r_b - r_r, 0.0, 0.0, 0.0, Omega]


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
    ctx.cache = &k[189]
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
_model.n_params = 15
_model.n_outputs = 8
_model.n_families = 1
_model.n_instances = _NCAM
_model.n_modes = _NM
_model.n_events = _NE
_model.n_const = 189
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
 "cam_families": [
  "R"
 ],
 "cam_instances": [],
 "cam_profile": {
  "argument": "theta",
  "family": "R",
  "kind": "RDFD, periodic in 2 pi"
 },
 "constraints": [
  {
   "multiplier": "lambda1",
   "name": "Phi1"
  },
  {
   "multiplier": "lambda2",
   "name": "Phi2"
  }
 ],
 "dependent": [
  "xE",
  "theta"
 ],
 "events": [
  "segment_up",
  "segment_down"
 ],
 "jacobian": "symbolic",
 "modes": [],
 "n_constraints": 2,
 "n_q": 3,
 "name": "beam1",
 "options": [
  [
   "modes",
   1
  ]
 ],
 "outputs": [
  {
   "doc": "transverse deflection of the rod at the roller pin E, v(x_E, t)",
   "name": "vE",
   "unit": "m"
  },
  {
   "doc": "transverse constraint residual (6)",
   "name": "Phi1",
   "unit": "m"
  },
  {
   "doc": "axial constraint residual (7)",
   "name": "Phi2",
   "unit": "m"
  },
  {
   "doc": "follower displacement of the cam law at theta",
   "name": "S",
   "unit": "m"
  },
  {
   "doc": "pressure angle atan(S'/r) at theta",
   "name": "pressure_angle",
   "unit": "rad"
  },
  {
   "doc": "axial acceleration of the roller pin",
   "name": "xEdd",
   "unit": "m/s^2"
  },
  {
   "doc": "multiplier of the first constraint (transverse, (6))",
   "name": "lambda1",
   "unit": "N"
  },
  {
   "doc": "multiplier of the second constraint (axial, (7))",
   "name": "lambda2",
   "unit": "N"
  }
 ],
 "parameters": [
  {
   "default": 240.0,
   "doc": "angular velocity of the cam (paper: 120, 240, 360)",
   "high": null,
   "low": 0.0,
   "name": "Omega",
   "open_high": false,
   "open_low": true,
   "range": "0 < Omega",
   "unit": "rad/s"
  },
  {
   "default": 0.112,
   "doc": "distance from the cam centre to the guide exit (paper: 102, 112, 122 mm)",
   "high": null,
   "low": 0.0,
   "name": "d",
   "open_high": false,
   "open_low": true,
   "range": "0 < d",
   "unit": "m"
  },
  {
   "default": 0.026,
   "doc": "base-circle radius of the cam (paper (3))",
   "high": null,
   "low": 0.0,
   "name": "r_b",
   "open_high": false,
   "open_low": true,
   "range": "0 < r_b",
   "unit": "m"
  },
  {
   "default": 0.005,
   "doc": "roller radius (paper (3))",
   "high": null,
   "low": 0.0,
   "name": "r_r",
   "open_high": false,
   "open_low": true,
   "range": "0 < r_r",
   "unit": "m"
  },
  {
   "default": 0.015,
   "doc": "total rise (paper (1); 8, 15, 22 mm)",
   "high": null,
   "low": 0.0,
   "name": "S_T",
   "open_high": false,
   "open_low": true,
   "range": "0 < S_T",
   "unit": "m"
  },
  {
   "default": 1.5707963267948966,
   "doc": "cam angle of the rise and of the fall (paper: pi/2)",
   "high": 3.141592653589793,
   "low": 0.0,
   "name": "beta_r",
   "open_high": false,
   "open_low": true,
   "range": "0 < beta_r <= 3.14159",
   "unit": "rad"
  },
  {
   "default": 0.005,
   "doc": "radius of the rod's circular section (paper: 3, 5, 7 mm)",
   "high": null,
   "low": 0.0,
   "name": "a_rod",
   "open_high": false,
   "open_low": true,
   "range": "0 < a_rod",
   "unit": "m"
  },
  {
   "default": 210000000000.0,
   "doc": "Young's modulus of the rod",
   "high": null,
   "low": 0.0,
   "name": "E",
   "open_high": false,
   "open_low": true,
   "range": "0 < E",
   "unit": "Pa"
  },
  {
   "default": 7800.0,
   "doc": "density of the rod",
   "high": null,
   "low": 0.0,
   "name": "rho",
   "open_high": false,
   "open_low": true,
   "range": "0 < rho",
   "unit": "kg/m^3"
  },
  {
   "default": 0.05,
   "doc": "roller mass (pin included)",
   "high": null,
   "low": 0.0,
   "name": "m_r",
   "open_high": false,
   "open_low": true,
   "range": "0 < m_r",
   "unit": "kg"
  },
  {
   "default": 6.25e-07,
   "doc": "roller moment of inertia about its pin (default: uniform disc m_r r_r^2/2)",
   "high": null,
   "low": 0.0,
   "name": "J_r",
   "open_high": false,
   "open_low": false,
   "range": "0 <= J_r",
   "unit": "kg m^2"
  },
  {
   "default": 1.0,
   "doc": "1 keeps the rod's rotary inertia (Rayleigh beam), 0 drops it",
   "high": 1.0,
   "low": 0.0,
   "name": "rayleigh",
   "open_high": false,
   "open_low": false,
   "range": "0 <= rayleigh <= 1",
   "unit": "1"
  },
  {
   "default": 0.0,
   "doc": "length of rod inside the guide carried axially (0: free part only)",
   "high": null,
   "low": 0.0,
   "name": "L_g",
   "open_high": false,
   "open_low": false,
   "range": "0 <= L_g",
   "unit": "m"
  },
  {
   "default": 2000.0,
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
   "doc": "0: augmented index-1 system with Baumgarte stabilization; 1: coordinate partitioning with Newton on (x_E, theta); 2: augmented system, projected onto the constraints after every step",
   "high": 2.0,
   "low": 0.0,
   "name": "formulation",
   "open_high": false,
   "open_low": false,
   "range": "0 <= formulation <= 2",
   "unit": "1"
  }
 ],
 "reference": "paper (1)-(20)",
 "residual": null,
 "solver": {
  "baumgarte_rate": "w_B",
  "formulation": "formulation"
 },
 "source_hash": "sha256:c16b3556f450993e2cc9f2fd4a99c60d51901b4ed16007df3788e4358514ae33",
 "states": [
  {
   "doc": "amplitude of the assumed mode (x/d)^2 (13)",
   "initial": 0.0,
   "name": "b1",
   "scale": 1e-05,
   "unit": "m"
  },
  {
   "doc": "free length of the rod, guide exit to roller pin E",
   "initial": "d - r_b - r_r",
   "name": "xE",
   "scale": 0.05,
   "unit": "m"
  },
  {
   "doc": "cam parameter of the contact (pitch-curve point of E)",
   "initial": 0.0,
   "name": "theta",
   "scale": 1.0,
   "unit": "rad"
  },
  {
   "doc": "rate of b1",
   "initial": 0.0,
   "name": "b1d",
   "scale": 1e-05,
   "unit": "m/s"
  },
  {
   "doc": "rate of xE",
   "initial": 0.0,
   "name": "xEd",
   "scale": 0.05,
   "unit": "m/s"
  },
  {
   "doc": "rate of theta",
   "initial": "Omega",
   "name": "thetad",
   "scale": 1.0,
   "unit": "rad/s"
  }
 ],
 "time": {
  "name": "t",
  "unit": "s"
 },
 "time_derivative": "symbolic",
 "title": "Rayleigh-beam follower in a grooved disk cam, N = 1 assumed modes"
}
"""
MANIFEST = json.loads(_MANIFEST_JSON)
"""States, parameters (defaults, units, ranges), outputs, the cam profile, events, source hash."""

# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True, initializedcheck=False
#
# GENERATED FILE - DO NOT EDIT.  Written by `camdyn derive` from camdyn/derive/models/beam.py;
# edit that and regenerate.  `camdyn derive --check` fails while this file is stale.
# Derivation key: sha256:0cd4c623d83d7cc2b568d9d63e92f547a8725ac7799ea77983cb7e3fa5133bf9
# Text hash: sha256:161fe17a4e7fc351d5bdfe675a7a97a87cb7276e6744227ce9d544ead398cf4a
#
# Rayleigh-beam follower in a grooved disk cam, N = 4 assumed modes (paper (1)-(20))
# Source hash: sha256:005fc6dd88930eeb16af7091c0a74ba4fe7f9c436ef794c0f2976a8de40a1269
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
# How the constraints are solved (augmented with Baumgarte's rate w_B, paper (20), or
# partitioned, the last two coordinates x_E and theta dependent, paper (21)-(27)) is the
# parameter ``formulation``, declared as the model's ConstraintSolver; the multipliers are the
# outputs lambda1 (transverse, (6)) and lambda2 (axial, (7)), in N.

import json

from cpython.pycapsule cimport PyCapsule_New
from libc.math cimport atan, cos, fabs, fmod, M_PI, pow, sin

from camdyn.runtime.engine.abi cimport *
from camdyn.generated.camlaws cimport camlaw_eval, camlaw_segment
from camdyn.runtime.engine.linalg cimport solve_inplace

# sizes, known when the integration loops (loops.pxi) are compiled into this module
cdef enum:
    _NQ = 6                  # coordinates Q
    _NC = 2                  # constraints Phi
    _NA = 8                  # unknowns of the augmented system: Q'', lambda
    _ND = 4                  # first dependent coordinate (the last _NC are dependent)
    _NS = 12                 # states: Q, Q'
    _NCAM = 0
    _NM = 0
    _NE = 2
    _NQ1 = 6
    _NE1 = 2
    _JAC_SYMBOLIC = 0           # jacobian() differences rhs(): the implicit loops difference it themselves
    _FT_SYMBOLIC = 0            # nor df/dt: jacobian() leaves _ft alone

cdef int _EDIR[_NE1]    # crossing direction of each event: +1 upward, -1 downward
_EDIR[0] = 1  # segment_up
_EDIR[1] = -1  # segment_down



cdef inline void _profile(Ctx* ctx, double th, double beta, double* out) noexcept nogil:
    """R(theta) and its derivatives dR/dtheta^k, k = 1..3, of the rise-dwell-fall-dwell (RDFD)
    motion with the cam law ctx.law[0], period 2 pi: rise on [0, beta), outer dwell to pi,
    fall on [pi, pi + beta), inner dwell to 2 pi."""
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
        camlaw_eval(ctx.law[0], ctx.law_par[0], camlaw_segment(ctx.law[0], ctx.law_par[0], T), T, h)
        if fall:
            s = -1.0
            h[0] -= 1.0
        out[0] = s * h[0]
        out[1] = s * h[1] / beta
        out[2] = s * h[2] / (beta * beta)
        out[3] = s * h[3] / (beta * beta * beta)
    else:
        out[0] = 0.0 if fall else 1.0
        out[1] = 0.0
        out[2] = 0.0
        out[3] = 0.0


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
    cdef double _c4 = (1.0/(d*d*d*d))
    cdef double _c5 = pow(d, -5.0)
    cdef double _c6 = pow(d, -6.0)
    cdef double _c7 = pow(d, -7.0)
    cdef double _c8 = 4.0*m_r
    cdef double _c9 = (d*d*d)
    cdef double _c10 = 5.0*_c3
    cdef double _c11 = 3.0*_c3
    cdef double _c12 = 5.0*_c2
    cdef double _c13 = (d*d)
    cdef double _c14 = 24.0*m_r
    cdef double _c15 = 4.0*_c3
    cdef double _c16 = 9.0*_c2
    cdef double _c17 = 0.5*_c2
    cdef double _c18 = pow(d, -8.0)
    cdef double _c19 = 20.0*m_r
    cdef double _c20 = 8.0*m_r
    cdef double _c21 = 4.0*_c2
    cdef double _c22 = 140.0*m_r
    cdef double _c23 = 20.0*_c3
    cdef double _c24 = pow(d, -9.0)
    cdef double _c25 = 12.0*m_r
    cdef double _c26 = 2.0*_c3
    cdef double _c27 = 3.0*_c2
    cdef double _c28 = pow(d, -10.0)
    cdef double _c29 = 40.0*m_r
    cdef double _c30 = 10.0*_c2
    cdef double _c31 = _c4*_c8
    cdef double _c32 = _c6*m_r
    cdef double _c33 = _c18*m_r
    cdef double _c34 = _c28*m_r
    cdef double _c35 = _c25*_c5
    cdef double _c36 = 16.0*_c32
    cdef double _c37 = _c19*_c7
    cdef double _c38 = _c14*_c7
    cdef double _c39 = 30.0*_c33
    cdef double _c40 = _c24*_c29
    cdef double _c41 = _c3*_c4
    cdef double _c42 = _c3*_c6
    cdef double _c43 = _c18*_c3
    cdef double _c44 = _c28*_c3
    cdef double _c45 = _c2*_c4
    cdef double _c46 = _c11*_c5
    cdef double _c47 = _c27*_c6
    cdef double _c48 = _c15*_c7
    cdef double _c49 = _c10*_c24
    cdef double _c50 = _c3*_c7
    cdef double _c51 = 3.3333333333333335*_c50
    cdef double _c52 = 3.2*_c42
    cdef double _c53 = 4.285714285714286*_c43
    cdef double _c54 = _c18*_c2
    cdef double _c55 = _c2*_c28
    cdef double _c56 = _c27*_c5
    cdef double _c57 = _c21*_c6
    cdef double _c58 = _c12*_c7
    cdef double _c59 = _c16*_c7
    cdef double _c60 = 12.0*_c54
    cdef double _c61 = _c2*_c24
    cdef double _c62 = 20.0*_c61
    cdef double _c63 = (r_b*r_b*r_b*r_b)
    cdef double _c64 = (r_r*r_r*r_r*r_r)
    cdef double _c65 = (r_r*r_r*r_r)
    cdef double _c66 = 4.0*_c65
    cdef double _c67 = (r_b*r_b*r_b)
    cdef double _c68 = 4.0*_c67
    cdef double _c69 = (r_r*r_r)
    cdef double _c70 = (r_b*r_b)
    cdef double _c71 = 6.0*_c70
    cdef double _c72 = (S_T*S_T*S_T*S_T)
    cdef double _c73 = 2.0*_c72
    cdef double _c74 = (S_T*S_T)
    cdef double _c75 = _c74*r_b
    cdef double _c76 = 4.0*r_r
    cdef double _c77 = 2.0*_c74
    cdef double _c78 = 12.0*S_T
    cdef double _c79 = _c69*r_b
    cdef double _c80 = _c70*r_r
    cdef double _c81 = (S_T*S_T*S_T)
    cdef double _c82 = 4.0*_c81
    cdef double _c83 = _c82*r_b
    cdef double _c84 = _c82*r_r
    cdef double _c85 = 12.0*_c75
    cdef double _c86 = _c69*_c74
    cdef double _c87 = J_r*_c72
    cdef double _c88 = 2.0*r_b
    cdef double _c89 = _c88*r_r
    cdef double _c90 = 2.0*S_T
    cdef double _c91 = _c90*r_b
    cdef double _c92 = _c90*r_r
    cdef double _c93 = J_r*_c74
    cdef double _c94 = 2.0*_c93
    cdef double _c95 = _c69*_c93 + _c70*_c93 + _c89*_c93
    cdef double _c96 = J_r*_c73
    cdef double _c97 = J_r*_c81
    cdef double _c98 = _c97*r_r
    cdef double _c99 = _c88*_c97 + 2.0*_c98
    cdef double _c100 = (1.0/_c13)
    cdef double _c101 = (1.0/_c9)
    cdef double _c102 = 2.0*_c100
    cdef double _c103 = 10.0*m_r
    cdef double _c104 = _c5*m_r
    cdef double _c105 = 2.0*m_r
    cdef double _c106 = 3.141592653589793*E*_c0
    cdef double _c107 = _c106*_c4
    cdef double _c108 = _c106*_c6
    cdef double _c109 = _c106*_c7
    cdef double _c110 = 1.5*_c5
    cdef double _c111 = _c3*_c5
    cdef double _c112 = _c2*_c5
    cdef double _c113 = _c2*_c7
    cdef double _c114 = _c106*_c18
    cdef double _c115 = 0.5*_c3
    cdef double _c116 = _c2*_c6
    cdef double _c117 = _c7*m_r
    cdef double _c118 = _c106*_c24
    cdef double _c119 = _c24*_c3
    cdef double _c120 = _c106*_c28
    cdef double _c121 = J_r*S_T
    cdef double _c122 = 6.0*pow(r_r, 5.0)
    cdef double _c123 = 6.0*pow(r_b, 5.0)
    cdef double _c124 = 15.0*_c64
    cdef double _c125 = 20.0*_c67
    cdef double _c126 = 15.0*_c63
    cdef double _c127 = pow(S_T, 6.0)
    cdef double _c128 = 3.0*_c74
    cdef double _c129 = 12.0*_c67
    cdef double _c130 = _c74*r_r
    cdef double _c131 = _c70*_c86
    cdef double _c132 = r_b*r_r
    cdef double _c133 = _c132*_c72
    cdef double _c134 = 3.0*_c72
    cdef double _c135 = 30.0*S_T
    cdef double _c136 = 60.0*S_T
    cdef double _c137 = pow(S_T, 5.0)
    cdef double _c138 = 6.0*_c137
    cdef double _c139 = _c138*r_b
    cdef double _c140 = _c138*r_r
    cdef double _c141 = 15.0*_c72
    cdef double _c142 = _c65*_c81
    cdef double _c143 = 60.0*_c81
    cdef double _c144 = 36.0*_c81
    cdef double _c145 = 12.0*_c137
    cdef double _c146 = 18.0*_c72
    cdef double _c147 = J_r*_c127
    cdef double _c148 = J_r*_c137
    cdef double _c149 = 2.0*r_r
    cdef double _c150 = _c97*r_b
    cdef double _c151 = _c150 + _c98
    cdef double _c152 = _c132*_c87
    cdef double _c153 = 4.0*_c87
    cdef double _c154 = _c148*r_b
    cdef double _c155 = _c148*_c76 + 4.0*_c154
    cdef double _c156 = _c76*r_b
    cdef double _c157 = 6.0*_c69
    cdef double _c158 = (Omega*Omega)
    cdef double _c159 = Omega*_c90
    ctx.k[0] = 0.3333333333333333*_c2  # _k0
    ctx.k[1] = 0.2*_c3  # _k1
    ctx.k[2] = _c4  # _k2
    ctx.k[3] = 0.16666666666666666*_c3  # _k3
    ctx.k[4] = 0.375*_c2  # _k4
    ctx.k[5] = _c5  # _k5
    ctx.k[6] = 0.14285714285714285*_c3  # _k6
    ctx.k[7] = 0.4*_c2  # _k7
    ctx.k[8] = _c6  # _k8
    ctx.k[9] = 0.125*_c3  # _k9
    ctx.k[10] = 0.4166666666666667*_c2  # _k10
    ctx.k[11] = _c7  # _k11
    ctx.k[12] = _c8  # _k12
    ctx.k[13] = _c2  # _k13
    ctx.k[14] = _c3  # _k14
    ctx.k[15] = 0.5*_c9  # _k15
    ctx.k[16] = 35.0*m_r  # _k16
    ctx.k[17] = _c10  # _k17
    ctx.k[18] = 14.0*_c2  # _k18
    ctx.k[19] = 15.0*m_r  # _k19
    ctx.k[20] = _c11  # _k20
    ctx.k[21] = _c12  # _k21
    ctx.k[22] = 0.2*_c13  # _k22
    ctx.k[23] = _c14  # _k23
    ctx.k[24] = _c15  # _k24
    ctx.k[25] = _c16  # _k25
    ctx.k[26] = 0.16666666666666666*d  # _k26
    ctx.k[27] = 0.45*_c2  # _k27
    ctx.k[28] = _c17  # _k28
    ctx.k[29] = 0.1111111111111111*_c3  # _k29
    ctx.k[30] = 0.5357142857142857*_c2  # _k30
    ctx.k[31] = _c18  # _k31
    ctx.k[32] = _c19  # _k32
    ctx.k[33] = 28.0*_c9  # _k33
    ctx.k[34] = _c20  # _k34
    ctx.k[35] = _c21  # _k35
    ctx.k[36] = _c22  # _k36
    ctx.k[37] = _c23  # _k37
    ctx.k[38] = 63.0*_c2  # _k38
    ctx.k[39] = 8.0*d  # _k39
    ctx.k[40] = 35.0*_c13  # _k40
    ctx.k[41] = 0.0035714285714285713*_c18  # _k41
    ctx.k[42] = 0.5714285714285714*_c2  # _k42
    ctx.k[43] = 0.1*_c3  # _k43
    ctx.k[44] = 0.625*_c2  # _k44
    ctx.k[45] = _c24  # _k45
    ctx.k[46] = 63.0*m_r  # _k46
    ctx.k[47] = 7.0*_c3  # _k47
    ctx.k[48] = 36.0*_c2  # _k48
    ctx.k[49] = _c25  # _k49
    ctx.k[50] = _c26  # _k50
    ctx.k[51] = _c27  # _k51
    ctx.k[52] = 105.0*_c9  # _k52
    ctx.k[53] = 54.0*_c13  # _k53
    ctx.k[54] = 315.0*d  # _k54
    ctx.k[55] = 0.0015873015873015873*_c24  # _k55
    ctx.k[56] = 0.09090909090909091*_c3  # _k56
    ctx.k[57] = 0.6944444444444444*_c2  # _k57
    ctx.k[58] = _c28  # _k58
    ctx.k[59] = _c29  # _k59
    ctx.k[60] = 25.0*_c2  # _k60
    ctx.k[61] = 28.0*m_r  # _k61
    ctx.k[62] = 7.0*_c2  # _k62
    ctx.k[63] = 0.07142857142857142*_c9  # _k63
    ctx.k[64] = _c30  # _k64
    ctx.k[65] = 0.125*_c13  # _k65
    ctx.k[66] = 252.0*m_r  # _k66
    ctx.k[67] = 28.0*_c3  # _k67
    ctx.k[68] = 135.0*_c2  # _k68
    ctx.k[69] = 0.015873015873015872*d  # _k69
    ctx.k[70] = L_g*_c3 + m_r  # _k70
    ctx.k[71] = _c31  # _k71
    ctx.k[72] = 9.0*_c32  # _k72
    ctx.k[73] = 16.0*_c33  # _k73
    ctx.k[74] = 25.0*_c34  # _k74
    ctx.k[75] = _c35  # _k75
    ctx.k[76] = _c36  # _k76
    ctx.k[77] = _c37  # _k77
    ctx.k[78] = _c38  # _k78
    ctx.k[79] = _c39  # _k79
    ctx.k[80] = _c40  # _k80
    ctx.k[81] = 1.3333333333333333*_c41  # _k81
    ctx.k[82] = 1.8*_c42  # _k82
    ctx.k[83] = 2.2857142857142856*_c43  # _k83
    ctx.k[84] = 2.7777777777777777*_c44  # _k84
    ctx.k[85] = _c45  # _k85
    ctx.k[86] = _c46  # _k86
    ctx.k[87] = _c47  # _k87
    ctx.k[88] = _c48  # _k88
    ctx.k[89] = _c49  # _k89
    ctx.k[90] = _c51  # _k90
    ctx.k[91] = _c52  # _k91
    ctx.k[92] = _c53  # _k92
    ctx.k[93] = 7.2*_c54  # _k93
    ctx.k[94] = 14.285714285714286*_c55  # _k94
    ctx.k[95] = _c56  # _k95
    ctx.k[96] = _c57  # _k96
    ctx.k[97] = _c58  # _k97
    ctx.k[98] = _c59  # _k98
    ctx.k[99] = _c60  # _k99
    ctx.k[100] = _c62  # _k100
    ctx.k[101] = _c63 + _c64 + _c66*r_b + _c68*r_r + _c69*_c71  # _k101
    ctx.k[102] = _c72  # _k102
    ctx.k[103] = _c73  # _k103
    ctx.k[104] = _c69*_c77 + _c70*_c77 + _c75*_c76  # _k104
    ctx.k[105] = S_T*_c66 + S_T*_c68 + _c78*_c79 + _c78*_c80  # _k105
    ctx.k[106] = _c83 + _c84  # _k106
    ctx.k[107] = _c71*_c74 + _c85*r_r + 6.0*_c86  # _k107
    ctx.k[108] = _c87  # _k108
    ctx.k[109] = _c69 + _c70 + _c89  # _k109
    ctx.k[110] = _c74  # _k110
    ctx.k[111] = _c91 + _c92  # _k111
    ctx.k[112] = _c94  # _k112
    ctx.k[113] = _c95  # _k113
    ctx.k[114] = -_c94  # _k114
    ctx.k[115] = -J_r*_c91 - J_r*_c92  # _k115
    ctx.k[116] = -_c96  # _k116
    ctx.k[117] = -_c99  # _k117
    ctx.k[118] = _c99  # _k118
    ctx.k[119] = -_c100  # _k119
    ctx.k[120] = -_c101  # _k120
    ctx.k[121] = -_c4  # _k121
    ctx.k[122] = -_c5  # _k122
    ctx.k[123] = -5.0*_c5  # _k123
    ctx.k[124] = -4.0*_c4  # _k124
    ctx.k[125] = -3.0*_c101  # _k125
    ctx.k[126] = -_c102  # _k126
    ctx.k[127] = r_b + r_r  # _k127
    ctx.k[128] = -_c37  # _k128
    ctx.k[129] = -_c25*_c6  # _k129
    ctx.k[130] = -_c103*_c7  # _k130
    ctx.k[131] = -_c20*_c6  # _k131
    ctx.k[132] = -6.0*_c104  # _k132
    ctx.k[133] = -_c31  # _k133
    ctx.k[134] = -_c105*_c4  # _k134
    ctx.k[135] = -_c107  # _k135
    ctx.k[136] = -2.0*_c108  # _k136
    ctx.k[137] = -2.5*_c109  # _k137
    ctx.k[138] = -_c106*_c110  # _k138
    ctx.k[139] = -_c41  # _k139
    ctx.k[140] = -2.4*_c42  # _k140
    ctx.k[141] = -_c51  # _k141
    ctx.k[142] = -1.4285714285714286*_c50  # _k142
    ctx.k[143] = -1.2*_c111  # _k143
    ctx.k[144] = -1.3333333333333333*_c42  # _k144
    ctx.k[145] = -_c110*_c3  # _k145
    ctx.k[146] = -0.6666666666666666*_c41  # _k146
    ctx.k[147] = -_c45  # _k147
    ctx.k[148] = -_c57  # _k148
    ctx.k[149] = -_c21*_c7  # _k149
    ctx.k[150] = -_c47  # _k150
    ctx.k[151] = -2.0*_c112  # _k151
    ctx.k[152] = -7.5*_c113  # _k152
    ctx.k[153] = -_c110*_c2  # _k153
    ctx.k[154] = -_c18*_c19  # _k154
    ctx.k[155] = -_c25*_c7  # _k155
    ctx.k[156] = -10.0*_c33  # _k156
    ctx.k[157] = -_c20*_c7  # _k157
    ctx.k[158] = -6.0*_c32  # _k158
    ctx.k[159] = -_c5*_c8  # _k159
    ctx.k[160] = -2.0*_c104  # _k160
    ctx.k[161] = -6.0*_c114  # _k161
    ctx.k[162] = -3.0*_c108  # _k162
    ctx.k[163] = -4.5*_c109  # _k163
    ctx.k[164] = -_c42  # _k164
    ctx.k[165] = -_c26*_c7  # _k165
    ctx.k[166] = -2.857142857142857*_c43  # _k166
    ctx.k[167] = -1.1428571428571428*_c50  # _k167
    ctx.k[168] = -1.2*_c42  # _k168
    ctx.k[169] = -1.25*_c43  # _k169
    ctx.k[170] = -0.8*_c111  # _k170
    ctx.k[171] = -_c115*_c5  # _k171
    ctx.k[172] = -_c112  # _k172
    ctx.k[173] = -_c16*_c18  # _k173
    ctx.k[174] = -_c12*_c18  # _k174
    ctx.k[175] = -3.6*_c113  # _k175
    ctx.k[176] = -4.5*_c113  # _k176
    ctx.k[177] = -2.25*_c116  # _k177
    ctx.k[178] = -1.5*_c116  # _k178
    ctx.k[179] = -_c19*_c24  # _k179
    ctx.k[180] = -_c18*_c25  # _k180
    ctx.k[181] = -_c103*_c24  # _k181
    ctx.k[182] = -_c18*_c20  # _k182
    ctx.k[183] = -6.0*_c117  # _k183
    ctx.k[184] = -_c6*_c8  # _k184
    ctx.k[185] = -2.0*_c32  # _k185
    ctx.k[186] = -10.0*_c118  # _k186
    ctx.k[187] = -7.2*_c114  # _k187
    ctx.k[188] = -_c50  # _k188
    ctx.k[189] = -_c43  # _k189
    ctx.k[190] = -1.7142857142857142*_c43  # _k190
    ctx.k[191] = -1.1111111111111112*_c119  # _k191
    ctx.k[192] = -0.8571428571428571*_c50  # _k192
    ctx.k[193] = -2.5*_c119  # _k193
    ctx.k[194] = -0.6666666666666666*_c42  # _k194
    ctx.k[195] = -0.4*_c42  # _k195
    ctx.k[196] = -_c116  # _k196
    ctx.k[197] = -_c24*_c30  # _k197
    ctx.k[198] = -_c18*_c21  # _k198
    ctx.k[199] = -5.714285714285714*_c61  # _k199
    ctx.k[200] = -4.8*_c54  # _k200
    ctx.k[201] = -2.4*_c113  # _k201
    ctx.k[202] = -1.5*_c113  # _k202
    ctx.k[203] = -_c19*_c28  # _k203
    ctx.k[204] = -_c24*_c25  # _k204
    ctx.k[205] = -10.0*_c34  # _k205
    ctx.k[206] = -_c20*_c24  # _k206
    ctx.k[207] = -6.0*_c33  # _k207
    ctx.k[208] = -_c7*_c8  # _k208
    ctx.k[209] = -_c105*_c7  # _k209
    ctx.k[210] = -14.285714285714286*_c120  # _k210
    ctx.k[211] = -_c44  # _k211
    ctx.k[212] = -2.2222222222222223*_c44  # _k212
    ctx.k[213] = -0.8888888888888888*_c119  # _k213
    ctx.k[214] = -0.8571428571428571*_c43  # _k214
    ctx.k[215] = -0.5714285714285714*_c50  # _k215
    ctx.k[216] = -1.5*_c119  # _k216
    ctx.k[217] = -0.75*_c43  # _k217
    ctx.k[218] = -0.3333333333333333*_c50  # _k218
    ctx.k[219] = -_c113  # _k219
    ctx.k[220] = -_c12*_c24  # _k220
    ctx.k[221] = -10.714285714285714*_c55  # _k221
    ctx.k[222] = -4.285714285714286*_c61  # _k222
    ctx.k[223] = -6.25*_c55  # _k223
    ctx.k[224] = -2.5*_c54  # _k224
    ctx.k[225] = -1.5*_c54  # _k225
    ctx.k[226] = -_c115  # _k226
    ctx.k[227] = -100.0*_c34  # _k227
    ctx.k[228] = -48.0*_c33  # _k228
    ctx.k[229] = -18.0*_c32  # _k229
    ctx.k[230] = -0.5*_c107  # _k230
    ctx.k[231] = -_c22*_c24  # _k231
    ctx.k[232] = -90.0*_c33  # _k232
    ctx.k[233] = -60.0*_c117  # _k233
    ctx.k[234] = -50.0*_c120  # _k234
    ctx.k[235] = -50.0*_c117  # _k235
    ctx.k[236] = -50.0*_c34  # _k236
    ctx.k[237] = -_c40  # _k237
    ctx.k[238] = -32.0*_c32  # _k238
    ctx.k[239] = -32.0*_c33  # _k239
    ctx.k[240] = -_c39  # _k240
    ctx.k[241] = -_c38  # _k241
    ctx.k[242] = -18.0*_c114  # _k242
    ctx.k[243] = -18.0*_c104  # _k243
    ctx.k[244] = -_c36  # _k244
    ctx.k[245] = -_c35  # _k245
    ctx.k[246] = -_c20*_c4  # _k246
    ctx.k[247] = -4.5*_c108  # _k247
    ctx.k[248] = -60.0*_c118  # _k248
    ctx.k[249] = -30.0*_c114  # _k249
    ctx.k[250] = -18.0*_c109  # _k250
    ctx.k[251] = -10.0*_c109  # _k251
    ctx.k[252] = -8.0*_c43  # _k252
    ctx.k[253] = -6.0*_c108  # _k253
    ctx.k[254] = -3.0*_c106*_c5  # _k254
    ctx.k[255] = -_c26*_c4  # _k255
    ctx.k[256] = -12.5*_c44  # _k256
    ctx.k[257] = -4.5*_c42  # _k257
    ctx.k[258] = -_c17*_c4  # _k258
    ctx.k[259] = -50.0*_c55  # _k259
    ctx.k[260] = -_c23*_c24  # _k260
    ctx.k[261] = -18.0*_c54  # _k261
    ctx.k[262] = -15.0*_c43  # _k262
    ctx.k[263] = -12.0*_c50  # _k263
    ctx.k[264] = -10.0*_c50  # _k264
    ctx.k[265] = -8.0*_c42  # _k265
    ctx.k[266] = -6.0*_c111  # _k266
    ctx.k[267] = -_c49  # _k267
    ctx.k[268] = -_c48  # _k268
    ctx.k[269] = -_c46  # _k269
    ctx.k[270] = -5.555555555555555*_c44  # _k270
    ctx.k[271] = -4.571428571428571*_c43  # _k271
    ctx.k[272] = -_c53  # _k272
    ctx.k[273] = -3.6*_c42  # _k273
    ctx.k[274] = -_c52  # _k274
    ctx.k[275] = -4.5*_c116  # _k275
    ctx.k[276] = -2.6666666666666665*_c41  # _k276
    ctx.k[277] = -60.0*_c61  # _k277
    ctx.k[278] = -30.0*_c54  # _k278
    ctx.k[279] = -_c62  # _k279
    ctx.k[280] = -18.0*_c113  # _k280
    ctx.k[281] = -_c60  # _k281
    ctx.k[282] = -_c30*_c7  # _k282
    ctx.k[283] = -_c59  # _k283
    ctx.k[284] = -6.0*_c116  # _k284
    ctx.k[285] = -_c58  # _k285
    ctx.k[286] = -_c56  # _k286
    ctx.k[287] = -2.0*_c45  # _k287
    ctx.k[288] = -28.571428571428573*_c55  # _k288
    ctx.k[289] = -14.4*_c54  # _k289
    ctx.k[290] = _c93  # _k290
    ctx.k[291] = _c121*r_b + _c121*r_r  # _k291
    ctx.k[292] = -_c93  # _k292
    ctx.k[293] = _c96  # _k293
    ctx.k[294] = _c122*r_b + _c123*r_r + _c124*_c70 + _c125*_c65 + _c126*_c69 + pow(r_b, 6.0) + pow(r_r, 6.0)  # _k294
    ctx.k[295] = _c127  # _k295
    ctx.k[296] = 3.0*_c127  # _k296
    ctx.k[297] = _c128*_c63 + _c128*_c64 + _c129*_c130 + 18.0*_c131 + _c65*_c85  # _k297
    ctx.k[298] = 6.0*_c133 + _c134*_c69 + _c134*_c70  # _k298
    ctx.k[299] = S_T*_c122 + S_T*_c123 + _c135*_c63*r_r + _c135*_c64*r_b + _c136*_c65*_c70 + _c136*_c67*_c69  # _k299
    ctx.k[300] = _c139 + _c140  # _k300
    ctx.k[301] = _c124*_c74 + _c126*_c74 + 60.0*_c130*_c67 + 90.0*_c131 + 60.0*_c65*_c75  # _k301
    ctx.k[302] = 30.0*_c133 + _c141*_c69 + _c141*_c70  # _k302
    ctx.k[303] = _c125*_c81 + 20.0*_c142 + _c143*_c79 + _c143*_c80  # _k303
    ctx.k[304] = _c129*_c81 + 12.0*_c142 + _c144*_c79 + _c144*_c80  # _k304
    ctx.k[305] = _c145*r_b + _c145*r_r  # _k305
    ctx.k[306] = 36.0*_c133 + _c146*_c69 + _c146*_c70  # _k306
    ctx.k[307] = 2.0*_c147  # _k307
    ctx.k[308] = _c148*_c149 + _c148*_c88  # _k308
    ctx.k[309] = _c151  # _k309
    ctx.k[310] = -_c87  # _k310
    ctx.k[311] = -_c151  # _k311
    ctx.k[312] = -_c95  # _k312
    ctx.k[313] = -4.0*_c147  # _k313
    ctx.k[314] = -8.0*_c152 - _c153*_c69 - _c153*_c70  # _k314
    ctx.k[315] = -_c155  # _k315
    ctx.k[316] = -_c156*_c93 - _c69*_c94 - _c70*_c94  # _k316
    ctx.k[317] = 2.0*J_r*_c142 + _c150*_c157 + 2.0*_c67*_c97 + _c71*_c98  # _k317
    ctx.k[318] = _c156*_c87 + _c69*_c96 + _c70*_c96  # _k318
    ctx.k[319] = -8.0*_c148*r_r - 8.0*_c154  # _k319
    ctx.k[320] = -J_r*_c83 - J_r*_c84  # _k320
    ctx.k[321] = _c155  # _k321
    ctx.k[322] = 12.0*_c152 + _c157*_c87 + _c71*_c87  # _k322
    ctx.k[323] = J_r*_c139 + J_r*_c140  # _k323
    ctx.k[324] = _c158*r_b + _c158*r_r  # _k324
    ctx.k[325] = _c102  # _k325
    ctx.k[326] = S_T*_c158  # _k326
    ctx.k[327] = -S_T  # _k327
    ctx.k[328] = -Omega*_c149 - Omega*_c88  # _k328
    ctx.k[329] = _c90  # _k329
    ctx.k[330] = 4.0*_c100  # _k330
    ctx.k[331] = 6.0*_c101  # _k331
    ctx.k[332] = 8.0*_c4  # _k332
    ctx.k[333] = 10.0*_c5  # _k333
    ctx.k[334] = 12.0*_c4  # _k334
    ctx.k[335] = 20.0*_c5  # _k335
    ctx.k[336] = -_c159  # _k336
    ctx.k[337] = -_c90  # _k337
    ctx.k[338] = _c159  # _k338
    ctx.k[339] = -d  # _k339
    ctx.k[340] = -Omega  # _k340
    ctx.k[341] = _c100  # _k341
    ctx.k[342] = _c101  # _k342


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
    cdef double _k189 = ctx.k[189]
    cdef double _k190 = ctx.k[190]
    cdef double _k191 = ctx.k[191]
    cdef double _k192 = ctx.k[192]
    cdef double _k193 = ctx.k[193]
    cdef double _k194 = ctx.k[194]
    cdef double _k195 = ctx.k[195]
    cdef double _k196 = ctx.k[196]
    cdef double _k197 = ctx.k[197]
    cdef double _k198 = ctx.k[198]
    cdef double _k199 = ctx.k[199]
    cdef double _k200 = ctx.k[200]
    cdef double _k201 = ctx.k[201]
    cdef double _k202 = ctx.k[202]
    cdef double _k203 = ctx.k[203]
    cdef double _k204 = ctx.k[204]
    cdef double _k205 = ctx.k[205]
    cdef double _k206 = ctx.k[206]
    cdef double _k207 = ctx.k[207]
    cdef double _k208 = ctx.k[208]
    cdef double _k209 = ctx.k[209]
    cdef double _k210 = ctx.k[210]
    cdef double _k211 = ctx.k[211]
    cdef double _k212 = ctx.k[212]
    cdef double _k213 = ctx.k[213]
    cdef double _k214 = ctx.k[214]
    cdef double _k215 = ctx.k[215]
    cdef double _k216 = ctx.k[216]
    cdef double _k217 = ctx.k[217]
    cdef double _k218 = ctx.k[218]
    cdef double _k219 = ctx.k[219]
    cdef double _k220 = ctx.k[220]
    cdef double _k221 = ctx.k[221]
    cdef double _k222 = ctx.k[222]
    cdef double _k223 = ctx.k[223]
    cdef double _k224 = ctx.k[224]
    cdef double _k225 = ctx.k[225]
    cdef double _k226 = ctx.k[226]
    cdef double _k227 = ctx.k[227]
    cdef double _k228 = ctx.k[228]
    cdef double _k229 = ctx.k[229]
    cdef double _k230 = ctx.k[230]
    cdef double _k231 = ctx.k[231]
    cdef double _k232 = ctx.k[232]
    cdef double _k233 = ctx.k[233]
    cdef double _k234 = ctx.k[234]
    cdef double _k235 = ctx.k[235]
    cdef double _k236 = ctx.k[236]
    cdef double _k237 = ctx.k[237]
    cdef double _k238 = ctx.k[238]
    cdef double _k239 = ctx.k[239]
    cdef double _k240 = ctx.k[240]
    cdef double _k241 = ctx.k[241]
    cdef double _k242 = ctx.k[242]
    cdef double _k243 = ctx.k[243]
    cdef double _k244 = ctx.k[244]
    cdef double _k245 = ctx.k[245]
    cdef double _k246 = ctx.k[246]
    cdef double _k247 = ctx.k[247]
    cdef double _k248 = ctx.k[248]
    cdef double _k249 = ctx.k[249]
    cdef double _k250 = ctx.k[250]
    cdef double _k251 = ctx.k[251]
    cdef double _k252 = ctx.k[252]
    cdef double _k253 = ctx.k[253]
    cdef double _k254 = ctx.k[254]
    cdef double _k255 = ctx.k[255]
    cdef double _k256 = ctx.k[256]
    cdef double _k257 = ctx.k[257]
    cdef double _k258 = ctx.k[258]
    cdef double _k259 = ctx.k[259]
    cdef double _k260 = ctx.k[260]
    cdef double _k261 = ctx.k[261]
    cdef double _k262 = ctx.k[262]
    cdef double _k263 = ctx.k[263]
    cdef double _k264 = ctx.k[264]
    cdef double _k265 = ctx.k[265]
    cdef double _k266 = ctx.k[266]
    cdef double _k267 = ctx.k[267]
    cdef double _k268 = ctx.k[268]
    cdef double _k269 = ctx.k[269]
    cdef double _k270 = ctx.k[270]
    cdef double _k271 = ctx.k[271]
    cdef double _k272 = ctx.k[272]
    cdef double _k273 = ctx.k[273]
    cdef double _k274 = ctx.k[274]
    cdef double _k275 = ctx.k[275]
    cdef double _k276 = ctx.k[276]
    cdef double _k277 = ctx.k[277]
    cdef double _k278 = ctx.k[278]
    cdef double _k279 = ctx.k[279]
    cdef double _k280 = ctx.k[280]
    cdef double _k281 = ctx.k[281]
    cdef double _k282 = ctx.k[282]
    cdef double _k283 = ctx.k[283]
    cdef double _k284 = ctx.k[284]
    cdef double _k285 = ctx.k[285]
    cdef double _k286 = ctx.k[286]
    cdef double _k287 = ctx.k[287]
    cdef double _k288 = ctx.k[288]
    cdef double _k289 = ctx.k[289]
    cdef double _k290 = ctx.k[290]
    cdef double _k291 = ctx.k[291]
    cdef double _k292 = ctx.k[292]
    cdef double _k293 = ctx.k[293]
    cdef double _k294 = ctx.k[294]
    cdef double _k295 = ctx.k[295]
    cdef double _k296 = ctx.k[296]
    cdef double _k297 = ctx.k[297]
    cdef double _k298 = ctx.k[298]
    cdef double _k299 = ctx.k[299]
    cdef double _k300 = ctx.k[300]
    cdef double _k301 = ctx.k[301]
    cdef double _k302 = ctx.k[302]
    cdef double _k303 = ctx.k[303]
    cdef double _k304 = ctx.k[304]
    cdef double _k305 = ctx.k[305]
    cdef double _k306 = ctx.k[306]
    cdef double _k307 = ctx.k[307]
    cdef double _k308 = ctx.k[308]
    cdef double _k309 = ctx.k[309]
    cdef double _k310 = ctx.k[310]
    cdef double _k311 = ctx.k[311]
    cdef double _k312 = ctx.k[312]
    cdef double _k313 = ctx.k[313]
    cdef double _k314 = ctx.k[314]
    cdef double _k315 = ctx.k[315]
    cdef double _k316 = ctx.k[316]
    cdef double _k317 = ctx.k[317]
    cdef double _k318 = ctx.k[318]
    cdef double _k319 = ctx.k[319]
    cdef double _k320 = ctx.k[320]
    cdef double _k321 = ctx.k[321]
    cdef double _k322 = ctx.k[322]
    cdef double _k323 = ctx.k[323]
    cdef double _k324 = ctx.k[324]
    cdef double _k325 = ctx.k[325]
    cdef double _k326 = ctx.k[326]
    cdef double _k327 = ctx.k[327]
    cdef double _k328 = ctx.k[328]
    cdef double _k329 = ctx.k[329]
    cdef double _k330 = ctx.k[330]
    cdef double _k331 = ctx.k[331]
    cdef double _k332 = ctx.k[332]
    cdef double _k333 = ctx.k[333]
    cdef double _k334 = ctx.k[334]
    cdef double _k335 = ctx.k[335]
    cdef double _k336 = ctx.k[336]
    cdef double _k337 = ctx.k[337]
    cdef double _k338 = ctx.k[338]
    cdef double _k339 = ctx.k[339]
    cdef double _k340 = ctx.k[340]
    cdef double _k341 = ctx.k[341]
    cdef double _k342 = ctx.k[342]
    cdef double b1 = _y[0]
    cdef double b2 = _y[1]
    cdef double b3 = _y[2]
    cdef double b4 = _y[3]
    cdef double xE = _y[4]
    cdef double theta = _y[5]
    cdef double b1d = _y[6]
    cdef double b2d = _y[7]
    cdef double b3d = _y[8]
    cdef double b4d = _y[9]
    cdef double xEd = _y[10]
    cdef double thetad = _y[11]
    cdef double _cam0[4]
    _profile(ctx, theta, beta_r, _cam0)

    cdef double _s0 = (xE*xE*xE)
    cdef double _s1 = m_r*xE
    cdef double _s2 = (xE*xE)
    cdef double _s3 = (xE*xE*xE*xE)
    cdef double _s4 = _k5*_s3*(_k3*_s2 + _k4 + _s1)
    cdef double _s5 = _k6*_s2 + _s1
    cdef double _s6 = pow(xE, 5.0)
    cdef double _s7 = _k8*_s6
    cdef double _s8 = _s7*(_k7 + _s5)
    cdef double _s9 = _k9*_s2 + _s1
    cdef double _s10 = pow(xE, 6.0)
    cdef double _s11 = _k11*_s10
    cdef double _s12 = _s11*(_k10 + _s9)
    cdef double _s13 = _k14*_s2
    cdef double _s14 = _k20*_s2
    cdef double _s15 = b2*xE
    cdef double _s16 = _k16*xE + _k17*_s2 + _k18
    cdef double _s17 = _s0*b4
    cdef double _s18 = _k23*xE
    cdef double _s19 = _k24*_s2
    cdef double _s20 = _k25 + _s18 + _s19
    cdef double _s21 = _s2*b3
    cdef double _s22 = _k11*_s2*(_k15*b1*(_k12*xE + _k13 + _s13) + _k22*_s15*(_k19*xE + _k21 + _s14) + _k26*_s20*_s21 + 0.14285714285714285*_s16*_s17)
    cdef double _s23 = _s11*(_k28 + _s9)
    cdef double _s24 = _k29*_s2 + _s1
    cdef double _s25 = pow(xE, 7.0)
    cdef double _s26 = _k31*_s25
    cdef double _s27 = _s26*(_k30 + _s24)
    cdef double _s28 = _k34*xE + _k35 + _s13
    cdef double _s29 = _k41*_s0*(_k33*b1*(_k21 + _k32*xE + _s19) + _k39*_s21*(_k36*xE + _k37*_s2 + _k38) + _k40*_s15*_s20 + 175.0*_s17*_s28)
    cdef double _s30 = pow(xE, 8.0)
    cdef double _s31 = _k45*_s30*(_k43*_s2 + _k44 + _s1)
    cdef double _s32 = _k55*_s3*(_k52*b1*(_k49*xE + _k50*_s2 + _k51) + _k53*_s15*_s16 + _k54*_s21*_s28 + 50.0*_s17*(_k46*xE + _k47*_s2 + _k48))
    cdef double _s33 = pow(xE, 9.0)
    cdef double _s34 = _k58*_s6*(_k63*b1*(_k61*xE + _k62 + _s19) + _k65*_s15*(_k64 + _s14 + _s18) + _k69*_s21*(_k66*xE + _k67*_s2 + _k68) + 0.125*_s17*(_k59*xE + _k60 + _s19))
    cdef double _s35 = (b1*b1)
    cdef double _s36 = _s35*xE
    cdef double _s37 = _s10*b4
    cdef double _s38 = _s37*b3
    cdef double _s39 = _s0*b2
    cdef double _s40 = _s3*b1
    cdef double _s41 = _s40*b3
    cdef double _s42 = _s6*b4
    cdef double _s43 = _s6*b3
    cdef double _s44 = _s43*b2
    cdef double _s45 = _s37*b2
    cdef double _s46 = _s25*b4
    cdef double _s47 = _s46*b3
    cdef double _s48 = b2*b3
    cdef double _s49 = _s30*b4
    cdef double _s50 = _s2*b2
    cdef double _s51 = _s0*b3
    cdef double _s52 = _s3*b4
    cdef double _s53 = _s3*_s48
    cdef double _s54 = _s42*b2
    cdef double _s55 = _s2*_s35
    cdef double _s56 = (b2*b2)
    cdef double _s57 = _s3*_s56
    cdef double _s58 = (b3*b3)
    cdef double _s59 = _s10*_s58
    cdef double _s60 = (b4*b4)
    cdef double _s61 = _s30*_s60
    cdef double _s62 = _s0*_s56
    cdef double _s63 = _s58*_s6
    cdef double _s64 = _s25*_s60
    cdef double _s65 = (_cam0[0]*_cam0[0])
    cdef double _s66 = (_cam0[1]*_cam0[1])
    cdef double _s67 = (1.0/(_cam0[0]*_k111 + _k109 + _k110*_s65 + _k110*_s66))
    cdef double _s68 = _cam0[2]*_s67
    cdef double _s69 = (_cam0[1]*_cam0[1]*_cam0[1]*_cam0[1])
    cdef double _s70 = (_cam0[0]*_cam0[0]*_cam0[0])
    cdef double _s71 = (_cam0[0]*_cam0[0]*_cam0[0]*_cam0[0])
    cdef double _s72 = _cam0[0]*_s66
    cdef double _s73 = _s65*_s66
    cdef double _s74 = (1.0/(_cam0[0]*_k105 + _k101 + _k102*_s69 + _k102*_s71 + _k103*_s73 + _k104*_s66 + _k106*_s70 + _k106*_s72 + _k107*_s65))
    cdef double _s75 = _k108*_s74
    cdef double _s76 = (_cam0[2]*_cam0[2])
    cdef double _s77 = _s74*_s76
    cdef double _s78 = _cam0[0]*_s77
    cdef double _s79 = _cam0[2]*_s74
    cdef double _s80 = _k117*_s79
    cdef double _s81 = _k116*_s79
    cdef double _s82 = _s65*_s76
    cdef double _s83 = _k119*_s2
    cdef double _s84 = _k120*_s0
    cdef double _s85 = _k121*_s3
    cdef double _s86 = _k122*_s6
    cdef double _s87 = b1*xE
    cdef double _s88 = Omega*t - theta
    cdef double _s89 = sin(_s88)
    cdef double _s90 = S_T*_cam0[1]
    cdef double _s91 = S_T*_cam0[0]
    cdef double _s92 = _k127 + _s91
    cdef double _s93 = cos(_s88)
    cdef double _s94 = _s92*_s93
    cdef double _s95 = _s89*_s92
    cdef double _s96 = b4d*xEd
    cdef double _s97 = _s10*_s96
    cdef double _s98 = _s6*xEd
    cdef double _s99 = _s98*b3d
    cdef double _s100 = _s3*xEd
    cdef double _s101 = _s100*b2d
    cdef double _s102 = b1d*xEd
    cdef double _s103 = _s0*_s102
    cdef double _s104 = _s100*b1d
    cdef double _s105 = _s25*_s96
    cdef double _s106 = _s98*b2d
    cdef double _s107 = _s10*xEd
    cdef double _s108 = _s107*b3d
    cdef double _s109 = _s6*_s96
    cdef double _s110 = _s100*b3d
    cdef double _s111 = b2d*xEd
    cdef double _s112 = (xEd*xEd)
    cdef double _s113 = _s112*_s42
    cdef double _s114 = _s112*_s3
    cdef double _s115 = _s114*b3
    cdef double _s116 = _s112*_s39
    cdef double _s117 = _s2*b1
    cdef double _s118 = _s112*_s117
    cdef double _s119 = _s112*_s43
    cdef double _s120 = _s112*_s37
    cdef double _s121 = _s114*b2
    cdef double _s122 = _s0*b1
    cdef double _s123 = _s112*_s122
    cdef double _s124 = _k148*_s51
    cdef double _s125 = _s112*_s52
    cdef double _s126 = _k161*_s6
    cdef double _s127 = _k163*_s3
    cdef double _s128 = _s107*b2d
    cdef double _s129 = b3d*xEd
    cdef double _s130 = _s129*_s25
    cdef double _s131 = _s30*_s96
    cdef double _s132 = _s98*b1d
    cdef double _s133 = _s10*_s112
    cdef double _s134 = _s133*b3
    cdef double _s135 = _s112*_s46
    cdef double _s136 = _s112*b2
    cdef double _s137 = _s136*_s6
    cdef double _s138 = _s112*_s40
    cdef double _s139 = _k186*_s10
    cdef double _s140 = _s129*_s30
    cdef double _s141 = _s33*_s96
    cdef double _s142 = _s111*_s25
    cdef double _s143 = _s10*_s102
    cdef double _s144 = _s133*b2
    cdef double _s145 = _s112*b3
    cdef double _s146 = _s145*_s25
    cdef double _s147 = _s112*_s49
    cdef double _s148 = _s112*b1
    cdef double _s149 = _s148*_s6
    cdef double _s150 = _s10*_s60
    cdef double _s151 = _s3*_s58
    cdef double _s152 = _s2*_s56
    cdef double _s153 = (thetad*thetad)
    cdef double _s154 = _cam0[3]*_s153
    cdef double _s155 = _s154*_s67
    cdef double _s156 = _cam0[1]*_s153
    cdef double _s157 = _s156*_s79
    cdef double _s158 = _s154*_s79
    cdef double _s159 = (_cam0[1]*_cam0[1]*_cam0[1])*_s153
    cdef double _s160 = _s159*_s74
    cdef double _s161 = _cam0[2]*_s159
    cdef double _s162 = (1.0/(pow(_cam0[0], 6.0)*_k295 + pow(_cam0[0], 5.0)*_k300 + _cam0[0]*_k299 + _cam0[0]*_k300*_s69 + pow(_cam0[1], 6.0)*_k295 + _k294 + _k296*_s65*_s69 + _k296*_s66*_s71 + _k297*_s66 + _k298*_s69 + _k301*_s65 + _k302*_s71 + _k303*_s70 + _k304*_s72 + _k305*_s66*_s70 + _k306*_s73))
    cdef double _s163 = _s153*_s162
    cdef double _s164 = pow(_cam0[1], 5.0)*_s163
    cdef double _s165 = _k307*_s164
    cdef double _s166 = _cam0[1]*_s163
    cdef double _s167 = _s166*_s76
    cdef double _s168 = (_cam0[2]*_cam0[2]*_cam0[2])*_s166
    cdef double _s169 = _s161*_s162
    cdef double _s170 = _s159*_s162*_s76
    cdef double _s171 = _cam0[0]*_k326
    cdef double _s172 = _k328*thetad
    cdef double _s173 = _k336*thetad
    cdef double _s174 = _cam0[0]*_s173
    cdef double _s175 = _cam0[1]*_s93
    cdef double _s176 = _k127*_s153
    cdef double _s177 = _s153*_s89
    cdef double _s178 = _cam0[2]*_k327
    cdef double _s179 = _s153*_s93
    _A[0] = _k2*_s0*(_k0 + _k1*_s2 + _s1)
    _A[1] = _s4
    _A[2] = _s8
    _A[3] = _s12
    _A[4] = _s22
    _A[5] = 0.0
    _A[6] = _s83
    _A[7] = 0.0
    _A[8] = _s4
    _A[9] = _s7*(_k27 + _s5)
    _A[10] = _s23
    _A[11] = _s27
    _A[12] = _s29
    _A[13] = 0.0
    _A[14] = _s84
    _A[15] = 0.0
    _A[16] = _s8
    _A[17] = _s23
    _A[18] = _s26*(_k42 + _s24)
    _A[19] = _s31
    _A[20] = _s32
    _A[21] = 0.0
    _A[22] = _s85
    _A[23] = 0.0
    _A[24] = _s12
    _A[25] = _s27
    _A[26] = _s31
    _A[27] = _k58*_s33*(_k56*_s2 + _k57 + _s1)
    _A[28] = _s34
    _A[29] = 0.0
    _A[30] = _s86
    _A[31] = 0.0
    _A[32] = _s22
    _A[33] = _s29
    _A[34] = _s32
    _A[35] = _s34
    _A[36] = _k100*_s38 + _k14*xE + _k70 + _k71*_s55 + _k72*_s57 + _k73*_s59 + _k74*_s61 + _k75*_s39*b1 + _k76*_s41 + _k77*_s42*b1 + _k78*_s44 + _k79*_s45 + _k80*_s47 + _k81*_s0*_s35 + _k82*_s56*_s6 + _k83*_s25*_s58 + _k84*_s33*_s60 + _k85*_s36 + _k86*_s40*b2 + _k87*_s62 + _k88*_s10*_s48 + _k89*_s49*b3 + _k90*_s37*b1 + _k91*_s43*b1 + _k92*_s46*b2 + _k93*_s63 + _k94*_s64 + _k95*_s50*b1 + _k96*_s51*b1 + _k97*_s52*b1 + _k98*_s53 + _k99*_s54
    _A[37] = 0.0
    _A[38] = _k123*_s52 + _k124*_s51 + _k125*_s50 + _k126*_s87
    _A[39] = 1.0
    _A[40] = 0.0
    _A[41] = 0.0
    _A[42] = 0.0
    _A[43] = 0.0
    _A[44] = 0.0
    _A[45] = J_r + _cam0[0]*_k114*_s68 + _k112*_s66*_s67 + _k113*_s77 + _k115*_s68 + _k118*_s78 + _s66*_s80 + _s69*_s75 + _s72*_s81 + _s75*_s82
    _A[46] = _s89*_s90 - _s94
    _A[47] = _s90*_s93 + _s95
    _A[48] = _s83
    _A[49] = _s84
    _A[50] = _s85
    _A[51] = _s86
    _A[52] = _k123*_s52 + _k124*_s51 + _k125*_s50 + _k126*_s87
    _A[53] = _s89*_s90 - _s94
    _A[54] = 0.0
    _A[55] = 0.0
    _A[56] = 0.0
    _A[57] = 0.0
    _A[58] = 0.0
    _A[59] = 0.0
    _A[60] = 1.0
    _A[61] = _s90*_s93 + _s95
    _A[62] = 0.0
    _A[63] = 0.0
    _b[0] = _k128*_s113 + _k129*_s115 + _k130*_s97 + _k131*_s99 + _k132*_s101 + _k132*_s116 + _k133*_s103 + _k134*_s118 + _k135*_s87 + _k136*_s51 + _k137*_s52 + _k138*_s50 + _k139*_s104 + _k140*_s119 + _k141*_s120 + _k142*_s105 + _k143*_s106 + _k144*_s108 + _k145*_s121 + _k146*_s123 + _k147*_s102*_s2 + _k149*_s109 + _k150*_s110 + _k151*_s0*_s111 + _k152*_s125 + _k153*_s112*_s50 + _s112*_s124
    _b[1] = _k138*_s117 + _k154*_s120 + _k155*_s119 + _k156*_s105 + _k157*_s108 + _k158*_s106 + _k158*_s121 + _k159*_s104 + _k160*_s123 + _k162*_s39 + _k164*_s128 + _k165*_s134 + _k166*_s135 + _k167*_s130 + _k168*_s137 + _k169*_s131 + _k170*_s132 + _k171*_s138 + _k172*_s103 + _k173*_s113 + _k174*_s97 + _k175*_s99 + _k176*_s115 + _k177*_s101 + _k178*_s116 + _s126*b4 + _s127*b3
    _b[2] = _k136*_s122 + _k179*_s135 + _k180*_s134 + _k181*_s131 + _k182*_s130 + _k183*_s128 + _k183*_s137 + _k184*_s132 + _k185*_s138 + _k187*_s43 + _k188*_s144 + _k189*_s140 + _k190*_s146 + _k191*_s141 + _k192*_s142 + _k193*_s147 + _k194*_s143 + _k195*_s149 + _k196*_s104 + _k197*_s120 + _k198*_s108 + _k199*_s105 + _k200*_s119 + _k201*_s106 + _k202*_s121 + _s127*b2 + _s139*b4
    _b[3] = _k137*_s40 + _k203*_s147 + _k204*_s146 + _k205*_s141 + _k206*_s140 + _k207*_s142 + _k207*_s144 + _k208*_s143 + _k209*_s149 + _k210*_s46 + _k211*_s96*pow(xE, 10.0) + _k212*_s112*_s33*b4 + _k213*_s129*_s33 + _k214*_s136*_s25 + _k215*_s102*_s25 + _k216*_s145*_s30 + _k217*_s111*_s30 + _k218*_s10*_s148 + _k219*_s132 + _k220*_s134 + _k221*_s135 + _k222*_s130 + _k223*_s131 + _k224*_s128 + _k225*_s137 + _s126*b2 + _s139*b3
    _b[4] = _k128*_s102*_s42 + _k128*_s109*b1 + _k133*_s112*_s36 + _k141*_s102*_s37 + _k141*_s97*b1 + _k148*_s122*_s129 + _k226*_s112 + _k227*_s112*_s64 + _k228*_s112*_s63 + _k229*_s101*b2 + _k229*_s112*_s62 + _k230*_s35 + _k231*_s112*_s38 + _k232*_s112*_s54 + _k233*_s112*_s53 + _k234*_s150 + _k235*_s148*_s52 + _k236*_s49*_s96 + _k237*_s105*b3 + _k237*_s129*_s46 + _k238*_s148*_s51 + _k239*_s108*b3 + _k240*_s111*_s37 + _k240*_s97*b2 + _k241*_s111*_s43 + _k241*_s99*b2 + _k242*_s151 + _k243*_s148*_s50 + _k244*_s104*b3 + _k244*_s129*_s40 + _k245*_s102*_s39 + _k245*_s111*_s122 + _k246*_s102*_s117 + _k247*_s152 + _k248*_s43*b4 + _k249*_s52*b2 + _k250*_s51*b2 + _k251*_s122*b4 + _k252*_s112*_s59 + _k253*_s117*b3 + _k254*_s87*b2 + _k255*_s112*_s55 + _k256*_s112*_s61 + _k257*_s112*_s57 + _k258*_s112*_s35 + _k259*_s112*_s150 + _k260*_s112*_s47 + _k261*_s112*_s151 + _k262*_s112*_s45 + _k263*_s112*_s44 + _k264*_s148*_s42 + _k265*_s112*_s41 + _k266*_s148*_s39 + _k267*_s129*_s49 + _k267*_s131*b3 + _k268*_s108*b2 + _k268*_s128*b3 + _k269*_s104*b2 + _k269*_s111*_s40 + _k270*_s141*b4 + _k271*_s130*b3 + _k272*_s105*b2 + _k272*_s111*_s46 + _k273*_s106*b2 + _k274*_s102*_s43 + _k274*_s99*b1 + _k275*_s112*_s152 + _k276*_s102*_s122 + _k277*_s119*b4 + _k278*_s125*b2 + _k279*_s129*_s37 + _k279*_s97*b3 + _k280*_s136*_s51 + _k281*_s109*b2 + _k281*_s111*_s42 + _k282*_s123*b4 + _k283*_s101*b3 + _k283*_s110*b2 + _k284*_s111*_s39 + _k284*_s118*b3 + _k285*_s102*_s52 + _k285*_s40*_s96 + _k286*_s102*_s50 + _k286*_s111*_s117 + _k286*_s136*_s87 + _k287*_s102*_s87 + _k288*_s46*_s96 + _k289*_s129*_s43 + _s102*_s124
    _b[5] = _cam0[0]*_k290*_s155 + _cam0[0]*_k293*_s160 + _cam0[0]*_k313*_s170 + _cam0[0]*_k319*_s169 + _cam0[0]*_k320*_s157 + _cam0[0]*_k321*_s168 + _cam0[0]*_k322*_s167 + _cam0[0]*_s154*_s80 + _cam0[0]*_s165 + _cam0[2]*_s165 + _k118*_s160 + _k291*_s155 + _k292*_s156*_s68 + _k307*_s167*_s70 + _k307*_s168*_s65 + _k308*_s164 + _k309*_s154*_s66*_s74 + _k310*_s156*_s78 + _k310*_s158*_s65 + _k311*_s156*_s77 + _k312*_s158 + _k313*_s169*_s65 + _k314*_s169 + _k315*_s170 + _k316*_s157 + _k317*_s167 + _k318*_s168 + _k323*_s166*_s82 + _s154*_s72*_s75 + _s156*_s65*_s81 + _s161*_s75
    _b[6] = _k324*_s89 + _k325*_s148 + _k329*_s153*_s175 + _k330*_s102*xE + _k331*_s111*_s2 + _k331*_s112*_s15 + _k332*_s0*_s129 + _k333*_s3*_s96 + _k334*_s112*_s21 + _k335*_s112*_s17 + _s171*_s89 + _s172*_s89 + _s173*_s175 + _s174*_s89 + _s176*_s89 + _s177*_s178 + _s177*_s91
    _ph[0] = _s83*b1 + _s84*b2 + _s85*b3 + _s86*b4 + _s95
    _phd[0] = Omega*_s94 + _A[48] * b1d + _A[49] * b2d + _A[50] * b3d + _A[51] * b4d + _A[52] * xEd + _A[53] * thetad
    _b[7] = _cam0[1]*_k337*_s177 + _cam0[1]*_k338*_s89*thetad + _k324*_s93 + _s171*_s93 + _s172*_s93 + _s174*_s93 + _s176*_s93 + _s178*_s179 + _s179*_s91
    _ph[1] = _k339 + _s94 + xE
    _phd[1] = _k340*_s95 + _A[56] * b1d + _A[57] * b2d + _A[58] * b3d + _A[59] * b4d + _A[60] * xEd + _A[61] * thetad


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
    cdef double _k189 = ctx.k[189]
    cdef double _k190 = ctx.k[190]
    cdef double _k191 = ctx.k[191]
    cdef double _k192 = ctx.k[192]
    cdef double _k193 = ctx.k[193]
    cdef double _k194 = ctx.k[194]
    cdef double _k195 = ctx.k[195]
    cdef double _k196 = ctx.k[196]
    cdef double _k197 = ctx.k[197]
    cdef double _k198 = ctx.k[198]
    cdef double _k199 = ctx.k[199]
    cdef double _k200 = ctx.k[200]
    cdef double _k201 = ctx.k[201]
    cdef double _k202 = ctx.k[202]
    cdef double _k203 = ctx.k[203]
    cdef double _k204 = ctx.k[204]
    cdef double _k205 = ctx.k[205]
    cdef double _k206 = ctx.k[206]
    cdef double _k207 = ctx.k[207]
    cdef double _k208 = ctx.k[208]
    cdef double _k209 = ctx.k[209]
    cdef double _k210 = ctx.k[210]
    cdef double _k211 = ctx.k[211]
    cdef double _k212 = ctx.k[212]
    cdef double _k213 = ctx.k[213]
    cdef double _k214 = ctx.k[214]
    cdef double _k215 = ctx.k[215]
    cdef double _k216 = ctx.k[216]
    cdef double _k217 = ctx.k[217]
    cdef double _k218 = ctx.k[218]
    cdef double _k219 = ctx.k[219]
    cdef double _k220 = ctx.k[220]
    cdef double _k221 = ctx.k[221]
    cdef double _k222 = ctx.k[222]
    cdef double _k223 = ctx.k[223]
    cdef double _k224 = ctx.k[224]
    cdef double _k225 = ctx.k[225]
    cdef double _k226 = ctx.k[226]
    cdef double _k227 = ctx.k[227]
    cdef double _k228 = ctx.k[228]
    cdef double _k229 = ctx.k[229]
    cdef double _k230 = ctx.k[230]
    cdef double _k231 = ctx.k[231]
    cdef double _k232 = ctx.k[232]
    cdef double _k233 = ctx.k[233]
    cdef double _k234 = ctx.k[234]
    cdef double _k235 = ctx.k[235]
    cdef double _k236 = ctx.k[236]
    cdef double _k237 = ctx.k[237]
    cdef double _k238 = ctx.k[238]
    cdef double _k239 = ctx.k[239]
    cdef double _k240 = ctx.k[240]
    cdef double _k241 = ctx.k[241]
    cdef double _k242 = ctx.k[242]
    cdef double _k243 = ctx.k[243]
    cdef double _k244 = ctx.k[244]
    cdef double _k245 = ctx.k[245]
    cdef double _k246 = ctx.k[246]
    cdef double _k247 = ctx.k[247]
    cdef double _k248 = ctx.k[248]
    cdef double _k249 = ctx.k[249]
    cdef double _k250 = ctx.k[250]
    cdef double _k251 = ctx.k[251]
    cdef double _k252 = ctx.k[252]
    cdef double _k253 = ctx.k[253]
    cdef double _k254 = ctx.k[254]
    cdef double _k255 = ctx.k[255]
    cdef double _k256 = ctx.k[256]
    cdef double _k257 = ctx.k[257]
    cdef double _k258 = ctx.k[258]
    cdef double _k259 = ctx.k[259]
    cdef double _k260 = ctx.k[260]
    cdef double _k261 = ctx.k[261]
    cdef double _k262 = ctx.k[262]
    cdef double _k263 = ctx.k[263]
    cdef double _k264 = ctx.k[264]
    cdef double _k265 = ctx.k[265]
    cdef double _k266 = ctx.k[266]
    cdef double _k267 = ctx.k[267]
    cdef double _k268 = ctx.k[268]
    cdef double _k269 = ctx.k[269]
    cdef double _k270 = ctx.k[270]
    cdef double _k271 = ctx.k[271]
    cdef double _k272 = ctx.k[272]
    cdef double _k273 = ctx.k[273]
    cdef double _k274 = ctx.k[274]
    cdef double _k275 = ctx.k[275]
    cdef double _k276 = ctx.k[276]
    cdef double _k277 = ctx.k[277]
    cdef double _k278 = ctx.k[278]
    cdef double _k279 = ctx.k[279]
    cdef double _k280 = ctx.k[280]
    cdef double _k281 = ctx.k[281]
    cdef double _k282 = ctx.k[282]
    cdef double _k283 = ctx.k[283]
    cdef double _k284 = ctx.k[284]
    cdef double _k285 = ctx.k[285]
    cdef double _k286 = ctx.k[286]
    cdef double _k287 = ctx.k[287]
    cdef double _k288 = ctx.k[288]
    cdef double _k289 = ctx.k[289]
    cdef double _k290 = ctx.k[290]
    cdef double _k291 = ctx.k[291]
    cdef double _k292 = ctx.k[292]
    cdef double _k293 = ctx.k[293]
    cdef double _k294 = ctx.k[294]
    cdef double _k295 = ctx.k[295]
    cdef double _k296 = ctx.k[296]
    cdef double _k297 = ctx.k[297]
    cdef double _k298 = ctx.k[298]
    cdef double _k299 = ctx.k[299]
    cdef double _k300 = ctx.k[300]
    cdef double _k301 = ctx.k[301]
    cdef double _k302 = ctx.k[302]
    cdef double _k303 = ctx.k[303]
    cdef double _k304 = ctx.k[304]
    cdef double _k305 = ctx.k[305]
    cdef double _k306 = ctx.k[306]
    cdef double _k307 = ctx.k[307]
    cdef double _k308 = ctx.k[308]
    cdef double _k309 = ctx.k[309]
    cdef double _k310 = ctx.k[310]
    cdef double _k311 = ctx.k[311]
    cdef double _k312 = ctx.k[312]
    cdef double _k313 = ctx.k[313]
    cdef double _k314 = ctx.k[314]
    cdef double _k315 = ctx.k[315]
    cdef double _k316 = ctx.k[316]
    cdef double _k317 = ctx.k[317]
    cdef double _k318 = ctx.k[318]
    cdef double _k319 = ctx.k[319]
    cdef double _k320 = ctx.k[320]
    cdef double _k321 = ctx.k[321]
    cdef double _k322 = ctx.k[322]
    cdef double _k323 = ctx.k[323]
    cdef double _k324 = ctx.k[324]
    cdef double _k325 = ctx.k[325]
    cdef double _k326 = ctx.k[326]
    cdef double _k327 = ctx.k[327]
    cdef double _k328 = ctx.k[328]
    cdef double _k329 = ctx.k[329]
    cdef double _k330 = ctx.k[330]
    cdef double _k331 = ctx.k[331]
    cdef double _k332 = ctx.k[332]
    cdef double _k333 = ctx.k[333]
    cdef double _k334 = ctx.k[334]
    cdef double _k335 = ctx.k[335]
    cdef double _k336 = ctx.k[336]
    cdef double _k337 = ctx.k[337]
    cdef double _k338 = ctx.k[338]
    cdef double _k339 = ctx.k[339]
    cdef double _k340 = ctx.k[340]
    cdef double _k341 = ctx.k[341]
    cdef double _k342 = ctx.k[342]
    cdef double b1 = _y[0]
    cdef double b2 = _y[1]
    cdef double b3 = _y[2]
    cdef double b4 = _y[3]
    cdef double xE = _y[4]
    cdef double theta = _y[5]
    cdef double b1d = _y[6]
    cdef double b2d = _y[7]
    cdef double b3d = _y[8]
    cdef double b4d = _y[9]
    cdef double xEd = _y[10]
    cdef double thetad = _y[11]
    cdef double _cam0[4]
    _profile(ctx, theta, beta_r, _cam0)

    cdef double _p0 = (xE*xE)
    cdef double _p1 = _k119*_p0
    cdef double _p2 = (xE*xE*xE)
    cdef double _p3 = _k120*_p2
    cdef double _p4 = _k121*(xE*xE*xE*xE)
    cdef double _p5 = _k122*pow(xE, 5.0)
    cdef double _p6 = S_T*_cam0[0] + _k127
    cdef double _p7 = Omega*t - theta
    cdef double _p8 = sin(_p7)
    cdef double _p9 = _p6*_p8
    cdef double _p10 = cos(_p7)
    cdef double _p11 = _p10*_p6
    cdef double _p12 = S_T*_cam0[1]
    _g[0] = _p1*b1 + _p3*b2 + _p4*b3 + _p5*b4 + _p9
    _g[1] = _k339 + _p11 + xE
    _J[0] = _p1
    _J[1] = _p3
    _J[2] = _p4
    _J[3] = _p5
    _J[4] = xE*(_k123*_p2*b4 + _k124*_p0*b3 + _k125*b2*xE + _k126*b1)
    _J[5] = -_p11 + _p12*_p8
    _J[6] = 0.0
    _J[7] = 0.0
    _J[8] = 0.0
    _J[9] = 0.0
    _J[10] = 1.0
    _J[11] = _p10*_p12 + _p9
    _gt[0] = Omega*_p11
    _gt[1] = _k340*_p9


cdef inline int _recover(double t, const double* _y, double* _yc, Ctx* ctx) noexcept nogil:
    """Coordinate partitioning: the state with its dependent coordinates recovered from the
    independent ones by Newton's method on Phi = 0, started from the values the state carries,
    and their rates from Phi_Q Q' = -dPhi/dt.  0, or 1 without convergence."""
    cdef double _g[_NC]
    cdef double _J[_NC * _NQ]
    cdef double _gt[_NC]
    cdef double _D[_NC * _NC]
    cdef int i, j, it
    cdef double step
    for i in range(_NS):
        _yc[i] = _y[i]
    for it in range(30):
        _constraints(t, _yc, _g, _J, _gt, ctx)
        for i in range(_NC):
            _g[i] = -_g[i]
            for j in range(_NC):
                _D[i * _NC + j] = _J[i * _NQ + _ND + j]
        if solve_inplace(_NC, _D, _g) != 0:
            return 1
        step = 0.0
        for j in range(_NC):
            _yc[_ND + j] += _g[j]
            step = max(step, fabs(_g[j]) / (1.0 + fabs(_yc[_ND + j])))
        if step < 1e-15:
            break
    else:
        return 1
    _constraints(t, _yc, _g, _J, _gt, ctx)
    for i in range(_NC):
        _g[i] = -_gt[i]
        for j in range(_ND):
            _g[i] -= _J[i * _NQ + j] * _yc[_NQ + j]
        for j in range(_NC):
            _D[i * _NC + j] = _J[i * _NQ + _ND + j]
    if solve_inplace(_NC, _D, _g) != 0:
        return 1
    for j in range(_NC):
        _yc[_NQ + _ND + j] = _g[j]
    return 0


cdef inline int _solve(double t, double* _yc, const double* _y, double* _acc, Ctx* ctx) noexcept nogil:
    """Q'' and lambda into _acc, and in _yc the state they belong to: the state itself with
    Baumgarte's terms (formulation 0), or its partitioned recovery (formulation 1)."""
    cdef double _A[_NA * _NA]
    cdef double _ph[_NC]
    cdef double _phd[_NC]
    cdef double w = ctx.p[13]  # w_B
    cdef int i
    cdef bint partitioned = ctx.p[14] > 0.5  # formulation
    if partitioned:
        if _recover(t, _y, _yc, ctx) != 0:
            return 1
    else:
        for i in range(_NS):
            _yc[i] = _y[i]
    _system(t, _yc, _A, _acc, _ph, _phd, ctx)
    if not partitioned:
        for i in range(_NC):
            _acc[_NQ + i] -= 2.0 * w * _phd[i] + w * w * _ph[i]
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
    cdef double _k189 = ctx.k[189]
    cdef double _k190 = ctx.k[190]
    cdef double _k191 = ctx.k[191]
    cdef double _k192 = ctx.k[192]
    cdef double _k193 = ctx.k[193]
    cdef double _k194 = ctx.k[194]
    cdef double _k195 = ctx.k[195]
    cdef double _k196 = ctx.k[196]
    cdef double _k197 = ctx.k[197]
    cdef double _k198 = ctx.k[198]
    cdef double _k199 = ctx.k[199]
    cdef double _k200 = ctx.k[200]
    cdef double _k201 = ctx.k[201]
    cdef double _k202 = ctx.k[202]
    cdef double _k203 = ctx.k[203]
    cdef double _k204 = ctx.k[204]
    cdef double _k205 = ctx.k[205]
    cdef double _k206 = ctx.k[206]
    cdef double _k207 = ctx.k[207]
    cdef double _k208 = ctx.k[208]
    cdef double _k209 = ctx.k[209]
    cdef double _k210 = ctx.k[210]
    cdef double _k211 = ctx.k[211]
    cdef double _k212 = ctx.k[212]
    cdef double _k213 = ctx.k[213]
    cdef double _k214 = ctx.k[214]
    cdef double _k215 = ctx.k[215]
    cdef double _k216 = ctx.k[216]
    cdef double _k217 = ctx.k[217]
    cdef double _k218 = ctx.k[218]
    cdef double _k219 = ctx.k[219]
    cdef double _k220 = ctx.k[220]
    cdef double _k221 = ctx.k[221]
    cdef double _k222 = ctx.k[222]
    cdef double _k223 = ctx.k[223]
    cdef double _k224 = ctx.k[224]
    cdef double _k225 = ctx.k[225]
    cdef double _k226 = ctx.k[226]
    cdef double _k227 = ctx.k[227]
    cdef double _k228 = ctx.k[228]
    cdef double _k229 = ctx.k[229]
    cdef double _k230 = ctx.k[230]
    cdef double _k231 = ctx.k[231]
    cdef double _k232 = ctx.k[232]
    cdef double _k233 = ctx.k[233]
    cdef double _k234 = ctx.k[234]
    cdef double _k235 = ctx.k[235]
    cdef double _k236 = ctx.k[236]
    cdef double _k237 = ctx.k[237]
    cdef double _k238 = ctx.k[238]
    cdef double _k239 = ctx.k[239]
    cdef double _k240 = ctx.k[240]
    cdef double _k241 = ctx.k[241]
    cdef double _k242 = ctx.k[242]
    cdef double _k243 = ctx.k[243]
    cdef double _k244 = ctx.k[244]
    cdef double _k245 = ctx.k[245]
    cdef double _k246 = ctx.k[246]
    cdef double _k247 = ctx.k[247]
    cdef double _k248 = ctx.k[248]
    cdef double _k249 = ctx.k[249]
    cdef double _k250 = ctx.k[250]
    cdef double _k251 = ctx.k[251]
    cdef double _k252 = ctx.k[252]
    cdef double _k253 = ctx.k[253]
    cdef double _k254 = ctx.k[254]
    cdef double _k255 = ctx.k[255]
    cdef double _k256 = ctx.k[256]
    cdef double _k257 = ctx.k[257]
    cdef double _k258 = ctx.k[258]
    cdef double _k259 = ctx.k[259]
    cdef double _k260 = ctx.k[260]
    cdef double _k261 = ctx.k[261]
    cdef double _k262 = ctx.k[262]
    cdef double _k263 = ctx.k[263]
    cdef double _k264 = ctx.k[264]
    cdef double _k265 = ctx.k[265]
    cdef double _k266 = ctx.k[266]
    cdef double _k267 = ctx.k[267]
    cdef double _k268 = ctx.k[268]
    cdef double _k269 = ctx.k[269]
    cdef double _k270 = ctx.k[270]
    cdef double _k271 = ctx.k[271]
    cdef double _k272 = ctx.k[272]
    cdef double _k273 = ctx.k[273]
    cdef double _k274 = ctx.k[274]
    cdef double _k275 = ctx.k[275]
    cdef double _k276 = ctx.k[276]
    cdef double _k277 = ctx.k[277]
    cdef double _k278 = ctx.k[278]
    cdef double _k279 = ctx.k[279]
    cdef double _k280 = ctx.k[280]
    cdef double _k281 = ctx.k[281]
    cdef double _k282 = ctx.k[282]
    cdef double _k283 = ctx.k[283]
    cdef double _k284 = ctx.k[284]
    cdef double _k285 = ctx.k[285]
    cdef double _k286 = ctx.k[286]
    cdef double _k287 = ctx.k[287]
    cdef double _k288 = ctx.k[288]
    cdef double _k289 = ctx.k[289]
    cdef double _k290 = ctx.k[290]
    cdef double _k291 = ctx.k[291]
    cdef double _k292 = ctx.k[292]
    cdef double _k293 = ctx.k[293]
    cdef double _k294 = ctx.k[294]
    cdef double _k295 = ctx.k[295]
    cdef double _k296 = ctx.k[296]
    cdef double _k297 = ctx.k[297]
    cdef double _k298 = ctx.k[298]
    cdef double _k299 = ctx.k[299]
    cdef double _k300 = ctx.k[300]
    cdef double _k301 = ctx.k[301]
    cdef double _k302 = ctx.k[302]
    cdef double _k303 = ctx.k[303]
    cdef double _k304 = ctx.k[304]
    cdef double _k305 = ctx.k[305]
    cdef double _k306 = ctx.k[306]
    cdef double _k307 = ctx.k[307]
    cdef double _k308 = ctx.k[308]
    cdef double _k309 = ctx.k[309]
    cdef double _k310 = ctx.k[310]
    cdef double _k311 = ctx.k[311]
    cdef double _k312 = ctx.k[312]
    cdef double _k313 = ctx.k[313]
    cdef double _k314 = ctx.k[314]
    cdef double _k315 = ctx.k[315]
    cdef double _k316 = ctx.k[316]
    cdef double _k317 = ctx.k[317]
    cdef double _k318 = ctx.k[318]
    cdef double _k319 = ctx.k[319]
    cdef double _k320 = ctx.k[320]
    cdef double _k321 = ctx.k[321]
    cdef double _k322 = ctx.k[322]
    cdef double _k323 = ctx.k[323]
    cdef double _k324 = ctx.k[324]
    cdef double _k325 = ctx.k[325]
    cdef double _k326 = ctx.k[326]
    cdef double _k327 = ctx.k[327]
    cdef double _k328 = ctx.k[328]
    cdef double _k329 = ctx.k[329]
    cdef double _k330 = ctx.k[330]
    cdef double _k331 = ctx.k[331]
    cdef double _k332 = ctx.k[332]
    cdef double _k333 = ctx.k[333]
    cdef double _k334 = ctx.k[334]
    cdef double _k335 = ctx.k[335]
    cdef double _k336 = ctx.k[336]
    cdef double _k337 = ctx.k[337]
    cdef double _k338 = ctx.k[338]
    cdef double _k339 = ctx.k[339]
    cdef double _k340 = ctx.k[340]
    cdef double _k341 = ctx.k[341]
    cdef double _k342 = ctx.k[342]
    cdef double b1 = _yc[0]
    cdef double b2 = _yc[1]
    cdef double b3 = _yc[2]
    cdef double b4 = _yc[3]
    cdef double xE = _yc[4]
    cdef double theta = _yc[5]
    cdef double b1d = _yc[6]
    cdef double b2d = _yc[7]
    cdef double b3d = _yc[8]
    cdef double b4d = _yc[9]
    cdef double xEd = _yc[10]
    cdef double thetad = _yc[11]
    cdef double _cam0[4]
    _profile(ctx, theta, beta_r, _cam0)

    cdef double _o0 = (xE*xE)
    cdef double _o1 = (xE*xE*xE)
    cdef double _o2 = S_T*_cam0[0]
    cdef double _o3 = _k127 + _o2
    cdef double _o4 = Omega*t - theta
    _out[0] = _o0*(_k2*_o0*b3 + _k341*b1 + _k342*b2*xE + _k5*_o1*b4)  # vE
    _out[1] = _k119*_o0*b1 + _k120*_o1*b2 + _k121*b3*(xE*xE*xE*xE) + _k122*b4*pow(xE, 5.0) + _o3*sin(_o4)  # Phi1
    _out[2] = _k339 + _o3*cos(_o4) + xE  # Phi2
    _out[3] = _o2  # S
    _out[4] = atan(S_T*_cam0[1]/_o3)  # pressure_angle
    _out[5] = _acc[4]  # xEdd
    _out[6] = _acc[6]  # lambda1
    _out[7] = _acc[7]  # lambda2


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


cdef double _SCALE[_NS]  # typical magnitude of each state (manifest "scale"): the difference steps
_SCALE[0] = 1e-05
_SCALE[1] = 1e-05
_SCALE[2] = 1e-05
_SCALE[3] = 1e-05
_SCALE[4] = 0.05
_SCALE[5] = 1.0
_SCALE[6] = 1e-05
_SCALE[7] = 1e-05
_SCALE[8] = 1e-05
_SCALE[9] = 1e-05
_SCALE[10] = 0.05
_SCALE[11] = 1.0


cdef void jacobian(double t, const double* _y, double* _J, double* _ft, Ctx* ctx) noexcept nogil:
    """d(dy/dt)/dy at (t, y), row-major _NS x _NS, by central differences of rhs() in C (the
    manifest says "finite-difference"), extrapolated (Richardson) from the steps h_j and h_j/2,
    h_j = 1e-3 scale_j: truncation O(h^4), rounding O(eps |f|/h), both far below 1e-6 relative
    where the right-hand side is smooth over the step (a step across a cam breakpoint sees its
    kink).  The symbolic Jacobian of the augmented system (A^-1 (db/dy - dA/dy x)) is not
    generated: it needs one derivative more of a cam profile than the cam-law library gives
    (order 4), the partitioned formulation recovers the dependent coordinates by Newton's
    method, and the systems are large; differences are what the implicit method's iteration
    matrix needs."""
    cdef double _yp[_NS]
    cdef double _f1[_NS]
    cdef double _f2[_NS]
    cdef double _f3[_NS]
    cdef double _f4[_NS]
    cdef double _h, _a1, _b1, _a2, _b2
    cdef int i, j
    for i in range(_NS):
        _yp[i] = _y[i]
    for j in range(_NS):
        _h = 1e-3 * _SCALE[j]
        _a1, _b1 = _y[j] + _h, _y[j] - _h
        _a2, _b2 = _y[j] + 0.5 * _h, _y[j] - 0.5 * _h
        _yp[j] = _a1
        rhs(t, _yp, _f1, ctx)
        _yp[j] = _b1
        rhs(t, _yp, _f2, ctx)
        _yp[j] = _a2
        rhs(t, _yp, _f3, ctx)
        _yp[j] = _b2
        rhs(t, _yp, _f4, ctx)
        _yp[j] = _y[j]
        for i in range(_NS):
            _J[i * _NS + j] = (4.0 * (_f3[i] - _f4[i]) / (_a2 - _b2)
                               - (_f1[i] - _f2[i]) / (_a1 - _b1)) / 3.0


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
    cdef double _k189 = ctx.k[189]
    cdef double _k190 = ctx.k[190]
    cdef double _k191 = ctx.k[191]
    cdef double _k192 = ctx.k[192]
    cdef double _k193 = ctx.k[193]
    cdef double _k194 = ctx.k[194]
    cdef double _k195 = ctx.k[195]
    cdef double _k196 = ctx.k[196]
    cdef double _k197 = ctx.k[197]
    cdef double _k198 = ctx.k[198]
    cdef double _k199 = ctx.k[199]
    cdef double _k200 = ctx.k[200]
    cdef double _k201 = ctx.k[201]
    cdef double _k202 = ctx.k[202]
    cdef double _k203 = ctx.k[203]
    cdef double _k204 = ctx.k[204]
    cdef double _k205 = ctx.k[205]
    cdef double _k206 = ctx.k[206]
    cdef double _k207 = ctx.k[207]
    cdef double _k208 = ctx.k[208]
    cdef double _k209 = ctx.k[209]
    cdef double _k210 = ctx.k[210]
    cdef double _k211 = ctx.k[211]
    cdef double _k212 = ctx.k[212]
    cdef double _k213 = ctx.k[213]
    cdef double _k214 = ctx.k[214]
    cdef double _k215 = ctx.k[215]
    cdef double _k216 = ctx.k[216]
    cdef double _k217 = ctx.k[217]
    cdef double _k218 = ctx.k[218]
    cdef double _k219 = ctx.k[219]
    cdef double _k220 = ctx.k[220]
    cdef double _k221 = ctx.k[221]
    cdef double _k222 = ctx.k[222]
    cdef double _k223 = ctx.k[223]
    cdef double _k224 = ctx.k[224]
    cdef double _k225 = ctx.k[225]
    cdef double _k226 = ctx.k[226]
    cdef double _k227 = ctx.k[227]
    cdef double _k228 = ctx.k[228]
    cdef double _k229 = ctx.k[229]
    cdef double _k230 = ctx.k[230]
    cdef double _k231 = ctx.k[231]
    cdef double _k232 = ctx.k[232]
    cdef double _k233 = ctx.k[233]
    cdef double _k234 = ctx.k[234]
    cdef double _k235 = ctx.k[235]
    cdef double _k236 = ctx.k[236]
    cdef double _k237 = ctx.k[237]
    cdef double _k238 = ctx.k[238]
    cdef double _k239 = ctx.k[239]
    cdef double _k240 = ctx.k[240]
    cdef double _k241 = ctx.k[241]
    cdef double _k242 = ctx.k[242]
    cdef double _k243 = ctx.k[243]
    cdef double _k244 = ctx.k[244]
    cdef double _k245 = ctx.k[245]
    cdef double _k246 = ctx.k[246]
    cdef double _k247 = ctx.k[247]
    cdef double _k248 = ctx.k[248]
    cdef double _k249 = ctx.k[249]
    cdef double _k250 = ctx.k[250]
    cdef double _k251 = ctx.k[251]
    cdef double _k252 = ctx.k[252]
    cdef double _k253 = ctx.k[253]
    cdef double _k254 = ctx.k[254]
    cdef double _k255 = ctx.k[255]
    cdef double _k256 = ctx.k[256]
    cdef double _k257 = ctx.k[257]
    cdef double _k258 = ctx.k[258]
    cdef double _k259 = ctx.k[259]
    cdef double _k260 = ctx.k[260]
    cdef double _k261 = ctx.k[261]
    cdef double _k262 = ctx.k[262]
    cdef double _k263 = ctx.k[263]
    cdef double _k264 = ctx.k[264]
    cdef double _k265 = ctx.k[265]
    cdef double _k266 = ctx.k[266]
    cdef double _k267 = ctx.k[267]
    cdef double _k268 = ctx.k[268]
    cdef double _k269 = ctx.k[269]
    cdef double _k270 = ctx.k[270]
    cdef double _k271 = ctx.k[271]
    cdef double _k272 = ctx.k[272]
    cdef double _k273 = ctx.k[273]
    cdef double _k274 = ctx.k[274]
    cdef double _k275 = ctx.k[275]
    cdef double _k276 = ctx.k[276]
    cdef double _k277 = ctx.k[277]
    cdef double _k278 = ctx.k[278]
    cdef double _k279 = ctx.k[279]
    cdef double _k280 = ctx.k[280]
    cdef double _k281 = ctx.k[281]
    cdef double _k282 = ctx.k[282]
    cdef double _k283 = ctx.k[283]
    cdef double _k284 = ctx.k[284]
    cdef double _k285 = ctx.k[285]
    cdef double _k286 = ctx.k[286]
    cdef double _k287 = ctx.k[287]
    cdef double _k288 = ctx.k[288]
    cdef double _k289 = ctx.k[289]
    cdef double _k290 = ctx.k[290]
    cdef double _k291 = ctx.k[291]
    cdef double _k292 = ctx.k[292]
    cdef double _k293 = ctx.k[293]
    cdef double _k294 = ctx.k[294]
    cdef double _k295 = ctx.k[295]
    cdef double _k296 = ctx.k[296]
    cdef double _k297 = ctx.k[297]
    cdef double _k298 = ctx.k[298]
    cdef double _k299 = ctx.k[299]
    cdef double _k300 = ctx.k[300]
    cdef double _k301 = ctx.k[301]
    cdef double _k302 = ctx.k[302]
    cdef double _k303 = ctx.k[303]
    cdef double _k304 = ctx.k[304]
    cdef double _k305 = ctx.k[305]
    cdef double _k306 = ctx.k[306]
    cdef double _k307 = ctx.k[307]
    cdef double _k308 = ctx.k[308]
    cdef double _k309 = ctx.k[309]
    cdef double _k310 = ctx.k[310]
    cdef double _k311 = ctx.k[311]
    cdef double _k312 = ctx.k[312]
    cdef double _k313 = ctx.k[313]
    cdef double _k314 = ctx.k[314]
    cdef double _k315 = ctx.k[315]
    cdef double _k316 = ctx.k[316]
    cdef double _k317 = ctx.k[317]
    cdef double _k318 = ctx.k[318]
    cdef double _k319 = ctx.k[319]
    cdef double _k320 = ctx.k[320]
    cdef double _k321 = ctx.k[321]
    cdef double _k322 = ctx.k[322]
    cdef double _k323 = ctx.k[323]
    cdef double _k324 = ctx.k[324]
    cdef double _k325 = ctx.k[325]
    cdef double _k326 = ctx.k[326]
    cdef double _k327 = ctx.k[327]
    cdef double _k328 = ctx.k[328]
    cdef double _k329 = ctx.k[329]
    cdef double _k330 = ctx.k[330]
    cdef double _k331 = ctx.k[331]
    cdef double _k332 = ctx.k[332]
    cdef double _k333 = ctx.k[333]
    cdef double _k334 = ctx.k[334]
    cdef double _k335 = ctx.k[335]
    cdef double _k336 = ctx.k[336]
    cdef double _k337 = ctx.k[337]
    cdef double _k338 = ctx.k[338]
    cdef double _k339 = ctx.k[339]
    cdef double _k340 = ctx.k[340]
    cdef double _k341 = ctx.k[341]
    cdef double _k342 = ctx.k[342]
    cdef double b1 = _y[0]
    cdef double b2 = _y[1]
    cdef double b3 = _y[2]
    cdef double b4 = _y[3]
    cdef double xE = _y[4]
    cdef double theta = _y[5]
    cdef double b1d = _y[6]
    cdef double b2d = _y[7]
    cdef double b3d = _y[8]
    cdef double b4d = _y[9]
    cdef double xEd = _y[10]
    cdef double thetad = _y[11]
    cdef double _cam0[4]
    _profile(ctx, theta, beta_r, _cam0)

    _g[0] = -sin(theta)*sin(beta_r - theta)  # segment_up
    _g[1] = -sin(theta)*sin(beta_r - theta)  # segment_down


cdef void on_event(int _e, double t, double* _y, Ctx* ctx) noexcept nogil:
    """A segment end switches nothing: the step just ends there."""
    refresh(ctx)


cdef void rhs_ptr(double t, const double* _y, double* _dy, Ctx* ctx) noexcept nogil:
    rhs(t, _y, _dy, ctx)


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
    return [0.0, 0.0, 0.0, 0.0, d - r_b - r_r, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, Omega]


def cam_time_affine(p):
    """No cam input with a time-affine argument: a profile follows a state of the model."""
    return []


def consistent_state(double[::1] p, double[::1] k, int[::1] law, double[::1] law_par,
                     int[::1] mode, double t, double[::1] y, double[::1] out):
    """The state y with its dependent coordinates (the last _NC) and their rates recovered
    from the independent ones (Newton's method on Phi = 0, then Phi_Q Q' = -dPhi/dt), into
    out; returns (0 or 1 without convergence, the largest |Phi| and |Phi'| of y itself).
    ``k``: n_const + n_cache + 1 doubles of scratch, ``mode``: the modes buffer."""
    cdef Ctx ctx
    cdef double _g[_NC]
    cdef double _J[_NC * _NQ]
    cdef double _gt[_NC]
    cdef double phi = 0.0, phid = 0.0, v
    cdef int i, j, status
    ctx.p = &p[0]
    ctx.k = &k[0]
    ctx.cache = &k[343]
    ctx.law = &law[0]
    ctx.law_par = &law_par[0]
    ctx.mode = &mode[0]
    ctx.variant = 0
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
_model.n_const = 343
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
_model.run = run_loops

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
 "jacobian": "finite-difference",
 "modes": [],
 "n_constraints": 2,
 "n_q": 6,
 "name": "beam4",
 "options": [
  [
   "modes",
   4
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
   "doc": "0: augmented index-1 system with Baumgarte stabilization; 1: coordinate partitioning with Newton on (x_E, theta)",
   "high": 1.0,
   "low": 0.0,
   "name": "formulation",
   "open_high": false,
   "open_low": false,
   "range": "0 <= formulation <= 1",
   "unit": "1"
  }
 ],
 "reference": "paper (1)-(20)",
 "residual": null,
 "solver": {
  "baumgarte_rate": "w_B",
  "formulation": "formulation"
 },
 "source_hash": "sha256:005fc6dd88930eeb16af7091c0a74ba4fe7f9c436ef794c0f2976a8de40a1269",
 "states": [
  {
   "doc": "amplitude of the assumed mode (x/d)^2 (13)",
   "initial": 0.0,
   "name": "b1",
   "scale": 1e-05,
   "unit": "m"
  },
  {
   "doc": "amplitude of the assumed mode (x/d)^3 (13)",
   "initial": 0.0,
   "name": "b2",
   "scale": 1e-05,
   "unit": "m"
  },
  {
   "doc": "amplitude of the assumed mode (x/d)^4 (13)",
   "initial": 0.0,
   "name": "b3",
   "scale": 1e-05,
   "unit": "m"
  },
  {
   "doc": "amplitude of the assumed mode (x/d)^5 (13)",
   "initial": 0.0,
   "name": "b4",
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
   "doc": "rate of b2",
   "initial": 0.0,
   "name": "b2d",
   "scale": 1e-05,
   "unit": "m/s"
  },
  {
   "doc": "rate of b3",
   "initial": 0.0,
   "name": "b3d",
   "scale": 1e-05,
   "unit": "m/s"
  },
  {
   "doc": "rate of b4",
   "initial": 0.0,
   "name": "b4d",
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
 "time_derivative": "finite-difference",
 "title": "Rayleigh-beam follower in a grooved disk cam, N = 4 assumed modes"
}
"""
MANIFEST = json.loads(_MANIFEST_JSON)
"""States, parameters (defaults, units, ranges), outputs, the cam profile, events, source hash."""

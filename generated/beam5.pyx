# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True, initializedcheck=False
#
# GENERATED FILE - DO NOT EDIT.  Written by `camdyn derive` from camdyn/derive/models/beam.py;
# edit that and regenerate.  `camdyn derive --check` fails while this file is stale.
# Derivation key: sha256:30fdb5d175bb817c87f46b46ffe2b5ccf0257fd029225816f231e8a5b7749d09
# Text hash: sha256:c27013e17dbb6e8986111e04f85a28bcfa9b4d3c41fe59cc8f1dfd1ac061fde1
#
# Rayleigh-beam follower in a grooved disk cam, N = 5 assumed modes (paper (1)-(20))
# Source hash: sha256:a91861c5ef9ef871d0972bdd6fadc95fb8bd8aa9c22b166a68b2e22724f00536
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
    _NQ = 7                  # coordinates Q
    _NC = 2                  # constraints Phi
    _NA = 9                  # unknowns of the augmented system: Q'', lambda
    _ND = 5                  # first dependent coordinate (the last _NC are dependent)
    _NS = 14                 # states: Q, Q'
    _NCAM = 0
    _NM = 0
    _NE = 2
    _NQ1 = 7
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
    cdef double _c2 = _c1*rayleigh
    cdef double _c3 = _c0*_c2
    cdef double _c4 = _c1*(a_rod*a_rod)
    cdef double _c5 = (1.0/(d*d*d*d))
    cdef double _c6 = pow(d, -5.0)
    cdef double _c7 = pow(d, -6.0)
    cdef double _c8 = pow(d, -7.0)
    cdef double _c9 = pow(d, -8.0)
    cdef double _c10 = 2.0*m_r
    cdef double _c11 = _c10*_c5
    cdef double _c12 = 3.0*m_r
    cdef double _c13 = 4.0*m_r
    cdef double _c14 = _c13*_c7
    cdef double _c15 = 5.0*m_r
    cdef double _c16 = 6.0*m_r
    cdef double _c17 = _c16*_c9
    cdef double _c18 = _c4*_c5
    cdef double _c19 = _c4*_c7
    cdef double _c20 = 0.6666666666666666*_c19
    cdef double _c21 = _c4*_c9
    cdef double _c22 = 0.75*_c21
    cdef double _c23 = _c4*_c6
    cdef double _c24 = _c4*_c8
    cdef double _c25 = _c3*_c6
    cdef double _c26 = _c0*_c5
    cdef double _c27 = _c2*_c26
    cdef double _c28 = 0.5*_c27
    cdef double _c29 = _c3*_c8
    cdef double _c30 = _c3*_c7
    cdef double _c31 = 1.5*_c30
    cdef double _c32 = _c3*_c9
    cdef double _c33 = 2.5*_c32
    cdef double _c34 = 0.5*_c3
    cdef double _c35 = pow(d, -9.0)
    cdef double _c36 = _c10*_c6
    cdef double _c37 = _c13*_c8
    cdef double _c38 = _c16*_c35
    cdef double _c39 = _c35*_c4
    cdef double _c40 = 0.6666666666666666*_c39
    cdef double _c41 = 0.5714285714285714*_c24
    cdef double _c42 = _c3*_c35
    cdef double _c43 = pow(d, -10.0)
    cdef double _c44 = _c10*_c7
    cdef double _c45 = _c13*_c9
    cdef double _c46 = 0.5*_c21
    cdef double _c47 = _c4*_c43
    cdef double _c48 = _c3*_c43
    cdef double _c49 = 12.0*m_r
    cdef double _c50 = 9.0*_c3
    cdef double _c51 = pow(d, -11.0)
    cdef double _c52 = _c10*_c8
    cdef double _c53 = _c4*_c51
    cdef double _c54 = _c3*_c51
    cdef double _c55 = pow(d, -12.0)
    cdef double _c56 = _c10*_c9
    cdef double _c57 = _c4*_c55
    cdef double _c58 = _c3*_c55
    cdef double _c59 = 4.0*_c5
    cdef double _c60 = _c59*m_r
    cdef double _c61 = _c7*m_r
    cdef double _c62 = _c9*m_r
    cdef double _c63 = _c43*m_r
    cdef double _c64 = 36.0*m_r
    cdef double _c65 = _c49*_c6
    cdef double _c66 = 16.0*_c61
    cdef double _c67 = _c8*m_r
    cdef double _c68 = 20.0*_c67
    cdef double _c69 = 24.0*_c62
    cdef double _c70 = 24.0*_c67
    cdef double _c71 = 30.0*_c62
    cdef double _c72 = _c35*_c64
    cdef double _c73 = _c35*m_r
    cdef double _c74 = 40.0*_c73
    cdef double _c75 = 48.0*_c63
    cdef double _c76 = _c51*m_r
    cdef double _c77 = 60.0*_c76
    cdef double _c78 = 3.0*_c23
    cdef double _c79 = 3.0*_c30
    cdef double _c80 = 4.0*_c24
    cdef double _c81 = 5.0*_c39
    cdef double _c82 = 6.0*_c53
    cdef double _c83 = 4.5*_c39
    cdef double _c84 = 3.3333333333333335*_c24
    cdef double _c85 = 5.333333333333333*_c47
    cdef double _c86 = 3.2*_c19
    cdef double _c87 = 3.4285714285714284*_c21
    cdef double _c88 = 4.285714285714286*_c21
    cdef double _c89 = 3.0*_c25
    cdef double _c90 = 4.0*_c30
    cdef double _c91 = 5.0*_c29
    cdef double _c92 = 6.0*_c32
    cdef double _c93 = _c50*_c8
    cdef double _c94 = 12.0*_c32
    cdef double _c95 = 15.0*_c42
    cdef double _c96 = 20.0*_c42
    cdef double _c97 = 37.5*_c54
    cdef double _c98 = 25.714285714285715*_c48
    cdef double _c99 = (r_b*r_b*r_b*r_b)
    cdef double _c100 = (r_r*r_r*r_r*r_r)
    cdef double _c101 = (r_r*r_r*r_r)
    cdef double _c102 = 4.0*_c101
    cdef double _c103 = (r_b*r_b*r_b)
    cdef double _c104 = 4.0*_c103
    cdef double _c105 = (r_r*r_r)
    cdef double _c106 = (r_b*r_b)
    cdef double _c107 = 6.0*_c106
    cdef double _c108 = (S_T*S_T*S_T*S_T)
    cdef double _c109 = 2.0*_c108
    cdef double _c110 = (S_T*S_T)
    cdef double _c111 = _c110*r_b
    cdef double _c112 = 4.0*r_r
    cdef double _c113 = 2.0*_c110
    cdef double _c114 = 12.0*S_T
    cdef double _c115 = _c105*r_b
    cdef double _c116 = _c106*r_r
    cdef double _c117 = (S_T*S_T*S_T)
    cdef double _c118 = 4.0*_c117
    cdef double _c119 = _c118*r_b
    cdef double _c120 = _c118*r_r
    cdef double _c121 = 12.0*_c111
    cdef double _c122 = _c105*_c110
    cdef double _c123 = J_r*_c108
    cdef double _c124 = 2.0*r_b
    cdef double _c125 = _c124*r_r
    cdef double _c126 = 2.0*S_T
    cdef double _c127 = _c126*r_b
    cdef double _c128 = _c126*r_r
    cdef double _c129 = J_r*_c110
    cdef double _c130 = 2.0*_c129
    cdef double _c131 = _c105*_c129 + _c106*_c129 + _c125*_c129
    cdef double _c132 = J_r*_c109
    cdef double _c133 = J_r*_c117
    cdef double _c134 = _c133*r_r
    cdef double _c135 = _c124*_c133 + 2.0*_c134
    cdef double _c136 = (1.0/(d*d))
    cdef double _c137 = (1.0/(d*d*d))
    cdef double _c138 = 6.0*_c7
    cdef double _c139 = 2.0*_c136
    cdef double _c140 = 3.141592653589793*E
    cdef double _c141 = _c140*_c26
    cdef double _c142 = _c0*_c140
    cdef double _c143 = _c142*_c9
    cdef double _c144 = _c142*_c7
    cdef double _c145 = _c142*_c8
    cdef double _c146 = _c142*_c6
    cdef double _c147 = _c142*_c35
    cdef double _c148 = 0.5*_c4
    cdef double _c149 = _c142*_c43
    cdef double _c150 = _c142*_c51
    cdef double _c151 = _c55*m_r
    cdef double _c152 = _c142*_c55
    cdef double _c153 = 8.0*_c5
    cdef double _c154 = J_r*S_T
    cdef double _c155 = 6.0*pow(r_r, 5.0)
    cdef double _c156 = 6.0*pow(r_b, 5.0)
    cdef double _c157 = 15.0*_c100
    cdef double _c158 = 20.0*_c103
    cdef double _c159 = 15.0*_c99
    cdef double _c160 = pow(S_T, 6.0)
    cdef double _c161 = 3.0*_c110
    cdef double _c162 = 12.0*_c103
    cdef double _c163 = _c110*r_r
    cdef double _c164 = _c106*_c122
    cdef double _c165 = r_b*r_r
    cdef double _c166 = _c108*_c165
    cdef double _c167 = 3.0*_c108
    cdef double _c168 = 30.0*S_T
    cdef double _c169 = 60.0*S_T
    cdef double _c170 = pow(S_T, 5.0)
    cdef double _c171 = 6.0*_c170
    cdef double _c172 = _c171*r_b
    cdef double _c173 = _c171*r_r
    cdef double _c174 = 15.0*_c108
    cdef double _c175 = _c101*_c117
    cdef double _c176 = 60.0*_c117
    cdef double _c177 = 36.0*_c117
    cdef double _c178 = 12.0*_c170
    cdef double _c179 = 18.0*_c108
    cdef double _c180 = J_r*_c160
    cdef double _c181 = J_r*_c170
    cdef double _c182 = 2.0*r_r
    cdef double _c183 = _c133*r_b
    cdef double _c184 = _c134 + _c183
    cdef double _c185 = _c123*_c165
    cdef double _c186 = 4.0*_c123
    cdef double _c187 = _c181*r_b
    cdef double _c188 = _c112*_c181 + 4.0*_c187
    cdef double _c189 = _c112*r_b
    cdef double _c190 = 6.0*_c105
    cdef double _c191 = (Omega*Omega)
    cdef double _c192 = Omega*_c126
    ctx.k[0] = 0.3333333333333333*_c3  # _k0
    ctx.k[1] = 0.2*_c4  # _k1
    ctx.k[2] = _c5  # _k2
    ctx.k[3] = 0.16666666666666666*_c4  # _k3
    ctx.k[4] = 0.375*_c3  # _k4
    ctx.k[5] = _c6  # _k5
    ctx.k[6] = 0.14285714285714285*_c4  # _k6
    ctx.k[7] = 0.4*_c3  # _k7
    ctx.k[8] = _c7  # _k8
    ctx.k[9] = 0.125*_c4  # _k9
    ctx.k[10] = 0.4166666666666667*_c3  # _k10
    ctx.k[11] = _c8  # _k11
    ctx.k[12] = 0.1111111111111111*_c4  # _k12
    ctx.k[13] = 0.42857142857142855*_c3  # _k13
    ctx.k[14] = _c9  # _k14
    ctx.k[15] = _c11  # _k15
    ctx.k[16] = _c12*_c6  # _k16
    ctx.k[17] = _c14  # _k17
    ctx.k[18] = _c15*_c8  # _k18
    ctx.k[19] = _c17  # _k19
    ctx.k[20] = 0.5*_c18  # _k20
    ctx.k[21] = _c20  # _k21
    ctx.k[22] = _c22  # _k22
    ctx.k[23] = 0.6*_c23  # _k23
    ctx.k[24] = 0.7142857142857143*_c24  # _k24
    ctx.k[25] = _c25  # _k25
    ctx.k[26] = _c28  # _k26
    ctx.k[27] = 2.0*_c29  # _k27
    ctx.k[28] = _c31  # _k28
    ctx.k[29] = _c33  # _k29
    ctx.k[30] = 0.45*_c3  # _k30
    ctx.k[31] = _c34  # _k31
    ctx.k[32] = 0.5357142857142857*_c3  # _k32
    ctx.k[33] = 0.1*_c4  # _k33
    ctx.k[34] = 0.5625*_c3  # _k34
    ctx.k[35] = _c35  # _k35
    ctx.k[36] = _c36  # _k36
    ctx.k[37] = _c12*_c7  # _k37
    ctx.k[38] = _c37  # _k38
    ctx.k[39] = _c15*_c9  # _k39
    ctx.k[40] = _c38  # _k40
    ctx.k[41] = 0.5*_c19  # _k41
    ctx.k[42] = _c40  # _k42
    ctx.k[43] = 0.4*_c23  # _k43
    ctx.k[44] = _c41  # _k44
    ctx.k[45] = 0.625*_c21  # _k45
    ctx.k[46] = 0.5*_c25  # _k46
    ctx.k[47] = 1.8*_c29  # _k47
    ctx.k[48] = 1.125*_c30  # _k48
    ctx.k[49] = 3.2142857142857144*_c42  # _k49
    ctx.k[50] = 0.5714285714285714*_c3  # _k50
    ctx.k[51] = 0.625*_c3  # _k51
    ctx.k[52] = 0.09090909090909091*_c4  # _k52
    ctx.k[53] = 0.6666666666666666*_c3  # _k53
    ctx.k[54] = _c43  # _k54
    ctx.k[55] = _c44  # _k55
    ctx.k[56] = _c12*_c8  # _k56
    ctx.k[57] = _c45  # _k57
    ctx.k[58] = _c15*_c35  # _k58
    ctx.k[59] = _c16*_c43  # _k59
    ctx.k[60] = _c46  # _k60
    ctx.k[61] = 0.3333333333333333*_c19  # _k61
    ctx.k[62] = 0.6*_c47  # _k62
    ctx.k[63] = 0.42857142857142855*_c24  # _k63
    ctx.k[64] = 0.5555555555555556*_c39  # _k64
    ctx.k[65] = _c34*_c7  # _k65
    ctx.k[66] = 2.0*_c32  # _k66
    ctx.k[67] = 1.2*_c29  # _k67
    ctx.k[68] = 3.75*_c48  # _k68
    ctx.k[69] = 2.857142857142857*_c42  # _k69
    ctx.k[70] = 0.6944444444444444*_c3  # _k70
    ctx.k[71] = _c49  # _k71
    ctx.k[72] = _c4  # _k72
    ctx.k[73] = _c50  # _k73
    ctx.k[74] = 0.08333333333333333*_c51  # _k74
    ctx.k[75] = _c52  # _k75
    ctx.k[76] = _c12*_c9  # _k76
    ctx.k[77] = _c13*_c35  # _k77
    ctx.k[78] = _c15*_c43  # _k78
    ctx.k[79] = _c16*_c51  # _k79
    ctx.k[80] = 0.5*_c47  # _k80
    ctx.k[81] = 0.2857142857142857*_c24  # _k81
    ctx.k[82] = 0.375*_c21  # _k82
    ctx.k[83] = 0.4444444444444444*_c39  # _k83
    ctx.k[84] = 0.5454545454545454*_c53  # _k84
    ctx.k[85] = _c34*_c8  # _k85
    ctx.k[86] = 1.25*_c32  # _k86
    ctx.k[87] = 2.142857142857143*_c42  # _k87
    ctx.k[88] = 4.166666666666667*_c54  # _k88
    ctx.k[89] = 3.125*_c48  # _k89
    ctx.k[90] = 0.07692307692307693*_c4  # _k90
    ctx.k[91] = 0.8181818181818182*_c3  # _k91
    ctx.k[92] = _c55  # _k92
    ctx.k[93] = _c56  # _k93
    ctx.k[94] = _c12*_c35  # _k94
    ctx.k[95] = _c13*_c43  # _k95
    ctx.k[96] = _c15*_c51  # _k96
    ctx.k[97] = _c16*_c55  # _k97
    ctx.k[98] = 0.5*_c57  # _k98
    ctx.k[99] = 0.3333333333333333*_c39  # _k99
    ctx.k[100] = 0.25*_c21  # _k100
    ctx.k[101] = 0.4*_c47  # _k101
    ctx.k[102] = 0.45454545454545453*_c53  # _k102
    ctx.k[103] = _c34*_c9  # _k103
    ctx.k[104] = 4.5*_c58  # _k104
    ctx.k[105] = 2.25*_c48  # _k105
    ctx.k[106] = 1.2857142857142858*_c42  # _k106
    ctx.k[107] = 3.3333333333333335*_c54  # _k107
    ctx.k[108] = L_g*_c4 + m_r  # _k108
    ctx.k[109] = _c60  # _k109
    ctx.k[110] = 9.0*_c61  # _k110
    ctx.k[111] = 16.0*_c62  # _k111
    ctx.k[112] = 25.0*_c63  # _k112
    ctx.k[113] = _c55*_c64  # _k113
    ctx.k[114] = _c65  # _k114
    ctx.k[115] = _c66  # _k115
    ctx.k[116] = _c68  # _k116
    ctx.k[117] = _c69  # _k117
    ctx.k[118] = _c70  # _k118
    ctx.k[119] = _c71  # _k119
    ctx.k[120] = _c72  # _k120
    ctx.k[121] = _c74  # _k121
    ctx.k[122] = _c75  # _k122
    ctx.k[123] = _c77  # _k123
    ctx.k[124] = 1.3333333333333333*_c18  # _k124
    ctx.k[125] = 1.8*_c19  # _k125
    ctx.k[126] = 2.2857142857142856*_c21  # _k126
    ctx.k[127] = 2.7777777777777777*_c47  # _k127
    ctx.k[128] = 3.272727272727273*_c57  # _k128
    ctx.k[129] = _c27  # _k129
    ctx.k[130] = _c78  # _k130
    ctx.k[131] = _c79  # _k131
    ctx.k[132] = _c80  # _k132
    ctx.k[133] = _c81  # _k133
    ctx.k[134] = _c82  # _k134
    ctx.k[135] = 25.0*_c58  # _k135
    ctx.k[136] = _c83  # _k136
    ctx.k[137] = _c84  # _k137
    ctx.k[138] = _c85  # _k138
    ctx.k[139] = _c86  # _k139
    ctx.k[140] = _c87  # _k140
    ctx.k[141] = _c88  # _k141
    ctx.k[142] = 7.2*_c32  # _k142
    ctx.k[143] = 14.285714285714286*_c48  # _k143
    ctx.k[144] = _c89  # _k144
    ctx.k[145] = _c90  # _k145
    ctx.k[146] = _c91  # _k146
    ctx.k[147] = _c92  # _k147
    ctx.k[148] = _c93  # _k148
    ctx.k[149] = _c94  # _k149
    ctx.k[150] = _c95  # _k150
    ctx.k[151] = _c96  # _k151
    ctx.k[152] = _c97  # _k152
    ctx.k[153] = _c98  # _k153
    ctx.k[154] = _c100 + _c102*r_b + _c104*r_r + _c105*_c107 + _c99  # _k154
    ctx.k[155] = _c108  # _k155
    ctx.k[156] = _c109  # _k156
    ctx.k[157] = _c105*_c113 + _c106*_c113 + _c111*_c112  # _k157
    ctx.k[158] = S_T*_c102 + S_T*_c104 + _c114*_c115 + _c114*_c116  # _k158
    ctx.k[159] = _c119 + _c120  # _k159
    ctx.k[160] = _c107*_c110 + _c121*r_r + 6.0*_c122  # _k160
    ctx.k[161] = _c123  # _k161
    ctx.k[162] = _c105 + _c106 + _c125  # _k162
    ctx.k[163] = _c110  # _k163
    ctx.k[164] = _c127 + _c128  # _k164
    ctx.k[165] = _c130  # _k165
    ctx.k[166] = _c131  # _k166
    ctx.k[167] = -_c130  # _k167
    ctx.k[168] = -J_r*_c127 - J_r*_c128  # _k168
    ctx.k[169] = -_c132  # _k169
    ctx.k[170] = -_c135  # _k170
    ctx.k[171] = _c135  # _k171
    ctx.k[172] = -_c136  # _k172
    ctx.k[173] = -_c137  # _k173
    ctx.k[174] = -_c5  # _k174
    ctx.k[175] = -_c6  # _k175
    ctx.k[176] = -_c7  # _k176
    ctx.k[177] = -_c138  # _k177
    ctx.k[178] = -5.0*_c6  # _k178
    ctx.k[179] = -_c59  # _k179
    ctx.k[180] = -3.0*_c137  # _k180
    ctx.k[181] = -_c139  # _k181
    ctx.k[182] = r_b + r_r  # _k182
    ctx.k[183] = -_c71  # _k183
    ctx.k[184] = -_c68  # _k184
    ctx.k[185] = -_c49*_c7  # _k185
    ctx.k[186] = -_c49*_c9  # _k186
    ctx.k[187] = -10.0*_c67  # _k187
    ctx.k[188] = -8.0*_c61  # _k188
    ctx.k[189] = -_c16*_c6  # _k189
    ctx.k[190] = -_c60  # _k190
    ctx.k[191] = -_c11  # _k191
    ctx.k[192] = -_c141  # _k192
    ctx.k[193] = -3.0*_c143  # _k193
    ctx.k[194] = -2.0*_c144  # _k194
    ctx.k[195] = -2.5*_c145  # _k195
    ctx.k[196] = -1.5*_c146  # _k196
    ctx.k[197] = -_c18  # _k197
    ctx.k[198] = -_c88  # _k198
    ctx.k[199] = -2.4*_c19  # _k199
    ctx.k[200] = -_c84  # _k200
    ctx.k[201] = -1.4285714285714286*_c24  # _k201
    ctx.k[202] = -1.2*_c23  # _k202
    ctx.k[203] = -1.3333333333333333*_c19  # _k203
    ctx.k[204] = -1.5*_c23  # _k204
    ctx.k[205] = -1.5*_c21  # _k205
    ctx.k[206] = -0.6666666666666666*_c18  # _k206
    ctx.k[207] = -_c27  # _k207
    ctx.k[208] = -_c94  # _k208
    ctx.k[209] = -5.0*_c32  # _k209
    ctx.k[210] = -_c90  # _k210
    ctx.k[211] = -4.0*_c29  # _k211
    ctx.k[212] = -_c79  # _k212
    ctx.k[213] = -2.0*_c25  # _k213
    ctx.k[214] = -7.5*_c29  # _k214
    ctx.k[215] = -1.5*_c25  # _k215
    ctx.k[216] = -30.0*_c73  # _k216
    ctx.k[217] = -20.0*_c62  # _k217
    ctx.k[218] = -_c49*_c8  # _k218
    ctx.k[219] = -_c35*_c49  # _k219
    ctx.k[220] = -10.0*_c62  # _k220
    ctx.k[221] = -8.0*_c67  # _k221
    ctx.k[222] = -_c138*m_r  # _k222
    ctx.k[223] = -_c13*_c6  # _k223
    ctx.k[224] = -_c36  # _k224
    ctx.k[225] = -6.0*_c143  # _k225
    ctx.k[226] = -3.0*_c144  # _k226
    ctx.k[227] = -7.5*_c147  # _k227
    ctx.k[228] = -4.5*_c145  # _k228
    ctx.k[229] = -_c19  # _k229
    ctx.k[230] = -2.0*_c24  # _k230
    ctx.k[231] = -2.857142857142857*_c21  # _k231
    ctx.k[232] = -3.75*_c39  # _k232
    ctx.k[233] = -1.1428571428571428*_c24  # _k233
    ctx.k[234] = -1.2*_c19  # _k234
    ctx.k[235] = -1.25*_c21  # _k235
    ctx.k[236] = -1.3333333333333333*_c39  # _k236
    ctx.k[237] = -0.8*_c23  # _k237
    ctx.k[238] = -_c148*_c6  # _k238
    ctx.k[239] = -_c25  # _k239
    ctx.k[240] = -_c95  # _k240
    ctx.k[241] = -_c50*_c9  # _k241
    ctx.k[242] = -6.428571428571429*_c42  # _k242
    ctx.k[243] = -3.6*_c29  # _k243
    ctx.k[244] = -4.5*_c29  # _k244
    ctx.k[245] = -2.25*_c30  # _k245
    ctx.k[246] = -_c31  # _k246
    ctx.k[247] = -30.0*_c63  # _k247
    ctx.k[248] = -20.0*_c73  # _k248
    ctx.k[249] = -_c43*_c49  # _k249
    ctx.k[250] = -10.0*_c73  # _k250
    ctx.k[251] = -8.0*_c62  # _k251
    ctx.k[252] = -_c16*_c8  # _k252
    ctx.k[253] = -_c14  # _k253
    ctx.k[254] = -_c44  # _k254
    ctx.k[255] = -10.0*_c147  # _k255
    ctx.k[256] = -12.857142857142858*_c149  # _k256
    ctx.k[257] = -7.2*_c143  # _k257
    ctx.k[258] = -_c24  # _k258
    ctx.k[259] = -_c21  # _k259
    ctx.k[260] = -1.7142857142857142*_c21  # _k260
    ctx.k[261] = -3.3333333333333335*_c47  # _k261
    ctx.k[262] = -1.1111111111111112*_c39  # _k262
    ctx.k[263] = -1.2*_c47  # _k263
    ctx.k[264] = -0.8571428571428571*_c24  # _k264
    ctx.k[265] = -2.5*_c39  # _k265
    ctx.k[266] = -_c20  # _k266
    ctx.k[267] = -0.4*_c19  # _k267
    ctx.k[268] = -_c30  # _k268
    ctx.k[269] = -10.0*_c42  # _k269
    ctx.k[270] = -4.0*_c32  # _k270
    ctx.k[271] = -17.142857142857142*_c48  # _k271
    ctx.k[272] = -5.714285714285714*_c42  # _k272
    ctx.k[273] = -4.8*_c32  # _k273
    ctx.k[274] = -7.5*_c48  # _k274
    ctx.k[275] = -2.4*_c29  # _k275
    ctx.k[276] = -1.5*_c29  # _k276
    ctx.k[277] = -30.0*_c76  # _k277
    ctx.k[278] = -20.0*_c63  # _k278
    ctx.k[279] = -_c49*_c51  # _k279
    ctx.k[280] = -10.0*_c63  # _k280
    ctx.k[281] = -8.0*_c73  # _k281
    ctx.k[282] = -_c17  # _k282
    ctx.k[283] = -_c37  # _k283
    ctx.k[284] = -_c52  # _k284
    ctx.k[285] = -14.285714285714286*_c149  # _k285
    ctx.k[286] = -18.75*_c150  # _k286
    ctx.k[287] = -_c47  # _k287
    ctx.k[288] = -3.0*_c53  # _k288
    ctx.k[289] = -2.2222222222222223*_c47  # _k289
    ctx.k[290] = -1.0909090909090908*_c53  # _k290
    ctx.k[291] = -0.8888888888888888*_c39  # _k291
    ctx.k[292] = -0.8571428571428571*_c21  # _k292
    ctx.k[293] = -_c41  # _k293
    ctx.k[294] = -1.5*_c39  # _k294
    ctx.k[295] = -_c22  # _k295
    ctx.k[296] = -0.3333333333333333*_c24  # _k296
    ctx.k[297] = -_c29  # _k297
    ctx.k[298] = -5.0*_c42  # _k298
    ctx.k[299] = -18.75*_c54  # _k299
    ctx.k[300] = -10.714285714285714*_c48  # _k300
    ctx.k[301] = -4.285714285714286*_c42  # _k301
    ctx.k[302] = -8.333333333333334*_c54  # _k302
    ctx.k[303] = -6.25*_c48  # _k303
    ctx.k[304] = -_c33  # _k304
    ctx.k[305] = -1.5*_c32  # _k305
    ctx.k[306] = -30.0*_c151  # _k306
    ctx.k[307] = -20.0*_c76  # _k307
    ctx.k[308] = -_c49*_c55  # _k308
    ctx.k[309] = -10.0*_c76  # _k309
    ctx.k[310] = -8.0*_c63  # _k310
    ctx.k[311] = -_c38  # _k311
    ctx.k[312] = -_c45  # _k312
    ctx.k[313] = -_c56  # _k313
    ctx.k[314] = -25.0*_c152  # _k314
    ctx.k[315] = -_c57  # _k315
    ctx.k[316] = -2.0*_c53  # _k316
    ctx.k[317] = -2.727272727272727*_c57  # _k317
    ctx.k[318] = -0.9090909090909091*_c53  # _k318
    ctx.k[319] = -1.3333333333333333*_c47  # _k319
    ctx.k[320] = -0.8*_c47  # _k320
    ctx.k[321] = -0.75*_c39  # _k321
    ctx.k[322] = -_c40  # _k322
    ctx.k[323] = -0.2857142857142857*_c21  # _k323
    ctx.k[324] = -_c46  # _k324
    ctx.k[325] = -_c32  # _k325
    ctx.k[326] = -20.0*_c58  # _k326
    ctx.k[327] = -_c50*_c55  # _k327
    ctx.k[328] = -11.25*_c54  # _k328
    ctx.k[329] = -5.142857142857143*_c48  # _k329
    ctx.k[330] = -6.666666666666667*_c54  # _k330
    ctx.k[331] = -2.5714285714285716*_c42  # _k331
    ctx.k[332] = -4.5*_c48  # _k332
    ctx.k[333] = -1.5*_c42  # _k333
    ctx.k[334] = -_c148  # _k334
    ctx.k[335] = -180.0*_c151  # _k335
    ctx.k[336] = -100.0*_c63  # _k336
    ctx.k[337] = -48.0*_c62  # _k337
    ctx.k[338] = -18.0*_c61  # _k338
    ctx.k[339] = -0.5*_c141  # _k339
    ctx.k[340] = -270.0*_c76  # _k340
    ctx.k[341] = -192.0*_c63  # _k341
    ctx.k[342] = -140.0*_c73  # _k342
    ctx.k[343] = -126.0*_c73  # _k343
    ctx.k[344] = -90.0*_c62  # _k344
    ctx.k[345] = -72.0*_c62  # _k345
    ctx.k[346] = -72.0*_c151  # _k346
    ctx.k[347] = -60.0*_c67  # _k347
    ctx.k[348] = -_c77  # _k348
    ctx.k[349] = -50.0*_c149  # _k349
    ctx.k[350] = -50.0*_c67  # _k350
    ctx.k[351] = -50.0*_c63  # _k351
    ctx.k[352] = -_c75  # _k352
    ctx.k[353] = -_c74  # _k353
    ctx.k[354] = -_c72  # _k354
    ctx.k[355] = -32.0*_c61  # _k355
    ctx.k[356] = -32.0*_c62  # _k356
    ctx.k[357] = -_c69  # _k357
    ctx.k[358] = -_c70  # _k358
    ctx.k[359] = -18.0*_c143  # _k359
    ctx.k[360] = -18.0*_c6*m_r  # _k360
    ctx.k[361] = -_c66  # _k361
    ctx.k[362] = -_c65  # _k362
    ctx.k[363] = -_c153*m_r  # _k363
    ctx.k[364] = -112.5*_c152  # _k364
    ctx.k[365] = -4.5*_c144  # _k365
    ctx.k[366] = -150.0*_c150  # _k366
    ctx.k[367] = -90.0*_c149  # _k367
    ctx.k[368] = -60.0*_c147  # _k368
    ctx.k[369] = -45.0*_c147  # _k369
    ctx.k[370] = -30.0*_c143  # _k370
    ctx.k[371] = -18.0*_c145  # _k371
    ctx.k[372] = -18.0*_c57  # _k372
    ctx.k[373] = -15.0*_c143  # _k373
    ctx.k[374] = -10.0*_c145  # _k374
    ctx.k[375] = -8.0*_c21  # _k375
    ctx.k[376] = -_c138*_c142  # _k376
    ctx.k[377] = -3.0*_c146  # _k377
    ctx.k[378] = -2.0*_c18  # _k378
    ctx.k[379] = -12.5*_c47  # _k379
    ctx.k[380] = -4.5*_c19  # _k380
    ctx.k[381] = -_c28  # _k381
    ctx.k[382] = -50.0*_c48  # _k382
    ctx.k[383] = -30.0*_c53  # _k383
    ctx.k[384] = -24.0*_c47  # _k384
    ctx.k[385] = -20.0*_c39  # _k385
    ctx.k[386] = -18.0*_c39  # _k386
    ctx.k[387] = -18.0*_c32  # _k387
    ctx.k[388] = -15.0*_c21  # _k388
    ctx.k[389] = -12.0*_c21  # _k389
    ctx.k[390] = -12.0*_c24  # _k390
    ctx.k[391] = -10.0*_c24  # _k391
    ctx.k[392] = -8.0*_c19  # _k392
    ctx.k[393] = -6.0*_c23  # _k393
    ctx.k[394] = -_c82  # _k394
    ctx.k[395] = -_c81  # _k395
    ctx.k[396] = -_c80  # _k396
    ctx.k[397] = -_c78  # _k397
    ctx.k[398] = -112.5*_c58  # _k398
    ctx.k[399] = -6.545454545454546*_c57  # _k399
    ctx.k[400] = -5.555555555555555*_c47  # _k400
    ctx.k[401] = -4.571428571428571*_c21  # _k401
    ctx.k[402] = -_c87  # _k402
    ctx.k[403] = -3.6*_c19  # _k403
    ctx.k[404] = -_c85  # _k404
    ctx.k[405] = -_c86  # _k405
    ctx.k[406] = -_c83  # _k406
    ctx.k[407] = -4.5*_c30  # _k407
    ctx.k[408] = -2.6666666666666665*_c18  # _k408
    ctx.k[409] = -150.0*_c54  # _k409
    ctx.k[410] = -90.0*_c48  # _k410
    ctx.k[411] = -60.0*_c42  # _k411
    ctx.k[412] = -50.0*_c58  # _k412
    ctx.k[413] = -45.0*_c42  # _k413
    ctx.k[414] = -30.0*_c32  # _k414
    ctx.k[415] = -_c96  # _k415
    ctx.k[416] = -18.0*_c29  # _k416
    ctx.k[417] = -15.0*_c32  # _k417
    ctx.k[418] = -10.0*_c29  # _k418
    ctx.k[419] = -_c93  # _k419
    ctx.k[420] = -_c138*_c3  # _k420
    ctx.k[421] = -_c92  # _k421
    ctx.k[422] = -_c91  # _k422
    ctx.k[423] = -_c89  # _k423
    ctx.k[424] = -2.0*_c27  # _k424
    ctx.k[425] = -28.571428571428573*_c48  # _k425
    ctx.k[426] = -_c98  # _k426
    ctx.k[427] = -_c97  # _k427
    ctx.k[428] = -14.4*_c32  # _k428
    ctx.k[429] = _c129  # _k429
    ctx.k[430] = _c154*r_b + _c154*r_r  # _k430
    ctx.k[431] = -_c129  # _k431
    ctx.k[432] = _c132  # _k432
    ctx.k[433] = _c101*_c158 + _c105*_c159 + _c106*_c157 + _c155*r_b + _c156*r_r + pow(r_b, 6.0) + pow(r_r, 6.0)  # _k433
    ctx.k[434] = _c160  # _k434
    ctx.k[435] = 3.0*_c160  # _k435
    ctx.k[436] = _c100*_c161 + _c101*_c121 + _c161*_c99 + _c162*_c163 + 18.0*_c164  # _k436
    ctx.k[437] = _c105*_c167 + _c106*_c167 + 6.0*_c166  # _k437
    ctx.k[438] = S_T*_c155 + S_T*_c156 + _c100*_c168*r_b + _c101*_c106*_c169 + _c103*_c105*_c169 + _c168*_c99*r_r  # _k438
    ctx.k[439] = _c172 + _c173  # _k439
    ctx.k[440] = 60.0*_c101*_c111 + 60.0*_c103*_c163 + _c110*_c157 + _c110*_c159 + 90.0*_c164  # _k440
    ctx.k[441] = _c105*_c174 + _c106*_c174 + 30.0*_c166  # _k441
    ctx.k[442] = _c115*_c176 + _c116*_c176 + _c117*_c158 + 20.0*_c175  # _k442
    ctx.k[443] = _c115*_c177 + _c116*_c177 + _c117*_c162 + 12.0*_c175  # _k443
    ctx.k[444] = _c178*r_b + _c178*r_r  # _k444
    ctx.k[445] = _c105*_c179 + _c106*_c179 + 36.0*_c166  # _k445
    ctx.k[446] = 2.0*_c180  # _k446
    ctx.k[447] = _c124*_c181 + _c181*_c182  # _k447
    ctx.k[448] = _c184  # _k448
    ctx.k[449] = -_c123  # _k449
    ctx.k[450] = -_c184  # _k450
    ctx.k[451] = -_c131  # _k451
    ctx.k[452] = -4.0*_c180  # _k452
    ctx.k[453] = -_c105*_c186 - _c106*_c186 - 8.0*_c185  # _k453
    ctx.k[454] = -_c188  # _k454
    ctx.k[455] = -_c105*_c130 - _c106*_c130 - _c129*_c189  # _k455
    ctx.k[456] = 2.0*J_r*_c175 + 2.0*_c103*_c133 + _c107*_c134 + _c183*_c190  # _k456
    ctx.k[457] = _c105*_c132 + _c106*_c132 + _c123*_c189  # _k457
    ctx.k[458] = -8.0*_c181*r_r - 8.0*_c187  # _k458
    ctx.k[459] = -J_r*_c119 - J_r*_c120  # _k459
    ctx.k[460] = _c188  # _k460
    ctx.k[461] = _c107*_c123 + _c123*_c190 + 12.0*_c185  # _k461
    ctx.k[462] = J_r*_c172 + J_r*_c173  # _k462
    ctx.k[463] = _c191*r_b + _c191*r_r  # _k463
    ctx.k[464] = _c139  # _k464
    ctx.k[465] = S_T*_c191  # _k465
    ctx.k[466] = -S_T  # _k466
    ctx.k[467] = -Omega*_c124 - Omega*_c182  # _k467
    ctx.k[468] = _c126  # _k468
    ctx.k[469] = 4.0*_c136  # _k469
    ctx.k[470] = 6.0*_c137  # _k470
    ctx.k[471] = _c153  # _k471
    ctx.k[472] = 10.0*_c6  # _k472
    ctx.k[473] = 12.0*_c5  # _k473
    ctx.k[474] = 12.0*_c7  # _k474
    ctx.k[475] = 20.0*_c6  # _k475
    ctx.k[476] = 30.0*_c7  # _k476
    ctx.k[477] = -_c192  # _k477
    ctx.k[478] = -_c126  # _k478
    ctx.k[479] = _c192  # _k479
    ctx.k[480] = -d  # _k480
    ctx.k[481] = -Omega  # _k481
    ctx.k[482] = _c136  # _k482
    ctx.k[483] = _c137  # _k483


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
    cdef double _k343 = ctx.k[343]
    cdef double _k344 = ctx.k[344]
    cdef double _k345 = ctx.k[345]
    cdef double _k346 = ctx.k[346]
    cdef double _k347 = ctx.k[347]
    cdef double _k348 = ctx.k[348]
    cdef double _k349 = ctx.k[349]
    cdef double _k350 = ctx.k[350]
    cdef double _k351 = ctx.k[351]
    cdef double _k352 = ctx.k[352]
    cdef double _k353 = ctx.k[353]
    cdef double _k354 = ctx.k[354]
    cdef double _k355 = ctx.k[355]
    cdef double _k356 = ctx.k[356]
    cdef double _k357 = ctx.k[357]
    cdef double _k358 = ctx.k[358]
    cdef double _k359 = ctx.k[359]
    cdef double _k360 = ctx.k[360]
    cdef double _k361 = ctx.k[361]
    cdef double _k362 = ctx.k[362]
    cdef double _k363 = ctx.k[363]
    cdef double _k364 = ctx.k[364]
    cdef double _k365 = ctx.k[365]
    cdef double _k366 = ctx.k[366]
    cdef double _k367 = ctx.k[367]
    cdef double _k368 = ctx.k[368]
    cdef double _k369 = ctx.k[369]
    cdef double _k370 = ctx.k[370]
    cdef double _k371 = ctx.k[371]
    cdef double _k372 = ctx.k[372]
    cdef double _k373 = ctx.k[373]
    cdef double _k374 = ctx.k[374]
    cdef double _k375 = ctx.k[375]
    cdef double _k376 = ctx.k[376]
    cdef double _k377 = ctx.k[377]
    cdef double _k378 = ctx.k[378]
    cdef double _k379 = ctx.k[379]
    cdef double _k380 = ctx.k[380]
    cdef double _k381 = ctx.k[381]
    cdef double _k382 = ctx.k[382]
    cdef double _k383 = ctx.k[383]
    cdef double _k384 = ctx.k[384]
    cdef double _k385 = ctx.k[385]
    cdef double _k386 = ctx.k[386]
    cdef double _k387 = ctx.k[387]
    cdef double _k388 = ctx.k[388]
    cdef double _k389 = ctx.k[389]
    cdef double _k390 = ctx.k[390]
    cdef double _k391 = ctx.k[391]
    cdef double _k392 = ctx.k[392]
    cdef double _k393 = ctx.k[393]
    cdef double _k394 = ctx.k[394]
    cdef double _k395 = ctx.k[395]
    cdef double _k396 = ctx.k[396]
    cdef double _k397 = ctx.k[397]
    cdef double _k398 = ctx.k[398]
    cdef double _k399 = ctx.k[399]
    cdef double _k400 = ctx.k[400]
    cdef double _k401 = ctx.k[401]
    cdef double _k402 = ctx.k[402]
    cdef double _k403 = ctx.k[403]
    cdef double _k404 = ctx.k[404]
    cdef double _k405 = ctx.k[405]
    cdef double _k406 = ctx.k[406]
    cdef double _k407 = ctx.k[407]
    cdef double _k408 = ctx.k[408]
    cdef double _k409 = ctx.k[409]
    cdef double _k410 = ctx.k[410]
    cdef double _k411 = ctx.k[411]
    cdef double _k412 = ctx.k[412]
    cdef double _k413 = ctx.k[413]
    cdef double _k414 = ctx.k[414]
    cdef double _k415 = ctx.k[415]
    cdef double _k416 = ctx.k[416]
    cdef double _k417 = ctx.k[417]
    cdef double _k418 = ctx.k[418]
    cdef double _k419 = ctx.k[419]
    cdef double _k420 = ctx.k[420]
    cdef double _k421 = ctx.k[421]
    cdef double _k422 = ctx.k[422]
    cdef double _k423 = ctx.k[423]
    cdef double _k424 = ctx.k[424]
    cdef double _k425 = ctx.k[425]
    cdef double _k426 = ctx.k[426]
    cdef double _k427 = ctx.k[427]
    cdef double _k428 = ctx.k[428]
    cdef double _k429 = ctx.k[429]
    cdef double _k430 = ctx.k[430]
    cdef double _k431 = ctx.k[431]
    cdef double _k432 = ctx.k[432]
    cdef double _k433 = ctx.k[433]
    cdef double _k434 = ctx.k[434]
    cdef double _k435 = ctx.k[435]
    cdef double _k436 = ctx.k[436]
    cdef double _k437 = ctx.k[437]
    cdef double _k438 = ctx.k[438]
    cdef double _k439 = ctx.k[439]
    cdef double _k440 = ctx.k[440]
    cdef double _k441 = ctx.k[441]
    cdef double _k442 = ctx.k[442]
    cdef double _k443 = ctx.k[443]
    cdef double _k444 = ctx.k[444]
    cdef double _k445 = ctx.k[445]
    cdef double _k446 = ctx.k[446]
    cdef double _k447 = ctx.k[447]
    cdef double _k448 = ctx.k[448]
    cdef double _k449 = ctx.k[449]
    cdef double _k450 = ctx.k[450]
    cdef double _k451 = ctx.k[451]
    cdef double _k452 = ctx.k[452]
    cdef double _k453 = ctx.k[453]
    cdef double _k454 = ctx.k[454]
    cdef double _k455 = ctx.k[455]
    cdef double _k456 = ctx.k[456]
    cdef double _k457 = ctx.k[457]
    cdef double _k458 = ctx.k[458]
    cdef double _k459 = ctx.k[459]
    cdef double _k460 = ctx.k[460]
    cdef double _k461 = ctx.k[461]
    cdef double _k462 = ctx.k[462]
    cdef double _k463 = ctx.k[463]
    cdef double _k464 = ctx.k[464]
    cdef double _k465 = ctx.k[465]
    cdef double _k466 = ctx.k[466]
    cdef double _k467 = ctx.k[467]
    cdef double _k468 = ctx.k[468]
    cdef double _k469 = ctx.k[469]
    cdef double _k470 = ctx.k[470]
    cdef double _k471 = ctx.k[471]
    cdef double _k472 = ctx.k[472]
    cdef double _k473 = ctx.k[473]
    cdef double _k474 = ctx.k[474]
    cdef double _k475 = ctx.k[475]
    cdef double _k476 = ctx.k[476]
    cdef double _k477 = ctx.k[477]
    cdef double _k478 = ctx.k[478]
    cdef double _k479 = ctx.k[479]
    cdef double _k480 = ctx.k[480]
    cdef double _k481 = ctx.k[481]
    cdef double _k482 = ctx.k[482]
    cdef double _k483 = ctx.k[483]
    cdef double b1 = _y[0]
    cdef double b2 = _y[1]
    cdef double b3 = _y[2]
    cdef double b4 = _y[3]
    cdef double b5 = _y[4]
    cdef double xE = _y[5]
    cdef double theta = _y[6]
    cdef double b1d = _y[7]
    cdef double b2d = _y[8]
    cdef double b3d = _y[9]
    cdef double b4d = _y[10]
    cdef double b5d = _y[11]
    cdef double xEd = _y[12]
    cdef double thetad = _y[13]
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
    cdef double _s13 = _k12*_s2 + _s1
    cdef double _s14 = pow(xE, 7.0)
    cdef double _s15 = _k14*_s14
    cdef double _s16 = _s15*(_k13 + _s13)
    cdef double _s17 = _s0*b1
    cdef double _s18 = _s3*b2
    cdef double _s19 = _s6*b3
    cdef double _s20 = _s10*b4
    cdef double _s21 = _s14*b5
    cdef double _s22 = _s3*b1
    cdef double _s23 = _s10*b3
    cdef double _s24 = pow(xE, 8.0)
    cdef double _s25 = _s24*b5
    cdef double _s26 = _s6*b2
    cdef double _s27 = _s14*b4
    cdef double _s28 = _s0*b2
    cdef double _s29 = _s2*b1
    cdef double _s30 = _s6*b4
    cdef double _s31 = _s3*b3
    cdef double _s32 = _s10*b5
    cdef double _s33 = _k15*_s17 + _k16*_s18 + _k17*_s19 + _k18*_s20 + _k19*_s21 + _k20*_s22 + _k21*_s23 + _k22*_s25 + _k23*_s26 + _k24*_s27 + _k25*_s28 + _k26*_s29 + _k27*_s30 + _k28*_s31 + _k29*_s32
    cdef double _s34 = _s11*(_k31 + _s9)
    cdef double _s35 = _s15*(_k32 + _s13)
    cdef double _s36 = _k33*_s2 + _s1
    cdef double _s37 = _k35*_s24
    cdef double _s38 = _s37*(_k34 + _s36)
    cdef double _s39 = _s10*b2
    cdef double _s40 = pow(xE, 9.0)
    cdef double _s41 = _s40*b5
    cdef double _s42 = _s6*b1
    cdef double _s43 = _s14*b3
    cdef double _s44 = _s24*b4
    cdef double _s45 = _k29*_s20 + _k36*_s22 + _k37*_s26 + _k38*_s23 + _k39*_s27 + _k40*_s25 + _k41*_s39 + _k42*_s41 + _k43*_s42 + _k44*_s43 + _k45*_s44 + _k46*_s17 + _k47*_s19 + _k48*_s18 + _k49*_s21
    cdef double _s46 = _s37*(_k51 + _s36)
    cdef double _s47 = _k52*_s2 + _s1
    cdef double _s48 = _k54*_s40
    cdef double _s49 = _s48*(_k53 + _s47)
    cdef double _s50 = _s24*b3
    cdef double _s51 = _s10*b1
    cdef double _s52 = pow(xE, 10.0)
    cdef double _s53 = _s52*b5
    cdef double _s54 = _s14*b2
    cdef double _s55 = _s40*b4
    cdef double _s56 = _k55*_s42 + _k56*_s39 + _k57*_s43 + _k58*_s44 + _k59*_s41 + _k60*_s50 + _k61*_s51 + _k62*_s53 + _k63*_s54 + _k64*_s55 + _k65*_s22 + _k66*_s23 + _k67*_s26 + _k68*_s25 + _k69*_s27
    cdef double _s57 = _k74*_s52*(_k71*xE + _k72*_s2 + _k73)
    cdef double _s58 = _s52*b4
    cdef double _s59 = _s14*b1
    cdef double _s60 = _s24*b2
    cdef double _s61 = _s40*b3
    cdef double _s62 = pow(xE, 11.0)
    cdef double _s63 = _s62*b5
    cdef double _s64 = _k75*_s51 + _k76*_s54 + _k77*_s50 + _k78*_s55 + _k79*_s53 + _k80*_s58 + _k81*_s59 + _k82*_s60 + _k83*_s61 + _k84*_s63 + _k85*_s42 + _k86*_s39 + _k87*_s43 + _k88*_s41 + _k89*_s44
    cdef double _s65 = pow(xE, 12.0)
    cdef double _s66 = _k100*_s24*b1 + _k101*_s52*b3 + _k102*_s62*b4 + _k103*_s51 + _k104*_s53 + _k105*_s50 + _k106*_s54 + _k107*_s55 + _k93*_s59 + _k94*_s60 + _k95*_s61 + _k96*_s58 + _k97*_s63 + _k98*_s65*b5 + _k99*_s40*b2
    cdef double _s67 = (b1*b1)
    cdef double _s68 = _s67*xE
    cdef double _s69 = _s17*b2
    cdef double _s70 = _s22*b3
    cdef double _s71 = _s19*b2
    cdef double _s72 = _s20*b2
    cdef double _s73 = _s21*b2
    cdef double _s74 = _s27*b3
    cdef double _s75 = _s25*b3
    cdef double _s76 = _s41*b4
    cdef double _s77 = _s29*b2
    cdef double _s78 = _s17*b3
    cdef double _s79 = _s22*b4
    cdef double _s80 = _s42*b5
    cdef double _s81 = _s18*b3
    cdef double _s82 = _s26*b4
    cdef double _s83 = _s32*b2
    cdef double _s84 = _s20*b3
    cdef double _s85 = _s25*b4
    cdef double _s86 = _s21*b3
    cdef double _s87 = _s2*_s67
    cdef double _s88 = (b2*b2)
    cdef double _s89 = _s3*_s88
    cdef double _s90 = (b3*b3)
    cdef double _s91 = _s10*_s90
    cdef double _s92 = (b4*b4)
    cdef double _s93 = _s24*_s92
    cdef double _s94 = (b5*b5)
    cdef double _s95 = _s52*_s94
    cdef double _s96 = _s0*_s88
    cdef double _s97 = _s40*_s94
    cdef double _s98 = _s6*_s90
    cdef double _s99 = _s14*_s92
    cdef double _s100 = (_cam0[0]*_cam0[0])
    cdef double _s101 = (_cam0[1]*_cam0[1])
    cdef double _s102 = (1.0/(_cam0[0]*_k164 + _k162 + _k163*_s100 + _k163*_s101))
    cdef double _s103 = _cam0[2]*_s102
    cdef double _s104 = (_cam0[1]*_cam0[1]*_cam0[1]*_cam0[1])
    cdef double _s105 = (_cam0[0]*_cam0[0]*_cam0[0])
    cdef double _s106 = (_cam0[0]*_cam0[0]*_cam0[0]*_cam0[0])
    cdef double _s107 = _cam0[0]*_s101
    cdef double _s108 = _s100*_s101
    cdef double _s109 = (1.0/(_cam0[0]*_k158 + _k154 + _k155*_s104 + _k155*_s106 + _k156*_s108 + _k157*_s101 + _k159*_s105 + _k159*_s107 + _k160*_s100))
    cdef double _s110 = _k161*_s109
    cdef double _s111 = (_cam0[2]*_cam0[2])
    cdef double _s112 = _s109*_s111
    cdef double _s113 = _cam0[0]*_s112
    cdef double _s114 = _cam0[2]*_s109
    cdef double _s115 = _k170*_s114
    cdef double _s116 = _k169*_s114
    cdef double _s117 = _s100*_s111
    cdef double _s118 = _k172*_s2
    cdef double _s119 = _k173*_s0
    cdef double _s120 = _k174*_s3
    cdef double _s121 = _k175*_s6
    cdef double _s122 = _k176*_s10
    cdef double _s123 = b1*xE
    cdef double _s124 = _s6*b5
    cdef double _s125 = _s3*b4
    cdef double _s126 = _s0*b3
    cdef double _s127 = _s2*b2
    cdef double _s128 = Omega*t - theta
    cdef double _s129 = sin(_s128)
    cdef double _s130 = S_T*_cam0[1]
    cdef double _s131 = S_T*_cam0[0]
    cdef double _s132 = _k182 + _s131
    cdef double _s133 = cos(_s128)
    cdef double _s134 = _s132*_s133
    cdef double _s135 = _s129*_s132
    cdef double _s136 = _s14*xEd
    cdef double _s137 = _s136*b5d
    cdef double _s138 = _s10*xEd
    cdef double _s139 = _s138*b4d
    cdef double _s140 = _s6*xEd
    cdef double _s141 = _s140*b3d
    cdef double _s142 = _s3*xEd
    cdef double _s143 = _s142*b2d
    cdef double _s144 = b1d*xEd
    cdef double _s145 = _s0*_s144
    cdef double _s146 = _s142*b1d
    cdef double _s147 = _s136*b4d
    cdef double _s148 = _s140*b2d
    cdef double _s149 = _s138*b3d
    cdef double _s150 = _s24*xEd
    cdef double _s151 = _s150*b5d
    cdef double _s152 = b2d*xEd
    cdef double _s153 = (xEd*xEd)
    cdef double _s154 = _s153*_s32
    cdef double _s155 = _s153*_s30
    cdef double _s156 = _s153*_s31
    cdef double _s157 = _s153*_s28
    cdef double _s158 = _s153*_s29
    cdef double _s159 = _s153*_s21
    cdef double _s160 = _s153*_s19
    cdef double _s161 = _s153*_s20
    cdef double _s162 = _s153*_s18
    cdef double _s163 = _s153*_s17
    cdef double _s164 = _k210*_s126
    cdef double _s165 = _s138*b2d
    cdef double _s166 = _s136*b3d
    cdef double _s167 = _s150*b4d
    cdef double _s168 = _s40*xEd
    cdef double _s169 = _s168*b5d
    cdef double _s170 = _s140*b1d
    cdef double _s171 = _s153*_s23
    cdef double _s172 = _s153*_s27
    cdef double _s173 = _s153*_s25
    cdef double _s174 = _s153*_s26
    cdef double _s175 = _s153*_s22
    cdef double _s176 = _s150*b3d
    cdef double _s177 = _s168*b4d
    cdef double _s178 = _s52*xEd
    cdef double _s179 = _s178*b5d
    cdef double _s180 = _s136*b2d
    cdef double _s181 = _s138*b1d
    cdef double _s182 = _s153*_s39
    cdef double _s183 = _s153*_s43
    cdef double _s184 = _s153*_s41
    cdef double _s185 = _s153*_s44
    cdef double _s186 = _s153*_s42
    cdef double _s187 = _s178*b4d
    cdef double _s188 = b5d*xEd
    cdef double _s189 = _s188*_s62
    cdef double _s190 = _s168*b3d
    cdef double _s191 = _s136*b1d
    cdef double _s192 = _s150*b2d
    cdef double _s193 = _s153*_s53
    cdef double _s194 = _s153*_s55
    cdef double _s195 = _s153*_s54
    cdef double _s196 = _s153*_s50
    cdef double _s197 = _s153*_s51
    cdef double _s198 = b4d*xEd
    cdef double _s199 = _s123*b2
    cdef double _s200 = _s10*_s92
    cdef double _s201 = _s3*_s90
    cdef double _s202 = _s24*_s94
    cdef double _s203 = _s2*_s88
    cdef double _s204 = b3d*xEd
    cdef double _s205 = _s153*b1
    cdef double _s206 = (thetad*thetad)
    cdef double _s207 = _cam0[3]*_s206
    cdef double _s208 = _s102*_s207
    cdef double _s209 = _cam0[1]*_s206
    cdef double _s210 = _s114*_s209
    cdef double _s211 = _s114*_s207
    cdef double _s212 = (_cam0[1]*_cam0[1]*_cam0[1])*_s206
    cdef double _s213 = _s109*_s212
    cdef double _s214 = _cam0[2]*_s212
    cdef double _s215 = (1.0/(pow(_cam0[0], 6.0)*_k434 + pow(_cam0[0], 5.0)*_k439 + _cam0[0]*_k438 + _cam0[0]*_k439*_s104 + pow(_cam0[1], 6.0)*_k434 + _k433 + _k435*_s100*_s104 + _k435*_s101*_s106 + _k436*_s101 + _k437*_s104 + _k440*_s100 + _k441*_s106 + _k442*_s105 + _k443*_s107 + _k444*_s101*_s105 + _k445*_s108))
    cdef double _s216 = _s206*_s215
    cdef double _s217 = pow(_cam0[1], 5.0)*_s216
    cdef double _s218 = _k446*_s217
    cdef double _s219 = _cam0[1]*_s216
    cdef double _s220 = _s111*_s219
    cdef double _s221 = (_cam0[2]*_cam0[2]*_cam0[2])*_s219
    cdef double _s222 = _s214*_s215
    cdef double _s223 = _s111*_s212*_s215
    cdef double _s224 = _cam0[0]*_k465
    cdef double _s225 = _k467*thetad
    cdef double _s226 = _k477*thetad
    cdef double _s227 = _cam0[0]*_s226
    cdef double _s228 = _cam0[1]*_s133
    cdef double _s229 = _k182*_s206
    cdef double _s230 = _s129*_s206
    cdef double _s231 = _cam0[2]*_k466
    cdef double _s232 = _s133*_s206
    _A[0] = _k2*_s0*(_k0 + _k1*_s2 + _s1)
    _A[1] = _s4
    _A[2] = _s8
    _A[3] = _s12
    _A[4] = _s16
    _A[5] = _s33
    _A[6] = 0.0
    _A[7] = _s118
    _A[8] = 0.0
    _A[9] = _s4
    _A[10] = _s7*(_k30 + _s5)
    _A[11] = _s34
    _A[12] = _s35
    _A[13] = _s38
    _A[14] = _s45
    _A[15] = 0.0
    _A[16] = _s119
    _A[17] = 0.0
    _A[18] = _s8
    _A[19] = _s34
    _A[20] = _s15*(_k50 + _s13)
    _A[21] = _s46
    _A[22] = _s49
    _A[23] = _s56
    _A[24] = 0.0
    _A[25] = _s120
    _A[26] = 0.0
    _A[27] = _s12
    _A[28] = _s35
    _A[29] = _s46
    _A[30] = _s48*(_k70 + _s47)
    _A[31] = _s57
    _A[32] = _s64
    _A[33] = 0.0
    _A[34] = _s121
    _A[35] = 0.0
    _A[36] = _s16
    _A[37] = _s38
    _A[38] = _s49
    _A[39] = _s57
    _A[40] = _k92*_s62*(_k90*_s2 + _k91 + _s1)
    _A[41] = _s66
    _A[42] = 0.0
    _A[43] = _s122
    _A[44] = 0.0
    _A[45] = _s33
    _A[46] = _s45
    _A[47] = _s56
    _A[48] = _s64
    _A[49] = _s66
    _A[50] = _k108 + _k109*_s87 + _k110*_s89 + _k111*_s91 + _k112*_s93 + _k113*_s95 + _k114*_s69 + _k115*_s70 + _k116*_s30*b1 + _k117*_s32*b1 + _k118*_s71 + _k119*_s72 + _k120*_s73 + _k121*_s74 + _k122*_s75 + _k123*_s76 + _k124*_s0*_s67 + _k125*_s6*_s88 + _k126*_s14*_s90 + _k127*_s40*_s92 + _k128*_s62*_s94 + _k129*_s68 + _k130*_s18*b1 + _k131*_s96 + _k132*_s23*b2 + _k133*_s44*b3 + _k134*_s53*b4 + _k135*_s97 + _k136*_s25*b2 + _k137*_s20*b1 + _k138*_s41*b3 + _k139*_s19*b1 + _k140*_s21*b1 + _k141*_s27*b2 + _k142*_s98 + _k143*_s99 + _k144*_s77 + _k145*_s78 + _k146*_s79 + _k147*_s80 + _k148*_s81 + _k149*_s82 + _k150*_s83 + _k151*_s84 + _k152*_s85 + _k153*_s86 + _k72*xE
    _A[51] = 0.0
    _A[52] = _k177*_s124 + _k178*_s125 + _k179*_s126 + _k180*_s127 + _k181*_s123
    _A[53] = 1.0
    _A[54] = 0.0
    _A[55] = 0.0
    _A[56] = 0.0
    _A[57] = 0.0
    _A[58] = 0.0
    _A[59] = 0.0
    _A[60] = J_r + _cam0[0]*_k167*_s103 + _k165*_s101*_s102 + _k166*_s112 + _k168*_s103 + _k171*_s113 + _s101*_s115 + _s104*_s110 + _s107*_s116 + _s110*_s117
    _A[61] = _s129*_s130 - _s134
    _A[62] = _s130*_s133 + _s135
    _A[63] = _s118
    _A[64] = _s119
    _A[65] = _s120
    _A[66] = _s121
    _A[67] = _s122
    _A[68] = _k177*_s124 + _k178*_s125 + _k179*_s126 + _k180*_s127 + _k181*_s123
    _A[69] = _s129*_s130 - _s134
    _A[70] = 0.0
    _A[71] = 0.0
    _A[72] = 0.0
    _A[73] = 0.0
    _A[74] = 0.0
    _A[75] = 0.0
    _A[76] = 0.0
    _A[77] = 1.0
    _A[78] = _s130*_s133 + _s135
    _A[79] = 0.0
    _A[80] = 0.0
    _b[0] = _k183*_s154 + _k184*_s155 + _k185*_s156 + _k186*_s137 + _k187*_s139 + _k188*_s141 + _k189*_s143 + _k189*_s157 + _k190*_s145 + _k191*_s158 + _k192*_s123 + _k193*_s124 + _k194*_s126 + _k195*_s125 + _k196*_s127 + _k197*_s146 + _k198*_s159 + _k199*_s160 + _k200*_s161 + _k201*_s147 + _k202*_s148 + _k203*_s149 + _k204*_s162 + _k205*_s151 + _k206*_s163 + _k207*_s144*_s2 + _k208*_s124*_s153 + _k209*_s138*b5d + _k211*_s140*b4d + _k212*_s142*b3d + _k213*_s0*_s152 + _k214*_s125*_s153 + _k215*_s127*_s153 + _s153*_s164
    _b[1] = _k196*_s29 + _k209*_s139 + _k216*_s159 + _k217*_s161 + _k218*_s160 + _k219*_s151 + _k220*_s147 + _k221*_s149 + _k222*_s148 + _k222*_s162 + _k223*_s146 + _k224*_s163 + _k225*_s30 + _k226*_s28 + _k227*_s32 + _k228*_s31 + _k229*_s165 + _k230*_s171 + _k231*_s172 + _k232*_s173 + _k233*_s166 + _k234*_s174 + _k235*_s167 + _k236*_s169 + _k237*_s170 + _k238*_s175 + _k239*_s145 + _k240*_s154 + _k241*_s155 + _k242*_s137 + _k243*_s141 + _k244*_s156 + _k245*_s143 + _k246*_s157
    _b[2] = _k186*_s171 + _k194*_s17 + _k228*_s18 + _k247*_s173 + _k248*_s172 + _k249*_s169 + _k250*_s167 + _k251*_s166 + _k252*_s165 + _k252*_s174 + _k253*_s170 + _k254*_s175 + _k255*_s20 + _k256*_s21 + _k257*_s19 + _k258*_s182 + _k259*_s176 + _k260*_s183 + _k261*_s184 + _k262*_s177 + _k263*_s179 + _k264*_s180 + _k265*_s185 + _k266*_s181 + _k267*_s186 + _k268*_s146 + _k269*_s161 + _k270*_s149 + _k271*_s159 + _k272*_s147 + _k273*_s160 + _k274*_s151 + _k275*_s148 + _k276*_s162
    _b[3] = _k195*_s22 + _k219*_s183 + _k225*_s26 + _k255*_s23 + _k277*_s184 + _k278*_s185 + _k279*_s179 + _k280*_s177 + _k281*_s176 + _k282*_s180 + _k282*_s182 + _k283*_s181 + _k284*_s186 + _k285*_s27 + _k286*_s25 + _k287*_s187 + _k288*_s193 + _k289*_s194 + _k290*_s189 + _k291*_s190 + _k292*_s195 + _k293*_s191 + _k294*_s196 + _k295*_s192 + _k296*_s197 + _k297*_s170 + _k298*_s171 + _k299*_s173 + _k300*_s172 + _k301*_s166 + _k302*_s169 + _k303*_s167 + _k304*_s165 + _k305*_s174
    _b[4] = _k193*_s42 + _k227*_s39 + _k249*_s196 + _k256*_s43 + _k286*_s44 + _k306*_s193 + _k307*_s194 + _k308*_s189 + _k309*_s187 + _k310*_s190 + _k311*_s192 + _k311*_s195 + _k312*_s191 + _k313*_s197 + _k314*_s41 + _k315*_s188*_s65 + _k316*_s153*_s58 + _k317*_s153*_s63 + _k318*_s198*_s62 + _k319*_s153*_s61 + _k320*_s178*b3d + _k321*_s153*_s60 + _k322*_s152*_s40 + _k323*_s153*_s59 + _k324*_s144*_s24 + _k325*_s181 + _k326*_s184 + _k327*_s179 + _k328*_s185 + _k329*_s183 + _k330*_s177 + _k331*_s180 + _k332*_s176 + _k333*_s182
    _b[5] = _k183*_s152*_s20 + _k183*_s198*_s39 + _k184*_s144*_s30 + _k184*_s198*_s42 + _k190*_s153*_s68 + _k198*_s152*_s27 + _k198*_s198*_s54 + _k200*_s144*_s20 + _k200*_s198*_s51 + _k208*_s152*_s30 + _k208*_s198*_s26 + _k210*_s17*_s204 + _k240*_s152*_s32 + _k240*_s188*_s39 + _k334*_s153 + _k335*_s153*_s97 + _k336*_s153*_s99 + _k337*_s153*_s98 + _k338*_s152*_s18 + _k338*_s153*_s96 + _k339*_s67 + _k340*_s153*_s85 + _k341*_s153*_s86 + _k342*_s153*_s84 + _k343*_s153*_s83 + _k344*_s153*_s82 + _k345*_s153*_s80 + _k346*_s188*_s53 + _k347*_s153*_s81 + _k348*_s188*_s55 + _k348*_s198*_s41 + _k349*_s200 + _k350*_s153*_s79 + _k351*_s198*_s44 + _k352*_s188*_s50 + _k352*_s204*_s25 + _k353*_s198*_s43 + _k353*_s204*_s27 + _k354*_s152*_s21 + _k354*_s188*_s54 + _k355*_s153*_s78 + _k356*_s204*_s23 + _k357*_s144*_s32 + _k357*_s188*_s51 + _k358*_s152*_s19 + _k358*_s204*_s26 + _k359*_s201 + _k360*_s153*_s77 + _k361*_s144*_s31 + _k361*_s204*_s22 + _k362*_s144*_s28 + _k362*_s152*_s17 + _k363*_s144*_s29 + _k364*_s202 + _k365*_s203 + _k366*_s21*b4 + _k367*_s23*b5 + _k368*_s19*b4 + _k369*_s26*b5 + _k370*_s18*b4 + _k371*_s28*b3 + _k372*_s153*_s95 + _k373*_s22*b5 + _k374*_s17*b4 + _k375*_s153*_s91 + _k376*_s29*b3 + _k377*_s199 + _k378*_s153*_s87 + _k379*_s153*_s93 + _k380*_s153*_s89 + _k381*_s153*_s67 + _k382*_s153*_s200 + _k383*_s153*_s76 + _k384*_s153*_s75 + _k385*_s153*_s74 + _k386*_s153*_s73 + _k387*_s153*_s201 + _k388*_s153*_s72 + _k389*_s205*_s32 + _k390*_s153*_s71 + _k391*_s205*_s30 + _k392*_s153*_s70 + _k393*_s153*_s69 + _k394*_s188*_s58 + _k394*_s198*_s53 + _k395*_s198*_s50 + _k395*_s204*_s44 + _k396*_s152*_s23 + _k396*_s204*_s39 + _k397*_s144*_s18 + _k397*_s152*_s22 + _k398*_s153*_s202 + _k399*_s188*_s63 + _k400*_s198*_s55 + _k401*_s204*_s43 + _k402*_s144*_s21 + _k402*_s188*_s59 + _k403*_s152*_s26 + _k404*_s188*_s61 + _k404*_s204*_s41 + _k405*_s144*_s19 + _k405*_s204*_s42 + _k406*_s152*_s25 + _k406*_s188*_s60 + _k407*_s153*_s203 + _k408*_s144*_s17 + _k409*_s159*b4 + _k410*_s171*b5 + _k411*_s160*b4 + _k412*_s188*_s41 + _k413*_s174*b5 + _k414*_s162*b4 + _k415*_s198*_s23 + _k415*_s20*_s204 + _k416*_s157*b3 + _k417*_s175*b5 + _k418*_s163*b4 + _k419*_s152*_s31 + _k419*_s18*_s204 + _k420*_s152*_s28 + _k420*_s158*b3 + _k421*_s124*_s144 + _k421*_s188*_s42 + _k422*_s125*_s144 + _k422*_s198*_s22 + _k423*_s127*_s144 + _k423*_s152*_s29 + _k423*_s153*_s199 + _k424*_s123*_s144 + _k425*_s198*_s27 + _k426*_s188*_s43 + _k426*_s204*_s21 + _k427*_s188*_s44 + _k427*_s198*_s25 + _k428*_s19*_s204 + _s144*_s164
    _b[6] = _cam0[0]*_k429*_s208 + _cam0[0]*_k432*_s213 + _cam0[0]*_k452*_s223 + _cam0[0]*_k458*_s222 + _cam0[0]*_k459*_s210 + _cam0[0]*_k460*_s221 + _cam0[0]*_k461*_s220 + _cam0[0]*_s115*_s207 + _cam0[0]*_s218 + _cam0[2]*_s218 + _k171*_s213 + _k430*_s208 + _k431*_s103*_s209 + _k446*_s100*_s221 + _k446*_s105*_s220 + _k447*_s217 + _k448*_s101*_s109*_s207 + _k449*_s100*_s211 + _k449*_s113*_s209 + _k450*_s112*_s209 + _k451*_s211 + _k452*_s100*_s222 + _k453*_s222 + _k454*_s223 + _k455*_s210 + _k456*_s220 + _k457*_s221 + _k462*_s117*_s219 + _s100*_s116*_s209 + _s107*_s110*_s207 + _s110*_s214
    _b[7] = _k463*_s129 + _k464*_s205 + _k468*_s206*_s228 + _k469*_s144*xE + _k470*_s152*_s2 + _k470*_s153*b2*xE + _k471*_s0*_s204 + _k472*_s142*b4d + _k473*_s153*_s2*b3 + _k474*_s140*b5d + _k475*_s0*_s153*b4 + _k476*_s153*_s3*b5 + _s129*_s224 + _s129*_s225 + _s129*_s227 + _s129*_s229 + _s131*_s230 + _s226*_s228 + _s230*_s231
    _ph[0] = _s118*b1 + _s119*b2 + _s120*b3 + _s121*b4 + _s122*b5 + _s135
    _phd[0] = Omega*_s134 + _A[63] * b1d + _A[64] * b2d + _A[65] * b3d + _A[66] * b4d + _A[67] * b5d + _A[68] * xEd + _A[69] * thetad
    _b[8] = _cam0[1]*_k478*_s230 + _cam0[1]*_k479*_s129*thetad + _k463*_s133 + _s131*_s232 + _s133*_s224 + _s133*_s225 + _s133*_s227 + _s133*_s229 + _s231*_s232
    _ph[1] = _k480 + _s134 + xE
    _phd[1] = _k481*_s135 + _A[72] * b1d + _A[73] * b2d + _A[74] * b3d + _A[75] * b4d + _A[76] * b5d + _A[77] * xEd + _A[78] * thetad


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
    cdef double _k343 = ctx.k[343]
    cdef double _k344 = ctx.k[344]
    cdef double _k345 = ctx.k[345]
    cdef double _k346 = ctx.k[346]
    cdef double _k347 = ctx.k[347]
    cdef double _k348 = ctx.k[348]
    cdef double _k349 = ctx.k[349]
    cdef double _k350 = ctx.k[350]
    cdef double _k351 = ctx.k[351]
    cdef double _k352 = ctx.k[352]
    cdef double _k353 = ctx.k[353]
    cdef double _k354 = ctx.k[354]
    cdef double _k355 = ctx.k[355]
    cdef double _k356 = ctx.k[356]
    cdef double _k357 = ctx.k[357]
    cdef double _k358 = ctx.k[358]
    cdef double _k359 = ctx.k[359]
    cdef double _k360 = ctx.k[360]
    cdef double _k361 = ctx.k[361]
    cdef double _k362 = ctx.k[362]
    cdef double _k363 = ctx.k[363]
    cdef double _k364 = ctx.k[364]
    cdef double _k365 = ctx.k[365]
    cdef double _k366 = ctx.k[366]
    cdef double _k367 = ctx.k[367]
    cdef double _k368 = ctx.k[368]
    cdef double _k369 = ctx.k[369]
    cdef double _k370 = ctx.k[370]
    cdef double _k371 = ctx.k[371]
    cdef double _k372 = ctx.k[372]
    cdef double _k373 = ctx.k[373]
    cdef double _k374 = ctx.k[374]
    cdef double _k375 = ctx.k[375]
    cdef double _k376 = ctx.k[376]
    cdef double _k377 = ctx.k[377]
    cdef double _k378 = ctx.k[378]
    cdef double _k379 = ctx.k[379]
    cdef double _k380 = ctx.k[380]
    cdef double _k381 = ctx.k[381]
    cdef double _k382 = ctx.k[382]
    cdef double _k383 = ctx.k[383]
    cdef double _k384 = ctx.k[384]
    cdef double _k385 = ctx.k[385]
    cdef double _k386 = ctx.k[386]
    cdef double _k387 = ctx.k[387]
    cdef double _k388 = ctx.k[388]
    cdef double _k389 = ctx.k[389]
    cdef double _k390 = ctx.k[390]
    cdef double _k391 = ctx.k[391]
    cdef double _k392 = ctx.k[392]
    cdef double _k393 = ctx.k[393]
    cdef double _k394 = ctx.k[394]
    cdef double _k395 = ctx.k[395]
    cdef double _k396 = ctx.k[396]
    cdef double _k397 = ctx.k[397]
    cdef double _k398 = ctx.k[398]
    cdef double _k399 = ctx.k[399]
    cdef double _k400 = ctx.k[400]
    cdef double _k401 = ctx.k[401]
    cdef double _k402 = ctx.k[402]
    cdef double _k403 = ctx.k[403]
    cdef double _k404 = ctx.k[404]
    cdef double _k405 = ctx.k[405]
    cdef double _k406 = ctx.k[406]
    cdef double _k407 = ctx.k[407]
    cdef double _k408 = ctx.k[408]
    cdef double _k409 = ctx.k[409]
    cdef double _k410 = ctx.k[410]
    cdef double _k411 = ctx.k[411]
    cdef double _k412 = ctx.k[412]
    cdef double _k413 = ctx.k[413]
    cdef double _k414 = ctx.k[414]
    cdef double _k415 = ctx.k[415]
    cdef double _k416 = ctx.k[416]
    cdef double _k417 = ctx.k[417]
    cdef double _k418 = ctx.k[418]
    cdef double _k419 = ctx.k[419]
    cdef double _k420 = ctx.k[420]
    cdef double _k421 = ctx.k[421]
    cdef double _k422 = ctx.k[422]
    cdef double _k423 = ctx.k[423]
    cdef double _k424 = ctx.k[424]
    cdef double _k425 = ctx.k[425]
    cdef double _k426 = ctx.k[426]
    cdef double _k427 = ctx.k[427]
    cdef double _k428 = ctx.k[428]
    cdef double _k429 = ctx.k[429]
    cdef double _k430 = ctx.k[430]
    cdef double _k431 = ctx.k[431]
    cdef double _k432 = ctx.k[432]
    cdef double _k433 = ctx.k[433]
    cdef double _k434 = ctx.k[434]
    cdef double _k435 = ctx.k[435]
    cdef double _k436 = ctx.k[436]
    cdef double _k437 = ctx.k[437]
    cdef double _k438 = ctx.k[438]
    cdef double _k439 = ctx.k[439]
    cdef double _k440 = ctx.k[440]
    cdef double _k441 = ctx.k[441]
    cdef double _k442 = ctx.k[442]
    cdef double _k443 = ctx.k[443]
    cdef double _k444 = ctx.k[444]
    cdef double _k445 = ctx.k[445]
    cdef double _k446 = ctx.k[446]
    cdef double _k447 = ctx.k[447]
    cdef double _k448 = ctx.k[448]
    cdef double _k449 = ctx.k[449]
    cdef double _k450 = ctx.k[450]
    cdef double _k451 = ctx.k[451]
    cdef double _k452 = ctx.k[452]
    cdef double _k453 = ctx.k[453]
    cdef double _k454 = ctx.k[454]
    cdef double _k455 = ctx.k[455]
    cdef double _k456 = ctx.k[456]
    cdef double _k457 = ctx.k[457]
    cdef double _k458 = ctx.k[458]
    cdef double _k459 = ctx.k[459]
    cdef double _k460 = ctx.k[460]
    cdef double _k461 = ctx.k[461]
    cdef double _k462 = ctx.k[462]
    cdef double _k463 = ctx.k[463]
    cdef double _k464 = ctx.k[464]
    cdef double _k465 = ctx.k[465]
    cdef double _k466 = ctx.k[466]
    cdef double _k467 = ctx.k[467]
    cdef double _k468 = ctx.k[468]
    cdef double _k469 = ctx.k[469]
    cdef double _k470 = ctx.k[470]
    cdef double _k471 = ctx.k[471]
    cdef double _k472 = ctx.k[472]
    cdef double _k473 = ctx.k[473]
    cdef double _k474 = ctx.k[474]
    cdef double _k475 = ctx.k[475]
    cdef double _k476 = ctx.k[476]
    cdef double _k477 = ctx.k[477]
    cdef double _k478 = ctx.k[478]
    cdef double _k479 = ctx.k[479]
    cdef double _k480 = ctx.k[480]
    cdef double _k481 = ctx.k[481]
    cdef double _k482 = ctx.k[482]
    cdef double _k483 = ctx.k[483]
    cdef double b1 = _y[0]
    cdef double b2 = _y[1]
    cdef double b3 = _y[2]
    cdef double b4 = _y[3]
    cdef double b5 = _y[4]
    cdef double xE = _y[5]
    cdef double theta = _y[6]
    cdef double b1d = _y[7]
    cdef double b2d = _y[8]
    cdef double b3d = _y[9]
    cdef double b4d = _y[10]
    cdef double b5d = _y[11]
    cdef double xEd = _y[12]
    cdef double thetad = _y[13]
    cdef double _cam0[4]
    _profile(ctx, theta, beta_r, _cam0)

    cdef double _p0 = (xE*xE)
    cdef double _p1 = _k172*_p0
    cdef double _p2 = (xE*xE*xE)
    cdef double _p3 = _k173*_p2
    cdef double _p4 = (xE*xE*xE*xE)
    cdef double _p5 = _k174*_p4
    cdef double _p6 = _k175*pow(xE, 5.0)
    cdef double _p7 = _k176*pow(xE, 6.0)
    cdef double _p8 = S_T*_cam0[0] + _k182
    cdef double _p9 = Omega*t - theta
    cdef double _p10 = sin(_p9)
    cdef double _p11 = _p10*_p8
    cdef double _p12 = cos(_p9)
    cdef double _p13 = _p12*_p8
    cdef double _p14 = S_T*_cam0[1]
    _g[0] = _p1*b1 + _p11 + _p3*b2 + _p5*b3 + _p6*b4 + _p7*b5
    _g[1] = _k480 + _p13 + xE
    _J[0] = _p1
    _J[1] = _p3
    _J[2] = _p5
    _J[3] = _p6
    _J[4] = _p7
    _J[5] = xE*(_k177*_p4*b5 + _k178*_p2*b4 + _k179*_p0*b3 + _k180*b2*xE + _k181*b1)
    _J[6] = _p10*_p14 - _p13
    _J[7] = 0.0
    _J[8] = 0.0
    _J[9] = 0.0
    _J[10] = 0.0
    _J[11] = 0.0
    _J[12] = 1.0
    _J[13] = _p11 + _p12*_p14
    _gt[0] = Omega*_p13
    _gt[1] = _k481*_p11


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
    cdef double _k343 = ctx.k[343]
    cdef double _k344 = ctx.k[344]
    cdef double _k345 = ctx.k[345]
    cdef double _k346 = ctx.k[346]
    cdef double _k347 = ctx.k[347]
    cdef double _k348 = ctx.k[348]
    cdef double _k349 = ctx.k[349]
    cdef double _k350 = ctx.k[350]
    cdef double _k351 = ctx.k[351]
    cdef double _k352 = ctx.k[352]
    cdef double _k353 = ctx.k[353]
    cdef double _k354 = ctx.k[354]
    cdef double _k355 = ctx.k[355]
    cdef double _k356 = ctx.k[356]
    cdef double _k357 = ctx.k[357]
    cdef double _k358 = ctx.k[358]
    cdef double _k359 = ctx.k[359]
    cdef double _k360 = ctx.k[360]
    cdef double _k361 = ctx.k[361]
    cdef double _k362 = ctx.k[362]
    cdef double _k363 = ctx.k[363]
    cdef double _k364 = ctx.k[364]
    cdef double _k365 = ctx.k[365]
    cdef double _k366 = ctx.k[366]
    cdef double _k367 = ctx.k[367]
    cdef double _k368 = ctx.k[368]
    cdef double _k369 = ctx.k[369]
    cdef double _k370 = ctx.k[370]
    cdef double _k371 = ctx.k[371]
    cdef double _k372 = ctx.k[372]
    cdef double _k373 = ctx.k[373]
    cdef double _k374 = ctx.k[374]
    cdef double _k375 = ctx.k[375]
    cdef double _k376 = ctx.k[376]
    cdef double _k377 = ctx.k[377]
    cdef double _k378 = ctx.k[378]
    cdef double _k379 = ctx.k[379]
    cdef double _k380 = ctx.k[380]
    cdef double _k381 = ctx.k[381]
    cdef double _k382 = ctx.k[382]
    cdef double _k383 = ctx.k[383]
    cdef double _k384 = ctx.k[384]
    cdef double _k385 = ctx.k[385]
    cdef double _k386 = ctx.k[386]
    cdef double _k387 = ctx.k[387]
    cdef double _k388 = ctx.k[388]
    cdef double _k389 = ctx.k[389]
    cdef double _k390 = ctx.k[390]
    cdef double _k391 = ctx.k[391]
    cdef double _k392 = ctx.k[392]
    cdef double _k393 = ctx.k[393]
    cdef double _k394 = ctx.k[394]
    cdef double _k395 = ctx.k[395]
    cdef double _k396 = ctx.k[396]
    cdef double _k397 = ctx.k[397]
    cdef double _k398 = ctx.k[398]
    cdef double _k399 = ctx.k[399]
    cdef double _k400 = ctx.k[400]
    cdef double _k401 = ctx.k[401]
    cdef double _k402 = ctx.k[402]
    cdef double _k403 = ctx.k[403]
    cdef double _k404 = ctx.k[404]
    cdef double _k405 = ctx.k[405]
    cdef double _k406 = ctx.k[406]
    cdef double _k407 = ctx.k[407]
    cdef double _k408 = ctx.k[408]
    cdef double _k409 = ctx.k[409]
    cdef double _k410 = ctx.k[410]
    cdef double _k411 = ctx.k[411]
    cdef double _k412 = ctx.k[412]
    cdef double _k413 = ctx.k[413]
    cdef double _k414 = ctx.k[414]
    cdef double _k415 = ctx.k[415]
    cdef double _k416 = ctx.k[416]
    cdef double _k417 = ctx.k[417]
    cdef double _k418 = ctx.k[418]
    cdef double _k419 = ctx.k[419]
    cdef double _k420 = ctx.k[420]
    cdef double _k421 = ctx.k[421]
    cdef double _k422 = ctx.k[422]
    cdef double _k423 = ctx.k[423]
    cdef double _k424 = ctx.k[424]
    cdef double _k425 = ctx.k[425]
    cdef double _k426 = ctx.k[426]
    cdef double _k427 = ctx.k[427]
    cdef double _k428 = ctx.k[428]
    cdef double _k429 = ctx.k[429]
    cdef double _k430 = ctx.k[430]
    cdef double _k431 = ctx.k[431]
    cdef double _k432 = ctx.k[432]
    cdef double _k433 = ctx.k[433]
    cdef double _k434 = ctx.k[434]
    cdef double _k435 = ctx.k[435]
    cdef double _k436 = ctx.k[436]
    cdef double _k437 = ctx.k[437]
    cdef double _k438 = ctx.k[438]
    cdef double _k439 = ctx.k[439]
    cdef double _k440 = ctx.k[440]
    cdef double _k441 = ctx.k[441]
    cdef double _k442 = ctx.k[442]
    cdef double _k443 = ctx.k[443]
    cdef double _k444 = ctx.k[444]
    cdef double _k445 = ctx.k[445]
    cdef double _k446 = ctx.k[446]
    cdef double _k447 = ctx.k[447]
    cdef double _k448 = ctx.k[448]
    cdef double _k449 = ctx.k[449]
    cdef double _k450 = ctx.k[450]
    cdef double _k451 = ctx.k[451]
    cdef double _k452 = ctx.k[452]
    cdef double _k453 = ctx.k[453]
    cdef double _k454 = ctx.k[454]
    cdef double _k455 = ctx.k[455]
    cdef double _k456 = ctx.k[456]
    cdef double _k457 = ctx.k[457]
    cdef double _k458 = ctx.k[458]
    cdef double _k459 = ctx.k[459]
    cdef double _k460 = ctx.k[460]
    cdef double _k461 = ctx.k[461]
    cdef double _k462 = ctx.k[462]
    cdef double _k463 = ctx.k[463]
    cdef double _k464 = ctx.k[464]
    cdef double _k465 = ctx.k[465]
    cdef double _k466 = ctx.k[466]
    cdef double _k467 = ctx.k[467]
    cdef double _k468 = ctx.k[468]
    cdef double _k469 = ctx.k[469]
    cdef double _k470 = ctx.k[470]
    cdef double _k471 = ctx.k[471]
    cdef double _k472 = ctx.k[472]
    cdef double _k473 = ctx.k[473]
    cdef double _k474 = ctx.k[474]
    cdef double _k475 = ctx.k[475]
    cdef double _k476 = ctx.k[476]
    cdef double _k477 = ctx.k[477]
    cdef double _k478 = ctx.k[478]
    cdef double _k479 = ctx.k[479]
    cdef double _k480 = ctx.k[480]
    cdef double _k481 = ctx.k[481]
    cdef double _k482 = ctx.k[482]
    cdef double _k483 = ctx.k[483]
    cdef double b1 = _yc[0]
    cdef double b2 = _yc[1]
    cdef double b3 = _yc[2]
    cdef double b4 = _yc[3]
    cdef double b5 = _yc[4]
    cdef double xE = _yc[5]
    cdef double theta = _yc[6]
    cdef double b1d = _yc[7]
    cdef double b2d = _yc[8]
    cdef double b3d = _yc[9]
    cdef double b4d = _yc[10]
    cdef double b5d = _yc[11]
    cdef double xEd = _yc[12]
    cdef double thetad = _yc[13]
    cdef double _cam0[4]
    _profile(ctx, theta, beta_r, _cam0)

    cdef double _o0 = (xE*xE)
    cdef double _o1 = (xE*xE*xE)
    cdef double _o2 = (xE*xE*xE*xE)
    cdef double _o3 = S_T*_cam0[0]
    cdef double _o4 = _k182 + _o3
    cdef double _o5 = Omega*t - theta
    _out[0] = _o0*(_k2*_o0*b3 + _k482*b1 + _k483*b2*xE + _k5*_o1*b4 + _k8*_o2*b5)  # vE
    _out[1] = _k172*_o0*b1 + _k173*_o1*b2 + _k174*_o2*b3 + _k175*b4*pow(xE, 5.0) + _k176*b5*pow(xE, 6.0) + _o4*sin(_o5)  # Phi1
    _out[2] = _k480 + _o4*cos(_o5) + xE  # Phi2
    _out[3] = _o3  # S
    _out[4] = atan(S_T*_cam0[1]/_o4)  # pressure_angle
    _out[5] = _acc[5]  # xEdd
    _out[6] = _acc[7]  # lambda1
    _out[7] = _acc[8]  # lambda2


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
_SCALE[4] = 1e-05
_SCALE[5] = 0.05
_SCALE[6] = 1.0
_SCALE[7] = 1e-05
_SCALE[8] = 1e-05
_SCALE[9] = 1e-05
_SCALE[10] = 1e-05
_SCALE[11] = 1e-05
_SCALE[12] = 0.05
_SCALE[13] = 1.0


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
    cdef double _k343 = ctx.k[343]
    cdef double _k344 = ctx.k[344]
    cdef double _k345 = ctx.k[345]
    cdef double _k346 = ctx.k[346]
    cdef double _k347 = ctx.k[347]
    cdef double _k348 = ctx.k[348]
    cdef double _k349 = ctx.k[349]
    cdef double _k350 = ctx.k[350]
    cdef double _k351 = ctx.k[351]
    cdef double _k352 = ctx.k[352]
    cdef double _k353 = ctx.k[353]
    cdef double _k354 = ctx.k[354]
    cdef double _k355 = ctx.k[355]
    cdef double _k356 = ctx.k[356]
    cdef double _k357 = ctx.k[357]
    cdef double _k358 = ctx.k[358]
    cdef double _k359 = ctx.k[359]
    cdef double _k360 = ctx.k[360]
    cdef double _k361 = ctx.k[361]
    cdef double _k362 = ctx.k[362]
    cdef double _k363 = ctx.k[363]
    cdef double _k364 = ctx.k[364]
    cdef double _k365 = ctx.k[365]
    cdef double _k366 = ctx.k[366]
    cdef double _k367 = ctx.k[367]
    cdef double _k368 = ctx.k[368]
    cdef double _k369 = ctx.k[369]
    cdef double _k370 = ctx.k[370]
    cdef double _k371 = ctx.k[371]
    cdef double _k372 = ctx.k[372]
    cdef double _k373 = ctx.k[373]
    cdef double _k374 = ctx.k[374]
    cdef double _k375 = ctx.k[375]
    cdef double _k376 = ctx.k[376]
    cdef double _k377 = ctx.k[377]
    cdef double _k378 = ctx.k[378]
    cdef double _k379 = ctx.k[379]
    cdef double _k380 = ctx.k[380]
    cdef double _k381 = ctx.k[381]
    cdef double _k382 = ctx.k[382]
    cdef double _k383 = ctx.k[383]
    cdef double _k384 = ctx.k[384]
    cdef double _k385 = ctx.k[385]
    cdef double _k386 = ctx.k[386]
    cdef double _k387 = ctx.k[387]
    cdef double _k388 = ctx.k[388]
    cdef double _k389 = ctx.k[389]
    cdef double _k390 = ctx.k[390]
    cdef double _k391 = ctx.k[391]
    cdef double _k392 = ctx.k[392]
    cdef double _k393 = ctx.k[393]
    cdef double _k394 = ctx.k[394]
    cdef double _k395 = ctx.k[395]
    cdef double _k396 = ctx.k[396]
    cdef double _k397 = ctx.k[397]
    cdef double _k398 = ctx.k[398]
    cdef double _k399 = ctx.k[399]
    cdef double _k400 = ctx.k[400]
    cdef double _k401 = ctx.k[401]
    cdef double _k402 = ctx.k[402]
    cdef double _k403 = ctx.k[403]
    cdef double _k404 = ctx.k[404]
    cdef double _k405 = ctx.k[405]
    cdef double _k406 = ctx.k[406]
    cdef double _k407 = ctx.k[407]
    cdef double _k408 = ctx.k[408]
    cdef double _k409 = ctx.k[409]
    cdef double _k410 = ctx.k[410]
    cdef double _k411 = ctx.k[411]
    cdef double _k412 = ctx.k[412]
    cdef double _k413 = ctx.k[413]
    cdef double _k414 = ctx.k[414]
    cdef double _k415 = ctx.k[415]
    cdef double _k416 = ctx.k[416]
    cdef double _k417 = ctx.k[417]
    cdef double _k418 = ctx.k[418]
    cdef double _k419 = ctx.k[419]
    cdef double _k420 = ctx.k[420]
    cdef double _k421 = ctx.k[421]
    cdef double _k422 = ctx.k[422]
    cdef double _k423 = ctx.k[423]
    cdef double _k424 = ctx.k[424]
    cdef double _k425 = ctx.k[425]
    cdef double _k426 = ctx.k[426]
    cdef double _k427 = ctx.k[427]
    cdef double _k428 = ctx.k[428]
    cdef double _k429 = ctx.k[429]
    cdef double _k430 = ctx.k[430]
    cdef double _k431 = ctx.k[431]
    cdef double _k432 = ctx.k[432]
    cdef double _k433 = ctx.k[433]
    cdef double _k434 = ctx.k[434]
    cdef double _k435 = ctx.k[435]
    cdef double _k436 = ctx.k[436]
    cdef double _k437 = ctx.k[437]
    cdef double _k438 = ctx.k[438]
    cdef double _k439 = ctx.k[439]
    cdef double _k440 = ctx.k[440]
    cdef double _k441 = ctx.k[441]
    cdef double _k442 = ctx.k[442]
    cdef double _k443 = ctx.k[443]
    cdef double _k444 = ctx.k[444]
    cdef double _k445 = ctx.k[445]
    cdef double _k446 = ctx.k[446]
    cdef double _k447 = ctx.k[447]
    cdef double _k448 = ctx.k[448]
    cdef double _k449 = ctx.k[449]
    cdef double _k450 = ctx.k[450]
    cdef double _k451 = ctx.k[451]
    cdef double _k452 = ctx.k[452]
    cdef double _k453 = ctx.k[453]
    cdef double _k454 = ctx.k[454]
    cdef double _k455 = ctx.k[455]
    cdef double _k456 = ctx.k[456]
    cdef double _k457 = ctx.k[457]
    cdef double _k458 = ctx.k[458]
    cdef double _k459 = ctx.k[459]
    cdef double _k460 = ctx.k[460]
    cdef double _k461 = ctx.k[461]
    cdef double _k462 = ctx.k[462]
    cdef double _k463 = ctx.k[463]
    cdef double _k464 = ctx.k[464]
    cdef double _k465 = ctx.k[465]
    cdef double _k466 = ctx.k[466]
    cdef double _k467 = ctx.k[467]
    cdef double _k468 = ctx.k[468]
    cdef double _k469 = ctx.k[469]
    cdef double _k470 = ctx.k[470]
    cdef double _k471 = ctx.k[471]
    cdef double _k472 = ctx.k[472]
    cdef double _k473 = ctx.k[473]
    cdef double _k474 = ctx.k[474]
    cdef double _k475 = ctx.k[475]
    cdef double _k476 = ctx.k[476]
    cdef double _k477 = ctx.k[477]
    cdef double _k478 = ctx.k[478]
    cdef double _k479 = ctx.k[479]
    cdef double _k480 = ctx.k[480]
    cdef double _k481 = ctx.k[481]
    cdef double _k482 = ctx.k[482]
    cdef double _k483 = ctx.k[483]
    cdef double b1 = _y[0]
    cdef double b2 = _y[1]
    cdef double b3 = _y[2]
    cdef double b4 = _y[3]
    cdef double b5 = _y[4]
    cdef double xE = _y[5]
    cdef double theta = _y[6]
    cdef double b1d = _y[7]
    cdef double b2d = _y[8]
    cdef double b3d = _y[9]
    cdef double b4d = _y[10]
    cdef double b5d = _y[11]
    cdef double xEd = _y[12]
    cdef double thetad = _y[13]
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
    return [0.0, 0.0, 0.0, 0.0, 0.0, d - r_b - r_r, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, Omega]


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
    ctx.cache = &k[484]
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
_model.n_const = 484
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
 "n_q": 7,
 "name": "beam5",
 "options": [
  [
   "modes",
   5
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
 "source_hash": "sha256:a91861c5ef9ef871d0972bdd6fadc95fb8bd8aa9c22b166a68b2e22724f00536",
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
   "doc": "amplitude of the assumed mode (x/d)^6 (13)",
   "initial": 0.0,
   "name": "b5",
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
   "doc": "rate of b5",
   "initial": 0.0,
   "name": "b5d",
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
 "title": "Rayleigh-beam follower in a grooved disk cam, N = 5 assumed modes"
}
"""
MANIFEST = json.loads(_MANIFEST_JSON)
"""States, parameters (defaults, units, ranges), outputs, the cam profile, events, source hash."""

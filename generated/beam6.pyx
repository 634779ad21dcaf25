# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True, initializedcheck=False
#
# GENERATED FILE - DO NOT EDIT.  Written by `camdyn derive` from camdyn/derive/models/beam.py;
# edit that and regenerate.  `camdyn derive --check` fails while this file is stale.
# Derivation key: sha256:60085b5f45ce2fa87b33025e597fb4f180d87f04c5f4bc5384e46ee167a5a1c1
# Text hash: sha256:7a9b32a2abd9e358f5f419b1c9eb4504199f7b507f8f8d558302256ab4982a69
#
# Rayleigh-beam follower in a grooved disk cam, N = 6 assumed modes (paper (1)-(20))
# Source hash: sha256:9d4ce2ed01f1ecad9d62194db1151f10c3655da69963e1cb0de52220801b3e5b
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
    _NQ = 8                  # coordinates Q
    _NC = 2                  # constraints Phi
    _NA = 10                  # unknowns of the augmented system: Q'', lambda
    _ND = 6                  # first dependent coordinate (the last _NC are dependent)
    _NS = 16                 # states: Q, Q'
    _NCAM = 0
    _NM = 0
    _NE = 2
    _NQ1 = 8
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
    cdef double _c10 = pow(d, -9.0)
    cdef double _c11 = 2.0*m_r
    cdef double _c12 = _c11*_c5
    cdef double _c13 = 3.0*m_r
    cdef double _c14 = 4.0*m_r
    cdef double _c15 = _c14*_c7
    cdef double _c16 = 5.0*m_r
    cdef double _c17 = 6.0*m_r
    cdef double _c18 = _c17*_c9
    cdef double _c19 = 7.0*m_r
    cdef double _c20 = _c4*_c5
    cdef double _c21 = _c4*_c7
    cdef double _c22 = 0.6666666666666666*_c21
    cdef double _c23 = _c4*_c9
    cdef double _c24 = 0.75*_c23
    cdef double _c25 = _c4*_c6
    cdef double _c26 = _c4*_c8
    cdef double _c27 = _c10*_c4
    cdef double _c28 = _c3*_c6
    cdef double _c29 = _c0*_c5
    cdef double _c30 = _c2*_c29
    cdef double _c31 = 0.5*_c30
    cdef double _c32 = _c3*_c8
    cdef double _c33 = _c10*_c3
    cdef double _c34 = _c3*_c7
    cdef double _c35 = 1.5*_c34
    cdef double _c36 = _c3*_c9
    cdef double _c37 = 2.5*_c36
    cdef double _c38 = 0.5*_c3
    cdef double _c39 = pow(d, -10.0)
    cdef double _c40 = _c11*_c6
    cdef double _c41 = _c14*_c8
    cdef double _c42 = _c10*_c17
    cdef double _c43 = 0.6666666666666666*_c27
    cdef double _c44 = 0.5714285714285714*_c26
    cdef double _c45 = _c39*_c4
    cdef double _c46 = _c3*_c39
    cdef double _c47 = pow(d, -11.0)
    cdef double _c48 = _c11*_c7
    cdef double _c49 = _c14*_c9
    cdef double _c50 = _c17*_c39
    cdef double _c51 = 0.5*_c23
    cdef double _c52 = 0.6*_c45
    cdef double _c53 = _c4*_c47
    cdef double _c54 = _c3*_c47
    cdef double _c55 = 4.666666666666667*_c54
    cdef double _c56 = 12.0*m_r
    cdef double _c57 = 9.0*_c3
    cdef double _c58 = pow(d, -12.0)
    cdef double _c59 = _c11*_c8
    cdef double _c60 = _c10*_c14
    cdef double _c61 = 0.4444444444444444*_c27
    cdef double _c62 = _c4*_c58
    cdef double _c63 = _c3*_c58
    cdef double _c64 = pow(d, -13.0)
    cdef double _c65 = _c11*_c9
    cdef double _c66 = _c4*_c64
    cdef double _c67 = _c3*_c64
    cdef double _c68 = pow(d, -14.0)
    cdef double _c69 = _c10*_c11
    cdef double _c70 = _c4*_c68
    cdef double _c71 = _c3*_c68
    cdef double _c72 = 4.0*_c5
    cdef double _c73 = _c72*m_r
    cdef double _c74 = _c7*m_r
    cdef double _c75 = _c9*m_r
    cdef double _c76 = _c39*m_r
    cdef double _c77 = 36.0*m_r
    cdef double _c78 = _c68*m_r
    cdef double _c79 = _c56*_c6
    cdef double _c80 = 16.0*_c74
    cdef double _c81 = _c8*m_r
    cdef double _c82 = 20.0*_c81
    cdef double _c83 = 24.0*_c75
    cdef double _c84 = 24.0*_c81
    cdef double _c85 = _c10*m_r
    cdef double _c86 = 28.0*_c85
    cdef double _c87 = 30.0*_c75
    cdef double _c88 = _c10*_c77
    cdef double _c89 = 40.0*_c85
    cdef double _c90 = 42.0*_c76
    cdef double _c91 = 48.0*_c76
    cdef double _c92 = _c47*m_r
    cdef double _c93 = 56.0*_c92
    cdef double _c94 = 60.0*_c92
    cdef double _c95 = _c58*m_r
    cdef double _c96 = 70.0*_c95
    cdef double _c97 = _c64*m_r
    cdef double _c98 = 84.0*_c97
    cdef double _c99 = 3.0*_c25
    cdef double _c100 = 3.0*_c34
    cdef double _c101 = 4.0*_c26
    cdef double _c102 = 5.0*_c27
    cdef double _c103 = 6.0*_c53
    cdef double _c104 = 7.0*_c66
    cdef double _c105 = 3.5*_c27
    cdef double _c106 = 4.5*_c27
    cdef double _c107 = 3.3333333333333335*_c26
    cdef double _c108 = 4.666666666666667*_c45
    cdef double _c109 = 5.333333333333333*_c45
    cdef double _c110 = 3.2*_c21
    cdef double _c111 = 3.4285714285714284*_c23
    cdef double _c112 = 5.6*_c53
    cdef double _c113 = 4.285714285714286*_c23
    cdef double _c114 = 6.363636363636363*_c62
    cdef double _c115 = 3.0*_c28
    cdef double _c116 = 4.0*_c34
    cdef double _c117 = 5.0*_c32
    cdef double _c118 = 6.0*_c36
    cdef double _c119 = 7.0*_c33
    cdef double _c120 = _c57*_c8
    cdef double _c121 = 12.0*_c36
    cdef double _c122 = 15.0*_c33
    cdef double _c123 = 18.0*_c46
    cdef double _c124 = 20.0*_c33
    cdef double _c125 = 63.0*_c67
    cdef double _c126 = 31.5*_c54
    cdef double _c127 = 37.5*_c54
    cdef double _c128 = 46.666666666666664*_c63
    cdef double _c129 = 25.714285714285715*_c46
    cdef double _c130 = (r_b*r_b*r_b*r_b)
    cdef double _c131 = (r_r*r_r*r_r*r_r)
    cdef double _c132 = (r_r*r_r*r_r)
    cdef double _c133 = 4.0*_c132
    cdef double _c134 = (r_b*r_b*r_b)
    cdef double _c135 = 4.0*_c134
    cdef double _c136 = (r_r*r_r)
    cdef double _c137 = (r_b*r_b)
    cdef double _c138 = 6.0*_c137
    cdef double _c139 = (S_T*S_T*S_T*S_T)
    cdef double _c140 = 2.0*_c139
    cdef double _c141 = (S_T*S_T)
    cdef double _c142 = _c141*r_b
    cdef double _c143 = 4.0*r_r
    cdef double _c144 = 2.0*_c141
    cdef double _c145 = 12.0*S_T
    cdef double _c146 = _c136*r_b
    cdef double _c147 = _c137*r_r
    cdef double _c148 = (S_T*S_T*S_T)
    cdef double _c149 = 4.0*_c148
    cdef double _c150 = _c149*r_b
    cdef double _c151 = _c149*r_r
    cdef double _c152 = 12.0*_c142
    cdef double _c153 = _c136*_c141
    cdef double _c154 = J_r*_c139
    cdef double _c155 = 2.0*r_b
    cdef double _c156 = _c155*r_r
    cdef double _c157 = 2.0*S_T
    cdef double _c158 = _c157*r_b
    cdef double _c159 = _c157*r_r
    cdef double _c160 = J_r*_c141
    cdef double _c161 = 2.0*_c160
    cdef double _c162 = _c136*_c160 + _c137*_c160 + _c156*_c160
    cdef double _c163 = J_r*_c140
    cdef double _c164 = J_r*_c148
    cdef double _c165 = _c164*r_r
    cdef double _c166 = _c155*_c164 + 2.0*_c165
    cdef double _c167 = (1.0/(d*d))
    cdef double _c168 = (1.0/(d*d*d))
    cdef double _c169 = 6.0*_c7
    cdef double _c170 = 2.0*_c167
    cdef double _c171 = 3.141592653589793*E
    cdef double _c172 = _c171*_c29
    cdef double _c173 = _c0*_c171
    cdef double _c174 = _c173*_c9
    cdef double _c175 = _c173*_c7
    cdef double _c176 = _c10*_c173
    cdef double _c177 = _c173*_c8
    cdef double _c178 = _c173*_c6
    cdef double _c179 = _c173*_c39
    cdef double _c180 = 0.5*_c4
    cdef double _c181 = _c173*_c47
    cdef double _c182 = _c173*_c58
    cdef double _c183 = _c173*_c64
    cdef double _c184 = _c173*_c68
    cdef double _c185 = 8.0*_c5
    cdef double _c186 = J_r*S_T
    cdef double _c187 = 6.0*pow(r_r, 5.0)
    cdef double _c188 = 6.0*pow(r_b, 5.0)
    cdef double _c189 = 15.0*_c131
    cdef double _c190 = 20.0*_c134
    cdef double _c191 = 15.0*_c130
    cdef double _c192 = pow(S_T, 6.0)
    cdef double _c193 = 3.0*_c141
    cdef double _c194 = 12.0*_c134
    cdef double _c195 = _c141*r_r
    cdef double _c196 = _c137*_c153
    cdef double _c197 = r_b*r_r
    cdef double _c198 = _c139*_c197
    cdef double _c199 = 3.0*_c139
    cdef double _c200 = 30.0*S_T
    cdef double _c201 = 60.0*S_T
    cdef double _c202 = pow(S_T, 5.0)
    cdef double _c203 = 6.0*_c202
    cdef double _c204 = _c203*r_b
    cdef double _c205 = _c203*r_r
    cdef double _c206 = 15.0*_c139
    cdef double _c207 = _c132*_c148
    cdef double _c208 = 60.0*_c148
    cdef double _c209 = 36.0*_c148
    cdef double _c210 = 12.0*_c202
    cdef double _c211 = 18.0*_c139
    cdef double _c212 = J_r*_c192
    cdef double _c213 = J_r*_c202
    cdef double _c214 = 2.0*r_r
    cdef double _c215 = _c164*r_b
    cdef double _c216 = _c165 + _c215
    cdef double _c217 = _c154*_c197
    cdef double _c218 = 4.0*_c154
    cdef double _c219 = _c213*r_b
    cdef double _c220 = _c143*_c213 + 4.0*_c219
    cdef double _c221 = _c143*r_b
    cdef double _c222 = 6.0*_c136
    cdef double _c223 = (Omega*Omega)
    cdef double _c224 = Omega*_c157
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
    ctx.k[15] = 0.1*_c4  # _k15
    ctx.k[16] = 0.4375*_c3  # _k16
    ctx.k[17] = _c10  # _k17
    ctx.k[18] = _c12  # _k18
    ctx.k[19] = _c13*_c6  # _k19
    ctx.k[20] = _c15  # _k20
    ctx.k[21] = _c16*_c8  # _k21
    ctx.k[22] = _c18  # _k22
    ctx.k[23] = _c10*_c19  # _k23
    ctx.k[24] = 0.5*_c20  # _k24
    ctx.k[25] = _c22  # _k25
    ctx.k[26] = _c24  # _k26
    ctx.k[27] = 0.6*_c25  # _k27
    ctx.k[28] = 0.7142857142857143*_c26  # _k28
    ctx.k[29] = 0.7777777777777778*_c27  # _k29
    ctx.k[30] = _c28  # _k30
    ctx.k[31] = _c31  # _k31
    ctx.k[32] = 2.0*_c32  # _k32
    ctx.k[33] = 3.0*_c33  # _k33
    ctx.k[34] = _c35  # _k34
    ctx.k[35] = _c37  # _k35
    ctx.k[36] = 0.45*_c3  # _k36
    ctx.k[37] = _c38  # _k37
    ctx.k[38] = 0.5357142857142857*_c3  # _k38
    ctx.k[39] = 0.5625*_c3  # _k39
    ctx.k[40] = 0.09090909090909091*_c4  # _k40
    ctx.k[41] = 0.5833333333333334*_c3  # _k41
    ctx.k[42] = _c39  # _k42
    ctx.k[43] = _c40  # _k43
    ctx.k[44] = _c13*_c7  # _k44
    ctx.k[45] = _c41  # _k45
    ctx.k[46] = _c16*_c9  # _k46
    ctx.k[47] = _c42  # _k47
    ctx.k[48] = _c19*_c39  # _k48
    ctx.k[49] = 0.5*_c21  # _k49
    ctx.k[50] = _c43  # _k50
    ctx.k[51] = 0.4*_c25  # _k51
    ctx.k[52] = _c44  # _k52
    ctx.k[53] = 0.625*_c23  # _k53
    ctx.k[54] = 0.7*_c45  # _k54
    ctx.k[55] = 0.5*_c28  # _k55
    ctx.k[56] = 1.8*_c32  # _k56
    ctx.k[57] = 1.125*_c34  # _k57
    ctx.k[58] = 3.2142857142857144*_c33  # _k58
    ctx.k[59] = 3.9375*_c46  # _k59
    ctx.k[60] = 0.5714285714285714*_c3  # _k60
    ctx.k[61] = 0.625*_c3  # _k61
    ctx.k[62] = 0.6666666666666666*_c3  # _k62
    ctx.k[63] = 0.08333333333333333*_c4  # _k63
    ctx.k[64] = 0.7*_c3  # _k64
    ctx.k[65] = _c47  # _k65
    ctx.k[66] = _c48  # _k66
    ctx.k[67] = _c13*_c8  # _k67
    ctx.k[68] = _c49  # _k68
    ctx.k[69] = _c10*_c16  # _k69
    ctx.k[70] = _c50  # _k70
    ctx.k[71] = _c19*_c47  # _k71
    ctx.k[72] = _c51  # _k72
    ctx.k[73] = 0.3333333333333333*_c21  # _k73
    ctx.k[74] = _c52  # _k74
    ctx.k[75] = 0.42857142857142855*_c26  # _k75
    ctx.k[76] = 0.5555555555555556*_c27  # _k76
    ctx.k[77] = 0.6363636363636364*_c53  # _k77
    ctx.k[78] = _c38*_c7  # _k78
    ctx.k[79] = 2.0*_c36  # _k79
    ctx.k[80] = 1.2*_c32  # _k80
    ctx.k[81] = _c55  # _k81
    ctx.k[82] = 3.75*_c46  # _k82
    ctx.k[83] = 2.857142857142857*_c33  # _k83
    ctx.k[84] = 0.6944444444444444*_c3  # _k84
    ctx.k[85] = _c56  # _k85
    ctx.k[86] = _c4  # _k86
    ctx.k[87] = _c57  # _k87
    ctx.k[88] = 0.08333333333333333*_c47  # _k88
    ctx.k[89] = 0.07692307692307693*_c4  # _k89
    ctx.k[90] = 0.7954545454545454*_c3  # _k90
    ctx.k[91] = _c58  # _k91
    ctx.k[92] = _c59  # _k92
    ctx.k[93] = _c13*_c9  # _k93
    ctx.k[94] = _c60  # _k94
    ctx.k[95] = _c16*_c39  # _k95
    ctx.k[96] = _c17*_c47  # _k96
    ctx.k[97] = _c19*_c58  # _k97
    ctx.k[98] = 0.5*_c45  # _k98
    ctx.k[99] = 0.2857142857142857*_c26  # _k99
    ctx.k[100] = 0.375*_c23  # _k100
    ctx.k[101] = _c61  # _k101
    ctx.k[102] = 0.5454545454545454*_c53  # _k102
    ctx.k[103] = 0.5833333333333334*_c62  # _k103
    ctx.k[104] = _c38*_c8  # _k104
    ctx.k[105] = 1.25*_c36  # _k105
    ctx.k[106] = 2.142857142857143*_c33  # _k106
    ctx.k[107] = 5.25*_c63  # _k107
    ctx.k[108] = 4.166666666666667*_c54  # _k108
    ctx.k[109] = 3.125*_c46  # _k109
    ctx.k[110] = 0.8181818181818182*_c3  # _k110
    ctx.k[111] = 0.07142857142857142*_c4  # _k111
    ctx.k[112] = 0.875*_c3  # _k112
    ctx.k[113] = _c64  # _k113
    ctx.k[114] = _c65  # _k114
    ctx.k[115] = _c10*_c13  # _k115
    ctx.k[116] = _c14*_c39  # _k116
    ctx.k[117] = _c16*_c47  # _k117
    ctx.k[118] = _c17*_c58  # _k118
    ctx.k[119] = _c19*_c64  # _k119
    ctx.k[120] = 0.5*_c62  # _k120
    ctx.k[121] = 0.3333333333333333*_c27  # _k121
    ctx.k[122] = 0.25*_c23  # _k122
    ctx.k[123] = 0.4*_c45  # _k123
    ctx.k[124] = 0.45454545454545453*_c53  # _k124
    ctx.k[125] = 0.5384615384615384*_c66  # _k125
    ctx.k[126] = _c38*_c9  # _k126
    ctx.k[127] = 4.5*_c63  # _k127
    ctx.k[128] = 2.25*_c46  # _k128
    ctx.k[129] = 1.2857142857142858*_c33  # _k129
    ctx.k[130] = 3.3333333333333335*_c54  # _k130
    ctx.k[131] = 5.7272727272727275*_c67  # _k131
    ctx.k[132] = 0.06666666666666667*_c4  # _k132
    ctx.k[133] = 0.9423076923076923*_c3  # _k133
    ctx.k[134] = _c68  # _k134
    ctx.k[135] = _c69  # _k135
    ctx.k[136] = _c13*_c39  # _k136
    ctx.k[137] = _c14*_c47  # _k137
    ctx.k[138] = _c16*_c58  # _k138
    ctx.k[139] = _c17*_c64  # _k139
    ctx.k[140] = _c19*_c68  # _k140
    ctx.k[141] = 0.5*_c70  # _k141
    ctx.k[142] = 0.2222222222222222*_c27  # _k142
    ctx.k[143] = 0.3*_c45  # _k143
    ctx.k[144] = 0.36363636363636365*_c53  # _k144
    ctx.k[145] = 0.4166666666666667*_c62  # _k145
    ctx.k[146] = 0.46153846153846156*_c66  # _k146
    ctx.k[147] = _c10*_c38  # _k147
    ctx.k[148] = 3.5*_c63  # _k148
    ctx.k[149] = 2.3333333333333335*_c54  # _k149
    ctx.k[150] = 1.3125*_c46  # _k150
    ctx.k[151] = 6.125*_c71  # _k151
    ctx.k[152] = 4.7727272727272725*_c67  # _k152
    ctx.k[153] = L_g*_c4 + m_r  # _k153
    ctx.k[154] = _c73  # _k154
    ctx.k[155] = 9.0*_c74  # _k155
    ctx.k[156] = 16.0*_c75  # _k156
    ctx.k[157] = 25.0*_c76  # _k157
    ctx.k[158] = _c58*_c77  # _k158
    ctx.k[159] = 49.0*_c78  # _k159
    ctx.k[160] = _c79  # _k160
    ctx.k[161] = _c80  # _k161
    ctx.k[162] = _c82  # _k162
    ctx.k[163] = _c83  # _k163
    ctx.k[164] = _c84  # _k164
    ctx.k[165] = _c86  # _k165
    ctx.k[166] = _c87  # _k166
    ctx.k[167] = _c88  # _k167
    ctx.k[168] = _c89  # _k168
    ctx.k[169] = _c90  # _k169
    ctx.k[170] = _c91  # _k170
    ctx.k[171] = _c93  # _k171
    ctx.k[172] = _c94  # _k172
    ctx.k[173] = _c96  # _k173
    ctx.k[174] = _c98  # _k174
    ctx.k[175] = 1.3333333333333333*_c20  # _k175
    ctx.k[176] = 1.8*_c21  # _k176
    ctx.k[177] = 2.2857142857142856*_c23  # _k177
    ctx.k[178] = 2.7777777777777777*_c45  # _k178
    ctx.k[179] = 3.272727272727273*_c62  # _k179
    ctx.k[180] = 3.769230769230769*_c70  # _k180
    ctx.k[181] = _c30  # _k181
    ctx.k[182] = _c99  # _k182
    ctx.k[183] = _c100  # _k183
    ctx.k[184] = _c101  # _k184
    ctx.k[185] = _c102  # _k185
    ctx.k[186] = _c103  # _k186
    ctx.k[187] = _c104  # _k187
    ctx.k[188] = 25.0*_c63  # _k188
    ctx.k[189] = _c105  # _k189
    ctx.k[190] = _c106  # _k190
    ctx.k[191] = _c107  # _k191
    ctx.k[192] = _c108  # _k192
    ctx.k[193] = _c109  # _k193
    ctx.k[194] = _c110  # _k194
    ctx.k[195] = _c111  # _k195
    ctx.k[196] = _c112  # _k196
    ctx.k[197] = _c113  # _k197
    ctx.k[198] = 7.2*_c36  # _k198
    ctx.k[199] = _c114  # _k199
    ctx.k[200] = 14.285714285714286*_c46  # _k200
    ctx.k[201] = 40.09090909090909*_c71  # _k201
    ctx.k[202] = _c115  # _k202
    ctx.k[203] = _c116  # _k203
    ctx.k[204] = _c117  # _k204
    ctx.k[205] = _c118  # _k205
    ctx.k[206] = _c119  # _k206
    ctx.k[207] = _c120  # _k207
    ctx.k[208] = _c121  # _k208
    ctx.k[209] = _c122  # _k209
    ctx.k[210] = _c123  # _k210
    ctx.k[211] = _c124  # _k211
    ctx.k[212] = _c125  # _k212
    ctx.k[213] = _c126  # _k213
    ctx.k[214] = _c127  # _k214
    ctx.k[215] = _c128  # _k215
    ctx.k[216] = _c129  # _k216
    ctx.k[217] = _c130 + _c131 + _c133*r_b + _c135*r_r + _c136*_c138  # _k217
    ctx.k[218] = _c139  # _k218
    ctx.k[219] = _c140  # _k219
    ctx.k[220] = _c136*_c144 + _c137*_c144 + _c142*_c143  # _k220
    ctx.k[221] = S_T*_c133 + S_T*_c135 + _c145*_c146 + _c145*_c147  # _k221
    ctx.k[222] = _c150 + _c151  # _k222
    ctx.k[223] = _c138*_c141 + _c152*r_r + 6.0*_c153  # _k223
    ctx.k[224] = _c154  # _k224
    ctx.k[225] = _c136 + _c137 + _c156  # _k225
    ctx.k[226] = _c141  # _k226
    ctx.k[227] = _c158 + _c159  # _k227
    ctx.k[228] = _c161  # _k228
    ctx.k[229] = _c162  # _k229
    ctx.k[230] = -_c161  # _k230
    ctx.k[231] = -J_r*_c158 - J_r*_c159  # _k231
    ctx.k[232] = -_c163  # _k232
    ctx.k[233] = -_c166  # _k233
    ctx.k[234] = _c166  # _k234
    ctx.k[235] = -_c167  # _k235
    ctx.k[236] = -_c168  # _k236
    ctx.k[237] = -_c5  # _k237
    ctx.k[238] = -_c6  # _k238
    ctx.k[239] = -_c7  # _k239
    ctx.k[240] = -_c8  # _k240
    ctx.k[241] = -7.0*_c8  # _k241
    ctx.k[242] = -_c169  # _k242
    ctx.k[243] = -5.0*_c6  # _k243
    ctx.k[244] = -_c72  # _k244
    ctx.k[245] = -3.0*_c168  # _k245
    ctx.k[246] = -_c170  # _k246
    ctx.k[247] = r_b + r_r  # _k247
    ctx.k[248] = -42.0*_c85  # _k248
    ctx.k[249] = -_c87  # _k249
    ctx.k[250] = -_c82  # _k250
    ctx.k[251] = -14.0*_c85  # _k251
    ctx.k[252] = -_c56*_c7  # _k252
    ctx.k[253] = -_c56*_c9  # _k253
    ctx.k[254] = -10.0*_c81  # _k254
    ctx.k[255] = -8.0*_c74  # _k255
    ctx.k[256] = -_c17*_c6  # _k256
    ctx.k[257] = -_c73  # _k257
    ctx.k[258] = -_c12  # _k258
    ctx.k[259] = -_c172  # _k259
    ctx.k[260] = -3.0*_c174  # _k260
    ctx.k[261] = -2.0*_c175  # _k261
    ctx.k[262] = -3.5*_c176  # _k262
    ctx.k[263] = -2.5*_c177  # _k263
    ctx.k[264] = -1.5*_c178  # _k264
    ctx.k[265] = -_c20  # _k265
    ctx.k[266] = -_c113  # _k266
    ctx.k[267] = -5.25*_c27  # _k267
    ctx.k[268] = -1.5555555555555556*_c27  # _k268
    ctx.k[269] = -2.4*_c21  # _k269
    ctx.k[270] = -_c107  # _k270
    ctx.k[271] = -1.4285714285714286*_c26  # _k271
    ctx.k[272] = -1.2*_c25  # _k272
    ctx.k[273] = -1.3333333333333333*_c21  # _k273
    ctx.k[274] = -1.5*_c25  # _k274
    ctx.k[275] = -1.5*_c23  # _k275
    ctx.k[276] = -0.6666666666666666*_c20  # _k276
    ctx.k[277] = -_c30  # _k277
    ctx.k[278] = -_c121  # _k278
    ctx.k[279] = -6.0*_c33  # _k279
    ctx.k[280] = -5.0*_c36  # _k280
    ctx.k[281] = -_c116  # _k281
    ctx.k[282] = -4.0*_c32  # _k282
    ctx.k[283] = -_c100  # _k283
    ctx.k[284] = -2.0*_c28  # _k284
    ctx.k[285] = -17.5*_c33  # _k285
    ctx.k[286] = -7.5*_c32  # _k286
    ctx.k[287] = -1.5*_c28  # _k287
    ctx.k[288] = -_c90  # _k288
    ctx.k[289] = -30.0*_c85  # _k289
    ctx.k[290] = -20.0*_c75  # _k290
    ctx.k[291] = -14.0*_c76  # _k291
    ctx.k[292] = -_c56*_c8  # _k292
    ctx.k[293] = -_c10*_c56  # _k293
    ctx.k[294] = -10.0*_c75  # _k294
    ctx.k[295] = -8.0*_c81  # _k295
    ctx.k[296] = -_c169*m_r  # _k296
    ctx.k[297] = -_c14*_c6  # _k297
    ctx.k[298] = -_c40  # _k298
    ctx.k[299] = -9.0*_c179  # _k299
    ctx.k[300] = -6.0*_c174  # _k300
    ctx.k[301] = -3.0*_c175  # _k301
    ctx.k[302] = -7.5*_c176  # _k302
    ctx.k[303] = -4.5*_c177  # _k303
    ctx.k[304] = -_c21  # _k304
    ctx.k[305] = -2.0*_c26  # _k305
    ctx.k[306] = -2.857142857142857*_c23  # _k306
    ctx.k[307] = -3.75*_c27  # _k307
    ctx.k[308] = -_c108  # _k308
    ctx.k[309] = -1.1428571428571428*_c26  # _k309
    ctx.k[310] = -1.4*_c45  # _k310
    ctx.k[311] = -1.2*_c21  # _k311
    ctx.k[312] = -1.25*_c23  # _k312
    ctx.k[313] = -1.3333333333333333*_c27  # _k313
    ctx.k[314] = -0.8*_c25  # _k314
    ctx.k[315] = -_c180*_c6  # _k315
    ctx.k[316] = -_c28  # _k316
    ctx.k[317] = -_c122  # _k317
    ctx.k[318] = -_c57*_c9  # _k318
    ctx.k[319] = -7.875*_c46  # _k319
    ctx.k[320] = -22.5*_c46  # _k320
    ctx.k[321] = -6.428571428571429*_c33  # _k321
    ctx.k[322] = -3.6*_c32  # _k322
    ctx.k[323] = -4.5*_c32  # _k323
    ctx.k[324] = -2.25*_c34  # _k324
    ctx.k[325] = -_c35  # _k325
    ctx.k[326] = -42.0*_c92  # _k326
    ctx.k[327] = -30.0*_c76  # _k327
    ctx.k[328] = -20.0*_c85  # _k328
    ctx.k[329] = -14.0*_c92  # _k329
    ctx.k[330] = -_c39*_c56  # _k330
    ctx.k[331] = -10.0*_c85  # _k331
    ctx.k[332] = -8.0*_c75  # _k332
    ctx.k[333] = -_c17*_c8  # _k333
    ctx.k[334] = -_c15  # _k334
    ctx.k[335] = -_c48  # _k335
    ctx.k[336] = -10.0*_c176  # _k336
    ctx.k[337] = -12.857142857142858*_c179  # _k337
    ctx.k[338] = -15.75*_c181  # _k338
    ctx.k[339] = -7.2*_c174  # _k339
    ctx.k[340] = -_c26  # _k340
    ctx.k[341] = -_c23  # _k341
    ctx.k[342] = -4.2*_c53  # _k342
    ctx.k[343] = -1.2727272727272727*_c53  # _k343
    ctx.k[344] = -1.7142857142857142*_c23  # _k344
    ctx.k[345] = -3.3333333333333335*_c45  # _k345
    ctx.k[346] = -1.1111111111111112*_c27  # _k346
    ctx.k[347] = -1.2*_c45  # _k347
    ctx.k[348] = -0.8571428571428571*_c26  # _k348
    ctx.k[349] = -2.5*_c27  # _k349
    ctx.k[350] = -_c22  # _k350
    ctx.k[351] = -0.4*_c21  # _k351
    ctx.k[352] = -_c34  # _k352
    ctx.k[353] = -10.0*_c33  # _k353
    ctx.k[354] = -4.0*_c36  # _k354
    ctx.k[355] = -17.142857142857142*_c46  # _k355
    ctx.k[356] = -26.25*_c54  # _k356
    ctx.k[357] = -5.714285714285714*_c33  # _k357
    ctx.k[358] = -9.333333333333334*_c54  # _k358
    ctx.k[359] = -4.8*_c36  # _k359
    ctx.k[360] = -7.5*_c46  # _k360
    ctx.k[361] = -2.4*_c32  # _k361
    ctx.k[362] = -1.5*_c32  # _k362
    ctx.k[363] = -42.0*_c95  # _k363
    ctx.k[364] = -30.0*_c92  # _k364
    ctx.k[365] = -20.0*_c76  # _k365
    ctx.k[366] = -14.0*_c95  # _k366
    ctx.k[367] = -_c47*_c56  # _k367
    ctx.k[368] = -10.0*_c76  # _k368
    ctx.k[369] = -8.0*_c85  # _k369
    ctx.k[370] = -_c18  # _k370
    ctx.k[371] = -_c41  # _k371
    ctx.k[372] = -_c59  # _k372
    ctx.k[373] = -14.285714285714286*_c179  # _k373
    ctx.k[374] = -18.75*_c181  # _k374
    ctx.k[375] = -23.333333333333332*_c182  # _k375
    ctx.k[376] = -_c45  # _k376
    ctx.k[377] = -3.0*_c53  # _k377
    ctx.k[378] = -3.8181818181818183*_c62  # _k378
    ctx.k[379] = -2.2222222222222223*_c45  # _k379
    ctx.k[380] = -1.0909090909090908*_c53  # _k380
    ctx.k[381] = -0.8888888888888888*_c27  # _k381
    ctx.k[382] = -1.1666666666666667*_c62  # _k382
    ctx.k[383] = -0.8571428571428571*_c23  # _k383
    ctx.k[384] = -_c44  # _k384
    ctx.k[385] = -1.5*_c27  # _k385
    ctx.k[386] = -_c24  # _k386
    ctx.k[387] = -0.3333333333333333*_c26  # _k387
    ctx.k[388] = -_c32  # _k388
    ctx.k[389] = -5.0*_c33  # _k389
    ctx.k[390] = -29.166666666666668*_c63  # _k390
    ctx.k[391] = -18.75*_c54  # _k391
    ctx.k[392] = -10.714285714285714*_c46  # _k392
    ctx.k[393] = -4.285714285714286*_c33  # _k393
    ctx.k[394] = -8.333333333333334*_c54  # _k394
    ctx.k[395] = -6.25*_c46  # _k395
    ctx.k[396] = -10.5*_c63  # _k396
    ctx.k[397] = -_c37  # _k397
    ctx.k[398] = -1.5*_c36  # _k398
    ctx.k[399] = -42.0*_c97  # _k399
    ctx.k[400] = -30.0*_c95  # _k400
    ctx.k[401] = -20.0*_c92  # _k401
    ctx.k[402] = -14.0*_c97  # _k402
    ctx.k[403] = -_c56*_c58  # _k403
    ctx.k[404] = -10.0*_c92  # _k404
    ctx.k[405] = -8.0*_c76  # _k405
    ctx.k[406] = -_c42  # _k406
    ctx.k[407] = -_c49  # _k407
    ctx.k[408] = -_c65  # _k408
    ctx.k[409] = -25.0*_c182  # _k409
    ctx.k[410] = -31.5*_c183  # _k410
    ctx.k[411] = -_c62  # _k411
    ctx.k[412] = -2.0*_c53  # _k412
    ctx.k[413] = -2.727272727272727*_c62  # _k413
    ctx.k[414] = -1.0769230769230769*_c66  # _k414
    ctx.k[415] = -0.9090909090909091*_c53  # _k415
    ctx.k[416] = -3.5*_c66  # _k416
    ctx.k[417] = -1.3333333333333333*_c45  # _k417
    ctx.k[418] = -0.8*_c45  # _k418
    ctx.k[419] = -0.75*_c27  # _k419
    ctx.k[420] = -_c43  # _k420
    ctx.k[421] = -0.2857142857142857*_c23  # _k421
    ctx.k[422] = -_c51  # _k422
    ctx.k[423] = -_c36  # _k423
    ctx.k[424] = -20.0*_c63  # _k424
    ctx.k[425] = -_c57*_c58  # _k425
    ctx.k[426] = -11.454545454545455*_c67  # _k426
    ctx.k[427] = -31.5*_c67  # _k427
    ctx.k[428] = -11.25*_c54  # _k428
    ctx.k[429] = -5.142857142857143*_c46  # _k429
    ctx.k[430] = -6.666666666666667*_c54  # _k430
    ctx.k[431] = -2.5714285714285716*_c33  # _k431
    ctx.k[432] = -4.5*_c46  # _k432
    ctx.k[433] = -1.5*_c33  # _k433
    ctx.k[434] = -42.0*_c78  # _k434
    ctx.k[435] = -30.0*_c97  # _k435
    ctx.k[436] = -20.0*_c95  # _k436
    ctx.k[437] = -14.0*_c78  # _k437
    ctx.k[438] = -_c56*_c64  # _k438
    ctx.k[439] = -10.0*_c95  # _k439
    ctx.k[440] = -8.0*_c92  # _k440
    ctx.k[441] = -_c50  # _k441
    ctx.k[442] = -_c60  # _k442
    ctx.k[443] = -_c69  # _k443
    ctx.k[444] = -40.09090909090909*_c184  # _k444
    ctx.k[445] = -_c70  # _k445
    ctx.k[446] = -3.230769230769231*_c70  # _k446
    ctx.k[447] = -1.8181818181818181*_c62  # _k447
    ctx.k[448] = -0.9230769230769231*_c66  # _k448
    ctx.k[449] = -0.7272727272727273*_c53  # _k449
    ctx.k[450] = -1.2*_c53  # _k450
    ctx.k[451] = -2.5*_c66  # _k451
    ctx.k[452] = -0.8333333333333334*_c62  # _k452
    ctx.k[453] = -_c61  # _k453
    ctx.k[454] = -_c52  # _k454
    ctx.k[455] = -0.6666666666666666*_c45  # _k455
    ctx.k[456] = -0.25*_c27  # _k456
    ctx.k[457] = -_c33  # _k457
    ctx.k[458] = -21.0*_c67  # _k458
    ctx.k[459] = -7.0*_c63  # _k459
    ctx.k[460] = -33.40909090909091*_c71  # _k460
    ctx.k[461] = -9.545454545454545*_c67  # _k461
    ctx.k[462] = -12.25*_c71  # _k462
    ctx.k[463] = -11.666666666666666*_c63  # _k463
    ctx.k[464] = -5.25*_c54  # _k464
    ctx.k[465] = -2.625*_c46  # _k465
    ctx.k[466] = -_c55  # _k466
    ctx.k[467] = -1.5*_c46  # _k467
    ctx.k[468] = -_c180  # _k468
    ctx.k[469] = -294.0*_c78  # _k469
    ctx.k[470] = -180.0*_c95  # _k470
    ctx.k[471] = -100.0*_c76  # _k471
    ctx.k[472] = -48.0*_c75  # _k472
    ctx.k[473] = -18.0*_c74  # _k473
    ctx.k[474] = -0.5*_c172  # _k474
    ctx.k[475] = -462.0*_c97  # _k475
    ctx.k[476] = -350.0*_c95  # _k476
    ctx.k[477] = -270.0*_c92  # _k477
    ctx.k[478] = -252.0*_c92  # _k478
    ctx.k[479] = -192.0*_c76  # _k479
    ctx.k[480] = -168.0*_c76  # _k480
    ctx.k[481] = -140.0*_c85  # _k481
    ctx.k[482] = -126.0*_c85  # _k482
    ctx.k[483] = -98.0*_c85  # _k483
    ctx.k[484] = -98.0*_c78  # _k484
    ctx.k[485] = -90.0*_c75  # _k485
    ctx.k[486] = -_c98  # _k486
    ctx.k[487] = -72.0*_c75  # _k487
    ctx.k[488] = -72.0*_c95  # _k488
    ctx.k[489] = -_c96  # _k489
    ctx.k[490] = -60.0*_c81  # _k490
    ctx.k[491] = -_c94  # _k491
    ctx.k[492] = -_c93  # _k492
    ctx.k[493] = -50.0*_c179  # _k493
    ctx.k[494] = -50.0*_c81  # _k494
    ctx.k[495] = -50.0*_c76  # _k495
    ctx.k[496] = -_c91  # _k496
    ctx.k[497] = -_c89  # _k497
    ctx.k[498] = -_c88  # _k498
    ctx.k[499] = -32.0*_c74  # _k499
    ctx.k[500] = -32.0*_c75  # _k500
    ctx.k[501] = -_c86  # _k501
    ctx.k[502] = -_c83  # _k502
    ctx.k[503] = -_c84  # _k503
    ctx.k[504] = -18.0*_c174  # _k504
    ctx.k[505] = -18.0*_c6*m_r  # _k505
    ctx.k[506] = -_c80  # _k506
    ctx.k[507] = -_c79  # _k507
    ctx.k[508] = -_c185*m_r  # _k508
    ctx.k[509] = -220.5*_c184  # _k509
    ctx.k[510] = -112.5*_c182  # _k510
    ctx.k[511] = -4.5*_c175  # _k511
    ctx.k[512] = -315.0*_c183  # _k512
    ctx.k[513] = -210.0*_c182  # _k513
    ctx.k[514] = -150.0*_c181  # _k514
    ctx.k[515] = -126.0*_c181  # _k515
    ctx.k[516] = -90.0*_c179  # _k516
    ctx.k[517] = -63.0*_c179  # _k517
    ctx.k[518] = -60.0*_c176  # _k518
    ctx.k[519] = -45.0*_c176  # _k519
    ctx.k[520] = -30.0*_c174  # _k520
    ctx.k[521] = -21.0*_c176  # _k521
    ctx.k[522] = -18.0*_c177  # _k522
    ctx.k[523] = -18.0*_c62  # _k523
    ctx.k[524] = -15.0*_c174  # _k524
    ctx.k[525] = -10.0*_c177  # _k525
    ctx.k[526] = -8.0*_c23  # _k526
    ctx.k[527] = -_c169*_c173  # _k527
    ctx.k[528] = -3.0*_c178  # _k528
    ctx.k[529] = -2.0*_c20  # _k529
    ctx.k[530] = -24.5*_c70  # _k530
    ctx.k[531] = -12.5*_c45  # _k531
    ctx.k[532] = -4.5*_c21  # _k532
    ctx.k[533] = -_c31  # _k533
    ctx.k[534] = -50.0*_c46  # _k534
    ctx.k[535] = -42.0*_c66  # _k535
    ctx.k[536] = -35.0*_c62  # _k536
    ctx.k[537] = -30.0*_c53  # _k537
    ctx.k[538] = -28.0*_c53  # _k538
    ctx.k[539] = -24.0*_c45  # _k539
    ctx.k[540] = -21.0*_c45  # _k540
    ctx.k[541] = -20.0*_c27  # _k541
    ctx.k[542] = -18.0*_c27  # _k542
    ctx.k[543] = -18.0*_c36  # _k543
    ctx.k[544] = -15.0*_c23  # _k544
    ctx.k[545] = -14.0*_c27  # _k545
    ctx.k[546] = -12.0*_c23  # _k546
    ctx.k[547] = -12.0*_c26  # _k547
    ctx.k[548] = -10.0*_c26  # _k548
    ctx.k[549] = -8.0*_c21  # _k549
    ctx.k[550] = -_c104  # _k550
    ctx.k[551] = -6.0*_c25  # _k551
    ctx.k[552] = -_c103  # _k552
    ctx.k[553] = -_c102  # _k553
    ctx.k[554] = -_c101  # _k554
    ctx.k[555] = -_c99  # _k555
    ctx.k[556] = -220.5*_c71  # _k556
    ctx.k[557] = -112.5*_c63  # _k557
    ctx.k[558] = -7.538461538461538*_c70  # _k558
    ctx.k[559] = -6.545454545454546*_c62  # _k559
    ctx.k[560] = -_c114  # _k560
    ctx.k[561] = -5.555555555555555*_c45  # _k561
    ctx.k[562] = -4.571428571428571*_c23  # _k562
    ctx.k[563] = -_c112  # _k563
    ctx.k[564] = -_c111  # _k564
    ctx.k[565] = -3.6*_c21  # _k565
    ctx.k[566] = -_c109  # _k566
    ctx.k[567] = -_c110  # _k567
    ctx.k[568] = -_c106  # _k568
    ctx.k[569] = -4.5*_c34  # _k569
    ctx.k[570] = -2.6666666666666665*_c20  # _k570
    ctx.k[571] = -_c105  # _k571
    ctx.k[572] = -315.0*_c67  # _k572
    ctx.k[573] = -210.0*_c63  # _k573
    ctx.k[574] = -150.0*_c54  # _k574
    ctx.k[575] = -126.0*_c54  # _k575
    ctx.k[576] = -90.0*_c46  # _k576
    ctx.k[577] = -63.0*_c46  # _k577
    ctx.k[578] = -_c125  # _k578
    ctx.k[579] = -60.0*_c33  # _k579
    ctx.k[580] = -50.0*_c63  # _k580
    ctx.k[581] = -45.0*_c33  # _k581
    ctx.k[582] = -30.0*_c36  # _k582
    ctx.k[583] = -21.0*_c33  # _k583
    ctx.k[584] = -_c124  # _k584
    ctx.k[585] = -18.0*_c32  # _k585
    ctx.k[586] = -_c123  # _k586
    ctx.k[587] = -15.0*_c36  # _k587
    ctx.k[588] = -10.0*_c32  # _k588
    ctx.k[589] = -_c120  # _k589
    ctx.k[590] = -_c119  # _k590
    ctx.k[591] = -_c169*_c3  # _k591
    ctx.k[592] = -_c118  # _k592
    ctx.k[593] = -_c117  # _k593
    ctx.k[594] = -_c115  # _k594
    ctx.k[595] = -2.0*_c30  # _k595
    ctx.k[596] = -80.18181818181819*_c71  # _k596
    ctx.k[597] = -28.571428571428573*_c46  # _k597
    ctx.k[598] = -_c129  # _k598
    ctx.k[599] = -_c128  # _k599
    ctx.k[600] = -_c127  # _k600
    ctx.k[601] = -14.4*_c36  # _k601
    ctx.k[602] = -_c126  # _k602
    ctx.k[603] = _c160  # _k603
    ctx.k[604] = _c186*r_b + _c186*r_r  # _k604
    ctx.k[605] = -_c160  # _k605
    ctx.k[606] = _c163  # _k606
    ctx.k[607] = _c132*_c190 + _c136*_c191 + _c137*_c189 + _c187*r_b + _c188*r_r + pow(r_b, 6.0) + pow(r_r, 6.0)  # _k607
    ctx.k[608] = _c192  # _k608
    ctx.k[609] = 3.0*_c192  # _k609
    ctx.k[610] = _c130*_c193 + _c131*_c193 + _c132*_c152 + _c194*_c195 + 18.0*_c196  # _k610
    ctx.k[611] = _c136*_c199 + _c137*_c199 + 6.0*_c198  # _k611
    ctx.k[612] = S_T*_c187 + S_T*_c188 + _c130*_c200*r_r + _c131*_c200*r_b + _c132*_c137*_c201 + _c134*_c136*_c201  # _k612
    ctx.k[613] = _c204 + _c205  # _k613
    ctx.k[614] = 60.0*_c132*_c142 + 60.0*_c134*_c195 + _c141*_c189 + _c141*_c191 + 90.0*_c196  # _k614
    ctx.k[615] = _c136*_c206 + _c137*_c206 + 30.0*_c198  # _k615
    ctx.k[616] = _c146*_c208 + _c147*_c208 + _c148*_c190 + 20.0*_c207  # _k616
    ctx.k[617] = _c146*_c209 + _c147*_c209 + _c148*_c194 + 12.0*_c207  # _k617
    ctx.k[618] = _c210*r_b + _c210*r_r  # _k618
    ctx.k[619] = _c136*_c211 + _c137*_c211 + 36.0*_c198  # _k619
    ctx.k[620] = 2.0*_c212  # _k620
    ctx.k[621] = _c155*_c213 + _c213*_c214  # _k621
    ctx.k[622] = _c216  # _k622
    ctx.k[623] = -_c154  # _k623
    ctx.k[624] = -_c216  # _k624
    ctx.k[625] = -_c162  # _k625
    ctx.k[626] = -4.0*_c212  # _k626
    ctx.k[627] = -_c136*_c218 - _c137*_c218 - 8.0*_c217  # _k627
    ctx.k[628] = -_c220  # _k628
    ctx.k[629] = -_c136*_c161 - _c137*_c161 - _c160*_c221  # _k629
    ctx.k[630] = 2.0*J_r*_c207 + 2.0*_c134*_c164 + _c138*_c165 + _c215*_c222  # _k630
    ctx.k[631] = _c136*_c163 + _c137*_c163 + _c154*_c221  # _k631
    ctx.k[632] = -8.0*_c213*r_r - 8.0*_c219  # _k632
    ctx.k[633] = -J_r*_c150 - J_r*_c151  # _k633
    ctx.k[634] = _c220  # _k634
    ctx.k[635] = _c138*_c154 + _c154*_c222 + 12.0*_c217  # _k635
    ctx.k[636] = J_r*_c204 + J_r*_c205  # _k636
    ctx.k[637] = _c223*r_b + _c223*r_r  # _k637
    ctx.k[638] = _c170  # _k638
    ctx.k[639] = S_T*_c223  # _k639
    ctx.k[640] = -S_T  # _k640
    ctx.k[641] = -Omega*_c155 - Omega*_c214  # _k641
    ctx.k[642] = _c157  # _k642
    ctx.k[643] = 4.0*_c167  # _k643
    ctx.k[644] = 6.0*_c168  # _k644
    ctx.k[645] = _c185  # _k645
    ctx.k[646] = 10.0*_c6  # _k646
    ctx.k[647] = 12.0*_c5  # _k647
    ctx.k[648] = 12.0*_c7  # _k648
    ctx.k[649] = 14.0*_c8  # _k649
    ctx.k[650] = 20.0*_c6  # _k650
    ctx.k[651] = 30.0*_c7  # _k651
    ctx.k[652] = 42.0*_c8  # _k652
    ctx.k[653] = -_c224  # _k653
    ctx.k[654] = -_c157  # _k654
    ctx.k[655] = _c224  # _k655
    ctx.k[656] = -d  # _k656
    ctx.k[657] = -Omega  # _k657
    ctx.k[658] = _c167  # _k658
    ctx.k[659] = _c168  # _k659


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
    cdef double _k484 = ctx.k[484]
    cdef double _k485 = ctx.k[485]
    cdef double _k486 = ctx.k[486]
    cdef double _k487 = ctx.k[487]
    cdef double _k488 = ctx.k[488]
    cdef double _k489 = ctx.k[489]
    cdef double _k490 = ctx.k[490]
    cdef double _k491 = ctx.k[491]
    cdef double _k492 = ctx.k[492]
    cdef double _k493 = ctx.k[493]
    cdef double _k494 = ctx.k[494]
    cdef double _k495 = ctx.k[495]
    cdef double _k496 = ctx.k[496]
    cdef double _k497 = ctx.k[497]
    cdef double _k498 = ctx.k[498]
    cdef double _k499 = ctx.k[499]
    cdef double _k500 = ctx.k[500]
    cdef double _k501 = ctx.k[501]
    cdef double _k502 = ctx.k[502]
    cdef double _k503 = ctx.k[503]
    cdef double _k504 = ctx.k[504]
    cdef double _k505 = ctx.k[505]
    cdef double _k506 = ctx.k[506]
    cdef double _k507 = ctx.k[507]
    cdef double _k508 = ctx.k[508]
    cdef double _k509 = ctx.k[509]
    cdef double _k510 = ctx.k[510]
    cdef double _k511 = ctx.k[511]
    cdef double _k512 = ctx.k[512]
    cdef double _k513 = ctx.k[513]
    cdef double _k514 = ctx.k[514]
    cdef double _k515 = ctx.k[515]
    cdef double _k516 = ctx.k[516]
    cdef double _k517 = ctx.k[517]
    cdef double _k518 = ctx.k[518]
    cdef double _k519 = ctx.k[519]
    cdef double _k520 = ctx.k[520]
    cdef double _k521 = ctx.k[521]
    cdef double _k522 = ctx.k[522]
    cdef double _k523 = ctx.k[523]
    cdef double _k524 = ctx.k[524]
    cdef double _k525 = ctx.k[525]
    cdef double _k526 = ctx.k[526]
    cdef double _k527 = ctx.k[527]
    cdef double _k528 = ctx.k[528]
    cdef double _k529 = ctx.k[529]
    cdef double _k530 = ctx.k[530]
    cdef double _k531 = ctx.k[531]
    cdef double _k532 = ctx.k[532]
    cdef double _k533 = ctx.k[533]
    cdef double _k534 = ctx.k[534]
    cdef double _k535 = ctx.k[535]
    cdef double _k536 = ctx.k[536]
    cdef double _k537 = ctx.k[537]
    cdef double _k538 = ctx.k[538]
    cdef double _k539 = ctx.k[539]
    cdef double _k540 = ctx.k[540]
    cdef double _k541 = ctx.k[541]
    cdef double _k542 = ctx.k[542]
    cdef double _k543 = ctx.k[543]
    cdef double _k544 = ctx.k[544]
    cdef double _k545 = ctx.k[545]
    cdef double _k546 = ctx.k[546]
    cdef double _k547 = ctx.k[547]
    cdef double _k548 = ctx.k[548]
    cdef double _k549 = ctx.k[549]
    cdef double _k550 = ctx.k[550]
    cdef double _k551 = ctx.k[551]
    cdef double _k552 = ctx.k[552]
    cdef double _k553 = ctx.k[553]
    cdef double _k554 = ctx.k[554]
    cdef double _k555 = ctx.k[555]
    cdef double _k556 = ctx.k[556]
    cdef double _k557 = ctx.k[557]
    cdef double _k558 = ctx.k[558]
    cdef double _k559 = ctx.k[559]
    cdef double _k560 = ctx.k[560]
    cdef double _k561 = ctx.k[561]
    cdef double _k562 = ctx.k[562]
    cdef double _k563 = ctx.k[563]
    cdef double _k564 = ctx.k[564]
    cdef double _k565 = ctx.k[565]
    cdef double _k566 = ctx.k[566]
    cdef double _k567 = ctx.k[567]
    cdef double _k568 = ctx.k[568]
    cdef double _k569 = ctx.k[569]
    cdef double _k570 = ctx.k[570]
    cdef double _k571 = ctx.k[571]
    cdef double _k572 = ctx.k[572]
    cdef double _k573 = ctx.k[573]
    cdef double _k574 = ctx.k[574]
    cdef double _k575 = ctx.k[575]
    cdef double _k576 = ctx.k[576]
    cdef double _k577 = ctx.k[577]
    cdef double _k578 = ctx.k[578]
    cdef double _k579 = ctx.k[579]
    cdef double _k580 = ctx.k[580]
    cdef double _k581 = ctx.k[581]
    cdef double _k582 = ctx.k[582]
    cdef double _k583 = ctx.k[583]
    cdef double _k584 = ctx.k[584]
    cdef double _k585 = ctx.k[585]
    cdef double _k586 = ctx.k[586]
    cdef double _k587 = ctx.k[587]
    cdef double _k588 = ctx.k[588]
    cdef double _k589 = ctx.k[589]
    cdef double _k590 = ctx.k[590]
    cdef double _k591 = ctx.k[591]
    cdef double _k592 = ctx.k[592]
    cdef double _k593 = ctx.k[593]
    cdef double _k594 = ctx.k[594]
    cdef double _k595 = ctx.k[595]
    cdef double _k596 = ctx.k[596]
    cdef double _k597 = ctx.k[597]
    cdef double _k598 = ctx.k[598]
    cdef double _k599 = ctx.k[599]
    cdef double _k600 = ctx.k[600]
    cdef double _k601 = ctx.k[601]
    cdef double _k602 = ctx.k[602]
    cdef double _k603 = ctx.k[603]
    cdef double _k604 = ctx.k[604]
    cdef double _k605 = ctx.k[605]
    cdef double _k606 = ctx.k[606]
    cdef double _k607 = ctx.k[607]
    cdef double _k608 = ctx.k[608]
    cdef double _k609 = ctx.k[609]
    cdef double _k610 = ctx.k[610]
    cdef double _k611 = ctx.k[611]
    cdef double _k612 = ctx.k[612]
    cdef double _k613 = ctx.k[613]
    cdef double _k614 = ctx.k[614]
    cdef double _k615 = ctx.k[615]
    cdef double _k616 = ctx.k[616]
    cdef double _k617 = ctx.k[617]
    cdef double _k618 = ctx.k[618]
    cdef double _k619 = ctx.k[619]
    cdef double _k620 = ctx.k[620]
    cdef double _k621 = ctx.k[621]
    cdef double _k622 = ctx.k[622]
    cdef double _k623 = ctx.k[623]
    cdef double _k624 = ctx.k[624]
    cdef double _k625 = ctx.k[625]
    cdef double _k626 = ctx.k[626]
    cdef double _k627 = ctx.k[627]
    cdef double _k628 = ctx.k[628]
    cdef double _k629 = ctx.k[629]
    cdef double _k630 = ctx.k[630]
    cdef double _k631 = ctx.k[631]
    cdef double _k632 = ctx.k[632]
    cdef double _k633 = ctx.k[633]
    cdef double _k634 = ctx.k[634]
    cdef double _k635 = ctx.k[635]
    cdef double _k636 = ctx.k[636]
    cdef double _k637 = ctx.k[637]
    cdef double _k638 = ctx.k[638]
    cdef double _k639 = ctx.k[639]
    cdef double _k640 = ctx.k[640]
    cdef double _k641 = ctx.k[641]
    cdef double _k642 = ctx.k[642]
    cdef double _k643 = ctx.k[643]
    cdef double _k644 = ctx.k[644]
    cdef double _k645 = ctx.k[645]
    cdef double _k646 = ctx.k[646]
    cdef double _k647 = ctx.k[647]
    cdef double _k648 = ctx.k[648]
    cdef double _k649 = ctx.k[649]
    cdef double _k650 = ctx.k[650]
    cdef double _k651 = ctx.k[651]
    cdef double _k652 = ctx.k[652]
    cdef double _k653 = ctx.k[653]
    cdef double _k654 = ctx.k[654]
    cdef double _k655 = ctx.k[655]
    cdef double _k656 = ctx.k[656]
    cdef double _k657 = ctx.k[657]
    cdef double _k658 = ctx.k[658]
    cdef double _k659 = ctx.k[659]
    cdef double b1 = _y[0]
    cdef double b2 = _y[1]
    cdef double b3 = _y[2]
    cdef double b4 = _y[3]
    cdef double b5 = _y[4]
    cdef double b6 = _y[5]
    cdef double xE = _y[6]
    cdef double theta = _y[7]
    cdef double b1d = _y[8]
    cdef double b2d = _y[9]
    cdef double b3d = _y[10]
    cdef double b4d = _y[11]
    cdef double b5d = _y[12]
    cdef double b6d = _y[13]
    cdef double xEd = _y[14]
    cdef double thetad = _y[15]
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
    cdef double _s17 = _k15*_s2 + _s1
    cdef double _s18 = pow(xE, 8.0)
    cdef double _s19 = _k17*_s18
    cdef double _s20 = _s19*(_k16 + _s17)
    cdef double _s21 = _s0*b1
    cdef double _s22 = _s3*b2
    cdef double _s23 = _s6*b3
    cdef double _s24 = _s10*b4
    cdef double _s25 = _s14*b5
    cdef double _s26 = _s18*b6
    cdef double _s27 = _s3*b1
    cdef double _s28 = _s10*b3
    cdef double _s29 = _s18*b5
    cdef double _s30 = _s6*b2
    cdef double _s31 = _s14*b4
    cdef double _s32 = pow(xE, 9.0)
    cdef double _s33 = _s32*b6
    cdef double _s34 = _s0*b2
    cdef double _s35 = _s2*b1
    cdef double _s36 = _s6*b4
    cdef double _s37 = _s14*b6
    cdef double _s38 = _s3*b3
    cdef double _s39 = _s10*b5
    cdef double _s40 = _k18*_s21 + _k19*_s22 + _k20*_s23 + _k21*_s24 + _k22*_s25 + _k23*_s26 + _k24*_s27 + _k25*_s28 + _k26*_s29 + _k27*_s30 + _k28*_s31 + _k29*_s33 + _k30*_s34 + _k31*_s35 + _k32*_s36 + _k33*_s37 + _k34*_s38 + _k35*_s39
    cdef double _s41 = _s11*(_k37 + _s9)
    cdef double _s42 = _s15*(_k38 + _s13)
    cdef double _s43 = _s19*(_k39 + _s17)
    cdef double _s44 = _k40*_s2 + _s1
    cdef double _s45 = _k42*_s32
    cdef double _s46 = _s45*(_k41 + _s44)
    cdef double _s47 = _s10*b2
    cdef double _s48 = _s32*b5
    cdef double _s49 = _s6*b1
    cdef double _s50 = _s14*b3
    cdef double _s51 = _s18*b4
    cdef double _s52 = pow(xE, 10.0)
    cdef double _s53 = _s52*b6
    cdef double _s54 = _k35*_s24 + _k43*_s27 + _k44*_s30 + _k45*_s28 + _k46*_s31 + _k47*_s29 + _k48*_s33 + _k49*_s47 + _k50*_s48 + _k51*_s49 + _k52*_s50 + _k53*_s51 + _k54*_s53 + _k55*_s21 + _k56*_s23 + _k57*_s22 + _k58*_s25 + _k59*_s26
    cdef double _s55 = _s19*(_k61 + _s17)
    cdef double _s56 = _s45*(_k62 + _s44)
    cdef double _s57 = _k65*_s52*(_k63*_s2 + _k64 + _s1)
    cdef double _s58 = _s18*b3
    cdef double _s59 = _s10*b1
    cdef double _s60 = _s52*b5
    cdef double _s61 = _s14*b2
    cdef double _s62 = _s32*b4
    cdef double _s63 = pow(xE, 11.0)
    cdef double _s64 = _s63*b6
    cdef double _s65 = _k66*_s49 + _k67*_s47 + _k68*_s50 + _k69*_s51 + _k70*_s48 + _k71*_s53 + _k72*_s58 + _k73*_s59 + _k74*_s60 + _k75*_s61 + _k76*_s62 + _k77*_s64 + _k78*_s27 + _k79*_s28 + _k80*_s30 + _k81*_s33 + _k82*_s29 + _k83*_s31
    cdef double _s66 = _k88*_s52*(_k85*xE + _k86*_s2 + _k87)
    cdef double _s67 = _k89*_s2 + _s1
    cdef double _s68 = _k91*_s63
    cdef double _s69 = _s68*(_k90 + _s67)
    cdef double _s70 = _s18*b2
    cdef double _s71 = _s32*b3
    cdef double _s72 = _s63*b5
    cdef double _s73 = pow(xE, 12.0)
    cdef double _s74 = _s73*b6
    cdef double _s75 = _s52*b4
    cdef double _s76 = _s14*b1
    cdef double _s77 = _k100*_s70 + _k101*_s71 + _k102*_s72 + _k103*_s74 + _k104*_s49 + _k105*_s47 + _k106*_s50 + _k107*_s53 + _k108*_s48 + _k109*_s51 + _k92*_s59 + _k93*_s61 + _k94*_s58 + _k95*_s62 + _k96*_s60 + _k97*_s64 + _k98*_s75 + _k99*_s76
    cdef double _s78 = _k113*_s73*(_k111*_s2 + _k112 + _s1)
    cdef double _s79 = _s73*b5
    cdef double _s80 = _s32*b2
    cdef double _s81 = _s18*b1
    cdef double _s82 = _s52*b3
    cdef double _s83 = _s63*b4
    cdef double _s84 = pow(xE, 13.0)
    cdef double _s85 = _s84*b6
    cdef double _s86 = _k114*_s76 + _k115*_s70 + _k116*_s71 + _k117*_s75 + _k118*_s72 + _k119*_s74 + _k120*_s79 + _k121*_s80 + _k122*_s81 + _k123*_s82 + _k124*_s83 + _k125*_s85 + _k126*_s59 + _k127*_s60 + _k128*_s58 + _k129*_s61 + _k130*_s62 + _k131*_s64
    cdef double _s87 = pow(xE, 14.0)
    cdef double _s88 = _k135*_s81 + _k136*_s80 + _k137*_s82 + _k138*_s83 + _k139*_s79 + _k140*_s85 + _k141*_s87*b6 + _k142*_s32*b1 + _k143*_s52*b2 + _k144*_s63*b3 + _k145*_s73*b4 + _k146*_s84*b5 + _k147*_s76 + _k148*_s75 + _k149*_s71 + _k150*_s70 + _k151*_s74 + _k152*_s72
    cdef double _s89 = (b1*b1)
    cdef double _s90 = _s89*xE
    cdef double _s91 = _s21*b2
    cdef double _s92 = _s27*b3
    cdef double _s93 = _s23*b2
    cdef double _s94 = _s24*b2
    cdef double _s95 = _s25*b2
    cdef double _s96 = _s31*b3
    cdef double _s97 = _s26*b2
    cdef double _s98 = _s29*b3
    cdef double _s99 = _s33*b3
    cdef double _s100 = _s48*b4
    cdef double _s101 = _s53*b4
    cdef double _s102 = _s64*b5
    cdef double _s103 = _s35*b2
    cdef double _s104 = _s21*b3
    cdef double _s105 = _s27*b4
    cdef double _s106 = _s49*b5
    cdef double _s107 = _s59*b6
    cdef double _s108 = _s22*b3
    cdef double _s109 = _s30*b4
    cdef double _s110 = _s39*b2
    cdef double _s111 = _s37*b2
    cdef double _s112 = _s24*b3
    cdef double _s113 = _s53*b5
    cdef double _s114 = _s26*b3
    cdef double _s115 = _s29*b4
    cdef double _s116 = _s33*b4
    cdef double _s117 = _s25*b3
    cdef double _s118 = _s2*_s89
    cdef double _s119 = (b2*b2)
    cdef double _s120 = _s119*_s3
    cdef double _s121 = (b3*b3)
    cdef double _s122 = _s10*_s121
    cdef double _s123 = (b4*b4)
    cdef double _s124 = _s123*_s18
    cdef double _s125 = (b5*b5)
    cdef double _s126 = _s125*_s52
    cdef double _s127 = (b6*b6)
    cdef double _s128 = _s127*_s73
    cdef double _s129 = _s0*_s119
    cdef double _s130 = _s125*_s32
    cdef double _s131 = _s121*_s6
    cdef double _s132 = _s123*_s14
    cdef double _s133 = _s127*_s63
    cdef double _s134 = (_cam0[0]*_cam0[0])
    cdef double _s135 = (_cam0[1]*_cam0[1])
    cdef double _s136 = (1.0/(_cam0[0]*_k227 + _k225 + _k226*_s134 + _k226*_s135))
    cdef double _s137 = _cam0[2]*_s136
    cdef double _s138 = (_cam0[1]*_cam0[1]*_cam0[1]*_cam0[1])
    cdef double _s139 = (_cam0[0]*_cam0[0]*_cam0[0])
    cdef double _s140 = (_cam0[0]*_cam0[0]*_cam0[0]*_cam0[0])
    cdef double _s141 = _cam0[0]*_s135
    cdef double _s142 = _s134*_s135
    cdef double _s143 = (1.0/(_cam0[0]*_k221 + _k217 + _k218*_s138 + _k218*_s140 + _k219*_s142 + _k220*_s135 + _k222*_s139 + _k222*_s141 + _k223*_s134))
    cdef double _s144 = _k224*_s143
    cdef double _s145 = (_cam0[2]*_cam0[2])
    cdef double _s146 = _s143*_s145
    cdef double _s147 = _cam0[0]*_s146
    cdef double _s148 = _cam0[2]*_s143
    cdef double _s149 = _k233*_s148
    cdef double _s150 = _k232*_s148
    cdef double _s151 = _s134*_s145
    cdef double _s152 = _k235*_s2
    cdef double _s153 = _k236*_s0
    cdef double _s154 = _k237*_s3
    cdef double _s155 = _k238*_s6
    cdef double _s156 = _k239*_s10
    cdef double _s157 = _k240*_s14
    cdef double _s158 = b1*xE
    cdef double _s159 = _s10*b6
    cdef double _s160 = _s6*b5
    cdef double _s161 = _s3*b4
    cdef double _s162 = _s0*b3
    cdef double _s163 = _s2*b2
    cdef double _s164 = Omega*t - theta
    cdef double _s165 = sin(_s164)
    cdef double _s166 = S_T*_cam0[1]
    cdef double _s167 = S_T*_cam0[0]
    cdef double _s168 = _k247 + _s167
    cdef double _s169 = cos(_s164)
    cdef double _s170 = _s168*_s169
    cdef double _s171 = _s165*_s168
    cdef double _s172 = b6d*xEd
    cdef double _s173 = _s172*_s18
    cdef double _s174 = _s14*xEd
    cdef double _s175 = _s174*b5d
    cdef double _s176 = _s10*xEd
    cdef double _s177 = _s176*b4d
    cdef double _s178 = _s6*xEd
    cdef double _s179 = _s178*b3d
    cdef double _s180 = _s3*xEd
    cdef double _s181 = _s180*b2d
    cdef double _s182 = b1d*xEd
    cdef double _s183 = _s0*_s182
    cdef double _s184 = _s180*b1d
    cdef double _s185 = _s172*_s32
    cdef double _s186 = _s174*b4d
    cdef double _s187 = _s178*b2d
    cdef double _s188 = _s176*b3d
    cdef double _s189 = _s18*xEd
    cdef double _s190 = _s189*b5d
    cdef double _s191 = b2d*xEd
    cdef double _s192 = (xEd*xEd)
    cdef double _s193 = _s192*_s37
    cdef double _s194 = _s192*_s39
    cdef double _s195 = _s192*_s36
    cdef double _s196 = _s192*_s38
    cdef double _s197 = _s192*_s34
    cdef double _s198 = _s192*_s35
    cdef double _s199 = _s192*_s25
    cdef double _s200 = _s192*_s26
    cdef double _s201 = _s192*_s23
    cdef double _s202 = _s192*_s24
    cdef double _s203 = _s192*_s22
    cdef double _s204 = _s192*_s21
    cdef double _s205 = _k281*_s162
    cdef double _s206 = _s176*b2d
    cdef double _s207 = _s174*b3d
    cdef double _s208 = _s172*_s52
    cdef double _s209 = _s189*b4d
    cdef double _s210 = _s32*xEd
    cdef double _s211 = _s210*b5d
    cdef double _s212 = _s178*b1d
    cdef double _s213 = _s192*_s28
    cdef double _s214 = _s192*_s31
    cdef double _s215 = _s192*_s29
    cdef double _s216 = _s192*_s33
    cdef double _s217 = _s192*_s30
    cdef double _s218 = _s192*_s27
    cdef double _s219 = _s189*b3d
    cdef double _s220 = _s172*_s63
    cdef double _s221 = _s210*b4d
    cdef double _s222 = _s52*xEd
    cdef double _s223 = _s222*b5d
    cdef double _s224 = _s174*b2d
    cdef double _s225 = _s176*b1d
    cdef double _s226 = _s192*_s47
    cdef double _s227 = _s192*_s53
    cdef double _s228 = _s192*_s50
    cdef double _s229 = _s192*_s48
    cdef double _s230 = _s192*_s51
    cdef double _s231 = _s192*_s49
    cdef double _s232 = _s222*b4d
    cdef double _s233 = b5d*xEd
    cdef double _s234 = _s233*_s63
    cdef double _s235 = _s210*b3d
    cdef double _s236 = _s172*_s73
    cdef double _s237 = _s174*b1d
    cdef double _s238 = _s189*b2d
    cdef double _s239 = _s192*_s60
    cdef double _s240 = _s192*_s64
    cdef double _s241 = _s192*_s62
    cdef double _s242 = _s192*_s61
    cdef double _s243 = _s192*_s58
    cdef double _s244 = _s192*_s59
    cdef double _s245 = _s233*_s73
    cdef double _s246 = _s172*_s84
    cdef double _s247 = _s63*xEd
    cdef double _s248 = _s247*b4d
    cdef double _s249 = _s222*b3d
    cdef double _s250 = _s191*_s32
    cdef double _s251 = _s18*_s182
    cdef double _s252 = _s192*_s75
    cdef double _s253 = _s192*_s72
    cdef double _s254 = _s192*_s74
    cdef double _s255 = _s192*_s71
    cdef double _s256 = _s192*_s70
    cdef double _s257 = _s192*_s76
    cdef double _s258 = b4d*xEd
    cdef double _s259 = _s158*b2
    cdef double _s260 = _s10*_s123
    cdef double _s261 = _s121*_s3
    cdef double _s262 = _s127*_s52
    cdef double _s263 = _s125*_s18
    cdef double _s264 = _s119*_s2
    cdef double _s265 = b3d*xEd
    cdef double _s266 = _s192*b1
    cdef double _s267 = (thetad*thetad)
    cdef double _s268 = _cam0[3]*_s267
    cdef double _s269 = _s136*_s268
    cdef double _s270 = _cam0[1]*_s267
    cdef double _s271 = _s148*_s270
    cdef double _s272 = _s148*_s268
    cdef double _s273 = (_cam0[1]*_cam0[1]*_cam0[1])*_s267
    cdef double _s274 = _s143*_s273
    cdef double _s275 = _cam0[2]*_s273
    cdef double _s276 = (1.0/(pow(_cam0[0], 6.0)*_k608 + pow(_cam0[0], 5.0)*_k613 + _cam0[0]*_k612 + _cam0[0]*_k613*_s138 + pow(_cam0[1], 6.0)*_k608 + _k607 + _k609*_s134*_s138 + _k609*_s135*_s140 + _k610*_s135 + _k611*_s138 + _k614*_s134 + _k615*_s140 + _k616*_s139 + _k617*_s141 + _k618*_s135*_s139 + _k619*_s142))
    cdef double _s277 = _s267*_s276
    cdef double _s278 = pow(_cam0[1], 5.0)*_s277
    cdef double _s279 = _k620*_s278
    cdef double _s280 = _cam0[1]*_s277
    cdef double _s281 = _s145*_s280
    cdef double _s282 = (_cam0[2]*_cam0[2]*_cam0[2])*_s280
    cdef double _s283 = _s275*_s276
    cdef double _s284 = _s145*_s273*_s276
    cdef double _s285 = _cam0[0]*_k639
    cdef double _s286 = _k641*thetad
    cdef double _s287 = _k653*thetad
    cdef double _s288 = _cam0[0]*_s287
    cdef double _s289 = _cam0[1]*_s169
    cdef double _s290 = _k247*_s267
    cdef double _s291 = _s165*_s267
    cdef double _s292 = _cam0[2]*_k640
    cdef double _s293 = _s169*_s267
    _A[0] = _k2*_s0*(_k0 + _k1*_s2 + _s1)
    _A[1] = _s4
    _A[2] = _s8
    _A[3] = _s12
    _A[4] = _s16
    _A[5] = _s20
    _A[6] = _s40
    _A[7] = 0.0
    _A[8] = _s152
    _A[9] = 0.0
    _A[10] = _s4
    _A[11] = _s7*(_k36 + _s5)
    _A[12] = _s41
    _A[13] = _s42
    _A[14] = _s43
    _A[15] = _s46
    _A[16] = _s54
    _A[17] = 0.0
    _A[18] = _s153
    _A[19] = 0.0
    _A[20] = _s8
    _A[21] = _s41
    _A[22] = _s15*(_k60 + _s13)
    _A[23] = _s55
    _A[24] = _s56
    _A[25] = _s57
    _A[26] = _s65
    _A[27] = 0.0
    _A[28] = _s154
    _A[29] = 0.0
    _A[30] = _s12
    _A[31] = _s42
    _A[32] = _s55
    _A[33] = _s45*(_k84 + _s44)
    _A[34] = _s66
    _A[35] = _s69
    _A[36] = _s77
    _A[37] = 0.0
    _A[38] = _s155
    _A[39] = 0.0
    _A[40] = _s16
    _A[41] = _s43
    _A[42] = _s56
    _A[43] = _s66
    _A[44] = _s68*(_k110 + _s67)
    _A[45] = _s78
    _A[46] = _s86
    _A[47] = 0.0
    _A[48] = _s156
    _A[49] = 0.0
    _A[50] = _s20
    _A[51] = _s46
    _A[52] = _s57
    _A[53] = _s69
    _A[54] = _s78
    _A[55] = _k134*_s84*(_k132*_s2 + _k133 + _s1)
    _A[56] = _s88
    _A[57] = 0.0
    _A[58] = _s157
    _A[59] = 0.0
    _A[60] = _s40
    _A[61] = _s54
    _A[62] = _s65
    _A[63] = _s77
    _A[64] = _s86
    _A[65] = _s88
    _A[66] = _k153 + _k154*_s118 + _k155*_s120 + _k156*_s122 + _k157*_s124 + _k158*_s126 + _k159*_s128 + _k160*_s91 + _k161*_s92 + _k162*_s36*b1 + _k163*_s39*b1 + _k164*_s93 + _k165*_s37*b1 + _k166*_s94 + _k167*_s95 + _k168*_s96 + _k169*_s97 + _k170*_s98 + _k171*_s99 + _k172*_s100 + _k173*_s101 + _k174*_s102 + _k175*_s0*_s89 + _k176*_s119*_s6 + _k177*_s121*_s14 + _k178*_s123*_s32 + _k179*_s125*_s63 + _k180*_s127*_s84 + _k181*_s90 + _k182*_s22*b1 + _k183*_s129 + _k184*_s28*b2 + _k185*_s51*b3 + _k186*_s60*b4 + _k187*_s74*b5 + _k188*_s130 + _k189*_s26*b1 + _k190*_s29*b2 + _k191*_s24*b1 + _k192*_s33*b2 + _k193*_s48*b3 + _k194*_s23*b1 + _k195*_s25*b1 + _k196*_s53*b3 + _k197*_s31*b2 + _k198*_s131 + _k199*_s64*b4 + _k200*_s132 + _k201*_s133 + _k202*_s103 + _k203*_s104 + _k204*_s105 + _k205*_s106 + _k206*_s107 + _k207*_s108 + _k208*_s109 + _k209*_s110 + _k210*_s111 + _k211*_s112 + _k212*_s113 + _k213*_s114 + _k214*_s115 + _k215*_s116 + _k216*_s117 + _k86*xE
    _A[67] = 0.0
    _A[68] = _k241*_s159 + _k242*_s160 + _k243*_s161 + _k244*_s162 + _k245*_s163 + _k246*_s158
    _A[69] = 1.0
    _A[70] = 0.0
    _A[71] = 0.0
    _A[72] = 0.0
    _A[73] = 0.0
    _A[74] = 0.0
    _A[75] = 0.0
    _A[76] = 0.0
    _A[77] = J_r + _cam0[0]*_k230*_s137 + _k228*_s135*_s136 + _k229*_s146 + _k231*_s137 + _k234*_s147 + _s135*_s149 + _s138*_s144 + _s141*_s150 + _s144*_s151
    _A[78] = _s165*_s166 - _s170
    _A[79] = _s166*_s169 + _s171
    _A[80] = _s152
    _A[81] = _s153
    _A[82] = _s154
    _A[83] = _s155
    _A[84] = _s156
    _A[85] = _s157
    _A[86] = _k241*_s159 + _k242*_s160 + _k243*_s161 + _k244*_s162 + _k245*_s163 + _k246*_s158
    _A[87] = _s165*_s166 - _s170
    _A[88] = 0.0
    _A[89] = 0.0
    _A[90] = 0.0
    _A[91] = 0.0
    _A[92] = 0.0
    _A[93] = 0.0
    _A[94] = 0.0
    _A[95] = 0.0
    _A[96] = 1.0
    _A[97] = _s166*_s169 + _s171
    _A[98] = 0.0
    _A[99] = 0.0
    _b[0] = _k248*_s193 + _k249*_s194 + _k250*_s195 + _k251*_s173 + _k252*_s196 + _k253*_s175 + _k254*_s177 + _k255*_s179 + _k256*_s181 + _k256*_s197 + _k257*_s183 + _k258*_s198 + _k259*_s158 + _k260*_s160 + _k261*_s162 + _k262*_s159 + _k263*_s161 + _k264*_s163 + _k265*_s184 + _k266*_s199 + _k267*_s200 + _k268*_s185 + _k269*_s201 + _k270*_s202 + _k271*_s186 + _k272*_s187 + _k273*_s188 + _k274*_s203 + _k275*_s190 + _k276*_s204 + _k277*_s182*_s2 + _k278*_s160*_s192 + _k279*_s14*_s172 + _k280*_s176*b5d + _k282*_s178*b4d + _k283*_s180*b3d + _k284*_s0*_s191 + _k285*_s159*_s192 + _k286*_s161*_s192 + _k287*_s163*_s192 + _s192*_s205
    _b[1] = _k264*_s35 + _k280*_s177 + _k288*_s200 + _k289*_s199 + _k290*_s202 + _k291*_s185 + _k292*_s201 + _k293*_s190 + _k294*_s186 + _k295*_s188 + _k296*_s187 + _k296*_s203 + _k297*_s184 + _k298*_s204 + _k299*_s37 + _k300*_s36 + _k301*_s34 + _k302*_s39 + _k303*_s38 + _k304*_s206 + _k305*_s213 + _k306*_s214 + _k307*_s215 + _k308*_s216 + _k309*_s207 + _k310*_s208 + _k311*_s217 + _k312*_s209 + _k313*_s211 + _k314*_s212 + _k315*_s218 + _k316*_s183 + _k317*_s194 + _k318*_s195 + _k319*_s173 + _k320*_s193 + _k321*_s175 + _k322*_s179 + _k323*_s196 + _k324*_s181 + _k325*_s197
    _b[2] = _k253*_s213 + _k261*_s21 + _k303*_s22 + _k326*_s216 + _k327*_s215 + _k328*_s214 + _k329*_s208 + _k330*_s211 + _k331*_s209 + _k332*_s207 + _k333*_s206 + _k333*_s217 + _k334*_s212 + _k335*_s218 + _k336*_s24 + _k337*_s25 + _k338*_s26 + _k339*_s23 + _k340*_s226 + _k341*_s219 + _k342*_s227 + _k343*_s220 + _k344*_s228 + _k345*_s229 + _k346*_s221 + _k347*_s223 + _k348*_s224 + _k349*_s230 + _k350*_s225 + _k351*_s231 + _k352*_s184 + _k353*_s202 + _k354*_s188 + _k355*_s199 + _k356*_s200 + _k357*_s186 + _k358*_s185 + _k359*_s201 + _k360*_s190 + _k361*_s187 + _k362*_s203
    _b[3] = _k263*_s27 + _k293*_s228 + _k300*_s30 + _k336*_s28 + _k363*_s227 + _k364*_s229 + _k365*_s230 + _k366*_s220 + _k367*_s223 + _k368*_s221 + _k369*_s219 + _k370*_s224 + _k370*_s226 + _k371*_s225 + _k372*_s231 + _k373*_s31 + _k374*_s29 + _k375*_s33 + _k376*_s232 + _k377*_s239 + _k378*_s240 + _k379*_s241 + _k380*_s234 + _k381*_s235 + _k382*_s236 + _k383*_s242 + _k384*_s237 + _k385*_s243 + _k386*_s238 + _k387*_s244 + _k388*_s212 + _k389*_s213 + _k390*_s216 + _k391*_s215 + _k392*_s214 + _k393*_s207 + _k394*_s211 + _k395*_s209 + _k396*_s208 + _k397*_s206 + _k398*_s217
    _b[4] = _k260*_s49 + _k302*_s47 + _k330*_s243 + _k337*_s50 + _k374*_s51 + _k399*_s240 + _k400*_s239 + _k401*_s241 + _k402*_s236 + _k403*_s234 + _k404*_s232 + _k405*_s235 + _k406*_s238 + _k406*_s242 + _k407*_s237 + _k408*_s244 + _k409*_s48 + _k410*_s53 + _k411*_s245 + _k412*_s252 + _k413*_s253 + _k414*_s246 + _k415*_s248 + _k416*_s254 + _k417*_s255 + _k418*_s249 + _k419*_s256 + _k420*_s250 + _k421*_s257 + _k422*_s251 + _k423*_s225 + _k424*_s229 + _k425*_s223 + _k426*_s220 + _k427*_s227 + _k428*_s230 + _k429*_s228 + _k430*_s221 + _k431*_s224 + _k432*_s219 + _k433*_s226
    _b[5] = _k262*_s59 + _k299*_s61 + _k338*_s58 + _k367*_s255 + _k375*_s62 + _k410*_s60 + _k434*_s254 + _k435*_s253 + _k436*_s252 + _k437*_s246 + _k438*_s245 + _k439*_s248 + _k440*_s249 + _k441*_s250 + _k441*_s256 + _k442*_s251 + _k443*_s257 + _k444*_s64 + _k445*_s172*_s87 + _k446*_s192*_s85 + _k447*_s192*_s83 + _k448*_s233*_s84 + _k449*_s247*b3d + _k450*_s192*_s82 + _k451*_s192*_s79 + _k452*_s258*_s73 + _k453*_s182*_s32 + _k454*_s191*_s52 + _k455*_s192*_s80 + _k456*_s192*_s81 + _k457*_s237 + _k458*_s239 + _k459*_s232 + _k460*_s240 + _k461*_s234 + _k462*_s236 + _k463*_s241 + _k464*_s243 + _k465*_s238 + _k466*_s235 + _k467*_s242
    _b[6] = _k249*_s191*_s24 + _k249*_s258*_s47 + _k250*_s182*_s36 + _k250*_s258*_s49 + _k257*_s192*_s90 + _k266*_s191*_s31 + _k266*_s258*_s61 + _k270*_s182*_s24 + _k270*_s258*_s59 + _k278*_s191*_s36 + _k278*_s258*_s30 + _k281*_s21*_s265 + _k288*_s172*_s70 + _k288*_s191*_s26 + _k308*_s172*_s80 + _k308*_s191*_s33 + _k317*_s191*_s39 + _k317*_s233*_s47 + _k468*_s192 + _k469*_s133*_s192 + _k470*_s130*_s192 + _k471*_s132*_s192 + _k472*_s131*_s192 + _k473*_s129*_s192 + _k473*_s191*_s22 + _k474*_s89 + _k475*_s113*_s192 + _k476*_s116*_s192 + _k477*_s115*_s192 + _k478*_s114*_s192 + _k479*_s117*_s192 + _k480*_s111*_s192 + _k481*_s112*_s192 + _k482*_s110*_s192 + _k483*_s107*_s192 + _k484*_s172*_s74 + _k485*_s109*_s192 + _k486*_s172*_s72 + _k486*_s233*_s64 + _k487*_s106*_s192 + _k488*_s233*_s60 + _k489*_s172*_s75 + _k489*_s258*_s53 + _k490*_s108*_s192 + _k491*_s233*_s62 + _k491*_s258*_s48 + _k492*_s172*_s71 + _k492*_s265*_s33 + _k493*_s260 + _k494*_s105*_s192 + _k495*_s258*_s51 + _k496*_s233*_s58 + _k496*_s265*_s29 + _k497*_s258*_s50 + _k497*_s265*_s31 + _k498*_s191*_s25 + _k498*_s233*_s61 + _k499*_s104*_s192 + _k500*_s265*_s28 + _k501*_s172*_s76 + _k501*_s182*_s37 + _k502*_s182*_s39 + _k502*_s233*_s59 + _k503*_s191*_s23 + _k503*_s265*_s30 + _k504*_s261 + _k505*_s103*_s192 + _k506*_s182*_s38 + _k506*_s265*_s27 + _k507*_s182*_s34 + _k507*_s191*_s21 + _k508*_s182*_s35 + _k509*_s262 + _k510*_s263 + _k511*_s264 + _k512*_s33*b5 + _k513*_s26*b4 + _k514*_s25*b4 + _k515*_s37*b3 + _k516*_s28*b5 + _k517*_s47*b6 + _k518*_s23*b4 + _k519*_s30*b5 + _k520*_s22*b4 + _k521*_s49*b6 + _k522*_s34*b3 + _k523*_s126*_s192 + _k524*_s27*b5 + _k525*_s21*b4 + _k526*_s122*_s192 + _k527*_s35*b3 + _k528*_s259 + _k529*_s118*_s192 + _k530*_s128*_s192 + _k531*_s124*_s192 + _k532*_s120*_s192 + _k533*_s192*_s89 + _k534*_s192*_s260 + _k535*_s102*_s192 + _k536*_s101*_s192 + _k537*_s100*_s192 + _k538*_s192*_s99 + _k539*_s192*_s98 + _k540*_s192*_s97 + _k541*_s192*_s96 + _k542*_s192*_s95 + _k543*_s192*_s261 + _k544*_s192*_s94 + _k545*_s266*_s37 + _k546*_s266*_s39 + _k547*_s192*_s93 + _k548*_s266*_s36 + _k549*_s192*_s92 + _k550*_s172*_s79 + _k550*_s233*_s74 + _k551*_s192*_s91 + _k552*_s233*_s75 + _k552*_s258*_s60 + _k553*_s258*_s58 + _k553*_s265*_s51 + _k554*_s191*_s28 + _k554*_s265*_s47 + _k555*_s182*_s22 + _k555*_s191*_s27 + _k556*_s192*_s262 + _k557*_s192*_s263 + _k558*_s172*_s85 + _k559*_s233*_s72 + _k560*_s172*_s83 + _k560*_s258*_s64 + _k561*_s258*_s62 + _k562*_s265*_s50 + _k563*_s172*_s82 + _k563*_s265*_s53 + _k564*_s182*_s25 + _k564*_s233*_s76 + _k565*_s191*_s30 + _k566*_s233*_s71 + _k566*_s265*_s48 + _k567*_s182*_s23 + _k567*_s265*_s49 + _k568*_s191*_s29 + _k568*_s233*_s70 + _k569*_s192*_s264 + _k570*_s182*_s21 + _k571*_s172*_s81 + _k571*_s182*_s26 + _k572*_s216*b5 + _k573*_s200*b4 + _k574*_s199*b4 + _k575*_s193*b3 + _k576*_s213*b5 + _k577*_s226*b6 + _k578*_s172*_s60 + _k578*_s233*_s53 + _k579*_s201*b4 + _k580*_s233*_s48 + _k581*_s217*b5 + _k582*_s203*b4 + _k583*_s231*b6 + _k584*_s24*_s265 + _k584*_s258*_s28 + _k585*_s197*b3 + _k586*_s172*_s61 + _k586*_s191*_s37 + _k587*_s218*b5 + _k588*_s204*b4 + _k589*_s191*_s38 + _k589*_s22*_s265 + _k590*_s159*_s182 + _k590*_s172*_s59 + _k591*_s191*_s34 + _k591*_s198*b3 + _k592*_s160*_s182 + _k592*_s233*_s49 + _k593*_s161*_s182 + _k593*_s258*_s27 + _k594*_s163*_s182 + _k594*_s191*_s35 + _k594*_s192*_s259 + _k595*_s158*_s182 + _k596*_s172*_s64 + _k597*_s258*_s31 + _k598*_s233*_s50 + _k598*_s25*_s265 + _k599*_s172*_s62 + _k599*_s258*_s33 + _k600*_s233*_s51 + _k600*_s258*_s29 + _k601*_s23*_s265 + _k602*_s172*_s58 + _k602*_s26*_s265 + _s182*_s205
    _b[7] = _cam0[0]*_k603*_s269 + _cam0[0]*_k606*_s274 + _cam0[0]*_k626*_s284 + _cam0[0]*_k632*_s283 + _cam0[0]*_k633*_s271 + _cam0[0]*_k634*_s282 + _cam0[0]*_k635*_s281 + _cam0[0]*_s149*_s268 + _cam0[0]*_s279 + _cam0[2]*_s279 + _k234*_s274 + _k604*_s269 + _k605*_s137*_s270 + _k620*_s134*_s282 + _k620*_s139*_s281 + _k621*_s278 + _k622*_s135*_s143*_s268 + _k623*_s134*_s272 + _k623*_s147*_s270 + _k624*_s146*_s270 + _k625*_s272 + _k626*_s134*_s283 + _k627*_s283 + _k628*_s284 + _k629*_s271 + _k630*_s281 + _k631*_s282 + _k636*_s151*_s280 + _s134*_s150*_s270 + _s141*_s144*_s268 + _s144*_s275
    _b[8] = _k637*_s165 + _k638*_s266 + _k642*_s267*_s289 + _k643*_s182*xE + _k644*_s191*_s2 + _k644*_s192*b2*xE + _k645*_s0*_s265 + _k646*_s180*b4d + _k647*_s192*_s2*b3 + _k648*_s178*b5d + _k649*_s10*_s172 + _k650*_s0*_s192*b4 + _k651*_s192*_s3*b5 + _k652*_s192*_s6*b6 + _s165*_s285 + _s165*_s286 + _s165*_s288 + _s165*_s290 + _s167*_s291 + _s287*_s289 + _s291*_s292
    _ph[0] = _s152*b1 + _s153*b2 + _s154*b3 + _s155*b4 + _s156*b5 + _s157*b6 + _s171
    _phd[0] = Omega*_s170 + _A[80] * b1d + _A[81] * b2d + _A[82] * b3d + _A[83] * b4d + _A[84] * b5d + _A[85] * b6d + _A[86] * xEd + _A[87] * thetad
    _b[9] = _cam0[1]*_k654*_s291 + _cam0[1]*_k655*_s165*thetad + _k637*_s169 + _s167*_s293 + _s169*_s285 + _s169*_s286 + _s169*_s288 + _s169*_s290 + _s292*_s293
    _ph[1] = _k656 + _s170 + xE
    _phd[1] = _k657*_s171 + _A[90] * b1d + _A[91] * b2d + _A[92] * b3d + _A[93] * b4d + _A[94] * b5d + _A[95] * b6d + _A[96] * xEd + _A[97] * thetad


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
    cdef double _k484 = ctx.k[484]
    cdef double _k485 = ctx.k[485]
    cdef double _k486 = ctx.k[486]
    cdef double _k487 = ctx.k[487]
    cdef double _k488 = ctx.k[488]
    cdef double _k489 = ctx.k[489]
    cdef double _k490 = ctx.k[490]
    cdef double _k491 = ctx.k[491]
    cdef double _k492 = ctx.k[492]
    cdef double _k493 = ctx.k[493]
    cdef double _k494 = ctx.k[494]
    cdef double _k495 = ctx.k[495]
    cdef double _k496 = ctx.k[496]
    cdef double _k497 = ctx.k[497]
    cdef double _k498 = ctx.k[498]
    cdef double _k499 = ctx.k[499]
    cdef double _k500 = ctx.k[500]
    cdef double _k501 = ctx.k[501]
    cdef double _k502 = ctx.k[502]
    cdef double _k503 = ctx.k[503]
    cdef double _k504 = ctx.k[504]
    cdef double _k505 = ctx.k[505]
    cdef double _k506 = ctx.k[506]
    cdef double _k507 = ctx.k[507]
    cdef double _k508 = ctx.k[508]
    cdef double _k509 = ctx.k[509]
    cdef double _k510 = ctx.k[510]
    cdef double _k511 = ctx.k[511]
    cdef double _k512 = ctx.k[512]
    cdef double _k513 = ctx.k[513]
    cdef double _k514 = ctx.k[514]
    cdef double _k515 = ctx.k[515]
    cdef double _k516 = ctx.k[516]
    cdef double _k517 = ctx.k[517]
    cdef double _k518 = ctx.k[518]
    cdef double _k519 = ctx.k[519]
    cdef double _k520 = ctx.k[520]
    cdef double _k521 = ctx.k[521]
    cdef double _k522 = ctx.k[522]
    cdef double _k523 = ctx.k[523]
    cdef double _k524 = ctx.k[524]
    cdef double _k525 = ctx.k[525]
    cdef double _k526 = ctx.k[526]
    cdef double _k527 = ctx.k[527]
    cdef double _k528 = ctx.k[528]
    cdef double _k529 = ctx.k[529]
    cdef double _k530 = ctx.k[530]
    cdef double _k531 = ctx.k[531]
    cdef double _k532 = ctx.k[532]
    cdef double _k533 = ctx.k[533]
    cdef double _k534 = ctx.k[534]
    cdef double _k535 = ctx.k[535]
    cdef double _k536 = ctx.k[536]
    cdef double _k537 = ctx.k[537]
    cdef double _k538 = ctx.k[538]
    cdef double _k539 = ctx.k[539]
    cdef double _k540 = ctx.k[540]
    cdef double _k541 = ctx.k[541]
    cdef double _k542 = ctx.k[542]
    cdef double _k543 = ctx.k[543]
    cdef double _k544 = ctx.k[544]
    cdef double _k545 = ctx.k[545]
    cdef double _k546 = ctx.k[546]
    cdef double _k547 = ctx.k[547]
    cdef double _k548 = ctx.k[548]
    cdef double _k549 = ctx.k[549]
    cdef double _k550 = ctx.k[550]
    cdef double _k551 = ctx.k[551]
    cdef double _k552 = ctx.k[552]
    cdef double _k553 = ctx.k[553]
    cdef double _k554 = ctx.k[554]
    cdef double _k555 = ctx.k[555]
    cdef double _k556 = ctx.k[556]
    cdef double _k557 = ctx.k[557]
    cdef double _k558 = ctx.k[558]
    cdef double _k559 = ctx.k[559]
    cdef double _k560 = ctx.k[560]
    cdef double _k561 = ctx.k[561]
    cdef double _k562 = ctx.k[562]
    cdef double _k563 = ctx.k[563]
    cdef double _k564 = ctx.k[564]
    cdef double _k565 = ctx.k[565]
    cdef double _k566 = ctx.k[566]
    cdef double _k567 = ctx.k[567]
    cdef double _k568 = ctx.k[568]
    cdef double _k569 = ctx.k[569]
    cdef double _k570 = ctx.k[570]
    cdef double _k571 = ctx.k[571]
    cdef double _k572 = ctx.k[572]
    cdef double _k573 = ctx.k[573]
    cdef double _k574 = ctx.k[574]
    cdef double _k575 = ctx.k[575]
    cdef double _k576 = ctx.k[576]
    cdef double _k577 = ctx.k[577]
    cdef double _k578 = ctx.k[578]
    cdef double _k579 = ctx.k[579]
    cdef double _k580 = ctx.k[580]
    cdef double _k581 = ctx.k[581]
    cdef double _k582 = ctx.k[582]
    cdef double _k583 = ctx.k[583]
    cdef double _k584 = ctx.k[584]
    cdef double _k585 = ctx.k[585]
    cdef double _k586 = ctx.k[586]
    cdef double _k587 = ctx.k[587]
    cdef double _k588 = ctx.k[588]
    cdef double _k589 = ctx.k[589]
    cdef double _k590 = ctx.k[590]
    cdef double _k591 = ctx.k[591]
    cdef double _k592 = ctx.k[592]
    cdef double _k593 = ctx.k[593]
    cdef double _k594 = ctx.k[594]
    cdef double _k595 = ctx.k[595]
    cdef double _k596 = ctx.k[596]
    cdef double _k597 = ctx.k[597]
    cdef double _k598 = ctx.k[598]
    cdef double _k599 = ctx.k[599]
    cdef double _k600 = ctx.k[600]
    cdef double _k601 = ctx.k[601]
    cdef double _k602 = ctx.k[602]
    cdef double _k603 = ctx.k[603]
    cdef double _k604 = ctx.k[604]
    cdef double _k605 = ctx.k[605]
    cdef double _k606 = ctx.k[606]
    cdef double _k607 = ctx.k[607]
    cdef double _k608 = ctx.k[608]
    cdef double _k609 = ctx.k[609]
    cdef double _k610 = ctx.k[610]
    cdef double _k611 = ctx.k[611]
    cdef double _k612 = ctx.k[612]
    cdef double _k613 = ctx.k[613]
    cdef double _k614 = ctx.k[614]
    cdef double _k615 = ctx.k[615]
    cdef double _k616 = ctx.k[616]
    cdef double _k617 = ctx.k[617]
    cdef double _k618 = ctx.k[618]
    cdef double _k619 = ctx.k[619]
    cdef double _k620 = ctx.k[620]
    cdef double _k621 = ctx.k[621]
    cdef double _k622 = ctx.k[622]
    cdef double _k623 = ctx.k[623]
    cdef double _k624 = ctx.k[624]
    cdef double _k625 = ctx.k[625]
    cdef double _k626 = ctx.k[626]
    cdef double _k627 = ctx.k[627]
    cdef double _k628 = ctx.k[628]
    cdef double _k629 = ctx.k[629]
    cdef double _k630 = ctx.k[630]
    cdef double _k631 = ctx.k[631]
    cdef double _k632 = ctx.k[632]
    cdef double _k633 = ctx.k[633]
    cdef double _k634 = ctx.k[634]
    cdef double _k635 = ctx.k[635]
    cdef double _k636 = ctx.k[636]
    cdef double _k637 = ctx.k[637]
    cdef double _k638 = ctx.k[638]
    cdef double _k639 = ctx.k[639]
    cdef double _k640 = ctx.k[640]
    cdef double _k641 = ctx.k[641]
    cdef double _k642 = ctx.k[642]
    cdef double _k643 = ctx.k[643]
    cdef double _k644 = ctx.k[644]
    cdef double _k645 = ctx.k[645]
    cdef double _k646 = ctx.k[646]
    cdef double _k647 = ctx.k[647]
    cdef double _k648 = ctx.k[648]
    cdef double _k649 = ctx.k[649]
    cdef double _k650 = ctx.k[650]
    cdef double _k651 = ctx.k[651]
    cdef double _k652 = ctx.k[652]
    cdef double _k653 = ctx.k[653]
    cdef double _k654 = ctx.k[654]
    cdef double _k655 = ctx.k[655]
    cdef double _k656 = ctx.k[656]
    cdef double _k657 = ctx.k[657]
    cdef double _k658 = ctx.k[658]
    cdef double _k659 = ctx.k[659]
    cdef double b1 = _y[0]
    cdef double b2 = _y[1]
    cdef double b3 = _y[2]
    cdef double b4 = _y[3]
    cdef double b5 = _y[4]
    cdef double b6 = _y[5]
    cdef double xE = _y[6]
    cdef double theta = _y[7]
    cdef double b1d = _y[8]
    cdef double b2d = _y[9]
    cdef double b3d = _y[10]
    cdef double b4d = _y[11]
    cdef double b5d = _y[12]
    cdef double b6d = _y[13]
    cdef double xEd = _y[14]
    cdef double thetad = _y[15]
    cdef double _cam0[4]
    _profile(ctx, theta, beta_r, _cam0)

    cdef double _p0 = (xE*xE)
    cdef double _p1 = _k235*_p0
    cdef double _p2 = (xE*xE*xE)
    cdef double _p3 = _k236*_p2
    cdef double _p4 = (xE*xE*xE*xE)
    cdef double _p5 = _k237*_p4
    cdef double _p6 = pow(xE, 5.0)
    cdef double _p7 = _k238*_p6
    cdef double _p8 = _k239*pow(xE, 6.0)
    cdef double _p9 = _k240*pow(xE, 7.0)
    cdef double _p10 = S_T*_cam0[0] + _k247
    cdef double _p11 = Omega*t - theta
    cdef double _p12 = sin(_p11)
    cdef double _p13 = _p10*_p12
    cdef double _p14 = cos(_p11)
    cdef double _p15 = _p10*_p14
    cdef double _p16 = S_T*_cam0[1]
    _g[0] = _p1*b1 + _p13 + _p3*b2 + _p5*b3 + _p7*b4 + _p8*b5 + _p9*b6
    _g[1] = _k656 + _p15 + xE
    _J[0] = _p1
    _J[1] = _p3
    _J[2] = _p5
    _J[3] = _p7
    _J[4] = _p8
    _J[5] = _p9
    _J[6] = xE*(_k241*_p6*b6 + _k242*_p4*b5 + _k243*_p2*b4 + _k244*_p0*b3 + _k245*b2*xE + _k246*b1)
    _J[7] = _p12*_p16 - _p15
    _J[8] = 0.0
    _J[9] = 0.0
    _J[10] = 0.0
    _J[11] = 0.0
    _J[12] = 0.0
    _J[13] = 0.0
    _J[14] = 1.0
    _J[15] = _p13 + _p14*_p16
    _gt[0] = Omega*_p15
    _gt[1] = _k657*_p13


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
    cdef double _k484 = ctx.k[484]
    cdef double _k485 = ctx.k[485]
    cdef double _k486 = ctx.k[486]
    cdef double _k487 = ctx.k[487]
    cdef double _k488 = ctx.k[488]
    cdef double _k489 = ctx.k[489]
    cdef double _k490 = ctx.k[490]
    cdef double _k491 = ctx.k[491]
    cdef double _k492 = ctx.k[492]
    cdef double _k493 = ctx.k[493]
    cdef double _k494 = ctx.k[494]
    cdef double _k495 = ctx.k[495]
    cdef double _k496 = ctx.k[496]
    cdef double _k497 = ctx.k[497]
    cdef double _k498 = ctx.k[498]
    cdef double _k499 = ctx.k[499]
    cdef double _k500 = ctx.k[500]
    cdef double _k501 = ctx.k[501]
    cdef double _k502 = ctx.k[502]
    cdef double _k503 = ctx.k[503]
    cdef double _k504 = ctx.k[504]
    cdef double _k505 = ctx.k[505]
    cdef double _k506 = ctx.k[506]
    cdef double _k507 = ctx.k[507]
    cdef double _k508 = ctx.k[508]
    cdef double _k509 = ctx.k[509]
    cdef double _k510 = ctx.k[510]
    cdef double _k511 = ctx.k[511]
    cdef double _k512 = ctx.k[512]
    cdef double _k513 = ctx.k[513]
    cdef double _k514 = ctx.k[514]
    cdef double _k515 = ctx.k[515]
    cdef double _k516 = ctx.k[516]
    cdef double _k517 = ctx.k[517]
    cdef double _k518 = ctx.k[518]
    cdef double _k519 = ctx.k[519]
    cdef double _k520 = ctx.k[520]
    cdef double _k521 = ctx.k[521]
    cdef double _k522 = ctx.k[522]
    cdef double _k523 = ctx.k[523]
    cdef double _k524 = ctx.k[524]
    cdef double _k525 = ctx.k[525]
    cdef double _k526 = ctx.k[526]
    cdef double _k527 = ctx.k[527]
    cdef double _k528 = ctx.k[528]
    cdef double _k529 = ctx.k[529]
    cdef double _k530 = ctx.k[530]
    cdef double _k531 = ctx.k[531]
    cdef double _k532 = ctx.k[532]
    cdef double _k533 = ctx.k[533]
    cdef double _k534 = ctx.k[534]
    cdef double _k535 = ctx.k[535]
    cdef double _k536 = ctx.k[536]
    cdef double _k537 = ctx.k[537]
    cdef double _k538 = ctx.k[538]
    cdef double _k539 = ctx.k[539]
    cdef double _k540 = ctx.k[540]
    cdef double _k541 = ctx.k[541]
    cdef double _k542 = ctx.k[542]
    cdef double _k543 = ctx.k[543]
    cdef double _k544 = ctx.k[544]
    cdef double _k545 = ctx.k[545]
    cdef double _k546 = ctx.k[546]
    cdef double _k547 = ctx.k[547]
    cdef double _k548 = ctx.k[548]
    cdef double _k549 = ctx.k[549]
    cdef double _k550 = ctx.k[550]
    cdef double _k551 = ctx.k[551]
    cdef double _k552 = ctx.k[552]
    cdef double _k553 = ctx.k[553]
    cdef double _k554 = ctx.k[554]
    cdef double _k555 = ctx.k[555]
    cdef double _k556 = ctx.k[556]
    cdef double _k557 = ctx.k[557]
    cdef double _k558 = ctx.k[558]
    cdef double _k559 = ctx.k[559]
    cdef double _k560 = ctx.k[560]
    cdef double _k561 = ctx.k[561]
    cdef double _k562 = ctx.k[562]
    cdef double _k563 = ctx.k[563]
    cdef double _k564 = ctx.k[564]
    cdef double _k565 = ctx.k[565]
    cdef double _k566 = ctx.k[566]
    cdef double _k567 = ctx.k[567]
    cdef double _k568 = ctx.k[568]
    cdef double _k569 = ctx.k[569]
    cdef double _k570 = ctx.k[570]
    cdef double _k571 = ctx.k[571]
    cdef double _k572 = ctx.k[572]
    cdef double _k573 = ctx.k[573]
    cdef double _k574 = ctx.k[574]
    cdef double _k575 = ctx.k[575]
    cdef double _k576 = ctx.k[576]
    cdef double _k577 = ctx.k[577]
    cdef double _k578 = ctx.k[578]
    cdef double _k579 = ctx.k[579]
    cdef double _k580 = ctx.k[580]
    cdef double _k581 = ctx.k[581]
    cdef double _k582 = ctx.k[582]
    cdef double _k583 = ctx.k[583]
    cdef double _k584 = ctx.k[584]
    cdef double _k585 = ctx.k[585]
    cdef double _k586 = ctx.k[586]
    cdef double _k587 = ctx.k[587]
    cdef double _k588 = ctx.k[588]
    cdef double _k589 = ctx.k[589]
    cdef double _k590 = ctx.k[590]
    cdef double _k591 = ctx.k[591]
    cdef double _k592 = ctx.k[592]
    cdef double _k593 = ctx.k[593]
    cdef double _k594 = ctx.k[594]
    cdef double _k595 = ctx.k[595]
    cdef double _k596 = ctx.k[596]
    cdef double _k597 = ctx.k[597]
    cdef double _k598 = ctx.k[598]
    cdef double _k599 = ctx.k[599]
    cdef double _k600 = ctx.k[600]
    cdef double _k601 = ctx.k[601]
    cdef double _k602 = ctx.k[602]
    cdef double _k603 = ctx.k[603]
    cdef double _k604 = ctx.k[604]
    cdef double _k605 = ctx.k[605]
    cdef double _k606 = ctx.k[606]
    cdef double _k607 = ctx.k[607]
    cdef double _k608 = ctx.k[608]
    cdef double _k609 = ctx.k[609]
    cdef double _k610 = ctx.k[610]
    cdef double _k611 = ctx.k[611]
    cdef double _k612 = ctx.k[612]
    cdef double _k613 = ctx.k[613]
    cdef double _k614 = ctx.k[614]
    cdef double _k615 = ctx.k[615]
    cdef double _k616 = ctx.k[616]
    cdef double _k617 = ctx.k[617]
    cdef double _k618 = ctx.k[618]
    cdef double _k619 = ctx.k[619]
    cdef double _k620 = ctx.k[620]
    cdef double _k621 = ctx.k[621]
    cdef double _k622 = ctx.k[622]
    cdef double _k623 = ctx.k[623]
    cdef double _k624 = ctx.k[624]
    cdef double _k625 = ctx.k[625]
    cdef double _k626 = ctx.k[626]
    cdef double _k627 = ctx.k[627]
    cdef double _k628 = ctx.k[628]
    cdef double _k629 = ctx.k[629]
    cdef double _k630 = ctx.k[630]
    cdef double _k631 = ctx.k[631]
    cdef double _k632 = ctx.k[632]
    cdef double _k633 = ctx.k[633]
    cdef double _k634 = ctx.k[634]
    cdef double _k635 = ctx.k[635]
    cdef double _k636 = ctx.k[636]
    cdef double _k637 = ctx.k[637]
    cdef double _k638 = ctx.k[638]
    cdef double _k639 = ctx.k[639]
    cdef double _k640 = ctx.k[640]
    cdef double _k641 = ctx.k[641]
    cdef double _k642 = ctx.k[642]
    cdef double _k643 = ctx.k[643]
    cdef double _k644 = ctx.k[644]
    cdef double _k645 = ctx.k[645]
    cdef double _k646 = ctx.k[646]
    cdef double _k647 = ctx.k[647]
    cdef double _k648 = ctx.k[648]
    cdef double _k649 = ctx.k[649]
    cdef double _k650 = ctx.k[650]
    cdef double _k651 = ctx.k[651]
    cdef double _k652 = ctx.k[652]
    cdef double _k653 = ctx.k[653]
    cdef double _k654 = ctx.k[654]
    cdef double _k655 = ctx.k[655]
    cdef double _k656 = ctx.k[656]
    cdef double _k657 = ctx.k[657]
    cdef double _k658 = ctx.k[658]
    cdef double _k659 = ctx.k[659]
    cdef double b1 = _yc[0]
    cdef double b2 = _yc[1]
    cdef double b3 = _yc[2]
    cdef double b4 = _yc[3]
    cdef double b5 = _yc[4]
    cdef double b6 = _yc[5]
    cdef double xE = _yc[6]
    cdef double theta = _yc[7]
    cdef double b1d = _yc[8]
    cdef double b2d = _yc[9]
    cdef double b3d = _yc[10]
    cdef double b4d = _yc[11]
    cdef double b5d = _yc[12]
    cdef double b6d = _yc[13]
    cdef double xEd = _yc[14]
    cdef double thetad = _yc[15]
    cdef double _cam0[4]
    _profile(ctx, theta, beta_r, _cam0)

    cdef double _o0 = (xE*xE)
    cdef double _o1 = pow(xE, 5.0)
    cdef double _o2 = (xE*xE*xE)
    cdef double _o3 = (xE*xE*xE*xE)
    cdef double _o4 = S_T*_cam0[0]
    cdef double _o5 = _k247 + _o4
    cdef double _o6 = Omega*t - theta
    _out[0] = _o0*(_k11*_o1*b6 + _k2*_o0*b3 + _k5*_o2*b4 + _k658*b1 + _k659*b2*xE + _k8*_o3*b5)  # vE
    _out[1] = _k235*_o0*b1 + _k236*_o2*b2 + _k237*_o3*b3 + _k238*_o1*b4 + _k239*b5*pow(xE, 6.0) + _k240*b6*pow(xE, 7.0) + _o5*sin(_o6)  # Phi1
    _out[2] = _k656 + _o5*cos(_o6) + xE  # Phi2
    _out[3] = _o4  # S
    _out[4] = atan(S_T*_cam0[1]/_o5)  # pressure_angle
    _out[5] = _acc[6]  # xEdd
    _out[6] = _acc[8]  # lambda1
    _out[7] = _acc[9]  # lambda2


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
_SCALE[5] = 1e-05
_SCALE[6] = 0.05
_SCALE[7] = 1.0
_SCALE[8] = 1e-05
_SCALE[9] = 1e-05
_SCALE[10] = 1e-05
_SCALE[11] = 1e-05
_SCALE[12] = 1e-05
_SCALE[13] = 1e-05
_SCALE[14] = 0.05
_SCALE[15] = 1.0


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
    cdef double _k484 = ctx.k[484]
    cdef double _k485 = ctx.k[485]
    cdef double _k486 = ctx.k[486]
    cdef double _k487 = ctx.k[487]
    cdef double _k488 = ctx.k[488]
    cdef double _k489 = ctx.k[489]
    cdef double _k490 = ctx.k[490]
    cdef double _k491 = ctx.k[491]
    cdef double _k492 = ctx.k[492]
    cdef double _k493 = ctx.k[493]
    cdef double _k494 = ctx.k[494]
    cdef double _k495 = ctx.k[495]
    cdef double _k496 = ctx.k[496]
    cdef double _k497 = ctx.k[497]
    cdef double _k498 = ctx.k[498]
    cdef double _k499 = ctx.k[499]
    cdef double _k500 = ctx.k[500]
    cdef double _k501 = ctx.k[501]
    cdef double _k502 = ctx.k[502]
    cdef double _k503 = ctx.k[503]
    cdef double _k504 = ctx.k[504]
    cdef double _k505 = ctx.k[505]
    cdef double _k506 = ctx.k[506]
    cdef double _k507 = ctx.k[507]
    cdef double _k508 = ctx.k[508]
    cdef double _k509 = ctx.k[509]
    cdef double _k510 = ctx.k[510]
    cdef double _k511 = ctx.k[511]
    cdef double _k512 = ctx.k[512]
    cdef double _k513 = ctx.k[513]
    cdef double _k514 = ctx.k[514]
    cdef double _k515 = ctx.k[515]
    cdef double _k516 = ctx.k[516]
    cdef double _k517 = ctx.k[517]
    cdef double _k518 = ctx.k[518]
    cdef double _k519 = ctx.k[519]
    cdef double _k520 = ctx.k[520]
    cdef double _k521 = ctx.k[521]
    cdef double _k522 = ctx.k[522]
    cdef double _k523 = ctx.k[523]
    cdef double _k524 = ctx.k[524]
    cdef double _k525 = ctx.k[525]
    cdef double _k526 = ctx.k[526]
    cdef double _k527 = ctx.k[527]
    cdef double _k528 = ctx.k[528]
    cdef double _k529 = ctx.k[529]
    cdef double _k530 = ctx.k[530]
    cdef double _k531 = ctx.k[531]
    cdef double _k532 = ctx.k[532]
    cdef double _k533 = ctx.k[533]
    cdef double _k534 = ctx.k[534]
    cdef double _k535 = ctx.k[535]
    cdef double _k536 = ctx.k[536]
    cdef double _k537 = ctx.k[537]
    cdef double _k538 = ctx.k[538]
    cdef double _k539 = ctx.k[539]
    cdef double _k540 = ctx.k[540]
    cdef double _k541 = ctx.k[541]
    cdef double _k542 = ctx.k[542]
    cdef double _k543 = ctx.k[543]
    cdef double _k544 = ctx.k[544]
    cdef double _k545 = ctx.k[545]
    cdef double _k546 = ctx.k[546]
    cdef double _k547 = ctx.k[547]
    cdef double _k548 = ctx.k[548]
    cdef double _k549 = ctx.k[549]
    cdef double _k550 = ctx.k[550]
    cdef double _k551 = ctx.k[551]
    cdef double _k552 = ctx.k[552]
    cdef double _k553 = ctx.k[553]
    cdef double _k554 = ctx.k[554]
    cdef double _k555 = ctx.k[555]
    cdef double _k556 = ctx.k[556]
    cdef double _k557 = ctx.k[557]
    cdef double _k558 = ctx.k[558]
    cdef double _k559 = ctx.k[559]
    cdef double _k560 = ctx.k[560]
    cdef double _k561 = ctx.k[561]
    cdef double _k562 = ctx.k[562]
    cdef double _k563 = ctx.k[563]
    cdef double _k564 = ctx.k[564]
    cdef double _k565 = ctx.k[565]
    cdef double _k566 = ctx.k[566]
    cdef double _k567 = ctx.k[567]
    cdef double _k568 = ctx.k[568]
    cdef double _k569 = ctx.k[569]
    cdef double _k570 = ctx.k[570]
    cdef double _k571 = ctx.k[571]
    cdef double _k572 = ctx.k[572]
    cdef double _k573 = ctx.k[573]
    cdef double _k574 = ctx.k[574]
    cdef double _k575 = ctx.k[575]
    cdef double _k576 = ctx.k[576]
    cdef double _k577 = ctx.k[577]
    cdef double _k578 = ctx.k[578]
    cdef double _k579 = ctx.k[579]
    cdef double _k580 = ctx.k[580]
    cdef double _k581 = ctx.k[581]
    cdef double _k582 = ctx.k[582]
    cdef double _k583 = ctx.k[583]
    cdef double _k584 = ctx.k[584]
    cdef double _k585 = ctx.k[585]
    cdef double _k586 = ctx.k[586]
    cdef double _k587 = ctx.k[587]
    cdef double _k588 = ctx.k[588]
    cdef double _k589 = ctx.k[589]
    cdef double _k590 = ctx.k[590]
    cdef double _k591 = ctx.k[591]
    cdef double _k592 = ctx.k[592]
    cdef double _k593 = ctx.k[593]
    cdef double _k594 = ctx.k[594]
    cdef double _k595 = ctx.k[595]
    cdef double _k596 = ctx.k[596]
    cdef double _k597 = ctx.k[597]
    cdef double _k598 = ctx.k[598]
    cdef double _k599 = ctx.k[599]
    cdef double _k600 = ctx.k[600]
    cdef double _k601 = ctx.k[601]
    cdef double _k602 = ctx.k[602]
    cdef double _k603 = ctx.k[603]
    cdef double _k604 = ctx.k[604]
    cdef double _k605 = ctx.k[605]
    cdef double _k606 = ctx.k[606]
    cdef double _k607 = ctx.k[607]
    cdef double _k608 = ctx.k[608]
    cdef double _k609 = ctx.k[609]
    cdef double _k610 = ctx.k[610]
    cdef double _k611 = ctx.k[611]
    cdef double _k612 = ctx.k[612]
    cdef double _k613 = ctx.k[613]
    cdef double _k614 = ctx.k[614]
    cdef double _k615 = ctx.k[615]
    cdef double _k616 = ctx.k[616]
    cdef double _k617 = ctx.k[617]
    cdef double _k618 = ctx.k[618]
    cdef double _k619 = ctx.k[619]
    cdef double _k620 = ctx.k[620]
    cdef double _k621 = ctx.k[621]
    cdef double _k622 = ctx.k[622]
    cdef double _k623 = ctx.k[623]
    cdef double _k624 = ctx.k[624]
    cdef double _k625 = ctx.k[625]
    cdef double _k626 = ctx.k[626]
    cdef double _k627 = ctx.k[627]
    cdef double _k628 = ctx.k[628]
    cdef double _k629 = ctx.k[629]
    cdef double _k630 = ctx.k[630]
    cdef double _k631 = ctx.k[631]
    cdef double _k632 = ctx.k[632]
    cdef double _k633 = ctx.k[633]
    cdef double _k634 = ctx.k[634]
    cdef double _k635 = ctx.k[635]
    cdef double _k636 = ctx.k[636]
    cdef double _k637 = ctx.k[637]
    cdef double _k638 = ctx.k[638]
    cdef double _k639 = ctx.k[639]
    cdef double _k640 = ctx.k[640]
    cdef double _k641 = ctx.k[641]
    cdef double _k642 = ctx.k[642]
    cdef double _k643 = ctx.k[643]
    cdef double _k644 = ctx.k[644]
    cdef double _k645 = ctx.k[645]
    cdef double _k646 = ctx.k[646]
    cdef double _k647 = ctx.k[647]
    cdef double _k648 = ctx.k[648]
    cdef double _k649 = ctx.k[649]
    cdef double _k650 = ctx.k[650]
    cdef double _k651 = ctx.k[651]
    cdef double _k652 = ctx.k[652]
    cdef double _k653 = ctx.k[653]
    cdef double _k654 = ctx.k[654]
    cdef double _k655 = ctx.k[655]
    cdef double _k656 = ctx.k[656]
    cdef double _k657 = ctx.k[657]
    cdef double _k658 = ctx.k[658]
    cdef double _k659 = ctx.k[659]
    cdef double b1 = _y[0]
    cdef double b2 = _y[1]
    cdef double b3 = _y[2]
    cdef double b4 = _y[3]
    cdef double b5 = _y[4]
    cdef double b6 = _y[5]
    cdef double xE = _y[6]
    cdef double theta = _y[7]
    cdef double b1d = _y[8]
    cdef double b2d = _y[9]
    cdef double b3d = _y[10]
    cdef double b4d = _y[11]
    cdef double b5d = _y[12]
    cdef double b6d = _y[13]
    cdef double xEd = _y[14]
    cdef double thetad = _y[15]
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
    return [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, d - r_b - r_r, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, Omega]


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
    ctx.cache = &k[660]
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
_model.n_const = 660
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
 "n_q": 8,
 "name": "beam6",
 "options": [
  [
   "modes",
   6
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
 "source_hash": "sha256:9d4ce2ed01f1ecad9d62194db1151f10c3655da69963e1cb0de52220801b3e5b",
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
   "doc": "amplitude of the assumed mode (x/d)^7 (13)",
   "initial": 0.0,
   "name": "b6",
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
   "doc": "rate of b6",
   "initial": 0.0,
   "name": "b6d",
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
 "title": "Rayleigh-beam follower in a grooved disk cam, N = 6 assumed modes"
}
"""
MANIFEST = json.loads(_MANIFEST_JSON)
"""States, parameters (defaults, units, ranges), outputs, the cam profile, events, source hash."""

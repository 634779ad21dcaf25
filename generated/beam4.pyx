# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True, initializedcheck=False
#
# GENERATED FILE - DO NOT EDIT.  Written by `camdyn derive` from camdyn/derive/models/beam.py;
# edit that and regenerate.  `camdyn derive --check` fails while this file is stale.
# Derivation key: sha256:95ac485c9b9789ec2819ce82a612055a3c6c4a8d49cc51012c529cfec4539fbf
# Text hash: sha256:6b2e5cb182d6d517f47be5c3111c514f198dd471f0028b90c556a9ac116ef3d0
#
# Rayleigh-beam follower in a grooved disk cam, N = 4 assumed modes (paper (1)-(20))
# Source hash: sha256:64a7efcd9334b75fa69119f83904c9f9c8d47957738123d27eab23d9cd1693f4
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
    _NQ = 6                  # coordinates Q
    _NC = 2                  # constraints Phi
    _NA = 8                  # unknowns of the augmented system: Q'', lambda
    _ND = 4                  # independent coordinates, beside the _NC dependent ones (_partition)
    _NS = 12                 # states: Q, Q'
    _NCAM = 0
    _NM = 0
    _NE = 2
    _NQ1 = 6
    _NE1 = 2
    _JAC_SYMBOLIC = 1           # jacobian() is exact: A^-1 d(b - A x)/dy at fixed x
    _FT_SYMBOLIC = 1            # and so is its df/dt
    _PROJECTS = 1               # the loops call project() after every accepted step

# the declared coordinate partition (ConstraintSolver.dependent): the dependent coordinates,
# then the independent ones; a run may choose another (Ctx.part, _partition)
cdef int _PART[_NQ]
_PART[0] = 4  # xE, dependent
_PART[1] = 5  # theta, dependent
_PART[2] = 0  # b1
_PART[3] = 1  # b2
_PART[4] = 2  # b3
_PART[5] = 3  # b4

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
    cdef double _c4 = (1.0/(d*d*d*d))
    cdef double _c5 = (1.0/(((d*d)*(d*d))*d))
    cdef double _c6 = (1.0/(((d*d)*(d*d))*(d*d)))
    cdef double _c7 = (1.0/(((d*d)*(d*d))*(d*d)*d))
    cdef double _c8 = 4.0*m_r
    cdef double _c9 = (d*d*d)
    cdef double _c10 = 5.0*_c3
    cdef double _c11 = 3.0*_c3
    cdef double _c12 = 5.0*_c2
    cdef double _c13 = (d*d)
    cdef double _c14 = 24.0*m_r
    cdef double _c15 = 4.0*_c3
    cdef double _c16 = 9.0*_c2
    cdef double _c17 = (1.0/((((d*d)*(d*d))*((d*d)*(d*d)))))
    cdef double _c18 = 20.0*m_r
    cdef double _c19 = 8.0*m_r
    cdef double _c20 = 4.0*_c2
    cdef double _c21 = 140.0*m_r
    cdef double _c22 = 20.0*_c3
    cdef double _c23 = 0.0035714285714285713*_c17
    cdef double _c24 = (1.0/((((d*d)*(d*d))*((d*d)*(d*d)))*d))
    cdef double _c25 = 36.0*_c2
    cdef double _c26 = 12.0*m_r
    cdef double _c27 = 2.0*_c3
    cdef double _c28 = 3.0*_c2
    cdef double _c29 = 0.0015873015873015873*_c24
    cdef double _c30 = (1.0/((((d*d)*(d*d))*((d*d)*(d*d)))*(d*d)))
    cdef double _c31 = 40.0*m_r
    cdef double _c32 = 10.0*_c2
    cdef double _c33 = _c4*_c8
    cdef double _c34 = _c6*m_r
    cdef double _c35 = _c17*m_r
    cdef double _c36 = _c30*m_r
    cdef double _c37 = _c26*_c5
    cdef double _c38 = 16.0*_c34
    cdef double _c39 = _c18*_c7
    cdef double _c40 = _c14*_c7
    cdef double _c41 = 30.0*_c35
    cdef double _c42 = _c24*_c31
    cdef double _c43 = _c3*_c4
    cdef double _c44 = 1.3333333333333333*_c43
    cdef double _c45 = _c3*_c6
    cdef double _c46 = _c17*_c3
    cdef double _c47 = _c3*_c30
    cdef double _c48 = _c2*_c4
    cdef double _c49 = _c11*_c5
    cdef double _c50 = _c28*_c6
    cdef double _c51 = _c15*_c7
    cdef double _c52 = _c10*_c24
    cdef double _c53 = _c3*_c7
    cdef double _c54 = 3.3333333333333335*_c53
    cdef double _c55 = 3.2*_c45
    cdef double _c56 = 4.285714285714286*_c46
    cdef double _c57 = _c17*_c2
    cdef double _c58 = _c2*_c30
    cdef double _c59 = _c28*_c5
    cdef double _c60 = _c20*_c6
    cdef double _c61 = _c12*_c7
    cdef double _c62 = _c16*_c7
    cdef double _c63 = 12.0*_c57
    cdef double _c64 = _c2*_c24
    cdef double _c65 = 20.0*_c64
    cdef double _c66 = (r_b*r_b*r_b*r_b)
    cdef double _c67 = (r_r*r_r*r_r*r_r)
    cdef double _c68 = (r_r*r_r*r_r)
    cdef double _c69 = 4.0*r_b
    cdef double _c70 = (r_b*r_b*r_b)
    cdef double _c71 = 4.0*r_r
    cdef double _c72 = (r_r*r_r)
    cdef double _c73 = (r_b*r_b)
    cdef double _c74 = 6.0*_c73
    cdef double _c75 = (S_T*S_T*S_T*S_T)
    cdef double _c76 = 2.0*_c75
    cdef double _c77 = (S_T*S_T)
    cdef double _c78 = _c77*r_r
    cdef double _c79 = 2.0*_c77
    cdef double _c80 = 4.0*S_T
    cdef double _c81 = 12.0*S_T
    cdef double _c82 = _c72*r_b
    cdef double _c83 = _c73*r_r
    cdef double _c84 = _c68*_c80 + _c70*_c80 + _c81*_c82 + _c81*_c83
    cdef double _c85 = (S_T*S_T*S_T)
    cdef double _c86 = _c69*_c85
    cdef double _c87 = _c71*_c85
    cdef double _c88 = _c86 + _c87
    cdef double _c89 = 12.0*r_b
    cdef double _c90 = _c72*_c77
    cdef double _c91 = J_r*_c75
    cdef double _c92 = 2.0*r_b
    cdef double _c93 = _c92*r_r
    cdef double _c94 = 2.0*S_T
    cdef double _c95 = _c94*r_b
    cdef double _c96 = _c94*r_r
    cdef double _c97 = _c95 + _c96
    cdef double _c98 = J_r*_c77
    cdef double _c99 = 2.0*_c98
    cdef double _c100 = _c73*_c98
    cdef double _c101 = _c72*_c98
    cdef double _c102 = _c100 + _c101 + _c93*_c98
    cdef double _c103 = J_r*_c95 + J_r*_c96
    cdef double _c104 = J_r*_c76
    cdef double _c105 = J_r*_c85
    cdef double _c106 = 2.0*r_r
    cdef double _c107 = _c105*_c106 + _c105*_c92
    cdef double _c108 = (1.0/(_c13))
    cdef double _c109 = (1.0/(_c9))
    cdef double _c110 = 5.0*_c5
    cdef double _c111 = 4.0*_c4
    cdef double _c112 = 3.0*_c109
    cdef double _c113 = 2.0*_c108
    cdef double _c114 = r_b + r_r
    cdef double _c115 = 10.0*m_r
    cdef double _c116 = _c5*m_r
    cdef double _c117 = _c4*m_r
    cdef double _c118 = 3.141592653589793*E*_c0
    cdef double _c119 = _c118*_c6
    cdef double _c120 = _c118*_c7
    cdef double _c121 = _c118*_c5
    cdef double _c122 = _c3*_c5
    cdef double _c123 = _c2*_c5
    cdef double _c124 = _c2*_c7
    cdef double _c125 = _c118*_c17
    cdef double _c126 = 2.0*_c7
    cdef double _c127 = 0.5*_c3
    cdef double _c128 = _c2*_c6
    cdef double _c129 = 6.0*_c7
    cdef double _c130 = _c118*_c24
    cdef double _c131 = _c24*_c3
    cdef double _c132 = _c118*_c30
    cdef double _c133 = 18.0*_c34
    cdef double _c134 = 0.5*_c4
    cdef double _c135 = _c7*m_r
    cdef double _c136 = 50.0*_c36
    cdef double _c137 = 32.0*_c35
    cdef double _c138 = _c19*_c4
    cdef double _c139 = 6.0*_c3
    cdef double _c140 = 5.555555555555555*_c47
    cdef double _c141 = 4.571428571428571*_c46
    cdef double _c142 = 3.6*_c45
    cdef double _c143 = 2.6666666666666665*_c43
    cdef double _c144 = 6.0*_c128
    cdef double _c145 = 2.0*_c48
    cdef double _c146 = 28.571428571428573*_c58
    cdef double _c147 = 14.4*_c57
    cdef double _c148 = J_r*S_T
    cdef double _c149 = 6.0*(((r_r*r_r)*(r_r*r_r))*r_r)
    cdef double _c150 = 6.0*(((r_b*r_b)*(r_b*r_b))*r_b)
    cdef double _c151 = 15.0*_c67
    cdef double _c152 = 20.0*_c70
    cdef double _c153 = 15.0*_c66
    cdef double _c154 = (((S_T*S_T)*(S_T*S_T))*(S_T*S_T))
    cdef double _c155 = 3.0*_c77
    cdef double _c156 = _c68*_c77
    cdef double _c157 = _c70*_c78
    cdef double _c158 = _c73*_c90
    cdef double _c159 = r_b*r_r
    cdef double _c160 = _c159*_c75
    cdef double _c161 = 3.0*_c75
    cdef double _c162 = 30.0*S_T
    cdef double _c163 = 60.0*S_T
    cdef double _c164 = S_T*_c149 + S_T*_c150 + _c162*_c66*r_r + _c162*_c67*r_b + _c163*_c68*_c73 + _c163*_c70*_c72
    cdef double _c165 = (((S_T*S_T)*(S_T*S_T))*S_T)
    cdef double _c166 = 6.0*_c165
    cdef double _c167 = _c166*r_b
    cdef double _c168 = _c166*r_r
    cdef double _c169 = _c167 + _c168
    cdef double _c170 = _c156*r_b
    cdef double _c171 = 15.0*_c75
    cdef double _c172 = _c68*_c85
    cdef double _c173 = 60.0*_c85
    cdef double _c174 = 12.0*_c85
    cdef double _c175 = 36.0*_c85
    cdef double _c176 = 12.0*_c172 + _c174*_c70 + _c175*_c82 + _c175*_c83
    cdef double _c177 = 12.0*_c165
    cdef double _c178 = _c177*r_b
    cdef double _c179 = _c177*r_r
    cdef double _c180 = 36.0*_c75
    cdef double _c181 = 18.0*_c75
    cdef double _c182 = J_r*_c154
    cdef double _c183 = J_r*_c165
    cdef double _c184 = _c105*r_b
    cdef double _c185 = _c105*r_r
    cdef double _c186 = _c184 + _c185
    cdef double _c187 = 4.0*_c182
    cdef double _c188 = 8.0*_c91
    cdef double _c189 = 4.0*_c91
    cdef double _c190 = _c159*_c188 + _c189*_c72 + _c189*_c73
    cdef double _c191 = _c183*_c69 + _c183*_c71
    cdef double _c192 = _c69*r_r
    cdef double _c193 = _c192*_c98 + _c72*_c99 + _c73*_c99
    cdef double _c194 = _c105*_c70
    cdef double _c195 = J_r*_c172
    cdef double _c196 = 6.0*_c184
    cdef double _c197 = 8.0*_c183
    cdef double _c198 = _c197*r_b + _c197*r_r
    cdef double _c199 = J_r*_c86 + J_r*_c87
    cdef double _c200 = 6.0*_c91
    cdef double _c201 = (Omega*Omega)
    cdef double _c202 = _c201*r_b
    cdef double _c203 = _c201*r_r
    cdef double _c204 = _c202 + _c203
    cdef double _c205 = S_T*_c201
    cdef double _c206 = Omega*_c106 + Omega*_c92
    cdef double _c207 = 6.0*_c109
    cdef double _c208 = 8.0*_c4
    cdef double _c209 = 12.0*_c4
    cdef double _c210 = 20.0*_c5
    cdef double _c211 = Omega*_c94
    cdef double _c212 = 10.0*_c3
    cdef double _c213 = 4.0*_c5
    cdef double _c214 = 100.0*_c135
    cdef double _c215 = _c22*_c7
    cdef double _c216 = _c111*_c3
    cdef double _c217 = 20.0*_c124
    cdef double _c218 = 12.0*_c128
    cdef double _c219 = 6.0*_c123
    cdef double _c220 = 40.0*_c3
    cdef double _c221 = _c16*_c6
    cdef double _c222 = 8.0*_c24
    cdef double _c223 = _c24*m_r
    cdef double _c224 = 36.0*_c34
    cdef double _c225 = 9.0*_c45
    cdef double _c226 = 96.0*_c35
    cdef double _c227 = 16.0*_c46
    cdef double _c228 = _c17*_c25
    cdef double _c229 = 200.0*_c36
    cdef double _c230 = 25.0*_c47
    cdef double _c231 = 100.0*_c58
    cdef double _c232 = 36.0*_c116
    cdef double _c233 = 64.0*_c34
    cdef double _c234 = 120.0*_c135
    cdef double _c235 = 180.0*_c35
    cdef double _c236 = 280.0*_c223
    cdef double _c237 = 12.0*_c122
    cdef double _c238 = 16.0*_c45
    cdef double _c239 = 24.0*_c53
    cdef double _c240 = 30.0*_c46
    cdef double _c241 = _c220*_c24
    cdef double _c242 = _c25*_c7
    cdef double _c243 = 60.0*_c57
    cdef double _c244 = 120.0*_c64
    cdef double _c245 = _c78*r_b
    cdef double _c246 = _c73*_c77
    cdef double _c247 = _c174*r_b
    cdef double _c248 = _c174*r_r
    cdef double _c249 = 6.0*_c154
    cdef double _c250 = _c70*_c85
    cdef double _c251 = 180.0*_c85
    cdef double _c252 = 60.0*_c75
    cdef double _c253 = 30.0*_c77
    cdef double _c254 = 30.0*_c165
    cdef double _c255 = 12.0*_c154
    cdef double _c256 = 36.0*_c165
    cdef double _c257 = J_r*_c178 + J_r*_c179
    cdef double _c258 = 8.0*_c85
    cdef double _c259 = 10.0*_c183
    cdef double _c260 = _c159*_c91
    cdef double _c261 = 12.0*_c91
    cdef double _c262 = 24.0*_c260 + _c261*_c72 + _c261*_c73
    cdef double _c263 = 12.0*_c75
    cdef double _c264 = 6.0*_c77
    cdef double _c265 = 72.0*_c85
    cdef double _c266 = 24.0*_c165
    cdef double _c267 = _c266*r_b
    cdef double _c268 = _c266*r_r
    cdef double _c269 = 16.0*_c183
    cdef double _c270 = Omega*S_T
    cdef double _c271 = (Omega*Omega*Omega)
    cdef double _c272 = _c271*r_b + _c271*r_r
    cdef double _c273 = S_T*_c271
    cdef double _c274 = Omega*r_b + Omega*r_r
    cdef double _c275 = 2.0*_c202 + 2.0*_c203
    cdef double _c276 = 2.0*_c205
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
    ctx.k[28] = 0.5*_c2  # _k28
    ctx.k[29] = 0.1111111111111111*_c3  # _k29
    ctx.k[30] = 0.5357142857142857*_c2  # _k30
    ctx.k[31] = _c17  # _k31
    ctx.k[32] = _c18  # _k32
    ctx.k[33] = 28.0*_c9  # _k33
    ctx.k[34] = _c19  # _k34
    ctx.k[35] = _c20  # _k35
    ctx.k[36] = _c21  # _k36
    ctx.k[37] = _c22  # _k37
    ctx.k[38] = 63.0*_c2  # _k38
    ctx.k[39] = 8.0*d  # _k39
    ctx.k[40] = 35.0*_c13  # _k40
    ctx.k[41] = _c23  # _k41
    ctx.k[42] = 0.5714285714285714*_c2  # _k42
    ctx.k[43] = 0.1*_c3  # _k43
    ctx.k[44] = 0.625*_c2  # _k44
    ctx.k[45] = _c24  # _k45
    ctx.k[46] = 63.0*m_r  # _k46
    ctx.k[47] = 7.0*_c3  # _k47
    ctx.k[48] = _c25  # _k48
    ctx.k[49] = _c26  # _k49
    ctx.k[50] = _c27  # _k50
    ctx.k[51] = _c28  # _k51
    ctx.k[52] = 105.0*_c9  # _k52
    ctx.k[53] = 54.0*_c13  # _k53
    ctx.k[54] = 315.0*d  # _k54
    ctx.k[55] = _c29  # _k55
    ctx.k[56] = 0.09090909090909091*_c3  # _k56
    ctx.k[57] = 0.6944444444444444*_c2  # _k57
    ctx.k[58] = _c30  # _k58
    ctx.k[59] = _c31  # _k59
    ctx.k[60] = 25.0*_c2  # _k60
    ctx.k[61] = 28.0*m_r  # _k61
    ctx.k[62] = 7.0*_c2  # _k62
    ctx.k[63] = 0.07142857142857142*_c9  # _k63
    ctx.k[64] = _c32  # _k64
    ctx.k[65] = 0.125*_c13  # _k65
    ctx.k[66] = 252.0*m_r  # _k66
    ctx.k[67] = 28.0*_c3  # _k67
    ctx.k[68] = 135.0*_c2  # _k68
    ctx.k[69] = 0.015873015873015872*d  # _k69
    ctx.k[70] = L_g*_c3 + m_r  # _k70
    ctx.k[71] = _c33  # _k71
    ctx.k[72] = 9.0*_c34  # _k72
    ctx.k[73] = 16.0*_c35  # _k73
    ctx.k[74] = 25.0*_c36  # _k74
    ctx.k[75] = _c37  # _k75
    ctx.k[76] = _c38  # _k76
    ctx.k[77] = _c39  # _k77
    ctx.k[78] = _c40  # _k78
    ctx.k[79] = _c41  # _k79
    ctx.k[80] = _c42  # _k80
    ctx.k[81] = _c44  # _k81
    ctx.k[82] = 1.8*_c45  # _k82
    ctx.k[83] = 2.2857142857142856*_c46  # _k83
    ctx.k[84] = 2.7777777777777777*_c47  # _k84
    ctx.k[85] = _c48  # _k85
    ctx.k[86] = _c49  # _k86
    ctx.k[87] = _c50  # _k87
    ctx.k[88] = _c51  # _k88
    ctx.k[89] = _c52  # _k89
    ctx.k[90] = _c54  # _k90
    ctx.k[91] = _c55  # _k91
    ctx.k[92] = _c56  # _k92
    ctx.k[93] = 7.2*_c57  # _k93
    ctx.k[94] = 14.285714285714286*_c58  # _k94
    ctx.k[95] = _c59  # _k95
    ctx.k[96] = _c60  # _k96
    ctx.k[97] = _c61  # _k97
    ctx.k[98] = _c62  # _k98
    ctx.k[99] = _c63  # _k99
    ctx.k[100] = _c65  # _k100
    ctx.k[101] = _c66 + _c67 + _c68*_c69 + _c70*_c71 + _c72*_c74  # _k101
    ctx.k[102] = _c75  # _k102
    ctx.k[103] = _c76  # _k103
    ctx.k[104] = _c69*_c78 + _c72*_c79 + _c73*_c79  # _k104
    ctx.k[105] = _c84  # _k105
    ctx.k[106] = _c88  # _k106
    ctx.k[107] = _c74*_c77 + _c78*_c89 + 6.0*_c90  # _k107
    ctx.k[108] = _c91  # _k108
    ctx.k[109] = _c72 + _c73 + _c93  # _k109
    ctx.k[110] = _c77  # _k110
    ctx.k[111] = _c97  # _k111
    ctx.k[112] = _c99  # _k112
    ctx.k[113] = _c102  # _k113
    ctx.k[114] = -_c99  # _k114
    ctx.k[115] = -_c103  # _k115
    ctx.k[116] = -_c104  # _k116
    ctx.k[117] = -_c107  # _k117
    ctx.k[118] = _c107  # _k118
    ctx.k[119] = -_c108  # _k119
    ctx.k[120] = -_c109  # _k120
    ctx.k[121] = -_c4  # _k121
    ctx.k[122] = -_c5  # _k122
    ctx.k[123] = -_c110  # _k123
    ctx.k[124] = -_c111  # _k124
    ctx.k[125] = -_c112  # _k125
    ctx.k[126] = -_c113  # _k126
    ctx.k[127] = _c114  # _k127
    ctx.k[128] = -_c39  # _k128
    ctx.k[129] = -_c26*_c6  # _k129
    ctx.k[130] = -_c115*_c7  # _k130
    ctx.k[131] = -_c19*_c6  # _k131
    ctx.k[132] = -6.0*_c116  # _k132
    ctx.k[133] = -_c33  # _k133
    ctx.k[134] = -2.0*_c117  # _k134
    ctx.k[135] = -_c118*_c4  # _k135
    ctx.k[136] = -2.0*_c119  # _k136
    ctx.k[137] = -2.5*_c120  # _k137
    ctx.k[138] = -1.5*_c121  # _k138
    ctx.k[139] = -_c43  # _k139
    ctx.k[140] = -2.4*_c45  # _k140
    ctx.k[141] = -_c54  # _k141
    ctx.k[142] = -1.4285714285714286*_c53  # _k142
    ctx.k[143] = -1.2*_c122  # _k143
    ctx.k[144] = -1.3333333333333333*_c45  # _k144
    ctx.k[145] = -1.5*_c122  # _k145
    ctx.k[146] = -0.6666666666666666*_c43  # _k146
    ctx.k[147] = -_c48  # _k147
    ctx.k[148] = -_c60  # _k148
    ctx.k[149] = -_c20*_c7  # _k149
    ctx.k[150] = -_c50  # _k150
    ctx.k[151] = -2.0*_c123  # _k151
    ctx.k[152] = -7.5*_c124  # _k152
    ctx.k[153] = -1.5*_c123  # _k153
    ctx.k[154] = -_c17*_c18  # _k154
    ctx.k[155] = -_c26*_c7  # _k155
    ctx.k[156] = -10.0*_c35  # _k156
    ctx.k[157] = -_c19*_c7  # _k157
    ctx.k[158] = -6.0*_c34  # _k158
    ctx.k[159] = -_c5*_c8  # _k159
    ctx.k[160] = -2.0*_c116  # _k160
    ctx.k[161] = -6.0*_c125  # _k161
    ctx.k[162] = -3.0*_c119  # _k162
    ctx.k[163] = -4.5*_c120  # _k163
    ctx.k[164] = -_c45  # _k164
    ctx.k[165] = -_c126*_c3  # _k165
    ctx.k[166] = -2.857142857142857*_c46  # _k166
    ctx.k[167] = -1.1428571428571428*_c53  # _k167
    ctx.k[168] = -1.2*_c45  # _k168
    ctx.k[169] = -1.25*_c46  # _k169
    ctx.k[170] = -0.8*_c122  # _k170
    ctx.k[171] = -_c127*_c5  # _k171
    ctx.k[172] = -_c123  # _k172
    ctx.k[173] = -_c16*_c17  # _k173
    ctx.k[174] = -_c12*_c17  # _k174
    ctx.k[175] = -3.6*_c124  # _k175
    ctx.k[176] = -4.5*_c124  # _k176
    ctx.k[177] = -2.25*_c128  # _k177
    ctx.k[178] = -1.5*_c128  # _k178
    ctx.k[179] = -_c18*_c24  # _k179
    ctx.k[180] = -_c17*_c26  # _k180
    ctx.k[181] = -_c115*_c24  # _k181
    ctx.k[182] = -_c17*_c19  # _k182
    ctx.k[183] = -_c129*m_r  # _k183
    ctx.k[184] = -_c6*_c8  # _k184
    ctx.k[185] = -2.0*_c34  # _k185
    ctx.k[186] = -10.0*_c130  # _k186
    ctx.k[187] = -7.2*_c125  # _k187
    ctx.k[188] = -_c53  # _k188
    ctx.k[189] = -_c46  # _k189
    ctx.k[190] = -1.7142857142857142*_c46  # _k190
    ctx.k[191] = -1.1111111111111112*_c131  # _k191
    ctx.k[192] = -0.8571428571428571*_c53  # _k192
    ctx.k[193] = -2.5*_c131  # _k193
    ctx.k[194] = -0.6666666666666666*_c45  # _k194
    ctx.k[195] = -0.4*_c45  # _k195
    ctx.k[196] = -_c128  # _k196
    ctx.k[197] = -_c24*_c32  # _k197
    ctx.k[198] = -_c17*_c20  # _k198
    ctx.k[199] = -5.714285714285714*_c64  # _k199
    ctx.k[200] = -4.8*_c57  # _k200
    ctx.k[201] = -2.4*_c124  # _k201
    ctx.k[202] = -1.5*_c124  # _k202
    ctx.k[203] = -_c18*_c30  # _k203
    ctx.k[204] = -_c24*_c26  # _k204
    ctx.k[205] = -10.0*_c36  # _k205
    ctx.k[206] = -_c19*_c24  # _k206
    ctx.k[207] = -6.0*_c35  # _k207
    ctx.k[208] = -_c7*_c8  # _k208
    ctx.k[209] = -_c126*m_r  # _k209
    ctx.k[210] = -14.285714285714286*_c132  # _k210
    ctx.k[211] = -_c47  # _k211
    ctx.k[212] = -2.2222222222222223*_c47  # _k212
    ctx.k[213] = -0.8888888888888888*_c131  # _k213
    ctx.k[214] = -0.8571428571428571*_c46  # _k214
    ctx.k[215] = -0.5714285714285714*_c53  # _k215
    ctx.k[216] = -1.5*_c131  # _k216
    ctx.k[217] = -0.75*_c46  # _k217
    ctx.k[218] = -0.3333333333333333*_c53  # _k218
    ctx.k[219] = -_c124  # _k219
    ctx.k[220] = -_c12*_c24  # _k220
    ctx.k[221] = -10.714285714285714*_c58  # _k221
    ctx.k[222] = -4.285714285714286*_c64  # _k222
    ctx.k[223] = -6.25*_c58  # _k223
    ctx.k[224] = -2.5*_c57  # _k224
    ctx.k[225] = -1.5*_c57  # _k225
    ctx.k[226] = -_c127  # _k226
    ctx.k[227] = -100.0*_c36  # _k227
    ctx.k[228] = -48.0*_c35  # _k228
    ctx.k[229] = -_c133  # _k229
    ctx.k[230] = -_c118*_c134  # _k230
    ctx.k[231] = -_c21*_c24  # _k231
    ctx.k[232] = -90.0*_c35  # _k232
    ctx.k[233] = -60.0*_c135  # _k233
    ctx.k[234] = -50.0*_c132  # _k234
    ctx.k[235] = -50.0*_c135  # _k235
    ctx.k[236] = -_c136  # _k236
    ctx.k[237] = -_c42  # _k237
    ctx.k[238] = -32.0*_c34  # _k238
    ctx.k[239] = -_c137  # _k239
    ctx.k[240] = -_c41  # _k240
    ctx.k[241] = -_c40  # _k241
    ctx.k[242] = -18.0*_c125  # _k242
    ctx.k[243] = -18.0*_c116  # _k243
    ctx.k[244] = -_c38  # _k244
    ctx.k[245] = -_c37  # _k245
    ctx.k[246] = -_c138  # _k246
    ctx.k[247] = -4.5*_c119  # _k247
    ctx.k[248] = -60.0*_c130  # _k248
    ctx.k[249] = -30.0*_c125  # _k249
    ctx.k[250] = -18.0*_c120  # _k250
    ctx.k[251] = -10.0*_c120  # _k251
    ctx.k[252] = -8.0*_c46  # _k252
    ctx.k[253] = -6.0*_c119  # _k253
    ctx.k[254] = -3.0*_c121  # _k254
    ctx.k[255] = -_c27*_c4  # _k255
    ctx.k[256] = -12.5*_c47  # _k256
    ctx.k[257] = -4.5*_c45  # _k257
    ctx.k[258] = -_c134*_c2  # _k258
    ctx.k[259] = -50.0*_c58  # _k259
    ctx.k[260] = -_c22*_c24  # _k260
    ctx.k[261] = -18.0*_c57  # _k261
    ctx.k[262] = -15.0*_c46  # _k262
    ctx.k[263] = -12.0*_c53  # _k263
    ctx.k[264] = -10.0*_c53  # _k264
    ctx.k[265] = -8.0*_c45  # _k265
    ctx.k[266] = -_c139*_c5  # _k266
    ctx.k[267] = -_c52  # _k267
    ctx.k[268] = -_c51  # _k268
    ctx.k[269] = -_c49  # _k269
    ctx.k[270] = -_c140  # _k270
    ctx.k[271] = -_c141  # _k271
    ctx.k[272] = -_c56  # _k272
    ctx.k[273] = -_c142  # _k273
    ctx.k[274] = -_c55  # _k274
    ctx.k[275] = -4.5*_c128  # _k275
    ctx.k[276] = -_c143  # _k276
    ctx.k[277] = -60.0*_c64  # _k277
    ctx.k[278] = -30.0*_c57  # _k278
    ctx.k[279] = -_c65  # _k279
    ctx.k[280] = -18.0*_c124  # _k280
    ctx.k[281] = -_c63  # _k281
    ctx.k[282] = -_c32*_c7  # _k282
    ctx.k[283] = -_c62  # _k283
    ctx.k[284] = -_c144  # _k284
    ctx.k[285] = -_c61  # _k285
    ctx.k[286] = -_c59  # _k286
    ctx.k[287] = -_c145  # _k287
    ctx.k[288] = -_c146  # _k288
    ctx.k[289] = -_c147  # _k289
    ctx.k[290] = _c98  # _k290
    ctx.k[291] = _c148*r_b + _c148*r_r  # _k291
    ctx.k[292] = -_c98  # _k292
    ctx.k[293] = _c104  # _k293
    ctx.k[294] = _c149*r_b + _c150*r_r + _c151*_c73 + _c152*_c68 + _c153*_c72 + (((r_b*r_b)*(r_b*r_b))*(r_b*r_b)) + (((r_r*r_r)*(r_r*r_r))*(r_r*r_r))  # _k294
    ctx.k[295] = _c154  # _k295
    ctx.k[296] = 3.0*_c154  # _k296
    ctx.k[297] = _c155*_c66 + _c155*_c67 + _c156*_c89 + 12.0*_c157 + 18.0*_c158  # _k297
    ctx.k[298] = 6.0*_c160 + _c161*_c72 + _c161*_c73  # _k298
    ctx.k[299] = _c164  # _k299
    ctx.k[300] = _c169  # _k300
    ctx.k[301] = _c151*_c77 + _c153*_c77 + 60.0*_c157 + 90.0*_c158 + 60.0*_c170  # _k301
    ctx.k[302] = 30.0*_c160 + _c171*_c72 + _c171*_c73  # _k302
    ctx.k[303] = _c152*_c85 + 20.0*_c172 + _c173*_c82 + _c173*_c83  # _k303
    ctx.k[304] = _c176  # _k304
    ctx.k[305] = _c178 + _c179  # _k305
    ctx.k[306] = _c159*_c180 + _c181*_c72 + _c181*_c73  # _k306
    ctx.k[307] = 2.0*_c182  # _k307
    ctx.k[308] = _c106*_c183 + _c183*_c92  # _k308
    ctx.k[309] = _c186  # _k309
    ctx.k[310] = -_c91  # _k310
    ctx.k[311] = -_c186  # _k311
    ctx.k[312] = -_c102  # _k312
    ctx.k[313] = -_c187  # _k313
    ctx.k[314] = -_c190  # _k314
    ctx.k[315] = -_c191  # _k315
    ctx.k[316] = -_c193  # _k316
    ctx.k[317] = _c185*_c74 + 2.0*_c194 + 2.0*_c195 + _c196*_c72  # _k317
    ctx.k[318] = _c104*_c72 + _c104*_c73 + _c192*_c91  # _k318
    ctx.k[319] = -_c198  # _k319
    ctx.k[320] = -_c199  # _k320
    ctx.k[321] = _c191  # _k321
    ctx.k[322] = _c200*_c72 + _c74*_c91 + _c89*_c91*r_r  # _k322
    ctx.k[323] = J_r*_c167 + J_r*_c168  # _k323
    ctx.k[324] = _c204  # _k324
    ctx.k[325] = _c113  # _k325
    ctx.k[326] = _c205  # _k326
    ctx.k[327] = -S_T  # _k327
    ctx.k[328] = -_c206  # _k328
    ctx.k[329] = _c94  # _k329
    ctx.k[330] = 4.0*_c108  # _k330
    ctx.k[331] = _c207  # _k331
    ctx.k[332] = _c208  # _k332
    ctx.k[333] = 10.0*_c5  # _k333
    ctx.k[334] = _c209  # _k334
    ctx.k[335] = _c210  # _k335
    ctx.k[336] = -_c211  # _k336
    ctx.k[337] = -_c94  # _k337
    ctx.k[338] = _c211  # _k338
    ctx.k[339] = -d  # _k339
    ctx.k[340] = -Omega  # _k340
    ctx.k[341] = _c108  # _k341
    ctx.k[342] = _c109  # _k342
    ctx.k[343] = -_c134  # _k343
    ctx.k[344] = -0.2*_c5  # _k344
    ctx.k[345] = -0.16666666666666666*_c6  # _k345
    ctx.k[346] = -0.14285714285714285*_c7  # _k346
    ctx.k[347] = 0.4*_c3  # _k347
    ctx.k[348] = 0.3333333333333333*_c3  # _k348
    ctx.k[349] = 0.2857142857142857*_c3  # _k349
    ctx.k[350] = -_c6  # _k350
    ctx.k[351] = 0.25*_c3  # _k351
    ctx.k[352] = -_c7  # _k352
    ctx.k[353] = _c212  # _k353
    ctx.k[354] = 0.3333333333333333*d  # _k354
    ctx.k[355] = _c139  # _k355
    ctx.k[356] = 8.0*_c3  # _k356
    ctx.k[357] = -_c129  # _k357
    ctx.k[358] = -5.0*_c6  # _k358
    ctx.k[359] = -_c213  # _k359
    ctx.k[360] = -3.0*_c4  # _k360
    ctx.k[361] = -_c126  # _k361
    ctx.k[362] = -_c214  # _k362
    ctx.k[363] = -48.0*_c34  # _k363
    ctx.k[364] = -_c31*_c6  # _k364
    ctx.k[365] = -_c14*_c5  # _k365
    ctx.k[366] = -_c26*_c4  # _k366
    ctx.k[367] = -_c215  # _k367
    ctx.k[368] = -12.0*_c45  # _k368
    ctx.k[369] = -_c216  # _k369
    ctx.k[370] = -30.0*_c124  # _k370
    ctx.k[371] = -_c217  # _k371
    ctx.k[372] = -_c218  # _k372
    ctx.k[373] = -_c219  # _k373
    ctx.k[374] = -_c31*_c7  # _k374
    ctx.k[375] = -_c14*_c6  # _k375
    ctx.k[376] = -4.8*_c45  # _k376
    ctx.k[377] = -6.666666666666667*_c53  # _k377
    ctx.k[378] = -_c44  # _k378
    ctx.k[379] = -15.0*_c124  # _k379
    ctx.k[380] = -8.0*_c128  # _k380
    ctx.k[381] = -0.1*_c5  # _k381
    ctx.k[382] = -0.125*_c6  # _k382
    ctx.k[383] = -0.02857142857142857*_c7  # _k383
    ctx.k[384] = -0.625*_c17  # _k384
    ctx.k[385] = _c112  # _k385
    ctx.k[386] = 0.2222222222222222*_c3  # _k386
    ctx.k[387] = -_c17  # _k387
    ctx.k[388] = -7.0*_c17  # _k388
    ctx.k[389] = -0.010714285714285714*_c17  # _k389
    ctx.k[390] = _c220  # _k390
    ctx.k[391] = 16.0*d  # _k391
    ctx.k[392] = -_c23  # _k392
    ctx.k[393] = -120.0*_c35  # _k393
    ctx.k[394] = -70.0*_c35  # _k394
    ctx.k[395] = -48.0*_c135  # _k395
    ctx.k[396] = -30.0*_c34  # _k396
    ctx.k[397] = -16.0*_c116  # _k397
    ctx.k[398] = -9.0*_c119  # _k398
    ctx.k[399] = -_c17*_c22  # _k399
    ctx.k[400] = -10.0*_c46  # _k400
    ctx.k[401] = -8.0*_c53  # _k401
    ctx.k[402] = -6.0*_c45  # _k402
    ctx.k[403] = -_c213*_c3  # _k403
    ctx.k[404] = -_c27*_c5  # _k404
    ctx.k[405] = -45.0*_c57  # _k405
    ctx.k[406] = -_c221  # _k406
    ctx.k[407] = -_c17*_c31  # _k407
    ctx.k[408] = -_c122  # _k408
    ctx.k[409] = -5.714285714285714*_c46  # _k409
    ctx.k[410] = -0.08571428571428572*_c7  # _k410
    ctx.k[411] = -0.5*_c17  # _k411
    ctx.k[412] = -0.07936507936507936*_c24  # _k412
    ctx.k[413] = _c111  # _k413
    ctx.k[414] = -_c24  # _k414
    ctx.k[415] = -_c222  # _k415
    ctx.k[416] = -0.006349206349206349*_c24  # _k416
    ctx.k[417] = 14.0*_c3  # _k417
    ctx.k[418] = 630.0*d  # _k418
    ctx.k[419] = -_c29  # _k419
    ctx.k[420] = -80.0*_c223  # _k420
    ctx.k[421] = -72.0*_c35  # _k421
    ctx.k[422] = -56.0*_c35  # _k422
    ctx.k[423] = -36.0*_c135  # _k423
    ctx.k[424] = -30.0*_c135  # _k424
    ctx.k[425] = -_c18*_c6  # _k425
    ctx.k[426] = -36.0*_c125  # _k426
    ctx.k[427] = -12.0*_c46  # _k427
    ctx.k[428] = -_c212*_c24  # _k428
    ctx.k[429] = -_c129*_c3  # _k429
    ctx.k[430] = -_c15*_c6  # _k430
    ctx.k[431] = -_c27*_c6  # _k431
    ctx.k[432] = -40.0*_c64  # _k432
    ctx.k[433] = -24.0*_c57  # _k433
    ctx.k[434] = -12.0*_c124  # _k434
    ctx.k[435] = -_c129*_c2  # _k435
    ctx.k[436] = -_c14*_c17  # _k436
    ctx.k[437] = -3.4285714285714284*_c46  # _k437
    ctx.k[438] = -0.8*_c45  # _k438
    ctx.k[439] = -_c28*_c7  # _k439
    ctx.k[440] = -9.6*_c57  # _k440
    ctx.k[441] = -0.07142857142857142*_c7  # _k441
    ctx.k[442] = -0.125*_c17  # _k442
    ctx.k[443] = -0.015873015873015872*_c24  # _k443
    ctx.k[444] = -0.125*_c30  # _k444
    ctx.k[445] = _c110  # _k445
    ctx.k[446] = 0.18181818181818182*_c3  # _k446
    ctx.k[447] = -_c30  # _k447
    ctx.k[448] = 56.0*_c3  # _k448
    ctx.k[449] = 0.031746031746031744*d  # _k449
    ctx.k[450] = -9.0*_c30  # _k450
    ctx.k[451] = -5.0*_c30  # _k451
    ctx.k[452] = -160.0*_c36  # _k452
    ctx.k[453] = -90.0*_c36  # _k453
    ctx.k[454] = -84.0*_c223  # _k454
    ctx.k[455] = -64.0*_c223  # _k455
    ctx.k[456] = -42.0*_c35  # _k456
    ctx.k[457] = -36.0*_c35  # _k457
    ctx.k[458] = -100.0*_c132  # _k458
    ctx.k[459] = -_c22*_c30  # _k459
    ctx.k[460] = -12.0*_c131  # _k460
    ctx.k[461] = -10.0*_c47  # _k461
    ctx.k[462] = -_c222*_c3  # _k462
    ctx.k[463] = -6.0*_c46  # _k463
    ctx.k[464] = -75.0*_c58  # _k464
    ctx.k[465] = -30.0*_c64  # _k465
    ctx.k[466] = -15.0*_c57  # _k466
    ctx.k[467] = -7.5*_c57  # _k467
    ctx.k[468] = -_c30*_c31  # _k468
    ctx.k[469] = -_c14*_c24  # _k469
    ctx.k[470] = -_c11*_c24  # _k470
    ctx.k[471] = -4.444444444444445*_c47  # _k471
    ctx.k[472] = -0.6666666666666666*_c53  # _k472
    ctx.k[473] = -_c17*_c28  # _k473
    ctx.k[474] = -21.428571428571427*_c58  # _k474
    ctx.k[475] = _c138  # _k475
    ctx.k[476] = _c143  # _k476
    ctx.k[477] = _c145  # _k477
    ctx.k[478] = _c133  # _k478
    ctx.k[479] = _c142  # _k479
    ctx.k[480] = _c144  # _k480
    ctx.k[481] = -_c224  # _k481
    ctx.k[482] = -_c225  # _k482
    ctx.k[483] = _c137  # _k483
    ctx.k[484] = _c141  # _k484
    ctx.k[485] = _c147  # _k485
    ctx.k[486] = -_c226  # _k486
    ctx.k[487] = -_c227  # _k487
    ctx.k[488] = -_c228  # _k488
    ctx.k[489] = _c136  # _k489
    ctx.k[490] = _c140  # _k490
    ctx.k[491] = _c146  # _k491
    ctx.k[492] = -_c229  # _k492
    ctx.k[493] = -_c230  # _k493
    ctx.k[494] = -_c231  # _k494
    ctx.k[495] = -_c210  # _k495
    ctx.k[496] = -_c209  # _k496
    ctx.k[497] = -_c207  # _k497
    ctx.k[498] = _c224  # _k498
    ctx.k[499] = _c226  # _k499
    ctx.k[500] = _c229  # _k500
    ctx.k[501] = _c232  # _k501
    ctx.k[502] = _c233  # _k502
    ctx.k[503] = _c214  # _k503
    ctx.k[504] = _c234  # _k504
    ctx.k[505] = _c235  # _k505
    ctx.k[506] = _c236  # _k506
    ctx.k[507] = _c216  # _k507
    ctx.k[508] = _c225  # _k508
    ctx.k[509] = _c227  # _k509
    ctx.k[510] = _c230  # _k510
    ctx.k[511] = _c221  # _k511
    ctx.k[512] = _c237  # _k512
    ctx.k[513] = _c238  # _k513
    ctx.k[514] = _c215  # _k514
    ctx.k[515] = _c239  # _k515
    ctx.k[516] = _c240  # _k516
    ctx.k[517] = _c228  # _k517
    ctx.k[518] = _c241  # _k518
    ctx.k[519] = _c231  # _k519
    ctx.k[520] = _c219  # _k520
    ctx.k[521] = _c218  # _k521
    ctx.k[522] = _c217  # _k522
    ctx.k[523] = _c242  # _k523
    ctx.k[524] = _c243  # _k524
    ctx.k[525] = _c244  # _k525
    ctx.k[526] = -700.0*_c36  # _k526
    ctx.k[527] = -240.0*_c35  # _k527
    ctx.k[528] = -54.0*_c34  # _k528
    ctx.k[529] = -840.0*_c223  # _k529
    ctx.k[530] = -450.0*_c35  # _k530
    ctx.k[531] = -400.0*_c36  # _k531
    ctx.k[532] = -300.0*_c132  # _k532
    ctx.k[533] = -_c236  # _k533
    ctx.k[534] = -240.0*_c135  # _k534
    ctx.k[535] = -200.0*_c135  # _k535
    ctx.k[536] = -192.0*_c35  # _k536
    ctx.k[537] = -_c235  # _k537
    ctx.k[538] = -_c234  # _k538
    ctx.k[539] = -96.0*_c34  # _k539
    ctx.k[540] = -72.0*_c125  # _k540
    ctx.k[541] = -72.0*_c34  # _k541
    ctx.k[542] = -_c233  # _k542
    ctx.k[543] = -_c232  # _k543
    ctx.k[544] = -16.0*_c117  # _k544
    ctx.k[545] = -300.0*_c130  # _k545
    ctx.k[546] = -120.0*_c125  # _k546
    ctx.k[547] = -100.0*_c47  # _k547
    ctx.k[548] = -54.0*_c120  # _k548
    ctx.k[549] = -48.0*_c46  # _k549
    ctx.k[550] = -30.0*_c120  # _k550
    ctx.k[551] = -18.0*_c45  # _k551
    ctx.k[552] = -12.0*_c119  # _k552
    ctx.k[553] = -300.0*_c58  # _k553
    ctx.k[554] = -140.0*_c131  # _k554
    ctx.k[555] = -90.0*_c46  # _k555
    ctx.k[556] = -72.0*_c57  # _k556
    ctx.k[557] = -60.0*_c53  # _k557
    ctx.k[558] = -50.0*_c53  # _k558
    ctx.k[559] = -50.0*_c47  # _k559
    ctx.k[560] = -_c241  # _k560
    ctx.k[561] = -32.0*_c45  # _k561
    ctx.k[562] = -32.0*_c46  # _k562
    ctx.k[563] = -_c240  # _k563
    ctx.k[564] = -_c239  # _k564
    ctx.k[565] = -18.0*_c122  # _k565
    ctx.k[566] = -_c238  # _k566
    ctx.k[567] = -_c237  # _k567
    ctx.k[568] = -_c208*_c3  # _k568
    ctx.k[569] = -300.0*_c64  # _k569
    ctx.k[570] = -200.0*_c58  # _k570
    ctx.k[571] = -120.0*_c57  # _k571
    ctx.k[572] = -_c244  # _k572
    ctx.k[573] = -_c243  # _k573
    ctx.k[574] = -54.0*_c124  # _k574
    ctx.k[575] = -_c242  # _k575
    ctx.k[576] = -18.0*_c128  # _k576
    ctx.k[577] = -_c3  # _k577
    ctx.k[578] = -_c84  # _k578
    ctx.k[579] = -4.0*_c75  # _k579
    ctx.k[580] = -24.0*_c245 - 12.0*_c246 - 12.0*_c90  # _k580
    ctx.k[581] = -_c247 - _c248  # _k581
    ctx.k[582] = -_c88  # _k582
    ctx.k[583] = -_c79  # _k583
    ctx.k[584] = -_c97  # _k584
    ctx.k[585] = -8.0*_c182  # _k585
    ctx.k[586] = -_c189  # _k586
    ctx.k[587] = -_c164  # _k587
    ctx.k[588] = -_c249  # _k588
    ctx.k[589] = -60.0*_c172 - 60.0*_c250 - _c251*_c82 - _c251*_c83  # _k589
    ctx.k[590] = -120.0*_c160 - _c252*_c72 - _c252*_c73  # _k590
    ctx.k[591] = -120.0*_c157 - 180.0*_c158 - 120.0*_c170 - _c253*_c66 - _c253*_c67  # _k591
    ctx.k[592] = -_c254*r_b - _c254*r_r  # _k592
    ctx.k[593] = -_c255  # _k593
    ctx.k[594] = -_c176  # _k594
    ctx.k[595] = -_c169  # _k595
    ctx.k[596] = -72.0*_c160 - _c180*_c72 - _c180*_c73  # _k596
    ctx.k[597] = -_c256*r_b - _c256*r_r  # _k597
    ctx.k[598] = _c187  # _k598
    ctx.k[599] = J_r*_c249  # _k599
    ctx.k[600] = _c257  # _k600
    ctx.k[601] = 4.0*_c98  # _k601
    ctx.k[602] = _c189  # _k602
    ctx.k[603] = -8.0*_c245 - 4.0*_c246 - 4.0*_c90  # _k603
    ctx.k[604] = -_c258*r_b - _c258*r_r  # _k604
    ctx.k[605] = _c199  # _k605
    ctx.k[606] = 3.0*_c91  # _k606
    ctx.k[607] = _c200  # _k607
    ctx.k[608] = 6.0*_c185 + _c196  # _k608
    ctx.k[609] = 10.0*_c182  # _k609
    ctx.k[610] = _c259*r_b + _c259*r_r  # _k610
    ctx.k[611] = -J_r*_c255  # _k611
    ctx.k[612] = -_c262  # _k612
    ctx.k[613] = -_c257  # _k613
    ctx.k[614] = -24.0*_c160 - _c263*_c72 - _c263*_c73  # _k614
    ctx.k[615] = -24.0*_c157 - 36.0*_c158 - 24.0*_c170 - _c264*_c66 - _c264*_c67  # _k615
    ctx.k[616] = -24.0*_c172 - 24.0*_c250 - _c265*_c82 - _c265*_c83  # _k616
    ctx.k[617] = -_c267 - _c268  # _k617
    ctx.k[618] = -J_r*_c267 - J_r*_c268  # _k618
    ctx.k[619] = _c193  # _k619
    ctx.k[620] = J_r*_c247*_c72 + J_r*_c248*_c73 + 4.0*_c194 + 4.0*_c195  # _k620
    ctx.k[621] = _c262  # _k621
    ctx.k[622] = _c103  # _k622
    ctx.k[623] = -_c188*_c72 - _c188*_c73 - 16.0*_c260  # _k623
    ctx.k[624] = -4.0*_c100 - 4.0*_c101 - 8.0*_c159*_c98  # _k624
    ctx.k[625] = _c190  # _k625
    ctx.k[626] = -_c269*r_b - _c269*r_r  # _k626
    ctx.k[627] = -8.0*_c184 - 8.0*_c185  # _k627
    ctx.k[628] = _c198  # _k628
    ctx.k[629] = 12.0*_c109  # _k629
    ctx.k[630] = 24.0*_c4  # _k630
    ctx.k[631] = 40.0*_c5  # _k631
    ctx.k[632] = 60.0*_c5  # _k632
    ctx.k[633] = -_c114  # _k633
    ctx.k[634] = -_c204  # _k634
    ctx.k[635] = -_c205  # _k635
    ctx.k[636] = _c206  # _k636
    ctx.k[637] = _c106 + _c92  # _k637
    ctx.k[638] = _c80  # _k638
    ctx.k[639] = -_c80  # _k639
    ctx.k[640] = _c270  # _k640
    ctx.k[641] = -_c270  # _k641
    ctx.k[642] = _c272  # _k642
    ctx.k[643] = _c273  # _k643
    ctx.k[644] = _c274  # _k644
    ctx.k[645] = -_c275  # _k645
    ctx.k[646] = -_c276  # _k646
    ctx.k[647] = _c276  # _k647
    ctx.k[648] = -_c272  # _k648
    ctx.k[649] = -_c273  # _k649
    ctx.k[650] = -_c274  # _k650
    ctx.k[651] = _c275  # _k651
    ctx.k[652] = -_c201  # _k652


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
    cdef double _cam0[5]
    _profile(ctx, theta, beta_r, _cam0, 0)

    cdef double _s0 = (xE*xE*xE)
    cdef double _s1 = m_r*xE
    cdef double _s2 = (xE*xE)
    cdef double _s3 = (xE*xE*xE*xE)
    cdef double _s4 = _k5*_s3*(_k3*_s2 + _k4 + _s1)
    cdef double _s5 = _k6*_s2 + _s1
    cdef double _s6 = (((xE*xE)*(xE*xE))*xE)
    cdef double _s7 = _k8*_s6
    cdef double _s8 = _s7*(_k7 + _s5)
    cdef double _s9 = _k9*_s2 + _s1
    cdef double _s10 = (((xE*xE)*(xE*xE))*(xE*xE))
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
    cdef double _s25 = (((xE*xE)*(xE*xE))*(xE*xE)*xE)
    cdef double _s26 = _k31*_s25
    cdef double _s27 = _s26*(_k30 + _s24)
    cdef double _s28 = _k34*xE + _k35 + _s13
    cdef double _s29 = _k41*_s0*(_k33*b1*(_k21 + _k32*xE + _s19) + _k39*_s21*(_k36*xE + _k37*_s2 + _k38) + _k40*_s15*_s20 + 175.0*_s17*_s28)
    cdef double _s30 = ((((xE*xE)*(xE*xE))*((xE*xE)*(xE*xE))))
    cdef double _s31 = _k45*_s30*(_k43*_s2 + _k44 + _s1)
    cdef double _s32 = _k55*_s3*(_k52*b1*(_k49*xE + _k50*_s2 + _k51) + _k53*_s15*_s16 + _k54*_s21*_s28 + 50.0*_s17*(_k46*xE + _k47*_s2 + _k48))
    cdef double _s33 = ((((xE*xE)*(xE*xE))*((xE*xE)*(xE*xE)))*xE)
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
    cdef double _s162 = (1.0/((((_cam0[0]*_cam0[0])*(_cam0[0]*_cam0[0]))*(_cam0[0]*_cam0[0]))*_k295 + (((_cam0[0]*_cam0[0])*(_cam0[0]*_cam0[0]))*_cam0[0])*_k300 + _cam0[0]*_k299 + _cam0[0]*_k300*_s69 + (((_cam0[1]*_cam0[1])*(_cam0[1]*_cam0[1]))*(_cam0[1]*_cam0[1]))*_k295 + _k294 + _k296*_s65*_s69 + _k296*_s66*_s71 + _k297*_s66 + _k298*_s69 + _k301*_s65 + _k302*_s71 + _k303*_s70 + _k304*_s72 + _k305*_s66*_s70 + _k306*_s73))
    cdef double _s163 = _s153*_s162
    cdef double _s164 = (((_cam0[1]*_cam0[1])*(_cam0[1]*_cam0[1]))*_cam0[1])*_s163
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
    _b[3] = _k137*_s40 + _k203*_s147 + _k204*_s146 + _k205*_s141 + _k206*_s140 + _k207*_s142 + _k207*_s144 + _k208*_s143 + _k209*_s149 + _k210*_s46 + _k211*_s96*((((xE*xE)*(xE*xE))*((xE*xE)*(xE*xE)))*(xE*xE)) + _k212*_s112*_s33*b4 + _k213*_s129*_s33 + _k214*_s136*_s25 + _k215*_s102*_s25 + _k216*_s145*_s30 + _k217*_s111*_s30 + _k218*_s10*_s148 + _k219*_s132 + _k220*_s134 + _k221*_s135 + _k222*_s130 + _k223*_s131 + _k224*_s128 + _k225*_s137 + _s126*b2 + _s139*b3
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
    cdef double _cam0[5]
    _profile(ctx, theta, beta_r, _cam0, 0)

    cdef double _p0 = (xE*xE)
    cdef double _p1 = _k119*_p0
    cdef double _p2 = (xE*xE*xE)
    cdef double _p3 = _k120*_p2
    cdef double _p4 = _k121*(xE*xE*xE*xE)
    cdef double _p5 = _k122*(((xE*xE)*(xE*xE))*xE)
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
    cdef double _cam0[5]
    _profile(ctx, theta, beta_r, _cam0, 0)

    cdef double _o0 = (xE*xE)
    cdef double _o1 = (xE*xE*xE)
    cdef double _o2 = S_T*_cam0[0]
    cdef double _o3 = _k127 + _o2
    cdef double _o4 = Omega*t - theta
    _out[0] = _o0*(_k2*_o0*b3 + _k341*b1 + _k342*b2*xE + _k5*_o1*b4)  # vE
    _out[1] = _k119*_o0*b1 + _k120*_o1*b2 + _k121*b3*(xE*xE*xE*xE) + _k122*b4*(((xE*xE)*(xE*xE))*xE) + _o3*sin(_o4)  # Phi1
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


cdef double _SCALE[_NS]  # typical magnitude of each state (manifest "scale"): the projection's step test
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
    cdef double _cam0[5]
    _profile(ctx, theta, beta_r, _cam0, 1)

    cdef double _j0 = (xE*xE)
    cdef double _j1 = (xEd*xEd)
    cdef double _j2 = _j0*_j1
    cdef double _j3 = (xE*xE*xE)
    cdef double _j4 = _j1*_j3
    cdef double _j5 = _j0*_acc[4]
    cdef double _j6 = _j0*_k14
    cdef double _j7 = _j6 + _k12*xE + _k13
    cdef double _j8 = _j7*_k343
    cdef double _j9 = _j0*_k138
    cdef double _j10 = (xE*xE*xE*xE)
    cdef double _j11 = _j1*_j10
    cdef double _j12 = _j3*_acc[4]
    cdef double _j13 = _j0*_k20
    cdef double _j14 = _j13 + _k19*xE + _k21
    cdef double _j15 = _j14*_k344
    cdef double _j16 = _j3*_k136
    cdef double _j17 = (((xE*xE)*(xE*xE))*xE)
    cdef double _j18 = _j1*_j17
    cdef double _j19 = _k23*xE
    cdef double _j20 = _j0*_k24
    cdef double _j21 = _j19 + _j20 + _k25
    cdef double _j22 = _j10*_acc[4]
    cdef double _j23 = _j21*_j22
    cdef double _j24 = _j10*_k137
    cdef double _j25 = (((xE*xE)*(xE*xE))*(xE*xE))
    cdef double _j26 = _j1*_j25
    cdef double _j27 = _j0*_k17 + _k16*xE + _k18
    cdef double _j28 = _j17*_acc[4]
    cdef double _j29 = _j27*_j28
    cdef double _j30 = _j3*_acc[0]
    cdef double _j31 = _j10*_acc[1]
    cdef double _j32 = _k122*(_k348*xE + m_r)
    cdef double _j33 = b1*xE
    cdef double _j34 = _j1*_k133
    cdef double _j35 = _j17*xEd
    cdef double _j36 = _j35*b4d
    cdef double _j37 = _j2*b1
    cdef double _j38 = _j25*xEd
    cdef double _j39 = _j38*b4d
    cdef double _j40 = _j35*b3d
    cdef double _j41 = _j10*xEd
    cdef double _j42 = _j41*b2d
    cdef double _j43 = _j17*_acc[2]
    cdef double _j44 = _k350*(_k349*xE + m_r)
    cdef double _j45 = _j25*_acc[3]
    cdef double _j46 = _k352*(_k351*xE + m_r)
    cdef double _j47 = _k50*xE
    cdef double _j48 = _k15*b1
    cdef double _j49 = _k355*xE
    cdef double _j50 = _k22*b2
    cdef double _j51 = _k16 + _k353*xE
    cdef double _j52 = _j3*b4
    cdef double _j53 = 0.14285714285714285*_j52
    cdef double _j54 = _k356*xE
    cdef double _j55 = _j54 + _k23
    cdef double _j56 = _j0*b3
    cdef double _j57 = _j56*_k26
    cdef double _j58 = _j14*_j50
    cdef double _j59 = b3*xE
    cdef double _j60 = _j0*b4
    cdef double _j61 = _k352*(_j21*_j59*_k354 + 0.42857142857142855*_j27*_j60 + _j48*(_j47 + _k12) + _j50*xE*(_j49 + _k19) + _j51*_j53 + _j55*_j57 + _j58)
    cdef double _j62 = m_r*xE
    cdef double _j63 = _j0*_k9 + _j62
    cdef double _j64 = _j17*_k357
    cdef double _j65 = _j64*(_j63 + _k10)
    cdef double _j66 = _j10*_acc[2]
    cdef double _j67 = _j0*_k6 + _j62
    cdef double _j68 = _k358*(_j67 + _k7)
    cdef double _j69 = _k359*(_j0*_k3 + _j62 + _k4)
    cdef double _j70 = _j3*_acc[1]
    cdef double _j71 = _j0*_acc[0]
    cdef double _j72 = _k361*xE*(_j21*_j57 + _j27*_j53 + _j48*_j7 + _j58*xE)
    cdef double _j73 = _j11*b4
    cdef double _j74 = _j4*b3
    cdef double _j75 = _j41*b3d
    cdef double _j76 = _j3*xEd
    cdef double _j77 = _j76*b2d
    cdef double _j78 = _j0*xEd
    cdef double _j79 = _j78*b1d
    cdef double _j80 = _j18*b4
    cdef double _j81 = _j11*b3
    cdef double _j82 = _j76*b1d
    cdef double _j83 = _j4*b4
    cdef double _j84 = _j41*b4d
    cdef double _j85 = _j2*b3
    cdef double _j86 = _j76*b3d
    cdef double _j87 = _j78*b2d
    cdef double _j88 = _j3*_k251
    cdef double _j89 = _j0*_k253
    cdef double _j90 = _k254*xE
    cdef double _j91 = _k325*xE
    cdef double _j92 = _j2*b2
    cdef double _j93 = _j4*b2
    cdef double _j94 = b2*xE
    cdef double _j95 = _j1*_k286
    cdef double _j96 = b1d*xE
    cdef double _j97 = _k287*xEd
    cdef double _j98 = _j88*b4 + _j89*b3 + _j90*b2 + _j91*_acc[6] + _j92*_k243 + _j93*_k266 + _j94*_j95 + _j96*_j97 + _k135*b1
    cdef double _j99 = _j0*_k147
    cdef double _j100 = (((xE*xE)*(xE*xE))*(xE*xE)*xE)
    cdef double _j101 = _j100*_k142
    cdef double _j102 = _j25*b4d
    cdef double _j103 = _j17*b3d
    cdef double _j104 = _j10*b2d
    cdef double _j105 = _j3*b1d
    cdef double _j106 = _j10*b1d
    cdef double _j107 = _j17*b2d
    cdef double _j108 = _j25*b3d
    cdef double _j109 = _j17*b4d
    cdef double _j110 = _j10*b3d
    cdef double _j111 = _j3*b2d
    cdef double _j112 = _j0*b1
    cdef double _j113 = _j112*xEd
    cdef double _j114 = _j35*b4
    cdef double _j115 = _j41*b3
    cdef double _j116 = _j35*b3
    cdef double _j117 = _j38*b4
    cdef double _j118 = _j76*b1
    cdef double _j119 = _j41*b4
    cdef double _j120 = _j76*b3
    cdef double _j121 = _j76*b2
    cdef double _j122 = _j41*b2
    cdef double _j123 = _j0*b2
    cdef double _j124 = _j123*_k286
    cdef double _j125 = _j121*_k245 + _j122*_k269 + _j124*xEd
    cdef double _j126 = _j20 + _k21 + _k32*xE
    cdef double _j127 = _j126*_k381
    cdef double _j128 = _j10*_k163
    cdef double _j129 = _j0*_k37 + _k36*xE + _k38
    cdef double _j130 = _j129*_k383
    cdef double _j131 = _j17*_k161
    cdef double _j132 = _j1*_j100
    cdef double _j133 = _j6 + _k34*xE + _k35
    cdef double _j134 = _j25*_acc[4]
    cdef double _j135 = _j133*_j134
    cdef double _j136 = _j10*_acc[0]
    cdef double _j137 = _j17*_j44
    cdef double _j138 = _j25*_j46
    cdef double _j139 = _j63 + _k28
    cdef double _j140 = _j100*_acc[3]
    cdef double _j141 = _k387*(_k386*xE + m_r)
    cdef double _j142 = _j0*_k29 + _j62
    cdef double _j143 = _k388*(_j142 + _k30)
    cdef double _j144 = _k33*b1
    cdef double _j145 = _k40*b2
    cdef double _j146 = _j145*_j21
    cdef double _j147 = 175.0*_j52
    cdef double _j148 = _j56*_k39
    cdef double _j149 = _k389*(_j126*_j144 + _j129*_j148 + _j133*_j147 + _j146*xE)
    cdef double _j150 = _j47 + _k34
    cdef double _j151 = _k392*(_j129*_j59*_k391 + 525.0*_j133*_j60 + _j144*(_j54 + _k32) + _j145*_j55*xE + _j146 + _j147*_j150 + _j148*(_k36 + _k390*xE))
    cdef double _j152 = _j26*b4
    cdef double _j153 = _j100*xEd
    cdef double _j154 = _j153*b4d
    cdef double _j155 = _j38*b3d
    cdef double _j156 = _j11*b2
    cdef double _j157 = _j35*b2d
    cdef double _j158 = _j41*b1d
    cdef double _j159 = _j4*b1
    cdef double _j160 = _j10*_k249
    cdef double _j161 = _j3*_k250
    cdef double _j162 = _j0*_k385
    cdef double _j163 = _j18*b3
    cdef double _j164 = _j123*_k398 + _j160*b4 + _j161*b3 + _j162*_acc[6] + _j163*_k263 + _j74*_k280 + _j79*_k286 + _j81*_k233 + _j90*b1
    cdef double _j165 = ((((xE*xE)*(xE*xE))*((xE*xE)*(xE*xE))))
    cdef double _j166 = _j165*_k169
    cdef double _j167 = _j100*b4d
    cdef double _j168 = _j25*b2d
    cdef double _j169 = _j100*b3d
    cdef double _j170 = _j17*b1d
    cdef double _j171 = _j35*b2
    cdef double _j172 = _j41*b1
    cdef double _j173 = _j153*b4
    cdef double _j174 = _j38*b3
    cdef double _j175 = _j115*_k283 + _j116*_k241 + _j174*_k268
    cdef double _j176 = _j0*_k50 + _k49*xE + _k51
    cdef double _j177 = _j176*_k345
    cdef double _j178 = _j25*_k186
    cdef double _j179 = _j1*_j165
    cdef double _j180 = _j100*_acc[4]
    cdef double _j181 = _j0*_k47 + _k46*xE + _k48
    cdef double _j182 = _j181*_k412
    cdef double _j183 = _j153*b3d
    cdef double _j184 = _j100*_j141
    cdef double _j185 = _j25*_acc[2]
    cdef double _j186 = _j165*_acc[3]
    cdef double _j187 = _k414*(_k1*xE + m_r)
    cdef double _j188 = _k415*(_j0*_k43 + _j62 + _k44)
    cdef double _j189 = _k52*b1
    cdef double _j190 = _k53*b2
    cdef double _j191 = _j190*_j27
    cdef double _j192 = 50.0*_j52
    cdef double _j193 = _j56*_k54
    cdef double _j194 = _k416*(_j133*_j193 + _j176*_j189 + _j181*_j192 + _j191*xE)
    cdef double _j195 = _k419*(_j133*_j59*_k418 + _j150*_j193 + 150.0*_j181*_j60 + _j189*(_k24*xE + _k49) + _j190*_j51*xE + _j191 + _j192*(_k417*xE + _k46))
    cdef double _j196 = _j26*b3
    cdef double _j197 = _j165*xEd
    cdef double _j198 = _j197*b4d
    cdef double _j199 = _j18*b2
    cdef double _j200 = _j38*b2d
    cdef double _j201 = _j35*b1d
    cdef double _j202 = _j11*b1
    cdef double _j203 = _j17*_k248
    cdef double _j204 = _j3*_k413
    cdef double _j205 = _j10*b3
    cdef double _j206 = _j132*b4
    cdef double _j207 = _j152*_k231 + _j161*b2 + _j203*b4 + _j204*_acc[6] + _j205*_k426 + _j206*_k260 + _j80*_k277 + _j82*_k148 + _j89*b1
    cdef double _j208 = ((((xE*xE)*(xE*xE))*((xE*xE)*(xE*xE)))*xE)
    cdef double _j209 = _j208*_k191
    cdef double _j210 = _j165*b4d
    cdef double _j211 = _j165*b3d
    cdef double _j212 = _j100*b2d
    cdef double _j213 = _j25*b1d
    cdef double _j214 = _j38*b2
    cdef double _j215 = _j153*b3
    cdef double _j216 = _j35*b1
    cdef double _j217 = _j197*b4
    cdef double _j218 = _j117*_k279 + _j173*_k237 + _j217*_k267
    cdef double _j219 = _j20 + _k61*xE + _k62
    cdef double _j220 = _j219*_k441
    cdef double _j221 = _j13 + _j19 + _k64
    cdef double _j222 = _j221*_k442
    cdef double _j223 = _j0*_k67 + _k66*xE + _k68
    cdef double _j224 = _j223*_k443
    cdef double _j225 = _j20 + _k59*xE + _k60
    cdef double _j226 = _j225*_k444
    cdef double _j227 = _j18*b1
    cdef double _j228 = _j38*b1d
    cdef double _j229 = _j25*_acc[1]
    cdef double _j230 = _j100*_acc[2]
    cdef double _j231 = _k447*_acc[3]
    cdef double _j232 = _k63*b1
    cdef double _j233 = _k65*b2
    cdef double _j234 = 0.125*_j52
    cdef double _j235 = _j56*_k69
    cdef double _j236 = _j221*_j233
    cdef double _j237 = _j223*_j59*_k449 + 0.375*_j225*_j60 + _j232*(_j54 + _k61) + _j233*xE*(_j49 + _k23) + _j234*(_j54 + _k59) + _j235*(_k448*xE + _k66) + _j236
    cdef double _j238 = _k451*(_j219*_j232 + _j223*_j235 + _j225*_j234 + _j236*xE)
    cdef double _j239 = _j179*b4
    cdef double _j240 = _j132*b3
    cdef double _j241 = _j208*xEd
    cdef double _j242 = _j241*b4d
    cdef double _j243 = _j197*b3d
    cdef double _j244 = _j26*b2
    cdef double _j245 = _j153*b2d
    cdef double _j246 = _j10*_k445
    cdef double _j247 = _j25*b4
    cdef double _j248 = _j158*_k285 + _j160*b2 + _j203*b3 + _j246*_acc[6] + _j247*_k458 + _j88*b1
    cdef double _j249 = _k211*((((xE*xE)*(xE*xE))*((xE*xE)*(xE*xE)))*(xE*xE))
    cdef double _j250 = _j208*b4d
    cdef double _j251 = _j153*b2
    cdef double _j252 = _j197*b3
    cdef double _j253 = _j241*b4
    cdef double _j254 = _j38*b1
    cdef double _j255 = _j3*b1
    cdef double _j256 = _j3*b2
    cdef double _j257 = _j17*b4
    cdef double _j258 = _j10*b2
    cdef double _j259 = _j17*b3
    cdef double _j260 = _j10*_k97
    cdef double _j261 = _j1*b1
    cdef double _j262 = _j1*_j33
    cdef double _j263 = _j17*b2
    cdef double _j264 = _j10*b1
    cdef double _j265 = _j25*b3
    cdef double _j266 = _j100*b4
    cdef double _j267 = _j100*b3
    cdef double _j268 = _j25*b2
    cdef double _j269 = _j165*b4
    cdef double _j270 = _j17*b1
    cdef double _j271 = b1*b2
    cdef double _j272 = (b2*b2)
    cdef double _j273 = _j272*xE
    cdef double _j274 = b2d*xEd
    cdef double _j275 = _j94*xEd
    cdef double _j276 = _j33*b1d
    cdef double _j277 = (b1*b1)
    cdef double _j278 = (b4*b4)
    cdef double _j279 = (b3*b3)
    cdef double _j280 = _k362*b1
    cdef double _j281 = _k367*b1
    cdef double _j282 = _j118*_k371
    cdef double _j283 = _k372*b3
    cdef double _j284 = _j56*xEd
    cdef double _j285 = _k533*b3
    cdef double _j286 = _k537*b2
    cdef double _j287 = _k538*b3
    cdef double _j288 = _k542*b3
    cdef double _j289 = _k543*xEd
    cdef double _j290 = _k560*b3
    cdef double _j291 = _k563*b2
    cdef double _j292 = _k564*b2
    cdef double _j293 = _k566*b1
    cdef double _j294 = _k572*b3
    cdef double _j295 = _k573*b4
    cdef double _j296 = _k575*b3
    cdef double _j297 = _j277*xE
    cdef double _j298 = _j52*_k495 + _j56*_k496 + _j94*_k497 + _k126*b1
    cdef double _j299 = _j33*b2
    cdef double _j300 = _j123*b1
    cdef double _j301 = _j0*_j277
    cdef double _j302 = _j0*_j272
    cdef double _j303 = Omega*t - theta
    cdef double _j304 = cos(_j303)
    cdef double _j305 = _j304*_k327
    cdef double _j306 = S_T*_cam0[0]
    cdef double _j307 = _j306 + _k127
    cdef double _j308 = sin(_j303)
    cdef double _j309 = _j307*_j308
    cdef double _j310 = _cam0[1]*_j305 - _j309
    cdef double _j311 = S_T*_j308
    cdef double _j312 = _j304*_j307
    cdef double _j313 = _cam0[1]*_j311 - _j312
    cdef double _j314 = (_cam0[0]*_cam0[0])
    cdef double _j315 = (_cam0[1]*_cam0[1])
    cdef double _j316 = _cam0[0]*_k111 + _j314*_k110 + _j315*_k110 + _k109
    cdef double _j317 = (1.0/(_j316))
    cdef double _j318 = (thetad*thetad)
    cdef double _j319 = _j317*_j318
    cdef double _j320 = _j319*_k290
    cdef double _j321 = (_cam0[0]*_cam0[0]*_cam0[0])
    cdef double _j322 = (_cam0[0]*_cam0[0]*_cam0[0]*_cam0[0])
    cdef double _j323 = (_cam0[1]*_cam0[1]*_cam0[1]*_cam0[1])
    cdef double _j324 = _cam0[0]*_j315
    cdef double _j325 = _j314*_j315
    cdef double _j326 = _cam0[0]*_k105 + _j314*_k107 + _j315*_k104 + _j321*_k106 + _j322*_k102 + _j323*_k102 + _j324*_k106 + _j325*_k103 + _k101
    cdef double _j327 = (1.0/(_j326))
    cdef double _j328 = _cam0[2]*_j327
    cdef double _j329 = _j318*_k312
    cdef double _j330 = _cam0[0]*_j328
    cdef double _j331 = _j318*_k117
    cdef double _j332 = _j315*_j327
    cdef double _j333 = _j318*_j332
    cdef double _j334 = _j324*_j327
    cdef double _j335 = _j318*_j334
    cdef double _j336 = _j314*_j328
    cdef double _j337 = _j318*_k310
    cdef double _j338 = _j317*_k114
    cdef double _j339 = _cam0[1]*_j317
    cdef double _j340 = _j318*_k292
    cdef double _j341 = _j318*_k316
    cdef double _j342 = _cam0[1]*_j327
    cdef double _j343 = _cam0[3]*_j327
    cdef double _j344 = (_cam0[1]*_cam0[1]*_cam0[1])
    cdef double _j345 = _j327*_j344
    cdef double _j346 = _j318*_j345
    cdef double _j347 = (((_cam0[0]*_cam0[0])*(_cam0[0]*_cam0[0]))*_cam0[0])
    cdef double _j348 = _cam0[0]*_j323
    cdef double _j349 = _j315*_j321
    cdef double _j350 = (((_cam0[0]*_cam0[0])*(_cam0[0]*_cam0[0]))*(_cam0[0]*_cam0[0]))*_k295 + _cam0[0]*_k299 + (((_cam0[1]*_cam0[1])*(_cam0[1]*_cam0[1]))*(_cam0[1]*_cam0[1]))*_k295 + _j314*_j323*_k296 + _j314*_k301 + _j315*_j322*_k296 + _j315*_k297 + _j321*_k303 + _j322*_k302 + _j323*_k298 + _j324*_k304 + _j325*_k306 + _j347*_k300 + _j348*_k300 + _j349*_k305 + _k294
    cdef double _j351 = (1.0/(_j350))
    cdef double _j352 = _j318*_j351
    cdef double _j353 = _j344*_j352
    cdef double _j354 = _j318*_j327
    cdef double _j355 = _cam0[0]*_cam0[1]
    cdef double _j356 = _j355*_k320
    cdef double _j357 = _cam0[0]*_j318
    cdef double _j358 = _j357*_k117
    cdef double _j359 = _cam0[0]*_j344
    cdef double _j360 = _j352*_j359
    cdef double _j361 = _cam0[1]*_j328
    cdef double _j362 = _cam0[1]*_k620
    cdef double _j363 = _cam0[2]*_j352
    cdef double _j364 = _cam0[1]*_j314
    cdef double _j365 = _j364*_k116
    cdef double _j366 = _j314*_j344
    cdef double _j367 = _j366*_k313
    cdef double _j368 = _j328*_k116
    cdef double _j369 = _j318*_j368
    cdef double _j370 = _j355*_k621
    cdef double _j371 = _cam0[1]*_j321
    cdef double _j372 = _j371*_k598
    cdef double _j373 = _j364*_k600
    cdef double _j374 = (((_cam0[1]*_cam0[1])*(_cam0[1]*_cam0[1]))*_cam0[1])
    cdef double _j375 = _j352*_k307
    cdef double _j376 = (_cam0[2]*_cam0[2])
    cdef double _j377 = _j352*_j376
    cdef double _j378 = _j377*_k322
    cdef double _j379 = _cam0[2]*_k319
    cdef double _j380 = _cam0[2]*_k585
    cdef double _j381 = _cam0[1]*_j378 + _j353*_j379 + _j355*_j377*_k600 + _j360*_j380 + _j364*_j377*_k599 + _j374*_j375
    cdef double _j382 = _cam0[2]*_j338
    cdef double _j383 = (1.0/(_j316*_j316))
    cdef double _j384 = _j383*(_cam0[0]*_k583 + _k584)
    cdef double _j385 = _cam0[2]*_j384
    cdef double _j386 = _j327*_j376
    cdef double _j387 = _cam0[0]*_j386
    cdef double _j388 = (1.0/(_j326*_j326))
    cdef double _j389 = _j388*(_cam0[0]*_k580 + _j314*_k581 + _j315*_k582 + _j321*_k579 + _j324*_k579 + _k578)
    cdef double _j390 = _j323*_k108
    cdef double _j391 = _j376*_k113
    cdef double _j392 = _j376*_j389
    cdef double _j393 = _cam0[0]*_k118
    cdef double _j394 = _cam0[2]*_j315
    cdef double _j395 = _j394*_k117
    cdef double _j396 = _cam0[2]*_j389
    cdef double _j397 = _j324*_k116
    cdef double _j398 = _j314*_k108
    cdef double _j399 = _j308*_k327
    cdef double _j400 = S_T*_j304
    cdef double _j401 = _j328*_k320
    cdef double _j402 = _cam0[1]*_j401
    cdef double _j403 = _j318*_j386
    cdef double _j404 = (_cam0[2]*_cam0[2]*_cam0[2])
    cdef double _j405 = _j352*_j404
    cdef double _j406 = _j405*_k321
    cdef double _j407 = _cam0[3]*_j318
    cdef double _j408 = _j407*_k117
    cdef double _j409 = _j318*_j389
    cdef double _j410 = _j344*_k118
    cdef double _j411 = _cam0[0]*_k591 + _j314*_k589 + _j315*_k594 + _j321*_k590 + _j322*_k592 + _j323*_k595 + _j324*_k596 + _j325*_k597 + _j347*_k588 + _j348*_k588 + _j349*_k593 + _k587
    cdef double _j412 = (1.0/(_j350*_j350))
    cdef double _j413 = _j374*_j412
    cdef double _j414 = _j411*_j413
    cdef double _j415 = _j318*_k308
    cdef double _j416 = _j328*_j355
    cdef double _j417 = _j416*_k586
    cdef double _j418 = _cam0[3]*_j357
    cdef double _j419 = _j359*_k293
    cdef double _j420 = _j414*_k307
    cdef double _j421 = _cam0[1]*_j341
    cdef double _j422 = _cam0[1]*_j318
    cdef double _j423 = _j422*_k311
    cdef double _j424 = _j411*_j412
    cdef double _j425 = _j376*_j424
    cdef double _j426 = _j422*_k317
    cdef double _j427 = _j318*_j424
    cdef double _j428 = _cam0[1]*_j404
    cdef double _j429 = _j428*_k318
    cdef double _j430 = _cam0[3]*_j329
    cdef double _j431 = _cam0[2]*_j344
    cdef double _j432 = _j431*_k108
    cdef double _j433 = _cam0[2]*_j318
    cdef double _j434 = _j431*_k314
    cdef double _j435 = _j389*_j407
    cdef double _j436 = _j315*_k309
    cdef double _j437 = _j318*_j425
    cdef double _j438 = _j344*_k315
    cdef double _j439 = _cam0[2]*_j409
    cdef double _j440 = _j337*_j355
    cdef double _j441 = _j404*_j427
    cdef double _j442 = _cam0[3]*_j358
    cdef double _j443 = _j359*_j379
    cdef double _j444 = _j324*_k108
    cdef double _j445 = _j359*_k313
    cdef double _j446 = _j364*_k307
    cdef double _j447 = _j371*_k307
    cdef double _j448 = _j364*_k323
    cdef double _j449 = _j314*_j407*_k310
    cdef double _j450 = _j355*_k116
    cdef double _j451 = _cam0[2]*_j383
    cdef double _j452 = _j315*_j318
    cdef double _j453 = _j318*_j355
    cdef double _j454 = _j388*(_cam0[1]*_k603 + _j344*_k579 + _j355*_k604 + _j364*_k579)
    cdef double _j455 = _cam0[2]*_j454
    cdef double _j456 = _j318*_j454
    cdef double _j457 = _cam0[2]*_j456
    cdef double _j458 = _j376*_j454
    cdef double _j459 = _j407*_j454
    cdef double _j460 = _j323*_j352
    cdef double _j461 = _cam0[1]*_j322*_k588 + _cam0[1]*_k615 + _j344*_k614 + _j355*_k616 + _j359*_k617 + _j364*_k596 + _j366*_k593 + _j371*_k617 + _j374*_k588
    cdef double _j462 = _j413*_j461
    cdef double _j463 = _j462*_k307
    cdef double _j464 = _j412*_j461
    cdef double _j465 = _j376*_j464
    cdef double _j466 = _j318*_j464
    cdef double _j467 = _j318*_j465
    cdef double _j468 = _j345*_k602
    cdef double _j469 = _cam0[3]*thetad
    cdef double _j470 = _j317*_j469
    cdef double _j471 = _cam0[1]*thetad
    cdef double _j472 = _j345*thetad
    cdef double _j473 = _j351*thetad
    cdef double _j474 = _j374*_j473
    cdef double _j475 = _j474*_k598
    cdef double _j476 = _j376*_j473
    cdef double _j477 = _j404*_j473
    cdef double _j478 = _j1*_k331
    cdef double _j479 = _k330*xEd
    cdef double _j480 = xE*xEd
    cdef double _j481 = _j76*_k631
    cdef double _j482 = _cam0[0]*_j304
    cdef double _j483 = _j304*thetad
    cdef double _j484 = _j482*thetad
    cdef double _j485 = _k336*thetad
    cdef double _j486 = _j308*_j485
    cdef double _j487 = _j304*_j318
    cdef double _j488 = _j318*_j400
    cdef double _j489 = _j305*_j318
    cdef double _j490 = _j308*_j318
    cdef double _j491 = _j318*_j399
    cdef double _j492 = _j487*_k329
    cdef double _j493 = _j304*_j485
    cdef double _j494 = _j399*_acc[5] + _j493
    cdef double _j495 = _j308*_k326
    cdef double _j496 = _j0*_k331
    cdef double _j497 = _j3*b3d
    cdef double _j498 = _j10*b4d
    cdef double _j499 = _j308*_k328
    cdef double _j500 = _cam0[0]*_j308
    cdef double _j501 = _cam0[1]*_k336
    cdef double _j502 = _j308*thetad
    cdef double _j503 = _j500*thetad
    cdef double _j504 = _cam0[1]*_j483
    cdef double _j505 = _cam0[2]*_k337
    cdef double _j506 = _cam0[1]*_j502
    cdef double _j507 = _j304*_k640
    cdef double _j508 = Omega*_j309
    cdef double _j509 = _cam0[1]*_j507 + _j508
    cdef double _j510 = _j308*_k641
    cdef double _j511 = Omega*_j312
    cdef double _j512 = _cam0[1]*_j510 + _j511
    cdef double _j513 = _j0*_k125
    cdef double _j514 = _j311*thetad
    _R[0] = _j2*_k134 + _j4*_k146 + _j5*_j8 + _k135*xE
    _R[1] = _j11*_k145 + _j12*_j15 + _j2*_k153 + _j4*_k132 + _j9
    _R[2] = _j11*_k129 + _j16 + _j18*_k140 + _j23*_k345 + _j4*_k148
    _R[3] = _j11*_k152 + _j18*_k128 + _j24 + _j26*_k141 + _j29*_k346
    _R[4] = _j30*_k121*(_k347*xE + m_r) + _j31*_j32 + _j33*_j34 + _j36*_k233 + _j37*_k255 + _j39*_k264 + _j40*_k265 + _j42*_k266 + _j43*_j44 + _j45*_j46 + _j5*_j61 + _j65*_acc[3] + _j66*_j68 + _j69*_j70 + _j71*_k360*(_j0*_k1 + _j62 + _k0) + _j72*_acc[4] + _j73*_k362 + _j74*_k363 + _j75*_k364 + _j77*_k365 + _j79*_k366 + _j80*_k367 + _j81*_k368 + _j82*_k369 + _j83*_k370 + _j84*_k371 + _j85*_k372 + _j86*_k372 + _j87*_k373 + _j98
    _R[5] = 0.0
    _R[6] = _j41*_k139 + _j76*_k133 + _j99*xEd
    _R[7] = _j35*_k143 + _j41*_k132 + _j76*_k151
    _R[8] = _j35*_k131 + _j38*_k144 + _j41*_k150
    _R[9] = _j101*xEd + _j35*_k149 + _j38*_k130
    _R[10] = _j101*b4d + _j102*_k130 + _j103*_k131 + _j104*_k132 + _j105*_k133 + _j106*_k139 + _j107*_k143 + _j108*_k144 + _j109*_k149 + _j110*_k150 + _j111*_k151 + _j113*_k133 + _j114*_k374 + _j115*_k375 + _j116*_k376 + _j117*_k377 + _j118*_k378 + _j119*_k379 + _j120*_k380 + _j125 + _j99*b1d
    _R[11] = 0.0
    _R[12] = _j11*_k171 + _j12*_j127 + _j4*_k160 + _j9
    _R[13] = _j11*_k158 + _j18*_k168 + _j23*_k382 + _j3*_k162 + _j4*_k178
    _R[14] = _j11*_k176 + _j128 + _j130*_j28 + _j18*_k155 + _j26*_k165
    _R[15] = _j131 + _j132*_k166 + _j135*_k384 + _j18*_k173 + _j26*_k154
    _R[16] = _j12*_j151 + _j136*_j32 + _j137*_acc[1] + _j138*_acc[2] + _j139*_j43*_k357 + _j140*_j141 + _j143*_j45 + _j149*_j5 + _j152*_k399 + _j154*_k400 + _j155*_k401 + _j156*_k402 + _j157*_k402 + _j158*_k403 + _j159*_k404 + _j164 + _j30*_j69 + _j31*_k358*(_j67 + _k27) + _j36*_k278 + _j37*_k132 + _j39*_k394 + _j40*_k395 + _j42*_k396 + _j73*_k405 + _j75*_k280 + _j77*_k406 + _j80*_k393 + _j82*_k397 + _j92*_k275 + _j93*_k375
    _R[17] = 0.0
    _R[18] = _j35*_k170 + _j41*_k159 + _j76*_k172
    _R[19] = _j35*_k158 + _j38*_k164 + _j41*_k177
    _R[20] = _j153*_k167 + _j35*_k175 + _j38*_k157
    _R[21] = _j153*_k156 + _j166*xEd + _j38*_k174
    _R[22] = _j102*_k174 + _j103*_k175 + _j104*_k177 + _j105*_k172 + _j106*_k159 + _j107*_k158 + _j108*_k157 + _j114*_k261 + _j117*_k407 + _j118*_k159 + _j121*_k150 + _j122*_k129 + _j166*b4d + _j167*_k156 + _j168*_k164 + _j169*_k167 + _j170*_k170 + _j171*_k140 + _j172*_k408 + _j173*_k409 + _j175
    _R[23] = 0.0
    _R[24] = _j11*_k185 + _j16 + _j177*_j22 + _j18*_k195
    _R[25] = _j11*_k202 + _j128 + _j18*_k183 + _j26*_k188 + _j29*_k410
    _R[26] = _j132*_k190 + _j135*_k411 + _j17*_k187 + _j18*_k200 + _j26*_k180
    _R[27] = _j132*_k179 + _j178 + _j179*_k193 + _j180*_j182 + _j26*_k197
    _R[28] = _j12*_j194 + _j136*_j68 + _j137*_acc[0] + _j138*_acc[1] + _j139*_j64*_acc[1] + _j140*_j188 + _j154*_k420 + _j155*_k422 + _j156*_k424 + _j157*_k423 + _j158*_k425 + _j159*_k131 + _j163*_k421 + _j183*_k252 + _j184*_acc[2] + _j185*_k388*(_j142 + _k42) + _j186*_j187 + _j195*_j22 + _j196*_k427 + _j198*_k428 + _j199*_k429 + _j200*_k429 + _j201*_k430 + _j202*_k431 + _j207 + _j39*_k432 + _j40*_k433 + _j42*_k434 + _j81*_k433 + _j93*_k435
    _R[29] = 0.0
    _R[30] = _j35*_k184 + _j38*_k194 + _j41*_k196
    _R[31] = _j153*_k192 + _j35*_k201 + _j38*_k183
    _R[32] = _j153*_k182 + _j197*_k189 + _j38*_k198
    _R[33] = _j153*_k199 + _j197*_k181 + _j209*xEd
    _R[34] = _j106*_k196 + _j107*_k201 + _j108*_k198 + _j116*_k440 + _j122*_k439 + _j167*_k199 + _j168*_k183 + _j169*_k182 + _j170*_k184 + _j171*_k155 + _j172*_k184 + _j174*_k436 + _j209*b4d + _j210*_k181 + _j211*_k189 + _j212*_k192 + _j213*_k194 + _j214*_k165 + _j215*_k437 + _j216*_k438 + _j218
    _R[35] = 0.0
    _R[36] = _j18*_k209 + _j220*_j28 + _j24 + _j26*_k218
    _R[37] = _j131 + _j132*_k214 + _j134*_j222 + _j18*_k225 + _j26*_k207
    _R[38] = _j132*_k204 + _j178 + _j179*_k216 + _j180*_j224 + _j26*_k220
    _R[39] = _j1*_j208*_k212 + _j100*_k210 + _j132*_k221 + _j165*_j226*_acc[4] + _j179*_k203
    _R[40] = _j138*_acc[0] + _j143*_j229 + _j152*_k464 + _j154*_k259 + _j155*_k465 + _j156*_k467 + _j157*_k466 + _j163*_k465 + _j165*_j187*_acc[2] + _j183*_k455 + _j184*_acc[1] + _j186*_k450*(_j0*_k56 + _j62 + _k57) + _j188*_j230 + _j196*_k454 + _j198*_k453 + _j199*_k457 + _j200*_k456 + _j201*_k241 + _j202*_k130 + _j206*_k452 + _j208*_j231*(_k446*xE + m_r) + _j22*_j238 + _j227*_k165 + _j228*_k268 + _j237*_j28*_k447 + _j239*_k459 + _j240*_k460 + _j242*_k461 + _j243*_k462 + _j244*_k463 + _j245*_k463 + _j248 + _j65*_acc[0]
    _R[41] = 0.0
    _R[42] = _j153*_k215 + _j35*_k219 + _j38*_k208
    _R[43] = _j153*_k207 + _j197*_k217 + _j38*_k224
    _R[44] = _j153*_k222 + _j197*_k206 + _j241*_k213
    _R[45] = _j197*_k223 + _j241*_k205 + _j249*xEd
    _R[46] = _j100*_k215*b1d + _j165*_k217*b2d + _j168*_k224 + _j169*_k222 + _j170*_k219 + _j171*_k473 + _j173*_k474 + _j174*_k197 + _j208*_k213*b3d + _j210*_k223 + _j211*_k206 + _j212*_k207 + _j213*_k208 + _j214*_k180 + _j215*_k469 + _j216*_k208 + _j217*_k468 + _j249*b4d + _j250*_k205 + _j251*_k190 + _j252*_k470 + _j253*_k471 + _j254*_k472
    _R[47] = 0.0
    _R[48] = _j127*_j70 + _j17*_j220*_acc[3] + _j177*_j66 + _j261*_k147 + _j262*_k246 + _j36*_k128 + _j37*_k369 + _j39*_k141 + _j40*_k274 + _j42*_k269 + _j71*_j8 + _j73*_k235 + _j74*_k238 + _j75*_k244 + _j77*_k245 + _j79*_k246 + _j80*_k264 + _j81*_k265 + _j82*_k276 + _j83*_k282 + _j84*_k285 + _j85*_k284 + _j86*_k148 + _j87*_k286 + _j98 - _acc[4]*(_j112*_k475 + _j123*_k95 + _j205*_k76 + _j247*_k90 + _j255*_k476 + _j256*_k75 + _j257*_k77 + _j258*_k86 + _j259*_k91 + _j260*b4 + _j3*_k96*b3 + _j33*_k477)
    _R[49] = _j15*_j30 + _j152*_k262 + _j154*_k272 + _j155*_k268 + _j156*_k482 + _j157*_k273 + _j158*_k269 + _j159*_k266 + _j164 + _j21*_j31*_k382 + _j222*_j45 + _j27*_j43*_k410 + _j33*_j95 + _j36*_k281 + _j37*_k243 + _j39*_k240 + _j40*_k241 + _j42*_k229 + _j73*_k278 + _j75*_k283 + _j77*_k284 + _j80*_k232 + _j82*_k245 + _j92*_k406 + _j93*_k481 - _acc[4]*(_j112*_k95 + _j205*_k98 + _j247*_k79 + _j255*_k75 + _j256*_k480 + _j257*_k99 + _j258*_k478 + _j259*_k78 + _j263*_k479 + _j264*_k86 + _j265*_k88 + _j266*_k92)
    _R[50] = _j130*_j17*_acc[1] + _j133*_j185*_k411 + _j136*_j21*_k345 + _j140*_j224 + _j154*_k237 + _j155*_k239 + _j156*_k233 + _j157*_k241 + _j158*_k244 + _j159*_k238 + _j163*_k486 + _j183*_k271 + _j196*_k487 + _j198*_k267 + _j199*_k263 + _j200*_k268 + _j201*_k274 + _j202*_k265 + _j207 + _j37*_k284 + _j39*_k279 + _j40*_k289 + _j42*_k283 + _j81*_k488 + _j93*_k280 - _acc[4]*(_j247*_k100 + _j255*_k96 + _j258*_k98 + _j259*_k485 + _j263*_k78 + _j264*_k76 + _j265*_k483 + _j266*_k80 + _j267*_k484 + _j268*_k88 + _j269*_k89 + _j270*_k91)
    _R[51] = _j133*_j229*_k384 + _j152*_k494 + _j154*_k288 + _j155*_k279 + _j156*_k278 + _j157*_k281 + _j159*_k282 + _j163*_k277 + _j17*_j27*_k346*_acc[0] + _j182*_j230 + _j183*_k237 + _j186*_j226 + _j196*_k231 + _j198*_k236 + _j199*_k232 + _j200*_k240 + _j201*_k128 + _j202*_k235 + _j206*_k492 + _j227*_k264 + _j228*_k141 + _j239*_k493 + _j240*_k260 + _j242*_k270 + _j243*_k267 + _j244*_k262 + _j245*_k272 + _j248 - _acc[4]*(_j100*_k92*b2 + _j165*_k89*b3 + _j208*_k490*b4 + _j25*_k90*b1 + _j260*b1 + _j263*_k99 + _j265*_k100 + _j266*_k491 + _j267*_k80 + _j268*_k79 + _j269*_k489 + _j270*_k77)
    _R[52] = _j0*_j149*_acc[1] + _j1*_j273*_k406 + _j1*_j297*_k369 + _j10*_j238*_acc[3] + _j11*_j279*_k527 + _j112*_k550*b4 + _j113*_k372*b3d + _j113*_k543*b2d + _j113*_k568*b1d + _j114*_k367*b1d + _j114*_k537*b2d + _j115*_k566*b1d + _j116*_k564*b2d + _j117*_k533*b3d + _j117*_k563*b2d + _j119*_k362*b1d + _j123*_j274*_k576 + _j123*_j289*b1d + _j123*_k548*b3 + _j132*_j278*_k547 + _j151*_j70 + _j152*_k554*b3 + _j154*_j290 + _j154*_k531*b4 + _j155*_k562*b3 + _j17*_j231*_j237 + _j17*_j278*_k532 + _j173*_k560*b3d + _j18*_j278*_k553 + _j18*_j279*_k549 + _j194*_j3*_acc[2] + _j195*_j66 + _j198*_k559*b4 + _j2*_j271*_k565 + _j2*_j272*_k528 + _j205*_k545*b4 + _j256*_k546*b4 + _j26*_j278*_k526 + _j261*_k286*b2 + _j262*_j283 + _j262*_k543*b2 + _j271*_k254 + _j272*_j4*_k551 + _j273*_k398 + _j274*_j33*_k373 + _j275*_k373*b1d + _j276*_k544*xEd + _j277*_j34 + _j279*_j3*_k540 + _j279*_j4*_k556 + _j280*_j84 + _j281*_j36 + _j282*b4d + _j284*_k372*b1d + _j285*_j39 + _j286*_j36 + _j287*_j42 + _j288*_j82 + _j291*_j39 + _j292*_j40 + _j293*_j75 + _j294*_j36 + _j295*_j42 + _j296*_j77 - _j298*_acc[6] + _j33*_k552*b3 + _j37*_k370*b4 + _j37*_k539*b3 + _j39*_k570*b4 + _j40*_k536*b3 + _j40*_k572*b4 + _j42*_k551*b2 + _j61*_j71 + _j72*_acc[0] + _j73*_k530*b2 + _j73*_k558*b1 + _j73*_k569*b3 + _j74*_k561*b1 + _j75*_k538*b2 + _j75*_k556*b3 + _j77*_k541*b2 + _j77*_k567*b1 + _j80*_k529*b3 + _j80*_k555*b2 + _j81*_k557*b2 + _j82*_k371*b4 + _j82*_k567*b2 + _j83*_k535*b1 + _j84*_k573*b2 + _j86*_k542*b1 + _j86*_k575*b2 + _j92*_k574*b3 + _j93*_k534*b3 + _j93*_k571*b4 + _j97*b1*b1d - _acc[4]*(_j10*_j272*_k508 + _j10*_j279*_k517 + _j100*_j278*_k500 + _j112*_k521*b3 + _j165*_j278*_k510 + _j17*_j279*_k499 + _j205*_k504*b2 + _j205*_k513*b1 + _j247*_k506*b3 + _j247*_k516*b2 + _j25*_j278*_k519 + _j25*_j279*_k509 + _j255*_k502*b3 + _j255*_k512*b2 + _j255*_k522*b4 + _j256*_k523*b3 + _j257*_k505*b2 + _j257*_k514*b1 + _j257*_k525*b3 + _j258*_k524*b4 + _j259*_k515*b2 + _j264*_k503*b4 + _j266*_k518*b3 + _j272*_j3*_k498 + _j277*_k85 + _j297*_k475 + _j299*_k520 + _j300*_k501 + _j301*_k507 + _j302*_k511 + _k14)
    _R[53] = 0.0
    _R[54] = _j113*_k246 + _j114*_k128 + _j115*_k244 + _j116*_k274 + _j117*_k141 + _j118*_k276 + _j119*_k285 + _j120*_k148 + _j125 + _j33*_j97
    _R[55] = _j113*_k286 + _j114*_k281 + _j117*_k240 + _j118*_k245 + _j121*_k284 + _j122*_k229 + _j171*_k273 + _j172*_k269 + _j173*_k272 + _j175
    _R[56] = _j116*_k289 + _j118*_k148 + _j122*_k283 + _j171*_k241 + _j172*_k244 + _j174*_k239 + _j214*_k268 + _j215*_k271 + _j216*_k274 + _j218
    _R[57] = _j171*_k281 + _j172*_k285 + _j173*_k288 + _j174*_k279 + _j214*_k240 + _j215*_k237 + _j216*_k128 + _j217*_k236 + _j251*_k272 + _j252*_k267 + _j253*_k270 + _j254*_k141
    _R[58] = _j102*_k141*b1 + _j102*_k240*b2 + _j102*_k279*b3 + _j103*_k241*b2 + _j103*_k274*b1 + _j103*_k289*b3 + _j104*_k229*b2 + _j104*_k269*b1 + _j104*_k283*b3 + _j105*_k148*b3 + _j105*_k245*b2 + _j105*_k276*b1 + _j106*_k244*b3 + _j106*_k269*b2 + _j106*_k285*b4 + _j107*_k241*b3 + _j107*_k273*b2 + _j107*_k281*b4 + _j108*_k239*b3 + _j108*_k268*b2 + _j108*_k279*b4 + _j109*_k128*b1 + _j109*_k281*b2 + _j110*_k244*b1 + _j110*_k283*b2 + _j111*_k245*b1 + _j111*_k284*b2 + _j112*_k246*b1d + _j112*_k286*b2d + _j113*_j283 + _j114*_j281 + _j114*_j286 + _j114*_j294 + _j115*_j293 + _j116*_j292 + _j117*_j285 + _j117*_j291 + _j118*_j288 + _j119*_j280 + _j121*_j296 + _j122*_j287 + _j122*_j295 + _j124*b1d + _j153*_j278*_k492 + _j167*_k237*b3 + _j167*_k272*b2 + _j167*_k288*b4 + _j168*_k240*b4 + _j168*_k268*b3 + _j169*_k237*b4 + _j169*_k271*b3 + _j170*_k128*b4 + _j170*_k274*b3 + _j173*_j290 + _j197*_j278*_k493 + _j210*_k236*b4 + _j210*_k267*b3 + _j211*_k267*b4 + _j212*_k272*b4 + _j213*_k141*b4 + _j250*_k270*b4 + _j255*_k148*b3d + _j264*_k285*b4d + _j271*_j76*_k567 + _j272*_j41*_k482 + _j272*_j76*_k481 + _j276*_k287 + _j277*_k147*xEd + _j278*_j38*_k494 + _j279*_j35*_k486 + _j279*_j38*_k487 + _j279*_j41*_k488 + _j282*b4 + _j289*_j300 + _j297*_k246*xEd + _j299*_k373*xEd + _j301*_k369*xEd + _j302*_k406*xEd + _k577*xEd
    _R[59] = 0.0
    _R[60] = 0.0
    _R[61] = 0.0
    _R[62] = 0.0
    _R[63] = 0.0
    _R[64] = 0.0
    _R[65] = _cam0[1]*(_cam0[1]*_j340*_j385 + _cam0[1]*_j403*_k310 + _cam0[1]*_j406 + _cam0[2]*_j367*_j427 + _cam0[3]*_j320 + _cam0[3]*_j333*_k108 + _j318*_j402 + _j318*_j417 + _j328*_j408 + _j344*_j377*_k313 + _j346*_k293 + _j355*_j405*_k598 + _j355*_j437*_k322 + _j355*_j441*_k321 + _j356*_j439 + _j357*_j420 + _j365*_j439 + _j368*_j418 + _j381 + _j384*_j407*_k291 + _j384*_j418*_k290 + _j392*_j423 + _j392*_j440 + _j396*_j421 + _j396*_j430 + _j396*_j442 + _j396*_j449 + _j399*_acc[7] + _j400*_acc[6] + _j409*_j410 + _j409*_j419 + _j409*_j432 + _j414*_j415 + _j420*_j433 + _j425*_j426 + _j427*_j429 + _j427*_j434 + _j427*_j443 + _j435*_j436 + _j435*_j444 + _j437*_j438 + _j437*_j445 + _j437*_j447 + _j437*_j448 + _j441*_j446 - _acc[5]*(_cam0[0]*_j385*_k114 + _j315*_j368 + _j315*_j384*_k112 + _j382 + _j385*_k115 + _j386*_k118 + _j387*_k293 + _j389*_j390 + _j389*_j391 + _j389*_j395 + _j392*_j393 + _j392*_j398 + _j396*_j397)) + _cam0[2]*(_cam0[0]*_j378 + _cam0[0]*_j406 + _cam0[1]*_j383*_j408 + _cam0[2]*_j319*_k292 + _cam0[2]*_j460*_k609 + _j305*_acc[7] + _j314*_j369 + _j314*_j375*_j404 + _j314*_j377*_k323 + _j315*_j377*_k613 + _j321*_j375*_j376 + _j324*_j363*_k618 + _j324*_j377*_k611 + _j325*_j363*_k611 + _j328*_j341 + _j328*_j452*_k606 + _j333*_k608 + _j335*_k607 + _j337*_j387 + _j342*_j407*_k118 + _j343*_j453*_k293 + _j348*_j352*_k609 + _j352*_j394*_k612 + _j356*_j457 + _j357*_j401 + _j357*_j463 + _j365*_j457 + _j367*_j433*_j464 + _j377*_k317 + _j383*_j407*_j450 + _j399*_acc[6] + _j403*_k311 + _j404*_j446*_j466 + _j404*_j453*_j464*_k321 + _j405*_k318 + _j410*_j456 + _j415*_j462 + _j419*_j456 + _j421*_j455 + _j423*_j458 + _j426*_j465 + _j429*_j466 + _j430*_j455 + _j432*_j456 + _j433*_j463 + _j434*_j466 + _j436*_j459 + _j438*_j467 + _j440*_j458 + _j442*_j455 + _j443*_j466 + _j444*_j459 + _j445*_j467 + _j447*_j467 + _j448*_j467 + _j449*_j455 + _j451*_j452*_k293 + _j453*_j465*_k322 + _j460*_k610 - _acc[5]*(_cam0[1]*_j451*_k605 + _j339*_k601 + _j344*_j383*_k586 + _j355*_j451*_k602 + _j390*_j454 + _j391*_j454 + _j393*_j458 + _j395*_j454 + _j397*_j455 + _j398*_j458 + _j402 + _j417 + _j468)) + _cam0[3]*(_j314*_j337*_j343 + _j329*_j343 + _j331*_j361 + _j339*_j340 + _j341*_j342 + _j343*_j358 + _j346*_k108 + _j352*_j367 + _j353*_k314 + _j354*_j356 + _j354*_j365 + _j355*_j369 + _j360*_k319 + _j362*_j363 + _j363*_j370 + _j363*_j372 + _j363*_j373 + _j381 - _acc[5]*(_cam0[0]*_j338 + _j317*_k115 + _j328*_k619 + _j330*_k605 + _j332*_k117 + _j334*_k116 + _j336*_k293)) + _cam0[4]*(_cam0[0]*_j320 + _j319*_k291 + _j328*_j329 + _j330*_j331 + _j333*_k309 + _j335*_k108 + _j336*_j337) - _j310*_acc[6] - _j313*_acc[7]
    _R[66] = 0.0
    _R[67] = 0.0
    _R[68] = 0.0
    _R[69] = 0.0
    _R[70] = 0.0
    _R[71] = _cam0[0]*_j401*_j469 + _cam0[0]*_j468*thetad + _cam0[0]*_j470*_k112 + _cam0[0]*_j475 + _cam0[2]*_j359*_j473*_k626 + _cam0[2]*_j472*_k293 + _cam0[2]*_j475 + _j314*_j368*_j469 + _j328*_j364*_k586*thetad + _j328*_j469*_k316 + _j332*_j469*_k118 + _j334*_j469*_k293 + _j344*_j476*_k319 + _j355*_j477*_k628 + _j359*_j476*_k585 + _j361*_k624*thetad + _j362*_j476 + _j364*_j477*_k598 + _j366*_j380*_j473 + _j370*_j476 + _j372*_j476 + _j373*_j476 + _j382*_j471 + _j386*_j450*thetad + _j386*_j471*_k117 + _j416*_k627*thetad + _j428*_j473*_k625 + _j431*_j473*_k623 + _j470*_k622 + _j472*_k605 + _j474*_k321
    _R[72] = _j1*_k325 + _j91*_acc[4]
    _R[73] = _j162*_acc[4] + _j478*xE
    _R[74] = _j2*_k334 + _j204*_acc[4]
    _R[75] = _j246*_acc[4] + _j4*_k335
    _R[76] = _j1*_j59*_k630 + _j162*_acc[1] + _j2*_k632*b4 + _j204*_acc[2] + _j246*_acc[3] - _j298*_acc[4] + _j478*b2 + _j479*b1d + _j480*_k629*b2d + _j481*b4d + _j78*_k630*b3d + _j91*_acc[0]
    _R[77] = _cam0[0]*_j489 + _cam0[1]*_j486 + _cam0[1]*_j490*_k329 + _cam0[1]*(_j311*_j318 + _j400*_acc[5] + _j486 + _j495) + _cam0[2]*_j488 + _cam0[2]*(_j492 + _j494) + _cam0[3]*_j491 + _j304*_k634 - _j310*_acc[5] + _j482*_k635 + _j483*_k636 + _j484*_k338 + _j487*_k633
    _R[78] = _j479*xE
    _R[79] = _j496*xEd
    _R[80] = _j76*_k332
    _R[81] = _j41*_k333
    _R[82] = _j275*_k629 + _j284*_k630 + _j479*b1 + _j481*b4 + _j496*b2d + _j497*_k332 + _j498*_k333 + _j96*_k330
    _R[83] = _j304*_j501 + _j499 + _j500*_k336 + _j502*_j505 + _j502*_k637 + _j503*_k329 + _j504*_k638
    _R[84] = 0.0
    _R[85] = 0.0
    _R[86] = 0.0
    _R[87] = 0.0
    _R[88] = 0.0
    _R[89] = _cam0[0]*_j486 + _cam0[0]*_j495 + _cam0[1]*_j492 + _cam0[1]*_j493 + _cam0[1]*(_j304*_k326 + _j488 + _j494) + _cam0[2]*_j491 + _cam0[2]*(_j305*_acc[5] + _j490*_k337 + _j502*_k338) + _cam0[3]*_j489 + _j306*_j490 + _j308*_k324 - _j313*_acc[5] + _j490*_k127 + _j499*thetad
    _R[90] = 0.0
    _R[91] = 0.0
    _R[92] = 0.0
    _R[93] = 0.0
    _R[94] = 0.0
    _R[95] = _cam0[1]*_j308*_k338 + _j304*_k328 + _j482*_k336 + _j483*_j505 + _j483*_k637 + _j484*_k329 + _j506*_k639
    _Rt[0] = 0.0
    _Rt[1] = 0.0
    _Rt[2] = 0.0
    _Rt[3] = 0.0
    _Rt[4] = 0.0
    _Rt[5] = -_j509*_acc[6] - _j512*_acc[7]
    _Rt[6] = _cam0[2]*_j487*_k641 + _j304*_k642 + _j357*_j507 + _j482*_k643 + _j483*_k645 + _j484*_k646 + _j487*_k644 + _j490*_j501 + _j506*_k647 - _j509*_acc[5]
    _Rt[7] = _cam0[2]*_j490*_k640 + _j308*_k648 + _j357*_j510 + _j487*_j501 + _j490*_k650 + _j500*_k649 + _j502*_k651 + _j503*_k647 + _j504*_k647 - _j512*_acc[5]
    _CQ[0] = _j480*_k126
    _CQ[1] = _j513*xEd
    _CQ[2] = _j76*_k124
    _CQ[3] = _j41*_k123
    _CQ[4] = _j298*xEd + _j497*_k124 + _j498*_k123 + _j513*b2d + _j96*_k126
    _CQ[5] = _cam0[1]*(_j305*thetad + _j507) + _cam0[2]*_j514 + _j310*thetad + _j508
    _CQ[6] = 0.0
    _CQ[7] = 0.0
    _CQ[8] = 0.0
    _CQ[9] = 0.0
    _CQ[10] = 0.0
    _CQ[11] = _cam0[1]*(_j510 + _j514) + _cam0[2]*_j400*thetad + _j313*thetad + _j511
    _Ct[0] = _j309*_k652 + _j509*thetad
    _Ct[1] = _j312*_k652 + _j512*thetad


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
    return [0.0, 0.0, 0.0, 0.0, d - r_b - r_r, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, Omega]


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
    ctx.cache = &k[653]
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
_model.n_const = 653
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
 "source_hash": "sha256:64a7efcd9334b75fa69119f83904c9f9c8d47957738123d27eab23d9cd1693f4",
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
 "time_derivative": "symbolic",
 "title": "Rayleigh-beam follower in a grooved disk cam, N = 4 assumed modes"
}
"""
MANIFEST = json.loads(_MANIFEST_JSON)
"""States, parameters (defaults, units, ranges), outputs, the cam profile, events, source hash."""

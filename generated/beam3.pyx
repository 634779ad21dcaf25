# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True, initializedcheck=False
#
# GENERATED FILE - DO NOT EDIT.  Written by `camdyn derive` from camdyn/derive/models/beam.py;
# edit that and regenerate.  `camdyn derive --check` fails while this file is stale.
# Derivation key: sha256:3b813bbee5111ad1fe754cfed84b303307e4de4135c053a25da18fc2a22af92b
# Text hash: sha256:be1bc0d30873c035ee89060aca3ca06be649553fa7c734c6a4e1da3321e76a77
#
# Rayleigh-beam follower in a grooved disk cam, N = 3 assumed modes (paper (1)-(20))
# Source hash: sha256:a4c10ed1c7eeed79759d12da9812dfb2e08f6d7ceaf7defeb99a53905305f1ad
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
    _NQ = 5                  # coordinates Q
    _NC = 2                  # constraints Phi
    _NA = 7                  # unknowns of the augmented system: Q'', lambda
    _ND = 3                  # independent coordinates, beside the _NC dependent ones (_partition)
    _NS = 10                 # states: Q, Q'
    _NCAM = 0
    _NM = 0
    _NE = 2
    _NQ1 = 5
    _NE1 = 2
    _JAC_SYMBOLIC = 1           # jacobian() is exact: A^-1 d(b - A x)/dy at fixed x
    _FT_SYMBOLIC = 1            # and so is its df/dt
    _PROJECTS = 1               # the loops call project() after every accepted step

# the declared coordinate partition (ConstraintSolver.dependent): the dependent coordinates,
# then the independent ones; a run may choose another (Ctx.part, _partition)
cdef int _PART[_NQ]
_PART[0] = 3  # xE, dependent
_PART[1] = 4  # theta, dependent
_PART[2] = 0  # b1
_PART[3] = 1  # b2
_PART[4] = 2  # b3

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
    cdef double _c7 = 4.0*m_r
    cdef double _c8 = (d*d)
    cdef double _c9 = 24.0*m_r
    cdef double _c10 = 4.0*_c3
    cdef double _c11 = 9.0*_c2
    cdef double _c12 = 3.0*_c3
    cdef double _c13 = (1.0/(((d*d)*(d*d))*(d*d)*d))
    cdef double _c14 = 20.0*m_r
    cdef double _c15 = (1.0/((((d*d)*(d*d))*((d*d)*(d*d)))))
    cdef double _c16 = 12.0*m_r
    cdef double _c17 = 2.0*_c3
    cdef double _c18 = 3.0*_c2
    cdef double _c19 = 8.0*m_r
    cdef double _c20 = 4.0*_c2
    cdef double _c21 = 0.004761904761904762*_c15
    cdef double _c22 = _c4*_c7
    cdef double _c23 = _c6*m_r
    cdef double _c24 = _c15*m_r
    cdef double _c25 = _c16*_c5
    cdef double _c26 = 16.0*_c23
    cdef double _c27 = _c13*_c9
    cdef double _c28 = _c3*_c4
    cdef double _c29 = 1.3333333333333333*_c28
    cdef double _c30 = _c3*_c6
    cdef double _c31 = _c15*_c3
    cdef double _c32 = _c2*_c4
    cdef double _c33 = _c12*_c5
    cdef double _c34 = _c18*_c6
    cdef double _c35 = _c10*_c13
    cdef double _c36 = 3.2*_c30
    cdef double _c37 = _c15*_c2
    cdef double _c38 = _c18*_c5
    cdef double _c39 = _c20*_c6
    cdef double _c40 = _c11*_c13
    cdef double _c41 = (r_b*r_b*r_b*r_b)
    cdef double _c42 = (r_r*r_r*r_r*r_r)
    cdef double _c43 = (r_r*r_r*r_r)
    cdef double _c44 = 4.0*r_b
    cdef double _c45 = (r_b*r_b*r_b)
    cdef double _c46 = 4.0*r_r
    cdef double _c47 = (r_r*r_r)
    cdef double _c48 = (r_b*r_b)
    cdef double _c49 = 6.0*_c48
    cdef double _c50 = (S_T*S_T*S_T*S_T)
    cdef double _c51 = 2.0*_c50
    cdef double _c52 = (S_T*S_T)
    cdef double _c53 = _c52*r_r
    cdef double _c54 = 2.0*_c52
    cdef double _c55 = 4.0*S_T
    cdef double _c56 = 12.0*S_T
    cdef double _c57 = _c47*r_b
    cdef double _c58 = _c48*r_r
    cdef double _c59 = _c43*_c55 + _c45*_c55 + _c56*_c57 + _c56*_c58
    cdef double _c60 = (S_T*S_T*S_T)
    cdef double _c61 = _c44*_c60
    cdef double _c62 = _c46*_c60
    cdef double _c63 = _c61 + _c62
    cdef double _c64 = 12.0*r_b
    cdef double _c65 = _c47*_c52
    cdef double _c66 = J_r*_c50
    cdef double _c67 = 2.0*r_b
    cdef double _c68 = _c67*r_r
    cdef double _c69 = 2.0*S_T
    cdef double _c70 = _c69*r_b
    cdef double _c71 = _c69*r_r
    cdef double _c72 = _c70 + _c71
    cdef double _c73 = J_r*_c52
    cdef double _c74 = 2.0*_c73
    cdef double _c75 = _c48*_c73
    cdef double _c76 = _c47*_c73
    cdef double _c77 = _c68*_c73 + _c75 + _c76
    cdef double _c78 = J_r*_c70 + J_r*_c71
    cdef double _c79 = J_r*_c51
    cdef double _c80 = J_r*_c60
    cdef double _c81 = 2.0*r_r
    cdef double _c82 = _c67*_c80 + _c80*_c81
    cdef double _c83 = (1.0/(_c8))
    cdef double _c84 = (1.0/(d*d*d))
    cdef double _c85 = 4.0*_c4
    cdef double _c86 = 3.0*_c84
    cdef double _c87 = 2.0*_c83
    cdef double _c88 = r_b + r_r
    cdef double _c89 = _c5*m_r
    cdef double _c90 = _c4*m_r
    cdef double _c91 = 3.141592653589793*E*_c0
    cdef double _c92 = 2.0*_c6
    cdef double _c93 = _c5*_c91
    cdef double _c94 = _c3*_c5
    cdef double _c95 = _c2*_c5
    cdef double _c96 = _c6*_c91
    cdef double _c97 = _c13*_c91
    cdef double _c98 = _c13*_c3
    cdef double _c99 = 0.5*_c3
    cdef double _c100 = _c13*_c2
    cdef double _c101 = _c2*_c6
    cdef double _c102 = 6.0*_c13
    cdef double _c103 = _c15*_c91
    cdef double _c104 = 18.0*_c23
    cdef double _c105 = 0.5*_c4
    cdef double _c106 = _c13*m_r
    cdef double _c107 = 32.0*_c24
    cdef double _c108 = _c19*_c4
    cdef double _c109 = 6.0*_c3
    cdef double _c110 = 4.571428571428571*_c31
    cdef double _c111 = 3.6*_c30
    cdef double _c112 = 2.6666666666666665*_c28
    cdef double _c113 = 6.0*_c101
    cdef double _c114 = 2.0*_c32
    cdef double _c115 = 14.4*_c37
    cdef double _c116 = J_r*S_T
    cdef double _c117 = 6.0*(((r_r*r_r)*(r_r*r_r))*r_r)
    cdef double _c118 = 6.0*(((r_b*r_b)*(r_b*r_b))*r_b)
    cdef double _c119 = 15.0*_c42
    cdef double _c120 = 20.0*_c45
    cdef double _c121 = 15.0*_c41
    cdef double _c122 = (((S_T*S_T)*(S_T*S_T))*(S_T*S_T))
    cdef double _c123 = 3.0*_c52
    cdef double _c124 = _c43*_c52
    cdef double _c125 = _c45*_c53
    cdef double _c126 = _c48*_c65
    cdef double _c127 = r_b*r_r
    cdef double _c128 = _c127*_c50
    cdef double _c129 = 3.0*_c50
    cdef double _c130 = 30.0*S_T
    cdef double _c131 = 60.0*S_T
    cdef double _c132 = S_T*_c117 + S_T*_c118 + _c130*_c41*r_r + _c130*_c42*r_b + _c131*_c43*_c48 + _c131*_c45*_c47
    cdef double _c133 = (((S_T*S_T)*(S_T*S_T))*S_T)
    cdef double _c134 = 6.0*_c133
    cdef double _c135 = _c134*r_b
    cdef double _c136 = _c134*r_r
    cdef double _c137 = _c135 + _c136
    cdef double _c138 = _c124*r_b
    cdef double _c139 = 15.0*_c50
    cdef double _c140 = _c43*_c60
    cdef double _c141 = 60.0*_c60
    cdef double _c142 = 12.0*_c60
    cdef double _c143 = 36.0*_c60
    cdef double _c144 = 12.0*_c140 + _c142*_c45 + _c143*_c57 + _c143*_c58
    cdef double _c145 = 12.0*_c133
    cdef double _c146 = _c145*r_b
    cdef double _c147 = _c145*r_r
    cdef double _c148 = 36.0*_c50
    cdef double _c149 = 18.0*_c50
    cdef double _c150 = J_r*_c122
    cdef double _c151 = J_r*_c133
    cdef double _c152 = _c80*r_b
    cdef double _c153 = _c80*r_r
    cdef double _c154 = _c152 + _c153
    cdef double _c155 = 4.0*_c150
    cdef double _c156 = 8.0*_c66
    cdef double _c157 = 4.0*_c66
    cdef double _c158 = _c127*_c156 + _c157*_c47 + _c157*_c48
    cdef double _c159 = _c151*_c44 + _c151*_c46
    cdef double _c160 = _c44*r_r
    cdef double _c161 = _c160*_c73 + _c47*_c74 + _c48*_c74
    cdef double _c162 = _c45*_c80
    cdef double _c163 = J_r*_c140
    cdef double _c164 = 6.0*_c152
    cdef double _c165 = 8.0*_c151
    cdef double _c166 = _c165*r_b + _c165*r_r
    cdef double _c167 = J_r*_c61 + J_r*_c62
    cdef double _c168 = 6.0*_c66
    cdef double _c169 = (Omega*Omega)
    cdef double _c170 = _c169*r_b
    cdef double _c171 = _c169*r_r
    cdef double _c172 = _c170 + _c171
    cdef double _c173 = S_T*_c169
    cdef double _c174 = Omega*_c67 + Omega*_c81
    cdef double _c175 = 6.0*_c84
    cdef double _c176 = 8.0*_c4
    cdef double _c177 = 12.0*_c4
    cdef double _c178 = Omega*_c69
    cdef double _c179 = 4.0*_c5
    cdef double _c180 = _c3*_c85
    cdef double _c181 = 12.0*_c101
    cdef double _c182 = 6.0*_c95
    cdef double _c183 = 3.0*_c13
    cdef double _c184 = _c11*_c6
    cdef double _c185 = 36.0*_c23
    cdef double _c186 = 9.0*_c30
    cdef double _c187 = 96.0*_c24
    cdef double _c188 = 16.0*_c31
    cdef double _c189 = 36.0*_c37
    cdef double _c190 = 36.0*_c89
    cdef double _c191 = 64.0*_c23
    cdef double _c192 = 120.0*_c106
    cdef double _c193 = 12.0*_c94
    cdef double _c194 = 16.0*_c30
    cdef double _c195 = 24.0*_c98
    cdef double _c196 = 36.0*_c100
    cdef double _c197 = _c53*r_b
    cdef double _c198 = _c48*_c52
    cdef double _c199 = _c142*r_b
    cdef double _c200 = _c142*r_r
    cdef double _c201 = 6.0*_c122
    cdef double _c202 = _c45*_c60
    cdef double _c203 = 180.0*_c60
    cdef double _c204 = 60.0*_c50
    cdef double _c205 = 30.0*_c52
    cdef double _c206 = 30.0*_c133
    cdef double _c207 = 12.0*_c122
    cdef double _c208 = 36.0*_c133
    cdef double _c209 = J_r*_c146 + J_r*_c147
    cdef double _c210 = 8.0*_c60
    cdef double _c211 = 10.0*_c151
    cdef double _c212 = _c127*_c66
    cdef double _c213 = 12.0*_c66
    cdef double _c214 = 24.0*_c212 + _c213*_c47 + _c213*_c48
    cdef double _c215 = 12.0*_c50
    cdef double _c216 = 6.0*_c52
    cdef double _c217 = 72.0*_c60
    cdef double _c218 = 24.0*_c133
    cdef double _c219 = _c218*r_b
    cdef double _c220 = _c218*r_r
    cdef double _c221 = 16.0*_c151
    cdef double _c222 = Omega*S_T
    cdef double _c223 = (Omega*Omega*Omega)
    cdef double _c224 = _c223*r_b + _c223*r_r
    cdef double _c225 = S_T*_c223
    cdef double _c226 = Omega*r_b + Omega*r_r
    cdef double _c227 = 2.0*_c170 + 2.0*_c171
    cdef double _c228 = 2.0*_c173
    ctx.k[0] = 0.3333333333333333*_c2  # _k0
    ctx.k[1] = 0.2*_c3  # _k1
    ctx.k[2] = _c4  # _k2
    ctx.k[3] = 0.16666666666666666*_c3  # _k3
    ctx.k[4] = 0.375*_c2  # _k4
    ctx.k[5] = _c5  # _k5
    ctx.k[6] = 0.14285714285714285*_c3  # _k6
    ctx.k[7] = 0.4*_c2  # _k7
    ctx.k[8] = _c6  # _k8
    ctx.k[9] = _c7  # _k9
    ctx.k[10] = _c2  # _k10
    ctx.k[11] = _c3  # _k11
    ctx.k[12] = 0.5*_c8  # _k12
    ctx.k[13] = _c9  # _k13
    ctx.k[14] = _c10  # _k14
    ctx.k[15] = _c11  # _k15
    ctx.k[16] = 15.0*m_r  # _k16
    ctx.k[17] = _c12  # _k17
    ctx.k[18] = 5.0*_c2  # _k18
    ctx.k[19] = 0.2*d  # _k19
    ctx.k[20] = 0.45*_c2  # _k20
    ctx.k[21] = 0.5*_c2  # _k21
    ctx.k[22] = 0.125*_c3  # _k22
    ctx.k[23] = _c13  # _k23
    ctx.k[24] = _c14  # _k24
    ctx.k[25] = 0.1*_c8  # _k25
    ctx.k[26] = 140.0*m_r  # _k26
    ctx.k[27] = 20.0*_c3  # _k27
    ctx.k[28] = 63.0*_c2  # _k28
    ctx.k[29] = 0.125*d  # _k29
    ctx.k[30] = 0.1111111111111111*_c3  # _k30
    ctx.k[31] = 0.5714285714285714*_c2  # _k31
    ctx.k[32] = _c15  # _k32
    ctx.k[33] = _c16  # _k33
    ctx.k[34] = _c17  # _k34
    ctx.k[35] = _c18  # _k35
    ctx.k[36] = 35.0*_c8  # _k36
    ctx.k[37] = _c19  # _k37
    ctx.k[38] = _c20  # _k38
    ctx.k[39] = 35.0*m_r  # _k39
    ctx.k[40] = 5.0*_c3  # _k40
    ctx.k[41] = 14.0*_c2  # _k41
    ctx.k[42] = 18.0*d  # _k42
    ctx.k[43] = _c21  # _k43
    ctx.k[44] = L_g*_c3 + m_r  # _k44
    ctx.k[45] = _c22  # _k45
    ctx.k[46] = 9.0*_c23  # _k46
    ctx.k[47] = 16.0*_c24  # _k47
    ctx.k[48] = _c25  # _k48
    ctx.k[49] = _c26  # _k49
    ctx.k[50] = _c27  # _k50
    ctx.k[51] = _c29  # _k51
    ctx.k[52] = 1.8*_c30  # _k52
    ctx.k[53] = 2.2857142857142856*_c31  # _k53
    ctx.k[54] = _c32  # _k54
    ctx.k[55] = _c33  # _k55
    ctx.k[56] = _c34  # _k56
    ctx.k[57] = _c35  # _k57
    ctx.k[58] = _c36  # _k58
    ctx.k[59] = 7.2*_c37  # _k59
    ctx.k[60] = _c38  # _k60
    ctx.k[61] = _c39  # _k61
    ctx.k[62] = _c40  # _k62
    ctx.k[63] = _c41 + _c42 + _c43*_c44 + _c45*_c46 + _c47*_c49  # _k63
    ctx.k[64] = _c50  # _k64
    ctx.k[65] = _c51  # _k65
    ctx.k[66] = _c44*_c53 + _c47*_c54 + _c48*_c54  # _k66
    ctx.k[67] = _c59  # _k67
    ctx.k[68] = _c63  # _k68
    ctx.k[69] = _c49*_c52 + _c53*_c64 + 6.0*_c65  # _k69
    ctx.k[70] = _c66  # _k70
    ctx.k[71] = _c47 + _c48 + _c68  # _k71
    ctx.k[72] = _c52  # _k72
    ctx.k[73] = _c72  # _k73
    ctx.k[74] = _c74  # _k74
    ctx.k[75] = _c77  # _k75
    ctx.k[76] = -_c74  # _k76
    ctx.k[77] = -_c78  # _k77
    ctx.k[78] = -_c79  # _k78
    ctx.k[79] = -_c82  # _k79
    ctx.k[80] = _c82  # _k80
    ctx.k[81] = -_c83  # _k81
    ctx.k[82] = -_c84  # _k82
    ctx.k[83] = -_c4  # _k83
    ctx.k[84] = -_c85  # _k84
    ctx.k[85] = -_c86  # _k85
    ctx.k[86] = -_c87  # _k86
    ctx.k[87] = _c88  # _k87
    ctx.k[88] = -_c16*_c6  # _k88
    ctx.k[89] = -_c19*_c6  # _k89
    ctx.k[90] = -6.0*_c89  # _k90
    ctx.k[91] = -_c22  # _k91
    ctx.k[92] = -2.0*_c90  # _k92
    ctx.k[93] = -_c4*_c91  # _k93
    ctx.k[94] = -_c91*_c92  # _k94
    ctx.k[95] = -1.5*_c93  # _k95
    ctx.k[96] = -_c28  # _k96
    ctx.k[97] = -2.4*_c30  # _k97
    ctx.k[98] = -1.2*_c94  # _k98
    ctx.k[99] = -1.3333333333333333*_c30  # _k99
    ctx.k[100] = -1.5*_c94  # _k100
    ctx.k[101] = -0.6666666666666666*_c28  # _k101
    ctx.k[102] = -_c32  # _k102
    ctx.k[103] = -_c39  # _k103
    ctx.k[104] = -_c34  # _k104
    ctx.k[105] = -2.0*_c95  # _k105
    ctx.k[106] = -1.5*_c95  # _k106
    ctx.k[107] = -_c13*_c16  # _k107
    ctx.k[108] = -_c13*_c19  # _k108
    ctx.k[109] = -6.0*_c23  # _k109
    ctx.k[110] = -_c5*_c7  # _k110
    ctx.k[111] = -2.0*_c89  # _k111
    ctx.k[112] = -3.0*_c96  # _k112
    ctx.k[113] = -4.5*_c97  # _k113
    ctx.k[114] = -_c30  # _k114
    ctx.k[115] = -_c13*_c17  # _k115
    ctx.k[116] = -1.1428571428571428*_c98  # _k116
    ctx.k[117] = -1.2*_c30  # _k117
    ctx.k[118] = -0.8*_c94  # _k118
    ctx.k[119] = -_c5*_c99  # _k119
    ctx.k[120] = -_c95  # _k120
    ctx.k[121] = -3.6*_c100  # _k121
    ctx.k[122] = -4.5*_c100  # _k122
    ctx.k[123] = -2.25*_c101  # _k123
    ctx.k[124] = -1.5*_c101  # _k124
    ctx.k[125] = -_c15*_c16  # _k125
    ctx.k[126] = -_c15*_c19  # _k126
    ctx.k[127] = -_c102*m_r  # _k127
    ctx.k[128] = -_c6*_c7  # _k128
    ctx.k[129] = -_c92*m_r  # _k129
    ctx.k[130] = -7.2*_c103  # _k130
    ctx.k[131] = -_c98  # _k131
    ctx.k[132] = -_c31  # _k132
    ctx.k[133] = -1.7142857142857142*_c31  # _k133
    ctx.k[134] = -0.8571428571428571*_c98  # _k134
    ctx.k[135] = -0.6666666666666666*_c30  # _k135
    ctx.k[136] = -0.4*_c30  # _k136
    ctx.k[137] = -_c101  # _k137
    ctx.k[138] = -_c15*_c20  # _k138
    ctx.k[139] = -4.8*_c37  # _k139
    ctx.k[140] = -2.4*_c100  # _k140
    ctx.k[141] = -1.5*_c100  # _k141
    ctx.k[142] = -_c99  # _k142
    ctx.k[143] = -48.0*_c24  # _k143
    ctx.k[144] = -_c104  # _k144
    ctx.k[145] = -_c105*_c91  # _k145
    ctx.k[146] = -60.0*_c106  # _k146
    ctx.k[147] = -32.0*_c23  # _k147
    ctx.k[148] = -_c107  # _k148
    ctx.k[149] = -_c27  # _k149
    ctx.k[150] = -18.0*_c103  # _k150
    ctx.k[151] = -18.0*_c89  # _k151
    ctx.k[152] = -_c26  # _k152
    ctx.k[153] = -_c25  # _k153
    ctx.k[154] = -_c108  # _k154
    ctx.k[155] = -4.5*_c96  # _k155
    ctx.k[156] = -18.0*_c97  # _k156
    ctx.k[157] = -8.0*_c31  # _k157
    ctx.k[158] = -6.0*_c96  # _k158
    ctx.k[159] = -3.0*_c93  # _k159
    ctx.k[160] = -_c17*_c4  # _k160
    ctx.k[161] = -4.5*_c30  # _k161
    ctx.k[162] = -_c105*_c2  # _k162
    ctx.k[163] = -18.0*_c37  # _k163
    ctx.k[164] = -12.0*_c98  # _k164
    ctx.k[165] = -8.0*_c30  # _k165
    ctx.k[166] = -_c109*_c5  # _k166
    ctx.k[167] = -_c35  # _k167
    ctx.k[168] = -_c33  # _k168
    ctx.k[169] = -_c110  # _k169
    ctx.k[170] = -_c111  # _k170
    ctx.k[171] = -_c36  # _k171
    ctx.k[172] = -4.5*_c101  # _k172
    ctx.k[173] = -_c112  # _k173
    ctx.k[174] = -18.0*_c100  # _k174
    ctx.k[175] = -_c40  # _k175
    ctx.k[176] = -_c113  # _k176
    ctx.k[177] = -_c38  # _k177
    ctx.k[178] = -_c114  # _k178
    ctx.k[179] = -_c115  # _k179
    ctx.k[180] = _c73  # _k180
    ctx.k[181] = _c116*r_b + _c116*r_r  # _k181
    ctx.k[182] = -_c73  # _k182
    ctx.k[183] = _c79  # _k183
    ctx.k[184] = _c117*r_b + _c118*r_r + _c119*_c48 + _c120*_c43 + _c121*_c47 + (((r_b*r_b)*(r_b*r_b))*(r_b*r_b)) + (((r_r*r_r)*(r_r*r_r))*(r_r*r_r))  # _k184
    ctx.k[185] = _c122  # _k185
    ctx.k[186] = 3.0*_c122  # _k186
    ctx.k[187] = _c123*_c41 + _c123*_c42 + _c124*_c64 + 12.0*_c125 + 18.0*_c126  # _k187
    ctx.k[188] = 6.0*_c128 + _c129*_c47 + _c129*_c48  # _k188
    ctx.k[189] = _c132  # _k189
    ctx.k[190] = _c137  # _k190
    ctx.k[191] = _c119*_c52 + _c121*_c52 + 60.0*_c125 + 90.0*_c126 + 60.0*_c138  # _k191
    ctx.k[192] = 30.0*_c128 + _c139*_c47 + _c139*_c48  # _k192
    ctx.k[193] = _c120*_c60 + 20.0*_c140 + _c141*_c57 + _c141*_c58  # _k193
    ctx.k[194] = _c144  # _k194
    ctx.k[195] = _c146 + _c147  # _k195
    ctx.k[196] = _c127*_c148 + _c149*_c47 + _c149*_c48  # _k196
    ctx.k[197] = 2.0*_c150  # _k197
    ctx.k[198] = _c151*_c67 + _c151*_c81  # _k198
    ctx.k[199] = _c154  # _k199
    ctx.k[200] = -_c66  # _k200
    ctx.k[201] = -_c154  # _k201
    ctx.k[202] = -_c77  # _k202
    ctx.k[203] = -_c155  # _k203
    ctx.k[204] = -_c158  # _k204
    ctx.k[205] = -_c159  # _k205
    ctx.k[206] = -_c161  # _k206
    ctx.k[207] = _c153*_c49 + 2.0*_c162 + 2.0*_c163 + _c164*_c47  # _k207
    ctx.k[208] = _c160*_c66 + _c47*_c79 + _c48*_c79  # _k208
    ctx.k[209] = -_c166  # _k209
    ctx.k[210] = -_c167  # _k210
    ctx.k[211] = _c159  # _k211
    ctx.k[212] = _c168*_c47 + _c49*_c66 + _c64*_c66*r_r  # _k212
    ctx.k[213] = J_r*_c135 + J_r*_c136  # _k213
    ctx.k[214] = _c172  # _k214
    ctx.k[215] = _c87  # _k215
    ctx.k[216] = _c173  # _k216
    ctx.k[217] = -S_T  # _k217
    ctx.k[218] = -_c174  # _k218
    ctx.k[219] = _c69  # _k219
    ctx.k[220] = 4.0*_c83  # _k220
    ctx.k[221] = _c175  # _k221
    ctx.k[222] = _c176  # _k222
    ctx.k[223] = _c177  # _k223
    ctx.k[224] = -_c178  # _k224
    ctx.k[225] = -_c69  # _k225
    ctx.k[226] = _c178  # _k226
    ctx.k[227] = -d  # _k227
    ctx.k[228] = -Omega  # _k228
    ctx.k[229] = _c83  # _k229
    ctx.k[230] = _c84  # _k230
    ctx.k[231] = -_c105  # _k231
    ctx.k[232] = -0.2*_c5  # _k232
    ctx.k[233] = -0.16666666666666666*_c6  # _k233
    ctx.k[234] = 0.4*_c3  # _k234
    ctx.k[235] = 0.3333333333333333*_c3  # _k235
    ctx.k[236] = -_c5  # _k236
    ctx.k[237] = 0.2857142857142857*_c3  # _k237
    ctx.k[238] = -_c6  # _k238
    ctx.k[239] = 8.0*_c3  # _k239
    ctx.k[240] = _c109  # _k240
    ctx.k[241] = -5.0*_c6  # _k241
    ctx.k[242] = -_c179  # _k242
    ctx.k[243] = -3.0*_c4  # _k243
    ctx.k[244] = -_c92  # _k244
    ctx.k[245] = -48.0*_c23  # _k245
    ctx.k[246] = -40.0*_c23  # _k246
    ctx.k[247] = -_c5*_c9  # _k247
    ctx.k[248] = -_c16*_c4  # _k248
    ctx.k[249] = -12.0*_c30  # _k249
    ctx.k[250] = -_c180  # _k250
    ctx.k[251] = -_c181  # _k251
    ctx.k[252] = -_c182  # _k252
    ctx.k[253] = -_c6*_c9  # _k253
    ctx.k[254] = -4.8*_c30  # _k254
    ctx.k[255] = -_c29  # _k255
    ctx.k[256] = -8.0*_c101  # _k256
    ctx.k[257] = -0.1*_c5  # _k257
    ctx.k[258] = -0.125*_c6  # _k258
    ctx.k[259] = -0.02857142857142857*_c13  # _k259
    ctx.k[260] = _c86  # _k260
    ctx.k[261] = 0.25*_c3  # _k261
    ctx.k[262] = -_c13  # _k262
    ctx.k[263] = 40.0*_c3  # _k263
    ctx.k[264] = -_c102  # _k264
    ctx.k[265] = -_c183  # _k265
    ctx.k[266] = -48.0*_c106  # _k266
    ctx.k[267] = -30.0*_c23  # _k267
    ctx.k[268] = -16.0*_c89  # _k268
    ctx.k[269] = -9.0*_c96  # _k269
    ctx.k[270] = -8.0*_c98  # _k270
    ctx.k[271] = -6.0*_c30  # _k271
    ctx.k[272] = -_c179*_c3  # _k272
    ctx.k[273] = -_c17*_c5  # _k273
    ctx.k[274] = -_c184  # _k274
    ctx.k[275] = -_c94  # _k275
    ctx.k[276] = -0.08571428571428572*_c13  # _k276
    ctx.k[277] = -0.5*_c15  # _k277
    ctx.k[278] = _c85  # _k278
    ctx.k[279] = 0.2222222222222222*_c3  # _k279
    ctx.k[280] = -_c15  # _k280
    ctx.k[281] = -7.0*_c15  # _k281
    ctx.k[282] = -0.01904761904761905*_c15  # _k282
    ctx.k[283] = 10.0*_c3  # _k283
    ctx.k[284] = -_c21  # _k284
    ctx.k[285] = -72.0*_c24  # _k285
    ctx.k[286] = -56.0*_c24  # _k286
    ctx.k[287] = -36.0*_c106  # _k287
    ctx.k[288] = -30.0*_c106  # _k288
    ctx.k[289] = -_c14*_c6  # _k289
    ctx.k[290] = -36.0*_c103  # _k290
    ctx.k[291] = -12.0*_c31  # _k291
    ctx.k[292] = -_c102*_c3  # _k292
    ctx.k[293] = -_c10*_c6  # _k293
    ctx.k[294] = -_c3*_c92  # _k294
    ctx.k[295] = -24.0*_c37  # _k295
    ctx.k[296] = -12.0*_c100  # _k296
    ctx.k[297] = -_c102*_c2  # _k297
    ctx.k[298] = -_c15*_c9  # _k298
    ctx.k[299] = -3.4285714285714284*_c31  # _k299
    ctx.k[300] = -0.8*_c30  # _k300
    ctx.k[301] = -_c183*_c2  # _k301
    ctx.k[302] = -9.6*_c37  # _k302
    ctx.k[303] = _c108  # _k303
    ctx.k[304] = _c112  # _k304
    ctx.k[305] = _c114  # _k305
    ctx.k[306] = _c104  # _k306
    ctx.k[307] = _c111  # _k307
    ctx.k[308] = _c113  # _k308
    ctx.k[309] = -_c185  # _k309
    ctx.k[310] = -_c186  # _k310
    ctx.k[311] = _c107  # _k311
    ctx.k[312] = _c110  # _k312
    ctx.k[313] = _c115  # _k313
    ctx.k[314] = -_c187  # _k314
    ctx.k[315] = -_c188  # _k315
    ctx.k[316] = -_c189  # _k316
    ctx.k[317] = -_c177  # _k317
    ctx.k[318] = -_c175  # _k318
    ctx.k[319] = _c185  # _k319
    ctx.k[320] = _c187  # _k320
    ctx.k[321] = _c190  # _k321
    ctx.k[322] = _c191  # _k322
    ctx.k[323] = _c192  # _k323
    ctx.k[324] = _c180  # _k324
    ctx.k[325] = _c186  # _k325
    ctx.k[326] = _c188  # _k326
    ctx.k[327] = _c184  # _k327
    ctx.k[328] = _c193  # _k328
    ctx.k[329] = _c194  # _k329
    ctx.k[330] = _c195  # _k330
    ctx.k[331] = _c189  # _k331
    ctx.k[332] = _c182  # _k332
    ctx.k[333] = _c181  # _k333
    ctx.k[334] = _c196  # _k334
    ctx.k[335] = -240.0*_c24  # _k335
    ctx.k[336] = -54.0*_c23  # _k336
    ctx.k[337] = -240.0*_c106  # _k337
    ctx.k[338] = -192.0*_c24  # _k338
    ctx.k[339] = -_c192  # _k339
    ctx.k[340] = -96.0*_c23  # _k340
    ctx.k[341] = -72.0*_c103  # _k341
    ctx.k[342] = -72.0*_c23  # _k342
    ctx.k[343] = -_c191  # _k343
    ctx.k[344] = -_c190  # _k344
    ctx.k[345] = -16.0*_c90  # _k345
    ctx.k[346] = -54.0*_c97  # _k346
    ctx.k[347] = -48.0*_c31  # _k347
    ctx.k[348] = -18.0*_c30  # _k348
    ctx.k[349] = -12.0*_c96  # _k349
    ctx.k[350] = -72.0*_c37  # _k350
    ctx.k[351] = -60.0*_c98  # _k351
    ctx.k[352] = -32.0*_c30  # _k352
    ctx.k[353] = -32.0*_c31  # _k353
    ctx.k[354] = -_c195  # _k354
    ctx.k[355] = -18.0*_c94  # _k355
    ctx.k[356] = -_c194  # _k356
    ctx.k[357] = -_c193  # _k357
    ctx.k[358] = -_c176*_c3  # _k358
    ctx.k[359] = -54.0*_c100  # _k359
    ctx.k[360] = -_c196  # _k360
    ctx.k[361] = -18.0*_c101  # _k361
    ctx.k[362] = -_c3  # _k362
    ctx.k[363] = -_c59  # _k363
    ctx.k[364] = -4.0*_c50  # _k364
    ctx.k[365] = -24.0*_c197 - 12.0*_c198 - 12.0*_c65  # _k365
    ctx.k[366] = -_c199 - _c200  # _k366
    ctx.k[367] = -_c63  # _k367
    ctx.k[368] = -_c54  # _k368
    ctx.k[369] = -_c72  # _k369
    ctx.k[370] = -8.0*_c150  # _k370
    ctx.k[371] = -_c157  # _k371
    ctx.k[372] = -_c132  # _k372
    ctx.k[373] = -_c201  # _k373
    ctx.k[374] = -60.0*_c140 - 60.0*_c202 - _c203*_c57 - _c203*_c58  # _k374
    ctx.k[375] = -120.0*_c128 - _c204*_c47 - _c204*_c48  # _k375
    ctx.k[376] = -120.0*_c125 - 180.0*_c126 - 120.0*_c138 - _c205*_c41 - _c205*_c42  # _k376
    ctx.k[377] = -_c206*r_b - _c206*r_r  # _k377
    ctx.k[378] = -_c207  # _k378
    ctx.k[379] = -_c144  # _k379
    ctx.k[380] = -_c137  # _k380
    ctx.k[381] = -72.0*_c128 - _c148*_c47 - _c148*_c48  # _k381
    ctx.k[382] = -_c208*r_b - _c208*r_r  # _k382
    ctx.k[383] = _c155  # _k383
    ctx.k[384] = J_r*_c201  # _k384
    ctx.k[385] = _c209  # _k385
    ctx.k[386] = 4.0*_c73  # _k386
    ctx.k[387] = _c157  # _k387
    ctx.k[388] = -8.0*_c197 - 4.0*_c198 - 4.0*_c65  # _k388
    ctx.k[389] = -_c210*r_b - _c210*r_r  # _k389
    ctx.k[390] = _c167  # _k390
    ctx.k[391] = 3.0*_c66  # _k391
    ctx.k[392] = _c168  # _k392
    ctx.k[393] = 6.0*_c153 + _c164  # _k393
    ctx.k[394] = 10.0*_c150  # _k394
    ctx.k[395] = _c211*r_b + _c211*r_r  # _k395
    ctx.k[396] = -J_r*_c207  # _k396
    ctx.k[397] = -_c214  # _k397
    ctx.k[398] = -_c209  # _k398
    ctx.k[399] = -24.0*_c128 - _c215*_c47 - _c215*_c48  # _k399
    ctx.k[400] = -24.0*_c125 - 36.0*_c126 - 24.0*_c138 - _c216*_c41 - _c216*_c42  # _k400
    ctx.k[401] = -24.0*_c140 - 24.0*_c202 - _c217*_c57 - _c217*_c58  # _k401
    ctx.k[402] = -_c219 - _c220  # _k402
    ctx.k[403] = -J_r*_c219 - J_r*_c220  # _k403
    ctx.k[404] = _c161  # _k404
    ctx.k[405] = J_r*_c199*_c47 + J_r*_c200*_c48 + 4.0*_c162 + 4.0*_c163  # _k405
    ctx.k[406] = _c214  # _k406
    ctx.k[407] = _c78  # _k407
    ctx.k[408] = -_c156*_c47 - _c156*_c48 - 16.0*_c212  # _k408
    ctx.k[409] = -8.0*_c127*_c73 - 4.0*_c75 - 4.0*_c76  # _k409
    ctx.k[410] = _c158  # _k410
    ctx.k[411] = -_c221*r_b - _c221*r_r  # _k411
    ctx.k[412] = -8.0*_c152 - 8.0*_c153  # _k412
    ctx.k[413] = _c166  # _k413
    ctx.k[414] = 12.0*_c84  # _k414
    ctx.k[415] = 24.0*_c4  # _k415
    ctx.k[416] = -_c88  # _k416
    ctx.k[417] = -_c172  # _k417
    ctx.k[418] = -_c173  # _k418
    ctx.k[419] = _c174  # _k419
    ctx.k[420] = _c67 + _c81  # _k420
    ctx.k[421] = _c55  # _k421
    ctx.k[422] = -_c55  # _k422
    ctx.k[423] = _c222  # _k423
    ctx.k[424] = -_c222  # _k424
    ctx.k[425] = _c224  # _k425
    ctx.k[426] = _c225  # _k426
    ctx.k[427] = _c226  # _k427
    ctx.k[428] = -_c227  # _k428
    ctx.k[429] = -_c228  # _k429
    ctx.k[430] = _c228  # _k430
    ctx.k[431] = -_c224  # _k431
    ctx.k[432] = -_c225  # _k432
    ctx.k[433] = -_c226  # _k433
    ctx.k[434] = _c227  # _k434
    ctx.k[435] = -_c169  # _k435


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
    cdef double b1 = _y[0]
    cdef double b2 = _y[1]
    cdef double b3 = _y[2]
    cdef double xE = _y[3]
    cdef double theta = _y[4]
    cdef double b1d = _y[5]
    cdef double b2d = _y[6]
    cdef double b3d = _y[7]
    cdef double xEd = _y[8]
    cdef double thetad = _y[9]
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
    cdef double _s9 = _k11*_s2
    cdef double _s10 = b2*xE
    cdef double _s11 = _k14*_s2
    cdef double _s12 = _k13*xE + _k15 + _s11
    cdef double _s13 = _s2*b3
    cdef double _s14 = _k8*_s2*(_k12*b1*(_k10 + _k9*xE + _s9) + _k19*_s10*(_k16*xE + _k17*_s2 + _k18) + 0.16666666666666666*_s12*_s13)
    cdef double _s15 = (((xE*xE)*(xE*xE))*(xE*xE))
    cdef double _s16 = _k23*_s15*(_k21 + _k22*_s2 + _s1)
    cdef double _s17 = _k23*_s0*(_k25*b1*(_k18 + _k24*xE + _s11) + _k29*_s10*_s12 + 0.02857142857142857*_s13*(_k26*xE + _k27*_s2 + _k28))
    cdef double _s18 = (((xE*xE)*(xE*xE))*(xE*xE)*xE)
    cdef double _s19 = _k43*_s3*(_k36*b1*(_k33*xE + _k34*_s2 + _k35) + _k42*_s10*(_k39*xE + _k40*_s2 + _k41) + 105.0*_s13*(_k37*xE + _k38 + _s9))
    cdef double _s20 = (b1*b1)
    cdef double _s21 = _s20*xE
    cdef double _s22 = _s0*b2
    cdef double _s23 = _s3*b1
    cdef double _s24 = _s6*b3
    cdef double _s25 = _s24*b2
    cdef double _s26 = b2*b3
    cdef double _s27 = _s2*b2
    cdef double _s28 = _s0*b3
    cdef double _s29 = _s26*_s3
    cdef double _s30 = _s2*_s20
    cdef double _s31 = (b2*b2)
    cdef double _s32 = _s3*_s31
    cdef double _s33 = (b3*b3)
    cdef double _s34 = _s15*_s33
    cdef double _s35 = _s0*_s31
    cdef double _s36 = _s33*_s6
    cdef double _s37 = (_cam0[0]*_cam0[0])
    cdef double _s38 = (_cam0[1]*_cam0[1])
    cdef double _s39 = (1.0/(_cam0[0]*_k73 + _k71 + _k72*_s37 + _k72*_s38))
    cdef double _s40 = _cam0[2]*_s39
    cdef double _s41 = (_cam0[1]*_cam0[1]*_cam0[1]*_cam0[1])
    cdef double _s42 = (_cam0[0]*_cam0[0]*_cam0[0])
    cdef double _s43 = (_cam0[0]*_cam0[0]*_cam0[0]*_cam0[0])
    cdef double _s44 = _cam0[0]*_s38
    cdef double _s45 = _s37*_s38
    cdef double _s46 = (1.0/(_cam0[0]*_k67 + _k63 + _k64*_s41 + _k64*_s43 + _k65*_s45 + _k66*_s38 + _k68*_s42 + _k68*_s44 + _k69*_s37))
    cdef double _s47 = _k70*_s46
    cdef double _s48 = (_cam0[2]*_cam0[2])
    cdef double _s49 = _s46*_s48
    cdef double _s50 = _cam0[0]*_s49
    cdef double _s51 = _cam0[2]*_s46
    cdef double _s52 = _k79*_s51
    cdef double _s53 = _k78*_s51
    cdef double _s54 = _s37*_s48
    cdef double _s55 = _k81*_s2
    cdef double _s56 = _k82*_s0
    cdef double _s57 = _k83*_s3
    cdef double _s58 = b1*xE
    cdef double _s59 = Omega*t - theta
    cdef double _s60 = sin(_s59)
    cdef double _s61 = S_T*_cam0[1]
    cdef double _s62 = S_T*_cam0[0]
    cdef double _s63 = _k87 + _s62
    cdef double _s64 = cos(_s59)
    cdef double _s65 = _s63*_s64
    cdef double _s66 = _s60*_s63
    cdef double _s67 = b1d*xEd
    cdef double _s68 = b3d*xEd
    cdef double _s69 = _s3*_s68
    cdef double _s70 = b2d*xEd
    cdef double _s71 = _s6*_s68
    cdef double _s72 = _s3*_s70
    cdef double _s73 = _s0*_s67
    cdef double _s74 = _s3*_s67
    cdef double _s75 = _s6*_s70
    cdef double _s76 = _s15*_s68
    cdef double _s77 = (xEd*xEd)
    cdef double _s78 = _s3*_s77
    cdef double _s79 = _s78*b2
    cdef double _s80 = _s0*b1
    cdef double _s81 = _s77*_s80
    cdef double _s82 = _k103*_s28
    cdef double _s83 = _s78*b3
    cdef double _s84 = _s22*_s77
    cdef double _s85 = _s2*b1
    cdef double _s86 = _s77*_s85
    cdef double _s87 = _s24*_s77
    cdef double _s88 = _k113*_s3
    cdef double _s89 = _s15*_s70
    cdef double _s90 = _s18*_s68
    cdef double _s91 = _s6*_s67
    cdef double _s92 = _s15*_s77
    cdef double _s93 = _s92*b3
    cdef double _s94 = _s77*b2
    cdef double _s95 = _s6*_s94
    cdef double _s96 = _s77*b1
    cdef double _s97 = _s3*_s96
    cdef double _s98 = _s3*_s33
    cdef double _s99 = _s2*_s31
    cdef double _s100 = (thetad*thetad)
    cdef double _s101 = _cam0[3]*_s100
    cdef double _s102 = _s101*_s39
    cdef double _s103 = _cam0[1]*_s100
    cdef double _s104 = _s103*_s51
    cdef double _s105 = _s101*_s51
    cdef double _s106 = (_cam0[1]*_cam0[1]*_cam0[1])
    cdef double _s107 = _s100*_s106
    cdef double _s108 = _s107*_s46
    cdef double _s109 = _s100/((((_cam0[0]*_cam0[0])*(_cam0[0]*_cam0[0]))*(_cam0[0]*_cam0[0]))*_k185 + (((_cam0[0]*_cam0[0])*(_cam0[0]*_cam0[0]))*_cam0[0])*_k190 + _cam0[0]*_k189 + _cam0[0]*_k190*_s41 + (((_cam0[1]*_cam0[1])*(_cam0[1]*_cam0[1]))*(_cam0[1]*_cam0[1]))*_k185 + _k184 + _k186*_s37*_s41 + _k186*_s38*_s43 + _k187*_s38 + _k188*_s41 + _k191*_s37 + _k192*_s43 + _k193*_s42 + _k194*_s44 + _k195*_s38*_s42 + _k196*_s45)
    cdef double _s110 = (((_cam0[1]*_cam0[1])*(_cam0[1]*_cam0[1]))*_cam0[1])*_s109
    cdef double _s111 = _k197*_s110
    cdef double _s112 = _cam0[1]*_s109
    cdef double _s113 = _s112*_s48
    cdef double _s114 = (_cam0[2]*_cam0[2]*_cam0[2])*_s112
    cdef double _s115 = _s106*_s109
    cdef double _s116 = _cam0[2]*_s115
    cdef double _s117 = _s115*_s48
    cdef double _s118 = _cam0[0]*_k216
    cdef double _s119 = _k218*thetad
    cdef double _s120 = _k224*thetad
    cdef double _s121 = _cam0[0]*_s120
    cdef double _s122 = _cam0[1]*_s64
    cdef double _s123 = _k87*_s100
    cdef double _s124 = _s100*_s60
    cdef double _s125 = _cam0[2]*_k217
    cdef double _s126 = _s100*_s64
    _A[0] = _k2*_s0*(_k0 + _k1*_s2 + _s1)
    _A[1] = _s4
    _A[2] = _s8
    _A[3] = _s14
    _A[4] = 0.0
    _A[5] = _s55
    _A[6] = 0.0
    _A[7] = _s4
    _A[8] = _s7*(_k20 + _s5)
    _A[9] = _s16
    _A[10] = _s17
    _A[11] = 0.0
    _A[12] = _s56
    _A[13] = 0.0
    _A[14] = _s8
    _A[15] = _s16
    _A[16] = _k32*_s18*(_k30*_s2 + _k31 + _s1)
    _A[17] = _s19
    _A[18] = 0.0
    _A[19] = _s57
    _A[20] = 0.0
    _A[21] = _s14
    _A[22] = _s17
    _A[23] = _s19
    _A[24] = _k11*xE + _k44 + _k45*_s30 + _k46*_s32 + _k47*_s34 + _k48*_s22*b1 + _k49*_s23*b3 + _k50*_s25 + _k51*_s0*_s20 + _k52*_s31*_s6 + _k53*_s18*_s33 + _k54*_s21 + _k55*_s23*b2 + _k56*_s35 + _k57*_s15*_s26 + _k58*_s24*b1 + _k59*_s36 + _k60*_s27*b1 + _k61*_s28*b1 + _k62*_s29
    _A[25] = 0.0
    _A[26] = _k84*_s28 + _k85*_s27 + _k86*_s58
    _A[27] = 1.0
    _A[28] = 0.0
    _A[29] = 0.0
    _A[30] = 0.0
    _A[31] = 0.0
    _A[32] = J_r + _cam0[0]*_k76*_s40 + _k74*_s38*_s39 + _k75*_s49 + _k77*_s40 + _k80*_s50 + _s38*_s52 + _s41*_s47 + _s44*_s53 + _s47*_s54
    _A[33] = _s60*_s61 - _s65
    _A[34] = _s61*_s64 + _s66
    _A[35] = _s55
    _A[36] = _s56
    _A[37] = _s57
    _A[38] = _k84*_s28 + _k85*_s27 + _k86*_s58
    _A[39] = _s60*_s61 - _s65
    _A[40] = 0.0
    _A[41] = 0.0
    _A[42] = 0.0
    _A[43] = 0.0
    _A[44] = 0.0
    _A[45] = 1.0
    _A[46] = _s61*_s64 + _s66
    _A[47] = 0.0
    _A[48] = 0.0
    _b[0] = _k100*_s79 + _k101*_s81 + _k102*_s2*_s67 + _k104*_s69 + _k105*_s0*_s70 + _k106*_s27*_s77 + _k88*_s83 + _k89*_s71 + _k90*_s72 + _k90*_s84 + _k91*_s73 + _k92*_s86 + _k93*_s58 + _k94*_s28 + _k95*_s27 + _k96*_s74 + _k97*_s87 + _k98*_s75 + _k99*_s76 + _s77*_s82
    _b[1] = _k107*_s87 + _k108*_s76 + _k109*_s75 + _k109*_s79 + _k110*_s74 + _k111*_s81 + _k112*_s22 + _k114*_s89 + _k115*_s93 + _k116*_s90 + _k117*_s95 + _k118*_s91 + _k119*_s97 + _k120*_s73 + _k121*_s71 + _k122*_s83 + _k123*_s72 + _k124*_s84 + _k95*_s85 + _s88*b3
    _b[2] = _k125*_s93 + _k126*_s90 + _k127*_s89 + _k127*_s95 + _k128*_s91 + _k129*_s97 + _k130*_s24 + _k131*_s92*b2 + _k132*_s68*((((xE*xE)*(xE*xE))*((xE*xE)*(xE*xE)))) + _k133*_s18*_s77*b3 + _k134*_s18*_s70 + _k135*_s15*_s67 + _k136*_s6*_s96 + _k137*_s74 + _k138*_s76 + _k139*_s87 + _k140*_s75 + _k141*_s79 + _k94*_s80 + _s88*b2
    _b[3] = _k103*_s68*_s80 + _k142*_s77 + _k143*_s36*_s77 + _k144*_s35*_s77 + _k144*_s72*b2 + _k145*_s20 + _k146*_s29*_s77 + _k147*_s28*_s96 + _k148*_s76*b3 + _k149*_s24*_s70 + _k149*_s71*b2 + _k150*_s98 + _k151*_s27*_s96 + _k152*_s23*_s68 + _k152*_s74*b3 + _k153*_s22*_s67 + _k153*_s70*_s80 + _k154*_s67*_s85 + _k155*_s99 + _k156*_s28*b2 + _k157*_s34*_s77 + _k158*_s85*b3 + _k159*_s58*b2 + _k160*_s30*_s77 + _k161*_s32*_s77 + _k162*_s20*_s77 + _k163*_s77*_s98 + _k164*_s25*_s77 + _k165*_s97*b3 + _k166*_s22*_s96 + _k167*_s76*b2 + _k167*_s89*b3 + _k168*_s23*_s70 + _k168*_s74*b2 + _k169*_s90*b3 + _k170*_s75*b2 + _k171*_s24*_s67 + _k171*_s71*b1 + _k172*_s77*_s99 + _k173*_s67*_s80 + _k174*_s28*_s94 + _k175*_s69*b2 + _k175*_s72*b3 + _k176*_s22*_s70 + _k176*_s86*b3 + _k177*_s27*_s67 + _k177*_s58*_s94 + _k177*_s70*_s85 + _k178*_s58*_s67 + _k179*_s24*_s68 + _k91*_s21*_s77 + _s67*_s82
    _b[4] = _cam0[0]*_k180*_s102 + _cam0[0]*_k183*_s108 + _cam0[0]*_k203*_s117 + _cam0[0]*_k209*_s116 + _cam0[0]*_k210*_s104 + _cam0[0]*_k211*_s114 + _cam0[0]*_k212*_s113 + _cam0[0]*_s101*_s52 + _cam0[0]*_s111 + _cam0[2]*_s107*_s47 + _cam0[2]*_s111 + _k181*_s102 + _k182*_s103*_s40 + _k197*_s113*_s42 + _k197*_s114*_s37 + _k198*_s110 + _k199*_s101*_s38*_s46 + _k200*_s103*_s50 + _k200*_s105*_s37 + _k201*_s103*_s49 + _k202*_s105 + _k203*_s116*_s37 + _k204*_s116 + _k205*_s117 + _k206*_s104 + _k207*_s113 + _k208*_s114 + _k213*_s112*_s54 + _k80*_s108 + _s101*_s44*_s47 + _s103*_s37*_s53
    _b[5] = _k214*_s60 + _k215*_s96 + _k219*_s100*_s122 + _k220*_s67*xE + _k221*_s10*_s77 + _k221*_s2*_s70 + _k222*_s0*_s68 + _k223*_s13*_s77 + _s118*_s60 + _s119*_s60 + _s120*_s122 + _s121*_s60 + _s123*_s60 + _s124*_s125 + _s124*_s62
    _ph[0] = _s55*b1 + _s56*b2 + _s57*b3 + _s66
    _phd[0] = Omega*_s65 + _A[35] * b1d + _A[36] * b2d + _A[37] * b3d + _A[38] * xEd + _A[39] * thetad
    _b[6] = _cam0[1]*_k225*_s124 + _cam0[1]*_k226*_s60*thetad + _k214*_s64 + _s118*_s64 + _s119*_s64 + _s121*_s64 + _s123*_s64 + _s125*_s126 + _s126*_s62
    _ph[1] = _k227 + _s65 + xE
    _phd[1] = _k228*_s66 + _A[42] * b1d + _A[43] * b2d + _A[44] * b3d + _A[45] * xEd + _A[46] * thetad


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
    cdef double b1 = _y[0]
    cdef double b2 = _y[1]
    cdef double b3 = _y[2]
    cdef double xE = _y[3]
    cdef double theta = _y[4]
    cdef double b1d = _y[5]
    cdef double b2d = _y[6]
    cdef double b3d = _y[7]
    cdef double xEd = _y[8]
    cdef double thetad = _y[9]
    cdef double _cam0[5]
    _profile(ctx, theta, beta_r, _cam0, 0)

    cdef double _p0 = (xE*xE)
    cdef double _p1 = _k81*_p0
    cdef double _p2 = _k82*(xE*xE*xE)
    cdef double _p3 = _k83*(xE*xE*xE*xE)
    cdef double _p4 = S_T*_cam0[0] + _k87
    cdef double _p5 = Omega*t - theta
    cdef double _p6 = sin(_p5)
    cdef double _p7 = _p4*_p6
    cdef double _p8 = cos(_p5)
    cdef double _p9 = _p4*_p8
    cdef double _p10 = S_T*_cam0[1]
    _g[0] = _p1*b1 + _p2*b2 + _p3*b3 + _p7
    _g[1] = _k227 + _p9 + xE
    _J[0] = _p1
    _J[1] = _p2
    _J[2] = _p3
    _J[3] = xE*(_k84*_p0*b3 + _k85*b2*xE + _k86*b1)
    _J[4] = _p10*_p6 - _p9
    _J[5] = 0.0
    _J[6] = 0.0
    _J[7] = 0.0
    _J[8] = 1.0
    _J[9] = _p10*_p8 + _p7
    _gt[0] = Omega*_p9
    _gt[1] = _k228*_p7


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
    cdef double b1 = _yc[0]
    cdef double b2 = _yc[1]
    cdef double b3 = _yc[2]
    cdef double xE = _yc[3]
    cdef double theta = _yc[4]
    cdef double b1d = _yc[5]
    cdef double b2d = _yc[6]
    cdef double b3d = _yc[7]
    cdef double xEd = _yc[8]
    cdef double thetad = _yc[9]
    cdef double _cam0[5]
    _profile(ctx, theta, beta_r, _cam0, 0)

    cdef double _o0 = (xE*xE)
    cdef double _o1 = S_T*_cam0[0]
    cdef double _o2 = _k87 + _o1
    cdef double _o3 = Omega*t - theta
    _out[0] = _o0*(_k2*_o0*b3 + _k229*b1 + _k230*b2*xE)  # vE
    _out[1] = _k81*_o0*b1 + _k82*b2*(xE*xE*xE) + _k83*b3*(xE*xE*xE*xE) + _o2*sin(_o3)  # Phi1
    _out[2] = _k227 + _o2*cos(_o3) + xE  # Phi2
    _out[3] = _o1  # S
    _out[4] = atan(S_T*_cam0[1]/_o2)  # pressure_angle
    _out[5] = _acc[3]  # xEdd
    _out[6] = _acc[5]  # lambda1
    _out[7] = _acc[6]  # lambda2


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
_SCALE[3] = 0.05
_SCALE[4] = 1.0
_SCALE[5] = 1e-05
_SCALE[6] = 1e-05
_SCALE[7] = 1e-05
_SCALE[8] = 0.05
_SCALE[9] = 1.0


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
    cdef double b1 = _y[0]
    cdef double b2 = _y[1]
    cdef double b3 = _y[2]
    cdef double xE = _y[3]
    cdef double theta = _y[4]
    cdef double b1d = _y[5]
    cdef double b2d = _y[6]
    cdef double b3d = _y[7]
    cdef double xEd = _y[8]
    cdef double thetad = _y[9]
    cdef double _cam0[5]
    _profile(ctx, theta, beta_r, _cam0, 1)

    cdef double _j0 = (xE*xE*xE)
    cdef double _j1 = (xEd*xEd)
    cdef double _j2 = _j0*_j1
    cdef double _j3 = (xE*xE)
    cdef double _j4 = _j1*_j3
    cdef double _j5 = _j3*_acc[3]
    cdef double _j6 = _j3*_k11
    cdef double _j7 = _j6 + _k10 + _k9*xE
    cdef double _j8 = _j7*_k231
    cdef double _j9 = _j3*_k95
    cdef double _j10 = (xE*xE*xE*xE)
    cdef double _j11 = _j1*_j10
    cdef double _j12 = _j0*_acc[3]
    cdef double _j13 = _j3*_k17 + _k16*xE + _k18
    cdef double _j14 = _j13*_k232
    cdef double _j15 = _j0*_k94
    cdef double _j16 = (((xE*xE)*(xE*xE))*xE)
    cdef double _j17 = _j1*_j16
    cdef double _j18 = _j3*_k14
    cdef double _j19 = _j18 + _k13*xE + _k15
    cdef double _j20 = _j10*_acc[3]
    cdef double _j21 = _j19*_j20
    cdef double _j22 = _j4*b1
    cdef double _j23 = _j16*xEd
    cdef double _j24 = _j23*b3d
    cdef double _j25 = _j10*xEd
    cdef double _j26 = _j25*b2d
    cdef double _j27 = _j10*_acc[1]
    cdef double _j28 = _k236*(_k235*xE + m_r)
    cdef double _j29 = _j16*_acc[2]
    cdef double _j30 = _k238*(_k237*xE + m_r)
    cdef double _j31 = _k34*xE
    cdef double _j32 = _k12*b1
    cdef double _j33 = _k19*b2
    cdef double _j34 = _k239*xE
    cdef double _j35 = _j34 + _k13
    cdef double _j36 = _j3*b3
    cdef double _j37 = 0.16666666666666666*_j36
    cdef double _j38 = _j13*_j33
    cdef double _j39 = b3*xE
    cdef double _j40 = _k238*(0.3333333333333333*_j19*_j39 + _j32*(_j31 + _k9) + _j33*xE*(_k16 + _k240*xE) + _j35*_j37 + _j38)
    cdef double _j41 = _j10*_acc[2]
    cdef double _j42 = m_r*xE
    cdef double _j43 = _j3*_k6 + _j42
    cdef double _j44 = _k241*(_j43 + _k7)
    cdef double _j45 = _j0*_acc[1]
    cdef double _j46 = _k242*(_j3*_k3 + _j42 + _k4)
    cdef double _j47 = _j3*_acc[0]
    cdef double _j48 = _k244*xE*(_j19*_j37 + _j32*_j7 + _j38*xE)
    cdef double _j49 = _j2*b3
    cdef double _j50 = _j25*b3d
    cdef double _j51 = _j0*xEd
    cdef double _j52 = _j51*b2d
    cdef double _j53 = _j3*xEd
    cdef double _j54 = _j53*b1d
    cdef double _j55 = _j11*b3
    cdef double _j56 = _j51*b1d
    cdef double _j57 = _j4*b3
    cdef double _j58 = _j51*b3d
    cdef double _j59 = _j53*b2d
    cdef double _j60 = _j0*_acc[0]
    cdef double _j61 = b1*xE
    cdef double _j62 = _j1*_k91
    cdef double _j63 = _j3*_k158
    cdef double _j64 = _k159*xE
    cdef double _j65 = _k215*xE
    cdef double _j66 = _j4*b2
    cdef double _j67 = _j2*b2
    cdef double _j68 = b2*xE
    cdef double _j69 = _j1*_k177
    cdef double _j70 = b1d*xE
    cdef double _j71 = _k178*xEd
    cdef double _j72 = _j63*b3 + _j64*b2 + _j65*_acc[5] + _j66*_k151 + _j67*_k166 + _j68*_j69 + _j70*_j71 + _k93*b1
    cdef double _j73 = _j3*_k102
    cdef double _j74 = (((xE*xE)*(xE*xE))*(xE*xE))
    cdef double _j75 = _j74*_k99
    cdef double _j76 = _j10*b3d
    cdef double _j77 = _j0*b2d
    cdef double _j78 = _j16*b3d
    cdef double _j79 = _j10*b2d
    cdef double _j80 = _j0*b1d
    cdef double _j81 = _j10*b1d
    cdef double _j82 = _j16*b2d
    cdef double _j83 = _j25*b3
    cdef double _j84 = _j23*b3
    cdef double _j85 = _j51*b1
    cdef double _j86 = _j51*b3
    cdef double _j87 = _j3*b1
    cdef double _j88 = _j87*xEd
    cdef double _j89 = _j51*b2
    cdef double _j90 = _j25*b2
    cdef double _j91 = _j3*b2
    cdef double _j92 = _k177*xEd
    cdef double _j93 = _j89*_k153 + _j90*_k168 + _j91*_j92
    cdef double _j94 = _j18 + _k18 + _k24*xE
    cdef double _j95 = _j94*_k257
    cdef double _j96 = _j10*_k113
    cdef double _j97 = _j1*_j74
    cdef double _j98 = _j16*_acc[3]
    cdef double _j99 = _j3*_k27 + _k26*xE + _k28
    cdef double _j100 = _j99*_k259
    cdef double _j101 = _j10*_acc[0]
    cdef double _j102 = _j16*_j30
    cdef double _j103 = _j74*_acc[2]
    cdef double _j104 = _k262*(_k261*xE + m_r)
    cdef double _j105 = _k25*b1
    cdef double _j106 = _k29*b2
    cdef double _j107 = 0.02857142857142857*_j36
    cdef double _j108 = _j106*_j19
    cdef double _j109 = _k262*(_j105*(_j34 + _k24) + _j106*_j35*xE + _j107*(_k26 + _k263*xE) + _j108 + 0.05714285714285714*_j39*_j99)
    cdef double _j110 = _k264*(_j3*_k22 + _j42 + _k21)
    cdef double _j111 = _k265*(_j105*_j94 + _j107*_j99 + _j108*xE)
    cdef double _j112 = _j74*xEd
    cdef double _j113 = _j112*b3d
    cdef double _j114 = _j11*b2
    cdef double _j115 = _j23*b2d
    cdef double _j116 = _j25*b1d
    cdef double _j117 = _j2*b1
    cdef double _j118 = _j0*_k156
    cdef double _j119 = _j3*_k260
    cdef double _j120 = _j17*b3
    cdef double _j121 = _j118*b3 + _j119*_acc[5] + _j120*_k164 + _j49*_k174 + _j54*_k177 + _j55*_k146 + _j64*b1 + _j91*_k269
    cdef double _j122 = (((xE*xE)*(xE*xE))*(xE*xE)*xE)
    cdef double _j123 = _j122*_k116
    cdef double _j124 = _j74*b3d
    cdef double _j125 = _j74*b2d
    cdef double _j126 = _j16*b1d
    cdef double _j127 = _j25*b1
    cdef double _j128 = _j23*b2
    cdef double _j129 = _j112*b3
    cdef double _j130 = _j129*_k167 + _j83*_k175 + _j84*_k149
    cdef double _j131 = _j3*_k34 + _k33*xE + _k35
    cdef double _j132 = _j131*_k233
    cdef double _j133 = _j3*_k40 + _k39*xE + _k41
    cdef double _j134 = _j133*_k276
    cdef double _j135 = _j6 + _k37*xE + _k38
    cdef double _j136 = _j135*_k277
    cdef double _j137 = _j122*xEd
    cdef double _j138 = _j137*b3d
    cdef double _j139 = _j16*_acc[1]
    cdef double _j140 = _k36*b1
    cdef double _j141 = _k42*b2
    cdef double _j142 = _j133*_j141
    cdef double _j143 = 105.0*_j36
    cdef double _j144 = _k282*(_j131*_j140 + _j135*_j143 + _j142*xE)
    cdef double _j145 = _k284*(210.0*_j135*_j39 + _j140*(_k14*xE + _k33) + _j141*xE*(_k283*xE + _k39) + _j142 + _j143*(_j31 + _k37))
    cdef double _j146 = _j97*b3
    cdef double _j147 = _j17*b2
    cdef double _j148 = _j112*b2d
    cdef double _j149 = _j23*b1d
    cdef double _j150 = _j11*b1
    cdef double _j151 = _j0*_k278
    cdef double _j152 = _j10*b3
    cdef double _j153 = _j118*b2 + _j151*_acc[5] + _j152*_k290 + _j56*_k103 + _j63*b1
    cdef double _j154 = _k132*((((xE*xE)*(xE*xE))*((xE*xE)*(xE*xE))))
    cdef double _j155 = _j122*b3d
    cdef double _j156 = _j112*b2
    cdef double _j157 = _j137*b3
    cdef double _j158 = _j23*b1
    cdef double _j159 = _j0*b1
    cdef double _j160 = _j0*b2
    cdef double _j161 = _j10*b2
    cdef double _j162 = _j16*b3
    cdef double _j163 = _j1*b1
    cdef double _j164 = _j1*_j61
    cdef double _j165 = _j16*b2
    cdef double _j166 = _j10*b1
    cdef double _j167 = _j74*b3
    cdef double _j168 = b1*b2
    cdef double _j169 = (b2*b2)
    cdef double _j170 = _j169*xE
    cdef double _j171 = b2d*xEd
    cdef double _j172 = _j68*xEd
    cdef double _j173 = _j61*b1d
    cdef double _j174 = (b3*b3)
    cdef double _j175 = (b1*b1)
    cdef double _j176 = _k251*b3
    cdef double _j177 = _j36*xEd
    cdef double _j178 = _k339*b3
    cdef double _j179 = _k343*b3
    cdef double _j180 = _j91*b1d
    cdef double _j181 = _k344*xEd
    cdef double _j182 = _k354*b2
    cdef double _j183 = _k356*b1
    cdef double _j184 = _k360*b3
    cdef double _j185 = _j175*xE
    cdef double _j186 = _j36*_k317 + _j68*_k318 + _k86*b1
    cdef double _j187 = _j61*b2
    cdef double _j188 = _j91*b1
    cdef double _j189 = _j175*_j3
    cdef double _j190 = _j169*_j3
    cdef double _j191 = Omega*t - theta
    cdef double _j192 = cos(_j191)
    cdef double _j193 = _j192*_k217
    cdef double _j194 = S_T*_cam0[0]
    cdef double _j195 = _j194 + _k87
    cdef double _j196 = sin(_j191)
    cdef double _j197 = _j195*_j196
    cdef double _j198 = _cam0[1]*_j193 - _j197
    cdef double _j199 = S_T*_j196
    cdef double _j200 = _j192*_j195
    cdef double _j201 = _cam0[1]*_j199 - _j200
    cdef double _j202 = (_cam0[0]*_cam0[0])
    cdef double _j203 = (_cam0[1]*_cam0[1])
    cdef double _j204 = _cam0[0]*_k73 + _j202*_k72 + _j203*_k72 + _k71
    cdef double _j205 = (1.0/(_j204))
    cdef double _j206 = (thetad*thetad)
    cdef double _j207 = _j205*_j206
    cdef double _j208 = _j207*_k180
    cdef double _j209 = (_cam0[0]*_cam0[0]*_cam0[0])
    cdef double _j210 = (_cam0[0]*_cam0[0]*_cam0[0]*_cam0[0])
    cdef double _j211 = (_cam0[1]*_cam0[1]*_cam0[1]*_cam0[1])
    cdef double _j212 = _cam0[0]*_j203
    cdef double _j213 = _j202*_j203
    cdef double _j214 = _cam0[0]*_k67 + _j202*_k69 + _j203*_k66 + _j209*_k68 + _j210*_k64 + _j211*_k64 + _j212*_k68 + _j213*_k65 + _k63
    cdef double _j215 = (1.0/(_j214))
    cdef double _j216 = _cam0[2]*_j215
    cdef double _j217 = _j206*_k202
    cdef double _j218 = _cam0[0]*_j216
    cdef double _j219 = _j206*_k79
    cdef double _j220 = _j203*_j215
    cdef double _j221 = _j206*_j220
    cdef double _j222 = _j212*_j215
    cdef double _j223 = _j206*_j222
    cdef double _j224 = _j202*_j216
    cdef double _j225 = _j206*_k200
    cdef double _j226 = _j205*_k76
    cdef double _j227 = _cam0[1]*_j205
    cdef double _j228 = _j206*_k182
    cdef double _j229 = _j206*_k206
    cdef double _j230 = _cam0[1]*_j215
    cdef double _j231 = _cam0[3]*_j215
    cdef double _j232 = (_cam0[1]*_cam0[1]*_cam0[1])
    cdef double _j233 = (((_cam0[0]*_cam0[0])*(_cam0[0]*_cam0[0]))*_cam0[0])
    cdef double _j234 = _cam0[0]*_j211
    cdef double _j235 = _j203*_j209
    cdef double _j236 = (((_cam0[0]*_cam0[0])*(_cam0[0]*_cam0[0]))*(_cam0[0]*_cam0[0]))*_k185 + _cam0[0]*_k189 + (((_cam0[1]*_cam0[1])*(_cam0[1]*_cam0[1]))*(_cam0[1]*_cam0[1]))*_k185 + _j202*_j211*_k186 + _j202*_k191 + _j203*_j210*_k186 + _j203*_k187 + _j209*_k193 + _j210*_k192 + _j211*_k188 + _j212*_k194 + _j213*_k196 + _j233*_k190 + _j234*_k190 + _j235*_k195 + _k184
    cdef double _j237 = (1.0/(_j236))
    cdef double _j238 = _j206*_j237
    cdef double _j239 = _j232*_j238
    cdef double _j240 = _j215*_j232
    cdef double _j241 = _j206*_j240
    cdef double _j242 = _cam0[0]*_cam0[1]
    cdef double _j243 = _j242*_k210
    cdef double _j244 = _cam0[0]*_j206
    cdef double _j245 = _j244*_k79
    cdef double _j246 = _cam0[0]*_j232
    cdef double _j247 = _j238*_j246
    cdef double _j248 = _cam0[1]*_k405
    cdef double _j249 = _cam0[2]*_j238
    cdef double _j250 = _cam0[1]*_j216
    cdef double _j251 = _cam0[1]*_j202
    cdef double _j252 = _j206*_k78
    cdef double _j253 = _j251*_j252
    cdef double _j254 = _j202*_j232
    cdef double _j255 = _j254*_k203
    cdef double _j256 = _j242*_k406
    cdef double _j257 = _j216*_j242
    cdef double _j258 = _cam0[1]*_j209
    cdef double _j259 = _j258*_k383
    cdef double _j260 = _j251*_k385
    cdef double _j261 = (((_cam0[1]*_cam0[1])*(_cam0[1]*_cam0[1]))*_cam0[1])
    cdef double _j262 = _j238*_k197
    cdef double _j263 = (_cam0[2]*_cam0[2])
    cdef double _j264 = _j238*_j263
    cdef double _j265 = _j264*_k212
    cdef double _j266 = _cam0[2]*_k209
    cdef double _j267 = _cam0[2]*_k370
    cdef double _j268 = _cam0[1]*_j265 + _j239*_j266 + _j242*_j264*_k385 + _j247*_j267 + _j251*_j264*_k384 + _j261*_j262
    cdef double _j269 = _cam0[2]*_j226
    cdef double _j270 = (1.0/(_j204*_j204))
    cdef double _j271 = _j270*(_cam0[0]*_k368 + _k369)
    cdef double _j272 = _cam0[2]*_j271
    cdef double _j273 = _j215*_j263
    cdef double _j274 = _cam0[0]*_j273
    cdef double _j275 = _j203*_j216
    cdef double _j276 = (1.0/(_j214*_j214))
    cdef double _j277 = _j276*(_cam0[0]*_k365 + _j202*_k366 + _j203*_k367 + _j209*_k364 + _j212*_k364 + _k363)
    cdef double _j278 = _j211*_k70
    cdef double _j279 = _j263*_k75
    cdef double _j280 = _j263*_j277
    cdef double _j281 = _cam0[0]*_k80
    cdef double _j282 = _cam0[2]*_j203
    cdef double _j283 = _j282*_k79
    cdef double _j284 = _cam0[2]*_j277
    cdef double _j285 = _j212*_k78
    cdef double _j286 = _j202*_k70
    cdef double _j287 = _j196*_k217
    cdef double _j288 = S_T*_j192
    cdef double _j289 = _j216*_k210
    cdef double _j290 = _cam0[1]*_j289
    cdef double _j291 = _j206*_j273
    cdef double _j292 = (_cam0[2]*_cam0[2]*_cam0[2])
    cdef double _j293 = _j238*_j292
    cdef double _j294 = _j293*_k211
    cdef double _j295 = _cam0[3]*_j206
    cdef double _j296 = _j295*_k79
    cdef double _j297 = _cam0[0]*_k376 + _j202*_k374 + _j203*_k379 + _j209*_k375 + _j210*_k377 + _j211*_k380 + _j212*_k381 + _j213*_k382 + _j233*_k373 + _j234*_k373 + _j235*_k378 + _k372
    cdef double _j298 = (1.0/(_j236*_j236))
    cdef double _j299 = _j261*_j298
    cdef double _j300 = _j297*_j299
    cdef double _j301 = _j206*_k198
    cdef double _j302 = _j206*_j277
    cdef double _j303 = _j232*_k80
    cdef double _j304 = _j257*_k371
    cdef double _j305 = _j295*_k78
    cdef double _j306 = _j300*_k197
    cdef double _j307 = _cam0[1]*_j229
    cdef double _j308 = _cam0[1]*_j206
    cdef double _j309 = _j308*_k201
    cdef double _j310 = _j297*_j298
    cdef double _j311 = _j263*_j310
    cdef double _j312 = _j308*_k207
    cdef double _j313 = _j206*_j310
    cdef double _j314 = _cam0[1]*_j292
    cdef double _j315 = _j314*_k208
    cdef double _j316 = _cam0[3]*_j217
    cdef double _j317 = _cam0[2]*_j206
    cdef double _j318 = _cam0[2]*_j232
    cdef double _j319 = _j318*_k204
    cdef double _j320 = _j318*_k70
    cdef double _j321 = _j277*_j295
    cdef double _j322 = _j203*_k199
    cdef double _j323 = _j206*_j311
    cdef double _j324 = _j232*_k205
    cdef double _j325 = _cam0[2]*_j302
    cdef double _j326 = _j225*_j242
    cdef double _j327 = _j292*_j313
    cdef double _j328 = _j242*_k211
    cdef double _j329 = _j242*_k212
    cdef double _j330 = _cam0[3]*_j245
    cdef double _j331 = _j246*_j266
    cdef double _j332 = _j212*_k70
    cdef double _j333 = _j246*_k203
    cdef double _j334 = _j251*_k197
    cdef double _j335 = _j258*_k197
    cdef double _j336 = _j251*_k213
    cdef double _j337 = _j202*_j295*_k200
    cdef double _j338 = _cam0[2]*_j270
    cdef double _j339 = _j206*_k183
    cdef double _j340 = _j276*(_cam0[1]*_k388 + _j232*_k364 + _j242*_k389 + _j251*_k364)
    cdef double _j341 = _cam0[2]*_j340
    cdef double _j342 = _j206*_j340
    cdef double _j343 = _j263*_j340
    cdef double _j344 = _j295*_j340
    cdef double _j345 = _j211*_j238
    cdef double _j346 = _cam0[1]*_j210*_k373 + _cam0[1]*_k400 + _j232*_k399 + _j242*_k401 + _j246*_k402 + _j251*_k381 + _j254*_k378 + _j258*_k402 + _j261*_k373
    cdef double _j347 = _j299*_j346
    cdef double _j348 = _j347*_k197
    cdef double _j349 = _j298*_j346
    cdef double _j350 = _j263*_j349
    cdef double _j351 = _j206*_j349
    cdef double _j352 = _j206*_j350
    cdef double _j353 = _j292*_j351
    cdef double _j354 = _j240*_k387
    cdef double _j355 = _cam0[3]*thetad
    cdef double _j356 = _j205*_j355
    cdef double _j357 = _cam0[1]*thetad
    cdef double _j358 = _j240*thetad
    cdef double _j359 = _j237*thetad
    cdef double _j360 = _j261*_j359
    cdef double _j361 = _j360*_k383
    cdef double _j362 = _j263*_j359
    cdef double _j363 = _j292*_j359
    cdef double _j364 = _j1*_k221
    cdef double _j365 = _k220*xEd
    cdef double _j366 = xE*xEd
    cdef double _j367 = _cam0[0]*_j192
    cdef double _j368 = _j192*thetad
    cdef double _j369 = _j367*thetad
    cdef double _j370 = _k224*thetad
    cdef double _j371 = _j196*_j370
    cdef double _j372 = _j192*_j206
    cdef double _j373 = _j206*_j288
    cdef double _j374 = _j193*_j206
    cdef double _j375 = _j196*_j206
    cdef double _j376 = _j206*_j287
    cdef double _j377 = _j372*_k219
    cdef double _j378 = _j192*_j370
    cdef double _j379 = _j287*_acc[4] + _j378
    cdef double _j380 = _j196*_k216
    cdef double _j381 = _j3*_k221
    cdef double _j382 = _j0*b3d
    cdef double _j383 = _j196*_k218
    cdef double _j384 = _cam0[0]*_j196
    cdef double _j385 = _cam0[1]*_k224
    cdef double _j386 = _j196*thetad
    cdef double _j387 = _j384*thetad
    cdef double _j388 = _cam0[1]*_j368
    cdef double _j389 = _cam0[2]*_k225
    cdef double _j390 = _cam0[1]*_j386
    cdef double _j391 = _j192*_k423
    cdef double _j392 = Omega*_j197
    cdef double _j393 = _cam0[1]*_j391 + _j392
    cdef double _j394 = _j196*_k424
    cdef double _j395 = Omega*_j200
    cdef double _j396 = _cam0[1]*_j394 + _j395
    cdef double _j397 = _j3*_k85
    cdef double _j398 = _j199*thetad
    _R[0] = _j2*_k101 + _j4*_k92 + _j5*_j8 + _k93*xE
    _R[1] = _j11*_k100 + _j12*_j14 + _j2*_k90 + _j4*_k106 + _j9
    _R[2] = _j11*_k88 + _j15 + _j17*_k97 + _j2*_k103 + _j21*_k233
    _R[3] = _j22*_k160 + _j24*_k165 + _j26*_k166 + _j27*_j28 + _j29*_j30 + _j40*_j5 + _j41*_j44 + _j45*_j46 + _j47*_k243*(_j3*_k1 + _j42 + _k0) + _j48*_acc[3] + _j49*_k245 + _j50*_k246 + _j52*_k247 + _j54*_k248 + _j55*_k249 + _j56*_k250 + _j57*_k251 + _j58*_k251 + _j59*_k252 + _j60*_k83*(_k234*xE + m_r) + _j61*_j62 + _j72
    _R[4] = 0.0
    _R[5] = _j25*_k96 + _j51*_k91 + _j73*xEd
    _R[6] = _j23*_k98 + _j25*_k90 + _j51*_k105
    _R[7] = _j23*_k89 + _j25*_k104 + _j75*xEd
    _R[8] = _j73*b1d + _j75*b3d + _j76*_k104 + _j77*_k105 + _j78*_k89 + _j79*_k90 + _j80*_k91 + _j81*_k96 + _j82*_k98 + _j83*_k253 + _j84*_k254 + _j85*_k255 + _j86*_k256 + _j88*_k91 + _j93
    _R[9] = 0.0
    _R[10] = _j11*_k119 + _j12*_j95 + _j2*_k111 + _j9
    _R[11] = _j0*_k112 + _j11*_k109 + _j17*_k117 + _j2*_k124 + _j21*_k258
    _R[12] = _j100*_j98 + _j11*_k122 + _j17*_k107 + _j96 + _j97*_k115
    _R[13] = _j101*_j28 + _j102*_acc[1] + _j103*_j104 + _j109*_j12 + _j110*_j29 + _j111*_j5 + _j113*_k270 + _j114*_k271 + _j115*_k271 + _j116*_k272 + _j117*_k273 + _j121 + _j22*_k90 + _j24*_k266 + _j26*_k267 + _j27*_k241*(_j43 + _k20) + _j46*_j60 + _j50*_k174 + _j52*_k274 + _j56*_k268 + _j66*_k172 + _j67*_k253
    _R[14] = 0.0
    _R[15] = _j23*_k118 + _j25*_k110 + _j51*_k120
    _R[16] = _j112*_k114 + _j23*_k109 + _j25*_k123
    _R[17] = _j112*_k108 + _j123*xEd + _j23*_k121
    _R[18] = _j123*b3d + _j124*_k108 + _j125*_k114 + _j126*_k118 + _j127*_k275 + _j128*_k97 + _j130 + _j78*_k121 + _j79*_k123 + _j80*_k120 + _j81*_k110 + _j82*_k109 + _j85*_k110 + _j89*_k104 + _j90*_k88
    _R[19] = 0.0
    _R[20] = _j11*_k129 + _j132*_j20 + _j15 + _j17*_k136
    _R[21] = _j11*_k141 + _j134*_j98 + _j17*_k127 + _j96 + _j97*_k131
    _R[22] = _j1*_j122*_k133 + _j136*_j74*_acc[3] + _j16*_k130 + _j17*_k139 + _j97*_k125
    _R[23] = _j101*_j44 + _j102*_acc[0] + _j103*_k281*(_j3*_k30 + _j42 + _k31) + _j104*_j74*_acc[1] + _j110*_j139 + _j113*_k286 + _j114*_k288 + _j115*_k287 + _j116*_k289 + _j117*_k89 + _j12*_j144 + _j120*_k285 + _j122*_k280*_acc[2]*(_k279*xE + m_r) + _j138*_k157 + _j145*_j20 + _j146*_k291 + _j147*_k292 + _j148*_k292 + _j149*_k293 + _j150*_k294 + _j153 + _j24*_k295 + _j26*_k296 + _j55*_k295 + _j67*_k297
    _R[24] = 0.0
    _R[25] = _j112*_k135 + _j23*_k128 + _j25*_k137
    _R[26] = _j112*_k127 + _j137*_k134 + _j23*_k140
    _R[27] = _j112*_k138 + _j137*_k126 + _j154*xEd
    _R[28] = _j122*_k134*b2d + _j124*_k138 + _j125*_k127 + _j126*_k128 + _j127*_k128 + _j128*_k107 + _j129*_k298 + _j154*b3d + _j155*_k126 + _j156*_k115 + _j157*_k299 + _j158*_k300 + _j74*_k135*b1d + _j81*_k137 + _j82*_k140 + _j84*_k302 + _j90*_k301
    _R[29] = 0.0
    _R[30] = _j132*_j41 + _j163*_k102 + _j164*_k154 + _j22*_k250 + _j24*_k171 + _j26*_k168 + _j45*_j95 + _j47*_j8 + _j49*_k147 + _j50*_k152 + _j52*_k153 + _j54*_k154 + _j55*_k165 + _j56*_k173 + _j57*_k176 + _j58*_k103 + _j59*_k177 + _j72 - _acc[3]*(_j0*_k61*b3 + _j152*_k49 + _j159*_k304 + _j160*_k48 + _j161*_k55 + _j162*_k58 + _j61*_k305 + _j87*_k303 + _j91*_k60)
    _R[31] = _j113*_k167 + _j114*_k310 + _j115*_k170 + _j116*_k168 + _j117*_k166 + _j121 + _j134*_j29 + _j14*_j60 + _j19*_j27*_k258 + _j22*_k151 + _j24*_k149 + _j26*_k144 + _j50*_k175 + _j52*_k176 + _j56*_k153 + _j61*_j69 + _j66*_k274 + _j67*_k309 - _acc[3]*(_j152*_k62 + _j159*_k48 + _j160*_k308 + _j161*_k306 + _j162*_k50 + _j165*_k307 + _j166*_k55 + _j167*_k57 + _j87*_k60)
    _R[32] = _j100*_j139 + _j101*_j19*_k233 + _j103*_j136 + _j113*_k148 + _j114*_k146 + _j115*_k149 + _j116*_k152 + _j117*_k147 + _j120*_k314 + _j138*_k169 + _j146*_k315 + _j147*_k164 + _j148*_k167 + _j149*_k171 + _j150*_k165 + _j153 + _j22*_k176 + _j24*_k179 + _j26*_k175 + _j55*_k316 + _j67*_k174 - _acc[3]*(_j122*_k312*b3 + _j159*_k61 + _j16*_k58*b1 + _j161*_k62 + _j162*_k313 + _j165*_k50 + _j166*_k49 + _j167*_k311 + _j74*_k57*b2)
    _R[33] = _j0*_j144*_acc[2] + _j0*_j174*_k341 + _j1*_j170*_k274 + _j1*_j185*_k250 + _j109*_j45 + _j11*_j174*_k335 + _j111*_j3*_acc[1] + _j113*_k353*b3 + _j145*_j41 + _j163*_k177*b2 + _j164*_j176 + _j164*_k344*b2 + _j168*_j4*_k355 + _j168*_k159 + _j169*_j2*_k348 + _j169*_j4*_k336 + _j17*_j174*_k347 + _j170*_k269 + _j171*_j61*_k252 + _j171*_j91*_k361 + _j172*_k252*b1d + _j173*_k345*xEd + _j174*_j2*_k350 + _j175*_j62 + _j177*_k251*b1d + _j178*_j26 + _j179*_j56 + _j180*_j181 + _j182*_j24 + _j183*_j50 + _j184*_j52 - _j186*_acc[5] + _j22*_k340*b3 + _j24*_k338*b3 + _j26*_k348*b2 + _j40*_j47 + _j48*_acc[0] + _j49*_k352*b1 + _j50*_k339*b2 + _j50*_k350*b3 + _j52*_k342*b2 + _j52*_k357*b1 + _j55*_k351*b2 + _j56*_k357*b2 + _j58*_k343*b1 + _j58*_k360*b2 + _j61*_k349*b3 + _j66*_k359*b3 + _j67*_k337*b3 + _j71*b1*b1d + _j83*_k356*b1d + _j84*_k354*b2d + _j88*_k251*b3d + _j88*_k344*b2d + _j88*_k358*b1d + _j91*_k346*b3 - _acc[3]*(_j0*_j169*_k319 + _j10*_j169*_k325 + _j10*_j174*_k331 + _j152*_k323*b2 + _j152*_k329*b1 + _j159*_k322*b3 + _j159*_k328*b2 + _j16*_j174*_k320 + _j160*_k334*b3 + _j162*_k330*b2 + _j174*_j74*_k326 + _j175*_k54 + _j185*_k303 + _j187*_k332 + _j188*_k321 + _j189*_k324 + _j190*_k327 + _j87*_k333*b3 + _k11)
    _R[34] = 0.0
    _R[35] = _j61*_j71 + _j83*_k152 + _j84*_k171 + _j85*_k173 + _j86*_k103 + _j88*_k154 + _j93
    _R[36] = _j127*_k168 + _j128*_k170 + _j130 + _j85*_k153 + _j87*_j92 + _j89*_k176 + _j90*_k144
    _R[37] = _j127*_k152 + _j128*_k149 + _j129*_k148 + _j156*_k167 + _j157*_k169 + _j158*_k171 + _j84*_k179 + _j85*_k103 + _j90*_k175
    _R[38] = _j112*_j174*_k315 + _j124*_k148*b3 + _j124*_k167*b2 + _j125*_k167*b3 + _j126*_k171*b3 + _j155*_k169*b3 + _j159*_k103*b3d + _j168*_j51*_k357 + _j169*_j25*_k310 + _j169*_j51*_k309 + _j173*_k178 + _j174*_j23*_k314 + _j174*_j25*_k316 + _j175*_k102*xEd + _j176*_j88 + _j178*_j90 + _j179*_j85 + _j180*_k177 + _j181*_j188 + _j182*_j84 + _j183*_j83 + _j184*_j89 + _j185*_k154*xEd + _j187*_k252*xEd + _j189*_k250*xEd + _j190*_k274*xEd + _j76*_k152*b1 + _j76*_k175*b2 + _j77*_k153*b1 + _j77*_k176*b2 + _j78*_k149*b2 + _j78*_k171*b1 + _j78*_k179*b3 + _j79*_k144*b2 + _j79*_k168*b1 + _j79*_k175*b3 + _j80*_k103*b3 + _j80*_k153*b2 + _j80*_k173*b1 + _j81*_k152*b3 + _j81*_k168*b2 + _j82*_k149*b3 + _j82*_k170*b2 + _j87*_k154*b1d + _j87*_k177*b2d + _k362*xEd
    _R[39] = 0.0
    _R[40] = 0.0
    _R[41] = 0.0
    _R[42] = 0.0
    _R[43] = 0.0
    _R[44] = _cam0[1]*(_cam0[1]*_j228*_j272 + _cam0[1]*_j291*_k200 + _cam0[1]*_j294 + _cam0[2]*_j255*_j313 + _cam0[3]*_j208 + _cam0[3]*_j221*_k70 + _cam0[3]*_j244*_j271*_k180 + _j206*_j290 + _j206*_j304 + _j216*_j296 + _j218*_j305 + _j232*_j264*_k203 + _j241*_k183 + _j242*_j293*_k383 + _j243*_j325 + _j244*_j306 + _j246*_j302*_k183 + _j251*_j325*_k78 + _j268 + _j271*_j295*_k181 + _j280*_j309 + _j280*_j326 + _j284*_j307 + _j284*_j316 + _j284*_j330 + _j284*_j337 + _j287*_acc[6] + _j288*_acc[5] + _j300*_j301 + _j302*_j303 + _j302*_j320 + _j306*_j317 + _j311*_j312 + _j313*_j315 + _j313*_j319 + _j313*_j331 + _j321*_j322 + _j321*_j332 + _j323*_j324 + _j323*_j329 + _j323*_j333 + _j323*_j335 + _j323*_j336 + _j327*_j328 + _j327*_j334 - _acc[4]*(_cam0[0]*_j272*_k76 + _j203*_j271*_k74 + _j269 + _j272*_k77 + _j273*_k80 + _j274*_k183 + _j275*_k78 + _j277*_j278 + _j277*_j279 + _j277*_j283 + _j280*_j281 + _j280*_j286 + _j284*_j285)) + _cam0[2]*(_cam0[0]*_j265 + _cam0[0]*_j294 + _cam0[1]*_j270*_j296 + _cam0[2]*_j207*_k182 + _cam0[2]*_j243*_j342 + _cam0[2]*_j345*_k394 + _j193*_acc[6] + _j202*_j262*_j292 + _j202*_j264*_k213 + _j203*_j264*_k398 + _j203*_j338*_j339 + _j206*_j275*_k391 + _j209*_j262*_j263 + _j212*_j249*_k403 + _j212*_j264*_k396 + _j213*_j249*_k396 + _j216*_j229 + _j221*_k393 + _j223*_k392 + _j224*_j252 + _j225*_j274 + _j230*_j295*_k80 + _j231*_j242*_j339 + _j234*_j238*_k394 + _j238*_j282*_k397 + _j242*_j270*_j305 + _j244*_j289 + _j244*_j348 + _j246*_j339*_j340 + _j253*_j341 + _j255*_j317*_j349 + _j264*_k207 + _j287*_acc[5] + _j291*_k201 + _j293*_k208 + _j301*_j347 + _j303*_j342 + _j307*_j341 + _j309*_j343 + _j312*_j350 + _j315*_j351 + _j316*_j341 + _j317*_j348 + _j319*_j351 + _j320*_j342 + _j322*_j344 + _j324*_j352 + _j326*_j343 + _j328*_j353 + _j329*_j352 + _j330*_j341 + _j331*_j351 + _j332*_j344 + _j333*_j352 + _j334*_j353 + _j335*_j352 + _j336*_j352 + _j337*_j341 + _j345*_k395 - _acc[4]*(_cam0[1]*_j338*_k390 + _j227*_k386 + _j232*_j270*_k371 + _j242*_j338*_k387 + _j278*_j340 + _j279*_j340 + _j281*_j343 + _j283*_j340 + _j285*_j341 + _j286*_j343 + _j290 + _j304 + _j354)) + _cam0[3]*(_j202*_j225*_j231 + _j206*_j215*_j243 + _j215*_j253 + _j217*_j231 + _j219*_j250 + _j227*_j228 + _j229*_j230 + _j231*_j245 + _j238*_j255 + _j239*_k204 + _j241*_k70 + _j247*_k209 + _j248*_j249 + _j249*_j256 + _j249*_j259 + _j249*_j260 + _j252*_j257 + _j268 - _acc[4]*(_cam0[0]*_j226 + _j205*_k77 + _j216*_k404 + _j218*_k390 + _j220*_k79 + _j222*_k78 + _j224*_k183)) + _cam0[4]*(_cam0[0]*_j208 + _j207*_k181 + _j216*_j217 + _j218*_j219 + _j221*_k199 + _j223*_k70 + _j224*_j225) - _j198*_acc[5] - _j201*_acc[6]
    _R[45] = 0.0
    _R[46] = 0.0
    _R[47] = 0.0
    _R[48] = 0.0
    _R[49] = _cam0[0]*_j289*_j355 + _cam0[0]*_j354*thetad + _cam0[0]*_j356*_k74 + _cam0[0]*_j361 + _cam0[2]*_j246*_j359*_k411 + _cam0[2]*_j358*_k183 + _cam0[2]*_j361 + _j216*_j251*_k371*thetad + _j216*_j355*_k206 + _j220*_j355*_k80 + _j222*_j355*_k183 + _j224*_j355*_k78 + _j232*_j362*_k209 + _j242*_j273*_k78*thetad + _j242*_j363*_k413 + _j246*_j362*_k370 + _j248*_j362 + _j250*_k409*thetad + _j251*_j363*_k383 + _j254*_j267*_j359 + _j256*_j362 + _j257*_k412*thetad + _j259*_j362 + _j260*_j362 + _j269*_j357 + _j273*_j357*_k79 + _j314*_j359*_k410 + _j318*_j359*_k408 + _j356*_k407 + _j358*_k390 + _j360*_k211
    _R[50] = _j1*_k215 + _j65*_acc[3]
    _R[51] = _j119*_acc[3] + _j364*xE
    _R[52] = _j151*_acc[3] + _j4*_k223
    _R[53] = _j1*_j39*_k415 + _j119*_acc[1] + _j151*_acc[2] - _j186*_acc[3] + _j364*b2 + _j365*b1d + _j366*_k414*b2d + _j53*_k415*b3d + _j65*_acc[0]
    _R[54] = _cam0[0]*_j374 + _cam0[1]*_j371 + _cam0[1]*_j375*_k219 + _cam0[1]*(_j199*_j206 + _j288*_acc[4] + _j371 + _j380) + _cam0[2]*_j373 + _cam0[2]*(_j377 + _j379) + _cam0[3]*_j376 + _j192*_k417 - _j198*_acc[4] + _j367*_k418 + _j368*_k419 + _j369*_k226 + _j372*_k416
    _R[55] = _j365*xE
    _R[56] = _j381*xEd
    _R[57] = _j51*_k222
    _R[58] = _j172*_k414 + _j177*_k415 + _j365*b1 + _j381*b2d + _j382*_k222 + _j70*_k220
    _R[59] = _j192*_j385 + _j383 + _j384*_k224 + _j386*_j389 + _j386*_k420 + _j387*_k219 + _j388*_k421
    _R[60] = 0.0
    _R[61] = 0.0
    _R[62] = 0.0
    _R[63] = 0.0
    _R[64] = _cam0[0]*_j371 + _cam0[0]*_j380 + _cam0[1]*_j377 + _cam0[1]*_j378 + _cam0[1]*(_j192*_k216 + _j373 + _j379) + _cam0[2]*_j376 + _cam0[2]*(_j193*_acc[4] + _j375*_k225 + _j386*_k226) + _cam0[3]*_j374 + _j194*_j375 + _j196*_k214 - _j201*_acc[4] + _j375*_k87 + _j383*thetad
    _R[65] = 0.0
    _R[66] = 0.0
    _R[67] = 0.0
    _R[68] = 0.0
    _R[69] = _cam0[1]*_j196*_k226 + _j192*_k218 + _j367*_k224 + _j368*_j389 + _j368*_k420 + _j369*_k219 + _j390*_k422
    _Rt[0] = 0.0
    _Rt[1] = 0.0
    _Rt[2] = 0.0
    _Rt[3] = 0.0
    _Rt[4] = -_j393*_acc[5] - _j396*_acc[6]
    _Rt[5] = _cam0[2]*_j372*_k424 + _j192*_k425 + _j244*_j391 + _j367*_k426 + _j368*_k428 + _j369*_k429 + _j372*_k427 + _j375*_j385 + _j390*_k430 - _j393*_acc[4]
    _Rt[6] = _cam0[2]*_j375*_k423 + _j196*_k431 + _j244*_j394 + _j372*_j385 + _j375*_k433 + _j384*_k432 + _j386*_k434 + _j387*_k430 + _j388*_k430 - _j396*_acc[4]
    _CQ[0] = _j366*_k86
    _CQ[1] = _j397*xEd
    _CQ[2] = _j51*_k84
    _CQ[3] = _j186*xEd + _j382*_k84 + _j397*b2d + _j70*_k86
    _CQ[4] = _cam0[1]*(_j193*thetad + _j391) + _cam0[2]*_j398 + _j198*thetad + _j392
    _CQ[5] = 0.0
    _CQ[6] = 0.0
    _CQ[7] = 0.0
    _CQ[8] = 0.0
    _CQ[9] = _cam0[1]*(_j394 + _j398) + _cam0[2]*_j288*thetad + _j201*thetad + _j395
    _Ct[0] = _j197*_k435 + _j393*thetad
    _Ct[1] = _j200*_k435 + _j396*thetad


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
    cdef double b1 = _y[0]
    cdef double b2 = _y[1]
    cdef double b3 = _y[2]
    cdef double xE = _y[3]
    cdef double theta = _y[4]
    cdef double b1d = _y[5]
    cdef double b2d = _y[6]
    cdef double b3d = _y[7]
    cdef double xEd = _y[8]
    cdef double thetad = _y[9]
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
    return [0.0, 0.0, 0.0, d - r_b - r_r, 0.0, 0.0, 0.0, 0.0, 0.0, Omega]


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
    ctx.cache = &k[436]
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
_model.n_const = 436
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
 "n_q": 5,
 "name": "beam3",
 "options": [
  [
   "modes",
   3
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
 "source_hash": "sha256:a4c10ed1c7eeed79759d12da9812dfb2e08f6d7ceaf7defeb99a53905305f1ad",
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
 "title": "Rayleigh-beam follower in a grooved disk cam, N = 3 assumed modes"
}
"""
MANIFEST = json.loads(_MANIFEST_JSON)
"""States, parameters (defaults, units, ranges), outputs, the cam profile, events, source hash."""

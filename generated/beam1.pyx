# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True, initializedcheck=False
#
# GENERATED FILE - DO NOT EDIT.  Written by `camdyn derive` from camdyn/derive/models/beam.py (camdyn/derive/dae.py);
# edit that and regenerate.  `camdyn derive --check` fails while this file is stale.
#
# Rayleigh-beam follower in a grooved disk cam, N = 1 assumed modes (paper (1)-(20); MODELS.md 'The Rayleigh-beam follower')
# Source hash: sha256:3f4ab16d895e9e319749f072d22ba447c6a5f455041849d614bd9aa187351458
#
# The Rayleigh-beam follower: a translating roller follower in the groove of a rigid disk cam,
# its rod a Rayleigh beam whose free length changes as the cam turns (second source paper,
# "Transverse vibration analysis of a translating roller-follower cam using cycloidal profile
# for RDFD motion"; MODELS.md, "The Rayleigh-beam follower").
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
#   limit the axial multiplier is then the inertia force of the rigid follower with that same
#   Lagrangian, (rho A x_E + m_r + rho A L_g) x_E'' + rho A x_E'^2/2.
# * RDFD motion (paper (1), fig. 2): rise over [0, beta_r], outer dwell to pi, fall over
#   [pi, pi + beta_r], inner dwell to 2 pi, repeated every revolution; S = S_T R(theta) with R
#   the normalized RDFD profile of the chosen cam law (cycloidal by default, any law of the
#   library).  The segment ends are located as events.

import json

from cpython.pycapsule cimport PyCapsule_New
from libc.math cimport atan, cos, fabs, fmod, M_PI, pow, sin

from camdyn.runtime.abi cimport *
from camdyn.generated.camlaws cimport camlaw_eval, camlaw_segment
from camdyn.runtime.linalg cimport solve_inplace

# sizes, known when the integration loops (loops.pxi) are compiled into this module
cdef enum:
    _NQ = 3                  # coordinates Q
    _NC = 2                  # constraints Phi
    _NA = 5                  # unknowns of the augmented system: Q'', lambda
    _ND = 1                  # first dependent coordinate (the last _NC are dependent)
    _NS = 6                 # states: Q, Q'
    _NCAM = 0
    _NM = 0
    _NE = 2
    _NQ1 = 3
    _NE1 = 2

cdef int _EDIR[_NE1]    # crossing direction of each event: +1 upward, -1 downward
_EDIR[0] = 1  # segment_up
_EDIR[1] = -1  # segment_down



cdef inline void _profile(Ctx* ctx, double th, double beta, double* out) noexcept nogil:
    """R(theta) and its derivatives dR/dtheta^k, k = 1..3, of the RDFD motion with the cam law
    ctx.law[0], period 2 pi: rise on [0, beta), outer dwell to pi, fall on [pi, pi + beta),
    inner dwell to 2 pi (paper (1), fig. 2)."""
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
    cdef double _c5 = 4.0*m_r
    cdef double _c6 = 0.5*_c4
    cdef double _c7 = _c4*_c5
    cdef double _c8 = _c3*_c4
    cdef double _c9 = _c2*_c4
    cdef double _c10 = (r_b*r_b*r_b*r_b)
    cdef double _c11 = (r_r*r_r*r_r*r_r)
    cdef double _c12 = (r_r*r_r*r_r)
    cdef double _c13 = 4.0*_c12
    cdef double _c14 = (r_b*r_b*r_b)
    cdef double _c15 = 4.0*_c14
    cdef double _c16 = (r_r*r_r)
    cdef double _c17 = (r_b*r_b)
    cdef double _c18 = 6.0*_c17
    cdef double _c19 = (S_T*S_T*S_T*S_T)
    cdef double _c20 = 12.0*S_T
    cdef double _c21 = _c16*r_b
    cdef double _c22 = _c17*r_r
    cdef double _c23 = (S_T*S_T*S_T)
    cdef double _c24 = 4.0*_c23
    cdef double _c25 = (S_T*S_T)
    cdef double _c26 = _c25*r_b
    cdef double _c27 = 12.0*r_r
    cdef double _c28 = _c17*_c25
    cdef double _c29 = _c16*_c25
    cdef double _c30 = pow(S_T, 8.0)
    cdef double _c31 = _c10*_c19
    cdef double _c32 = _c11*_c19
    cdef double _c33 = _c12*_c19
    cdef double _c34 = _c33*r_b
    cdef double _c35 = _c14*_c19
    cdef double _c36 = 4.0*r_r
    cdef double _c37 = _c17*_c19
    cdef double _c38 = 6.0*_c16
    cdef double _c39 = 2.0*r_b
    cdef double _c40 = 2.0*S_T
    cdef double _c41 = pow(S_T, 6.0)
    cdef double _c42 = 2.0*_c41
    cdef double _c43 = 2.0*_c25
    cdef double _c44 = _c12*_c26
    cdef double _c45 = _c25*r_r
    cdef double _c46 = _c14*_c45
    cdef double _c47 = _c16*_c28
    cdef double _c48 = pow(S_T, 5.0)
    cdef double _c49 = 12.0*_c48
    cdef double _c50 = pow(S_T, 7.0)
    cdef double _c51 = 4.0*_c50
    cdef double _c52 = _c41*r_b
    cdef double _c53 = _c17*_c41
    cdef double _c54 = _c16*_c41
    cdef double _c55 = 8.0*_c23
    cdef double _c56 = _c16*_c23
    cdef double _c57 = 24.0*r_b
    cdef double _c58 = _c23*r_r
    cdef double _c59 = _c17*_c58
    cdef double _c60 = 8.0*_c48
    cdef double _c61 = _c19*r_r
    cdef double _c62 = _c16*_c19
    cdef double _c63 = J_r*_c19
    cdef double _c64 = 2.0*_c19
    cdef double _c65 = r_b*r_r
    cdef double _c66 = 2.0*_c48
    cdef double _c67 = J_r*_c25
    cdef double _c68 = J_r*S_T
    cdef double _c69 = 2.0*r_r
    cdef double _c70 = 3.0*_c16
    cdef double _c71 = 3.0*_c17
    cdef double _c72 = 6.0*r_b
    cdef double _c73 = S_T*r_r
    cdef double _c74 = _c62*r_b
    cdef double _c75 = _c37*r_r
    cdef double _c76 = _c14*_c25
    cdef double _c77 = _c12*_c25
    cdef double _c78 = 6.0*_c48
    cdef double _c79 = _c78*r_b
    cdef double _c80 = 3.0*_c41
    cdef double _c81 = _c58*r_b
    cdef double _c82 = 6.0*_c19
    cdef double _c83 = J_r*_c23
    cdef double _c84 = 2.0*_c83
    cdef double _c85 = (1.0/(d*d))
    cdef double _c86 = 2.0*_c85
    cdef double _c87 = 3.141592653589793*E*_c0
    cdef double _c88 = 2.0*_c3
    cdef double _c89 = pow(r_b, 7.0)
    cdef double _c90 = pow(r_r, 7.0)
    cdef double _c91 = pow(r_r, 6.0)
    cdef double _c92 = 7.0*_c91
    cdef double _c93 = pow(r_b, 6.0)
    cdef double _c94 = 7.0*_c93
    cdef double _c95 = pow(r_r, 5.0)
    cdef double _c96 = 21.0*_c95
    cdef double _c97 = 35.0*_c11
    cdef double _c98 = _c14*_c97
    cdef double _c99 = 35.0*_c10
    cdef double _c100 = _c12*_c99
    cdef double _c101 = pow(r_b, 5.0)
    cdef double _c102 = 21.0*_c101
    cdef double _c103 = S_T*r_b
    cdef double _c104 = 42.0*_c95
    cdef double _c105 = 42.0*_c101
    cdef double _c106 = 105.0*S_T
    cdef double _c107 = _c11*_c17
    cdef double _c108 = 140.0*_c12
    cdef double _c109 = S_T*_c14
    cdef double _c110 = _c10*_c16
    cdef double _c111 = 7.0*_c41
    cdef double _c112 = 105.0*_c11
    cdef double _c113 = 105.0*_c10
    cdef double _c114 = _c12*_c28
    cdef double _c115 = 210.0*_c14
    cdef double _c116 = 21.0*_c48
    cdef double _c117 = _c23*r_b
    cdef double _c118 = 140.0*_c14
    cdef double _c119 = 210.0*_c17
    cdef double _c120 = 6.0*_c95
    cdef double _c121 = 6.0*_c101
    cdef double _c122 = 15.0*_c11
    cdef double _c123 = 20.0*_c14
    cdef double _c124 = _c12*_c123
    cdef double _c125 = 15.0*_c10
    cdef double _c126 = S_T*_c17
    cdef double _c127 = 60.0*_c12
    cdef double _c128 = 20.0*_c12
    cdef double _c129 = 60.0*r_b
    cdef double _c130 = _c41*_c91
    cdef double _c131 = _c41*_c93
    cdef double _c132 = _c41*_c95
    cdef double _c133 = _c101*_c41
    cdef double _c134 = pow(S_T, 9.0)
    cdef double _c135 = pow(S_T, 11.0)
    cdef double _c136 = 3.0*_c25
    cdef double _c137 = 21.0*_c91
    cdef double _c138 = 21.0*_c93
    cdef double _c139 = 63.0*_c95
    cdef double _c140 = 63.0*_c101
    cdef double _c141 = 3.0*_c19
    cdef double _c142 = _c19*r_b
    cdef double _c143 = _c50*r_b
    cdef double _c144 = _c50*r_r
    cdef double _c145 = 105.0*_c50
    cdef double _c146 = _c11*_c145
    cdef double _c147 = _c10*_c145
    cdef double _c148 = pow(S_T, 12.0)
    cdef double _c149 = 7.0*_c148
    cdef double _c150 = 21.0*_c23
    cdef double _c151 = 126.0*_c95
    cdef double _c152 = 126.0*_c101
    cdef double _c153 = 315.0*_c107
    cdef double _c154 = 420.0*_c12
    cdef double _c155 = _c14*_c154
    cdef double _c156 = 315.0*_c10
    cdef double _c157 = _c48*r_b
    cdef double _c158 = _c48*r_r
    cdef double _c159 = 21.0*_c30
    cdef double _c160 = pow(S_T, 10.0)
    cdef double _c161 = 21.0*_c160
    cdef double _c162 = 105.0*_c30
    cdef double _c163 = _c11*r_b
    cdef double _c164 = _c10*r_r
    cdef double _c165 = _c12*_c30
    cdef double _c166 = _c16*_c30
    cdef double _c167 = _c135*r_r
    cdef double _c168 = 21.0*_c135
    cdef double _c169 = _c134*_c16
    cdef double _c170 = 35.0*_c160
    cdef double _c171 = 105.0*_c160
    cdef double _c172 = 63.0*_c19
    cdef double _c173 = 315.0*r_b
    cdef double _c174 = 315.0*r_r
    cdef double _c175 = 630.0*_c12
    cdef double _c176 = 630.0*_c14
    cdef double _c177 = _c41*r_r
    cdef double _c178 = 126.0*_c65
    cdef double _c179 = 63.0*_c50
    cdef double _c180 = 63.0*_c134
    cdef double _c181 = 105.0*_c48
    cdef double _c182 = 420.0*_c14
    cdef double _c183 = _c17*_c48
    cdef double _c184 = 630.0*_c16
    cdef double _c185 = 105.0*_c41
    cdef double _c186 = 315.0*_c30
    cdef double _c187 = 2.0*_c50
    cdef double _c188 = 5.0*_c11
    cdef double _c189 = _c188*r_b
    cdef double _c190 = 5.0*_c10
    cdef double _c191 = _c190*r_r
    cdef double _c192 = 10.0*_c17
    cdef double _c193 = 10.0*_c14
    cdef double _c194 = 30.0*_c16
    cdef double _c195 = 5.0*_c19
    cdef double _c196 = 30.0*_c14
    cdef double _c197 = 30.0*_c50
    cdef double _c198 = _c17*_c197
    cdef double _c199 = 5.0*_c160
    cdef double _c200 = 30.0*_c30
    cdef double _c201 = 60.0*_c14
    cdef double _c202 = 90.0*_c17
    cdef double _c203 = 60.0*_c48
    cdef double _c204 = _c12*_c203
    cdef double _c205 = _c14*_c203
    cdef double _c206 = 15.0*_c41
    cdef double _c207 = 15.0*_c30
    cdef double _c208 = 30.0*_c41
    cdef double _c209 = 90.0*r_r
    cdef double _c210 = 30.0*_c48
    cdef double _c211 = 60.0*_c50
    cdef double _c212 = 6.0*r_r
    cdef double _c213 = 18.0*_c95
    cdef double _c214 = 18.0*_c101
    cdef double _c215 = 45.0*_c32
    cdef double _c216 = 45.0*_c31
    cdef double _c217 = _c12*_c211
    cdef double _c218 = _c14*_c211
    cdef double _c219 = 15.0*_c160
    cdef double _c220 = 18.0*_c23
    cdef double _c221 = 90.0*_c11
    cdef double _c222 = 90.0*_c10
    cdef double _c223 = 180.0*_c12
    cdef double _c224 = 180.0*_c14
    cdef double _c225 = 18.0*_c48
    cdef double _c226 = 18.0*_c50
    cdef double _c227 = 18.0*_c134
    cdef double _c228 = 270.0*_c16
    cdef double _c229 = 45.0*_c41
    cdef double _c230 = 45.0*_c30
    cdef double _c231 = 180.0*_c48
    cdef double _c232 = 180.0*_c50
    cdef double _c233 = (Omega*Omega)
    cdef double _c234 = Omega*_c40
    ctx.k[0] = 0.3333333333333333*_c2  # _k0
    ctx.k[1] = 0.2*_c3  # _k1
    ctx.k[2] = _c4  # _k2
    ctx.k[3] = _c5  # _k3
    ctx.k[4] = _c2  # _k4
    ctx.k[5] = _c3  # _k5
    ctx.k[6] = _c6  # _k6
    ctx.k[7] = L_g*_c3 + m_r  # _k7
    ctx.k[8] = _c7  # _k8
    ctx.k[9] = 1.3333333333333333*_c8  # _k9
    ctx.k[10] = _c9  # _k10
    ctx.k[11] = _c10 + _c11 + _c13*r_b + _c15*r_r + _c16*_c18  # _k11
    ctx.k[12] = _c19  # _k12
    ctx.k[13] = S_T*_c13 + S_T*_c15 + _c20*_c21 + _c20*_c22  # _k13
    ctx.k[14] = _c24*r_b + _c24*r_r  # _k14
    ctx.k[15] = _c26*_c27 + 6.0*_c28 + 6.0*_c29  # _k15
    ctx.k[16] = _c30  # _k16
    ctx.k[17] = _c31 + _c32 + 4.0*_c34 + _c35*_c36 + _c37*_c38  # _k17
    ctx.k[18] = _c16 + _c17 + _c39*r_r  # _k18
    ctx.k[19] = _c25  # _k19
    ctx.k[20] = _c40*r_b + _c40*r_r  # _k20
    ctx.k[21] = _c42  # _k21
    ctx.k[22] = _c10*_c43 + _c11*_c43 + 8.0*_c44 + 8.0*_c46 + 12.0*_c47  # _k22
    ctx.k[23] = _c13*_c48 + _c15*_c48 + _c21*_c49 + _c22*_c49  # _k23
    ctx.k[24] = _c51*r_b + _c51*r_r  # _k24
    ctx.k[25] = _c27*_c52 + 6.0*_c53 + 6.0*_c54  # _k25
    ctx.k[26] = _c12*_c55 + _c14*_c55 + _c56*_c57 + 24.0*_c59  # _k26
    ctx.k[27] = _c60*r_b + _c60*r_r  # _k27
    ctx.k[28] = 12.0*_c37 + _c57*_c61 + 12.0*_c62  # _k28
    ctx.k[29] = _c63  # _k29
    ctx.k[30] = _c41  # _k30
    ctx.k[31] = _c37 + _c62 + _c64*_c65  # _k31
    ctx.k[32] = _c64  # _k32
    ctx.k[33] = _c26*_c36 + 2.0*_c28 + 2.0*_c29  # _k33
    ctx.k[34] = _c66*r_b + _c66*r_r  # _k34
    ctx.k[35] = _c67  # _k35
    ctx.k[36] = r_b + r_r  # _k36
    ctx.k[37] = _c23  # _k37
    ctx.k[38] = _c26 + _c45  # _k38
    ctx.k[39] = -2.0*_c68  # _k39
    ctx.k[40] = _c26*_c69 + _c28 + _c29  # _k40
    ctx.k[41] = _c23*_c39 + 2.0*_c58  # _k41
    ctx.k[42] = 2.0*_c67  # _k42
    ctx.k[43] = _c12 + _c14 + _c70*r_b + _c71*r_r  # _k43
    ctx.k[44] = S_T*_c70 + S_T*_c71 + _c72*_c73  # _k44
    ctx.k[45] = 3.0*_c26 + 3.0*_c45  # _k45
    ctx.k[46] = _c50  # _k46
    ctx.k[47] = _c33 + _c35 + 3.0*_c74 + 3.0*_c75  # _k47
    ctx.k[48] = _c66  # _k48
    ctx.k[49] = _c18*_c45 + _c26*_c38 + 2.0*_c76 + 2.0*_c77  # _k49
    ctx.k[50] = _c48*_c70 + _c48*_c71 + _c79*r_r  # _k50
    ctx.k[51] = _c80*r_b + _c80*r_r  # _k51
    ctx.k[52] = _c18*_c23 + 6.0*_c56 + 12.0*_c81  # _k52
    ctx.k[53] = _c82*r_b + _c82*r_r  # _k53
    ctx.k[54] = -_c84  # _k54
    ctx.k[55] = -_c85  # _k55
    ctx.k[56] = -_c86  # _k56
    ctx.k[57] = -12.0*m_r  # _k57
    ctx.k[58] = -6.0*m_r  # _k58
    ctx.k[59] = -3.0*_c87  # _k59
    ctx.k[60] = -3.0*_c3  # _k60
    ctx.k[61] = -_c88  # _k61
    ctx.k[62] = -3.0*_c2  # _k62
    ctx.k[63] = 0.3333333333333333*_c4  # _k63
    ctx.k[64] = -_c7  # _k64
    ctx.k[65] = -_c6*_c87  # _k65
    ctx.k[66] = -8.0*_c4*m_r  # _k66
    ctx.k[67] = -0.5*_c3  # _k67
    ctx.k[68] = -_c4*_c88  # _k68
    ctx.k[69] = -_c2*_c6  # _k69
    ctx.k[70] = -2.6666666666666665*_c8  # _k70
    ctx.k[71] = -2.0*_c9  # _k71
    ctx.k[72] = _c68  # _k72
    ctx.k[73] = _c100 + _c102*_c16 + _c17*_c96 + _c89 + _c90 + _c92*r_b + _c94*r_r + _c98  # _k73
    ctx.k[74] = S_T*_c92 + S_T*_c94 + _c103*_c104 + _c105*_c73 + _c106*_c107 + _c106*_c110 + _c108*_c109  # _k74
    ctx.k[75] = _c111*r_b + _c111*r_r  # _k75
    ctx.k[76] = _c102*_c25 + _c112*_c26 + _c113*_c45 + 210.0*_c114 + _c115*_c29 + _c25*_c96  # _k76
    ctx.k[77] = _c116*_c16 + _c116*_c17 + 42.0*_c48*_c65  # _k77
    ctx.k[78] = _c108*_c117 + _c118*_c58 + _c119*_c56 + _c23*_c97 + _c23*_c99  # _k78
    ctx.k[79] = 35.0*_c33 + 35.0*_c35 + 105.0*_c74 + 105.0*_c75  # _k79
    ctx.k[80] = _c120*r_b + _c121*r_r + _c122*_c17 + _c124 + _c125*_c16 + _c91 + _c93  # _k80
    ctx.k[81] = S_T*_c120 + S_T*_c121 + 30.0*_c10*_c73 + 30.0*_c103*_c11 + 60.0*_c109*_c16 + _c126*_c127  # _k81
    ctx.k[82] = _c78*r_r + _c79  # _k82
    ctx.k[83] = _c122*_c25 + _c125*_c25 + 60.0*_c44 + 60.0*_c46 + 90.0*_c47  # _k83
    ctx.k[84] = 15.0*_c37 + 30.0*_c61*r_b + 15.0*_c62  # _k84
    ctx.k[85] = _c123*_c23 + _c128*_c23 + _c129*_c56 + 60.0*_c59  # _k85
    ctx.k[86] = pow(S_T, 13.0)  # _k86
    ctx.k[87] = _c100*_c41 + 7.0*_c130*r_b + 7.0*_c131*r_r + 21.0*_c132*_c17 + 21.0*_c133*_c16 + _c41*_c89 + _c41*_c90 + _c41*_c98  # _k87
    ctx.k[88] = 3.0*_c134  # _k88
    ctx.k[89] = 3.0*_c135  # _k89
    ctx.k[90] = _c112*_c76 + _c113*_c77 + _c136*_c89 + _c136*_c90 + _c137*_c26 + _c138*_c45 + _c139*_c28 + _c140*_c29  # _k90
    ctx.k[91] = 105.0*_c12*_c31 + _c137*_c142 + _c138*_c61 + _c139*_c37 + 105.0*_c14*_c32 + _c140*_c62 + _c141*_c89 + _c141*_c90  # _k91
    ctx.k[92] = _c104*_c143 + _c105*_c144 + _c108*_c14*_c50 + _c146*_c17 + _c147*_c16 + _c50*_c92 + _c50*_c94  # _k92
    ctx.k[93] = _c149*r_b + _c149*r_r  # _k93
    ctx.k[94] = _c117*_c151 + _c150*_c91 + _c150*_c93 + _c152*_c58 + _c153*_c23 + _c155*_c23 + _c156*_c56  # _k94
    ctx.k[95] = 315.0*_c110*_c48 + _c116*_c91 + _c116*_c93 + _c151*_c157 + _c152*_c158 + _c153*_c48 + _c155*_c48  # _k95
    ctx.k[96] = _c159*r_b + _c159*r_r  # _k96
    ctx.k[97] = _c161*r_b + _c161*r_r  # _k97
    ctx.k[98] = _c102*_c30 + _c115*_c166 + _c119*_c165 + _c162*_c163 + _c162*_c164 + _c30*_c96  # _k98
    ctx.k[99] = _c16*_c168 + 42.0*_c167*r_b + _c168*_c17  # _k99
    ctx.k[100] = _c108*_c134*r_b + _c118*_c134*r_r + _c119*_c169 + _c134*_c97 + _c134*_c99  # _k100
    ctx.k[101] = _c12*_c170 + _c14*_c170 + _c171*_c21 + _c171*_c22  # _k101
    ctx.k[102] = _c101*_c172 + _c172*_c95 + _c173*_c32 + _c174*_c31 + _c175*_c37 + _c176*_c62  # _k102
    ctx.k[103] = 315.0*_c11*_c52 + 63.0*_c132 + 63.0*_c133 + _c156*_c177 + _c175*_c53 + _c176*_c54  # _k103
    ctx.k[104] = _c16*_c179 + _c17*_c179 + _c178*_c50  # _k104
    ctx.k[105] = _c134*_c178 + _c16*_c180 + _c17*_c180  # _k105
    ctx.k[106] = _c10*_c181 + _c11*_c181 + _c154*_c157 + _c158*_c182 + _c183*_c184  # _k106
    ctx.k[107] = _c143*_c154 + _c144*_c182 + _c146 + _c147 + _c17*_c184*_c50  # _k107
    ctx.k[108] = _c12*_c185 + _c14*_c185 + _c173*_c54 + _c174*_c53  # _k108
    ctx.k[109] = _c12*_c162 + _c14*_c162 + _c186*_c21 + _c186*_c22  # _k109
    ctx.k[110] = -J_r*_c187  # _k110
    ctx.k[111] = _c48  # _k111
    ctx.k[112] = _c26*_c70 + _c45*_c71 + _c76 + _c77  # _k112
    ctx.k[113] = _c23*_c70 + _c23*_c71 + _c58*_c72  # _k113
    ctx.k[114] = _c141*r_b + _c141*r_r  # _k114
    ctx.k[115] = _c84  # _k115
    ctx.k[116] = _c83  # _k116
    ctx.k[117] = -_c67  # _k117
    ctx.k[118] = -_c63  # _k118
    ctx.k[119] = _c101 + _c12*_c192 + _c16*_c193 + _c189 + _c191 + _c95  # _k119
    ctx.k[120] = S_T*_c188 + S_T*_c190 + _c103*_c128 + _c123*_c73 + _c126*_c194  # _k120
    ctx.k[121] = _c195*r_b + _c195*r_r  # _k121
    ctx.k[122] = 30.0*_c17*_c45 + _c194*_c26 + 10.0*_c76 + 10.0*_c77  # _k122
    ctx.k[123] = _c192*_c23 + 10.0*_c56 + 20.0*_c81  # _k123
    ctx.k[124] = _c135  # _k124
    ctx.k[125] = 10.0*_c12*_c53 + _c132 + _c133 + _c189*_c41 + _c191*_c41 + _c193*_c54  # _k125
    ctx.k[126] = 3.0*_c50  # _k126
    ctx.k[127] = _c101*_c136 + 30.0*_c114 + _c122*_c26 + _c125*_c45 + _c136*_c95 + _c196*_c29  # _k127
    ctx.k[128] = _c101*_c141 + 30.0*_c12*_c37 + _c141*_c95 + _c196*_c62 + 15.0*_c31*r_r + 15.0*_c32*r_b  # _k128
    ctx.k[129] = _c123*_c144 + _c128*_c143 + _c16*_c198 + _c188*_c50 + _c190*_c50  # _k129
    ctx.k[130] = _c199*r_b + _c199*r_r  # _k130
    ctx.k[131] = 10.0*_c165 + _c193*_c30 + _c200*_c21 + _c200*_c22  # _k131
    ctx.k[132] = _c134*_c192 + 20.0*_c134*_c65 + 10.0*_c169  # _k132
    ctx.k[133] = _c117*_c127 + _c122*_c23 + _c125*_c23 + _c201*_c58 + _c202*_c56  # _k133
    ctx.k[134] = _c122*_c48 + _c125*_c48 + 90.0*_c16*_c183 + _c204*r_b + _c205*r_r  # _k134
    ctx.k[135] = _c206*r_b + _c206*r_r  # _k135
    ctx.k[136] = _c207*r_b + _c207*r_r  # _k136
    ctx.k[137] = 30.0*_c33 + 30.0*_c35 + 90.0*_c74 + 90.0*_c75  # _k137
    ctx.k[138] = _c12*_c208 + _c14*_c208 + _c209*_c53 + 90.0*_c54*r_b  # _k138
    ctx.k[139] = _c16*_c210 + _c17*_c210 + _c203*_c65  # _k139
    ctx.k[140] = _c16*_c197 + _c198 + _c211*_c65  # _k140
    ctx.k[141] = -J_r*_c78  # _k141
    ctx.k[142] = -3.0*_c67  # _k142
    ctx.k[143] = _c141  # _k143
    ctx.k[144] = _c212*_c26 + 3.0*_c28 + 3.0*_c29  # _k144
    ctx.k[145] = _c42*_c65 + _c53 + _c54  # _k145
    ctx.k[146] = _c23*_c72 + 6.0*_c58  # _k146
    ctx.k[147] = _c187*r_r + _c39*_c50  # _k147
    ctx.k[148] = 2.0*_c63  # _k148
    ctx.k[149] = _c148  # _k149
    ctx.k[150] = _c122*_c53 + _c124*_c41 + _c125*_c54 + _c130 + _c131 + _c132*_c72 + _c133*_c212  # _k150
    ctx.k[151] = 3.0*_c30  # _k151
    ctx.k[152] = 3.0*_c160  # _k152
    ctx.k[153] = 45.0*_c10*_c29 + 45.0*_c11*_c28 + _c127*_c76 + _c136*_c91 + _c136*_c93 + _c213*_c26 + _c214*_c45  # _k153
    ctx.k[154] = _c127*_c35 + _c141*_c91 + _c141*_c93 + _c142*_c213 + _c16*_c216 + _c17*_c215 + _c214*_c61  # _k154
    ctx.k[155] = _c120*_c50 + _c121*_c50 + _c16*_c218 + _c163*_c197 + _c164*_c197 + _c17*_c217  # _k155
    ctx.k[156] = _c135*_c72 + 6.0*_c167  # _k156
    ctx.k[157] = _c122*_c30 + _c125*_c30 + _c129*_c165 + _c166*_c202 + _c201*_c30*r_r  # _k157
    ctx.k[158] = _c16*_c219 + 30.0*_c160*_c65 + _c17*_c219  # _k158
    ctx.k[159] = _c101*_c220 + _c117*_c221 + _c17*_c223*_c23 + _c220*_c95 + _c222*_c58 + _c224*_c56  # _k159
    ctx.k[160] = _c101*_c225 + _c157*_c221 + _c158*_c222 + _c16*_c224*_c48 + _c183*_c223 + _c225*_c95  # _k160
    ctx.k[161] = _c226*r_b + _c226*r_r  # _k161
    ctx.k[162] = _c227*r_b + _c227*r_r  # _k162
    ctx.k[163] = _c123*_c134 + _c128*_c134 + _c129*_c169 + 60.0*_c134*_c22  # _k163
    ctx.k[164] = _c215 + _c216 + _c228*_c37 + 180.0*_c34 + 180.0*_c35*r_r  # _k164
    ctx.k[165] = _c10*_c229 + _c11*_c229 + _c177*_c224 + _c223*_c52 + _c228*_c53  # _k165
    ctx.k[166] = _c209*_c52 + 45.0*_c53 + 45.0*_c54  # _k166
    ctx.k[167] = _c16*_c230 + _c17*_c230 + 90.0*_c30*_c65  # _k167
    ctx.k[168] = _c204 + _c205 + _c21*_c231 + _c22*_c231  # _k168
    ctx.k[169] = _c21*_c232 + _c217 + _c218 + _c22*_c232  # _k169
    ctx.k[170] = 6.0*J_r*_c41  # _k170
    ctx.k[171] = _c233*r_b + _c233*r_r  # _k171
    ctx.k[172] = _c86  # _k172
    ctx.k[173] = S_T*_c233  # _k173
    ctx.k[174] = -S_T  # _k174
    ctx.k[175] = -Omega*_c39 - Omega*_c69  # _k175
    ctx.k[176] = _c40  # _k176
    ctx.k[177] = 4.0*_c85  # _k177
    ctx.k[178] = -_c234  # _k178
    ctx.k[179] = -_c40  # _k179
    ctx.k[180] = _c234  # _k180
    ctx.k[181] = -d  # _k181
    ctx.k[182] = -Omega  # _k182
    ctx.k[183] = _c85  # _k183


cdef inline void _system(double t, const double* _y, double* _A, double* _b, double* _ph,
                         double* _phd, Ctx* ctx) noexcept nogil:
    """The augmented matrix [[M, Phi_Q^T], [Phi_Q, 0]] (row-major, _NA x _NA), the right side
    [f; gamma] (paper (20)), and Phi, Phi' at (t, Q, Q')."""
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
    cdef double b1 = _y[0]
    cdef double xE = _y[1]
    cdef double theta = _y[2]
    cdef double b1d = _y[3]
    cdef double xEd = _y[4]
    cdef double thetad = _y[5]
    cdef double _cam0[4]
    _profile(ctx, theta, beta_r, _cam0)

    cdef double _s0 = (xE*xE*xE)
    cdef double _s1 = (xE*xE)
    cdef double _s2 = _s1*b1
    cdef double _s3 = _k6*_s2*(_k3*xE + _k4 + _k5*_s1)
    cdef double _s4 = (b1*b1)
    cdef double _s5 = _s4*xE
    cdef double _s6 = _s1*_s4
    cdef double _s7 = (_cam0[1]*_cam0[1])
    cdef double _s8 = (_cam0[0]*_cam0[0])
    cdef double _s9 = _cam0[0]*_k20 + _k18 + _k19*_s8
    cdef double _s10 = _s7/_s9
    cdef double _s11 = _cam0[0]*_s10
    cdef double _s12 = S_T*_cam0[0]
    cdef double _s13 = _k36 + _s12
    cdef double _s14 = (1.0/(_k37*_s11 + _k38*_s10 + _s13))
    cdef double _s15 = _s10*_s8
    cdef double _s16 = (1.0/(_k12*_s15 + _k40*_s10 + _k41*_s11 + _s9))
    cdef double _s17 = (_cam0[2]*_cam0[2])
    cdef double _s18 = (_cam0[1]*_cam0[1]*_cam0[1]*_cam0[1])
    cdef double _s19 = (_cam0[0]*_cam0[0]*_cam0[0])
    cdef double _s20 = (_cam0[0]*_cam0[0]*_cam0[0]*_cam0[0])
    cdef double _s21 = _cam0[0]*_k13 + _k11 + _k12*_s20 + _k14*_s19 + _k15*_s8
    cdef double _s22 = (1.0/_s21)
    cdef double _s23 = _s18*_s22
    cdef double _s24 = _cam0[0]*_s23
    cdef double _s25 = _s23*_s8
    cdef double _s26 = (1.0/(_k14*_s11 + _k30*_s25 + _k31*_s23 + _k32*_s15 + _k33*_s10 + _k34*_s24 + _s9))
    cdef double _s27 = _s19*_s23
    cdef double _s28 = _s10*_s19
    cdef double _s29 = _cam0[0]*_k44 + _k37*_s19 + _k43 + _k45*_s8
    cdef double _s30 = (1.0/(_k46*_s27 + _k47*_s23 + _k48*_s28 + _k49*_s10 + _k50*_s24 + _k51*_s25 + _k52*_s11 + _k53*_s15 + _s29))
    cdef double _s31 = _s30*_s7
    cdef double _s32 = _s20*_s23
    cdef double _s33 = _s10*_s20
    cdef double _s34 = (1.0/(_k16*_s32 + _k17*_s23 + _k21*_s33 + _k22*_s10 + _k23*_s24 + _k24*_s27 + _k25*_s25 + _k26*_s11 + _k27*_s28 + _k28*_s15 + _s21))
    cdef double _s35 = _k55*_s1
    cdef double _s36 = b1*xE
    cdef double _s37 = Omega*t - theta
    cdef double _s38 = sin(_s37)
    cdef double _s39 = S_T*_cam0[1]
    cdef double _s40 = cos(_s37)
    cdef double _s41 = _s13*_s40
    cdef double _s42 = _s13*_s38
    cdef double _s43 = b1d*xEd
    cdef double _s44 = _s43*xE
    cdef double _s45 = (xEd*xEd)
    cdef double _s46 = _s0*_s43
    cdef double _s47 = _s45*b1
    cdef double _s48 = (thetad*thetad)
    cdef double _s49 = _cam0[3]*_s48
    cdef double _s50 = _cam0[1]*_s48
    cdef double _s51 = (_cam0[1]*_cam0[1]*_cam0[1])*_s48
    cdef double _s52 = pow(_cam0[1], 6.0)
    cdef double _s53 = _s22*_s52
    cdef double _s54 = pow(_cam0[0], 5.0)
    cdef double _s55 = _s10*_s54
    cdef double _s56 = _s23*_s54
    cdef double _s57 = pow(_cam0[0], 6.0)
    cdef double _s58 = _cam0[0]*_k81 + _k30*_s57 + _k80 + _k82*_s54 + _k83*_s8 + _k84*_s20 + _k85*_s19
    cdef double _s59 = _s52/_s58
    cdef double _s60 = _cam0[0]*_s59
    cdef double _s61 = _s59*_s8
    cdef double _s62 = _s19*_s59
    cdef double _s63 = _s20*_s59
    cdef double _s64 = _s54*_s59
    cdef double _s65 = _s57*_s59
    cdef double _s66 = _s10*_s57
    cdef double _s67 = _s23*_s57
    cdef double _s68 = pow(_cam0[0], 7.0)
    cdef double _s69 = _cam0[0]*_k173
    cdef double _s70 = _k175*thetad
    cdef double _s71 = _k178*thetad
    cdef double _s72 = _cam0[0]*_s71
    cdef double _s73 = _cam0[1]*_s40
    cdef double _s74 = _k36*_s48
    cdef double _s75 = _s38*_s48
    cdef double _s76 = _cam0[2]*_k174
    cdef double _s77 = _s40*_s48
    _A[0] = _k2*_s0*(_k0 + _k1*_s1 + m_r*xE)
    _A[1] = _s3
    _A[2] = 0.0
    _A[3] = _s35
    _A[4] = 0.0
    _A[5] = _s3
    _A[6] = _k10*_s5 + _k5*xE + _k7 + _k8*_s6 + _k9*_s0*_s4
    _A[7] = 0.0
    _A[8] = _k56*_s36
    _A[9] = 1.0
    _A[10] = 0.0
    _A[11] = 0.0
    _A[12] = J_r + _cam0[2]*_k39*_s14 + _cam0[2]*_k54*_s31 + _k29*_s18*_s34 + _k35*_s17*_s26 + _k42*_s16*_s7
    _A[13] = _s38*_s39 - _s41
    _A[14] = _s39*_s40 + _s42
    _A[15] = _s35
    _A[16] = _k56*_s36
    _A[17] = _s38*_s39 - _s41
    _A[18] = 0.0
    _A[19] = 0.0
    _A[20] = 0.0
    _A[21] = 1.0
    _A[22] = _s39*_s40 + _s42
    _A[23] = 0.0
    _A[24] = 0.0
    _b[0] = _k63*xE*(_k57*_s1*_s43 + _k58*_s36*_s45 + _k59*b1 + _k60*_s46 + _k61*_s1*_s47 + _k62*_s44)
    _b[1] = _k64*_s45*_s5 + _k65*_s4 + _k66*_s2*_s43 + _k67*_s45 + _k68*_s45*_s6 + _k69*_s4*_s45 + _k70*_s46*b1 + _k71*_s36*_s43
    _b[2] = pow(_cam0[1], 7.0)*_k110*_s48/(_cam0[0]*_k74 + _k100*_s62 + _k101*_s63 + _k102*_s15 + _k103*_s25 + _k104*_s55 + _k105*_s56 + _k106*_s28 + _k107*_s27 + _k108*_s33 + _k109*_s32 + _k46*_s68 + _k73 + _k75*_s57 + _k76*_s8 + _k77*_s54 + _k78*_s19 + _k79*_s20 + _k86*_s59*_s68 + _k87*_s59 + _k88*_s10*_s68 + _k89*_s23*_s68 + _k90*_s10 + _k91*_s23 + _k92*_s60 + _k93*_s65 + _k94*_s11 + _k95*_s24 + _k96*_s66 + _k97*_s67 + _k98*_s61 + _k99*_s64) + pow(_cam0[1], 5.0)*_cam0[2]*_k170*_s48/(_k149*_s65 + _k150*_s59 + _k151*_s66 + _k152*_s67 + _k153*_s10 + _k154*_s23 + _k155*_s60 + _k156*_s64 + _k157*_s61 + _k158*_s63 + _k159*_s11 + _k160*_s24 + _k161*_s55 + _k162*_s56 + _k163*_s62 + _k164*_s15 + _k165*_s25 + _k166*_s33 + _k167*_s32 + _k168*_s28 + _k169*_s27 + _s58) + (_cam0[2]*_cam0[2]*_cam0[2])*_k148*_s50/(_cam0[0]*_k146*_s7 + _cam0[0]*_k147*_s53 + _k143*_s18 + _k143*_s7*_s8 + _k144*_s7 + _k145*_s53 + _k16*_s53*_s8 + _s21) + _cam0[2]*_k117*_s26*_s49 + _cam0[2]*_k118*_s34*_s51 + _cam0[2]*_k142*_s16*_s50 + _k115*_s51/(_k111*_s28 + _k112*_s10 + _k113*_s11 + _k114*_s15 + _s29) + _k116*_s17*_s30*_s50 + _k116*_s31*_s49 + _k141*_s17*_s51/(_cam0[0]*_k120 + _k111*_s54 + _k119 + _k121*_s20 + _k122*_s8 + _k123*_s19 + _k124*_s64 + _k125*_s59 + _k126*_s55 + _k127*_s10 + _k128*_s23 + _k129*_s60 + _k130*_s63 + _k131*_s61 + _k132*_s62 + _k133*_s11 + _k134*_s24 + _k135*_s33 + _k136*_s32 + _k137*_s15 + _k138*_s25 + _k139*_s28 + _k140*_s27 + _k88*_s56) + _k72*_s14*_s49
    _b[3] = _k171*_s38 + _k172*_s47 + _k176*_s48*_s73 + _k177*_s44 + _s12*_s75 + _s38*_s69 + _s38*_s70 + _s38*_s72 + _s38*_s74 + _s71*_s73 + _s75*_s76
    _ph[0] = _s35*b1 + _s42
    _phd[0] = Omega*_s41 + _A[15] * b1d + _A[16] * xEd + _A[17] * thetad
    _b[4] = _cam0[1]*_k179*_s75 + _cam0[1]*_k180*_s38*thetad + _k171*_s40 + _s12*_s77 + _s40*_s69 + _s40*_s70 + _s40*_s72 + _s40*_s74 + _s76*_s77
    _ph[1] = _k181 + _s41 + xE
    _phd[1] = _k182*_s42 + _A[20] * b1d + _A[21] * xEd + _A[22] * thetad


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
    cdef double b1 = _y[0]
    cdef double xE = _y[1]
    cdef double theta = _y[2]
    cdef double b1d = _y[3]
    cdef double xEd = _y[4]
    cdef double thetad = _y[5]
    cdef double _cam0[4]
    _profile(ctx, theta, beta_r, _cam0)

    cdef double _p0 = _k55*(xE*xE)
    cdef double _p1 = S_T*_cam0[0] + _k36
    cdef double _p2 = Omega*t - theta
    cdef double _p3 = sin(_p2)
    cdef double _p4 = _p1*_p3
    cdef double _p5 = cos(_p2)
    cdef double _p6 = _p1*_p5
    cdef double _p7 = S_T*_cam0[1]
    _g[0] = _p0*b1 + _p4
    _g[1] = _k181 + _p6 + xE
    _J[0] = _p0
    _J[1] = _k56*b1*xE
    _J[2] = _p3*_p7 - _p6
    _J[3] = 0.0
    _J[4] = 1.0
    _J[5] = _p4 + _p5*_p7
    _gt[0] = Omega*_p6
    _gt[1] = _k182*_p4


cdef inline int _recover(double t, const double* _y, double* _yc, Ctx* ctx) noexcept nogil:
    """Coordinate partitioning (paper (21)-(27)): the state with its dependent coordinates
    recovered from the independent ones by Newton's method on Phi = 0, started from the values
    the state carries, and their rates from Phi_Q Q' = -dPhi/dt.  0, or 1 without convergence."""
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
    cdef double w = ctx.p[13]
    cdef int i
    cdef bint partitioned = ctx.p[14] > 0.5
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
    """dy/dt = [Q', Q''] from the augmented system (paper (20))."""
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
    cdef double b1 = _yc[0]
    cdef double xE = _yc[1]
    cdef double theta = _yc[2]
    cdef double b1d = _yc[3]
    cdef double xEd = _yc[4]
    cdef double thetad = _yc[5]
    cdef double _cam0[4]
    _profile(ctx, theta, beta_r, _cam0)

    cdef double _o0 = b1*(xE*xE)
    cdef double _o1 = S_T*_cam0[0]
    cdef double _o2 = _k36 + _o1
    cdef double _o3 = Omega*t - theta
    _out[0] = _k183*_o0  # vE
    _out[1] = _k55*_o0 + _o2*sin(_o3)  # Phi1
    _out[2] = _k181 + _o2*cos(_o3) + xE  # Phi2
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


cdef void refresh(Ctx* ctx) noexcept nogil:
    """No modes: the profile is evaluated afresh at every call."""
    ctx.variant = 0


cdef void update_modes(double t, const double* _y, Ctx* ctx) noexcept nogil:
    refresh(ctx)


cdef void events(double t, const double* _y, double* _g, Ctx* ctx) noexcept nogil:
    """Breakpoints: the profile's segment ends."""
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
    cdef double b1 = _y[0]
    cdef double xE = _y[1]
    cdef double theta = _y[2]
    cdef double b1d = _y[3]
    cdef double xEd = _y[4]
    cdef double thetad = _y[5]
    cdef double _cam0[4]
    _profile(ctx, theta, beta_r, _cam0)

    _g[0] = -sin(theta)*sin(beta_r - theta)  # segment_up
    _g[1] = -sin(theta)*sin(beta_r - theta)  # segment_down


cdef void on_event(int _e, double t, double* _y, Ctx* ctx) noexcept nogil:
    """A segment end switches nothing: the step just ends there."""
    refresh(ctx)


cdef void rhs_ptr(double t, const double* _y, double* _dy, Ctx* ctx) noexcept nogil:
    rhs(t, _y, _dy, ctx)


# the integration loops of camdyn.runtime, compiled here with rhs() inlined
include "camdyn/runtime/loops.pxi"


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
    """No cam input with a time-affine argument: the profile follows the state theta."""
    return []


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
_model.n_const = 184
_model.n_cache = 0
_model.prepare = prepare
_model.rhs = rhs_ptr
_model.outputs = outputs
_model.update_modes = update_modes
_model.refresh = refresh
_model.events = events
_model.on_event = on_event
_model.mass_stiffness = mass_stiffness
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
 "dependent": [
  "xE",
  "theta"
 ],
 "events": [
  "segment_up",
  "segment_down"
 ],
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
 "reference": "paper (1)-(20); MODELS.md 'The Rayleigh-beam follower'",
 "residual": null,
 "source_hash": "sha256:3f4ab16d895e9e319749f072d22ba447c6a5f455041849d614bd9aa187351458",
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
 "title": "Rayleigh-beam follower in a grooved disk cam, N = 1 assumed modes"
}
"""
MANIFEST = json.loads(_MANIFEST_JSON)
"""States, parameters (defaults, units, ranges), outputs, the cam profile, events, source hash."""

# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True, initializedcheck=False
#
# GENERATED FILE - DO NOT EDIT.  Written by `camdyn derive` from camdyn/derive/models/beam.py;
# edit that and regenerate.  `camdyn derive --check` fails while this file is stale.
# Derivation key: sha256:bad3e42fbaefbf8e6606e3ba0e2c87fde35824165022b55d519034755339eabf
# Text hash: sha256:de5ddcf99250feb0bc744945f9352873b77149d8f19be87f02cb1a69139645ab
#
# Rayleigh-beam follower in a grooved disk cam, N = 2 assumed modes (paper (1)-(20))
# Source hash: sha256:e6f5b38d9e7b1dd5f920d6438c12a96321d776db2c76dee854114e82adf9e94d
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
    _NQ = 4                  # coordinates Q
    _NC = 2                  # constraints Phi
    _NA = 6                  # unknowns of the augmented system: Q'', lambda
    _ND = 2                  # independent coordinates, beside the _NC dependent ones (_partition)
    _NS = 8                 # states: Q, Q'
    _NCAM = 0
    _NM = 0
    _NE = 2
    _NQ1 = 4
    _NE1 = 2
    _JAC_SYMBOLIC = 1           # jacobian() is exact: A^-1 d(b - A x)/dy at fixed x
    _FT_SYMBOLIC = 1            # and so is its df/dt
    _PROJECTS = 1               # the loops call project() after every accepted step

# the declared coordinate partition (ConstraintSolver.dependent): the dependent coordinates,
# then the independent ones; a run may choose another (Ctx.part, _partition)
cdef int _PART[_NQ]
_PART[0] = 2  # xE, dependent
_PART[1] = 3  # theta, dependent
_PART[2] = 0  # b1
_PART[3] = 1  # b2

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
    cdef double _c6 = 4.0*m_r
    cdef double _c7 = (((d*d)*(d*d))*(d*d))
    cdef double _c8 = (1.0/(_c7))
    cdef double _c9 = 24.0*m_r
    cdef double _c10 = 4.0*_c3
    cdef double _c11 = 9.0*_c2
    cdef double _c12 = 12.0*m_r
    cdef double _c13 = 3.0*_c5
    cdef double _c14 = (r_b*r_b*r_b*r_b)
    cdef double _c15 = (r_r*r_r*r_r*r_r)
    cdef double _c16 = (r_r*r_r*r_r)
    cdef double _c17 = 4.0*r_b
    cdef double _c18 = (r_b*r_b*r_b)
    cdef double _c19 = 4.0*r_r
    cdef double _c20 = (r_r*r_r)
    cdef double _c21 = (r_b*r_b)
    cdef double _c22 = 6.0*_c21
    cdef double _c23 = (S_T*S_T*S_T*S_T)
    cdef double _c24 = 2.0*_c23
    cdef double _c25 = (S_T*S_T)
    cdef double _c26 = _c25*r_r
    cdef double _c27 = 2.0*_c25
    cdef double _c28 = 4.0*S_T
    cdef double _c29 = 12.0*S_T
    cdef double _c30 = _c20*r_b
    cdef double _c31 = _c21*r_r
    cdef double _c32 = _c16*_c28 + _c18*_c28 + _c29*_c30 + _c29*_c31
    cdef double _c33 = (S_T*S_T*S_T)
    cdef double _c34 = _c17*_c33
    cdef double _c35 = _c19*_c33
    cdef double _c36 = _c34 + _c35
    cdef double _c37 = 12.0*r_b
    cdef double _c38 = _c20*_c25
    cdef double _c39 = J_r*_c23
    cdef double _c40 = 2.0*r_b
    cdef double _c41 = _c40*r_r
    cdef double _c42 = 2.0*S_T
    cdef double _c43 = _c42*r_b
    cdef double _c44 = _c42*r_r
    cdef double _c45 = _c43 + _c44
    cdef double _c46 = J_r*_c25
    cdef double _c47 = 2.0*_c46
    cdef double _c48 = _c21*_c46
    cdef double _c49 = _c20*_c46
    cdef double _c50 = _c41*_c46 + _c48 + _c49
    cdef double _c51 = J_r*_c43 + J_r*_c44
    cdef double _c52 = J_r*_c24
    cdef double _c53 = J_r*_c33
    cdef double _c54 = 2.0*r_r
    cdef double _c55 = _c40*_c53 + _c53*_c54
    cdef double _c56 = (d*d)
    cdef double _c57 = (1.0/(_c56))
    cdef double _c58 = (1.0/(d*d*d))
    cdef double _c59 = 3.0*_c58
    cdef double _c60 = 2.0*_c57
    cdef double _c61 = r_b + r_r
    cdef double _c62 = 6.0*m_r
    cdef double _c63 = _c4*m_r
    cdef double _c64 = 3.141592653589793*E*_c0
    cdef double _c65 = 1.5*_c5
    cdef double _c66 = _c3*_c4
    cdef double _c67 = _c3*_c5
    cdef double _c68 = _c2*_c4
    cdef double _c69 = 2.0*_c5
    cdef double _c70 = 3.0*_c8
    cdef double _c71 = _c3*_c8
    cdef double _c72 = 0.5*_c3
    cdef double _c73 = _c2*_c5
    cdef double _c74 = _c2*_c8
    cdef double _c75 = 18.0*m_r
    cdef double _c76 = 0.5*_c4
    cdef double _c77 = _c64*_c8
    cdef double _c78 = 6.0*_c3
    cdef double _c79 = J_r*S_T
    cdef double _c80 = 6.0*(((r_r*r_r)*(r_r*r_r))*r_r)
    cdef double _c81 = 6.0*(((r_b*r_b)*(r_b*r_b))*r_b)
    cdef double _c82 = 15.0*_c15
    cdef double _c83 = 20.0*_c18
    cdef double _c84 = 15.0*_c14
    cdef double _c85 = (((S_T*S_T)*(S_T*S_T))*(S_T*S_T))
    cdef double _c86 = 3.0*_c25
    cdef double _c87 = _c16*_c25
    cdef double _c88 = _c18*_c26
    cdef double _c89 = _c21*_c38
    cdef double _c90 = r_b*r_r
    cdef double _c91 = _c23*_c90
    cdef double _c92 = 3.0*_c23
    cdef double _c93 = 30.0*S_T
    cdef double _c94 = 60.0*S_T
    cdef double _c95 = S_T*_c80 + S_T*_c81 + _c14*_c93*r_r + _c15*_c93*r_b + _c16*_c21*_c94 + _c18*_c20*_c94
    cdef double _c96 = (((S_T*S_T)*(S_T*S_T))*S_T)
    cdef double _c97 = 6.0*_c96
    cdef double _c98 = _c97*r_b
    cdef double _c99 = _c97*r_r
    cdef double _c100 = _c98 + _c99
    cdef double _c101 = _c87*r_b
    cdef double _c102 = 15.0*_c23
    cdef double _c103 = _c16*_c33
    cdef double _c104 = 60.0*_c33
    cdef double _c105 = 12.0*_c33
    cdef double _c106 = 36.0*_c33
    cdef double _c107 = 12.0*_c103 + _c105*_c18 + _c106*_c30 + _c106*_c31
    cdef double _c108 = 12.0*_c96
    cdef double _c109 = _c108*r_b
    cdef double _c110 = _c108*r_r
    cdef double _c111 = 36.0*_c23
    cdef double _c112 = 18.0*_c23
    cdef double _c113 = J_r*_c85
    cdef double _c114 = J_r*_c96
    cdef double _c115 = _c53*r_b
    cdef double _c116 = _c53*r_r
    cdef double _c117 = _c115 + _c116
    cdef double _c118 = 4.0*_c113
    cdef double _c119 = 8.0*_c39
    cdef double _c120 = 4.0*_c39
    cdef double _c121 = _c119*_c90 + _c120*_c20 + _c120*_c21
    cdef double _c122 = _c114*_c17 + _c114*_c19
    cdef double _c123 = _c17*r_r
    cdef double _c124 = _c123*_c46 + _c20*_c47 + _c21*_c47
    cdef double _c125 = _c18*_c53
    cdef double _c126 = J_r*_c103
    cdef double _c127 = 6.0*_c115
    cdef double _c128 = 8.0*_c114
    cdef double _c129 = _c128*r_b + _c128*r_r
    cdef double _c130 = J_r*_c34 + J_r*_c35
    cdef double _c131 = 6.0*_c39
    cdef double _c132 = (Omega*Omega)
    cdef double _c133 = _c132*r_b
    cdef double _c134 = _c132*r_r
    cdef double _c135 = _c133 + _c134
    cdef double _c136 = S_T*_c132
    cdef double _c137 = Omega*_c40 + Omega*_c54
    cdef double _c138 = 6.0*_c58
    cdef double _c139 = Omega*_c42
    cdef double _c140 = 4.0*_c5
    cdef double _c141 = _c8*m_r
    cdef double _c142 = _c5*m_r
    cdef double _c143 = _c26*r_b
    cdef double _c144 = _c21*_c25
    cdef double _c145 = _c105*r_b
    cdef double _c146 = _c105*r_r
    cdef double _c147 = 6.0*_c85
    cdef double _c148 = _c18*_c33
    cdef double _c149 = 180.0*_c33
    cdef double _c150 = 60.0*_c23
    cdef double _c151 = 30.0*_c25
    cdef double _c152 = 30.0*_c96
    cdef double _c153 = 12.0*_c85
    cdef double _c154 = 36.0*_c96
    cdef double _c155 = J_r*_c109 + J_r*_c110
    cdef double _c156 = 8.0*_c33
    cdef double _c157 = 10.0*_c114
    cdef double _c158 = _c39*_c90
    cdef double _c159 = 12.0*_c39
    cdef double _c160 = 24.0*_c158 + _c159*_c20 + _c159*_c21
    cdef double _c161 = 12.0*_c23
    cdef double _c162 = 6.0*_c25
    cdef double _c163 = 72.0*_c33
    cdef double _c164 = 24.0*_c96
    cdef double _c165 = _c164*r_b
    cdef double _c166 = _c164*r_r
    cdef double _c167 = 16.0*_c114
    cdef double _c168 = Omega*S_T
    cdef double _c169 = (Omega*Omega*Omega)
    cdef double _c170 = _c169*r_b + _c169*r_r
    cdef double _c171 = S_T*_c169
    cdef double _c172 = Omega*r_b + Omega*r_r
    cdef double _c173 = 2.0*_c133 + 2.0*_c134
    cdef double _c174 = 2.0*_c136
    ctx.k[0] = 0.3333333333333333*_c2  # _k0
    ctx.k[1] = 0.2*_c3  # _k1
    ctx.k[2] = _c4  # _k2
    ctx.k[3] = 0.16666666666666666*_c3  # _k3
    ctx.k[4] = 0.375*_c2  # _k4
    ctx.k[5] = _c5  # _k5
    ctx.k[6] = _c6  # _k6
    ctx.k[7] = _c2  # _k7
    ctx.k[8] = _c3  # _k8
    ctx.k[9] = 0.5*d  # _k9
    ctx.k[10] = 15.0*m_r  # _k10
    ctx.k[11] = 3.0*_c3  # _k11
    ctx.k[12] = 5.0*_c2  # _k12
    ctx.k[13] = 0.14285714285714285*_c3  # _k13
    ctx.k[14] = 0.45*_c2  # _k14
    ctx.k[15] = _c8  # _k15
    ctx.k[16] = _c9  # _k16
    ctx.k[17] = _c10  # _k17
    ctx.k[18] = _c11  # _k18
    ctx.k[19] = 20.0*m_r  # _k19
    ctx.k[20] = 0.1*d  # _k20
    ctx.k[21] = L_g*_c3 + m_r  # _k21
    ctx.k[22] = 0.6*_c8  # _k22
    ctx.k[23] = _c12  # _k23
    ctx.k[24] = 3.0*_c2  # _k24
    ctx.k[25] = 0.3333333333333333*_c4  # _k25
    ctx.k[26] = _c13  # _k26
    ctx.k[27] = _c14 + _c15 + _c16*_c17 + _c18*_c19 + _c20*_c22  # _k27
    ctx.k[28] = _c23  # _k28
    ctx.k[29] = _c24  # _k29
    ctx.k[30] = _c17*_c26 + _c20*_c27 + _c21*_c27  # _k30
    ctx.k[31] = _c32  # _k31
    ctx.k[32] = _c36  # _k32
    ctx.k[33] = _c22*_c25 + _c26*_c37 + 6.0*_c38  # _k33
    ctx.k[34] = _c39  # _k34
    ctx.k[35] = _c20 + _c21 + _c41  # _k35
    ctx.k[36] = _c25  # _k36
    ctx.k[37] = _c45  # _k37
    ctx.k[38] = _c47  # _k38
    ctx.k[39] = _c50  # _k39
    ctx.k[40] = -_c47  # _k40
    ctx.k[41] = -_c51  # _k41
    ctx.k[42] = -_c52  # _k42
    ctx.k[43] = -_c55  # _k43
    ctx.k[44] = _c55  # _k44
    ctx.k[45] = -_c57  # _k45
    ctx.k[46] = -_c58  # _k46
    ctx.k[47] = -_c59  # _k47
    ctx.k[48] = -_c60  # _k48
    ctx.k[49] = _c61  # _k49
    ctx.k[50] = -_c5*_c62  # _k50
    ctx.k[51] = -_c4*_c6  # _k51
    ctx.k[52] = -2.0*_c63  # _k52
    ctx.k[53] = -_c4*_c64  # _k53
    ctx.k[54] = -_c64*_c65  # _k54
    ctx.k[55] = -_c66  # _k55
    ctx.k[56] = -1.2*_c67  # _k56
    ctx.k[57] = -1.5*_c67  # _k57
    ctx.k[58] = -0.6666666666666666*_c66  # _k58
    ctx.k[59] = -_c68  # _k59
    ctx.k[60] = -_c2*_c69  # _k60
    ctx.k[61] = -_c2*_c65  # _k61
    ctx.k[62] = -_c62*_c8  # _k62
    ctx.k[63] = -_c5*_c6  # _k63
    ctx.k[64] = -_c69*m_r  # _k64
    ctx.k[65] = -_c64*_c70  # _k65
    ctx.k[66] = -_c71  # _k66
    ctx.k[67] = -1.2*_c71  # _k67
    ctx.k[68] = -0.8*_c67  # _k68
    ctx.k[69] = -_c5*_c72  # _k69
    ctx.k[70] = -_c73  # _k70
    ctx.k[71] = -2.25*_c74  # _k71
    ctx.k[72] = -1.5*_c74  # _k72
    ctx.k[73] = -_c72  # _k73
    ctx.k[74] = -_c75*_c8  # _k74
    ctx.k[75] = -_c64*_c76  # _k75
    ctx.k[76] = -_c5*_c75  # _k76
    ctx.k[77] = -_c12*_c5  # _k77
    ctx.k[78] = -8.0*_c63  # _k78
    ctx.k[79] = -4.5*_c77  # _k79
    ctx.k[80] = -_c13*_c64  # _k80
    ctx.k[81] = -2.0*_c66  # _k81
    ctx.k[82] = -4.5*_c71  # _k82
    ctx.k[83] = -_c2*_c76  # _k83
    ctx.k[84] = -_c5*_c78  # _k84
    ctx.k[85] = -_c13*_c3  # _k85
    ctx.k[86] = -3.6*_c71  # _k86
    ctx.k[87] = -4.5*_c74  # _k87
    ctx.k[88] = -2.6666666666666665*_c66  # _k88
    ctx.k[89] = -6.0*_c74  # _k89
    ctx.k[90] = -_c13*_c2  # _k90
    ctx.k[91] = -2.0*_c68  # _k91
    ctx.k[92] = _c46  # _k92
    ctx.k[93] = _c79*r_b + _c79*r_r  # _k93
    ctx.k[94] = -_c46  # _k94
    ctx.k[95] = _c52  # _k95
    ctx.k[96] = _c16*_c83 + _c20*_c84 + _c21*_c82 + _c80*r_b + _c81*r_r + (((r_b*r_b)*(r_b*r_b))*(r_b*r_b)) + (((r_r*r_r)*(r_r*r_r))*(r_r*r_r))  # _k96
    ctx.k[97] = _c85  # _k97
    ctx.k[98] = 3.0*_c85  # _k98
    ctx.k[99] = _c14*_c86 + _c15*_c86 + _c37*_c87 + 12.0*_c88 + 18.0*_c89  # _k99
    ctx.k[100] = _c20*_c92 + _c21*_c92 + 6.0*_c91  # _k100
    ctx.k[101] = _c95  # _k101
    ctx.k[102] = _c100  # _k102
    ctx.k[103] = 60.0*_c101 + _c25*_c82 + _c25*_c84 + 60.0*_c88 + 90.0*_c89  # _k103
    ctx.k[104] = _c102*_c20 + _c102*_c21 + 30.0*_c91  # _k104
    ctx.k[105] = 20.0*_c103 + _c104*_c30 + _c104*_c31 + _c33*_c83  # _k105
    ctx.k[106] = _c107  # _k106
    ctx.k[107] = _c109 + _c110  # _k107
    ctx.k[108] = _c111*_c90 + _c112*_c20 + _c112*_c21  # _k108
    ctx.k[109] = 2.0*_c113  # _k109
    ctx.k[110] = _c114*_c40 + _c114*_c54  # _k110
    ctx.k[111] = _c117  # _k111
    ctx.k[112] = -_c39  # _k112
    ctx.k[113] = -_c117  # _k113
    ctx.k[114] = -_c50  # _k114
    ctx.k[115] = -_c118  # _k115
    ctx.k[116] = -_c121  # _k116
    ctx.k[117] = -_c122  # _k117
    ctx.k[118] = -_c124  # _k118
    ctx.k[119] = _c116*_c22 + 2.0*_c125 + 2.0*_c126 + _c127*_c20  # _k119
    ctx.k[120] = _c123*_c39 + _c20*_c52 + _c21*_c52  # _k120
    ctx.k[121] = -_c129  # _k121
    ctx.k[122] = -_c130  # _k122
    ctx.k[123] = _c122  # _k123
    ctx.k[124] = _c131*_c20 + _c22*_c39 + _c37*_c39*r_r  # _k124
    ctx.k[125] = J_r*_c98 + J_r*_c99  # _k125
    ctx.k[126] = _c135  # _k126
    ctx.k[127] = _c60  # _k127
    ctx.k[128] = _c136  # _k128
    ctx.k[129] = -S_T  # _k129
    ctx.k[130] = -_c137  # _k130
    ctx.k[131] = _c42  # _k131
    ctx.k[132] = 4.0*_c57  # _k132
    ctx.k[133] = _c138  # _k133
    ctx.k[134] = -_c139  # _k134
    ctx.k[135] = -_c42  # _k135
    ctx.k[136] = _c139  # _k136
    ctx.k[137] = -d  # _k137
    ctx.k[138] = -Omega  # _k138
    ctx.k[139] = _c57  # _k139
    ctx.k[140] = _c58  # _k140
    ctx.k[141] = -_c76  # _k141
    ctx.k[142] = -0.2*_c5  # _k142
    ctx.k[143] = 0.4*_c3  # _k143
    ctx.k[144] = -_c4  # _k144
    ctx.k[145] = 0.3333333333333333*_c3  # _k145
    ctx.k[146] = -_c5  # _k146
    ctx.k[147] = 2.0*_c3  # _k147
    ctx.k[148] = _c78  # _k148
    ctx.k[149] = -_c140  # _k149
    ctx.k[150] = -3.0*_c4  # _k150
    ctx.k[151] = -_c69  # _k151
    ctx.k[152] = -_c5*_c9  # _k152
    ctx.k[153] = -_c12*_c4  # _k153
    ctx.k[154] = -_c10*_c4  # _k154
    ctx.k[155] = -6.0*_c73  # _k155
    ctx.k[156] = -1.3333333333333333*_c66  # _k156
    ctx.k[157] = -0.1*_c5  # _k157
    ctx.k[158] = -0.125*_c8  # _k158
    ctx.k[159] = _c59  # _k159
    ctx.k[160] = 0.2857142857142857*_c3  # _k160
    ctx.k[161] = -_c8  # _k161
    ctx.k[162] = 8.0*_c3  # _k162
    ctx.k[163] = -5.0*_c8  # _k163
    ctx.k[164] = -_c70  # _k164
    ctx.k[165] = -30.0*_c141  # _k165
    ctx.k[166] = -_c8*_c9  # _k166
    ctx.k[167] = -16.0*_c142  # _k167
    ctx.k[168] = -9.0*_c77  # _k168
    ctx.k[169] = -6.0*_c71  # _k169
    ctx.k[170] = -_c140*_c3  # _k170
    ctx.k[171] = -_c3*_c69  # _k171
    ctx.k[172] = -_c11*_c8  # _k172
    ctx.k[173] = -_c12*_c8  # _k173
    ctx.k[174] = -_c67  # _k174
    ctx.k[175] = -2.4*_c71  # _k175
    ctx.k[176] = -_c2*_c70  # _k176
    ctx.k[177] = 10.0*_c56  # _k177
    ctx.k[178] = 45.0*d  # _k178
    ctx.k[179] = -0.06666666666666667*_c8  # _k179
    ctx.k[180] = -36.0*_c141  # _k180
    ctx.k[181] = -9.0*_c71  # _k181
    ctx.k[182] = -_c138  # _k182
    ctx.k[183] = 5.0*_c56  # _k183
    ctx.k[184] = 15.0*_c3*_c7  # _k184
    ctx.k[185] = 90.0*d  # _k185
    ctx.k[186] = -54.0*_c141  # _k186
    ctx.k[187] = -72.0*_c141  # _k187
    ctx.k[188] = -36.0*_c142  # _k188
    ctx.k[189] = -16.0*_c63  # _k189
    ctx.k[190] = -18.0*_c71  # _k190
    ctx.k[191] = -18.0*_c67  # _k191
    ctx.k[192] = -12.0*_c67  # _k192
    ctx.k[193] = -8.0*_c66  # _k193
    ctx.k[194] = -18.0*_c74  # _k194
    ctx.k[195] = -_c3  # _k195
    ctx.k[196] = -_c32  # _k196
    ctx.k[197] = -4.0*_c23  # _k197
    ctx.k[198] = -24.0*_c143 - 12.0*_c144 - 12.0*_c38  # _k198
    ctx.k[199] = -_c145 - _c146  # _k199
    ctx.k[200] = -_c36  # _k200
    ctx.k[201] = -_c27  # _k201
    ctx.k[202] = -_c45  # _k202
    ctx.k[203] = -8.0*_c113  # _k203
    ctx.k[204] = -_c120  # _k204
    ctx.k[205] = -_c95  # _k205
    ctx.k[206] = -_c147  # _k206
    ctx.k[207] = -60.0*_c103 - 60.0*_c148 - _c149*_c30 - _c149*_c31  # _k207
    ctx.k[208] = -_c150*_c20 - _c150*_c21 - 120.0*_c91  # _k208
    ctx.k[209] = -120.0*_c101 - _c14*_c151 - _c15*_c151 - 120.0*_c88 - 180.0*_c89  # _k209
    ctx.k[210] = -_c152*r_b - _c152*r_r  # _k210
    ctx.k[211] = -_c153  # _k211
    ctx.k[212] = -_c107  # _k212
    ctx.k[213] = -_c100  # _k213
    ctx.k[214] = -_c111*_c20 - _c111*_c21 - 72.0*_c91  # _k214
    ctx.k[215] = -_c154*r_b - _c154*r_r  # _k215
    ctx.k[216] = _c118  # _k216
    ctx.k[217] = J_r*_c147  # _k217
    ctx.k[218] = _c155  # _k218
    ctx.k[219] = 4.0*_c46  # _k219
    ctx.k[220] = _c120  # _k220
    ctx.k[221] = -8.0*_c143 - 4.0*_c144 - 4.0*_c38  # _k221
    ctx.k[222] = -_c156*r_b - _c156*r_r  # _k222
    ctx.k[223] = _c130  # _k223
    ctx.k[224] = 3.0*_c39  # _k224
    ctx.k[225] = _c131  # _k225
    ctx.k[226] = 6.0*_c116 + _c127  # _k226
    ctx.k[227] = 10.0*_c113  # _k227
    ctx.k[228] = _c157*r_b + _c157*r_r  # _k228
    ctx.k[229] = -J_r*_c153  # _k229
    ctx.k[230] = -_c160  # _k230
    ctx.k[231] = -_c155  # _k231
    ctx.k[232] = -_c161*_c20 - _c161*_c21 - 24.0*_c91  # _k232
    ctx.k[233] = -24.0*_c101 - _c14*_c162 - _c15*_c162 - 24.0*_c88 - 36.0*_c89  # _k233
    ctx.k[234] = -24.0*_c103 - 24.0*_c148 - _c163*_c30 - _c163*_c31  # _k234
    ctx.k[235] = -_c165 - _c166  # _k235
    ctx.k[236] = -J_r*_c165 - J_r*_c166  # _k236
    ctx.k[237] = _c124  # _k237
    ctx.k[238] = J_r*_c145*_c20 + J_r*_c146*_c21 + 4.0*_c125 + 4.0*_c126  # _k238
    ctx.k[239] = _c160  # _k239
    ctx.k[240] = _c51  # _k240
    ctx.k[241] = -_c119*_c20 - _c119*_c21 - 16.0*_c158  # _k241
    ctx.k[242] = -8.0*_c46*_c90 - 4.0*_c48 - 4.0*_c49  # _k242
    ctx.k[243] = _c121  # _k243
    ctx.k[244] = -_c167*r_b - _c167*r_r  # _k244
    ctx.k[245] = -8.0*_c115 - 8.0*_c116  # _k245
    ctx.k[246] = _c129  # _k246
    ctx.k[247] = 12.0*_c58  # _k247
    ctx.k[248] = -_c61  # _k248
    ctx.k[249] = -_c135  # _k249
    ctx.k[250] = -_c136  # _k250
    ctx.k[251] = _c137  # _k251
    ctx.k[252] = _c40 + _c54  # _k252
    ctx.k[253] = _c28  # _k253
    ctx.k[254] = -_c28  # _k254
    ctx.k[255] = _c168  # _k255
    ctx.k[256] = -_c168  # _k256
    ctx.k[257] = _c170  # _k257
    ctx.k[258] = _c171  # _k258
    ctx.k[259] = _c172  # _k259
    ctx.k[260] = -_c173  # _k260
    ctx.k[261] = -_c174  # _k261
    ctx.k[262] = _c174  # _k262
    ctx.k[263] = -_c170  # _k263
    ctx.k[264] = -_c171  # _k264
    ctx.k[265] = -_c172  # _k265
    ctx.k[266] = _c173  # _k266
    ctx.k[267] = -_c132  # _k267


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
    cdef double b1 = _y[0]
    cdef double b2 = _y[1]
    cdef double xE = _y[2]
    cdef double theta = _y[3]
    cdef double b1d = _y[4]
    cdef double b2d = _y[5]
    cdef double xEd = _y[6]
    cdef double thetad = _y[7]
    cdef double _cam0[5]
    _profile(ctx, theta, beta_r, _cam0, 0)

    cdef double _s0 = (xE*xE*xE)
    cdef double _s1 = m_r*xE
    cdef double _s2 = (xE*xE)
    cdef double _s3 = (xE*xE*xE*xE)
    cdef double _s4 = _k5*_s3*(_k3*_s2 + _k4 + _s1)
    cdef double _s5 = b1*(_k6*xE + _k7 + _k8*_s2)
    cdef double _s6 = _k10*xE + _k11*_s2 + _k12
    cdef double _s7 = b2*xE
    cdef double _s8 = _k5*_s2*(_k9*_s5 + 0.2*_s6*_s7)
    cdef double _s9 = (((xE*xE)*(xE*xE))*xE)
    cdef double _s10 = _k17*_s2
    cdef double _s11 = _k15*_s0*(_k20*b1*(_k12 + _k19*xE + _s10) + 0.125*_s7*(_k16*xE + _k18 + _s10))
    cdef double _s12 = (b1*b1)
    cdef double _s13 = _s2*b2
    cdef double _s14 = (b2*b2)
    cdef double _s15 = _s0*_s14
    cdef double _s16 = (_cam0[0]*_cam0[0])
    cdef double _s17 = (_cam0[1]*_cam0[1])
    cdef double _s18 = (1.0/(_cam0[0]*_k37 + _k35 + _k36*_s16 + _k36*_s17))
    cdef double _s19 = _cam0[2]*_s18
    cdef double _s20 = (_cam0[1]*_cam0[1]*_cam0[1]*_cam0[1])
    cdef double _s21 = (_cam0[0]*_cam0[0]*_cam0[0])
    cdef double _s22 = (_cam0[0]*_cam0[0]*_cam0[0]*_cam0[0])
    cdef double _s23 = _cam0[0]*_s17
    cdef double _s24 = _s16*_s17
    cdef double _s25 = (1.0/(_cam0[0]*_k31 + _k27 + _k28*_s20 + _k28*_s22 + _k29*_s24 + _k30*_s17 + _k32*_s21 + _k32*_s23 + _k33*_s16))
    cdef double _s26 = _k34*_s25
    cdef double _s27 = (_cam0[2]*_cam0[2])
    cdef double _s28 = _s25*_s27
    cdef double _s29 = _cam0[0]*_s28
    cdef double _s30 = _cam0[2]*_s25
    cdef double _s31 = _k43*_s30
    cdef double _s32 = _k42*_s30
    cdef double _s33 = _s16*_s27
    cdef double _s34 = _k45*_s2
    cdef double _s35 = _k46*_s0
    cdef double _s36 = b1*xE
    cdef double _s37 = Omega*t - theta
    cdef double _s38 = sin(_s37)
    cdef double _s39 = S_T*_cam0[1]
    cdef double _s40 = S_T*_cam0[0]
    cdef double _s41 = _k49 + _s40
    cdef double _s42 = cos(_s37)
    cdef double _s43 = _s41*_s42
    cdef double _s44 = _s38*_s41
    cdef double _s45 = _s3*xEd
    cdef double _s46 = _s45*b2d
    cdef double _s47 = b1d*xEd
    cdef double _s48 = _s0*_s47
    cdef double _s49 = _s45*b1d
    cdef double _s50 = b2d*xEd
    cdef double _s51 = _s50*_s9
    cdef double _s52 = _s0*_s50
    cdef double _s53 = (xEd*xEd)
    cdef double _s54 = _s0*b2
    cdef double _s55 = _s53*_s54
    cdef double _s56 = _s2*b1
    cdef double _s57 = _s53*b2
    cdef double _s58 = _s3*_s57
    cdef double _s59 = _s53*b1
    cdef double _s60 = _s0*_s59
    cdef double _s61 = _s14*_s2
    cdef double _s62 = _s12*_s53
    cdef double _s63 = (thetad*thetad)
    cdef double _s64 = _cam0[3]*_s63
    cdef double _s65 = _s18*_s64
    cdef double _s66 = _cam0[1]*_s63
    cdef double _s67 = _s30*_s66
    cdef double _s68 = _s30*_s64
    cdef double _s69 = (_cam0[1]*_cam0[1]*_cam0[1])
    cdef double _s70 = _s63*_s69
    cdef double _s71 = _s25*_s70
    cdef double _s72 = _s63/((((_cam0[0]*_cam0[0])*(_cam0[0]*_cam0[0]))*(_cam0[0]*_cam0[0]))*_k97 + (((_cam0[0]*_cam0[0])*(_cam0[0]*_cam0[0]))*_cam0[0])*_k102 + _cam0[0]*_k101 + _cam0[0]*_k102*_s20 + (((_cam0[1]*_cam0[1])*(_cam0[1]*_cam0[1]))*(_cam0[1]*_cam0[1]))*_k97 + _k100*_s20 + _k103*_s16 + _k104*_s22 + _k105*_s21 + _k106*_s23 + _k107*_s17*_s21 + _k108*_s24 + _k96 + _k98*_s16*_s20 + _k98*_s17*_s22 + _k99*_s17)
    cdef double _s73 = (((_cam0[1]*_cam0[1])*(_cam0[1]*_cam0[1]))*_cam0[1])*_s72
    cdef double _s74 = _k109*_s73
    cdef double _s75 = _cam0[1]*_s72
    cdef double _s76 = _s27*_s75
    cdef double _s77 = (_cam0[2]*_cam0[2]*_cam0[2])*_s75
    cdef double _s78 = _s69*_s72
    cdef double _s79 = _cam0[2]*_s78
    cdef double _s80 = _s27*_s78
    cdef double _s81 = _cam0[0]*_k128
    cdef double _s82 = _k130*thetad
    cdef double _s83 = _k134*thetad
    cdef double _s84 = _cam0[0]*_s83
    cdef double _s85 = _cam0[1]*_s42
    cdef double _s86 = _k49*_s63
    cdef double _s87 = _s38*_s63
    cdef double _s88 = _cam0[2]*_k129
    cdef double _s89 = _s42*_s63
    _A[0] = _k2*_s0*(_k0 + _k1*_s2 + _s1)
    _A[1] = _s4
    _A[2] = _s8
    _A[3] = 0.0
    _A[4] = _s34
    _A[5] = 0.0
    _A[6] = _s4
    _A[7] = _k15*_s9*(_k13*_s2 + _k14 + _s1)
    _A[8] = _s11
    _A[9] = 0.0
    _A[10] = _s35
    _A[11] = 0.0
    _A[12] = _s8
    _A[13] = _s11
    _A[14] = _k21 + _k22*_s15*_s6 + _k25*_s12*xE*(_k23*xE + _k24 + _s10) + _k26*_s13*_s5 + _k8*xE
    _A[15] = 0.0
    _A[16] = _k47*_s13 + _k48*_s36
    _A[17] = 1.0
    _A[18] = 0.0
    _A[19] = 0.0
    _A[20] = 0.0
    _A[21] = J_r + _cam0[0]*_k40*_s19 + _k38*_s17*_s18 + _k39*_s28 + _k41*_s19 + _k44*_s29 + _s17*_s31 + _s20*_s26 + _s23*_s32 + _s26*_s33
    _A[22] = _s38*_s39 - _s43
    _A[23] = _s39*_s42 + _s44
    _A[24] = _s34
    _A[25] = _s35
    _A[26] = _k47*_s13 + _k48*_s36
    _A[27] = _s38*_s39 - _s43
    _A[28] = 0.0
    _A[29] = 0.0
    _A[30] = 0.0
    _A[31] = 0.0
    _A[32] = 1.0
    _A[33] = _s39*_s42 + _s44
    _A[34] = 0.0
    _A[35] = 0.0
    _b[0] = _k50*_s46 + _k50*_s55 + _k51*_s48 + _k52*_s53*_s56 + _k53*_s36 + _k54*_s13 + _k55*_s49 + _k56*_s51 + _k57*_s58 + _k58*_s60 + _k59*_s2*_s47 + _k60*_s52 + _k61*_s13*_s53
    _b[1] = _k54*_s56 + _k62*_s51 + _k62*_s58 + _k63*_s49 + _k64*_s60 + _k65*_s54 + _k66*_s50*(((xE*xE)*(xE*xE))*(xE*xE)) + _k67*_s57*_s9 + _k68*_s47*_s9 + _k69*_s3*_s59 + _k70*_s48 + _k71*_s46 + _k72*_s55
    _b[2] = _k51*_s62*xE + _k73*_s53 + _k74*_s15*_s53 + _k74*_s46*b2 + _k75*_s12 + _k76*_s13*_s59 + _k77*_s47*_s54 + _k77*_s52*b1 + _k78*_s47*_s56 + _k79*_s61 + _k80*_s36*b2 + _k81*_s2*_s62 + _k82*_s14*_s3*_s53 + _k83*_s62 + _k84*_s54*_s59 + _k85*_s46*b1 + _k85*_s49*b2 + _k86*_s51*b2 + _k87*_s53*_s61 + _k88*_s48*b1 + _k89*_s50*_s54 + _k90*_s13*_s47 + _k90*_s36*_s57 + _k90*_s50*_s56 + _k91*_s36*_s47
    _b[3] = _cam0[0]*_k115*_s80 + _cam0[0]*_k121*_s79 + _cam0[0]*_k122*_s67 + _cam0[0]*_k123*_s77 + _cam0[0]*_k124*_s76 + _cam0[0]*_k92*_s65 + _cam0[0]*_k95*_s71 + _cam0[0]*_s31*_s64 + _cam0[0]*_s74 + _cam0[2]*_s26*_s70 + _cam0[2]*_s74 + _k109*_s16*_s77 + _k109*_s21*_s76 + _k110*_s73 + _k111*_s17*_s25*_s64 + _k112*_s16*_s68 + _k112*_s29*_s66 + _k113*_s28*_s66 + _k114*_s68 + _k115*_s16*_s79 + _k116*_s79 + _k117*_s80 + _k118*_s67 + _k119*_s76 + _k120*_s77 + _k125*_s33*_s75 + _k44*_s71 + _k93*_s65 + _k94*_s19*_s66 + _s16*_s32*_s66 + _s23*_s26*_s64
    _b[4] = _k126*_s38 + _k127*_s59 + _k131*_s63*_s85 + _k132*_s47*xE + _k133*_s2*_s50 + _k133*_s53*_s7 + _s38*_s81 + _s38*_s82 + _s38*_s84 + _s38*_s86 + _s40*_s87 + _s83*_s85 + _s87*_s88
    _ph[0] = _s34*b1 + _s35*b2 + _s44
    _phd[0] = Omega*_s43 + _A[24] * b1d + _A[25] * b2d + _A[26] * xEd + _A[27] * thetad
    _b[5] = _cam0[1]*_k135*_s87 + _cam0[1]*_k136*_s38*thetad + _k126*_s42 + _s40*_s89 + _s42*_s81 + _s42*_s82 + _s42*_s84 + _s42*_s86 + _s88*_s89
    _ph[1] = _k137 + _s43 + xE
    _phd[1] = _k138*_s44 + _A[30] * b1d + _A[31] * b2d + _A[32] * xEd + _A[33] * thetad


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
    cdef double b1 = _y[0]
    cdef double b2 = _y[1]
    cdef double xE = _y[2]
    cdef double theta = _y[3]
    cdef double b1d = _y[4]
    cdef double b2d = _y[5]
    cdef double xEd = _y[6]
    cdef double thetad = _y[7]
    cdef double _cam0[5]
    _profile(ctx, theta, beta_r, _cam0, 0)

    cdef double _p0 = _k45*(xE*xE)
    cdef double _p1 = _k46*(xE*xE*xE)
    cdef double _p2 = S_T*_cam0[0] + _k49
    cdef double _p3 = Omega*t - theta
    cdef double _p4 = sin(_p3)
    cdef double _p5 = _p2*_p4
    cdef double _p6 = cos(_p3)
    cdef double _p7 = _p2*_p6
    cdef double _p8 = S_T*_cam0[1]
    _g[0] = _p0*b1 + _p1*b2 + _p5
    _g[1] = _k137 + _p7 + xE
    _J[0] = _p0
    _J[1] = _p1
    _J[2] = xE*(_k47*b2*xE + _k48*b1)
    _J[3] = _p4*_p8 - _p7
    _J[4] = 0.0
    _J[5] = 0.0
    _J[6] = 1.0
    _J[7] = _p5 + _p6*_p8
    _gt[0] = Omega*_p7
    _gt[1] = _k138*_p5


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
    cdef double b1 = _yc[0]
    cdef double b2 = _yc[1]
    cdef double xE = _yc[2]
    cdef double theta = _yc[3]
    cdef double b1d = _yc[4]
    cdef double b2d = _yc[5]
    cdef double xEd = _yc[6]
    cdef double thetad = _yc[7]
    cdef double _cam0[5]
    _profile(ctx, theta, beta_r, _cam0, 0)

    cdef double _o0 = (xE*xE)
    cdef double _o1 = S_T*_cam0[0]
    cdef double _o2 = _k49 + _o1
    cdef double _o3 = Omega*t - theta
    _out[0] = _o0*(_k139*b1 + _k140*b2*xE)  # vE
    _out[1] = _k45*_o0*b1 + _k46*b2*(xE*xE*xE) + _o2*sin(_o3)  # Phi1
    _out[2] = _k137 + _o2*cos(_o3) + xE  # Phi2
    _out[3] = _o1  # S
    _out[4] = atan(S_T*_cam0[1]/_o2)  # pressure_angle
    _out[5] = _acc[2]  # xEdd
    _out[6] = _acc[4]  # lambda1
    _out[7] = _acc[5]  # lambda2


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
_SCALE[2] = 0.05
_SCALE[3] = 1.0
_SCALE[4] = 1e-05
_SCALE[5] = 1e-05
_SCALE[6] = 0.05
_SCALE[7] = 1.0


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
    cdef double b1 = _y[0]
    cdef double b2 = _y[1]
    cdef double xE = _y[2]
    cdef double theta = _y[3]
    cdef double b1d = _y[4]
    cdef double b2d = _y[5]
    cdef double xEd = _y[6]
    cdef double thetad = _y[7]
    cdef double _cam0[5]
    _profile(ctx, theta, beta_r, _cam0, 1)

    cdef double _j0 = (xE*xE)
    cdef double _j1 = (xEd*xEd)
    cdef double _j2 = _j0*_j1
    cdef double _j3 = (xE*xE*xE)
    cdef double _j4 = _j1*_j3
    cdef double _j5 = _j0*_acc[2]
    cdef double _j6 = _j0*_k8 + _k6*xE + _k7
    cdef double _j7 = _j6*_k141
    cdef double _j8 = _j0*_k54
    cdef double _j9 = (xE*xE*xE*xE)
    cdef double _j10 = _j1*_j9
    cdef double _j11 = _j3*_acc[2]
    cdef double _j12 = _j0*_k11 + _k10*xE + _k12
    cdef double _j13 = _j12*_k142
    cdef double _j14 = _j3*_acc[0]
    cdef double _j15 = _j9*_acc[1]
    cdef double _j16 = _k146*(_k145*xE + m_r)
    cdef double _j17 = _k147*xE + _k6
    cdef double _j18 = _k9*b1
    cdef double _j19 = _k10 + _k148*xE
    cdef double _j20 = 0.2*b2
    cdef double _j21 = _j12*_j20
    cdef double _j22 = _k146*(_j17*_j18 + _j19*_j20*xE + _j21)
    cdef double _j23 = m_r*xE
    cdef double _j24 = _k149*(_j0*_k3 + _j23 + _k4)
    cdef double _j25 = _j3*_acc[1]
    cdef double _j26 = _j0*_acc[0]
    cdef double _j27 = _k151*xE*(_j18*_j6 + _j21*xE)
    cdef double _j28 = _j3*xEd
    cdef double _j29 = _j28*b2d
    cdef double _j30 = _j0*xEd
    cdef double _j31 = _j30*b1d
    cdef double _j32 = _j28*b1d
    cdef double _j33 = _j30*b2d
    cdef double _j34 = _j1*b1
    cdef double _j35 = _j34*xE
    cdef double _j36 = _j2*b1
    cdef double _j37 = _j9*xEd
    cdef double _j38 = _j37*b2d
    cdef double _j39 = _k127*xE
    cdef double _j40 = _k80*xE
    cdef double _j41 = _j2*b2
    cdef double _j42 = _j4*b2
    cdef double _j43 = b2*xE
    cdef double _j44 = b1d*xE
    cdef double _j45 = _k91*xEd
    cdef double _j46 = _j1*_j43*_k90 + _j39*_acc[4] + _j40*b2 + _j41*_k76 + _j42*_k84 + _j44*_j45 + _k53*b1
    cdef double _j47 = _j0*_k59
    cdef double _j48 = (((xE*xE)*(xE*xE))*xE)
    cdef double _j49 = _j48*_k56
    cdef double _j50 = _j9*b2d
    cdef double _j51 = _j3*b1d
    cdef double _j52 = _j9*b1d
    cdef double _j53 = _j3*b2d
    cdef double _j54 = _j28*b1
    cdef double _j55 = _j30*b1
    cdef double _j56 = _j28*b2
    cdef double _j57 = _j37*b2
    cdef double _j58 = _j0*b2
    cdef double _j59 = _j58*_k90
    cdef double _j60 = _j56*_k77 + _j57*_k85 + _j59*xEd
    cdef double _j61 = _j0*_k17
    cdef double _j62 = _j61 + _k12 + _k19*xE
    cdef double _j63 = _j62*_k157
    cdef double _j64 = _j61 + _k16*xE + _k18
    cdef double _j65 = _j64*_k158
    cdef double _j66 = _k162*xE
    cdef double _j67 = _k20*b1
    cdef double _j68 = 0.125*b2
    cdef double _j69 = _j64*_j68
    cdef double _j70 = _k161*(_j67*(_j66 + _k19) + _j68*xE*(_j66 + _k16) + _j69)
    cdef double _j71 = _k164*(_j62*_j67 + _j69*xE)
    cdef double _j72 = _j10*b2
    cdef double _j73 = _j48*xEd
    cdef double _j74 = _j73*b2d
    cdef double _j75 = _j37*b1d
    cdef double _j76 = _j4*b1
    cdef double _j77 = _j0*_k159
    cdef double _j78 = _j31*_k90 + _j40*b1 + _j58*_k168 + _j77*_acc[4]
    cdef double _j79 = _k66*(((xE*xE)*(xE*xE))*(xE*xE))
    cdef double _j80 = _j48*b2d
    cdef double _j81 = _j37*b1
    cdef double _j82 = _j73*b2
    cdef double _j83 = _j61 + _k23*xE + _k24
    cdef double _j84 = _j6*_k178
    cdef double _j85 = _k179*_acc[2]
    cdef double _j86 = _j0*b1
    cdef double _j87 = b1*b2
    cdef double _j88 = (b2*b2)
    cdef double _j89 = _j88*xE
    cdef double _j90 = xE*xEd
    cdef double _j91 = _j90*b2d
    cdef double _j92 = _k155*b1
    cdef double _j93 = _j43*xEd
    cdef double _j94 = (b1*b1)
    cdef double _j95 = _j1*_j94
    cdef double _j96 = _j58*xEd
    cdef double _j97 = _j43*_k182 + _k48*b1
    cdef double _j98 = _j94*_k183
    cdef double _j99 = _j58*b1
    cdef double _j100 = _k91*b1
    cdef double _j101 = _j94*xEd
    cdef double _j102 = Omega*t - theta
    cdef double _j103 = cos(_j102)
    cdef double _j104 = _j103*_k129
    cdef double _j105 = S_T*_cam0[0]
    cdef double _j106 = _j105 + _k49
    cdef double _j107 = sin(_j102)
    cdef double _j108 = _j106*_j107
    cdef double _j109 = _cam0[1]*_j104 - _j108
    cdef double _j110 = S_T*_j107
    cdef double _j111 = _j103*_j106
    cdef double _j112 = _cam0[1]*_j110 - _j111
    cdef double _j113 = (_cam0[0]*_cam0[0])
    cdef double _j114 = (_cam0[1]*_cam0[1])
    cdef double _j115 = _cam0[0]*_k37 + _j113*_k36 + _j114*_k36 + _k35
    cdef double _j116 = (1.0/(_j115))
    cdef double _j117 = (thetad*thetad)
    cdef double _j118 = _j116*_j117
    cdef double _j119 = _j118*_k92
    cdef double _j120 = (_cam0[0]*_cam0[0]*_cam0[0])
    cdef double _j121 = (_cam0[0]*_cam0[0]*_cam0[0]*_cam0[0])
    cdef double _j122 = (_cam0[1]*_cam0[1]*_cam0[1]*_cam0[1])
    cdef double _j123 = _cam0[0]*_j114
    cdef double _j124 = _j113*_j114
    cdef double _j125 = _cam0[0]*_k31 + _j113*_k33 + _j114*_k30 + _j120*_k32 + _j121*_k28 + _j122*_k28 + _j123*_k32 + _j124*_k29 + _k27
    cdef double _j126 = (1.0/(_j125))
    cdef double _j127 = _cam0[2]*_j126
    cdef double _j128 = _j117*_k114
    cdef double _j129 = _cam0[0]*_j127
    cdef double _j130 = _j117*_k43
    cdef double _j131 = _j114*_j126
    cdef double _j132 = _j117*_j131
    cdef double _j133 = _j123*_j126
    cdef double _j134 = _j117*_j133
    cdef double _j135 = _j113*_j127
    cdef double _j136 = _j117*_k112
    cdef double _j137 = _j116*_k40
    cdef double _j138 = _j117*_k118
    cdef double _j139 = _cam0[1]*_j126
    cdef double _j140 = _cam0[1]*_j116
    cdef double _j141 = _j117*_k94
    cdef double _j142 = _cam0[3]*_j126
    cdef double _j143 = (_cam0[1]*_cam0[1]*_cam0[1])
    cdef double _j144 = (((_cam0[0]*_cam0[0])*(_cam0[0]*_cam0[0]))*_cam0[0])
    cdef double _j145 = _cam0[0]*_j122
    cdef double _j146 = _j114*_j120
    cdef double _j147 = (((_cam0[0]*_cam0[0])*(_cam0[0]*_cam0[0]))*(_cam0[0]*_cam0[0]))*_k97 + _cam0[0]*_k101 + (((_cam0[1]*_cam0[1])*(_cam0[1]*_cam0[1]))*(_cam0[1]*_cam0[1]))*_k97 + _j113*_j122*_k98 + _j113*_k103 + _j114*_j121*_k98 + _j114*_k99 + _j120*_k105 + _j121*_k104 + _j122*_k100 + _j123*_k106 + _j124*_k108 + _j144*_k102 + _j145*_k102 + _j146*_k107 + _k96
    cdef double _j148 = (1.0/(_j147))
    cdef double _j149 = _j117*_j148
    cdef double _j150 = _j143*_j149
    cdef double _j151 = _j126*_j143
    cdef double _j152 = _j117*_j151
    cdef double _j153 = _cam0[0]*_cam0[1]
    cdef double _j154 = _j153*_k122
    cdef double _j155 = _cam0[0]*_j117
    cdef double _j156 = _j155*_k43
    cdef double _j157 = _cam0[0]*_j143
    cdef double _j158 = _j149*_j157
    cdef double _j159 = _cam0[1]*_k238
    cdef double _j160 = _cam0[2]*_j149
    cdef double _j161 = _cam0[1]*_j127
    cdef double _j162 = _cam0[1]*_j113
    cdef double _j163 = _j117*_k42
    cdef double _j164 = _j162*_j163
    cdef double _j165 = _j113*_j143
    cdef double _j166 = _j165*_k115
    cdef double _j167 = _j153*_k239
    cdef double _j168 = _j127*_j153
    cdef double _j169 = _cam0[1]*_j120
    cdef double _j170 = _j169*_k216
    cdef double _j171 = _j162*_k218
    cdef double _j172 = (((_cam0[1]*_cam0[1])*(_cam0[1]*_cam0[1]))*_cam0[1])
    cdef double _j173 = _j149*_k109
    cdef double _j174 = (_cam0[2]*_cam0[2])
    cdef double _j175 = _j149*_j174
    cdef double _j176 = _j175*_k124
    cdef double _j177 = _cam0[2]*_k121
    cdef double _j178 = _cam0[2]*_k203
    cdef double _j179 = _cam0[1]*_j176 + _j150*_j177 + _j153*_j175*_k218 + _j158*_j178 + _j162*_j175*_k217 + _j172*_j173
    cdef double _j180 = _cam0[2]*_j137
    cdef double _j181 = (1.0/(_j115*_j115))
    cdef double _j182 = _j181*(_cam0[0]*_k201 + _k202)
    cdef double _j183 = _cam0[2]*_j182
    cdef double _j184 = _j126*_j174
    cdef double _j185 = _cam0[0]*_j184
    cdef double _j186 = _j114*_j127
    cdef double _j187 = (1.0/(_j125*_j125))
    cdef double _j188 = _j187*(_cam0[0]*_k198 + _j113*_k199 + _j114*_k200 + _j120*_k197 + _j123*_k197 + _k196)
    cdef double _j189 = _j122*_k34
    cdef double _j190 = _j174*_k39
    cdef double _j191 = _j174*_j188
    cdef double _j192 = _cam0[0]*_k44
    cdef double _j193 = _cam0[2]*_j114
    cdef double _j194 = _j193*_k43
    cdef double _j195 = _cam0[2]*_j188
    cdef double _j196 = _j123*_k42
    cdef double _j197 = _j113*_k34
    cdef double _j198 = _j107*_k129
    cdef double _j199 = S_T*_j103
    cdef double _j200 = _j127*_k122
    cdef double _j201 = _cam0[1]*_j200
    cdef double _j202 = _j117*_j184
    cdef double _j203 = (_cam0[2]*_cam0[2]*_cam0[2])
    cdef double _j204 = _j149*_j203
    cdef double _j205 = _j204*_k123
    cdef double _j206 = _cam0[3]*_j117
    cdef double _j207 = _j206*_k43
    cdef double _j208 = _cam0[0]*_k209 + _j113*_k207 + _j114*_k212 + _j120*_k208 + _j121*_k210 + _j122*_k213 + _j123*_k214 + _j124*_k215 + _j144*_k206 + _j145*_k206 + _j146*_k211 + _k205
    cdef double _j209 = (1.0/(_j147*_j147))
    cdef double _j210 = _j172*_j209
    cdef double _j211 = _j208*_j210
    cdef double _j212 = _j117*_k110
    cdef double _j213 = _j117*_j188
    cdef double _j214 = _j143*_k44
    cdef double _j215 = _j168*_k204
    cdef double _j216 = _j206*_k42
    cdef double _j217 = _j211*_k109
    cdef double _j218 = _cam0[1]*_j138
    cdef double _j219 = _cam0[1]*_j117
    cdef double _j220 = _j219*_k113
    cdef double _j221 = _j208*_j209
    cdef double _j222 = _j174*_j221
    cdef double _j223 = _j219*_k119
    cdef double _j224 = _j117*_j221
    cdef double _j225 = _cam0[1]*_j203
    cdef double _j226 = _j225*_k120
    cdef double _j227 = _cam0[3]*_j128
    cdef double _j228 = _cam0[2]*_j117
    cdef double _j229 = _cam0[2]*_j143
    cdef double _j230 = _j229*_k116
    cdef double _j231 = _j229*_k34
    cdef double _j232 = _j188*_j206
    cdef double _j233 = _j114*_k111
    cdef double _j234 = _j117*_j222
    cdef double _j235 = _j143*_k117
    cdef double _j236 = _cam0[2]*_j213
    cdef double _j237 = _j136*_j153
    cdef double _j238 = _j203*_j224
    cdef double _j239 = _j153*_k123
    cdef double _j240 = _j153*_k124
    cdef double _j241 = _cam0[3]*_j156
    cdef double _j242 = _j157*_j177
    cdef double _j243 = _j123*_k34
    cdef double _j244 = _j157*_k115
    cdef double _j245 = _j162*_k109
    cdef double _j246 = _j169*_k109
    cdef double _j247 = _j162*_k125
    cdef double _j248 = _j113*_j206*_k112
    cdef double _j249 = _cam0[2]*_j181
    cdef double _j250 = _j117*_k95
    cdef double _j251 = _j187*(_cam0[1]*_k221 + _j143*_k197 + _j153*_k222 + _j162*_k197)
    cdef double _j252 = _cam0[2]*_j251
    cdef double _j253 = _j117*_j251
    cdef double _j254 = _j174*_j251
    cdef double _j255 = _j206*_j251
    cdef double _j256 = _j122*_j149
    cdef double _j257 = _cam0[1]*_j121*_k206 + _cam0[1]*_k233 + _j143*_k232 + _j153*_k234 + _j157*_k235 + _j162*_k214 + _j165*_k211 + _j169*_k235 + _j172*_k206
    cdef double _j258 = _j210*_j257
    cdef double _j259 = _j258*_k109
    cdef double _j260 = _j209*_j257
    cdef double _j261 = _j174*_j260
    cdef double _j262 = _j117*_j260
    cdef double _j263 = _j117*_j261
    cdef double _j264 = _j203*_j262
    cdef double _j265 = _j151*_k220
    cdef double _j266 = _cam0[3]*thetad
    cdef double _j267 = _j116*_j266
    cdef double _j268 = _cam0[1]*thetad
    cdef double _j269 = _j151*thetad
    cdef double _j270 = _j148*thetad
    cdef double _j271 = _j172*_j270
    cdef double _j272 = _j271*_k216
    cdef double _j273 = _j174*_j270
    cdef double _j274 = _j203*_j270
    cdef double _j275 = _j1*_k133
    cdef double _j276 = _k132*xEd
    cdef double _j277 = _cam0[0]*_j103
    cdef double _j278 = _j103*thetad
    cdef double _j279 = _j277*thetad
    cdef double _j280 = _k134*thetad
    cdef double _j281 = _j107*_j280
    cdef double _j282 = _j103*_j117
    cdef double _j283 = _j117*_j199
    cdef double _j284 = _j104*_j117
    cdef double _j285 = _j107*_j117
    cdef double _j286 = _j117*_j198
    cdef double _j287 = _j282*_k131
    cdef double _j288 = _j103*_j280
    cdef double _j289 = _j198*_acc[3] + _j288
    cdef double _j290 = _j107*_k128
    cdef double _j291 = _j0*_k133
    cdef double _j292 = _j107*_k130
    cdef double _j293 = _cam0[0]*_j107
    cdef double _j294 = _cam0[1]*_k134
    cdef double _j295 = _j107*thetad
    cdef double _j296 = _j293*thetad
    cdef double _j297 = _cam0[1]*_j278
    cdef double _j298 = _cam0[2]*_k135
    cdef double _j299 = _cam0[1]*_j295
    cdef double _j300 = _j103*_k255
    cdef double _j301 = Omega*_j108
    cdef double _j302 = _cam0[1]*_j300 + _j301
    cdef double _j303 = _j107*_k256
    cdef double _j304 = Omega*_j111
    cdef double _j305 = _cam0[1]*_j303 + _j304
    cdef double _j306 = _j0*_k47
    cdef double _j307 = _j110*thetad
    _R[0] = _j2*_k52 + _j4*_k58 + _j5*_j7 + _k53*xE
    _R[1] = _j10*_k57 + _j11*_j13 + _j2*_k61 + _j4*_k50 + _j8
    _R[2] = _j14*_k144*(_k143*xE + m_r) + _j15*_j16 + _j22*_j5 + _j24*_j25 + _j26*_k150*(_j0*_k1 + _j23 + _k0) + _j27*_acc[2] + _j29*_k152 + _j31*_k153 + _j32*_k154 + _j33*_k155 + _j35*_k51 + _j36*_k81 + _j38*_k84 + _j46
    _R[3] = 0.0
    _R[4] = _j28*_k51 + _j37*_k55 + _j47*xEd
    _R[5] = _j28*_k60 + _j37*_k50 + _j49*xEd
    _R[6] = _j47*b1d + _j49*b2d + _j50*_k50 + _j51*_k51 + _j52*_k55 + _j53*_k60 + _j54*_k156 + _j55*_k51 + _j60
    _R[7] = 0.0
    _R[8] = _j10*_k69 + _j11*_j63 + _j4*_k64 + _j8
    _R[9] = _j1*_j48*_k67 + _j10*_k62 + _j3*_k65 + _j4*_k72 + _j65*_j9*_acc[2]
    _R[10] = _j11*_j70 + _j14*_j24 + _j15*_k163*(_j0*_k13 + _j23 + _k14) + _j16*_j9*_acc[0] + _j29*_k172 + _j32*_k167 + _j36*_k50 + _j38*_k165 + _j41*_k87 + _j42*_k166 + _j48*_k161*_acc[1]*(_k160*xE + m_r) + _j5*_j71 + _j72*_k169 + _j74*_k169 + _j75*_k170 + _j76*_k171 + _j78
    _R[11] = 0.0
    _R[12] = _j28*_k70 + _j37*_k63 + _j73*_k68
    _R[13] = _j37*_k71 + _j73*_k62 + _j79*xEd
    _R[14] = _j48*_k68*b1d + _j50*_k71 + _j51*_k70 + _j52*_k63 + _j54*_k63 + _j56*_k176 + _j57*_k173 + _j79*b2d + _j80*_k62 + _j81*_k174 + _j82*_k175
    _R[15] = 0.0
    _R[16] = _j25*_j63 + _j26*_j7 + _j29*_k77 + _j31*_k78 + _j32*_k88 + _j33*_k90 + _j34*_k59 + _j35*_k78 + _j36*_k154 + _j38*_k85 + _j46 + _j85*(_j58*_j84 + _j83*_k177*b1*xE)
    _R[17] = _j13*_j14 + _j15*_j65 + _j29*_k89 + _j32*_k77 + _j35*_k90 + _j36*_k76 + _j38*_k74 + _j41*_k172 + _j42*_k180 + _j72*_k181 + _j74*_k86 + _j75*_k85 + _j76*_k84 + _j78 + _j85*(18.0*_j12*_j3*b2 + _j84*_j86)
    _R[18] = _j0*_j71*_acc[1] + _j1*_j89*_k172 + _j2*_j87*_k191 + _j2*_j88*_k186 + _j22*_j26 + _j25*_j70 + _j27*_acc[0] + _j29*_k187*b2 + _j29*_k192*b1 + _j31*_k193*b1 + _j32*_k192*b2 + _j33*_k188*b1 + _j34*_j43*_k188 + _j34*_k90*b2 + _j38*_k190*b2 + _j4*_j88*_k190 + _j44*_k189*b1*xEd + _j45*b1*b1d + _j85*(27.0*_j0*_j12*_j88 + _j17*_j99*_k178 + 9.0*_j19*_j3*_j88 + _j43*_j6*_k185*b1 + _j83*_j98 + _j98*xE*(_j66 + _k23) + _k184) + _j87*_k80 + _j89*_k168 + _j91*_j92 + _j93*_k155*b1d + _j95*_k154*xE + _j95*_k51 + _j96*_k188*b1d + _j96*_k194*b2d - _j97*_acc[4]
    _R[19] = 0.0
    _R[20] = _j100*_j90 + _j54*_k88 + _j55*_k78 + _j60
    _R[21] = _j54*_k77 + _j55*_k90 + _j56*_k89 + _j57*_k74 + _j81*_k85 + _j82*_k86
    _R[22] = _j0*_j101*_k154 + _j100*_j44 + _j101*_k59 + _j101*_k78*xE + _j28*_j87*_k192 + _j28*_j88*_k180 + _j30*_j88*_k172 + _j37*_j88*_k181 + _j50*_k74*b2 + _j50*_k85*b1 + _j51*_k77*b2 + _j51*_k88*b1 + _j52*_k85*b2 + _j53*_k77*b1 + _j53*_k89*b2 + _j59*b1d + _j80*_k86*b2 + _j86*_k78*b1d + _j86*_k90*b2d + _j92*_j93 + _j99*_k188*xEd + _k195*xEd
    _R[23] = 0.0
    _R[24] = 0.0
    _R[25] = 0.0
    _R[26] = 0.0
    _R[27] = _cam0[1]*(_cam0[1]*_j141*_j183 + _cam0[1]*_j202*_k112 + _cam0[1]*_j205 + _cam0[2]*_j166*_j224 + _cam0[3]*_j119 + _cam0[3]*_j132*_k34 + _cam0[3]*_j155*_j182*_k92 + _j117*_j201 + _j117*_j215 + _j127*_j207 + _j129*_j216 + _j143*_j175*_k115 + _j152*_k95 + _j153*_j204*_k216 + _j154*_j236 + _j155*_j217 + _j157*_j213*_k95 + _j162*_j236*_k42 + _j179 + _j182*_j206*_k93 + _j191*_j220 + _j191*_j237 + _j195*_j218 + _j195*_j227 + _j195*_j241 + _j195*_j248 + _j198*_acc[5] + _j199*_acc[4] + _j211*_j212 + _j213*_j214 + _j213*_j231 + _j217*_j228 + _j222*_j223 + _j224*_j226 + _j224*_j230 + _j224*_j242 + _j232*_j233 + _j232*_j243 + _j234*_j235 + _j234*_j240 + _j234*_j244 + _j234*_j246 + _j234*_j247 + _j238*_j239 + _j238*_j245 - _acc[3]*(_cam0[0]*_j183*_k40 + _j114*_j182*_k38 + _j180 + _j183*_k41 + _j184*_k44 + _j185*_k95 + _j186*_k42 + _j188*_j189 + _j188*_j190 + _j188*_j194 + _j191*_j192 + _j191*_j197 + _j195*_j196)) + _cam0[2]*(_cam0[0]*_j176 + _cam0[0]*_j205 + _cam0[1]*_j181*_j207 + _cam0[2]*_j118*_k94 + _cam0[2]*_j154*_j253 + _cam0[2]*_j256*_k227 + _j104*_acc[5] + _j113*_j173*_j203 + _j113*_j175*_k125 + _j114*_j175*_k231 + _j114*_j249*_j250 + _j117*_j186*_k224 + _j120*_j173*_j174 + _j123*_j160*_k236 + _j123*_j175*_k229 + _j124*_j160*_k229 + _j127*_j138 + _j132*_k226 + _j134*_k225 + _j135*_j163 + _j136*_j185 + _j139*_j206*_k44 + _j142*_j153*_j250 + _j145*_j149*_k227 + _j149*_j193*_k230 + _j153*_j181*_j216 + _j155*_j200 + _j155*_j259 + _j157*_j250*_j251 + _j164*_j252 + _j166*_j228*_j260 + _j175*_k119 + _j198*_acc[4] + _j202*_k113 + _j204*_k120 + _j212*_j258 + _j214*_j253 + _j218*_j252 + _j220*_j254 + _j223*_j261 + _j226*_j262 + _j227*_j252 + _j228*_j259 + _j230*_j262 + _j231*_j253 + _j233*_j255 + _j235*_j263 + _j237*_j254 + _j239*_j264 + _j240*_j263 + _j241*_j252 + _j242*_j262 + _j243*_j255 + _j244*_j263 + _j245*_j264 + _j246*_j263 + _j247*_j263 + _j248*_j252 + _j256*_k228 - _acc[3]*(_cam0[1]*_j249*_k223 + _j140*_k219 + _j143*_j181*_k204 + _j153*_j249*_k220 + _j189*_j251 + _j190*_j251 + _j192*_j254 + _j194*_j251 + _j196*_j252 + _j197*_j254 + _j201 + _j215 + _j265)) + _cam0[3]*(_j113*_j136*_j142 + _j117*_j126*_j154 + _j126*_j164 + _j128*_j142 + _j130*_j161 + _j138*_j139 + _j140*_j141 + _j142*_j156 + _j149*_j166 + _j150*_k116 + _j152*_k34 + _j158*_k121 + _j159*_j160 + _j160*_j167 + _j160*_j170 + _j160*_j171 + _j163*_j168 + _j179 - _acc[3]*(_cam0[0]*_j137 + _j116*_k41 + _j127*_k237 + _j129*_k223 + _j131*_k43 + _j133*_k42 + _j135*_k95)) + _cam0[4]*(_cam0[0]*_j119 + _j118*_k93 + _j127*_j128 + _j129*_j130 + _j132*_k111 + _j134*_k34 + _j135*_j136) - _j109*_acc[4] - _j112*_acc[5]
    _R[28] = 0.0
    _R[29] = 0.0
    _R[30] = 0.0
    _R[31] = _cam0[0]*_j200*_j266 + _cam0[0]*_j265*thetad + _cam0[0]*_j267*_k38 + _cam0[0]*_j272 + _cam0[2]*_j157*_j270*_k244 + _cam0[2]*_j269*_k95 + _cam0[2]*_j272 + _j127*_j162*_k204*thetad + _j127*_j266*_k118 + _j131*_j266*_k44 + _j133*_j266*_k95 + _j135*_j266*_k42 + _j143*_j273*_k121 + _j153*_j184*_k42*thetad + _j153*_j274*_k246 + _j157*_j273*_k203 + _j159*_j273 + _j161*_k242*thetad + _j162*_j274*_k216 + _j165*_j178*_j270 + _j167*_j273 + _j168*_k245*thetad + _j170*_j273 + _j171*_j273 + _j180*_j268 + _j184*_j268*_k43 + _j225*_j270*_k243 + _j229*_j270*_k241 + _j267*_k240 + _j269*_k223 + _j271*_k123
    _R[32] = _j1*_k127 + _j39*_acc[2]
    _R[33] = _j275*xE + _j77*_acc[2]
    _R[34] = _j275*b2 + _j276*b1d + _j39*_acc[0] + _j77*_acc[1] + _j91*_k247 - _j97*_acc[2]
    _R[35] = _cam0[0]*_j284 + _cam0[1]*_j281 + _cam0[1]*_j285*_k131 + _cam0[1]*(_j110*_j117 + _j199*_acc[3] + _j281 + _j290) + _cam0[2]*_j283 + _cam0[2]*(_j287 + _j289) + _cam0[3]*_j286 + _j103*_k249 - _j109*_acc[3] + _j277*_k250 + _j278*_k251 + _j279*_k136 + _j282*_k248
    _R[36] = _j276*xE
    _R[37] = _j291*xEd
    _R[38] = _j276*b1 + _j291*b2d + _j44*_k132 + _j93*_k247
    _R[39] = _j103*_j294 + _j292 + _j293*_k134 + _j295*_j298 + _j295*_k252 + _j296*_k131 + _j297*_k253
    _R[40] = 0.0
    _R[41] = 0.0
    _R[42] = 0.0
    _R[43] = _cam0[0]*_j281 + _cam0[0]*_j290 + _cam0[1]*_j287 + _cam0[1]*_j288 + _cam0[1]*(_j103*_k128 + _j283 + _j289) + _cam0[2]*_j286 + _cam0[2]*(_j104*_acc[3] + _j285*_k135 + _j295*_k136) + _cam0[3]*_j284 + _j105*_j285 + _j107*_k126 - _j112*_acc[3] + _j285*_k49 + _j292*thetad
    _R[44] = 0.0
    _R[45] = 0.0
    _R[46] = 0.0
    _R[47] = _cam0[1]*_j107*_k136 + _j103*_k130 + _j277*_k134 + _j278*_j298 + _j278*_k252 + _j279*_k131 + _j299*_k254
    _Rt[0] = 0.0
    _Rt[1] = 0.0
    _Rt[2] = 0.0
    _Rt[3] = -_j302*_acc[4] - _j305*_acc[5]
    _Rt[4] = _cam0[2]*_j282*_k256 + _j103*_k257 + _j155*_j300 + _j277*_k258 + _j278*_k260 + _j279*_k261 + _j282*_k259 + _j285*_j294 + _j299*_k262 - _j302*_acc[3]
    _Rt[5] = _cam0[2]*_j285*_k255 + _j107*_k263 + _j155*_j303 + _j282*_j294 + _j285*_k265 + _j293*_k264 + _j295*_k266 + _j296*_k262 + _j297*_k262 - _j305*_acc[3]
    _CQ[0] = _j90*_k48
    _CQ[1] = _j306*xEd
    _CQ[2] = _j306*b2d + _j44*_k48 + _j97*xEd
    _CQ[3] = _cam0[1]*(_j104*thetad + _j300) + _cam0[2]*_j307 + _j109*thetad + _j301
    _CQ[4] = 0.0
    _CQ[5] = 0.0
    _CQ[6] = 0.0
    _CQ[7] = _cam0[1]*(_j303 + _j307) + _cam0[2]*_j199*thetad + _j112*thetad + _j304
    _Ct[0] = _j108*_k267 + _j302*thetad
    _Ct[1] = _j111*_k267 + _j305*thetad


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
    cdef double b1 = _y[0]
    cdef double b2 = _y[1]
    cdef double xE = _y[2]
    cdef double theta = _y[3]
    cdef double b1d = _y[4]
    cdef double b2d = _y[5]
    cdef double xEd = _y[6]
    cdef double thetad = _y[7]
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
    return [0.0, 0.0, d - r_b - r_r, 0.0, 0.0, 0.0, 0.0, Omega]


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
    ctx.cache = &k[268]
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
_model.n_const = 268
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
 "n_q": 4,
 "name": "beam2",
 "options": [
  [
   "modes",
   2
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
 "source_hash": "sha256:e6f5b38d9e7b1dd5f920d6438c12a96321d776db2c76dee854114e82adf9e94d",
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
 "title": "Rayleigh-beam follower in a grooved disk cam, N = 2 assumed modes"
}
"""
MANIFEST = json.loads(_MANIFEST_JSON)
"""States, parameters (defaults, units, ranges), outputs, the cam profile, events, source hash."""

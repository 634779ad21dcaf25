# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True, initializedcheck=False
#
# GENERATED FILE - DO NOT EDIT.  Written by `camdyn derive` from camdyn/derive/models/beam.py;
# edit that and regenerate.  `camdyn derive --check` fails while this file is stale.
# Derivation key: sha256:a47abf847cafe44cad639e6a20642335e373d80cc872d652e3057ec196b5e92e
# Text hash: sha256:934ebcf8feab716faf2a4ecd41b32379c28a55d82716828f654077c5ec52a130
#
# Rayleigh-beam follower in a grooved disk cam, N = 1 assumed modes (paper (1)-(20))
# Source hash: sha256:bfb311a2dc642912ccf96df03b945a685fb049d1c1bb63babea364e48a9d993c
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
    cdef double _c5 = 4.0*m_r
    cdef double _c6 = 0.5*_c4
    cdef double _c7 = _c4*_c5
    cdef double _c8 = _c3*_c4
    cdef double _c9 = _c2*_c4
    cdef double _c10 = (r_b*r_b*r_b*r_b)
    cdef double _c11 = (r_r*r_r*r_r*r_r)
    cdef double _c12 = (r_r*r_r*r_r)
    cdef double _c13 = (r_b*r_b*r_b)
    cdef double _c14 = (r_b*r_b)
    cdef double _c15 = (r_r*r_r)
    cdef double _c16 = _c10 + _c11 + 4.0*_c12*r_b + 4.0*_c13*r_r + 6.0*_c14*_c15
    cdef double _c17 = (S_T*S_T*S_T*S_T)
    cdef double _c18 = 2.0*_c17
    cdef double _c19 = (S_T*S_T)
    cdef double _c20 = _c14 + _c15 + 2.0*r_b*r_r
    cdef double _c21 = _c19*_c20
    cdef double _c22 = _c12 + _c13 + 3.0*_c14*r_r + 3.0*_c15*r_b
    cdef double _c23 = r_b + r_r
    cdef double _c24 = (S_T*S_T*S_T)
    cdef double _c25 = _c23*_c24
    cdef double _c26 = 4.0*_c25
    cdef double _c27 = J_r*_c17
    cdef double _c28 = 2.0*S_T
    cdef double _c29 = _c23*_c28
    cdef double _c30 = J_r*_c19
    cdef double _c31 = 2.0*_c30
    cdef double _c32 = _c20*_c30
    cdef double _c33 = J_r*_c18
    cdef double _c34 = J_r*_c25
    cdef double _c35 = 2.0*_c34
    cdef double _c36 = (1.0/(d*d))
    cdef double _c37 = 2.0*_c36
    cdef double _c38 = 3.141592653589793*E*_c0
    cdef double _c39 = 2.0*_c3
    cdef double _c40 = J_r*_c23
    cdef double _c41 = pow(r_r, 5.0)
    cdef double _c42 = pow(r_b, 5.0)
    cdef double _c43 = pow(S_T, 6.0)
    cdef double _c44 = _c16*_c19
    cdef double _c45 = _c17*_c20
    cdef double _c46 = pow(S_T, 5.0)
    cdef double _c47 = _c23*_c46
    cdef double _c48 = _c22*_c24
    cdef double _c49 = J_r*_c43
    cdef double _c50 = _c40*_c46
    cdef double _c51 = _c20*_c27
    cdef double _c52 = 4.0*_c50
    cdef double _c53 = (Omega*Omega)
    cdef double _c54 = Omega*_c28
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
    ctx.k[11] = _c16  # _k11
    ctx.k[12] = _c17  # _k12
    ctx.k[13] = _c18  # _k13
    ctx.k[14] = 2.0*_c21  # _k14
    ctx.k[15] = 4.0*S_T*_c22  # _k15
    ctx.k[16] = _c26  # _k16
    ctx.k[17] = 6.0*_c21  # _k17
    ctx.k[18] = _c27  # _k18
    ctx.k[19] = _c20  # _k19
    ctx.k[20] = _c19  # _k20
    ctx.k[21] = _c29  # _k21
    ctx.k[22] = _c31  # _k22
    ctx.k[23] = _c32  # _k23
    ctx.k[24] = -_c31  # _k24
    ctx.k[25] = -J_r*_c29  # _k25
    ctx.k[26] = -_c33  # _k26
    ctx.k[27] = -_c35  # _k27
    ctx.k[28] = _c35  # _k28
    ctx.k[29] = -_c36  # _k29
    ctx.k[30] = -_c37  # _k30
    ctx.k[31] = _c23  # _k31
    ctx.k[32] = -12.0*m_r  # _k32
    ctx.k[33] = -6.0*m_r  # _k33
    ctx.k[34] = -3.0*_c38  # _k34
    ctx.k[35] = -3.0*_c3  # _k35
    ctx.k[36] = -_c39  # _k36
    ctx.k[37] = -3.0*_c2  # _k37
    ctx.k[38] = 0.3333333333333333*_c4  # _k38
    ctx.k[39] = -_c7  # _k39
    ctx.k[40] = -_c38*_c6  # _k40
    ctx.k[41] = -8.0*_c4*m_r  # _k41
    ctx.k[42] = -0.5*_c3  # _k42
    ctx.k[43] = -_c39*_c4  # _k43
    ctx.k[44] = -_c2*_c6  # _k44
    ctx.k[45] = -2.6666666666666665*_c8  # _k45
    ctx.k[46] = -2.0*_c9  # _k46
    ctx.k[47] = _c30  # _k47
    ctx.k[48] = S_T*_c40  # _k48
    ctx.k[49] = -_c30  # _k49
    ctx.k[50] = _c33  # _k50
    ctx.k[51] = 15.0*_c10*_c15 + 15.0*_c11*_c14 + 20.0*_c12*_c13 + 6.0*_c41*r_b + 6.0*_c42*r_r + pow(r_b, 6.0) + pow(r_r, 6.0)  # _k51
    ctx.k[52] = _c43  # _k52
    ctx.k[53] = 3.0*_c43  # _k53
    ctx.k[54] = 3.0*_c44  # _k54
    ctx.k[55] = 3.0*_c45  # _k55
    ctx.k[56] = 6.0*S_T*(5.0*_c10*r_r + 5.0*_c11*r_b + 10.0*_c12*_c14 + 10.0*_c13*_c15 + _c41 + _c42)  # _k56
    ctx.k[57] = 6.0*_c47  # _k57
    ctx.k[58] = 15.0*_c44  # _k58
    ctx.k[59] = 15.0*_c45  # _k59
    ctx.k[60] = 20.0*_c48  # _k60
    ctx.k[61] = 12.0*_c48  # _k61
    ctx.k[62] = 12.0*_c47  # _k62
    ctx.k[63] = 18.0*_c45  # _k63
    ctx.k[64] = 2.0*_c49  # _k64
    ctx.k[65] = 2.0*_c50  # _k65
    ctx.k[66] = _c34  # _k66
    ctx.k[67] = -_c27  # _k67
    ctx.k[68] = -_c34  # _k68
    ctx.k[69] = -_c32  # _k69
    ctx.k[70] = -4.0*_c49  # _k70
    ctx.k[71] = -4.0*_c51  # _k71
    ctx.k[72] = -_c52  # _k72
    ctx.k[73] = -_c20*_c31  # _k73
    ctx.k[74] = 2.0*J_r*_c48  # _k74
    ctx.k[75] = _c20*_c33  # _k75
    ctx.k[76] = -8.0*_c50  # _k76
    ctx.k[77] = -J_r*_c26  # _k77
    ctx.k[78] = _c52  # _k78
    ctx.k[79] = 6.0*_c51  # _k79
    ctx.k[80] = 6.0*_c50  # _k80
    ctx.k[81] = _c23*_c53  # _k81
    ctx.k[82] = _c37  # _k82
    ctx.k[83] = S_T*_c53  # _k83
    ctx.k[84] = -S_T  # _k84
    ctx.k[85] = -2.0*Omega*_c23  # _k85
    ctx.k[86] = _c28  # _k86
    ctx.k[87] = 4.0*_c36  # _k87
    ctx.k[88] = -_c54  # _k88
    ctx.k[89] = -_c28  # _k89
    ctx.k[90] = _c54  # _k90
    ctx.k[91] = -d  # _k91
    ctx.k[92] = -Omega  # _k92
    ctx.k[93] = _c36  # _k93


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
    cdef double _s49 = (1.0/(pow(_cam0[0], 6.0)*_k52 + pow(_cam0[0], 5.0)*_k57 + _cam0[0]*_k56 + _cam0[0]*_k57*_s11 + pow(_cam0[1], 6.0)*_k52 + _k51 + _k53*_s11*_s7 + _k53*_s13*_s8 + _k54*_s8 + _k55*_s11 + _k58*_s7 + _k59*_s13 + _k60*_s12 + _k61*_s14 + _k62*_s12*_s8 + _k63*_s15))
    cdef double _s50 = _s40*_s49
    cdef double _s51 = pow(_cam0[1], 5.0)*_s50
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
    cdef double b1 = _y[0]
    cdef double xE = _y[1]
    cdef double theta = _y[2]
    cdef double b1d = _y[3]
    cdef double xEd = _y[4]
    cdef double thetad = _y[5]
    cdef double _cam0[4]
    _profile(ctx, theta, beta_r, _cam0)

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


cdef double _SCALE[_NS]  # typical magnitude of each state (manifest "scale"): the difference steps
_SCALE[0] = 1e-05
_SCALE[1] = 0.05
_SCALE[2] = 1.0
_SCALE[3] = 1e-05
_SCALE[4] = 0.05
_SCALE[5] = 1.0


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
    ctx.cache = &k[94]
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
_model.n_const = 94
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
 "reference": "paper (1)-(20)",
 "residual": null,
 "solver": {
  "baumgarte_rate": "w_B",
  "formulation": "formulation"
 },
 "source_hash": "sha256:bfb311a2dc642912ccf96df03b945a685fb049d1c1bb63babea364e48a9d993c",
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
 "time_derivative": "finite-difference",
 "title": "Rayleigh-beam follower in a grooved disk cam, N = 1 assumed modes"
}
"""
MANIFEST = json.loads(_MANIFEST_JSON)
"""States, parameters (defaults, units, ranges), outputs, the cam profile, events, source hash."""

# cython: language_level=3, boundscheck=False, wraparound=False, cdivision=True, initializedcheck=False
#
# GENERATED FILE - DO NOT EDIT.  Written by `camdyn derive` from camdyn/derive/models/dynacam.py;
# edit that and regenerate.  `camdyn derive --check` fails while this file is stale.
# Derivation key: sha256:e192ff178e6a10ca9709c754fb85b8c58ca762695b5269ed5208d22c74019c2e
# Text hash: sha256:70ee91f0acec65a02dba6a458663c9ded645119a466a2dfb00eb7abf784f56d2
#
# DYNACAM, cam mechanism with four degrees of freedom and drive (thesis ch. 6, figs 6.1, 6.2, 6.15, 6.18)
# Source hash: sha256:e63183f45a2d3708dd5707654b2e7f19e223ec32be78ba20c70cfa560282b899
#
# This variant:
#   cam = radial: radial disk cam, pitch radius R_b + h (6.21)
#   motor = constant: camshaft input turning at the constant speed omega_s (ideal drive)
#   gear = rigid: reduction gear without backlash: the shaft torsion k, d_b alone (6.10)
#   roller = bilateral: roller held on both sides: the linkage spring always carries (6.42)
#   shaft_y = no: shaft rigid tangentially
#   shaft_z = no: shaft rigid along the follower
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
    _NQ = 2                  # second-order coordinates
    _NS = 4                  # states: q, q', first-order states
    _NCAM = 1                # cam input instances (one segment mode each)
    _NM = 1                  # modes: cam segments, then the force elements' modes
    _NE = 2                  # events
    _NQ1 = 2                 # array sizes that must not be zero
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
    cdef double _c0 = (1.0/(J))
    cdef double _c1 = _c0*k
    cdef double _c2 = sqrt(J)
    cdef double _c3 = 2.0*sqrt(k)*q_b
    cdef double _c4 = _c3/_c2
    cdef double _c5 = c_x*h_m
    cdef double _c6 = sqrt(m_x)
    cdef double _c7 = sqrt(c_x)
    cdef double _c8 = 2.0*_c7*q_x
    cdef double _c9 = _c6*_c8
    cdef double _c10 = (1.0/(beta_m))
    cdef double _c11 = _c10*h_m
    cdef double _c12 = _c0*_c11
    cdef double _c13 = (h_m*h_m)
    cdef double _c14 = (beta_m*beta_m)
    cdef double _c15 = (1.0/(_c14))
    cdef double _c16 = _c0*_c15
    cdef double _c17 = (1.0/(m_x))
    cdef double _c18 = _c17*_c5
    cdef double _c19 = _c8/_c6
    cdef double _c20 = (1.0/(h_m))
    cdef double _c21 = (1.0/(omega_s*omega_s))
    cdef double _c22 = _c13*c_x
    ctx.k[0] = -_c1  # _k0
    ctx.k[1] = _c1*omega_s  # _k1
    ctx.k[2] = -_c4  # _k2
    ctx.k[3] = _c4*omega_s  # _k3
    ctx.k[4] = -_c5  # _k4
    ctx.k[5] = _c9  # _k5
    ctx.k[6] = _c12  # _k6
    ctx.k[7] = -_c13*_c16*_c9  # _k7
    ctx.k[8] = -_c17*c_x  # _k8
    ctx.k[9] = _c18  # _k9
    ctx.k[10] = -_c19  # _k10
    ctx.k[11] = _c11*_c19  # _k11
    ctx.k[12] = -beta_0  # _k12
    ctx.k[13] = _c10  # _k13
    ctx.k[14] = _c14*_c20*_c21  # _k14
    ctx.k[15] = _c21*beta_m  # _k15
    ctx.k[16] = -h_m  # _k16
    ctx.k[17] = _c20  # _k17
    ctx.k[18] = -k  # _k18
    ctx.k[19] = k*omega_s  # _k19
    ctx.k[20] = _c2*_c3  # _k20
    ctx.k[21] = -c_x  # _k21
    ctx.k[22] = _c5  # _k22
    ctx.k[23] = -_c9  # _k23
    ctx.k[24] = _c11*_c9  # _k24
    ctx.k[25] = (1.0/(omega_s))  # _k25
    ctx.k[26] = _c11  # _k26
    ctx.k[27] = _c5*beta_m  # _k27
    ctx.k[28] = -_c22*beta_m  # _k28
    ctx.k[29] = _c9*beta_m*h_m  # _k29
    ctx.k[30] = -4.0*_c13*_c6*_c7*q_x  # _k30
    ctx.k[31] = _c0/(beta_m*beta_m*beta_m)  # _k31
    ctx.k[32] = -_c16*_c22  # _k32
    ctx.k[33] = _c0*_c10*_c5  # _k33
    ctx.k[34] = _c12*_c9  # _k34
    ctx.k[35] = _c10*_c18  # _k35
    ctx.k[36] = _c15*_c19*h_m  # _k36


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
    cdef double beta = _y[0]
    cdef double x = _y[1]
    cdef double betad = _y[2]
    cdef double xd = _y[3]
    cdef double _cam0[4]  # H((beta - beta_0)/beta_m) and its derivatives
    cdef int _v = ctx.variant
    cdef double* _c
    cdef double _a
    if _v & 1:
        _cam0[0] = ctx.cache[1]  # H in the dwell, set by refresh()
    else:
        # the stages of a step share arguments (RK4: t + h/2 twice, t + h for the next
        # k1): the last evaluation is kept in ctx.cache and reused
        _a = (beta - beta_0)/beta_m
        _c = &ctx.cache[0]
        if _a == _c[0]:
            _cam0[0], _cam0[1], _cam0[2], _cam0[3] = _c[1], _c[2], _c[3], _c[4]
        else:
            camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], _a, _cam0)
            _c[0], _c[1], _c[2], _c[3], _c[4] = _a, _cam0[0], _cam0[1], _cam0[2], _cam0[3]

    _dy[0] = betad
    _dy[1] = xd
    if _v == 0:
        _dy[2] = (_cam0[1]*_cam0[1])*_k7*betad + _cam0[1]*_k6*(_cam0[0]*_k4 + _k5*xd + c_x*x) + _k0*beta + _k1*t + _k2*betad + _k3
        _dy[3] = _cam0[0]*_k9 + _cam0[1]*_k11*betad + _k10*xd + _k8*x
    elif _v == 1:  # in a dwell: 0
        _dy[2] = _k0*beta + _k1*t + _k2*betad + _k3
        _dy[3] = _cam0[0]*_k9 + _k10*xd + _k8*x


cdef void outputs(double t, const double* _y, double* _out, Ctx* ctx) noexcept nogil:
    """The named outputs (B, Xdd, Bdd, U, xdd, torque, Fx, speed_var, tan_alpha)."""
    cdef double _dy[4]
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
    cdef double beta = _y[0]
    cdef double x = _y[1]
    cdef double betad = _y[2]
    cdef double xd = _y[3]
    cdef double betadd = _dy[2]
    cdef double xdd = _dy[3]
    cdef double _cam0[4]  # H((beta - beta_0)/beta_m) and its derivatives
    cdef double* _c
    # rhs() has just evaluated this input at the same argument and kept it (outside a dwell)
    _c = &ctx.cache[0]
    if _c[0] == (beta - beta_0)/beta_m:
        _cam0[0], _cam0[1], _cam0[2], _cam0[3] = _c[1], _c[2], _c[3], _c[4]
    else:
        camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], (beta - beta_0)/beta_m, _cam0)

    _out[0] = _k13*(_k12 + beta)  # B
    _out[1] = _k14*_dy[3]  # Xdd
    _out[2] = _k15*_dy[2]  # Bdd
    _out[3] = _k17*(_cam0[0]*_k16 + x)  # U
    _out[4] = _dy[3]  # xdd
    _out[5] = _k18*beta + _k19*t - _k20*(betad - omega_s)  # torque
    _out[6] = _cam0[0]*_k22 + _cam0[1]*_k24*betad + _k21*x + _k23*xd  # Fx
    _out[7] = _k25*betad - 1.0  # speed_var
    _out[8] = _cam0[1]*_k26/(R_b + _cam0[0]*h_m)  # tan_alpha


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
    cdef double beta = _y[0]
    cdef double x = _y[1]
    cdef double betad = _y[2]
    cdef double xd = _y[3]
    cdef double _cam0[4]  # H((beta - beta_0)/beta_m) and its derivatives
    camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], (beta - beta_0)/beta_m, _cam0)

    cdef double _m0 = (beta_m*beta_m)
    cdef double _m1 = (h_m*h_m)
    cdef double _m2 = sqrt(c_x)*sqrt(m_x)*q_x
    cdef double _m3 = (1.0/(beta_m))
    cdef double _m4 = _cam0[2]*_m3*betad
    cdef double _m5 = 2.0*_m2
    cdef double _m6 = _cam0[1]*c_x
    cdef double _m7 = _m3*h_m
    _Mm[0] = J
    _Mm[1] = 0.0
    _Mm[2] = 0.0
    _Mm[3] = m_x
    _Km[0] = ((_cam0[1]*_cam0[1])*_m1*c_x + 4.0*_cam0[1]*_m1*_m2*_m4 - _cam0[2]*h_m*(-_cam0[0]*c_x*h_m + _m5*xd + c_x*x) + _m0*k)/_m0
    _Km[1] = -_m6*_m7
    _Km[2] = -_m7*(_m4*_m5 + _m6)
    _Km[3] = c_x


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
    cdef double beta = _y[0]
    cdef double x = _y[1]
    cdef double betad = _y[2]
    cdef double xd = _y[3]
    cdef double _cam0[4]  # H((beta - beta_0)/beta_m) and its derivatives
    camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], (beta - beta_0)/beta_m, _cam0)

    cdef int _k
    cdef double _ftl[4]
    for _k in range(16):
        _J[_k] = 0.0
    for _k in range(4):
        _ftl[_k] = 0.0
    for _k in range(2):
        _J[_k * 5 + 2] = 1.0  # d q'/d q'
    cdef double _j0 = (_cam0[1]*_cam0[1])
    _J[8] = _cam0[2]*_k31*(_cam0[0]*_k28 + _cam0[1]*_k30*betad + _k27*x + _k29*xd) + _j0*_k32 + _k0
    _J[9] = _cam0[1]*_k33
    _J[10] = _j0*_k7 + _k2
    _J[11] = _cam0[1]*_k34
    _J[12] = _cam0[1]*_k35 + _cam0[2]*_k36*betad
    _J[13] = _k8
    _J[14] = _cam0[1]*_k11
    _J[15] = _k10
    _ftl[2] = _k1
    if _ft != NULL:
        for _k in range(4):
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
    cdef double beta = _y[0]
    cdef double x = _y[1]
    cdef double betad = _y[2]
    cdef double xd = _y[3]

    ctx.mode[0] = camlaw_segment(ctx.law[0], ctx.law_par[0], (beta - beta_0)/beta_m)
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
    cdef double beta = _y[0]
    cdef double x = _y[1]
    cdef double betad = _y[2]
    cdef double xd = _y[3]
    cdef double _cam0[4]  # H((beta - beta_0)/beta_m) and its derivatives
    camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], (beta - beta_0)/beta_m, _cam0)

    _g[0] = ((beta - beta_0)/beta_m) - camlaw_hi(ctx.law[0], ctx.law_par[0], ctx.mode[0])  # cam0_hi: next segment
    _g[1] = ((beta - beta_0)/beta_m) - camlaw_lo(ctx.law[0], ctx.law_par[0], ctx.mode[0])  # cam0_lo: previous segment


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
    cdef double beta = _y[0]
    cdef double x = _y[1]
    cdef double betad = _y[2]
    cdef double xd = _y[3]
    cdef double _cam0[4]  # H((beta - beta_0)/beta_m) and its derivatives
    camlaw_eval(ctx.law[0], ctx.law_par[0], ctx.mode[0], (beta - beta_0)/beta_m, _cam0)

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
    return [0.0, 0.0, omega_s, 0.0]


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
    return [None]


cdef ModelC _model
_model.abi_version = CAMDYN_ABI
_model.n_q = _NQ
_model.n_states = _NS
_model.n_params = 11
_model.n_outputs = 9
_model.n_families = 1
_model.n_instances = _NCAM
_model.n_modes = _NM
_model.n_events = _NE
_model.n_const = 37
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
   "argument": "(beta - beta_0)/beta_m",
   "family": "H",
   "order": 2,
   "time_affine": false
  }
 ],
 "events": [
  "cam0_hi",
  "cam0_lo"
 ],
 "jacobian": "symbolic",
 "modes": [],
 "n_q": 2,
 "name": "dynacam_radial_ideal_rigidgear_bilateral",
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
   false
  ],
  [
   "shaft_z",
   false
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
  }
 ],
 "reference": "thesis ch. 6, figs 6.1, 6.2, 6.15, 6.18",
 "residual": {
  "acceleration": "Xdd",
  "error": "U",
  "rise_end": 1.0,
  "rise_state": "B"
 },
 "source_hash": "sha256:e63183f45a2d3708dd5707654b2e7f19e223ec32be78ba20c70cfa560282b899",
 "states": [
  {
   "doc": "cam angle",
   "initial": 0.0,
   "name": "beta",
   "scale": 1.0,
   "unit": "rad"
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

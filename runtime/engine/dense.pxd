# The continuous extension of a recorded step, written once for the loops (event location),
# the driver (sampling) and the figure finder.
#
# On the step from point i to i + 1 (length h, s in [0, 1], s1 = 1 - s) every method's dense
# output has Hairer's nested form (Hairer, Norsett & Wanner, Solving ODEs I, sec. II.6; the
# dense output of their codes DOPRI5 and DOP853):
#
#     y(t_i + s h) = y_i + s (v0 + s1 (v1 + s (v2 + s1 (v3 + s (v4 + s1 (v5 + s v6))))))
#     v0 = y_i+1 - y_i,  v1 = h f_i - v0,  v2 = v0 - h f_i+1 - v1,  v3... = the step's extras
#
# the multipliers alternating s1, s, s1, ...  With no extra it is the cubic Hermite
# interpolant (RK4, the thesis scheme), with one DP54's quartic, with two the quintic of
# RADAU5 and RODAS4 (the Hermite interpolant over three points), with four DOP853's
# polynomial of degree 7.  The extras multiply s^2 s1^2, so any choice of them keeps the
# values and slopes at both ends.
#
# The extras of a step can also be fitted to the state at n_extra interior points
# s_j = (j + 1)/(n_extra + 1): the exact linear segments (loops.pxi, _loop_exact) take them
# from the exact propagator, and a step cut at an event keeps the interpolant of the whole
# step on its shortened part.


cdef inline double dense_component(double s, double h, double y0, double y1, double f0,
                                   double f1, const double* e, int nx,
                                   Py_ssize_t stride) noexcept nogil:
    """One component of the continuous extension at s; e[j * stride] is extra j."""
    cdef double s1 = 1.0 - s, acc = 0.0
    cdef double v0 = y1 - y0
    cdef double v1 = h * f0 - v0
    cdef double v2 = v0 - h * f1 - v1
    cdef int j
    for j in range(nx - 1, -1, -1):
        # extra j is v_(j+3); the multiplier of what follows it is s for j even, s1 for j odd
        acc = e[j * stride] + (s if j % 2 == 0 else s1) * acc
    return y0 + s * (v0 + s1 * (v1 + s * (v2 + s1 * acc)))


cdef inline double extra_basis(int j, double s) noexcept nogil:
    """The factor of extra j in y(s), divided by s^2 s1^2: 1, s, s s1, s^2 s1, ..."""
    cdef double b = 1.0
    cdef int i
    for i in range(1, j + 1):
        b *= s if i % 2 == 1 else 1.0 - s
    return b


cdef inline int fit_matrix(int nx, double* W) noexcept nogil:
    """W (nx x nx) maps what the cubic Hermite part leaves at the interior nodes, per unit of
    s^2 s1^2, to the extras (fit_extras); it depends on nx alone.  -1 if nx > 8."""
    cdef double B[64]
    cdef double s, x
    cdef int i, j, k
    if nx > 8:
        return -1
    # Gauss-Jordan on [B | I] without pivoting: the basis is well conditioned at equally
    # spaced interior nodes for nx <= 8
    for i in range(nx):
        s = (i + 1.0) / (nx + 1.0)
        for j in range(nx):
            B[i * nx + j] = extra_basis(j, s)
            W[i * nx + j] = 1.0 if i == j else 0.0
    for k in range(nx):
        x = 1.0 / B[k * nx + k]
        for j in range(nx):
            B[k * nx + j] *= x
            W[k * nx + j] *= x
        for i in range(nx):
            if i != k:
                x = B[i * nx + k]
                for j in range(nx):
                    B[i * nx + j] -= x * B[k * nx + j]
                    W[i * nx + j] -= x * W[k * nx + j]
    return 0


cdef inline void fit_extras(int nx, int ns, const double* W, double h, const double* y0,
                            const double* y1, const double* f0, const double* f1,
                            const double* values, double* extra) noexcept nogil:
    """The extras (nx x ns, extra j of component c at extra[j * ns + c]) whose extension
    passes through values[j * ns + c] at s_j = (j + 1)/(nx + 1); W from fit_matrix(nx)."""
    cdef double rest[8]
    cdef double s, x
    cdef int i, j, c
    for c in range(ns):
        for i in range(nx):
            s = (i + 1.0) / (nx + 1.0)
            rest[i] = (values[i * ns + c] - dense_component(s, h, y0[c], y1[c], f0[c], f1[c],
                                                            NULL, 0, 0)) / (s * s * (1.0 - s) * (1.0 - s))
        for j in range(nx):
            x = 0.0
            for i in range(nx):
                x += W[j * nx + i] * rest[i]
            extra[j * ns + c] = x

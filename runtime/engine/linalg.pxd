# cython: cdivision=True
# Small dense linear algebra for generated right-hand sides (inline, nogil).
#
# The integration loops call the LU routines with the model's state count, a compile-time
# constant once they are inlined.  Up to LA_SMALL unknowns their triangular loops run over the
# whole row with the triangle as a condition: every loop then has a constant trip count and the
# compiler unrolls the factorization and the solves completely (the Radau and Rosenbrock steps
# of a four-state model spent about half their time in the loops' bookkeeping otherwise).  Above
# it they run over the triangle only, the condition always true.
#
# C division (the directive above): the routines test their pivots themselves, and Python's
# zero-division checks put a call that may raise into every factorization.

from libc.math cimport fabs, sqrt

cdef enum:
    LA_SMALL = 6

cdef inline int solve_inplace(int n, double* A, double* b) noexcept nogil:
    """Solve A x = b by Gaussian elimination with partial pivoting.

    A is n x n row-major and is overwritten; b becomes x.  Returns 0, or
    k + 1 when pivot k vanishes (singular matrix).
    """
    cdef int i, j, k, piv
    cdef double amax, v, tmp
    for k in range(n):
        piv = k
        amax = abs(A[k * n + k])
        for i in range(k + 1, n):
            v = abs(A[i * n + k])
            if v > amax:
                amax = v
                piv = i
        if amax == 0.0:
            return k + 1
        if piv != k:
            for j in range(n):
                tmp = A[k * n + j]
                A[k * n + j] = A[piv * n + j]
                A[piv * n + j] = tmp
            tmp = b[k]
            b[k] = b[piv]
            b[piv] = tmp
        for i in range(k + 1, n):
            v = A[i * n + k] / A[k * n + k]
            if v != 0.0:
                for j in range(k + 1, n):
                    A[i * n + j] -= v * A[k * n + j]
                b[i] -= v * b[k]
    for i in range(n - 1, -1, -1):
        v = b[i]
        for j in range(i + 1, n):
            v -= A[i * n + j] * b[j]
        b[i] = v / A[i * n + i]
    return 0


cdef inline int lu_factor(int n, double* A, int* piv) noexcept nogil:
    """LU factorization with partial pivoting, in place: A = P L U (row-major, L unit lower).

    Kept apart from solve_inplace so that one factorization serves several right-hand
    sides (the stages of a Rosenbrock step, the Newton sweeps of a Radau step).  piv[k] is
    the row swapped with k at step k.  The diagonal holds 1/U_kk: solves outnumber
    factorizations, and a multiplication does not stall the back substitution as a division
    does (on the roller's Radau steps the divisions were a fifth of the loop's time).
    Returns 0, or k + 1 when pivot k vanishes (singular matrix).
    """
    cdef int i, j, k, p
    cdef double amax, v, tmp
    for k in range(n):
        p = k
        amax = abs(A[k * n + k])
        for i in range(k + 1, n):
            v = abs(A[i * n + k])
            if v > amax:
                amax = v
                p = i
        piv[k] = p
        if amax == 0.0:
            return k + 1
        if p != k:
            for j in range(n):
                tmp = A[k * n + j]
                A[k * n + j] = A[p * n + j]
                A[p * n + j] = tmp
        A[k * n + k] = 1.0 / A[k * n + k]
        for i in range(0 if n <= LA_SMALL else k + 1, n):
            if i > k:
                v = A[i * n + k] * A[k * n + k]
                A[i * n + k] = v
                if v != 0.0:
                    for j in range(0 if n <= LA_SMALL else k + 1, n):
                        if j > k:
                            A[i * n + j] -= v * A[k * n + j]
    return 0


cdef inline void lu_solve(int n, const double* LU, const int* piv, double* b) noexcept nogil:
    """Solve A x = b with the factors of lu_factor; b becomes x."""
    cdef int i, j
    cdef double v
    for i in range(n):
        j = piv[i]
        if j != i:
            v = b[i]
            b[i] = b[j]
            b[j] = v
    for i in range(1, n):
        v = b[i]
        for j in range(n if n <= LA_SMALL else i):
            if j < i:
                v -= LU[i * n + j] * b[j]
        b[i] = v
    for i in range(n - 1, -1, -1):
        v = b[i]
        for j in range(0 if n <= LA_SMALL else i + 1, n):
            if j > i:
                v -= LU[i * n + j] * b[j]
        b[i] = v * LU[i * n + i]


cdef inline int clu_factor(int n, double* Ar, double* Ai, int* piv) noexcept nogil:
    """LU factorization with partial pivoting of the complex n x n matrix Ar + i Ai, in place,
    as lu_factor (row-major, L unit lower, the diagonal holding 1/U_kk), the real and imaginary
    parts in two arrays; pivots by |Re| + |Im|, as Hairer & Wanner's DECC.  A complex system
    of size n costs half the flops of its real form of size 2n to factor, and its solves run
    over n rows instead of 2n.  Returns 0, or k + 1 when pivot k vanishes."""
    cdef int i, j, k, p
    cdef double amax, v, tmp, ur, ui, r, d, lr, li
    for k in range(n):
        p = k
        amax = fabs(Ar[k * n + k]) + fabs(Ai[k * n + k])
        for i in range(k + 1, n):
            v = fabs(Ar[i * n + k]) + fabs(Ai[i * n + k])
            if v > amax:
                amax = v
                p = i
        piv[k] = p
        if amax == 0.0:
            return k + 1
        if p != k:
            for j in range(n):
                tmp = Ar[k * n + j]
                Ar[k * n + j] = Ar[p * n + j]
                Ar[p * n + j] = tmp
                tmp = Ai[k * n + j]
                Ai[k * n + j] = Ai[p * n + j]
                Ai[p * n + j] = tmp
        # 1/(ur + i ui) by Smith's rule: no square of a large or small part overflows
        ur = Ar[k * n + k]
        ui = Ai[k * n + k]
        if fabs(ur) >= fabs(ui):
            r = ui / ur
            d = 1.0 / (ur + ui * r)
            ur = d
            ui = -r * d
        else:
            r = ur / ui
            d = 1.0 / (ur * r + ui)
            ur = r * d
            ui = -d
        Ar[k * n + k] = ur
        Ai[k * n + k] = ui
        for i in range(0 if n <= LA_SMALL else k + 1, n):
            if i > k:
                lr = Ar[i * n + k] * ur - Ai[i * n + k] * ui
                li = Ar[i * n + k] * ui + Ai[i * n + k] * ur
                Ar[i * n + k] = lr
                Ai[i * n + k] = li
                if lr != 0.0 or li != 0.0:
                    for j in range(0 if n <= LA_SMALL else k + 1, n):
                        if j > k:
                            Ar[i * n + j] -= lr * Ar[k * n + j] - li * Ai[k * n + j]
                            Ai[i * n + j] -= lr * Ai[k * n + j] + li * Ar[k * n + j]
    return 0


cdef inline void clu_solve(int n, const double* Ar, const double* Ai, const int* piv, double* br,
                           double* bi) noexcept nogil:
    """Solve (Ar + i Ai) x = br + i bi with the factors of clu_factor; (br, bi) becomes x."""
    cdef int i, j
    cdef double vr, vi
    for i in range(n):
        j = piv[i]
        if j != i:
            vr = br[i]
            br[i] = br[j]
            br[j] = vr
            vi = bi[i]
            bi[i] = bi[j]
            bi[j] = vi
    for i in range(1, n):
        vr = br[i]
        vi = bi[i]
        for j in range(n if n <= LA_SMALL else i):
            if j < i:
                vr -= Ar[i * n + j] * br[j] - Ai[i * n + j] * bi[j]
                vi -= Ar[i * n + j] * bi[j] + Ai[i * n + j] * br[j]
        br[i] = vr
        bi[i] = vi
    for i in range(n - 1, -1, -1):
        vr = br[i]
        vi = bi[i]
        for j in range(0 if n <= LA_SMALL else i + 1, n):
            if j > i:
                vr -= Ar[i * n + j] * br[j] - Ai[i * n + j] * bi[j]
                vi -= Ar[i * n + j] * bi[j] + Ai[i * n + j] * br[j]
        br[i] = vr * Ar[i * n + i] - vi * Ai[i * n + i]
        bi[i] = vr * Ai[i * n + i] + vi * Ar[i * n + i]


cdef inline int cholesky_solve(int n, double* A, double* b) noexcept nogil:
    """Solve A x = b for a symmetric A that must be positive definite (a mass matrix), by
    Cholesky's factorization A = L L^T, in place (the lower triangle of A becomes L, the upper
    is left); b becomes x.  Returns 0, or k + 1 when pivot k is not positive: the leading
    (k+1) x (k+1) block is not positive definite, and x is not computed.  Half the work of
    solve_inplace, and it tells an indefinite or singular mass matrix apart."""
    cdef int i, j, k
    cdef double v
    for k in range(n):
        v = A[k * n + k]
        for j in range(k):
            v -= A[k * n + j] * A[k * n + j]
        if not v > 0.0:            # also catches NaN
            return k + 1
        v = sqrt(v)
        A[k * n + k] = v
        for i in range(k + 1, n):
            for j in range(k):
                A[i * n + k] -= A[i * n + j] * A[k * n + j]
            A[i * n + k] /= v
    for i in range(n):                      # L y = b
        v = b[i]
        for j in range(i):
            v -= A[i * n + j] * b[j]
        b[i] = v / A[i * n + i]
    for i in range(n - 1, -1, -1):          # L^T x = y
        v = b[i]
        for j in range(i + 1, n):
            v -= A[j * n + i] * b[j]
        b[i] = v / A[i * n + i]
    return 0


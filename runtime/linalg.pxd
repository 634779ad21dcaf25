# Small dense linear algebra for generated right-hand sides (inline, nogil).

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

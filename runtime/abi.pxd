# The C interface between generated models and the compiled integrators.
#
# A generated module fills one ModelC with pointers to its nogil functions and
# hands it to Python as a PyCapsule named "camdyn.ModelC"; the integrators in
# camdyn.runtime._integrate take the pointer out of the capsule once and then
# call the model through these pointers only, with no Python in the loop.
#
# State layout: y = [q_1..q_n, q'_1..q'_n, first-order states...].
# This header has no .pyx of its own on purpose: cimporting it never imports
# a module at run time.

cdef struct Ctx:
    const double* p        # parameters, in manifest order
    const int* law         # cam law code per cam input family
    const double* law_par  # cam law parameter (theta of the modified sine) per family
    int* mode              # discrete mode per cam input instance (segment of the law)
    double* work           # scratch for the model (e.g. the mass matrix), n_work doubles

ctypedef void (*rhs_fn)(double t, const double* y, double* dy, Ctx* ctx) noexcept nogil
ctypedef void (*out_fn)(double t, const double* y, double* out, Ctx* ctx) noexcept nogil
ctypedef void (*mode_fn)(double t, const double* y, Ctx* ctx) noexcept nogil

cdef struct ModelC:
    int abi_version        # CAMDYN_ABI below; checked before any call
    int n_q                # second-order coordinates
    int n_states
    int n_params
    int n_outputs
    int n_families         # cam input families (H, ...)
    int n_instances        # distinct cam input arguments (one mode each)
    int n_work
    rhs_fn rhs             # dy = f(t, y)
    out_fn outputs         # named outputs at (t, y)
    mode_fn update_modes   # segment of every cam input at (t, y), right-continuous

cdef enum:
    CAMDYN_ABI = 1

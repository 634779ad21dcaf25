# The check of a run's coordinate partition (Ctx.part), for the driver and the figure finder,
# which take it from Python.

from camdyn.runtime.engine.abi cimport ModelC, partition_ok


cdef inline int check_partition(ModelC* m, const int[::1] part) except -1:
    """A ValueError unless ``part`` is None (the declared partition) or a coordinate partition
    of the constrained model m (Ctx.part)."""
    if part is not None and not partition_ok(m, &part[0] if part.shape[0] else NULL,
                                             part.shape[0]):
        raise ValueError(f"a coordinate partition is {m.n_q} distinct coordinate indices of a "
                         "constrained model, the dependent ones first")
    return 0

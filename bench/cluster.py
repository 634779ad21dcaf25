"""The Dask cluster the sweep benchmarks (sweep.py, atlas.py) time `camdyn sweep` on: a
LocalCluster of 2 worker processes, 1 thread each, its start timed apart."""
from __future__ import annotations

import time


def start_local_cluster(say) -> tuple:
    """(client, cluster, seconds the start took); (None, None, NaN), said once through ``say``,
    where dask.distributed is not installed.  The caller closes client and cluster."""
    try:
        from distributed import Client, LocalCluster
    except ImportError:
        say("dask.distributed is not installed (pip install 'dask[distributed]'): no Dask row")
        return None, None, float("nan")
    t0 = time.perf_counter()
    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                           dashboard_address=None)
    client = Client(cluster)
    return client, cluster, time.perf_counter() - t0

"""Batch solves on a Dask cluster (dask.distributed): the rows split into chunks, each chunk solved by
lac.solve_batch on a worker, the columns concatenated in row order. Rows are independent and every
solve is deterministic, so the result equals the local run row for row.

    from dask.distributed import Client, LocalCluster
    client = Client(LocalCluster(n_workers=4))           # or Client("tcp://scheduler:8786")
    t = lac.solve_batch("g1", data, client=client)

The workers must be able to ``import lac`` (the same build on PYTHONPATH, or installed).
"""
import numpy as np

from .batch import EXTRA_COLUMNS, RESULT_COLUMNS, _kind, rows_of, slice_rows


def _solve_chunk(kind, data, threads, options):
    from . import _lac  # imported on the worker

    out = _lac._solve_batch(kind, data, threads=threads, **options)
    return {k: out[k] for k in RESULT_COLUMNS + EXTRA_COLUMNS if k in out}


def local_client(n_workers=2, processes=True, threads_per_worker=1, **kwargs):
    """A dask.distributed Client on a LocalCluster of this machine (the default cluster)."""
    from dask.distributed import Client, LocalCluster

    cluster = LocalCluster(n_workers=n_workers, processes=processes, threads_per_worker=threads_per_worker,
                           dashboard_address=None, **kwargs)
    return Client(cluster)


def solve_batch_dask(client, kind, data, *, threads=0, chunk_rows=None, timeout=None, **options):
    """lac.solve_batch(kind, data, client=client, ...): see there. `timeout` (seconds) bounds the
    wait for the results (dask's TimeoutError past it)."""
    from ._columns import Columns

    k = _kind(kind)
    data = dict(data)
    n = rows_of(k, data)
    if chunk_rows is None:
        workers = max(1, len(client.scheduler_info().get("workers", {})))
        chunk_rows = max(1, -(-n // (4 * workers)))
    bounds = [(a, min(n, a + chunk_rows)) for a in range(0, n, chunk_rows)]
    futures = [client.submit(_solve_chunk, k, slice_rows(k, data, a, b), threads, options, pure=False)
               for a, b in bounds]
    parts = client.gather(futures) if timeout is None else [f.result(timeout=timeout) for f in futures]
    return Columns({key: np.concatenate([p[key] for p in parts]) for key in parts[0]})

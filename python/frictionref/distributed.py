"""Parameter maps on a Dask cluster (python3-distributed), by shards.

A map's grid is cut into contiguous shards (frictionref.map(..., shard=(i, n))),
each shard runs as one task on a worker, and the shards' rows are joined in
order: the result is the single-process map, bit for bit (each point is
computed by itself, the same way, wherever it runs). docs/python.md has the
measured speed-up and how it scales.

    >>> from distributed import Client
    >>> import frictionref.distributed
    >>> with Client("tcp://scheduler:8786") as client:
    ...     m = frictionref.distributed.map(client, "lambda:0:1.2:241",
    ...                                     "frequency-ratio:0.1:3:146", stiffness=1)
"""

import numpy

import frictionref


def _shard(x, y, index, count, threads, keywords):
    # Runs on a worker: one shard, on that worker's threads.
    return frictionref.map(x, y, shard=(index, count), threads=threads, **keywords)


def map(client, x, y, *, shards=None, threads_per_shard=None, **keywords):
    """frictionref.map(x, y, **keywords) over a distributed.Client, by shards.

    shards: how many tasks the grid is cut into (default: 4 per worker
    thread of the cluster: the points' costs vary, and several shards per
    worker keep them all busy to the end). threads_per_shard: threads each task uses (default 1,
    since Dask already runs one task per worker thread). Every other keyword
    is frictionref.map's (periods, the model keywords); bad input raises
    ValueError here, before anything is sent to the cluster.

    Returns the same structured array as frictionref.map(x, y, **keywords).
    """
    if "shard" in keywords or "progress" in keywords:
        raise TypeError("distributed.map() sets shard itself and takes no progress callback")
    # The whole map's checks, on a single point of it: fails here, not on a worker.
    frictionref.map(x, y, shard=(1, 10**6), threads=1, **keywords)
    if shards is None:
        shards = max(1, 4 * sum(client.nthreads().values()))
    if isinstance(shards, bool) or not isinstance(shards, int) or not 1 <= shards <= 10**6:
        raise ValueError(f"shards = {shards!r}: must be a whole number from 1 to 10^6")
    threads = 1 if threads_per_shard is None else threads_per_shard
    futures = [
        client.submit(_shard, x, y, i, shards, threads, keywords, pure=False)
        for i in range(1, shards + 1)
    ]
    parts = client.gather(futures)
    # Filled in place rather than numpy.concatenate, which would repack the
    # structured dtype: the result has frictionref.map's exact layout.
    rows = numpy.empty(sum(len(part) for part in parts), dtype=parts[0].dtype)
    begin = 0
    for part in parts:
        rows[begin:begin + len(part)] = part
        begin += len(part)
    return rows

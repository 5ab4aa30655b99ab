#!/usr/bin/env python3
"""Times one map three ways: one process on one thread, one process on all
cores (frictionref.map's threads), and a Dask LocalCluster of worker
processes (frictionref.distributed.map), and checks the three agree bit for
bit. The numbers in docs/python.md come from this script.

    PYTHONPATH=build/release/python python3 docs/examples/dask_speedup.py [WORKERS]
"""
import os
import sys
import time

from distributed import Client, LocalCluster

import frictionref
import frictionref.distributed

X, Y = "lambda:0.05:1.2:40", "frequency-ratio:0.2:3:30"
KEYWORDS = dict(stiffness=1, damping=0.02, periods=200)


def timed(label, run):
    start = time.perf_counter()
    rows = run()
    seconds = time.perf_counter() - start
    print(f"{label:44s} {seconds:7.2f} s", flush=True)
    return rows, seconds


def main():
    workers = int(sys.argv[1]) if len(sys.argv) > 1 else os.cpu_count()
    print(f"map {X} x {Y}, {KEYWORDS}; load average {os.getloadavg()[0]:.1f} "
          f"on {os.cpu_count()} cores")
    one, t1 = timed("one process, 1 thread", lambda: frictionref.map(X, Y, threads=1, **KEYWORDS))
    threads, tt = timed(f"one process, {workers} threads",
                        lambda: frictionref.map(X, Y, threads=workers, **KEYWORDS))
    with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                      dashboard_address=None) as cluster, Client(cluster) as client:
        client.run(lambda: __import__("frictionref"))  # workers import the module before timing
        dask, td = timed(f"Dask LocalCluster, {workers} worker processes",
                         lambda: frictionref.distributed.map(client, X, Y, shards=8 * workers,
                                                             **KEYWORDS))
    assert one.tobytes() == threads.tobytes() == dask.tobytes(), "results differ"
    print(f"{len(one)} points, {1000 * t1 / len(one):.2f} ms of CPU per point; speed-up "
          f"{t1 / tt:.2f} (threads), {t1 / td:.2f} (Dask); identical bit for bit")


if __name__ == "__main__":  # the worker processes re-import this file
    main()

"""frictionref.distributed.map on a Dask LocalCluster (two worker processes):
the same rows as the single-process map, bit for bit."""
import pytest

import frictionref

distributed = pytest.importorskip("distributed")


def test_distributed_map_equals_the_single_process_map():
    args = ("lambda:0.1:0.9:5", "frequency-ratio:0.5:2:4")
    keywords = dict(stiffness=1, damping=0.05, periods=60)
    expected = frictionref.map(*args, **keywords)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        got = frictionref.distributed.map(client, *args, **keywords)
        assert got.tobytes() == expected.tobytes()
        # More shards than workers (and some empty): the same rows.
        more = frictionref.distributed.map(client, *args, shards=25, **keywords)
        assert more.tobytes() == expected.tobytes()
        # Bad input is refused here, not on a worker.
        with pytest.raises(ValueError, match="^--periods = 1: must be >= 2$"):
            frictionref.distributed.map(client, *args, stiffness=1, periods=1)

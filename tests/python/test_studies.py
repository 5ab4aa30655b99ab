"""sweep() and map(): against the seed's steady state (closed_forms.py),
by shards and threads bit for bit, and the CLI (consistency)."""
import numpy as np
import pytest

import frictionref
from closed_forms import steady_state
from conftest import joined, read_csv

LAMBDAS = [0.1, 0.3, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.2]


def test_sweep_against_the_closed_form_steady_state():
    s = frictionref.sweep(LAMBDAS, periods=100)
    for row in s:
        regime, stuck, slide = steady_state(row["lambda"])
        assert row["regime_simulated"] == row["regime_threshold"] == regime
        assert abs(row["stuck_fraction"] - float(stuck)) <= 1e-12
        # The transient decays as exp(-4 lambda P) (docs/cli.md): 1e-16 at lambda = 0.1.
        assert abs(row["slide_per_period"] - float(slide)) <= 1e-12 * max(1, float(slide))
        assert row["stops_per_period"] == (2 if regime == "dead-bands" else 0)
        assert row["reversals_per_period"] == (2 if regime == "continuous" else 0)


def test_sweep_grid_is_the_decimal_grid():
    s = frictionref.sweep(lambda_from=0, lambda_to=1.2, points=13, periods=2)
    assert list(s["lambda"]) == [0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.1, 1.2]


def test_sweep_shards_and_threads_give_the_same_rows():
    whole = frictionref.sweep(lambda_from=0, lambda_to=1.2, points=101, periods=20, stiffness=1,
                              omega=2)
    parts = [frictionref.sweep(lambda_from=0, lambda_to=1.2, points=101, periods=20,
                               stiffness=1, omega=2, shard=(i, 4), threads=1)
             for i in range(1, 5)]
    assert joined(parts).tobytes() == whole.tobytes()


def test_map_of_the_seeds_model_follows_lambda_star():
    # The seed's model in other masses: the regime and stuck fraction depend on lambda only.
    m = frictionref.map(("lambda", 0.3, 0.9, 4), "mass:1:2:2", periods=50)
    assert m.dtype.names == ("lambda", "mass", "regime", "stops_per_period",
                             "reversals_per_period", "multiplicity", "stuck_fraction",
                             "transient_periods")
    for row in m:
        regime, stuck, _ = steady_state(row["lambda"])
        assert row["regime"] == regime
        assert abs(row["stuck_fraction"] - float(stuck)) <= 1e-12


def test_map_shards_concatenate_to_the_whole_map():
    args = ("lambda:0.1:0.9:5", "frequency-ratio:0.5:2:3")
    whole = frictionref.map(*args, stiffness=1, periods=60)
    parts = [frictionref.map(*args, stiffness=1, periods=60, shard=f"{i}/4") for i in range(1, 5)]
    assert joined(parts).tobytes() == whole.tobytes()


def test_progress_is_called_and_can_stop_the_study():
    calls = []
    frictionref.sweep(lambda_from=0, lambda_to=1, points=11, periods=5,
                      progress=lambda done, total: calls.append((done, total)))
    assert calls[-1] == (11, 11)

    class Stop(Exception):
        pass

    def stop(done, total):
        raise Stop()

    with pytest.raises(Stop):
        frictionref.map("lambda:0:1:50", "mass:1:2:50", periods=400, progress=stop)


def test_sweep_consistency_with_the_cli(cli):
    code, out, _ = cli("sweep", "--lambda-from", "0", "--lambda-to", "1", "--points", "21",
                       "--periods", "10", "--static-ratio", "1.5", "--stiffness", "1")
    assert code == 0
    rows = read_csv(out)
    s = frictionref.sweep(lambda_from=0, lambda_to=1, points=21, periods=10, static_ratio=1.5,
                          stiffness=1)
    for row, got in zip(rows, s, strict=True):
        for key in got.dtype.names:
            expected = row[key]
            assert (str(got[key]) if isinstance(got[key], str) else float(got[key])) == (
                expected if isinstance(got[key], str) else float(expected)), key


def test_map_consistency_with_the_cli(cli):
    code, out, _ = cli("map", "--x", "lambda:0.1:0.9:3", "--y", "damping-ratio:0:0.2:3",
                       "--stiffness", "1", "--periods", "40")
    assert code == 0
    rows = read_csv(out)
    m = frictionref.map("lambda:0.1:0.9:3", "damping-ratio:0:0.2:3", stiffness=1, periods=40)
    for row, got in zip(rows, m, strict=True):
        for key in got.dtype.names:
            value = got[key]
            assert (value if isinstance(value, str) else float(value)) == (
                row[key] if isinstance(value, str) else float(row[key])), key

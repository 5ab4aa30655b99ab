"""curve() against the closed forms (closed_forms.py) and the CLI (consistency)."""
import numpy as np
import pytest

import frictionref
from closed_forms import case_10_3, close, dead_band_phases, dead_band_state
from conftest import read_csv


def test_case_10_2_at_any_times_in_any_order():
    rng = np.random.default_rng(7)
    t = rng.uniform(0, 30, 400)
    c = frictionref.curve(frictionref.Model(lambda_=0.7), t)
    assert list(c.dtype.names) == ["t", "x", "v", "a", "phase"]
    assert np.array_equal(c["t"], t)
    for row in c:
        x, v, kind = dead_band_state(0.7, row["t"])
        assert row["phase"] == kind
        # x and v are closed forms of t: a few ulps of their scale (1), and
        # the event times they start from are within an ulp.
        assert close(row["v"], v, ulps=64) and close(row["x"], x, ulps=64)
        if kind == "stick":
            assert row["a"] == 0
        else:
            sign = 1 if kind == "slip+" else -1
            assert close(row["a"], np.sin(row["t"]) - sign * 0.7, ulps=16)


def test_phase_boundaries_carry_the_new_phase():
    # At the engine's own event times (the semantics, not the times, are tested here).
    model = frictionref.Model(lambda_=0.7)
    table = frictionref.events(model, 30)
    times = np.append(table["t_begin"][1:], 30.0)  # 30 is the horizon
    c = frictionref.curve(model, times)
    assert list(c["phase"][:-1]) == list(table["phase"][1:])
    assert list(c["phase"][:-1]) == [kind for kind, *_ in dead_band_phases(0.7, 30)[1:]]


def test_case_10_3():
    t = np.linspace(0, 3, 301)
    c = frictionref.curve(frictionref.Model(lambda_=1.01, v0=-1), t)
    for row in c:
        x, v, kind = case_10_3(row["t"])
        assert row["phase"] == kind
        assert close(row["x"], x, ulps=64) and close(row["v"], v, ulps=64)


def test_grid_rows_as_the_cli_grid():
    c = frictionref.curve(frictionref.Model(lambda_=0.7), t_end=30, dt=0.01)
    assert len(c) == 3001 and c["t"][0] == 0 and c["t"][-1] == 30
    assert c["t"][1234] == 1234 * 0.01  # t0 + i dt, never accumulated
    with_events = frictionref.curve(frictionref.Model(lambda_=0.7), t_end=30, dt=0.01,
                                    include_events=True)
    assert len(with_events) == 3001 + 19  # plus every phase boundary before 30


def test_empty_times_give_an_empty_table():
    assert len(frictionref.curve(frictionref.Model(lambda_=0.7), [])) == 0


def test_consistency_with_the_cli_curve(cli):
    code, out, _ = cli("curve", "--lambda", "0.4", "--static-lambda", "0.6", "--stiffness", "1",
                       "--damping", "0.1", "--t-end", "30", "--dt", "0.05", "--include-events")
    assert code == 0
    rows = read_csv(out)
    c = frictionref.curve(frictionref.Model(lambda_=0.4, static_lambda=0.6, stiffness=1,
                                            damping=0.1), t_end=30, dt=0.05, include_events=True)
    assert len(rows) == len(c)
    for row, got in zip(rows, c):
        assert [float(row[k]) for k in "txva"] == [got[k] for k in "txva"]
        assert row["phase"] == got["phase"]
    # The same states at the same times through curve(model, t).
    again = frictionref.curve(frictionref.Model(lambda_=0.4, static_lambda=0.6, stiffness=1,
                                                damping=0.1), c["t"])
    assert again.tobytes() == c.tobytes()


def test_times_before_t0_are_refused():
    with pytest.raises(ValueError, match=r"^t\[1\] = -1: must be >= t0 = 0$"):
        frictionref.curve(frictionref.Model(lambda_=0.7), [0.5, -1])


def test_times_in_any_order_give_the_grid_rows_bit_for_bit():
    # curve(model, t) evaluates the times of one phase together (the seed's
    # dense fast path takes four at a time): the answers do not depend on the
    # order or on the company, so they are the grid's rows exactly.
    model = frictionref.Model(lambda_=0.3)
    grid = frictionref.curve(model, t_end=30, dt=0.01)
    order = np.random.default_rng(11).permutation(len(grid))
    c = frictionref.curve(model, grid["t"][order])
    for name in ("x", "v", "a", "phase"):
        assert np.array_equal(c[name], grid[name][order]), name

"""events(), phases(), summary() against the closed forms of the seed's
dead-band motion (closed_forms.py, mpmath) and the CLI (consistency)."""
import math

import numpy as np
import pytest

import frictionref
from closed_forms import case_10_3_stop, close, dead_band_phases, dead_band_state
from conftest import joined, read_csv

FIELDS = ["phase", "t_begin", "t_end", "x_begin", "x_end", "v_begin", "v_end"]


def test_case_10_2_phase_table_is_the_closed_form():
    table = frictionref.events(frictionref.Model(lambda_=0.7), 30)
    assert list(table.dtype.names) == FIELDS
    expected = dead_band_phases(0.7, 30)
    assert len(table) == len(expected) == 20
    for row, (kind, t0, t1, x0, x1) in zip(table, expected):
        assert row["phase"] == kind
        # Event times within 4 ulps of |t| (docs/accuracy.md: 0.5005).
        assert close(row["t_begin"], t0, scale=1) and close(row["t_end"], t1, scale=1)
        # Positions are differences of closed forms: a few ulps of the slide.
        assert close(row["x_begin"], x0, ulps=16)
        if row["t_end"] < 30:
            assert close(row["x_end"], x1, ulps=16)
    # The last phase is cut at t = 30.
    x, v, _ = dead_band_state(0.7, 30)
    assert close(table["x_end"][-1], x, ulps=64) and close(table["v_end"][-1], v, ulps=64)
    assert np.all(table["v_begin"][:-1] == 0) and np.all(table["v_end"][:-1] == 0)


def test_case_10_3_one_slide_then_rest():
    table = frictionref.events(frictionref.Model(lambda_=1.01, v0=-1), 30)
    assert list(table["phase"]) == ["slip-", "stick"]
    assert close(table["t_end"][0], case_10_3_stop(), scale=1)
    assert table["v_begin"][0] == -1 and table["t_end"][-1] == 30


def test_phases_iterator_streams_the_same_table():
    model = frictionref.Model(lambda_=0.3, stiffness=1, damping=0.1)
    table = frictionref.events(model, 200)
    one = list(frictionref.phases(model, 200))
    assert len(one) == len(table)
    for p, row in zip(one, table):
        assert isinstance(p, frictionref.Phase)
        assert tuple(p) == tuple(row[f] for f in FIELDS)
    stream = frictionref.phases(model, 200, chunk=7)
    chunks = list(stream)
    assert all(len(c) <= 7 for c in chunks)
    assert joined(chunks).tobytes() == table.tobytes()
    assert stream.summary == frictionref.summary(model, 200)


def test_summary_counts():
    s = frictionref.summary(frictionref.Model(lambda_=0.7), 30)
    # 10 sticks, 5 slides each way; 9 stops before t = 30 (the 10th slide is cut).
    assert (s["phases"], s["stick"], s["slip+"], s["slip-"], s["stops"]) == (20, 10, 5, 5, 9)
    assert s["termination"] == "reached_end" and s["t"] == 30


def test_max_phases_stops_early():
    table = frictionref.events(frictionref.Model(lambda_=0.7), 30, max_phases=3)
    assert len(table) == 3


def test_result_is_handed_over_without_a_copy():
    table = frictionref.events(frictionref.Model(lambda_=0.7), 30)
    assert not table.flags.owndata and table.base is not None


def test_consistency_with_the_cli_events(cli):
    # Consistency, not correctness: the CLI runs the same engine.
    model = frictionref.Model(mass=2, amplitude=5, omega=3, friction=1.5, v0=-1, stiffness=0.5)
    code, out, _ = cli("events", "--mass", "2", "--amplitude", "5", "--omega", "3",
                       "--friction", "1.5", "--v0", "-1", "--stiffness", "0.5", "--t-end", "100")
    assert code == 0
    rows = read_csv(out)
    table = frictionref.events(model, 100)
    assert len(rows) == len(table)
    for row, got in zip(rows, table):
        assert row["phase"] == got["phase"]
        for f in FIELDS[1:]:
            assert float(row[f]) == got[f]


def test_huge_horizons_are_refused_as_by_the_cli(cli_error):
    model = frictionref.Model(lambda_=0.3)
    with pytest.raises(ValueError) as error:
        frictionref.events(model, 1e10)
    assert str(error.value) == cli_error("events", "--lambda", "0.3", "--t-end", "1e+10")

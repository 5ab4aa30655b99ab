"""compare(): the exact motion passes, a wrong one fails, and the report
matches the CLI's JSON for the same record (consistency)."""
import json

import numpy as np

import frictionref
from closed_forms import case_10_3, dead_band_state


def exact_record(state, t):
    x, v = zip(*[(float(s[0]), float(s[1])) for s in map(state, t)])
    return np.array(x), np.array(v)


def test_the_closed_form_passes_and_a_shifted_one_fails():
    t = np.linspace(0, 30, 3001)
    x, v = exact_record(lambda s: dead_band_state(0.7, s), t)
    model = frictionref.Model(lambda_=0.7)
    report = frictionref.compare(model, t, v, x)
    assert report["verdict"] == "PASS" and report["failed_checks"] == []
    assert report["velocity_error"]["max"] < 1e-12
    assert len(report["sticks"]["matched"]) == 10
    assert "verdict: PASS" in report["report"]
    shifted = frictionref.compare(model, t, v + 0.05)
    assert shifted["verdict"] == "FAIL" and "velocity_max" in shifted["failed_checks"]


def test_case_10_3_and_displacement():
    t = np.linspace(0, 10, 1001)
    x, v = exact_record(case_10_3, t)
    model = frictionref.Model(lambda_=1.01, v0=-1)
    assert frictionref.compare(model, t, v, x)["verdict"] == "PASS"
    wrong = frictionref.compare(model, t, v, x + 0.1)
    assert wrong["failed_checks"] == ["displacement_max"]


def test_stiff_spring_passes_as_in_the_seed():
    model = frictionref.Model(lambda_=0.7)
    s = frictionref.stiff(model, 30)
    assert frictionref.compare(model, s["t"], s["v"])["verdict"] == "PASS"


def test_consistency_with_the_cli_json(cli, tmp_path):
    model = frictionref.Model(lambda_=0.7)
    s = frictionref.stiff(model, 30, kf=1e5)
    path = tmp_path / "run.csv"
    with open(path, "w") as f:
        f.write("t,x,v\n")
        for row in s:
            f.write(f"{row['t']!r},{row['x']!r},{row['v']!r}\n")
    code, out, _ = cli("compare", "--candidate", path, "--lambda", "0.7", "--json",
                       "--displacement-column", "x", "--max-extra-stops", "1")
    assert code in (0, 1)
    expected = json.loads(out)
    got = frictionref.compare(model, s["t"], s["v"], s["x"], max_extra_stops=1)
    for key in ("candidate", "command", "report"):
        expected.pop(key, None)
        got.pop(key, None)
    for check in expected["checks"]:
        check.pop("message")
    for check in got["checks"]:
        check.pop("message")
    assert got == expected


def test_samples_that_cannot_see_the_motion_are_inconclusive():
    # The mpmath closed form every 0.1: every check passes, but the events
    # fall between samples further apart than the stop-time tolerance.
    t = np.linspace(0, 30, 301)
    x, v = exact_record(lambda s: dead_band_state(0.7, s), t)
    report = frictionref.compare(frictionref.Model(lambda_=0.7), t, v, x)
    assert report["failed_checks"] == []
    assert report["verdict"] == "INCONCLUSIVE"
    resolution = report["resolution"]
    assert not resolution["resolved"] and resolution["unresolved_events"] > 0
    assert resolution["resolving_step"] == 0.01 * 2 * np.pi / 2
    assert "verdict: INCONCLUSIVE" in report["report"]

"""Ground-motion records from Python: Model(ground_accel=...) with events,
curve, summary and stiff, and frictionref.newmark(), against motions solved
by hand, against the CLI's output for the same input, and bad input raising
ValueError with the CLI's message.

The hand-solved record is a rectangular pulse: a_g = A for 0 <= t <= T and 0
after (the record is 0 after its last sample), on a rigid block of yield
acceleration KY, mu = KY g. In SLAMMER's convention (newmark's "normal"
polarity) the block's downslope acceleration relative to the ground is
a_g - mu while it slides downslope, so if A > mu it slides at once:

    v(t) = (A - mu) t,  x(t) = (A - mu) t^2 / 2          (0 <= t <= T),

then, the ground still, slows at mu and stops at t_s = T + v(T) / mu = A T / mu:

    x(t) = x(T) + v(T) (t - T) - mu (t - T)^2 / 2        (T <= t <= t_s),
    D = x(t_s) = (A - mu) T^2 / 2 + ((A - mu) T)^2 / (2 mu) = A (A - mu) T^2 / (2 mu).

One slide, the largest speed v(T) = (A - mu) T. If A <= mu it never slides.
The "inverse" polarity pushes the block upslope: the one-way block stays
put; the two-way block slides the mirror image, -D. With KY = 0 it never
stops: x(T) = A T^2 / 2 and the speed A T for ever.
"""
import json
import math
import os
import pickle

import numpy as np
import pytest

import frictionref
from conftest import read_csv

G = 9.80665  # the default --gravity: metres
M = frictionref.Model
# The synthetic records of the repository (data/records/generate_synthetic.py).
SOURCE = os.environ.get("FRICTIONREF_SOURCE_DIR",
                        os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
SYNTHETIC = os.path.join(SOURCE, "data", "records", "synthetic")


def write_pulse(path, a, duration, header="t,a"):
    """A two-sample table: a for 0 <= t <= duration (in the file's units)."""
    path.write_text(f"{header}\n0,{a!r}\n{duration!r},{a!r}\n")
    return path


def pulse_motion(a, mu, duration):
    """The hand solution above: (x(T), D or None, slides, max speed) in the
    normal polarity."""
    if mu == 0:
        return a * duration**2 / 2, None, 1, a * duration
    if not a > mu:
        return 0.0, 0.0, 0, 0.0
    return ((a - mu) * duration**2 / 2, a * (a - mu) * duration**2 / (2 * mu), 1,
            (a - mu) * duration)


def close(x, y):
    return math.isclose(x, y, rel_tol=1e-12, abs_tol=1e-12)


# ---------------------------------------------------------------- newmark()


@pytest.mark.parametrize("one_way", [True, False])
def test_newmark_rectangular_pulse_by_hand(tmp_path, one_way):
    a_g, duration = 0.5, 2.0  # in g, s
    kys = [0, 0.1, 0.2, 0.3, 0.5, 0.6]
    record = write_pulse(tmp_path / "pulse.csv", a_g, duration)
    r = frictionref.newmark(str(record), kys, one_way=one_way, polarity="both")
    assert len(r["record"]) == len(kys) * 2
    assert list(r["polarity"]) == ["normal", "inverse"] * len(kys)
    assert set(r["method"]) == {"exact"} and set(r["length_unit"]) == {"m"}
    assert list(r["yield_accel_g"]) == [ky for ky in kys for _ in (0, 1)]
    assert all(r["pga_g"] == a_g)
    for i, ky in enumerate(kys):
        at_end, permanent, slides, speed = pulse_motion(a_g * G, ky * G, duration)
        normal, inverse = 2 * i, 2 * i + 1
        assert close(r["displacement_at_record_end"][normal], at_end), ky
        if permanent is None:
            assert math.isnan(r["permanent_displacement"][normal])
        else:
            assert close(r["permanent_displacement"][normal], permanent), ky
        assert r["slip_episodes"][normal] == slides
        assert close(r["max_relative_velocity"][normal], speed)
        # Upslope: the mirror image, or nothing for the one-way block.
        sign = 0 if one_way else -1
        assert close(r["displacement_at_record_end"][inverse], sign * at_end)
        if permanent is None and not one_way:
            assert math.isnan(r["permanent_displacement"][inverse])
        else:
            assert close(r["permanent_displacement"][inverse], sign * (permanent or 0))
        assert r["slip_episodes"][inverse] == (0 if one_way else slides)


def test_newmark_units_scaling_and_one_column(tmp_path):
    # The same pulse, 0.5 g for 2 s, written four ways; KY = 0.2.
    expected = pulse_motion(0.5 * G, 0.2 * G, 2.0)[1]
    cm = write_pulse(tmp_path / "cm.csv", 0.5 * 980.665, 2.0)
    r = frictionref.newmark(cm, 0.2, accel_units="cm/s2", gravity=980.665)
    assert r["length_unit"][0] == "cm"
    assert math.isclose(r["permanent_displacement"][0], 100 * expected, rel_tol=1e-12)
    one_g = write_pulse(tmp_path / "one_g.csv", 1.0, 2.0)
    for scaling in ({"target_pga": 0.5}, {"scale": 0.5}):
        r = frictionref.newmark([one_g], [0.2], **scaling)
        assert r["pga_g"][0] == 0.5
        assert close(r["permanent_displacement"][0], expected), scaling
    column = tmp_path / "column.txt"
    column.write_text("0.5\n0.5\n")
    r = frictionref.newmark(column, 0.2, record_dt=2)
    assert close(r["permanent_displacement"][0], expected)


def test_newmark_progress_and_threads(tmp_path):
    record = write_pulse(tmp_path / "pulse.csv", 0.5, 2.0)
    calls = []
    r = frictionref.newmark(record, np.linspace(0.05, 0.45, 9), threads=2,
                            progress=lambda done, total: calls.append((done, total)))
    assert calls[-1] == (9, 9)
    assert np.array_equal(r["slip_episodes"], np.ones(9))

    def stop(done, total):
        raise RuntimeError("stopped by the callback")

    with pytest.raises(RuntimeError, match="stopped by the callback"):
        frictionref.newmark(record, 0.1, progress=stop)


def cli_newmark_json(cli, args):
    code, out, err = cli("newmark", *args, "--json")
    assert code == 0, err
    return json.loads(out)


def assert_same_as_cli(got, rows):
    """A newmark() dict against the rows of newmark --json, exactly."""
    assert len(got["record"]) == len(rows)
    for key in rows[0]:
        for i, row in enumerate(rows):
            value = got[key][i]
            if row[key] is None:
                assert math.isnan(value), (key, i)
            else:
                assert value == row[key], (key, i, value, row[key])


@pytest.mark.parametrize("options", [
    {},
    {"polarity": "both", "one_way": False},
    {"polarity": "inverse", "target_pga": 0.3, "gravity": 980.665},
    {"method": "slammer", "polarity": "both", "scale": 1.5},
])
def test_newmark_equals_the_cli(cli, options, monkeypatch):
    monkeypatch.chdir(SYNTHETIC)
    records = ["pulse-train.AT2", "noise-burst.AT2"]
    kys = [0.02, 0.1, 0.3]
    args = [a for f in records for a in ("--record", f)]
    args += ["--yield-accel", ",".join(map(repr, kys))]
    flags = {"one_way": {False: ["--two-way"]},
             "polarity": {"inverse": ["--inverse"], "both": ["--both-polarities"]},
             "method": {"slammer": ["--method", "slammer"]}}
    for key, value in options.items():
        args += flags[key][value] if key in flags else [f"--{key.replace('_', '-')}", repr(value)]
    rows = cli_newmark_json(cli, args)
    assert_same_as_cli(frictionref.newmark(records, kys, **options), rows)


def test_newmark_table_of_times_equals_the_cli(cli, monkeypatch):
    monkeypatch.chdir(SYNTHETIC)
    rows = cli_newmark_json(cli, ["--record", "nonuniform.csv", "--yield-accel", "0,0.05"])
    assert_same_as_cli(frictionref.newmark("nonuniform.csv", [0, 0.05]), rows)


# ------------------------------------------------- models with a record


def test_model_with_a_record_events_curve_summary_by_hand(tmp_path):
    a_g, duration, ky = 0.5, 2.0, 0.2
    record = write_pulse(tmp_path / "pulse.csv", a_g, duration)
    # The model's record enters as -m a_g: negated, x is the downslope
    # displacement (newmark's normal polarity).
    model = M(ground_accel=record, yield_accel=ky, inverse=True, one_way=True)
    a, mu = a_g * G, ky * G
    assert model.amplitude == 0 and model.friction == ky * G and model.one_way
    assert list(model.record["t"]) == [0, duration]
    assert list(model.record["a"]) == [-a, -a]
    assert model.record["factor"] == -G and model.record["format"] == "time-acceleration table"
    stop = a * duration / mu
    permanent = a * (a - mu) * duration**2 / (2 * mu)

    table = frictionref.events(model, 10)
    slides = table[table["phase"] != "stick"]
    assert len(slides) == 1 and slides["phase"][0] == "slip+"
    assert close(slides["t_begin"][0], 0) and close(slides["t_end"][0], stop)
    assert close(slides["x_end"][0], permanent)
    assert table["t_end"][-1] == 10 and close(table["x_end"][-1], permanent)

    t = np.array([duration / 2, duration, duration + 1, 9.0])
    c = frictionref.curve(model, t)
    v_t = (a - mu) * duration
    assert close(c["x"][0], (a - mu) * (duration / 2) ** 2 / 2)
    assert close(c["v"][0], (a - mu) * duration / 2)
    assert close(c["x"][1], (a - mu) * duration**2 / 2) and close(c["v"][1], v_t)
    assert close(c["x"][2], (a - mu) * duration**2 / 2 + v_t - mu / 2)
    assert close(c["v"][2], v_t - mu)
    assert close(c["x"][3], permanent) and c["v"][3] == 0
    assert list(c["phase"]) == ["slip+", "slip+", "slip+", "stick"]

    s = frictionref.summary(model, 10)
    assert close(s["x"], permanent) and s["v"] == 0 and s["slip+"] == 1 and s["slip-"] == 0


def test_compare_with_a_record_in_its_scales(tmp_path):
    """The hand solution above as a candidate passes, in the record's scales:
    PGV = a T (the ground's velocity after the pulse), PGA = a,
    T* = 2 pi PGV / PGA = 2 pi T; twice the deceleration after the pulse
    fails."""
    a_g, duration, ky = 0.5, 2.0, 0.2
    record = write_pulse(tmp_path / "pulse.csv", a_g, duration)
    model = M(ground_accel=record, yield_accel=ky, inverse=True, one_way=True)
    a, mu = a_g * G, ky * G

    def candidate(decel):
        t = np.linspace(0, 10, 1001)
        v_t = (a - mu) * duration
        v = np.where(t <= duration, (a - mu) * t, np.maximum(v_t - decel * (t - duration), 0))
        return t, v

    report = frictionref.compare(model, *candidate(mu))
    assert report["verdict"] == "PASS", report["report"]
    scales = report["scales"]
    assert scales["velocity_name"] == "PGV" and scales["period_name"] == "T* = 2 pi PGV/PGA"
    assert math.isclose(scales["velocity"], a * duration, rel_tol=1e-15)
    assert math.isclose(scales["period"], 2 * math.pi * duration, rel_tol=1e-15)
    wrong = frictionref.compare(model, *candidate(2 * mu))
    assert wrong["verdict"] == "FAIL"
    assert "stop_times" in wrong["failed_checks"]


def test_stiff_with_a_record_converges_to_the_hand_solution(tmp_path):
    # Two-way (the penalty model has no one-way slider); the record as given
    # pushes the block towards -x: the mirror image of the above, at rest
    # from t = A T / mu = 5 at -D. The record's step down at T costs the
    # explicit scheme an error of first order in its step, which goes as
    # 1 / sqrt(kf): 100 times kf, a tenth of the error.
    a_g, duration, ky = 0.5, 2.0, 0.2
    model = M(ground_accel=write_pulse(tmp_path / "pulse.csv", a_g, duration), yield_accel=ky)
    a, mu = a_g * G, ky * G
    permanent = a * (a - mu) * duration**2 / (2 * mu)
    errors = []
    for kf in (1e7, 1e9):
        s = frictionref.stiff(model, 6, kf=kf, output_dt=0.5)
        assert list(s["t"]) == [0.5 * i for i in range(13)]
        assert np.all(np.abs(s["f"]) <= mu * (1 + 1e-12))
        errors.append(abs(s["x"][-1] + permanent))
    assert errors[0] < 1e-3 * permanent
    assert errors[1] < errors[0] / 5


def test_events_and_stiff_equal_the_cli(cli, monkeypatch):
    monkeypatch.chdir(SYNTHETIC)
    args = ["--ground-accel", "pulse-train.AT2", "--inverse", "--yield-accel", "0.1",
            "--one-way", "--t-end", "25"]
    code, out, err = cli("events", *args)
    assert code == 0, err
    rows = read_csv(out)
    model = M(ground_accel="pulse-train.AT2", inverse=True, yield_accel=0.1, one_way=True)
    table = frictionref.events(model, 25)
    assert len(table) == len(rows) > 10
    for row, got in zip(rows, table):
        assert row["phase"] == got["phase"]
        for key in ("t_begin", "t_end", "x_begin", "x_end", "v_begin", "v_end"):
            assert float(row[key]) == got[key], key

    code, out, err = cli("stiff", "--ground-accel", "nonuniform.csv", "--scale", "2",
                         "--yield-accel", "0.05", "--gravity", "980.665", "--t-end", "3")
    assert code == 0, err
    rows = read_csv(out)
    s = frictionref.stiff(M(ground_accel="nonuniform.csv", scale=2, yield_accel=0.05,
                            gravity=980.665), 3)
    assert len(s) == len(rows)
    for row, got in zip(rows, s):
        for key in ("t", "x", "v"):
            assert float(row[key]) == got[key], key


def test_record_with_spring_damper_harmonic_equals_the_cli(cli, monkeypatch):
    # The general laws under a record (theory.md 9.6), one-way and two-way.
    monkeypatch.chdir(SYNTHETIC)
    for one_way in (False, True):
        args = ["--ground-accel", "noise-burst.AT2", "--yield-accel", "0.1", "--stiffness", "158",
                "--damping", "1.3", "--static-friction", "1.2", "--harmonic", "0.3,5,0.2",
                "--t-end", "15"] + (["--one-way"] if one_way else [])
        code, out, err = cli("events", *args)
        assert code == 0, err
        rows = read_csv(out)
        model = M(ground_accel="noise-burst.AT2", yield_accel=0.1, stiffness=158, damping=1.3,
                  static_friction=1.2, harmonics=[(0.3, 5, 0.2)], one_way=one_way)
        table = frictionref.events(model, 15)
        assert len(table) == len(rows) > 10
        assert one_way == all(got["phase"] != "slip-" for got in table)
        for row, got in zip(rows, table):
            assert row["phase"] == got["phase"]
            for key in ("t_begin", "t_end", "x_begin", "x_end", "v_begin", "v_end"):
                assert float(row[key]) == got[key], key


def test_model_with_a_record_repr_equality_pickle(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    write_pulse(tmp_path / "pulse.csv", 0.5, 2.0)
    model = M(ground_accel="pulse.csv", yield_accel=0.2, inverse=True, one_way=True)
    assert repr(model) == ("frictionref.Model(yield_accel=0.2, ground_accel='pulse.csv', "
                           "inverse=True, one_way=True)")
    assert eval(repr(model), {"frictionref": frictionref}) == model
    assert model.ground_accel == "pulse.csv" and M(friction=1).ground_accel is None
    d = model.to_dict()
    assert d["amplitude"] == 0 and d["ground_accel"] == "pulse.csv" and d["one_way"] is True
    assert d["record_sha256"] == model.record["sha256"] and len(d["record_sha256"]) == 64
    copy = pickle.loads(pickle.dumps(model))
    assert copy == model and hash(copy) == hash(model) and repr(copy) == repr(model)
    # By value: the same samples under another name are the same model;
    # another scaling, sign or sliding is not.
    (tmp_path / "same.csv").write_bytes((tmp_path / "pulse.csv").read_bytes())
    assert M(ground_accel="same.csv", yield_accel=0.2, inverse=True, one_way=True) == model
    assert M(ground_accel="pulse.csv", yield_accel=0.2, inverse=True) != model
    assert M(ground_accel="pulse.csv", yield_accel=0.2, one_way=True) != model
    assert M(ground_accel="pulse.csv", yield_accel=0.2, inverse=True, one_way=True,
             scale=2) != model
    assert M(friction=0.2 * G, amplitude=0) != M(ground_accel="pulse.csv", yield_accel=0.2)
    # Unpickling reads the file again: it must still be the same file.
    state = pickle.dumps(model)
    write_pulse(tmp_path / "pulse.csv", 0.6, 2.0)
    with pytest.raises(ValueError, match=r"^--ground-accel = pulse.csv: is not the file the "
                                         r"model was pickled with \(SHA-256 [0-9a-f]{64}, now "):
        pickle.loads(state)
    (tmp_path / "pulse.csv").unlink()
    with pytest.raises(ValueError, match=r"^--ground-accel = pulse.csv: "):
        pickle.loads(state)


def test_a_model_without_a_record_is_unchanged():
    m = M(lambda_=0.7)
    assert m.record is None and not m.one_way and "ground_accel" not in m.to_dict()
    assert repr(m) == "frictionref.Model(lambda_=0.7)"
    # yield_accel without a record: R = m KY g.
    assert M(yield_accel=0.1, mass=2, gravity=1).friction == 0.2


# ------------------------------------------------------------ bad input

PULSE = "pulse.csv"
TWO_COLUMNS = ["--ground-accel", PULSE]


def model(**keywords):
    return M(ground_accel=PULSE, **keywords)


# (Python call, the same input on the command line), run in a directory
# holding pulse.csv (a two-column table, 0.5 g for 2 s) and column.txt.
CASES = [
    (lambda: M(ground_accel="missing.csv", yield_accel=0.1), ["events", "--ground-accel", "missing.csv", "--yield-accel", "0.1", "--t-end", "1"]),
    (lambda: model(yield_accel=-0.1), ["events", *TWO_COLUMNS, "--yield-accel", "-0.1", "--t-end", "1"]),
    (lambda: model(yield_accel=float("nan")), ["events", *TWO_COLUMNS, "--yield-accel", "nan", "--t-end", "1"]),
    (lambda: model(yield_accel=0.1, scale=2, target_pga=0.3), ["events", *TWO_COLUMNS, "--yield-accel", "0.1", "--scale", "2", "--target-pga", "0.3", "--t-end", "1"]),
    (lambda: model(yield_accel=0.1, friction=1), ["events", *TWO_COLUMNS, "--yield-accel", "0.1", "--friction", "1", "--t-end", "1"]),
    (lambda: model(yield_accel=0.1, lambda_=1), ["events", *TWO_COLUMNS, "--yield-accel", "0.1", "--lambda", "1", "--t-end", "1"]),
    (lambda: model(yield_accel=0.1, scale=0), ["events", *TWO_COLUMNS, "--yield-accel", "0.1", "--scale", "0", "--t-end", "1"]),
    (lambda: model(yield_accel=0.1, target_pga=-1), ["events", *TWO_COLUMNS, "--yield-accel", "0.1", "--target-pga", "-1", "--t-end", "1"]),
    (lambda: model(yield_accel=0.1, accel_units="furlongs"), ["events", *TWO_COLUMNS, "--yield-accel", "0.1", "--accel-units", "furlongs", "--t-end", "1"]),
    (lambda: model(yield_accel=0.1, record_dt=0.01), ["events", *TWO_COLUMNS, "--yield-accel", "0.1", "--record-dt", "0.01", "--t-end", "1"]),
    (lambda: model(yield_accel=0.1, gravity=0), ["events", *TWO_COLUMNS, "--yield-accel", "0.1", "--gravity", "0", "--t-end", "1"]),
    (lambda: model(yield_accel=0.1, one_way=True, v0=-1), ["events", *TWO_COLUMNS, "--yield-accel", "0.1", "--one-way", "--v0", "-1", "--t-end", "1"]),
    (lambda: M(ground_accel="column.txt", yield_accel=0.1), ["events", "--ground-accel", "column.txt", "--yield-accel", "0.1", "--t-end", "1"]),
    (lambda: M(friction=1, one_way=True), ["events", "--friction", "1", "--one-way", "--t-end", "1"]),
    (lambda: M(friction=1, scale=2), ["events", "--friction", "1", "--scale", "2", "--t-end", "1"]),
    (lambda: M(friction=1, inverse=True), ["events", "--friction", "1", "--inverse", "--t-end", "1"]),
    (lambda: frictionref.events(model(yield_accel=0.1), -1), ["events", *TWO_COLUMNS, "--yield-accel", "0.1", "--t-end", "-1"]),
    (lambda: frictionref.stiff(model(yield_accel=0.1, one_way=True), 1), ["stiff", *TWO_COLUMNS, "--yield-accel", "0.1", "--one-way", "--t-end", "1"]),
    (lambda: frictionref.classify(model(yield_accel=0.1)), ["classify", *TWO_COLUMNS, "--yield-accel", "0.1"]),
    (lambda: frictionref.classify(model(yield_accel=0.1, amplitude=1)), ["classify", *TWO_COLUMNS, "--yield-accel", "0.1", "--amplitude", "1"]),
    (lambda: frictionref.compare(M(ground_accel="zeros.txt", record_dt=0.01, yield_accel=0.1), [0, 1], [0, 0]), ["compare", "--candidate", "none.csv", "--ground-accel", "zeros.txt", "--record-dt", "0.01", "--yield-accel", "0.1"]),
    (lambda: frictionref.compare(M(friction=1, amplitude=0), [0, 1], [0, 0]), ["compare", "--candidate", "none.csv", "--friction", "1", "--amplitude", "0"]),
    (lambda: frictionref.sweep(lambda_from=0, lambda_to=1, points=3, ground_accel=PULSE), ["sweep", "--lambda-from", "0", "--lambda-to", "1", "--points", "3", *TWO_COLUMNS]),
    (lambda: frictionref.sweep(lambda_from=0, lambda_to=1, points=3, ground_accel=PULSE, amplitude=1), ["sweep", "--lambda-from", "0", "--lambda-to", "1", "--points", "3", *TWO_COLUMNS, "--amplitude", "1"]),
    (lambda: frictionref.map("lambda:0:1:3", "mass:1:2:3", ground_accel=PULSE), ["map", "--x", "lambda:0:1:3", "--y", "mass:1:2:3", *TWO_COLUMNS]),
    (lambda: frictionref.map("foo:0:1:3", "mass:1:2:3", ground_accel=PULSE), ["map", "--x", "foo:0:1:3", "--y", "mass:1:2:3", *TWO_COLUMNS]),
    (lambda: frictionref.newmark("missing.csv", 0.1), ["newmark", "--record", "missing.csv", "--yield-accel", "0.1"]),
    (lambda: frictionref.newmark(PULSE, -0.1), ["newmark", "--record", PULSE, "--yield-accel", "-0.1"]),
    (lambda: frictionref.newmark(PULSE, [0.1, float("inf")]), ["newmark", "--record", PULSE, "--yield-accel", "0.1,inf"]),
    (lambda: frictionref.newmark(PULSE, 0.1, scale=2, target_pga=0.3), ["newmark", "--record", PULSE, "--yield-accel", "0.1", "--scale", "2", "--target-pga", "0.3"]),
    (lambda: frictionref.newmark(PULSE, 0.1, scale=-2), ["newmark", "--record", PULSE, "--yield-accel", "0.1", "--scale", "-2"]),
    (lambda: frictionref.newmark(PULSE, 0.1, target_pga=0), ["newmark", "--record", PULSE, "--yield-accel", "0.1", "--target-pga", "0"]),
    (lambda: frictionref.newmark(PULSE, 0.1, method="newton"), ["newmark", "--record", PULSE, "--yield-accel", "0.1", "--method", "newton"]),
    (lambda: frictionref.newmark(PULSE, 0, method="slammer"), ["newmark", "--record", PULSE, "--yield-accel", "0", "--method", "slammer"]),
    (lambda: frictionref.newmark(PULSE, 0.1, method="slammer"), ["newmark", "--record", PULSE, "--yield-accel", "0.1", "--method", "slammer"]),
    (lambda: frictionref.newmark(PULSE, 0.1, threads=0), ["newmark", "--record", PULSE, "--yield-accel", "0.1", "--threads", "0"]),
    (lambda: frictionref.newmark(PULSE, 0.1, accel_units="g/s"), ["newmark", "--record", PULSE, "--yield-accel", "0.1", "--accel-units", "g/s"]),
    (lambda: frictionref.newmark(PULSE, 0.1, record_dt=0.01), ["newmark", "--record", PULSE, "--yield-accel", "0.1", "--record-dt", "0.01"]),
    (lambda: frictionref.newmark(PULSE, 0.1, gravity=float("nan")), ["newmark", "--record", PULSE, "--yield-accel", "0.1", "--gravity", "nan"]),
    (lambda: frictionref.newmark(["column.txt"], 0.1), ["newmark", "--record", "column.txt", "--yield-accel", "0.1"]),
    (lambda: frictionref.newmark([PULSE], [0.1] * 10001), ["newmark", "--record", PULSE, "--yield-accel", ",".join(["0.1"] * 10001)]),
    (lambda: frictionref.newmark([PULSE, "missing.csv"], 0.1, method="slammer"), ["newmark", "--record", PULSE, "--record", "missing.csv", "--yield-accel", "0.1", "--method", "slammer"]),
]


@pytest.fixture
def records_here(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    write_pulse(tmp_path / PULSE, 0.5, 2.0)
    (tmp_path / "column.txt").write_text("0.5\n0.5\n")
    (tmp_path / "zeros.txt").write_text("0\n0\n0\n")


@pytest.mark.parametrize("call, argv", CASES, ids=[" ".join(a)[:70] for _, a in CASES])
def test_same_message_as_the_cli(call, argv, cli_error, records_here):
    with pytest.raises(ValueError) as error:
        call()
    assert str(error.value) == cli_error(*argv)


def test_python_only_rules_name_the_keyword(records_here):
    with pytest.raises(ValueError, match=r"^polarity = up: must be normal, inverse \(--inverse\) "
                                         r"or both \(--both-polarities\)$"):
        frictionref.newmark(PULSE, 0.1, polarity="up")
    with pytest.raises(ValueError, match=r"^--record is required$"):
        frictionref.newmark([], 0.1)
    with pytest.raises(ValueError, match=r"^--yield-accel is required$"):
        frictionref.newmark(PULSE, [])
    with pytest.raises(ValueError, match=r"^--ground-accel = -: standard input is read by the "
                                         r"command line only; give a file$"):
        M(ground_accel="-", yield_accel=0.1)
    with pytest.raises(ValueError, match=r"^--record = -: "):
        frictionref.newmark("-", 0.1)
    with pytest.raises(ValueError, match=r"^--ground-accel: a path cannot hold a NUL character$"):
        M(ground_accel=PULSE + "\0.AT2", yield_accel=0.1)
    with pytest.raises(ValueError, match=r"^--yield-accel = 0.1: not a sweep option; "):
        frictionref.sweep(lambda_from=0, lambda_to=1, points=3, yield_accel=0.1)


TYPE_ERRORS = [
    lambda: M(ground_accel=3, yield_accel=0.1),
    lambda: M(ground_accel=PULSE, yield_accel="0.1"),
    lambda: M(ground_accel=PULSE, yield_accel=0.1, accel_units=1),
    lambda: M(ground_accel=PULSE, yield_accel=0.1, inverse="yes"),
    lambda: M(ground_accel=PULSE, yield_accel=0.1, one_way=1),
    lambda: frictionref.newmark(3, 0.1),
    lambda: frictionref.newmark([PULSE, None], 0.1),
    lambda: frictionref.newmark(PULSE, "0.1"),
    lambda: frictionref.newmark(PULSE, 0.1, polarity=None),
    lambda: frictionref.newmark(PULSE, 0.1, method=1),
    lambda: frictionref.newmark(PULSE, 0.1, one_way="no"),
    lambda: frictionref.newmark(PULSE, 0.1, progress=3),
    lambda: frictionref.newmark(PULSE, 0.1, threads=1.5j),
    lambda: frictionref.newmark(PULSE, 0.1, two_way=True),
]


@pytest.mark.parametrize("call", TYPE_ERRORS)
def test_wrong_types_raise_type_error(call, records_here):
    with pytest.raises(TypeError):
        call()

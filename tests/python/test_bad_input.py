"""Bad input through Python raises ValueError with the command line's own
one-line message: each case runs the same input through the frictionref
binary and compares the two lines. Wrong types raise TypeError."""
import numpy as np
import pytest

import frictionref

M = frictionref.Model

# (Python call, the same input on the command line). Numbers on the command
# line are written as Python prints them (the shortest text that reads back
# to the same double), since that is the text the messages quote.
CASES = [
    (lambda: M(mass=-1, lambda_=0.7), ["events", "--mass", "-1", "--lambda", "0.7", "--t-end", "1"]),
    (lambda: M(mass=0, friction=0.3), ["events", "--mass", "0", "--friction", "0.3", "--t-end", "1"]),
    (lambda: M(lambda_=float("nan")), ["events", "--lambda", "nan", "--t-end", "1"]),
    (lambda: M(omega=float("inf"), friction=1), ["events", "--omega", "inf", "--friction", "1", "--t-end", "1"]),
    (lambda: M(friction=10**400), ["events", "--friction", str(10**400), "--t-end", "1"]),
    (lambda: M(friction=0.3, lambda_=0.3), ["events", "--friction", "0.3", "--lambda", "0.3", "--t-end", "1"]),
    (lambda: M(), ["events", "--t-end", "1"]),
    (lambda: M(lambda_=0.5, amplitude=0), ["events", "--lambda", "0.5", "--amplitude", "0", "--t-end", "1"]),
    (lambda: M(lambda_=-0.5), ["events", "--lambda", "-0.5", "--t-end", "1"]),
    (lambda: M(lambda_=0.5, static_lambda=0.3), ["events", "--lambda", "0.5", "--static-lambda", "0.3", "--t-end", "1"]),
    (lambda: M(friction=0.5, static_friction=0.2), ["events", "--friction", "0.5", "--static-friction", "0.2", "--t-end", "1"]),
    (lambda: M(friction=0.5, static_friction=1, static_lambda=1), ["events", "--friction", "0.5", "--static-friction", "1", "--static-lambda", "1", "--t-end", "1"]),
    (lambda: M(friction=0.5, harmonics=[(1, 0)]), ["events", "--friction", "0.5", "--harmonic", "1,0", "--t-end", "1"]),
    (lambda: M(friction=0.5, harmonics=[(1,)]), ["events", "--friction", "0.5", "--harmonic", "1", "--t-end", "1"]),
    (lambda: M(friction=0.5, harmonics=[(1, 2, 1e11)]), ["events", "--friction", "0.5", "--harmonic", "1,2,1e+11", "--t-end", "1"]),
    (lambda: M(friction=0.5, harmonics=["1,x"]), ["events", "--friction", "0.5", "--harmonic", "1,x", "--t-end", "1"]),
    (lambda: M(friction=0.5, stiffness=-2), ["events", "--friction", "0.5", "--stiffness", "-2", "--t-end", "1"]),
    (lambda: M(friction=0.5, damping=-1e-05), ["events", "--friction", "0.5", "--damping", "-1e-05", "--t-end", "1"]),
    (lambda: M(friction=0.5, x0=float("-inf")), ["events", "--friction", "0.5", "--x0", "-inf", "--t-end", "1"]),
    (lambda: frictionref.events(M(lambda_=0.7), 0), ["events", "--lambda", "0.7", "--t-end", "0"]),
    (lambda: frictionref.events(M(lambda_=0.7, t0=5), 1), ["events", "--lambda", "0.7", "--t0", "5", "--t-end", "1"]),
    (lambda: frictionref.events(M(lambda_=0.3), 1e10), ["events", "--lambda", "0.3", "--t-end", "1e+10"]),
    (lambda: frictionref.events(M(lambda_=0.3, stiffness=1e17), 30), ["events", "--lambda", "0.3", "--stiffness", "1e+17", "--t-end", "30"]),
    (lambda: frictionref.summary(M(lambda_=0.3), float("nan")), ["events", "--lambda", "0.3", "--t-end", "nan", "--summary"]),
    (lambda: frictionref.curve(M(lambda_=0.7), t_end=1, dt=0), ["curve", "--lambda", "0.7", "--t-end", "1", "--dt", "0"]),
    (lambda: frictionref.curve(M(lambda_=0.7), t_end=1e9, dt=0.01), ["curve", "--lambda", "0.7", "--t-end", "1e+09", "--dt", "0.01"]),
    (lambda: frictionref.stiff(M(lambda_=0.7), 30, kf=-1), ["stiff", "--lambda", "0.7", "--t-end", "30", "--kf", "-1"]),
    (lambda: frictionref.stiff(M(lambda_=0.7), 30, dt=0.001), ["stiff", "--lambda", "0.7", "--t-end", "30", "--dt", "0.001"]),
    (lambda: frictionref.stiff(M(lambda_=0.7), 30, dt=0), ["stiff", "--lambda", "0.7", "--t-end", "30", "--dt", "0"]),
    (lambda: frictionref.stiff(M(lambda_=0.7), 30, output_dt=1e-05, dt=0.0001, kf=1e5), ["stiff", "--lambda", "0.7", "--t-end", "30", "--output-dt", "1e-05", "--dt", "0.0001", "--kf", "1e+05"]),
    (lambda: frictionref.classify(M(lambda_=0.7), max_periods=1), ["classify", "--lambda", "0.7", "--max-periods", "1"]),
    (lambda: frictionref.classify(M(amplitude=0, friction=1)), ["classify", "--amplitude", "0", "--friction", "1"]),
    (lambda: frictionref.compare(M(lambda_=0.7), [0, 1], [0, 0], stick_threshold=0), ["compare", "--candidate", "none.csv", "--lambda", "0.7", "--stick-threshold", "0"]),
    (lambda: frictionref.compare(M(lambda_=0.7), [0, 1], [0, 0], velocity_tolerance=-1), ["compare", "--candidate", "none.csv", "--lambda", "0.7", "--velocity-tolerance", "-1"]),
    (lambda: frictionref.compare(M(friction=0.7, amplitude=0), [0, 1], [0, 0]), ["compare", "--candidate", "none.csv", "--friction", "0.7", "--amplitude", "0"]),
    (lambda: frictionref.compare(M(lambda_=0.7), [0, 1], [0, 0], max_missed_stops=-1), ["compare", "--candidate", "none.csv", "--lambda", "0.7", "--max-missed-stops", "-1"]),
    (lambda: frictionref.sweep(lambda_from=0.5, lambda_to=0.1, points=3), ["sweep", "--lambda-from", "0.5", "--lambda-to", "0.1", "--points", "3"]),
    (lambda: frictionref.sweep(lambda_from=0, lambda_to=1, points=1), ["sweep", "--lambda-from", "0", "--lambda-to", "1", "--points", "1"]),
    (lambda: frictionref.sweep(lambda_from=0, lambda_to=1, points=0.5), ["sweep", "--lambda-from", "0", "--lambda-to", "1", "--points", "0.5"]),
    (lambda: frictionref.sweep(lambda_from=0, lambda_to=1, points=10**4, periods=10**6), ["sweep", "--lambda-from", "0", "--lambda-to", "1", "--points", "10000", "--periods", "1000000"]),
    (lambda: frictionref.sweep(lambda_from=0, lambda_to=1, points=3, lambda_=0.3), ["sweep", "--lambda-from", "0", "--lambda-to", "1", "--points", "3", "--lambda", "0.3"]),
    (lambda: frictionref.sweep(lambda_from=0, lambda_to=1, points=3, t0=1), ["sweep", "--lambda-from", "0", "--lambda-to", "1", "--points", "3", "--t0", "1"]),
    (lambda: frictionref.sweep(lambda_from=0, lambda_to=1, points=3, static_ratio=0.5), ["sweep", "--lambda-from", "0", "--lambda-to", "1", "--points", "3", "--static-ratio", "0.5"]),
    (lambda: frictionref.sweep(lambda_from=0, lambda_to=1, points=3, amplitude=0), ["sweep", "--lambda-from", "0", "--lambda-to", "1", "--points", "3", "--amplitude", "0"]),
    (lambda: frictionref.sweep(lambda_from=0, lambda_to=1, points=3, v0=1e7), ["sweep", "--lambda-from", "0", "--lambda-to", "1", "--points", "3", "--v0", "1e+07"]),
    (lambda: frictionref.sweep(lambda_from=0, lambda_to=1, points=3, threads=0), ["sweep", "--lambda-from", "0", "--lambda-to", "1", "--points", "3", "--threads", "0"]),
    (lambda: frictionref.map("lambda:0:1:11", "lambda:0:1:3"), ["map", "--x", "lambda:0:1:11", "--y", "lambda:0:1:3"]),
    (lambda: frictionref.map("foo:0:1:3", "lambda:0:1:3"), ["map", "--x", "foo:0:1:3", "--y", "lambda:0:1:3"]),
    (lambda: frictionref.map(("frequency-ratio", 0.5, 2, 3), "lambda:0:1:3"), ["map", "--x", "frequency-ratio:0.5:2:3", "--y", "lambda:0:1:3"]),
    (lambda: frictionref.map("lambda:0:1:3", "mass:-1:1:3"), ["map", "--x", "lambda:0:1:3", "--y", "mass:-1:1:3"]),
    (lambda: frictionref.map("lambda:0:1:3", "mass:1:2:3", periods=1), ["map", "--x", "lambda:0:1:3", "--y", "mass:1:2:3", "--periods", "1"]),
    (lambda: frictionref.map("lambda:0:1:3", "mass:1:2:3", shard=(3, 2)), ["map", "--x", "lambda:0:1:3", "--y", "mass:1:2:3", "--shard", "3/2"]),
]


@pytest.mark.parametrize("call, argv", CASES, ids=[" ".join(a) [:60] for _, a in CASES])
def test_same_message_as_the_cli(call, argv, cli_error, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(ValueError) as error:
        call()
    assert str(error.value) == cli_error(*argv)


TYPE_ERRORS = [
    lambda: M(mass="1", friction=1),
    lambda: M(friction=None, lambda_=True),
    lambda: M(friction=1j),
    lambda: M(friction=1, colour=3),
    lambda: M(friction=1, harmonics=3),
    lambda: M(friction=1, harmonics=[(1, "2")]),
    lambda: M(lambda_=0.3, lam=0.3),
    lambda: frictionref.events(M(lambda_=0.7), "30"),
    lambda: frictionref.events("model", 30),
    lambda: frictionref.curve(M(lambda_=0.7), ["a", "b"]),
    lambda: frictionref.curve(M(lambda_=0.7), [1 + 2j]),
    lambda: frictionref.curve(M(lambda_=0.7), [0.5], t_end=1, dt=0.1),
    lambda: frictionref.curve(M(lambda_=0.7)),
    lambda: frictionref.curve(M(lambda_=0.7), t_end=1, dt=0.1, include_events="yes"),
    lambda: frictionref.classify(M(lambda_=0.7), max_periods="400"),
    lambda: frictionref.compare(M(lambda_=0.7), [0, 1], [None, 0]),
    lambda: frictionref.sweep(),
    lambda: frictionref.sweep([0.5], lambda_from=0, lambda_to=1, points=3),
    lambda: frictionref.sweep([0.5], progress=3),
    lambda: frictionref.map(3, "lambda:0:1:3"),
    lambda: frictionref.map("lambda:0:1:3", "mass:1:2:3", shard=1.5),
]


@pytest.mark.parametrize("call", TYPE_ERRORS)
def test_wrong_types_raise_type_error(call):
    with pytest.raises(TypeError):
        call()


def test_python_only_rules_name_the_keyword():
    model = M(lambda_=0.7)
    with pytest.raises(ValueError, match=r"^t must be a one-dimensional array, not one with 2 "):
        frictionref.curve(model, np.zeros((2, 2)))
    with pytest.raises(ValueError, match=r"^t\[0\] = nan: must be a finite number$"):
        frictionref.curve(model, [float("nan")])
    with pytest.raises(ValueError, match=r"^t: must hold at least 2 rows|^t"):
        frictionref.compare(model, [0.0], [0.0])
    with pytest.raises(ValueError, match=r"^max_phases = 0: must be a whole number >= 1$"):
        frictionref.events(model, 1, max_phases=0)

"""stiff(): the central-difference penalty model, against the exact motion
where the scheme's error is known, and the CLI (consistency)."""
import numpy as np

import frictionref
from closed_forms import dead_band_state
from conftest import read_csv


def test_without_friction_it_is_central_differences_of_x_pp_equal_sin_t():
    # R = 0: the slider follows the mass (f = 0, z = x); from rest the exact
    # motion is x = t - sin t, v = 1 - cos t, and central differences are
    # second order: |error| ~ dt^2 / 6 on these unit-size terms.
    s = frictionref.stiff(frictionref.Model(friction=0), 10, kf=1e4, dt=1e-3, output_dt=0.01)
    assert list(s.dtype.names) == ["t", "x", "v", "f", "z"]
    assert np.all(s["f"] == 0) and np.array_equal(s["z"], s["x"])
    assert np.max(np.abs(s["x"] - (s["t"] - np.sin(s["t"])))) < 1e-5
    assert np.max(np.abs(s["v"] - (1 - np.cos(s["t"])))) < 1e-5


def test_friction_bound_and_convergence_to_the_exact_motion():
    s = frictionref.stiff(frictionref.Model(lambda_=0.7), 30)
    assert len(s) == 3001
    assert np.all(np.abs(s["f"]) <= 0.7)
    # docs/validation.md: with K_f = 1e7 the velocity is within 2.2e-4 of the exact one.
    exact = np.array([float(dead_band_state(0.7, t)[1]) for t in s["t"][::10]])
    assert np.max(np.abs(s["v"][::10] - exact)) < 1e-3


def test_consistency_with_the_cli_stiff(cli):
    code, out, _ = cli("stiff", "--lambda", "0.7", "--t-end", "5", "--kf", "1e5", "--dt", "1e-4")
    assert code == 0
    rows = read_csv(out)
    s = frictionref.stiff(frictionref.Model(lambda_=0.7), 5, kf=1e5, dt=1e-4)
    assert len(rows) == len(s)
    for row, got in zip(rows, s):
        assert [float(row[k]) for k in "txv"] == [got[k] for k in "txv"]


def test_general_model_with_a_damped_contact_matches_the_cli_and_holds_rs(cli):
    # Spring, second harmonic, static friction above R: the spring's force
    # never exceeds Rs, the slider slides with exactly R, and the values are
    # the binary's to the bit.
    args = ["--lambda", "0.6", "--static-lambda", "0.8", "--stiffness", "0.5",
            "--harmonic", "0.3,2"]
    model = frictionref.Model(lambda_=0.6, static_lambda=0.8, stiffness=0.5,
                              harmonics=[(0.3, 2)])
    code, out, _ = cli("stiff", *args, "--t-end", "5", "--kf", "1e5",
                       "--contact-damping", "1")
    assert code == 0
    rows = read_csv(out)
    s = frictionref.stiff(model, 5, kf=1e5, contact_damping=1)
    assert len(rows) == len(s)
    for row, got in zip(rows, s):
        assert [float(row[k]) for k in "txv"] == [got[k] for k in "txv"]
    assert np.all(np.abs(s["f"]) <= 0.8)
    spring = -1e5 * (s["x"] - s["z"])
    assert np.all(np.abs(spring) <= 0.8 * (1 + 1e-9))

"""classify() against the seed's closed forms (closed_forms.py) and Den
Hartog's solution (docs/theory.md 8.2), and the CLI's JSON (consistency)."""
import json
import math

import mpmath as mp
import pytest

import frictionref
from closed_forms import LAMBDA_STAR, close, dead_band_motion


def test_threshold_is_two_over_sqrt_four_plus_pi_squared():
    assert close(frictionref.regime_threshold(), LAMBDA_STAR, ulps=1)


def test_dead_bands_at_0_7():
    c = frictionref.classify(frictionref.Model(lambda_=0.7))
    a, ts, d = dead_band_motion(0.7)
    assert (c["regime"], c["method"], c["stops_per_period"]) == ("dead-bands", "closed-form", 2)
    assert close(c["breakaway_phase"], a, ulps=2) and close(c["stop_phase"], ts, ulps=8)
    assert close(c["stuck_fraction"], 1 - (ts - a) / mp.pi, ulps=16)
    assert close(c["slide_per_half_period"], d, ulps=16)
    assert c["reversal_phase"] is None


def test_continuous_at_0_3_and_the_quoted_threshold():
    c = frictionref.classify(frictionref.Model(lambda_=0.3))
    assert c["regime"] == "continuous"
    assert close(c["reversal_phase"], mp.acos(mp.mpf(0.3) * mp.pi / 2), ulps=4)
    # Between 0.536 and lambda* the seed's quoted threshold says otherwise.
    between = frictionref.classify(frictionref.Model(lambda_=0.5365))
    assert (between["regime"], between["regime_by_quoted_threshold"]) == ("continuous",
                                                                          "dead-bands")


def test_stops_from_1():
    assert frictionref.classify(frictionref.Model(lambda_=1))["regime"] == "stops"


def test_den_hartog_amplitude():
    # m = B = k = 1, w = 2: beta = 2, V = 1 / (1 - 4) = -1/3, U = (1/2) tan(pi/4) = 1/2,
    # X = sqrt(V^2 - r^2 U^2) (B / k = 1); non-stop for r < 4 / (3 sqrt 5).
    r = 0.4
    c = frictionref.classify(frictionref.Model(lambda_=r, stiffness=1, omega=2))
    assert c["regime"] == "continuous" and c["method"] == "closed-form"
    x = math.sqrt(1 / 9 - r * r / 4)
    assert abs(c["den_hartog"]["amplitude"] - x) <= 1e-14
    assert c["den_hartog"]["non_stop"] and c["den_hartog"]["stable"]


def test_simulation_of_the_seeds_model_agrees_with_the_closed_form():
    c = frictionref.classify(frictionref.Model(lambda_=0.7), simulate=True)
    _, ts, d = dead_band_motion(0.7)
    assert (c["regime"], c["method"], c["multiplicity"]) == ("dead-bands", "simulation", 1)
    assert abs(c["stuck_fraction"] - float(1 - (ts - mp.asin(0.7)) / mp.pi)) <= 1e-12


@pytest.mark.parametrize("args", [
    ["--lambda", "0.7"],
    ["--lambda", "0.3", "--stiffness", "1", "--damping", "0.1", "--static-lambda", "0.5"],
    ["--lambda", "0.4", "--stiffness", "1", "--omega", "2"],
])
def test_consistency_with_the_cli_json(cli, args):
    code, out, _ = cli("classify", *args, "--json")
    assert code == 0
    keywords = {}
    for option, value in zip(args[::2], args[1::2]):
        name = option[2:].replace("-", "_")
        keywords["lambda_" if name == "lambda" else name] = float(value)
    got = frictionref.classify(frictionref.Model(**keywords))
    got["model"]["harmonics"] = [list(h) for h in got["model"]["harmonics"]]
    assert got == json.loads(out)

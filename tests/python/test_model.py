"""frictionref.Model: keywords, derived fields, immutability, pickling."""
import json
import math
import pickle

import pytest

import frictionref


def test_defaults_are_the_seeds_unit_model():
    m = frictionref.Model(friction=0.7)
    assert (m.mass, m.amplitude, m.omega, m.friction) == (1, 1, 1, 0.7)
    assert (m.stiffness, m.damping, m.force_offset, m.harmonics) == (0, 0, 0, [])
    assert (m.x0, m.v0, m.t0) == (0, 0, 0)
    assert m.static_friction is None
    assert m.is_seed


def test_lambda_sets_r_as_lambda_times_b():
    # R is the double nearest L * B: 0.35 * 2 rounded once.
    m = frictionref.Model(amplitude=2, lambda_=0.35)
    assert m.friction == 0.35 * 2
    assert frictionref.Model(lam=0.35, amplitude=2) == m
    assert frictionref.Model(**{"lambda": 0.35, "amplitude": 2}) == m
    assert m.lambda_ == 0.35


def test_static_lambda_and_general_fields():
    m = frictionref.Model(amplitude=2, lambda_=0.25, static_lambda=0.5, stiffness=3, damping=0.1,
                          force_offset=-0.2, harmonics=[(0.5, 3), (0.25, 2, 1.5)], x0=1, v0=-2,
                          t0=4)
    assert m.static_friction == 1.0
    assert m.harmonics == [(0.5, 3.0, 0.0), (0.25, 2.0, 1.5)]
    assert not m.is_seed
    # The harmonics also as the command line writes them.
    assert frictionref.Model(amplitude=2, lambda_=0.25, static_lambda=0.5, stiffness=3,
                             damping=0.1, force_offset=-0.2, harmonics=["0.5,3", "0.25,2,1.5"],
                             x0=1, v0=-2, t0=4) == m


def test_numpy_scalars_are_numbers():
    np = pytest.importorskip("numpy")
    m = frictionref.Model(mass=np.float64(2), friction=np.int64(1), omega=np.float32(0.5))
    assert (m.mass, m.friction, m.omega) == (2, 1, 0.5)


def test_immutable_picklable_comparable():
    m = frictionref.Model(lambda_=0.3, harmonics=[(0.1, 3)], t0=-1)
    with pytest.raises(AttributeError):
        m.mass = 2
    copy = pickle.loads(pickle.dumps(m))
    assert copy == m and hash(copy) == hash(m)
    assert repr(copy) == repr(m) == "frictionref.Model(lambda_=0.3, harmonics=['0.1,3'], t0=-1)"
    assert frictionref.Model(lambda_=0.3) != m


def test_to_dict_has_the_cli_json_model_keys(cli):
    # Consistency with the CLI (the same library, another code path).
    code, out, _ = cli("classify", "--lambda", "0.3", "--stiffness", "1", "--harmonic", "0.1,3",
                       "--json")
    assert code == 0
    expected = json.loads(out)["model"]
    got = frictionref.Model(lambda_=0.3, stiffness=1, harmonics=[(0.1, 3)]).to_dict()
    got["harmonics"] = [list(h) for h in got["harmonics"]]
    assert got == expected


def test_lambda_of_a_model_without_force():
    assert math.isinf(frictionref.Model(amplitude=0, friction=1).lambda_)

# gyrores.pair and gyrores.asymptotics against the CLI and against independent values.
import math

import pytest

import gyrores

# r_res of (6, 5) to 40 digits (the certificate's enclosure, docs/usage.md "Certificates").
R_RES_6_5 = "5.074580579103337246371565118651053368385e-02"


def test_pair_matches_cli_json(cli_json):
    for tau, sigma, digits in [(6, 5, 30), (11, 9, 20), (9, 4, 17), (2, 1, 12)]:
        expected = cli_json("pair", str(tau), str(sigma), "--digits", str(digits))
        raw = gyrores.pair(tau, sigma, digits=digits).to_dict(raw=True)
        assert raw == expected
        # The same keys in the same order (the dict is built directly, not from the JSON text),
        # and pair() keeps that order once its lazy keys are filled.
        assert list(raw) == list(expected) and list(raw["asymptotic"]) == list(expected["asymptotic"])
        assert list(gyrores.pair(tau, sigma, digits=digits)) == list(expected)
        assert list(gyrores.pair(tau, sigma, digits=min(digits, 15))) == list(expected)


def test_big_pair_matches_cli_json(cli_json):
    tau = 10**30 + 1
    expected = cli_json("pair", str(tau), str(10**30), "--digits", "25")
    got = gyrores.pair(tau, 10**30, digits=25).to_dict(raw=True)
    assert got == expected
    assert got["tau"] == tau and got["order"] == 2 * 10**30 + 1


def test_r_res_of_6_5_at_40_digits():
    r = gyrores.pair(6, 5, digits=40)
    assert r.to_dict(raw=True)["r_res"] == R_RES_6_5
    assert r.digits == 40 and r.theorem == "lattice-theorem/1" and r.format == "gyrores-pair/2"


def test_reals_are_floats_up_to_15_digits():
    r = gyrores.pair(6, 5, digits=15)
    assert isinstance(r.r_res, float) and isinstance(r.minimisers, tuple)
    assert r.r_res == pytest.approx(float(R_RES_6_5), rel=1e-14)
    assert r["t_first"] == pytest.approx(r.theta_first * math.sqrt(30), rel=1e-14)


def test_reals_beyond_15_digits_are_mpf_or_text():
    r = gyrores.pair(6, 5, digits=40)
    try:
        import mpmath
    except ImportError:
        assert r.r_res == R_RES_6_5
    else:
        assert isinstance(r.r_res, mpmath.mpf)
        with mpmath.workdps(45):
            assert abs(r.r_res - mpmath.mpf(R_RES_6_5)) < mpmath.mpf("1e-43")


def test_degenerate_pair_is_exact():
    r = gyrores.pair(11, 9, digits=30)
    assert r.degenerate and r.m_min == 0
    raw = r.to_dict(raw=True)
    assert raw["r_res"] == "0." + "0" * 29 + "e+00"
    # pi/2 to 30 digits, written out independently.
    assert raw["theta_first"] == "1.57079632679489661923132169164e+00"
    assert gyrores.pair(11, 9, digits=12).theta_first == pytest.approx(math.pi / 2, rel=1e-11)  # 12 digits


def test_qdot0_scales_r_res():
    r1 = gyrores.pair(9, 4, digits=14)
    r3 = gyrores.pair(9, 4, digits=14, qdot0=3)
    assert r3.r_res == pytest.approx(3 * r1.r_res, rel=1e-13)
    assert r3.t_first == r1.t_first


def test_enclosures_hold_the_rounded_values():
    import mpmath
    r = gyrores.pair(6, 5, digits=20, enclosures=True)
    raw = r.to_dict(raw=True)
    for key in ("r_res", "theta_first", "t_first", "n", "h_z_max", "r_res_asy"):
        lo, hi = r.enclosures[key]
        assert isinstance(lo, mpmath.mpf) and lo <= r[key] <= hi and r[key] in r.enclosures[key]
        # the value is the CLI's decimal text, to the call's precision
        assert r[key] == gyrores._numbers.mpf_of_text(raw[key], gyrores._numbers.bits_of_digits(20))
    assert "lattice-theorem/1" in repr(r)
    r3 = gyrores.pair(6, 5, digits=20, enclosures=True, qdot0=3)
    with mpmath.workdps(60):
        assert 3 * mpmath.mpf(raw["r_res"]) - r3.enclosures["r_res"].mid < mpmath.mpf("1e-20")


@pytest.mark.parametrize("args, kwargs, message", [
    ((6, 4), {}, "not coprime"),
    ((5, 6), {}, "tau must exceed sigma"),
    ((6, 5), {"digits": 0}, "digits must be in [1, 10000], got 0"),
    ((6, 5), {"qdot0": "-1"}, "qdot0"),
    ((6.0, 5), {}, "tau must be an integer"),
    ((6, 5), {"qdot0": "0", "enclosures": True}, "qdot0"),
])
def test_bad_input_raises_value_error(args, kwargs, message):
    with pytest.raises(ValueError, match=None) as e:
        gyrores.pair(*args, **kwargs)
    assert message in str(e.value) and "\n" not in str(e.value)
    assert isinstance(e.value, gyrores.UsageError)


def test_asymptotics_match_the_pair_report(cli_json):
    a = gyrores.asymptotics(6, 5, digits=20)
    expected = cli_json("pair", "6", "5", "--digits", "20")
    got = gyrores._gyrores._asymptotics(6, 5, 20)
    assert got["lobes"] == expected["asymptotic"]["lobes"]
    assert got["r_res_asy"] == expected["r_res_asy"]
    assert a["applicable"] and len(a["lobes"]) == 2 and a["lobes"][0]["k"] == 5


def test_asymptotics_not_applicable_for_large_x():
    a = gyrores.asymptotics(3, 1, digits=10)  # x = b/a = 1/2
    assert not a["applicable"] and a["r_res_asy"] is None and a["reason"]


# pair() computes the asymptotics (and bits) on first access; everything a caller can read must
# be what the eager computation (_proved_pair with the asymptotics, the path of enclosures=True
# and of the CLI) gives, in the same key order.
@pytest.mark.parametrize("tau, sigma, digits, qdot0", [
    (6, 5, 15, 1), (6, 5, 17, 1), (6, 5, 30, 3), (2, 1, 12, 1), (3, 1, 20, 1), (11, 9, 25, 1),
    (10**12 + 1, 10**12, 20, "1/4"),
])
def test_lazy_asymptotics_equal_the_eager_ones(tau, sigma, digits, qdot0):
    import copy
    import json
    import pickle
    eager, _ = gyrores._proved_pair(*gyrores._pair_arguments(tau, sigma, digits, qdot0, False, "pair"), "pair")
    r = gyrores.pair(tau, sigma, digits=digits, qdot0=qdot0)
    # Reading the values most callers read computes nothing more.
    assert (r.r_res, r["theta_first"], r.get("t_first"), r.minimisers) == (
        eager["r_res"], eager["theta_first"], eager["t_first"], eager["minimisers"])
    assert "asymptotic" in r and "bits" in r and "lattice-theorem/1" in repr(r) and "r_res_asy" in dir(r)
    assert "_lazy" in r.__dict__
    assert r.asymptotic == eager["asymptotic"] and r["bits"] == eager["bits"]
    assert r.get("r_res_asy") == eager["r_res_asy"] and r.r_res_asy_rel_error == eager["r_res_asy_rel_error"]
    assert "_lazy" not in r.__dict__
    assert list(r.keys()) == list(eager.keys()) and r == eager
    # Every way of seeing the whole dict fills it first, in the eager order.
    for view in (lambda x: list(dict(x).items()), lambda x: list(x.items()), lambda x: list(x),
                 lambda x: list(copy.deepcopy(x).items()), lambda x: list(pickle.loads(pickle.dumps(x)).items()),
                 lambda x: list({**x}.items()), lambda x: len(x)):
        want = view(eager)
        if isinstance(want, dict):
            want = list(want.items())
        got = view(gyrores.pair(tau, sigma, digits=digits, qdot0=qdot0))
        assert (list(got.items()) if isinstance(got, dict) else got) == want
    assert gyrores.pair(tau, sigma, digits=digits, qdot0=qdot0) == eager
    assert gyrores.pair(tau, sigma, digits=digits, qdot0=qdot0).to_dict() == dict(eager)
    if digits <= 15:
        assert json.dumps(gyrores.pair(tau, sigma, digits=digits, qdot0=qdot0)) == json.dumps(eager)
    # With the enclosures the report is computed at once, as before.
    e = gyrores.pair(tau, sigma, digits=digits, qdot0=qdot0, enclosures=True)
    assert "_lazy" not in e.__dict__ and e.asymptotic == eager["asymptotic"] and e.bits == eager["bits"]

# The numbers the module returns, as a researcher in a notebook would use them: one type per call
# (float for digits <= 15, mpmath.mpf beyond, never str), reals that are the correct roundings
# they claim to be, enclosures that hold them, integers of any size both ways.
from decimal import Decimal
from fractions import Fraction

import mpmath
import pytest

import gyrores

BIG = 10**5000  # a pair of 5000-digit members: beyond Python's 4300-digit int <-> str limit


def _leaves(value):
    """Every leaf of a result (dicts and tuples walked)."""
    if isinstance(value, dict):
        for k, v in value.items():
            yield from ((f"{k}.{p}" if p else k, x) for p, x in _leaves(v))
    elif isinstance(value, gyrores.Interval):
        yield "lo", value.lo
        yield "hi", value.hi
    elif isinstance(value, (tuple, list)):
        for i, v in enumerate(value):
            yield from ((f"{i}.{p}" if p else str(i), x) for p, x in _leaves(v))
    else:
        yield "", value


# Keys whose values are text by nature: names, explanations, formats, a design's verdicts and
# tolerance as given ("1%"); and coupling()'s exact algebraic numbers x and
# horizon_lobe_distance ("sqrt(2)/2"), which no Python number holds.
TEXT_KEYS = {"format", "theorem", "reason", "note", "inf_reason", "horizon_source", "orientation",
             "orientation_meaning", "time", "problem", "input", "x", "horizon_lobe_distance", "verdict", "percent"}


def _assert_numeric(result, real_type):
    reals = 0
    for path, v in _leaves(result):
        if isinstance(v, str):
            assert set(path.split(".")) & TEXT_KEYS, f"{path} is the str {v!r}"
        elif isinstance(v, (float, mpmath.mpf)):
            assert isinstance(v, real_type), f"{path} is {type(v).__name__}, not {real_type.__name__}"
            reals += 1
        else:
            assert v is None or isinstance(v, (int, bool, Fraction)), f"{path}: {type(v).__name__}"
    assert reals > 0


CALLS = {
    "pair": lambda **kw: gyrores.pair(6, 5, **kw),
    "pair big": lambda **kw: gyrores.pair(BIG + 1, BIG, **kw),
    "asymptotics": lambda **kw: gyrores.asymptotics(9, 4, **kw),
    "design": lambda **kw: gyrores.design("contain", 17, beat=10, **kw),
    "pareto": lambda **kw: gyrores.pareto(60, **kw),
    "coupling": lambda **kw: gyrores.coupling(n2="1/12", convergents=3, **kw),
    "coupling band": lambda **kw: gyrores.coupling(0.5, horizon=5, convergents=0, tolerance="10%", band_digits=2, **kw),
    "band alone": lambda **kw: gyrores.coupling(band=("0.200", "0.202"), horizon=16, below="1%", band_digits=3, **kw),
    "design tolerance": lambda **kw: gyrores.design("absorb", 20, tolerance="1%", level="1%", **kw),
}
DEFAULT_TYPE = {"pair": mpmath.mpf, "pair big": mpmath.mpf, "asymptotics": mpmath.mpf, "design": float,
                "pareto": float, "coupling": float, "coupling band": float, "band alone": float,
                "design tolerance": float}


@pytest.mark.parametrize("name", CALLS)
def test_default_digits_give_one_numeric_type(name):
    _assert_numeric(CALLS[name](), DEFAULT_TYPE[name])


@pytest.mark.parametrize("name", CALLS)
@pytest.mark.parametrize("digits, real_type", [(1, float), (15, float), (16, mpmath.mpf), (300, mpmath.mpf)])
def test_explicit_digits_give_one_numeric_type(name, digits, real_type):
    _assert_numeric(CALLS[name](digits=digits), real_type)


def test_ten_thousand_digits_of_a_five_thousand_digit_pair():
    r = gyrores.pair(BIG + 1, BIG, digits=10000, enclosures=True)
    _assert_numeric(r, mpmath.mpf)
    assert r.tau == BIG + 1 and r.order == 2 * BIG + 1  # ints of any size come back whole
    assert r.r_res in r.enclosures.r_res
    # Every digit is there: the mpf has >= 10000 digits of precision, whatever mpmath.mp.dps is.
    man, exp = r.r_res.man_exp
    assert man.bit_length() > 10000 * 3.32 - 64
    assert r.enclosures.r_res.width < abs(r.r_res) * mpmath.mpf(10) ** -9999


def test_mpf_holds_every_digit_whatever_mp_dps_is():
    text = gyrores.pair(6, 5, digits=60).to_dict(raw=True)["r_res"]
    with mpmath.workdps(5):
        r = gyrores.pair(6, 5, digits=60)
    with mpmath.workdps(80):
        assert abs(r.r_res - mpmath.mpf(text)) < mpmath.mpf("1e-62")


def test_floats_are_the_correctly_rounded_doubles():
    # Reference: the double nearest to a 60-digit rounding (Python's float() of decimal text is
    # correctly rounded; a 60-digit rounding decides the double unless it lies within 1e-60 of a
    # midpoint between doubles, which the pairs here do not).
    for tau, sigma in [(6, 5), (9, 4), (23, 19), (101, 100), (1000, 999), (10**9, 1), (10**30 + 1, 10**30)]:
        r = gyrores.pair(tau, sigma, digits=15)
        ref = gyrores.pair(tau, sigma, digits=60).to_dict(raw=True)
        for key in ("r_res", "theta_first", "t_first", "n", "h_min", "t_min_paper"):
            assert r[key] == float(Decimal(ref[key])), (tau, sigma, key)
        assert r.minimisers == tuple(float(Decimal(m)) for m in ref["minimisers"])
        assert r.digits == 15


def test_enclosures_are_intervals_that_hold_value_and_exact_value():
    for digits in (10, 17, 40):
        r = gyrores.pair(9, 4, digits=digits, enclosures=True)
        exact = gyrores.pair(9, 4, digits=80).r_res  # within 1e-80 of the exact value
        iv = r.enclosures.r_res
        assert isinstance(iv, gyrores.Interval) and iv.lo <= iv.hi and r.r_res in iv and iv.contains(r.r_res)
        assert iv.lo < exact < iv.hi
        lo, hi = iv
        assert lo <= iv.mid <= hi
        for i, m in enumerate(r.minimisers):
            assert m in r.enclosures.minimisers[i]
        for lobe, enc in zip(r.asymptotic.lobes, r.enclosures.asymptotic_lobes):
            assert lobe.u_asy in enc.u_asy
    # A float enclosure is rounded outward: lo <= exact <= hi although lo and hi are doubles.
    iv = gyrores.pair(6, 5, digits=12, enclosures=True).enclosures.n  # n = 1/sqrt(30)
    with mpmath.workdps(50):
        assert mpmath.mpf(iv.lo) <= 1 / mpmath.sqrt(30) <= mpmath.mpf(iv.hi)


def test_results_are_mappings_with_attributes():
    r = gyrores.pair(6, 5)
    assert isinstance(r, dict) and "r_res" in r and r["r_res"] == r.r_res
    assert r.asymptotic.lobes[0].k == 5 and r.asymptotic["lobes"][0]["m"] == 1
    assert dict(r)["tau"] == 6 and set(r.keys()) >= {"r_res", "t_first", "minimisers"}
    with pytest.raises(AttributeError):
        r.no_such_field
    c = gyrores.check(gyrores.certify(6, 5))
    assert c == {"holds": True, "failure": ""} and c.holds and bool(c)
    s = gyrores.coupling(n2="1/12")
    assert s.n2 == Fraction(1, 12) and s.horizon == 100


class Weird(int):
    """An int whose text lies: the value must be read, never its str()."""

    def __str__(self):
        return "7"

    __repr__ = __str__


def test_integers_the_python_way():
    np = pytest.importorskip("numpy")
    ref = gyrores.pair(6, 5).r_res
    for t, s in [(np.int64(6), np.int64(5)), (np.int32(6), np.uint8(5)), (Weird(6), 5), (6, np.int16(5))]:
        r = gyrores.pair(t, s)
        assert r.tau == 6 and r.sigma == 5 and r.r_res == ref and type(r.tau) is int
    rows, _ = gyrores.sweep(12)
    row = rows[5]
    assert gyrores.pair(row["tau"], row["sigma"]).tau == row["tau"]  # sweep rows can be fed back
    assert gyrores.pair(6, 5, digits=np.int64(20)).digits == 20


@pytest.mark.parametrize("call, message", [
    (lambda: gyrores.pair(6.0, 5), "pair(): tau must be an integer, got 6.0 (float)"),
    (lambda: gyrores.pair(6, True), "pair(): sigma must be an integer, got a bool True"),
    (lambda: gyrores.pair(6, "5"), "pair(): sigma must be an integer, got '5' (str)"),
    (lambda: gyrores.pair(6, 5, digits=2.5), "pair(): digits must be an integer"),
    (lambda: gyrores.pair(6, 5, digits=10**30), "pair(): digits must be in [1, 10000]"),
    (lambda: gyrores.pair(6, 5, enclosures=1), "pair(): enclosures must be True or False"),
    (lambda: gyrores.pair(6, 5, qdot0=[1]), "pair(): qdot0 must be a number"),
    (lambda: gyrores.asymptotics(6, 5.5), "asymptotics(): sigma must be an integer"),
    (lambda: gyrores.certify("6", 5), "certify(): tau must be an integer"),
    (lambda: gyrores.design("absorb", 17, max_order=200.0), "design(): max_order must be an integer"),
    (lambda: gyrores.design("both", 17), "design(): problem must be one of 'absorb', 'contain'"),
    (lambda: gyrores.pareto(60, orientation=1), "pareto(): orientation must be one of"),
    (lambda: gyrores.coupling(n=2, convergents=1.5), "coupling(): convergents must be an integer"),
    (lambda: gyrores.sweep(20.5), "sweep(): max_order must be an integer"),
    (lambda: gyrores.enumerate_pairs(None), "enumerate_pairs(): max_order must be an integer"),
    (lambda: gyrores.pairs([6.5], [5]), "pairs(): taus[0] must be an integer"),
    (lambda: gyrores.check(42), "check(): cert must be"),
])
def test_wrong_types_raise_usage_error_naming_function_and_argument(call, message):
    with pytest.raises(gyrores.UsageError) as e:
        call()
    assert str(e.value).startswith(message) and "\n" not in str(e.value)
    assert isinstance(e.value, ValueError)


def test_rationals_the_python_way():
    ref = gyrores.pair(9, 4, digits=20, qdot0="1/4").r_res
    for q in (Fraction(1, 4), Decimal("0.25"), 0.25, "0.25", mpmath.mpf(0.25)):
        assert gyrores.pair(9, 4, digits=20, qdot0=q).r_res == ref
    assert gyrores.pair(9, 4, digits=20, qdot0=0.1).qdot0 == gyrores.pair(9, 4, digits=20, qdot0="0.1").qdot0


def test_huge_python_ints_in_and_out():
    big = 10**4400 + 1  # str(big) raises ValueError under Python's default limit
    r = gyrores.pair(big, 10**4400, digits=20)
    assert r.tau == big and r.sigma == 10**4400
    with pytest.raises(gyrores.UsageError, match="not coprime"):
        gyrores.pair(2 * big, 2 * 10**4400)


def _r_res_by_mpmath(tau, sigma, dps):
    """r_res of (tau, sigma), qdot0 = 1, independently of gyrores: every root of
    q'(theta) = W1 cos(tau theta) + W2 cos(sigma theta) on [0, 2 pi] (sign changes on a fine grid,
    then mpmath.findroot at `dps` digits), r = rho0 |sin(tau theta) + sin(sigma theta)|, the least."""
    with mpmath.workdps(dps):
        t, s = mpmath.mpf(tau), mpmath.mpf(sigma)
        w1, w2 = mpmath.sqrt(t / s), mpmath.sqrt(s / t)
        rho0 = 1 / (w1 + w2)

        def qdot(th):
            return w1 * mpmath.cos(t * th) + w2 * mpmath.cos(s * th)

        grid = [2 * mpmath.pi * i / 2000 for i in range(2001)]
        radii = []
        for a, b in zip(grid, grid[1:]):
            if qdot(a) * qdot(b) < 0:
                th = mpmath.findroot(qdot, (a, b), solver="anderson")
                radii.append(rho0 * abs(mpmath.sin(t * th) + mpmath.sin(s * th)))
        return min(radii)


def _significant_digits(text):
    """The significant digits of a plain or e-notation decimal text ("0.0507" -> "507")."""
    mantissa = text.lstrip("-").split("e")[0].replace(".", "")
    return mantissa.lstrip("0")


@pytest.mark.parametrize("digits", [16, 30, 60])
def test_str_and_repr_show_every_digit_asked(digits):
    r = gyrores.pair(6, 5, digits=digits)
    shown = str(r.r_res)
    assert len(_significant_digits(shown)) == digits, shown
    assert repr(r.r_res) == f"mpf('{shown}')" and shown in repr(r)
    # The digits shown are the correct rounding of the exact value: an independent 80-digit value
    # (mpmath, the naive formulation) rounded to `digits` digits gives the same text.
    exact = _r_res_by_mpmath(6, 5, digits + 20)
    assert shown == mpmath.nstr(exact, digits, strip_zeros=False, min_fixed=-5, max_fixed=digits)
    # Every other real too, and str() is not mpmath.mp.dps's: 15 digits would be shown otherwise.
    assert all(len(_significant_digits(str(v))) == digits for v in (r.theta_first, r.t_first, r.n))
    with mpmath.workdps(5):
        assert str(r.r_res) == shown


def test_str_of_thirty_digits_of_r_res():
    # The example of the issue: str(pair(6, 5, digits=30).r_res), checked digit by digit against
    # mpmath's own value of r_res (not against the library's text).
    shown = str(gyrores.pair(6, 5, digits=30).r_res)
    assert shown == "0.0507458057910333724637156511865"
    with mpmath.workdps(60):
        assert abs(mpmath.mpf(shown) - _r_res_by_mpmath(6, 5, 60)) <= mpmath.mpf("0.5e-31")
    # Must fail on a value off in its last digit.
    with mpmath.workdps(60):
        assert abs(mpmath.mpf("0.0507458057910333724637156511866") - _r_res_by_mpmath(6, 5, 60)) > mpmath.mpf("0.5e-31")


def test_interval_repr_shows_distinct_ends_and_the_width():
    iv = gyrores.pair(6, 5, digits=30, enclosures=True).enclosures.r_res
    text = repr(iv)
    lo_text, hi_text = (part.split("'")[1] for part in text.split(", ")[:2])
    assert lo_text != hi_text
    with mpmath.workdps(60):  # the ends as printed are proved bounds of the exact value
        assert mpmath.mpf(lo_text) <= _r_res_by_mpmath(6, 5, 60) <= mpmath.mpf(hi_text)
    assert "width=" in text
    width = float(text.split("width=")[1].rstrip(")"))
    assert 0 < width < 1e-30
    f = gyrores.pair(6, 5, digits=12, enclosures=True).enclosures.r_res
    assert "width=" in repr(f) and repr(f.lo) in repr(f) and repr(f.hi) in repr(f)


def test_reals_stay_mpf_and_compute_as_mpf():
    r = gyrores.pair(6, 5, digits=40)
    assert isinstance(r.r_res, mpmath.mpf)
    assert type(r.r_res * 2) is mpmath.mpf and r.r_res * 2 == 2 * r.r_res
    import copy
    import pickle
    assert pickle.loads(pickle.dumps(r.r_res)) == r.r_res and str(pickle.loads(pickle.dumps(r.r_res))) == str(r.r_res)
    assert copy.deepcopy(r.r_res) == r.r_res

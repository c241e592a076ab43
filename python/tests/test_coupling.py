# gyrores.coupling and gyrores.couplings against the CLI's JSON (`gyrores coupling --json`, the
# reference), against the pair analysis where the horizon holds a resonant pair's first hit, and
# the array call against one call per element.
import time
from fractions import Fraction

import mpmath
import pytest

import gyrores

np = pytest.importorskip("numpy")


@pytest.mark.parametrize("call, cli_args", [
    (lambda: gyrores._gyrores._coupling("2", None, "1e30", None, 8, 12), ("2", "--horizon", "1e30")),
    (lambda: gyrores._gyrores._coupling(None, "1/12", "100", None, 8, 12), ("--n2", "1/12")),
    (lambda: gyrores._gyrores._coupling("2", None, "100pi", "1%", 3, 20),
     ("2", "--horizon", "100pi", "--below", "1%", "--convergents", "3", "--digits", "20")),
])
def test_raw_dict_is_the_cli_json(cli_json, call, cli_args):
    assert call() == cli_json("coupling", *cli_args)


def test_values_are_the_cli_values(cli_json):
    expected = cli_json("coupling", "2", "--horizon", "1e30", "--below", "1%", "--digits", "25")
    got = gyrores.coupling(2, horizon=1e30, below="1%", digits=25)
    for key in ("h_min_horizon", "t_min_horizon", "r_min_horizon", "t_below"):
        assert isinstance(got[key], mpmath.mpf)
        assert got[key] == gyrores._numbers.mpf_of_text(expected[key], gyrores._numbers.bits_of_digits(25)), key
        assert got.enclosures[key].contains(got[key])
    assert got.horizon == 10**30 and got.min_at_horizon_end == expected["min_at_horizon_end"]
    assert got.horizon_lobe == int(expected["horizon_lobe"]) and isinstance(got.horizon_lobe, int)
    assert got.cut_lobe == int(expected["cut_lobe"])
    assert got.x == "sqrt(2)/2" and got.horizon_lobe_distance == expected["horizon_lobe_distance"]
    assert got.below.level == Fraction(1, 200) and got.below.lobe == expected["below"]["lobe"]
    small = gyrores.coupling(2, horizon="1e30", digits=12)  # floats: the double of the 17-digit rounding
    expected17 = cli_json("coupling", "2", "--horizon", "1e30", "--digits", "17")
    assert small.h_min_horizon == float(expected17["h_min_horizon"])
    assert isinstance(small.enclosures.h_min_horizon, gyrores.Interval)


def test_horizon_of_pi_multiples_and_huge_t():
    assert gyrores.coupling(2, horizon="100pi").horizon == "100pi"
    assert gyrores.coupling(2, horizon="1e308").horizon == 10**308
    assert gyrores.coupling(2, horizon="1e400", convergents=0).horizon == 10**400
    r = gyrores.coupling(2, horizon="1e100")
    assert r.horizon == 10**100 and r.h_min_horizon < 1e-150
    assert r.horizon_lobe > 10**90


def test_resonant_pair_whose_horizon_holds_t_first_gives_the_pair_values():
    r = gyrores.coupling(n2="1/12", horizon=1000, digits=30)  # the pair (4, 3): t_first ~ 10.03
    p = gyrores.pair(4, 3, digits=30)
    assert r.resonant and (r.pair.tau, r.pair.sigma) == (4, 3)
    assert r.t_min_horizon == p.t_first and r.h_min_horizon == p.h_min
    assert not r.min_at_horizon_end


def test_below_a_percentage_is_the_same_energy():
    pct = gyrores.coupling(2, below="1%", digits=20)
    energy = gyrores.coupling(2, below=Fraction(1, 200), digits=20)
    assert pct.t_below == energy.t_below == pct.below.t_below and not pct.below.never
    assert pct.t_below < pct.t_min_horizon or pct.h_min_horizon <= Fraction(1, 200)
    never = gyrores.coupling(n2="1/12", below="1e-6")  # (4, 3): H_q min ~ 0.0031 > 1e-6
    assert never.below.never and never.t_below is None and never.below.reason
    assert "t_below" not in never.enclosures


def test_array_equals_one_call_per_element():
    ns = [2, "1/3", 0.5, Fraction(7, 3)]
    horizons = [10, "1e30", "100pi", 3]
    table = gyrores.couplings(ns, horizon=horizons, below="1%")
    assert table.shape == (4,) and table.dtype["h_min_horizon"] == np.float64
    for row, n, t in zip(table, ns, horizons):
        one = gyrores.coupling(Fraction(n) if isinstance(n, float) else n, horizon=t, below="1%", digits=40)
        assert row["h_min_horizon"] == float(one.h_min_horizon)
        assert row["t_min_horizon"] == float(one.t_min_horizon)
        assert row["t_below"] == float(one.t_below)
        assert row["min_at_horizon_end"] == one.min_at_horizon_end and row["resonant"] == one.resonant
        assert row["n"] == float(Fraction(n))
    assert table["horizon"][2] == float(mpmath.mpf(100) * mpmath.pi)


def test_array_broadcasts_and_marks_none():
    table = gyrores.couplings(n2=np.array([[Fraction(1, 12)], ["1/3"]], dtype=object), horizon=np.array([5.0, 1e6]))
    assert table.shape == (2, 2) and table.dtype.names[0] == "n2"
    assert np.isnan(table["t_below"]).all()  # no level given
    assert table["resonant"].tolist() == [[True, True], [False, False]]
    assert table["h_min_horizon"][0, 1] == float(gyrores.coupling(n2="1/12", horizon=10**6, digits=40).h_min_horizon)
    never = gyrores.couplings(n2="1/12", horizon=100, below="1e-6")
    assert never.shape == () and np.isnan(never["t_below"])


def test_float_elements_are_exact_binary_values():
    table = gyrores.couplings(n=np.array([0.1]), horizon=1e6)
    exact = gyrores.coupling(Fraction(0.1), horizon=10**6, digits=40)
    assert table["h_min_horizon"][0] == float(exact.h_min_horizon)


def test_progress_is_called_up_to_the_total():
    seen = []
    gyrores.couplings(np.linspace(0.5, 3, 100), horizon=50, progress=lambda done, total: seen.append((done, total)))
    assert seen[-1] == (100, 100) and seen == sorted(seen)


@pytest.mark.parametrize("call, message", [
    (lambda: gyrores.coupling(2, horizon=[1]), "coupling(): horizon must be a number"),
    (lambda: gyrores.coupling(2, horizon="abc"), "coupling(): horizon must be"),
    (lambda: gyrores.coupling(2, horizon=-1), "coupling(): horizon must be >= 0"),
    # beyond the double range the library aborts the process: refused (docs/python.md, Not done here)
    (lambda: gyrores.coupling(2, below=True), "coupling(): below must be a number"),
    (lambda: gyrores.coupling(2, below="x%"), "coupling(): below must be"),
    (lambda: gyrores.coupling(2, digits=2.0), "coupling(): digits must be an integer"),
    (lambda: gyrores.couplings(), "couplings(): give exactly one of n"),
    (lambda: gyrores.couplings([2, "x"]), "couplings(): n[1] must be"),
    (lambda: gyrores.couplings([2, True]), "couplings(): n[1] must be a number"),
    (lambda: gyrores.couplings(2, horizon=[1, float("nan")]), "couplings(): horizon[1] must be finite"),
    (lambda: gyrores.couplings([1, 2], horizon=[1, 2, 3]), "couplings(): n of shape (2,) and horizon of shape (3,)"),
    (lambda: gyrores.couplings(2, below=[1]), "couplings(): below must be a number"),
    (lambda: gyrores.couplings(2, progress=3), "couplings(): progress must be callable"),
])
def test_wrong_arguments_name_function_and_argument(call, message):
    with pytest.raises(gyrores.UsageError) as e:
        call()
    assert str(e.value).startswith(message) and "\n" not in str(e.value)


def test_an_exception_in_progress_stops_the_loop():
    def progress(done, total):
        raise RuntimeError(f"stop at {done}")

    with pytest.raises(RuntimeError, match="stop at 64"):
        gyrores.couplings(np.linspace(0.5, 3, 300), horizon=100, progress=progress)
    assert gyrores.couplings(2)["h_min_horizon"] > 0  # still usable


# Bands (--band N1:N2, --tolerance P%): the CLI's "band" object, converted.

@pytest.mark.parametrize("call, cli_args", [
    (lambda: gyrores._gyrores._coupling(None, None, "16", None, 8, 12, "0.200:0.202", None, 0),
     ("--band", "0.200:0.202", "--horizon", "16")),
    (lambda: gyrores._gyrores._coupling("0.2", None, "40", None, 2, 12, None, "1%", 3),
     ("0.2", "--tolerance", "1%", "--horizon", "40", "--convergents", "2", "--band-digits", "3")),
    (lambda: gyrores._gyrores._coupling(None, "1/12", "5", "1%", 0, 20, "1/2:3/5", None, 0),
     ("--n2", "1/12", "--horizon", "5", "--below", "1%", "--convergents", "0", "--digits", "20",
      "--band", "1/2:3/5")),
    # n = sqrt(1/12) irrational: rational ends enclosing n (1 -+ 1%) outward, as the CLI's
    (lambda: gyrores._gyrores._coupling(None, "1/12", "20", None, 0, 12, None, "1%", 0),
     ("--n2", "1/12", "--tolerance", "1%", "--horizon", "20", "--convergents", "0")),
    (lambda: gyrores._gyrores._coupling(None, None, "1e6", "1%", 8, 12, "1/2:3/5", None, 4),
     ("--band", "1/2:3/5", "--horizon", "1e6", "--below", "1%", "--band-digits", "4")),
])
def test_band_raw_dict_is_the_cli_json(cli_json, call, cli_args):
    assert call() == cli_json("coupling", *cli_args)


def _exact(x):
    """The exact rational of a float or an mpf."""
    return Fraction(x) if isinstance(x, float) else Fraction(x.man) * Fraction(2) ** x.exp


def _interval_holds(iv, lo, hi):
    """Whether the Interval (floats or mpf) holds [lo, hi], the decimal texts of the CLI's JSON."""
    return _exact(iv.lo) <= Fraction(lo) and Fraction(hi) <= _exact(iv.hi)


def test_band_values_and_types_against_the_cli(cli_json):
    expected = cli_json("coupling", "0.5", "--tolerance", "10%", "--horizon", "5", "--band-digits", "3")["band"]
    r = gyrores.coupling(0.5, horizon=5, tolerance="10%", band_digits=3)
    b = r.band
    assert list(b) == list(expected)  # the CLI's keys, in its order
    assert (b.n1, b.n2) == (Fraction(9, 20), Fraction(11, 20)) and b.horizon == 5 and b.digits == 3
    assert b.format == "gyrores-band/2" and b.theorem == "band-theorem/1" and b.interrupted is False
    assert b.first_below is None  # no level asked
    for key in ("absorption", "containment"):
        e, want = b[key], expected[key]
        assert list(e) == list(want)
        assert e.settled and not e.interrupted and e.reason is None
        assert isinstance(e.h_min, float) and e.h_min == float(want["h_min"]) and e.h_min in e.enclosure
        assert isinstance(e.enclosure, gyrores.Interval) and _interval_holds(e.enclosure, *want["enclosure"])
        assert e.intervals == want["intervals"] and isinstance(e.intervals, int) and e.couplings == want["couplings"]
        assert e.at.n2 == Fraction(want["at"]["n2"]) and e.at.x == want["at"]["x"]
        assert isinstance(e.at.h_min, float) and e.at.h_min == float(want["at"]["h_min"])
        assert b.n1 ** 2 <= e.at.n2 <= b.n2 ** 2
    assert b.containment.h_min <= b.absorption.h_min
    # A tolerance given as a number is a fraction of |n|; the same band.
    same = gyrores.coupling(-0.5, horizon=5, tolerance=Fraction(1, 10), band_digits=3).band
    assert same == b
    # Beyond 15 digits every real of the call is an mpf, the band's too, with all its digits.
    wide = gyrores.coupling(0.5, horizon=5, tolerance="10%", band_digits=40, digits=30).band
    wide_expected = cli_json("coupling", "0.5", "--tolerance", "10%", "--horizon", "5", "--band-digits", "40",
                             "--digits", "30")["band"]
    for key in ("absorption", "containment"):
        e, want = wide[key], wide_expected[key]
        assert isinstance(e.h_min, mpmath.mpf) and isinstance(e.enclosure.lo, mpmath.mpf) and wide.digits == 40
        assert e.h_min == gyrores._numbers.mpf_of_text(want["h_min"], gyrores._numbers.bits_of_digits(40))
        assert _interval_holds(e.enclosure, *want["enclosure"]) and e.h_min in b[key].enclosure
    # By default the band has the call's digits (floats: from 17, as the coupling's own values).
    assert gyrores.coupling(0.5, horizon=5, tolerance="10%").band.digits == 12


def test_band_guarantees_bound_every_sampled_minimum():
    # Independent reference: each coupling's own proved minimum over [0, T] (the horizon theorem,
    # one coupling at a time). Every sampled minimum lies under the absorption guarantee (the
    # highest) and over the containment guarantee (the lowest), and each guarantee is the minimum
    # of the coupling where it is attained.
    b = gyrores.coupling(band="9/20:11/20", horizon=5, band_digits=8).band
    absorption, containment = b.absorption, b.containment
    samples = [b.n1 + (b.n2 - b.n1) * Fraction(i, 100) for i in range(101)]
    minima = [gyrores.coupling(n, horizon=5, convergents=0, digits=17).enclosures.h_min_horizon for n in samples]
    assert all(containment.enclosure.lo <= m.hi and m.lo <= absorption.enclosure.hi for m in minima)
    # the sampling comes near both ends (the guarantees are attained inside the band)
    assert max(m.hi for m in minima) >= absorption.enclosure.lo * (1 - 1e-2)
    assert min(m.lo for m in minima) <= containment.enclosure.hi * (1 + 1e-2)
    for e in (absorption, containment):
        own = gyrores.coupling(n2=e.at.n2, horizon=5, convergents=0, digits=17).enclosures.h_min_horizon
        assert e.enclosure.lo <= own.hi and own.lo <= e.enclosure.hi


def test_band_holding_a_degenerate_pair_has_containment_zero_past_its_zero_time():
    # n in [0.200, 0.202] holds (11, 9): n^2 = 4/99, r_res = 0, H_q = 0 at t ~ 15.63.
    pair = gyrores.coupling(n2=Fraction(4, 99), horizon=16, digits=12)
    assert pair.h_min_horizon == 0 and (pair.pair.tau, pair.pair.sigma) == (11, 9)
    t_zero = pair.pair_analysis.t_first
    assert 15.6 < t_zero < 15.7
    r = gyrores.coupling(band=(Fraction(1, 5), "0.202"), horizon=16)
    assert set(r) == {"horizon", "theorem", "band", "digits"} and r.horizon == 16  # a band alone: the CLI's keys
    c = r.band.containment
    assert c.settled and c.h_min == 0 and c.enclosure == gyrores.Interval(0.0, 0.0)
    assert c.at.n2 == Fraction(4, 99) and (c.at.pair.tau, c.at.pair.sigma) == (11, 9)
    assert abs(c.at.t_min - t_zero) <= 1e-9 * t_zero
    # Before the zero time every coupling keeps some energy: the containment guarantee is > 0.
    before = gyrores.coupling(band=(Fraction(1, 5), "0.202"), horizon=15.5).band.containment
    assert before.settled and before.enclosure.lo > 0
    at = gyrores.coupling(n2=before.at.n2, horizon=15.5, digits=17).enclosures.h_min_horizon
    assert before.enclosure.lo <= at.hi and at.lo <= before.enclosure.hi


def test_band_first_below_is_the_latest_first_time():
    # Each coupling's own first time below E (the horizon theorem) comes no later than the band's
    # first time below, which is attained at its coupling.
    b = gyrores.coupling(band=("1/2", "3/5"), below="1%", band_digits=8).band
    fb = b.first_below
    assert fb.level == Fraction(1, 200) and not fb.never and fb.settled and fb.t_below in fb.enclosure
    for i in range(21):
        n = Fraction(1, 2) + Fraction(i, 200)
        own = gyrores.coupling(n, below="1%", convergents=0, digits=17)
        assert not own.below.never and own.enclosures.t_below.lo <= fb.enclosure.hi
    own = gyrores.coupling(n2=fb.at.n2, below="1%", convergents=0, digits=17).enclosures.t_below
    assert fb.enclosure.lo <= own.hi and own.lo <= fb.enclosure.hi


def test_band_first_below_never_when_a_coupling_keeps_above_the_level():
    # [0.28, 0.29] holds (4, 3) (n^2 = 1/12), whose H_q stays above ~0.0031 for all time.
    own = gyrores.coupling(n2="1/12", below="1e-6")
    assert own.below.never
    fb = gyrores.coupling(band=("0.28", "0.29"), below="1e-6").band.first_below
    assert fb.never and fb.settled and fb.t_below is None and fb.enclosure is None and fb.reason
    assert fb.at.n2 == Fraction(1, 12) and (fb.at.pair.tau, fb.at.pair.sigma) == (4, 3) and fb.at.t_below is None


@pytest.mark.parametrize("call, message", [
    (lambda: gyrores.coupling(band=(0.3, 0.2)), "coupling(): band needs 0 < n1 < n2, got 3/10:1/5"),
    (lambda: gyrores.coupling(band=(0.2, 0.2)), "coupling(): band needs 0 < n1 < n2"),
    (lambda: gyrores.coupling(band=(-0.2, 0.2)), "coupling(): band needs 0 < n1 < n2"),
    (lambda: gyrores.coupling(band="0:0.2"), "coupling(): band needs 0 < n1 < n2"),
    # checked before the coupling's own analysis (a horizon of 1e30 would take a while)
    (lambda: gyrores.coupling(2, horizon="1e30", band="3:1"), "coupling(): band needs 0 < n1 < n2"),
    (lambda: gyrores.coupling(0.2, band=(0.1, 0.3), tolerance="1%"), "coupling(): give at most one of band and tolerance"),
    (lambda: gyrores.coupling(0.2, tolerance="-1%"), "coupling(): tolerance must be in (0%, 100%), got -1%"),
    (lambda: gyrores.coupling(0.2, tolerance=-0.01), "coupling(): tolerance must be in (0%, 100%)"),
    (lambda: gyrores.coupling(0.2, tolerance=1), "coupling(): tolerance must be in (0%, 100%), got 100%"),
    (lambda: gyrores.coupling(0.2, tolerance="1"), "coupling(): tolerance must be a percentage such as 1%"),
    (lambda: gyrores.coupling(0.2, tolerance=[1]), "coupling(): tolerance must be a number"),
    (lambda: gyrores.coupling(tolerance="1%"), "coupling(): give exactly one of n"),
    (lambda: gyrores.coupling(band="0.2-0.3"), "coupling(): band must be N1:N2, got 0.2-0.3"),
    (lambda: gyrores.coupling(band=(0.2,)), "coupling(): band must be (n1, n2) or text 'N1:N2'"),
    (lambda: gyrores.coupling(band=(0.2, True)), "coupling(): band[1] must be a number"),
    (lambda: gyrores.coupling(band=(0.2, "x")), "coupling(): band N2"),
    (lambda: gyrores.coupling(band=(0.1, 0.2), below="x%"), "coupling(): below must be"),
    (lambda: gyrores.coupling(band=(0.1, 0.2), band_digits=0), "coupling(): band_digits must be in [1, 10000], got 0"),
    (lambda: gyrores.coupling(band=(0.1, 0.2), band_digits=10001), "coupling(): band_digits must be in [1, 10000]"),
    (lambda: gyrores.coupling(band=(0.1, 0.2), band_digits=2.0), "coupling(): band_digits must be an integer"),
    (lambda: gyrores.coupling(band=(0.1, 0.2), horizon=-1), "coupling(): horizon must be >= 0"),
    (lambda: gyrores.coupling(2, n2=4, band=(0.1, 0.2)), "coupling(): give exactly one of n"),
])
def test_band_wrong_arguments_name_function_and_argument(call, message):
    start = time.monotonic()
    with pytest.raises(gyrores.UsageError) as e:
        call()
    assert str(e.value).startswith(message) and "\n" not in str(e.value)
    assert time.monotonic() - start < 1.0  # before any work

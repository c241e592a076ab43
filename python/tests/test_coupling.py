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
    (lambda: gyrores._gyrores._coupling(None, None, "16", None, 8, 12, "0.200:0.202", None, 6, 200),
     ("--band", "0.200:0.202", "--horizon", "16", "--band-evaluations", "200")),
    (lambda: gyrores._gyrores._coupling("0.2", None, "40", None, 2, 12, None, "1%", 3, 100),
     ("0.2", "--tolerance", "1%", "--horizon", "40", "--convergents", "2", "--band-digits", "3",
      "--band-evaluations", "100")),
    (lambda: gyrores._gyrores._coupling(None, "1/12", "5", None, 0, 20, "1/2:3/5", None, 2, 50),
     ("--n2", "1/12", "--horizon", "5", "--convergents", "0", "--digits", "20", "--band", "1/2:3/5",
      "--band-digits", "2", "--band-evaluations", "50")),
])
def test_band_raw_dict_is_the_cli_json(cli_json, call, cli_args):
    assert call() == cli_json("coupling", *cli_args)


def _fraction_interval_holds(iv, lo, hi):
    """Whether the Interval (floats or mpf) holds the exact rationals [lo, hi] of the CLI's JSON."""
    def exact(x):
        return Fraction(x) if isinstance(x, float) else Fraction(x.man) * Fraction(2) ** x.exp
    return exact(iv.lo) <= Fraction(lo) and Fraction(hi) <= exact(iv.hi)


def test_band_values_and_types_against_the_cli(cli_json):
    expected = cli_json("coupling", "0.5", "--tolerance", "10%", "--horizon", "5", "--band-digits", "3")["band"]
    r = gyrores.coupling(0.5, horizon=5, tolerance="10%", band_digits=3)
    b = r.band
    assert (b.n1, b.n2) == (Fraction(9, 20), Fraction(11, 20)) and b.degenerate is None
    assert b.evaluations == expected["evaluations"] and isinstance(b.evaluations, int) and b.digits == 3
    assert isinstance(b.lipschitz, float) and b.lipschitz == float(expected["lipschitz"])
    for key in ("worst_h_min", "best_h_min"):
        e, want = b[key], expected[key]
        assert isinstance(e.enclosure, gyrores.Interval) and isinstance(e.enclosure.lo, float)
        assert _fraction_interval_holds(e.enclosure, *want["enclosure"])  # outward from the exact ends
        assert e.converged == want["converged"] and e.n_at == Fraction(want["n_at"])
        assert e.n_box == tuple(Fraction(t) for t in want["n_box"]) and e.n_box[0] <= e.n_at <= e.n_box[1]
        assert (e.value is None) == (want["value"] is None)
        if e.value is not None:
            assert isinstance(e.value, float) and e.value == float(want["value"]) and e.value in e.enclosure
    # A tolerance given as a number is a fraction of |n|; the same band.
    same = gyrores.coupling(-0.5, horizon=5, tolerance=Fraction(1, 10), band_digits=3).band
    assert same.worst_h_min.enclosure == b.worst_h_min.enclosure and (same.n1, same.n2) == (b.n1, b.n2)
    # Beyond 15 digits every real of the call is an mpf, the band's too.
    wide = gyrores.coupling(0.5, horizon=5, tolerance="10%", band_digits=3, digits=30).band
    assert isinstance(wide.worst_h_min.enclosure.lo, mpmath.mpf) and isinstance(wide.lipschitz, mpmath.mpf)
    assert _fraction_interval_holds(wide.worst_h_min.enclosure, *expected["worst_h_min"]["enclosure"])


def test_band_holds_every_sampled_minimum():
    # Brute force: the proved minimum of every sampled coupling of the band lies in [best.lo, worst.hi],
    # and the minimum at each n_at lies in its extreme's enclosure.
    b = gyrores.coupling(band="9/20:11/20", horizon=5, band_digits=4).band
    assert b.degenerate is None
    worst, best = b.worst_h_min, b.best_h_min
    samples = [b.n1 + (b.n2 - b.n1) * Fraction(i, 200) for i in range(201)]
    minima = [gyrores.coupling(n, horizon=5, convergents=0, digits=17).enclosures.h_min_horizon for n in samples]
    assert all(best.enclosure.lo <= m.lo and m.hi <= worst.enclosure.hi for m in minima)
    # the samples come close to both extremes (the sampling step times the Lipschitz bound)
    slack = b.lipschitz * float(b.n2 - b.n1) / 200
    assert max(m.hi for m in minima) >= worst.enclosure.lo - slack
    assert min(m.lo for m in minima) <= best.enclosure.hi + slack
    for e in (worst, best):
        at = gyrores.coupling(e.n_at, horizon=5, convergents=0, digits=17).enclosures.h_min_horizon
        assert e.enclosure.lo <= at.hi and at.lo <= e.enclosure.hi


def test_band_with_a_degenerate_pair_has_best_zero_exactly():
    # n in [0.200, 0.202], T = 16 holds (11, 9) (n^2 = 4/99, r_res = 0, H_q = 0 at t ~ 15.63).
    r = gyrores.coupling(band=(Fraction(1, 5), "0.202"), horizon=16, band_evaluations=200)
    b = r.band
    assert (b.degenerate.tau, b.degenerate.sigma) == (11, 9) and b.degenerate.n2 == Fraction(4, 99)
    assert b.best_h_min.value == 0 and b.best_h_min.enclosure == gyrores.Interval(0.0, 0.0)
    assert b.best_h_min.n_at is None and b.best_h_min.n_box is None and b.best_h_min.converged
    assert b.n1 <= Fraction(4, 99) ** 0.5 <= b.n2
    pair = gyrores.coupling(n2=b.degenerate.n2, horizon=16, digits=12)
    assert pair.h_min_horizon == 0 and (pair.pair.tau, pair.pair.sigma) == (11, 9)
    assert abs(b.degenerate.t_zero - pair.pair_analysis.t_first) <= 1e-10 * pair.pair_analysis.t_first
    assert b.degenerate.t_zero <= 16 and r.horizon == 16 and r.theorem == "horizon-theorem/1"
    assert set(r) == {"horizon", "theorem", "band", "digits"}  # a band alone: the CLI's keys
    # the worst case converges (lobe bounds) and its enclosure holds the value at its n_at
    w = b.worst_h_min
    assert w.converged and w.enclosure.lo <= w.value <= w.enclosure.hi
    at = gyrores.coupling(w.n_at, horizon=16, digits=12)
    assert w.enclosure.lo <= at.h_min_horizon * (1 + 1e-11) and at.h_min_horizon * (1 - 1e-11) <= w.enclosure.hi


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
    (lambda: gyrores.coupling(n2="1/12", tolerance="1%"), "coupling(): tolerance needs the coupling n"),
    (lambda: gyrores.coupling(tolerance="1%"), "coupling(): give exactly one of n"),
    (lambda: gyrores.coupling(band="0.2-0.3"), "coupling(): band must be N1:N2, got 0.2-0.3"),
    (lambda: gyrores.coupling(band=(0.2,)), "coupling(): band must be (n1, n2) or text 'N1:N2'"),
    (lambda: gyrores.coupling(band=(0.2, True)), "coupling(): band[1] must be a number"),
    (lambda: gyrores.coupling(band=(0.2, "x")), "coupling(): band N2"),
    (lambda: gyrores.coupling(band=(0.1, 0.2), below="1%"), "coupling(): below needs the coupling n or n2"),
    (lambda: gyrores.coupling(band=(0.1, 0.2), band_digits=13), "coupling(): band_digits must be in [1, 12]"),
    (lambda: gyrores.coupling(band=(0.1, 0.2), band_evaluations=5), "coupling(): band_evaluations must be in"),
    (lambda: gyrores.coupling(band=(0.1, 0.2), horizon=-1), "coupling(): horizon must be >= 0"),
    (lambda: gyrores.coupling(2, n2=4, band=(0.1, 0.2)), "coupling(): give exactly one of n"),
])
def test_band_wrong_arguments_name_function_and_argument(call, message):
    start = time.monotonic()
    with pytest.raises(gyrores.UsageError) as e:
        call()
    assert str(e.value).startswith(message) and "\n" not in str(e.value)
    assert time.monotonic() - start < 1.0  # before any work

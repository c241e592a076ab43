# gyrores.coupling and gyrores.couplings against the CLI's JSON (`gyrores coupling --json`, the
# reference), against the pair analysis where the horizon holds a resonant pair's first hit, and
# the array call against one call per element.
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

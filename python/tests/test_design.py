# gyrores.design and gyrores.pareto against the CLI's JSON (coupling: test_coupling.py).
from fractions import Fraction

import pytest

import gyrores


def test_design_matches_cli(cli_json):
    expected = cli_json("design", "contain", "--tmax", "17", "--beat", "10", "--digits", "12")
    got = gyrores._gyrores._design("contain", "17", "10", 200, 0, None, False, 5, 12)
    assert got == expected
    d = gyrores.design("contain", 17, beat=10, digits=12)
    assert (d["chosen"]["tau"], d["chosen"]["sigma"]) == (6, 5)  # the paper's Case B, exact time
    assert isinstance(d["chosen"]["r_res"], float)


def test_design_with_proxy_picks_the_papers_pair():
    d = gyrores.design("contain", "17", beat="10", proxy=True)
    assert (d["chosen"]["tau"], d["chosen"]["sigma"]) == (23, 19)


def test_pareto_matches_cli(cli_json):
    expected = cli_json("pareto", "--max-order", "40", "--digits", "10")
    got = gyrores._gyrores._pareto(40, "absorb", False, False, None, 0, 10)
    for key in ("orientation", "orientation_meaning", "time", "max_order", "pairs", "front", "digits"):
        assert got[key] == expected[key], key


def test_bad_input():
    with pytest.raises(ValueError, match="give exactly one"):
        gyrores.coupling()
    with pytest.raises(ValueError, match="tmax must be > 0"):
        gyrores.design("absorb", 0)
    with pytest.raises(ValueError, match="max_order"):
        gyrores.pareto(2)
    with pytest.raises(ArithmeticError, match="no resonant pair"):
        gyrores.design("absorb", "0.001", max_order=20)


# design(..., tolerance=, level=, horizon=): `gyrores design --tolerance P% --level E [--horizon H]`.

@pytest.mark.parametrize("args, cli_args", [
    (("absorb", "20", None, 200, 0, None, False, 5, 10, "1%", "1%", None),
     ("absorb", "--tmax", "20", "--tolerance", "1%", "--level", "1%")),
    (("contain", "17", "10", 200, 0, None, False, 5, 12, "0.5%", "1/1000", "10"),
     ("contain", "--tmax", "17", "--beat", "10", "--digits", "12", "--tolerance", "0.5%", "--level", "1/1000",
      "--horizon", "10")),
])
def test_design_tolerance_raw_dict_is_the_cli_json(cli_json, args, cli_args):
    assert gyrores._gyrores._design(*args) == cli_json("design", *cli_args)


# Pairs (n, 1) up to T = 30 (3, 1 excluded): six bands fail 3.5e-9, (27, 1) is the first that meets it.
MIXED = ("absorb", "--tmax", "30", "--exclude-low", "4", "--tolerance", "1%", "--level", "3.5e-9")


def test_design_tolerance_verdicts_are_the_cli_verdicts(cli_json):
    expected = cli_json("design", *MIXED)["tolerance"]
    got = gyrores.design("absorb", 30, exclude_low=4, tolerance=Fraction(1, 100), level=Fraction(35, 10**10)).tolerance
    assert [(c.tau, c.sigma, c.verdict) for c in got.checked] == [
        (c["tau"], c["sigma"], c["verdict"]) for c in expected["checked"]]
    assert [c.verdict for c in got.checked] == ["fails"] * 6 + ["meets"]
    assert (got.chosen.tau, got.chosen.sigma) == (expected["chosen"]["tau"], expected["chosen"]["sigma"]) == (27, 1)
    assert got.level == Fraction(35, 10**10) and got.percent == "1%" and got.theorem == "band-theorem/1"
    assert gyrores.design("absorb", 20, tolerance="1%", level="1%").tolerance.level == Fraction(1, 200)
    for c, want in zip(got.checked, expected["checked"]):
        assert c.band == tuple(Fraction(t) for t in want["band"]) and c.at_n2 == Fraction(want["at_n2"])
        lo, hi = (Fraction(t) for t in want["absorption"])
        assert isinstance(c.absorption, gyrores.Interval)
        assert Fraction(c.absorption.lo) <= lo and hi <= Fraction(c.absorption.hi)


def test_design_tolerance_verdicts_against_the_band_of_coupling():
    # Independent reference: coupling()'s band over the same couplings and horizon. absorb meets
    # the level when the band's absorption guarantee (its highest minimum) is proved <= E.
    level = Fraction(35, 10**10)
    d = gyrores.design("absorb", 30, exclude_low=4, tolerance="1%", level=level)
    assert d.tolerance.chosen is not None
    for c in d.tolerance.checked:
        band = gyrores.coupling(band=c.band, horizon=30, band_digits=8).band.absorption.enclosure
        assert band.lo <= c.absorption.hi and c.absorption.lo <= band.hi
        if c.verdict == "meets":
            assert band.lo <= level
        elif c.verdict == "fails":
            assert band.hi > level
    chosen = d.tolerance.checked[-1]
    assert chosen.verdict == "meets" and (chosen.tau, chosen.sigma) == (d.tolerance.chosen.tau, d.tolerance.chosen.sigma)


def test_design_tolerance_that_no_pair_meets(cli_json):
    # H_q <= 1e-30 before T = 20 for a whole 1% band: no pair walked meets it; chosen is None, as
    # the CLI's null, and every verdict is the CLI's.
    expected = cli_json("design", "absorb", "--tmax", "20", "--tolerance", "1%", "--level", "1e-30")["tolerance"]
    got = gyrores.design("absorb", 20, tolerance="1%", level="1e-30").tolerance
    assert got.chosen is None and expected["chosen"] is None
    assert [c.verdict for c in got.checked] == [c["verdict"] for c in expected["checked"]]
    assert "meets" not in [c.verdict for c in got.checked]


@pytest.mark.parametrize("call, message", [
    (lambda: gyrores.design("absorb", 20, level="1%"), "design(): level and horizon need tolerance"),
    (lambda: gyrores.design("contain", 20, horizon=5), "design(): level and horizon need tolerance"),
    (lambda: gyrores.design("absorb", 20, tolerance="1%"), "design(): tolerance needs level E"),
    (lambda: gyrores.design("absorb", 20, tolerance="1%", level="1%", horizon=5), "design(): horizon is for contain"),
    (lambda: gyrores.design("absorb", 20, tolerance="1%", level="1%", proxy=True),
     "design(): a tolerance needs the exact first-hit time"),
    (lambda: gyrores.design("absorb", 20, tolerance="200%", level="1%"), "design(): tolerance must be in (0%, 100%)"),
    (lambda: gyrores.design("absorb", 20, tolerance=0, level="1%"), "design(): tolerance must be in (0%, 100%)"),
    (lambda: gyrores.design("absorb", 20, tolerance="1", level="1%"), "design(): tolerance must be a percentage"),
    (lambda: gyrores.design("absorb", 20, tolerance=[1], level="1%"), "design(): tolerance must be a number"),
    (lambda: gyrores.design("absorb", 20, tolerance="1%", level=True), "design(): level must be a number"),
    (lambda: gyrores.design("absorb", 20, tolerance="1%", level="x%"), "design(): level must be"),
    (lambda: gyrores.design("absorb", 20, tolerance="1%", level=-1), "design(): level must be"),
    (lambda: gyrores.design("contain", 20, tolerance="1%", level="1%", horizon=0), "design(): horizon must be > 0"),
    (lambda: gyrores.design("contain", 20, tolerance="1%", level="1%", horizon="x"), "design(): horizon must be"),
    (lambda: gyrores.design("contain", 20, tolerance="1%", level="1%", horizon=[1]), "design(): horizon must be a number"),
])
def test_design_tolerance_wrong_arguments_name_function_and_argument(call, message):
    with pytest.raises(gyrores.UsageError) as e:
        call()
    assert str(e.value).startswith(message) and "\n" not in str(e.value)

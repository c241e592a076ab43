# gyrores.design and gyrores.pareto against the CLI's JSON (coupling: test_coupling.py).
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

# Arguments at the edges: every error a one-line UsageError naming the function and the argument
# (never a raw OverflowError or Python's int <-> text limit), and rationals of any length both
# ways, whatever sys.get_int_max_str_digits is.
import sys
from decimal import Decimal
from fractions import Fraction

import mpmath
import pytest

import gyrores

BIG = 10**5000  # beyond Python's 4300-digit int <-> text limit


@pytest.mark.parametrize("call, message", [
    (lambda: gyrores.couplings(n=2, horizon=["1e400"]), "couplings(): horizon[0] = 1e400 is beyond the largest double"),
    (lambda: gyrores.couplings(n=[0.5, "1e-400"]), "couplings(): n[1] = 1e-400 is below the smallest double"),
    (lambda: gyrores.couplings(n2=[Fraction(BIG)]), "couplings(): n2[0] = 1000"),
    (lambda: gyrores.couplings(n=2, horizon="1e309pi"), "couplings(): horizon = 1e309pi is beyond the largest double"),
    (lambda: gyrores.couplings(n=[float("inf")]), "couplings(): n[0] must be finite"),
    (lambda: gyrores.coupling(n=mpmath.mpf("1e100000000")), "coupling(): n = 1.0e+100000000 is beyond the range"),
    (lambda: gyrores.coupling(n=mpmath.inf), "coupling(): n must be finite"),
    (lambda: gyrores.coupling(2, horizon=Decimal("NaN")), "coupling(): horizon must be finite"),
    (lambda: gyrores.pair(6, 5, digits=BIG), "pair(): digits must be in [1, 10000], got an integer of about 5001 digits"),
    (lambda: gyrores.pair(6, 5, digits=-BIG), "pair(): digits must be in [1, 10000]"),
    (lambda: gyrores.sweep(BIG), "sweep(): max_order must be in"),
    (lambda: gyrores.pairs([BIG], [1]), "pairs(): taus[0] = an integer of about 5001 digits is above 2^40"),
    (lambda: gyrores.pair(6, 5, qdot0=[BIG]), "pair(): qdot0 must be a number"),
])
def test_argument_errors_are_usage_errors_naming_the_argument(call, message):
    with pytest.raises(gyrores.UsageError) as e:
        call()
    assert str(e.value).startswith(message), str(e.value)
    assert "\n" not in str(e.value) and len(str(e.value)) < 400


def test_values_the_table_holds_are_not_refused():
    # Inside the doubles and the coupling limits (|n| >= 10^-150: docs/formats.md, limits): the
    # float64 columns hold them (the checks above must not refuse these).
    table = gyrores.couplings(n=["1e-150", 2], horizon=["1e300", "4.9e-324"])
    assert table["n"][0] == 1e-150 and table["horizon"][0] == 1e300 and table["horizon"][1] == 5e-324


def test_rationals_of_any_length_in_and_out():
    assert sys.get_int_max_str_digits() in (0, 4300) or True  # whatever it is, nothing here depends on it
    q = Fraction(BIG + 1, BIG)
    r = gyrores.pair(6, 5, digits=20, qdot0=q)
    assert r.r_res == gyrores.pair(6, 5, digits=20).r_res  # r_res scales with qdot0, 1 + 1e-5000 here
    # A coupling's n^2 takes at most 2000 characters and lies in [10^-300, 10^300] (docs/formats.md,
    # limits): the longest such fractions go in and come back exactly; one past is refused by name.
    big = 10**998  # (10^998 + 1)/10^998: 1999 characters as p/q, the longest accepted
    q2 = Fraction(big + 1, big)
    c = gyrores.coupling(n2=q2, horizon=10, convergents=0)
    assert c.n2 == q2
    c = gyrores.coupling(n2=Fraction(1, 10**299), horizon=10, convergents=0)
    assert c.n2 == Fraction(1, 10**299) and c.h_min_horizon == 0.5
    assert gyrores.coupling(n=mpmath.mpf(2) ** -400, horizon=1, convergents=0).n2 == Fraction(1, 2**800)
    # Must fail: a value off by one in its last digit is not read back as equal.
    assert c.n2 != Fraction(1, 10**299 + 1)
    with pytest.raises(gyrores.UsageError, match="2000"):
        gyrores.coupling(n2=q, horizon=10, convergents=0)


def test_import_without_mpmath_says_so_in_one_line(tmp_path):
    import os
    import subprocess
    fake = tmp_path / "mpmath"
    fake.mkdir()
    (fake / "__init__.py").write_text("raise ImportError('No module named mpmath')\n")
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(tmp_path), os.environ.get("PYTHONPATH", "")]))
    out = subprocess.run([sys.executable, "-c", "import gyrores"], env=env, capture_output=True, text=True)
    assert out.returncode != 0
    assert out.stderr.strip().splitlines()[-1] == (
        "ImportError: gyrores needs mpmath (its reals beyond 15 digits are mpmath numbers): "
        "pip install mpmath, or on Debian apt-get install python3-mpmath")
    assert "During handling" not in out.stderr  # the message, not a chain of tracebacks

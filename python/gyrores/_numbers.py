"""Numbers of any size between the library's decimal text and Python: no limit of Python's own.

Python refuses to convert decimal text of more than ``sys.get_int_max_str_digits()`` (4300)
digits to an int, and mpmath parses decimal text through such ints. Here long decimal integers go
through ``decimal.Decimal`` (whose conversion to int has no such limit) and reals through exact
integer arithmetic with a single rounding (mpmath.libmp), so nothing process-wide is changed.
"""

import decimal as _decimal
import fractions as _fractions
import json as _json
import math as _math
import re as _re

import mpmath as _mpmath
from mpmath import libmp as _libmp

from . import _gyrores
from ._types import _real_of_text

_PYTHON_BACKEND = _libmp.BACKEND == "python"  # mantissas are ints (else gmpy's mpz)

mpf_type = _mpmath.mpf  # what every real of more than 15 digits is (a Real, its subclass)

# The library's reals: format_scientific (core/decimal.hpp), e.g. "5.0745805e-02", "-1e+00", "0".
_SCIENTIFIC = _re.compile(r"^(-?)(\d)(?:\.(\d+))?e([+-]\d+)$")
_SAFE_DIGITS = 4000  # below Python's default limit (4300): int(text) is fine


def int_of_text(text):
    """The int of a decimal integer text of any length."""
    if len(text) <= _SAFE_DIGITS:
        return int(text)
    with _decimal.localcontext() as ctx:  # exact: no rounding to the context's 28 digits
        ctx.prec = _decimal.MAX_PREC
        ctx.Emax = _decimal.MAX_EMAX
        return int(_decimal.Decimal(text.strip()))


def int_text(value):
    """The decimal text of an int of any size (str(int) is limited to 4300 digits)."""
    if value.bit_length() <= 13000:  # under 3914 digits, within Python's limit
        return str(value)
    with _decimal.localcontext() as ctx:  # Decimal(int) is exact; its str has no digit limit
        ctx.prec = _decimal.MAX_PREC
        return str(_decimal.Decimal(value))


# An exact rational as text: "P/Q", "P", or a decimal "-1.5e-3" (the library's and the CLI's forms).
_FRACTION_TEXT = _re.compile(r"^\s*([+-]?\d+)\s*/\s*(\d+)\s*$")


def fraction_of_text(text):
    """The Fraction of an exact rational text of any length (Fraction(str) goes through int(str),
    limited to 4300 digits); ValueError for anything else."""
    m = _FRACTION_TEXT.match(text)
    if m:
        return _fractions.Fraction(int_of_text(m.group(1)), int_of_text(m.group(2)))
    if len(text) <= _SAFE_DIGITS:
        return _fractions.Fraction(text)
    try:
        d = _decimal.Decimal(text.strip())
    except _decimal.InvalidOperation:
        raise ValueError(f"not a rational: {text[:40]!r}...") from None
    if not d.is_finite():
        raise ValueError(f"not a finite rational: {text[:40]!r}...")
    return _fractions.Fraction(*d.as_integer_ratio())


def loads(text):
    """json.loads with integers of any size (the library's JSON has 10^400-sized pair members)."""
    return _json.loads(text, parse_int=int_of_text)


def is_real_text(text):
    """Whether `text` has the form of the library's reals (a scientific decimal, or 0)."""
    return text in ("0", "-0") or _SCIENTIFIC.match(text) is not None


def _fraction_of(text):
    """(sign, man, exp10): text = (-1)^sign man 10^exp10 exactly."""
    if text in ("0", "-0"):
        return 0, 0, 0
    m = _SCIENTIFIC.match(text)
    if m is None:
        raise ValueError(f"not a decimal real of the library: {text!r}")
    sign, lead, frac, exp = m.groups()
    frac = frac or ""
    return (1 if sign else 0), int_of_text(lead + frac), int(exp) - len(frac)


def mpf_of_text(text, prec, rounding="n"):
    """The mpf of `prec` bits nearest to `text` ('n'), below ('f') or above ('c'): one rounding
    (MPFR's, in the compiled module). A Real (an mpf that prints as `text`, every digit): the
    library's decimal is the number."""
    sign, man, exp, bc = _gyrores._mpf_parts(text, prec, rounding)  # UsageError for other text
    return _real_of_text(text, (sign, man if _PYTHON_BACKEND else _libmp.MPZ(man), exp, bc))


def float_of_text(text, rounding="n"):
    """The double nearest to `text` ('n', Python's float(), correctly rounded), or below/above."""
    x = float(text)
    if rounding == "n" or _math.isinf(x):
        return x
    exact = _decimal.Decimal(text)
    if rounding == "f" and _decimal.Decimal(x) > exact:
        return _math.nextafter(x, -_math.inf)
    if rounding == "c" and _decimal.Decimal(x) < exact:
        return _math.nextafter(x, _math.inf)
    return x


def float_of_fraction(q, rounding="n"):
    """The double nearest to the Fraction `q` ('n', correctly rounded), or below ('f') / above ('c')."""
    x = float(q)  # int / int: correctly rounded
    if rounding == "f" and _fractions.Fraction(x) > q:
        return _math.nextafter(x, -_math.inf)
    if rounding == "c" and _fractions.Fraction(x) < q:
        return _math.nextafter(x, _math.inf)
    return x


def mpf_of_fraction(q, prec, rounding="n"):
    """The mpf of `prec` bits nearest to the Fraction `q` ('n'), below ('f') or above ('c')."""
    raw = _libmp.mpf_div(_libmp.from_int(q.numerator), _libmp.from_int(q.denominator), prec, rounding)
    return _mpmath.mp.make_mpf(raw)


def bits_of_digits(digits):
    """Binary digits that hold `digits` decimal digits, with a few to spare."""
    return int(_math.ceil(digits * _math.log2(10))) + 8

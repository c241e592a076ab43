"""Arguments the Python way: integers through __index__, reals and rationals as exact text.

Every check raises UsageError (a ValueError) naming the public function and the argument.
"""

import decimal as _decimal
import fractions as _fractions
import numbers as _numbers
import operator as _operator

from ._gyrores import UsageError
from ._numbers import int_text as _int_text

# An mpf or float is given exactly, as P/Q: beyond this many binary digits (about 100,000 decimal
# digits, the library's own bound on a decimal exponent, core/rational.hpp) its text is refused.
_MAX_EXACT_BITS = 332200


def _show(value):
    """repr of a value for a message, at most 60 characters; an int too long for Python's int ->
    text conversion (4300 digits) by its size."""
    if isinstance(value, int) and value.bit_length() > 200:
        return f"an integer of about {int(value.bit_length() * 0.30103) + 1} digits"
    try:
        text = repr(value)
    except ValueError:  # a container holding such an int, an mpf of a huge exponent...
        text = f"<{type(value).__name__}>"
    return text if len(text) <= 60 else text[:57] + "..."


def _describe(value):
    return f"{_show(value)} ({type(value).__name__})"


def integer(value, function, name):
    """operator.index(value): ints, NumPy integers, anything with __index__; bool refused."""
    if isinstance(value, bool) or type(value).__name__ == "bool_":
        raise UsageError(f"{function}(): {name} must be an integer, got a bool {value!r}")
    try:
        return int(_operator.index(value))  # int(): a plain int, whatever subclass __index__ gave
    except TypeError:
        raise UsageError(f"{function}(): {name} must be an integer, got {_describe(value)}") from None


def bounded(value, function, name, lo, hi):
    """An integer in [lo, hi]."""
    v = integer(value, function, name)
    if not lo <= v <= hi:
        raise UsageError(f"{function}(): {name} must be in [{lo}, {hi}], got {_show(v)}")
    return v


def flag(value, function, name):
    """A bool (or a NumPy bool)."""
    if isinstance(value, bool) or type(value).__name__ == "bool_":
        return bool(value)
    raise UsageError(f"{function}(): {name} must be True or False, got {_describe(value)}")


def choice(value, function, name, allowed):
    if not isinstance(value, str) or value not in allowed:
        raise UsageError(f"{function}(): {name} must be one of {', '.join(map(repr, allowed))}, got {_describe(value)}")
    return value


def rational(value, function, name):
    """Exact text of a number: an int (or __index__), a float (its shortest repr, exactly what it
    prints), a Fraction, a Decimal, an mpmath.mpf (exactly), or text as the CLI takes it
    ("0.25", "1/4", "2.5e-3")."""
    if isinstance(value, bool):
        raise UsageError(f"{function}(): {name} must be a number, got a bool {value!r}")
    if isinstance(value, str):
        return value.strip()
    if isinstance(value, _fractions.Fraction):
        return f"{_int_text(value.numerator)}/{_int_text(value.denominator)}"
    if isinstance(value, _decimal.Decimal):
        if not value.is_finite():
            raise UsageError(f"{function}(): {name} must be finite, got {value}")
        return str(value)  # Decimal's text has no digit limit
    if hasattr(value, "__index__"):
        return _int_text(integer(value, function, name))
    if isinstance(value, _numbers.Real) and hasattr(value, "as_integer_ratio"):  # float, NumPy floats
        f = float(value)
        if f != f or f in (float("inf"), float("-inf")):
            raise UsageError(f"{function}(): {name} must be finite, got {f}")
        return repr(f)
    try:
        import mpmath
        if isinstance(value, mpmath.mpf):
            if not mpmath.isfinite(value):
                raise UsageError(f"{function}(): {name} must be finite, got {value}")
            man, exp = value.man_exp
            if abs(exp) + int(man).bit_length() > _MAX_EXACT_BITS:
                raise UsageError(f"{function}(): {name} = {mpmath.nstr(value, 5)} is beyond the range gyrores "
                                 f"reads exactly (about 1e-100000 to 1e100000)")
            return _int_text(man * 2**exp) if exp >= 0 else f"{_int_text(man)}/{_int_text(2**-exp)}"
    except ImportError:  # pragma: no cover - mpmath is a dependency
        pass
    raise UsageError(f"{function}(): {name} must be a number (int, float, Fraction, Decimal, mpf or text), "
                     f"got {_describe(value)}")

"""The result types: Result (a dict with attribute access), Interval (a proved enclosure) and
Real (an mpmath.mpf that prints every digit asked)."""

import decimal as _decimal

import mpmath as _mpmath
from mpmath import libmp as _libmp


class Real(_mpmath.mpf):
    """An mpmath.mpf that prints all the digits it was computed to.

    A plain mpf prints mpmath.mp.dps digits (15 by default: str) or 17 (repr), whatever its own
    precision, so a value proved to 30 digits would show 15 of them. A Real keeps the library's
    decimal text, the correct rounding of the exact value to the digits asked, and str()/repr()
    show exactly those digits (``str(pair(6, 5, digits=30).r_res)`` has 30 significant digits).
    The binary value is that decimal rounded to nearest at a few more bits than it needs (so it
    rounds back to the same text). Arithmetic on it gives plain mpf at mpmath.mp's precision, as
    for any mpf.
    """

    __slots__ = ("_text",)

    def __str__(self):
        return _plain(self._text)

    def __repr__(self):
        return f"mpf('{_plain(self._text)}')"

    def __reduce__(self):
        return (_real_of_text, (self._text, self._mpf_))

    def __copy__(self):
        return self

    def __deepcopy__(self, memo):
        return self


def _real_of_text(text, raw):
    """A Real of the decimal `text` whose binary value is the mpmath tuple `raw`."""
    r = object.__new__(Real)
    r._mpf_ = raw
    r._text = text
    return r


def _plain(text):
    """The library's decimal ("5.07e-02", "0") in plain notation where it reads better ("0.0507",
    "16.35") and in e-notation beyond ("1.2e-10", and "2.5e+14" rather than zeros that were never
    digits), every significant digit kept, trailing zeros included."""
    d = _decimal.Decimal(text)
    exponent = d.adjusted()
    if -5 <= exponent < max(len(d.as_tuple().digits), 1):
        return f"{d:f}"
    return str(d).replace("E", "e")


class Result(dict):
    """A dict whose keys are also attributes (``r.r_res`` is ``r["r_res"]``), as SciPy's OptimizeResult.

    Nested objects of the library's JSON are Results too; lists are tuples.
    """

    def __getattr__(self, name):
        try:
            return self[name]
        except KeyError:
            raise AttributeError(name) from None

    def __dir__(self):
        return list(super().__dir__()) + [k for k in self if isinstance(k, str)]

    # Pickling and copying go through dict; attribute access must not hide those hooks.
    def __getstate__(self):
        return None

    def __reduce__(self):
        return (type(self), (dict(self),))


class Interval:
    """A closed interval [lo, hi] that contains an exact value: lo and hi rounded outward.

    lo and hi are floats (digits <= 15) or mpmath.mpf with the precision of the call, whatever
    mpmath.mp.dps is. ``x in iv`` / ``iv.contains(x)`` compare exactly; ``lo, hi = iv`` unpacks.
    """

    __slots__ = ("lo", "hi")

    def __init__(self, lo, hi):
        if not lo <= hi:
            raise ValueError(f"an interval needs lo <= hi, got [{lo}, {hi}]")
        self.lo = lo
        self.hi = hi

    def contains(self, x):
        """Whether lo <= x <= hi (exact comparisons: float, int, mpf, Fraction, Decimal...)."""
        if isinstance(self.lo, _mpmath.mpf) and not isinstance(x, _mpmath.mpf):
            x = _mpmath.mpf(x) if isinstance(x, (int, float)) else x
        return bool(self.lo <= x <= self.hi)

    __contains__ = contains

    @property
    def mid(self):
        """The midpoint, exact when it fits (an mpf of one more bit), else nearest."""
        if isinstance(self.lo, float):
            return self.lo / 2 + self.hi / 2
        s = _libmp.mpf_add(self.lo._mpf_, self.hi._mpf_, 0)  # prec 0: exact
        return _mpmath.mp.make_mpf(_libmp.mpf_shift(s, -1))

    @property
    def width(self):
        """hi - lo (rounded up for floats; exact for mpf)."""
        if isinstance(self.lo, float):
            import math
            w = self.hi - self.lo
            return math.nextafter(w, math.inf) if w else w
        return _mpmath.mp.make_mpf(_libmp.mpf_sub(self.hi._mpf_, self.lo._mpf_, 0))

    def mpi(self):
        """The same interval as mpmath.mpi (at mpmath.iv's precision, rounded outward)."""
        return _mpmath.mpi(self.lo, self.hi)

    def __iter__(self):
        yield self.lo
        yield self.hi

    def __eq__(self, other):
        return isinstance(other, Interval) and self.lo == other.lo and self.hi == other.hi

    def __hash__(self):
        return hash((self.lo, self.hi))

    def __repr__(self):
        # Each end as it prints (a Real shows all its digits, so the ends differ wherever the
        # interval is not a point), and the width, so that a narrow interval does not look like
        # two equal numbers.
        return f"Interval({self.lo!r}, {self.hi!r}, width={_short_real(self.width)})"


def _short_real(x):
    """x with 3 significant digits (float or mpf)."""
    if isinstance(x, float):
        return f"{x:.3g}"
    return _mpmath.nstr(x, 3)

"""The result types: Result (a dict with attribute access) and Interval (a proved enclosure)."""

import mpmath as _mpmath
from mpmath import libmp as _libmp


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
        return f"Interval({self.lo!r}, {self.hi!r})"

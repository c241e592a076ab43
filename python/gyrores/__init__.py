"""gyrores: certified high-precision analysis of gyroscopically coupled oscillators.

Python bindings of the gyrores C++ library (the compiled part is ``gyrores._gyrores``). For a
resonant pair ``(tau, sigma)`` (coprime integers ``tau > sigma >= 1``, any size) ``pair`` gives
the inscribed radius ``r_res``, its minimisers and the first-hit time with every digit proved, as
``gyrores pair --json`` does; ``pairs`` gives the sweep's values for arrays of pairs;
``certify`` and ``check`` produce and re-prove interval certificates; ``asymptotics``,
``design``, ``pareto`` and ``coupling`` mirror the commands of the same names;
``enumerate_pairs`` and ``sweep`` visit every pair up to an order. docs/python.md is the guide.

Numbers: one type per call. With ``digits <= 15`` every real is a ``float``; for ``pair`` and
``asymptotics`` it is the correctly rounded double of the exact value (decided from a proved
enclosure), for ``design``, ``pareto`` and ``coupling`` the double nearest to the value's correct
17-digit rounding. With ``digits > 15`` every real is an ``mpmath.mpf`` holding all the digits
asked (whatever ``mpmath.mp.dps`` is). Enclosures are ``Interval`` objects (``lo``, ``hi``
rounded outward, ``contains``, ``mid``). Integers come back as ints of any size. Results are
``Result`` objects: dicts whose keys are also attributes. An enclosure holds the exact value and
the returned number (widened to it where a correct rounding falls just outside).

Arguments: integers are anything with ``__index__`` (NumPy integers included; ``bool`` is
refused); rationals are ints, floats (their repr), ``Fraction``, ``Decimal``, ``mpf`` or text as
the CLI takes it. Bad input raises ``UsageError`` (a ``ValueError``) naming the function and the
argument; a result that cannot be computed honestly ``ComputeError`` (an ``ArithmeticError``).

Every call may run on several threads at once and takes no lock; the long ones run without the
GIL and stop within a fraction of a second on Ctrl-C (``KeyboardInterrupt``).
"""

import copy as _copy
import fractions as _fractions
import functools as _functools
import json as _json
import os as _os
import re as _re
import stat as _stat

try:  # every real of more than 15 digits is an mpmath number: one line, not a traceback, without it
    import mpmath as _mpmath  # noqa: F401
except ImportError:
    raise ImportError("gyrores needs mpmath (its reals beyond 15 digits are mpmath numbers): "
                      "pip install mpmath, or on Debian apt-get install python3-mpmath") from None

from . import _args, _numbers
from . import _gyrores
from ._gyrores import ComputeError, UsageError
from ._types import Interval, Result

__version__ = _gyrores.__version__

__all__ = [
    "CheckResult", "ComputeError", "Interval", "PairResult", "Result", "UsageError", "__version__", "asymptotics",
    "certify", "check", "coupling", "couplings", "design", "enumerate_pairs", "pair", "pairs", "pareto", "plant",
    "sweep",
]

# Keys whose values are exact rationals as text ("1/12", "17"): fractions.Fraction.
_RATIONAL_KEYS = frozenset({"tmax", "beat", "n2", "level"})
# Keys whose strings are text (or the caller's input echoed back), never converted.
# x and horizon_lobe_distance are exact algebraic numbers as text ("sqrt(2)/2 + 1/2"): no Python
# number type holds them exactly, and a float would pass for the proved value.
_ECHO_KEYS = _RATIONAL_KEYS | frozenset({"input", "format", "theorem", "reason", "note", "x", "horizon_lobe_distance",
                        "inf_reason", "horizon_source", "orientation", "orientation_meaning", "time", "problem"})
_DOUBLE_DIGITS = 15  # up to here reals are floats
_FLOAT_SOURCE_DIGITS = 17  # the digits asked of the library when floats are wanted
# A double as the sweep's summary writes it (plain or scientific decimal).
_DECIMAL_TEXT = _re.compile(r"^-?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?$|^-?(?:inf|nan)$")


# The keys pair() fills on first access: the paper's asymptotics and the precision that decided
# the report with them (their guard bits raise it). They cost most of a call (the lobes' roots and
# their conversion) and most callers read r_res, theta_first, t_first.
_LAZY_PAIR_KEYS = ("r_res_asy", "r_res_asy_rel_error", "asymptotic", "bits")


class PairResult(Result):
    """What gyrores reports about one resonant pair: the fields of ``gyrores pair --json``.

    A Result (``r.r_res`` or ``r["r_res"]``), in the CLI's order; with ``enclosures=True`` also
    ``r.enclosures``, the same keys with Intervals (lobes under ``asymptotic_lobes``). The
    asymptotics (``asymptotic``, ``r_res_asy``, ``r_res_asy_rel_error``) and ``bits`` are
    computed on first access (of them, or of the whole dict: iteration, ``dict(r)``, ``==``,
    JSON, copies), with the values and key order an eager computation gives.
    """

    def _complete(self):
        """Fill the lazy keys (once): the report with the asymptotics, in the CLI's key order; and
        convert every value still held as the library's text."""
        fill = self.__dict__.pop("_lazy", None)
        if fill is not None:
            full = fill()
            have = dict(dict.items(self))
            dict.clear(self)
            for k, v in full.items():  # the returned objects of the eager keys stay the same objects
                dict.__setitem__(self, k, v if k in _LAZY_PAIR_KEYS or k not in have else have[k])
        pending = self.__dict__.pop("_pending", None)
        if pending is not None:
            real, keys = pending
            for k in keys:
                if dict.__contains__(self, k):
                    dict.__setitem__(self, k, _convert_item(k, dict.__getitem__(self, k), real))

    def __getitem__(self, key):
        if key in _LAZY_PAIR_KEYS:
            self._complete()
            return dict.__getitem__(self, key)
        # A value still held as text is converted on its first access (most callers read r_res,
        # theta_first, t_first of the fifteen or so reals).
        pending = self.__dict__.get("_pending")
        if pending is not None and key in pending[1]:
            pending[1].discard(key)
            value = dict.__getitem__(self, key)
            # The reals (most reads) straight to their conversion; the rest as _convert does.
            if type(value) is str and key not in _ECHO_KEYS:  # the reals (most reads), straight
                try:
                    value = pending[0](value)
                except UsageError:  # text that is not a real stays text, as _convert leaves it
                    pass
            else:
                value = _convert_item(key, value, pending[0])
            dict.__setitem__(self, key, value)
            return value
        return dict.__getitem__(self, key)

    def get(self, key, default=None):
        try:
            return self[key]
        except KeyError:
            return default

    def __contains__(self, key):
        return (key in _LAZY_PAIR_KEYS and "_lazy" in self.__dict__) or dict.__contains__(self, key)

    def __eq__(self, other):
        self._complete()
        if isinstance(other, PairResult):
            other._complete()
        return dict.__eq__(self, other)

    def __ne__(self, other):
        eq = self.__eq__(other)
        return eq if eq is NotImplemented else not eq

    __hash__ = None

    def __dir__(self):
        return list(object.__dir__(self)) + [k for k in dict.__iter__(self) if isinstance(k, str)] + [
            k for k in _LAZY_PAIR_KEYS if "_lazy" in self.__dict__]

    def to_dict(self, raw=False):
        """The fields as a plain dict; ``raw=True``: exactly the JSON of ``gyrores pair --json`` at
        the call's digits (reals as decimal strings; computed again when digits <= 15 or when the
        asymptotics were not read yet)."""
        if not raw:
            return dict(self)
        return self.__dict__["_raw_source"]()

    def __repr__(self):
        shown = ", ".join(f"{k}={_short(self[k])}" for k in ("r_res", "theta_first", "t_first", "n"))
        return (f"PairResult(tau={_short(self['tau'])}, sigma={_short(self['sigma'])}, {shown}, "
                f"minimisers={len(dict.__getitem__(self, 'minimisers'))}, "
                f"degenerate={self['degenerate']}, digits={self['digits']}, proved by {self['theorem']})")


def _completing(name):
    """dict's method `name`, after the lazy keys are filled (everything that shows all keys)."""
    method = getattr(dict, name)

    def call(self, *args, **kwargs):
        self._complete()
        return method(self, *args, **kwargs)

    call.__name__ = name
    call.__doc__ = method.__doc__
    return call


# __iter__ overridden also makes dict(r) and {**r} go through keys() (CPython takes the storage
# directly only when tp_iter is dict's); json.dumps calls items() on a dict subclass.
for _name in ("__iter__", "__len__", "__reversed__", "keys", "values", "items", "copy", "pop", "popitem",
              "setdefault", "update", "clear", "__setitem__", "__delitem__", "__or__", "__ror__", "__ior__"):
    setattr(PairResult, _name, _completing(_name))
del _name


def _short(value):
    """repr of a number, or its size where Python's int <-> text limit would refuse it."""
    if isinstance(value, int) and value.bit_length() > 4000 * 3:
        return f"<int of about {int(value.bit_length() * 0.30103) + 1} digits>"
    try:
        return repr(value)
    except ValueError:
        return f"<{type(value).__name__} too large to print>"


class CheckResult(Result):
    """The verdict of check(): ``holds`` (bool) and ``failure`` (the first claim that does not hold,
    "" when it holds). Its truth value is ``holds``."""

    def __bool__(self):
        return bool(self["holds"])


# Conversions ------------------------------------------------------------------------------------

def _convert(value, real, key=None):
    """A JSON-shaped value as Results and tuples, its real texts converted by `real`."""
    if isinstance(value, dict):
        return Result({k: _rational(v) if k in _RATIONAL_KEYS else v if k in _ECHO_KEYS else _convert(v, real, k)
                       for k, v in value.items()})
    if isinstance(value, list):
        return tuple(_convert(v, real, key) for v in value)
    if isinstance(value, str) and key not in _ECHO_KEYS and _numbers.is_real_text(value):
        return real(value)
    return value


def _convert_item(key, value, real):
    """The value of `key` of the library's JSON converted as _convert converts it in a dict."""
    return _rational(value) if key in _RATIONAL_KEYS else value if key in _ECHO_KEYS else _convert(value, real, key)


def _rational(value):
    """An exact rational of the library's JSON ("1/12", "17", "0.25") as a Fraction."""
    return _numbers.fraction_of_text(value) if isinstance(value, str) else value


def _real(digits):
    """The conversion of a real of `digits` digits: float, or mpf of as many digits."""
    if digits <= _DOUBLE_DIGITS:
        return _numbers.float_of_text
    return _functools.partial(_numbers.mpf_of_text, prec=_numbers.bits_of_digits(digits))


def _enclosure_path(path):
    """Where the enclosure of the real at `path` of a pair's JSON is, in its enclosures object."""
    if path[:2] == ("asymptotic", "lobes"):
        return ("asymptotic_lobes",) + path[2:]
    return path


def _real_paths(value, path=()):
    """The paths of the reals (floats, mpf) of a converted JSON value."""
    if isinstance(value, dict):
        for k, v in value.items():
            if k != "enclosures":
                yield from _real_paths(v, path + (k,))
    elif isinstance(value, tuple):
        for i, v in enumerate(value):
            yield from _real_paths(v, path + (i,))
    elif isinstance(value, float) or isinstance(value, _numbers.mpf_type):
        yield path, value


def _hull_with_values(intervals, out):
    """Widen each Interval to hold the returned rounding too: it then holds both the exact value
    and the number the caller got (a correct rounding may lie just outside the enclosure)."""
    for path, value in _real_paths(out):
        node = intervals
        epath = _enclosure_path(path)
        try:
            for p in epath[:-1]:
                node = node[p]
            iv = node[epath[-1]]
        except (KeyError, IndexError, TypeError):
            continue
        if isinstance(iv, Interval) and not iv.contains(value):
            widened = Interval(min(iv.lo, value), max(iv.hi, value))
            if isinstance(node, tuple):
                continue  # tuples are rebuilt below
            node[epath[-1]] = widened
    # Tuples (minimisers) are immutable: rebuild them.
    for key, seq in list(intervals.items()):
        if isinstance(seq, tuple) and key in out and isinstance(out[key], tuple):
            intervals[key] = tuple(iv if not isinstance(iv, Interval) or iv.contains(v)
                                   else Interval(min(iv.lo, v), max(iv.hi, v)) for iv, v in zip(seq, out[key]))
    return intervals


def _intervals(enclosures, digits):
    """The enclosures object as Intervals, rounded outward to floats or mpf of digits + 3 digits."""
    if digits <= _DOUBLE_DIGITS:
        def make(lo, hi):
            return Interval(_numbers.float_of_text(lo, "f"), _numbers.float_of_text(hi, "c"))
    else:
        bits = _numbers.bits_of_digits(digits + 3)

        def make(lo, hi):
            return Interval(_numbers.mpf_of_text(lo, bits, "f"), _numbers.mpf_of_text(hi, bits, "c"))

    def walk(value):
        if isinstance(value, dict):
            return Result({k: walk(v) for k, v in value.items()})
        if isinstance(value, list) and len(value) == 2 and all(isinstance(t, str) for t in value):
            return make(*value)
        if isinstance(value, list):
            return tuple(walk(v) for v in value)
        return value

    return walk(enclosures)


def _pair_arguments(tau, sigma, digits, qdot0, enclosures, function):
    """(tau, sigma, digits, qdot0 text, enclosures) checked; plain ints take the short way."""
    t = tau if type(tau) is int else _args.integer(tau, function, "tau")
    s = sigma if type(sigma) is int else _args.integer(sigma, function, "sigma")
    d = digits if type(digits) is int and 1 <= digits <= 10000 else _args.bounded(digits, function, "digits", 1, 10000)
    q = "1" if type(qdot0) is int and qdot0 == 1 else _args.rational(qdot0, function, "qdot0")
    return t, s, d, q, _args.flag(enclosures, function, "enclosures")


def _proved_pair(t, s, d, q, enclosures, function, asymptotics=True):
    """The JSON of `gyrores pair` converted: floats decided by enclosures, or mpf (arguments as
    _pair_arguments gives them). Without the asymptotics (asymptotics=False) its `asymptotic`,
    `r_res_asy`, `r_res_asy_rel_error` and `bits` are not the CLI's; the raw source computes them."""
    if d > _DOUBLE_DIGITS:
        raw = _gyrores._pair(t, s, d, q, enclosures, asymptotics)
        out = _convert({k: v for k, v in raw.items() if k != "enclosures"}, _real(d))
        if enclosures:
            out["enclosures"] = _hull_with_values(_intervals(raw["enclosures"], d), out)
        if not asymptotics:
            return out, lambda: _gyrores._pair(t, s, d, q, enclosures)
        return out, lambda: _copy.deepcopy(raw)
    # Floats decided in the compiled module, by the report's own enclosures.
    raw = _prefixed(function, _gyrores._pair_doubles, t, s, d, q, asymptotics, enclosures)
    out = _convert({k: v for k, v in raw.items() if k != "enclosures"}, None)
    if enclosures:
        out["enclosures"] = _hull_with_values(_intervals(raw["enclosures"], d), out)
    return out, lambda: _gyrores._pair(t, s, d, q, enclosures)


# The functions --------------------------------------------------------------------------------

def pair(tau, sigma, digits=17, qdot0=1, enclosures=False):
    """Inscribed radius, minimisers and first-hit time of the resonant pair (tau, sigma).

    tau, sigma: integers of any size (anything with __index__), coprime, tau > sigma >= 1.
    digits: 1..10000; every real is proved: for digits <= 15 a float, the correctly rounded
    double of the exact value; beyond, a Real (an mpmath.mpf that prints all its digits), the
    correct rounding to `digits` digits.
    qdot0: the impulse amplitude > 0 (a rational: int, float, Fraction, Decimal, mpf, "1/4").
    enclosures: also ``r.enclosures``, an Interval holding each real (outward).
    Returns a PairResult; raises UsageError / ComputeError; Ctrl-C stops it. The paper's
    asymptotics (``asymptotic``, ``r_res_asy``, ``r_res_asy_rel_error``) and ``bits`` are computed
    when first read (at once with ``enclosures=True``), with the same values.
    """
    t, s, d, q, enclosures = _pair_arguments(tau, sigma, digits, qdot0, enclosures, "pair")
    if enclosures:
        # Eager: the enclosures of every real depend on the precision, which the asymptotics'
        # guard bits raise; with them asked for, the report is computed once, as the CLI's.
        out, raw = _proved_pair(t, s, d, q, True, "pair")
        result = PairResult(out)
        result.__dict__["_raw_source"] = raw
        return result
    if d > _DOUBLE_DIGITS:
        # The library's dict as it is; each value converted on first access (PairResult).
        raw = _gyrores._pair(t, s, d, q, False, False)
        for key in _LAZY_PAIR_KEYS:
            raw.pop(key, None)
        result = PairResult(raw)
        result.__dict__["_pending"] = (_real(d), set(raw))
        result.__dict__["_raw_source"] = lambda: _gyrores._pair(t, s, d, q, False)
    else:
        # Floats decided in the compiled module, by the report's own enclosures.
        out = _prefixed("pair", _gyrores._pair_doubles, t, s, d, q, False, False)
        for key in _LAZY_PAIR_KEYS:
            out.pop(key, None)
        out["minimisers"] = tuple(out["minimisers"])
        result = PairResult(out)
        result.__dict__["_raw_source"] = lambda: _gyrores._pair(t, s, d, q, False)
    result.__dict__["_lazy"] = lambda: _proved_pair(t, s, d, q, False, "pair")[0]
    return result


def asymptotics(tau, sigma, digits=17):
    """The paper's asymptotics of the pair (the ``asymptotic`` object of ``gyrores pair --json``).

    A Result: applicable, reason, lobes (per lobe k, m, s, u_asy, theta_asy, the exact lobe root
    theta_c, error, bound pi^3 x^2/a, ratio, holds_global_min), r_res_asy (the x -> 0 limit form)
    and r_res_asy_rel_error (None when not applicable), digits; qdot0 = 1. Reals as in pair().
    """
    out, _ = _proved_pair(*_pair_arguments(tau, sigma, digits, 1, False, "asymptotics"), "asymptotics")
    d = out["digits"]
    result = Result(out["asymptotic"])
    for key in ("r_res_asy", "r_res_asy_rel_error"):
        result[key] = out.get(key)
    result["digits"] = d
    return result


def certify(tau, sigma, digits=30):
    """An interval certificate of r_res, theta_first and t_first of (tau, sigma), qdot0 = 1.

    Returns the dict of ``gyrores certify`` ("gyrores-certificate/2", docs/formats.md): a data
    format, so its reals stay the exact decimal strings the checker reads (json.dump it for
    ``gyrores check``, or pass it to check()). Raises UsageError / ComputeError.
    """
    t = _args.integer(tau, "certify", "tau")
    s = _args.integer(sigma, "certify", "sigma")
    d = _args.bounded(digits, "certify", "digits", 1, 10000)
    return _gyrores._certify(t, s, d)


# What `gyrores check` reads of a certificate file at most (io/files.hpp, certificate_read_limit).
_CERTIFICATE_READ_LIMIT = 4 << 20


def _too_large(what):
    return UsageError(f"check(): {what} is larger than {_CERTIFICATE_READ_LIMIT} bytes (the limit for a certificate)")


def _read_certificate(path):
    """The bytes of a certificate file, as `gyrores check` reads it: at most 4 MiB (a device such
    as /dev/zero is refused, never read to its end); a FIFO, socket or device is refused at once
    (opened without blocking: no writer is waited for)."""
    name = _os.fspath(path)
    if isinstance(name, bytes):
        name = _os.fsdecode(name)
    try:
        fd = _os.open(name, _os.O_RDONLY | getattr(_os, "O_NONBLOCK", 0) | getattr(_os, "O_CLOEXEC", 0))
    except OSError as e:
        raise UsageError(f"check(): cannot read certificate '{name}': {e.strerror}") from None
    try:
        mode = _os.fstat(fd)
        if _stat.S_ISDIR(mode.st_mode):
            raise UsageError(f"check(): cannot read certificate '{name}': it is a directory")
        if not _stat.S_ISREG(mode.st_mode):
            kind = ("a FIFO" if _stat.S_ISFIFO(mode.st_mode) else "a socket" if _stat.S_ISSOCK(mode.st_mode)
                    else "a device" if _stat.S_ISCHR(mode.st_mode) or _stat.S_ISBLK(mode.st_mode) else "special")
            raise UsageError(f"check(): cannot read certificate '{name}': it is {kind}, not a regular file")
        if mode.st_size > _CERTIFICATE_READ_LIMIT:
            raise _too_large(f"'{name}'")
        chunks, size = [], 0
        while True:  # a file growing while read is held to the same cap
            try:
                chunk = _os.read(fd, 1 << 16)
            except OSError as e:
                raise UsageError(f"check(): cannot read certificate '{name}': {e.strerror}") from None
            if not chunk:
                return b"".join(chunks)
            size += len(chunk)
            if size > _CERTIFICATE_READ_LIMIT:
                raise _too_large(f"'{name}'")
            chunks.append(chunk)
    finally:
        _os.close(fd)


def check(cert):
    """Re-prove a certificate independently; returns a CheckResult {holds, failure}.

    cert: a certificate of any format `gyrores check` reads (``gyrores-certificate/2`` of
    certify(), ``gyrores-coupling-certificate/1`` and ``gyrores-band-certificate/1`` of
    ``gyrores coupling --certificate``; docs/formats.md) as a dict (json.load of the file), its
    JSON text (str or bytes), or the path of the file (str or os.PathLike; a regular file of at
    most 4 MiB, as the CLI reads). ``failure`` names the first claim or fact that does not hold
    ("" when it holds); ``bool(result)`` is ``holds``. Malformed content, a file that cannot be
    read (missing, a directory, a FIFO or device, larger than 4 MiB), and a certificate of the
    retired format "gyrores-certificate/1" raise UsageError at once (``gyrores check`` exits 2
    there).
    """
    if isinstance(cert, dict):
        # Written by the library (integers of any size, whatever sys.get_int_max_str_digits is).
        holds, failure = _prefixed("check", _gyrores._check_object, cert)
    else:
        if isinstance(cert, (bytes, bytearray)) and cert.lstrip().startswith(b"{"):
            text = bytes(cert)
        elif isinstance(cert, str) and cert.lstrip().startswith("{"):
            text = cert.encode("utf-8", "surrogatepass")
        elif isinstance(cert, (str, bytes, _os.PathLike)):
            text = _read_certificate(cert)
        else:
            raise UsageError(f"check(): cert must be a dict, JSON text or a path, got {type(cert).__name__}")
        if len(text) > _CERTIFICATE_READ_LIMIT:
            raise _too_large("the certificate text")
        holds, failure = _prefixed("check", _gyrores._check_text, text)
    return CheckResult(holds=bool(holds), failure=failure)


def _library_digits(d):
    """The digits asked of the library: 17 when floats are wanted (then rounded to the double)."""
    return max(d, _FLOAT_SOURCE_DIGITS) if d <= _DOUBLE_DIGITS else d


def design(problem, tmax, beat=None, max_order=200, exclude_low=0, delta=None, proxy=False, candidates=5,
           digits=10, tolerance=None, level=None, horizon=None):
    """Choose a resonant pair: "absorb" (min r_res) or "contain" (max r_res) with time <= tmax.

    tmax, beat: rationals; beat: (tau+sigma)/(tau-sigma) >= beat; max_order 3..5000;
    exclude_low: drop tau + sigma <= exclude_low; delta: only tau - sigma = delta; proxy: use the
    paper's proxy pi/|n| instead of the exact first-hit time; digits 1..1000.
    tolerance: the coupling is realised only within n (1 -+ P%) (text "P%", or a number, the
    fraction: 0.01 is 1%); level (needed with it): E, an energy or a percentage of H_q(0) = 1/2
    ("1%"); horizon (contain only, default tmax). Then the ranked pairs are walked, best first,
    and each one's band is proved (band-theorem/1): absorb needs H_q <= E before tmax for every n
    of the band (its absorption guarantee <= E), contain H_q >= E on [0, horizon] (its
    containment guarantee >= E). ``tolerance`` is then the CLI's object: ``checked`` (tau, sigma,
    band (n1, n2) Fractions, the guarantee's enclosure ``absorption`` or ``containment`` an
    Interval, at_n2 a Fraction, verdict "meets", "fails" or "undecided"), ``chosen`` (the first
    pair that meets it, {tau, sigma}, or None: no pair walked meets it), theorem, ``percent`` (as
    given) and ``level`` (the energy E, a Fraction). Needs the exact time (not proxy).
    Returns the Result of ``gyrores design --json``; ComputeError when no pair is feasible.
    """
    f = "design"
    d = _args.bounded(digits, f, "digits", 1, 1000)
    raw = _prefixed(f, _gyrores._design, _args.choice(problem, f, "problem", ("absorb", "contain")),
                    _args.rational(tmax, f, "tmax"), None if beat is None else _args.rational(beat, f, "beat"),
                    _args.bounded(max_order, f, "max_order", 3, 5000),
                    _args.bounded(exclude_low, f, "exclude_low", 0, 2**62),
                    None if delta is None else _args.bounded(delta, f, "delta", 1, 2**62),
                    _args.flag(proxy, f, "proxy"), _args.bounded(candidates, f, "candidates", 0, 1000),
                    _library_digits(d), _tolerance_text(tolerance, f), _level(level, f, "level"),
                    None if horizon is None else _args.rational(horizon, f, "horizon"))
    raw["digits"] = d
    tolerance_raw = raw.pop("tolerance", None)
    out = _convert(raw, _real(d))
    if tolerance_raw is not None:
        out["tolerance"] = _design_tolerance(tolerance_raw, d)
    return out


def _energy(text):
    """A level as the library reads it, an energy ("1/200", "1e-6") or a percentage of
    H_q(0) = 1/2 ("1%"), as the exact energy (a Fraction)."""
    if text.endswith("%"):
        return _numbers.fraction_of_text(text[:-1].strip()) / 200
    return _numbers.fraction_of_text(text)


def _design_tolerance(raw, digits):
    """design()'s "tolerance" object converted: bands and at_n2 Fractions, each guarantee's
    enclosure an Interval of the call's type, the level the energy E; keys in the CLI's order."""
    def checked(c):
        out = Result(c)
        out["band"] = tuple(_numbers.fraction_of_text(t) for t in c["band"])
        out["at_n2"] = _numbers.fraction_of_text(c["at_n2"])
        for key in ("absorption", "containment"):
            if key in c:
                out[key] = _intervals(c[key], digits)
        return out

    out = Result(raw)
    out["checked"] = tuple(checked(c) for c in raw["checked"])
    out["chosen"] = None if raw["chosen"] is None else Result(raw["chosen"])
    out["level"] = _energy(raw["level"])
    return out


def pareto(max_order, orientation="absorb", proxy=False, exclude_degenerate=False, beat=None, exclude_low=0,
           digits=10):
    """The Pareto front of (r_res, time) over the resonant pairs with tau + sigma <= max_order.

    orientation "absorb" (lower r_res and time better) or "contain" (higher r_res, lower time);
    proxy: time = pi/|n| instead of t_first. Returns the Result of ``gyrores pareto --json``
    without its file keys (csv, plot).
    """
    f = "pareto"
    d = _args.bounded(digits, f, "digits", 1, 1000)
    raw = _gyrores._pareto(_args.bounded(max_order, f, "max_order", 3, 5000),
                           _args.choice(orientation, f, "orientation", ("absorb", "contain")),
                           _args.flag(proxy, f, "proxy"), _args.flag(exclude_degenerate, f, "exclude_degenerate"),
                           None if beat is None else _args.rational(beat, f, "beat"),
                           _args.bounded(exclude_low, f, "exclude_low", 0, 2**62), _library_digits(d))
    raw["digits"] = d
    return _convert(raw, _real(d))


def _prefixed(function, call, *args):
    """call(*args), its UsageError naming `function` (the library names only the argument)."""
    try:
        return call(*args)
    except UsageError as e:
        raise UsageError(f"{function}(): {e}") from None


def _level(below, function, name="below"):
    """The level E as text: an energy (a rational) or a percentage of H_q(0) = 1/2 ("1%")."""
    if below is None:
        return None
    if isinstance(below, str):
        return below.strip()
    return _args.rational(below, function, name)


def _band_text(band, function):
    """A band (n1, n2) or "N1:N2" as the library's text "N1:N2"."""
    if band is None:
        return None
    if isinstance(band, str):
        return band.strip()
    if isinstance(band, (tuple, list)) and len(band) == 2:
        return ":".join(_args.rational(v, function, f"band[{i}]") for i, v in enumerate(band))
    raise UsageError(f"{function}(): band must be (n1, n2) or text 'N1:N2', got {_args._describe(band)}")


def _tolerance_text(tolerance, function):
    """A tolerance as the library's text "P%": text as given ("1%"), a number as a fraction of n
    (Fraction(1, 100), 0.01, Decimal("0.01") are 1%)."""
    if tolerance is None:
        return None
    if isinstance(tolerance, str):
        return tolerance.strip()
    p = _numbers.fraction_of_text(_args.rational(tolerance, function, "tolerance")) * 100
    return (_numbers.int_text(p.numerator) if p.denominator == 1
            else f"{_numbers.int_text(p.numerator)}/{_numbers.int_text(p.denominator)}") + "%"


def _band_interval(texts, value, digits):
    """An enclosure [lo, hi] of the band's JSON (decimal texts rounded outward) as an Interval of
    the call's type, widened to hold the returned value (a correct rounding may lie just outside)."""
    iv = _intervals(texts, digits)
    if value is not None and not iv.contains(value):
        iv = Interval(min(iv.lo, value), max(iv.hi, value))
    return iv


def _band_part(raw, precision, value_key):
    """One part of the band (a guarantee, or the first time below) converted: its reals of the
    call's type (mpf of `precision` digits beyond 15: see _band), its enclosure an Interval
    holding the exact value and the value at `value_key`, the coupling where it is attained
    ("at": n2 a Fraction, x exact text, pair ints), in the CLI's key order. None stays None (a
    part not proved: interrupted before it started, or no level asked)."""
    if raw is None:
        return None
    out = _convert({k: v for k, v in raw.items() if k != "enclosure"}, _real(precision))
    at = out.get("at")
    if at is not None and at.get("t_below") == "":  # the JSON's "" for a coupling that never gets below E
        at["t_below"] = None
    enclosure = raw["enclosure"]
    out["enclosure"] = None if enclosure is None else _band_interval(enclosure, out[value_key], precision)
    return Result((k, out[k]) for k in raw)


def _band(raw, digits, band_digits):
    """The "band" object of the CLI's JSON (format gyrores-band/2) converted, with the CLI's keys:
    n1, n2 (the band's couplings) Fractions, horizon as coupling() gives it back, absorption and
    containment (the highest and the lowest minimum of H_q over [0, T] across the band) and
    first_below (the latest first time H_q <= E) by _band_part. Reals are of the call's type
    (`digits`), holding all of the `band_digits` digits the library rounded them to when mpf."""
    precision = digits if digits <= _DOUBLE_DIGITS else max(digits, band_digits)
    out = Result(format=raw["format"], theorem=raw["theorem"], n1=_numbers.fraction_of_text(raw["n1"]),
                 n2=_numbers.fraction_of_text(raw["n2"]), horizon=_horizon_value(raw["horizon"]), digits=band_digits,
                 interrupted=raw["interrupted"])
    out["absorption"] = _band_part(raw["absorption"], precision, "h_min")
    out["containment"] = _band_part(raw["containment"], precision, "h_min")
    out["first_below"] = _band_part(raw["first_below"], precision, "t_below")
    return out


def _horizon_value(text):
    """The horizon as given back: a Fraction, or the text of a multiple of pi ("100pi")."""
    try:
        return _numbers.fraction_of_text(text)
    except ValueError:
        return text


def _plant_texts(plant, function):
    """The plant's (mass, stiffness, gyro, velocity) as exact texts: from a Result of plant(), a
    mapping with those keys, or a 4-tuple."""
    keys = ("mass", "stiffness", "gyro", "velocity")
    if hasattr(plant, "keys"):
        missing = [k for k in keys if k not in plant]
        if missing:
            raise UsageError(f"{function}(): plant needs {', '.join(keys)}: {missing[0]} is missing")
        values = [plant[k] for k in keys]
    elif isinstance(plant, (tuple, list)) and len(plant) == 4:
        values = list(plant)
    else:
        raise UsageError(f"{function}(): plant must be plant(...), a mapping or (mass, stiffness, gyro, velocity), "
                         f"got {_args._describe(plant)}")
    return tuple(_args.rational(v, function, k) for k, v in zip(keys, values))


def _plant_result(raw, d):
    """The library's "plant" object: inputs, n2, energy_scale and h_q0 Fractions; omega0, n and
    time_scale reals of `d` digits; units the SI units as text."""
    real = _real(d)
    out = Result()
    for k, v in raw.items():
        if k in ("omega0", "n", "time_scale"):
            out[k] = real(v)
        elif k == "units":
            out[k] = dict(v)
        else:
            out[k] = _numbers.fraction_of_text(v)
    return out


def plant(mass, stiffness, gyro, velocity, digits=17):
    """A physical plant in the model's terms (docs/units.md): two equal-frequency modes with mass m
    (kg), stiffness k (N/m) and gyroscopic coefficient g (N s/m), m q'' + g z' + k q = 0,
    m z'' - g q' + k z = 0, struck so that q'(0) = V (m/s; an impulse J gives V = J/m).

    Each input exact (int, Fraction, Decimal, text "0.5"; a float is its exact binary value), > 0.
    Returns a Result: mass, stiffness, gyro, velocity (Fractions); omega0 = sqrt(k/m) (rad/s);
    n = g/sqrt(m k) and n2 = g^2/(m k) (a Fraction: give it to coupling(n2=...)); time_scale =
    1/omega0 = sqrt(m/k) (s: a model time t is t * time_scale seconds); energy_scale = m V^2 (J:
    the energy (m q'^2 + k q^2)/2 kept in q is energy_scale * H_q of the unit impulse); h_q0 =
    m V^2/2 (J); units. Reals are correct roundings of proved enclosures (floats for digits <= 15).
    Give it to coupling(plant=...) for the answers in joules and seconds.
    """
    f = "plant"
    d = _args.bounded(digits, f, "digits", 1, 1000)
    texts = _plant_texts((mass, stiffness, gyro, velocity), f)
    return _plant_result(_prefixed(f, _gyrores._plant, texts, _library_digits(d)), d)


def coupling(n=None, n2=None, horizon=None, below=None, convergents=8, digits=12, band=None, tolerance=None,
             band_digits=None, qdot0=1, pair=None, plant=None, horizon_s=None):
    """Any coupling n (or its square n2, e.g. "1/12"): resonance test, min of H_q over [0, T],
    the first time H_q <= E, the infimum over all time, convergents (``gyrores coupling --json``);
    and the guarantees of that minimum over a band of couplings (``--band``, ``--tolerance``).

    Exactly one of n, n2 (rationals), or neither with a band. horizon: T >= 0 as the CLI takes
    it: a number, a decimal, scientific or fraction text ("1e100", "1/3"), or a multiple of pi
    ("100pi"); the minimum of H_q over [0, T] and its first time are proved by the horizon theorem
    in O(log T). below: a level E, an energy (a rational) or a percentage of H_q(0) = 1/2 ("1%"):
    ``t_below`` (None when never, ``below.reason`` says why). convergents: 0..60; digits 1..1000.
    Returns a Result with the CLI's keys: reals as in design() (floats for digits <= 15, mpf
    beyond); ``enclosures`` Intervals (h_min_horizon, t_min_horizon, r_min_horizon, t_below);
    integers (horizon_lobe, cut_lobe, discriminant) exact ints; ``n2``, ``below.level`` and
    ``horizon`` Fractions (``horizon`` stays text when it is a multiple of pi); ``x`` and
    ``horizon_lobe_distance`` exact algebraic numbers as text (e.g. "sqrt(2)/2 + 1/2").

    band: (n1, n2) (rationals) or text "N1:N2", 0 < n1 < n2; or tolerance around n (or
    sqrt(n2)): text "P%" (0 < P < 100) or a number, the fraction of |n| (Fraction(1, 100) is
    1%): the band |n| (1 -+ P%); when n = sqrt(n2) is irrational, rational ends (30 digits)
    enclosing it outward, whose guarantees hold for the band asked. Adds ``band``, the CLI's "band" object (band-theorem/1) with its keys: n1, n2
    (Fractions), horizon, digits, interrupted; ``absorption``, the absorption guarantee (the
    highest minimum of H_q over [0, T] across the band: every coupling of the band drains H_q at
    least that low) and ``containment``, the containment guarantee (the lowest minimum: every
    coupling keeps at least that much; 0 exactly once T passes the zero of a degenerate pair
    in the band), each with ``h_min`` (the correct rounding to band_digits digits, None when not
    settled), ``enclosure`` (an Interval holding the exact guarantee and h_min), ``settled``,
    ``interrupted``, ``reason`` (why not settled, else None), ``at`` (the coupling where it is
    attained: its n2 a Fraction, x exact text, pair (tau, sigma) or None, and its own h_min, lobe,
    at_horizon_end, t_min), ``intervals`` and ``couplings`` (the proof's work). With below, also
    ``first_below``: the latest first time H_q <= E across the band (level a Fraction, never,
    reason, t_below, enclosure, settled, interrupted, at with its own t_below, intervals,
    couplings), else None. band_digits: 1..10000, default digits (floats then come from 17
    digits, as the coupling's own values). A band alone (no n, n2) gives a Result {horizon,
    theorem, band, digits}. Ctrl-C stops the computation (KeyboardInterrupt: a band's bracket
    reached so far is not returned).

    pair: (tau, sigma), the coupling n^2 = (tau - sigma)^2/(tau sigma) of a resonant pair, instead
    of n or n2 (e.g. with tolerance="1%"). qdot0: the impulse q'(0) > 0 (exact; default 1): energies
    (h_min_horizon, the pair's and the band's) scale by qdot0^2, radii by qdot0, times not; an
    absolute below is an energy at this qdot0 (a percentage a share of H_q(0) = qdot0^2/2); adds
    ``qdot0`` (a Fraction) when not 1, and ``below.level_given`` (``below.level`` is then the unit
    impulse's level). horizon: default 100 (model time t omega0).

    plant: a physical plant (plant(...), or mass, stiffness, gyro, velocity), instead of n, n2, pair
    and qdot0 (with tolerance, not band): the horizon values (h_min_horizon in J, t_min_horizon and t_below in s,
    r_min_horizon the amplitude in m) and t_min_paper (s) in its units, the pair's values in model
    units; horizon_s: the horizon in seconds (else horizon in model time). Adds ``plant`` (as
    plant() gives it), ``horizon_s`` and ``horizon_exact`` (False when T = horizon_s omega0 is
    irrational: the minimum is then proved over [0, T'], T' its upper rounding to digits + 20
    significant digits, and ``horizon`` is T'). tolerance with a plant: the band of the plant's
    n = g/sqrt(m k) (the same tolerance on g), its guarantees in J and its times (the first time
    below, each ``at``'s t_min and t_below) in s; the band's n1, n2 and horizon stay model units.
    """
    f = "coupling"
    d = _args.bounded(digits, f, "digits", 1, 1000)
    bd = d if band_digits is None else _args.bounded(band_digits, f, "band_digits", 1, 10000)
    if pair is not None and not (isinstance(pair, (tuple, list)) and len(pair) == 2):
        raise UsageError(f"{f}(): pair must be (tau, sigma), got {_args._describe(pair)}")
    raw = _prefixed(f, _gyrores._coupling, None if n is None else _args.rational(n, f, "n"),
                    None if n2 is None else _args.rational(n2, f, "n2"),
                    None if horizon is None else _args.rational(horizon, f, "horizon"),
                    _level(below, f), _args.bounded(convergents, f, "convergents", 0, 60), _library_digits(d),
                    _band_text(band, f), _tolerance_text(tolerance, f),
                    0 if band_digits is None else bd,  # 0: the library's digits (17 for floats)
                    _args.rational(qdot0, f, "qdot0"),
                    None if pair is None else tuple(_args.integer(v, f, "pair") for v in pair),
                    None if plant is None else _plant_texts(plant, f),
                    None if horizon_s is None else _args.rational(horizon_s, f, "horizon_s"))
    raw["digits"] = d
    order = list(raw)  # the CLI's order of the keys
    extra = {}
    for k in ("qdot0", "plant", "horizon_s", "horizon_exact"):
        if k in raw:
            v = raw.pop(k)
            extra[k] = (_numbers.fraction_of_text(v) if k == "qdot0" else _plant_result(v, d) if k == "plant" else v)
    level_given = raw["below"].pop("level_given", None) if isinstance(raw.get("below"), dict) else None
    band_raw = raw.pop("band", None)
    horizon_text = raw.pop("horizon")
    enclosures = raw.pop("enclosures", None)
    out = _convert(raw, _real(d))
    out["horizon"] = _horizon_value(horizon_text)
    if enclosures is not None:
        out["enclosures"] = _hull_with_values(_intervals(enclosures, d), out)
    if band_raw is not None:
        out["band"] = _band(band_raw, d, bd)
    out.update(extra)
    if level_given is not None:
        out["below"]["level_given"] = level_given
    return Result((k, out[k]) for k in order)


def _input_texts(values, function, name):
    """Two NumPy arrays (any shape) of `values`: their exact texts (floats as their exact binary
    values: the float 0.1 is 3602879701896397/36028797018963968; strings as the CLI reads them;
    other numbers as in coupling()) and their doubles for the table (_double_of_text). A value
    the table's float64 column cannot hold is refused (UsageError naming it), before any work."""
    import numpy as np
    if isinstance(values, np.ndarray):
        arr = values
    elif isinstance(values, (str, bytes)) or not hasattr(values, "__iter__"):
        arr = np.empty((), dtype=object)
        arr[()] = values
    else:
        try:
            arr = np.array(list(values), dtype=object)  # nested lists: a grid
        except ValueError:
            raise UsageError(f"{function}(): {name} is ragged (nested sequences of different lengths)") from None
    texts = np.empty(arr.shape, dtype=object)
    doubles = np.empty(arr.shape, dtype=np.float64)
    for i, (index, v) in enumerate(zip(np.ndindex(arr.shape), arr.flat)):
        where = f"{name}[{i}]" if arr.ndim else name
        if isinstance(v, (bool, np.bool_)):
            raise UsageError(f"{function}(): {where} must be a number, got a bool {v!r}")
        if isinstance(v, (float, np.floating)):
            if not np.isfinite(v):
                raise UsageError(f"{function}(): {where} must be finite, got {v}")
            p, q = v.as_integer_ratio()
            text = f"{p}/{q}"
        elif isinstance(v, str):
            text = v.strip()
        elif isinstance(v, bytes):
            raise UsageError(f"{function}(): {where} must be a number or text, got bytes")
        else:
            text = _args.rational(v, function, where)
        texts[index] = text
        doubles[index] = _double_of_text(text, function, where)
    return texts, doubles


def _double_of_text(text, function, where):
    """The double of an exact input text: a rational (correctly rounded), or a multiple of pi;
    NaN for text the library will refuse (it names the argument). UsageError when the value lies
    beyond the doubles (overflow) or is nonzero and rounds to 0 (underflow)."""
    pi = text.endswith("pi")
    try:
        q = _numbers.fraction_of_text(text[:-2].rstrip(" *") if pi else text)
    except (ValueError, ZeroDivisionError):
        return float("nan")
    try:
        if pi:
            import mpmath
            with mpmath.workdps(40):
                x = float(mpmath.mpf(q.numerator) / q.denominator * mpmath.pi)
        else:
            x = float(q)  # int / int: correctly rounded, OverflowError beyond the doubles
        overflow = x in (float("inf"), float("-inf"))
    except OverflowError:
        overflow = True
    shown = text if len(text) <= 40 else text[:37] + "..."
    if overflow:
        raise UsageError(f"{function}(): {where} = {shown} is beyond the largest double (1.8e308), which the "
                         f"table's float64 column holds: use coupling() for it")
    if x == 0 and q != 0:
        raise UsageError(f"{function}(): {where} = {shown} is below the smallest double (4.9e-324), which the "
                         f"table's float64 column holds: use coupling() for it")
    return x


def couplings(n=None, n2=None, horizon=100, below=None, progress=None):
    """coupling() over arrays: the minimum of H_q over [0, T] and the first time H_q <= E for
    every (n, T) in one call, as a NumPy structured array.

    Exactly one of n, n2: a number or a NumPy array / iterable of numbers; horizon likewise
    (numbers, or texts as coupling() takes them: "1e100", "100pi"); they are broadcast together
    (NumPy rules) and the table has the broadcast shape. Floats (and NumPy floats) are taken as
    their exact binary values (0.1 is 3602879701896397/2^55, not 1/10): give text ("0.1") for a
    decimal. below: one level for all (as in coupling()). Fields, float64, each the correctly
    rounded double of the proved value (decided from its enclosure, more digits when needed): n
    (or n2), horizon (T; for a multiple of pi its nearest double), h_min_horizon, t_min_horizon,
    t_below (NaN without below or when never); min_at_horizon_end and resonant (bool). The loop
    runs in C++ without the GIL; Ctrl-C stops it between elements or inside one
    (KeyboardInterrupt). progress, if given, is called as progress(done, total) every 64
    elements and at the end, from a worker thread; an exception it raises stops the loop.
    """
    import numpy as np
    f = "couplings"
    if (n is None) == (n2 is None):
        raise UsageError(f"{f}(): give exactly one of n (the coupling) or n2 (its square)")
    if progress is not None and not callable(progress):
        raise UsageError(f"{f}(): progress must be callable, got {type(progress).__name__}")
    name = "n" if n2 is None else "n2"
    coupling_texts, coupling_doubles = _input_texts(n if n2 is None else n2, f, name)
    horizon_texts, horizon_doubles = _input_texts(horizon, f, "horizon")
    try:
        cb, hb, cd, hd = np.broadcast_arrays(coupling_texts, horizon_texts, coupling_doubles, horizon_doubles)
    except ValueError:
        raise UsageError(f"{f}(): {name} of shape {coupling_texts.shape} and horizon of shape {horizon_texts.shape} "
                         "do not broadcast") from None
    cs, hs = [str(t) for t in cb.flat], [str(t) for t in hb.flat]
    h_min, t_min, at_end, t_below, resonant = _prefixed(f, _gyrores._couplings, cs, n2 is not None, hs,
                                                        _level(below, f), progress)
    table = np.empty(cb.shape, dtype=[(name, np.float64), ("horizon", np.float64), ("h_min_horizon", np.float64),
                                      ("t_min_horizon", np.float64), ("min_at_horizon_end", bool),
                                      ("t_below", np.float64), ("resonant", bool)])
    flat = table.reshape(-1)
    flat[name] = cd.reshape(-1)
    flat["horizon"] = hd.reshape(-1)
    flat["h_min_horizon"] = h_min
    flat["t_min_horizon"] = t_min
    flat["min_at_horizon_end"] = at_end
    flat["t_below"] = t_below
    flat["resonant"] = resonant
    return table


def enumerate_pairs(max_order, min_order=3):
    """A lazy iterator over the resonant pairs (tau, sigma) with min_order <= tau + sigma <= max_order.

    Coprime tau > sigma >= 1, by order ascending then sigma ascending; nothing is materialised.
    """
    f = "enumerate_pairs"
    return _gyrores._enumerate_pairs(_args.bounded(max_order, f, "max_order", 0, 2**40),
                                     _args.bounded(min_order, f, "min_order", 0, 2**40))


def _row_table(count):
    """An empty table of `count` sweep rows (the library's row fields), notes "" (one character wide)."""
    import numpy as np
    table = np.empty(count, dtype=np.dtype(_gyrores._row_fields()))
    table["note"] = ""
    return table


def _with_notes(table, notes):
    """The table with its rows' notes [(index, text)]: the note field widened to the longest
    (rare: rows that failed); the table itself when there is none."""
    if not notes:
        return table
    import numpy as np
    width = max(len(text) for _, text in notes)
    wide = np.empty(len(table), dtype=[(n, f if n != "note" else f"<U{width}") for n, f in _gyrores._row_fields()])
    for name in table.dtype.names:
        wide[name] = table[name]
    for i, text in notes:
        wide["note"][i] = text
    return wide


# The memory the rows of sweep() take at their peak per pair (the table's record, written in place,
# and the library's rows of the blocks not yet taken), and what sweep() accepts without
# allow_large=True.
_SWEEP_ROW_BYTES = 160
_SWEEP_ROWS_LIMIT = 4 * 2**30


def sweep(max_order, min_order=3, rows=True, progress=None, checks="default", threads=0, examples=5,
          allow_large=False):
    """Check the paper's claims on every pair with min_order <= tau + sigma <= max_order (in double).

    Returns (rows, summary): rows a NumPy structured array, one record per pair in enumeration
    order, with the columns of ``gyrores sweep --out`` (not applicable: NaN for reals, -1 for
    flags; check_* columns 1 pass, 0 fail, -1 not run; failed bool; note text, "" for most), or None when
    rows=False; summary the Result of ``gyrores sweep --json``. The work runs on `threads` workers
    (0: every core) with the GIL released; progress, if given, is called as progress(done, total)
    after every block of pairs (it may call gyrores itself), and an exception it raises (or
    Ctrl-C) stops the sweep. checks: "default" or "all" (the paper's four claims) or a
    comma-separated list (degeneracy, paper-node, asy-bound, structure). The rows take about 160
    bytes a pair at their peak: beyond 4 GiB (about 27 million pairs, max_order 13400) sweep()
    refuses with the estimate unless allow_large=True (rows=False needs no such memory).
    """
    f = "sweep"
    if progress is not None and not callable(progress):
        raise UsageError(f"sweep(): progress must be callable, got {type(progress).__name__}")
    if not isinstance(checks, str):
        raise UsageError(f"sweep(): checks must be text, got {type(checks).__name__}")
    top, bottom = _args.bounded(max_order, f, "max_order", 0, 2**40), _args.bounded(min_order, f, "min_order", 0, 2**40)
    table = None
    allow_large = _args.flag(allow_large, f, "allow_large")
    if _args.flag(rows, f, "rows"):
        count = _gyrores._sweep_pairs(max(bottom, 3), top) if max(bottom, 3) <= top else 0
        need = count * _SWEEP_ROW_BYTES
        if need > _SWEEP_ROWS_LIMIT and not allow_large:
            raise UsageError(f"sweep(): the rows of {count} pairs would take about "
                             f"{need / 1e9:.3g} GB of memory: pass rows=False (the summary alone), a smaller "
                             f"max_order, or allow_large=True")
        table = _row_table(count)
    notes, summary = _gyrores._sweep(top, bottom, table, progress, checks, _args.bounded(threads, f, "threads", 0, 4096),
                                     _args.bounded(examples, f, "examples", 0, 2**31))
    return (None if table is None else _with_notes(table, notes)), _sweep_summary(summary)


def _sweep_summary(raw):
    """The summary of ``gyrores sweep --json`` as a Result: its reals (the sweep's doubles, written
    as plain decimals such as "0.0049966470557269195": asy_ratio_max.value, sharp_constant.value,
    the t_first_over_proxy statistics) as floats, never str."""
    def walk(value, key):
        if isinstance(value, dict):
            return Result({k: walk(v, k) for k, v in value.items()})
        if isinstance(value, list):
            return tuple(walk(v, key) for v in value)
        if isinstance(value, str) and key not in _ECHO_KEYS and _DECIMAL_TEXT.match(value):
            return float(value)
        return value

    return walk(raw, None)


_PROVED_COLUMNS = ("n", "r_res", "h_min", "theta_first", "t_first", "t_min_paper")


def _proved_pairs(taus, sigmas, digits, threads):
    """pairs(..., digits=D): pair() of every pair on a thread pool, as a structured array."""
    import concurrent.futures
    import numpy as np
    t = [_args.integer(v, "pairs", f"taus[{i}]") for i, v in enumerate(taus)]
    s = [_args.integer(v, "pairs", f"sigmas[{i}]") for i, v in enumerate(sigmas)]
    if len(t) != len(s):
        raise UsageError(f"pairs(): taus and sigmas differ in length ({len(t)} and {len(s)})")
    workers = threads or (_os.cpu_count() or 1)
    pool = concurrent.futures.ThreadPoolExecutor(max_workers=workers)
    try:
        futures = [pool.submit(pair, a, b, digits) for a, b in zip(t, s)]
        results = []
        for i, f in enumerate(futures):
            try:
                results.append(f.result())
            except UsageError as e:
                raise UsageError(f"pairs(): (taus[{i}], sigmas[{i}]) = ({_args._show(t[i])}, {_args._show(s[i])}): "
                                 f"{e}") from None
    finally:  # on Ctrl-C or an error: drop the pairs not started
        pool.shutdown(wait=False, cancel_futures=True)
    small = all(-2**63 <= v < 2**63 for v in t + s)
    integer = np.int64 if small else object
    real = np.float64 if digits <= _DOUBLE_DIGITS else object
    dtype = [("tau", integer), ("sigma", integer)] + [(k, real) for k in _PROVED_COLUMNS] + [
        ("degenerate", bool), ("minimisers", np.int32)]
    table = np.empty(len(results), dtype=dtype)
    for i, r in enumerate(results):
        table[i] = (r.tau, r.sigma, *(r[k] for k in _PROVED_COLUMNS), r.degenerate, len(r.minimisers))
    return table


def _int64_column(values, name):
    """A one-dimensional int64 array of the pair members `values` (any iterable of integers)."""
    import numpy as np
    if isinstance(values, np.ndarray) and values.dtype.kind != "O":  # object arrays: element by element below
        if values.dtype.kind not in "iu" or values.ndim != 1:
            raise UsageError(f"pairs(): {name} must be a one-dimensional array of integers, got dtype {values.dtype} "
                             f"with {values.ndim} dimensions")
        if values.dtype.kind == "u" and values.size and values.max() > 2**40:
            raise UsageError(f"pairs(): {name} holds a value above 2^40 (use pair() beyond)")
        return values.astype(np.int64, copy=False)
    items = [_args.integer(v, "pairs", f"{name}[{i}]") for i, v in enumerate(values)]
    for i, v in enumerate(items):
        if not -2**62 < v < 2**62:
            raise UsageError(f"pairs(): {name}[{i}] = {_args._show(v)} is above 2^40 (use pair() beyond)")
    return np.array(items, dtype=np.int64)


def pairs(taus, sigmas, digits=None, certified=False, checks="default", threads=0):
    """Values of every pair (taus[i], sigmas[i]) as a NumPy structured array.

    digits=None: the sweep's row of each pair (the columns and values of sweep(): r_res,
    theta_first, t_first... in double, a few ulps from the exact values; certified=True: the
    exact values rounded, from proved enclosures, and the checks decided by proofs, as ``gyrores sweep
    --certified``), pairs with tau + sigma <= 2^40, on `threads` workers (0: every core) writing
    straight into the table without the GIL. digits=D: the proved values of pair(tau, sigma,
    digits=D) (tau, sigma, n, r_res, h_min, theta_first, t_first, t_min_paper, degenerate,
    minimisers), pairs of any size, on `threads` Python threads (each pair() runs without the
    GIL): float columns for D <= 15, mpmath.mpf objects beyond. taus, sigmas: NumPy integer arrays
    or any iterables of integers, of the same length. Ctrl-C stops it; UsageError names the first
    invalid pair.
    """
    if digits is not None:
        return _proved_pairs(taus, sigmas, _args.bounded(digits, "pairs", "digits", 1, 10000),
                             _args.bounded(threads, "pairs", "threads", 0, 4096))
    t = _int64_column(taus, "taus")
    s = _int64_column(sigmas, "sigmas")
    if len(t) != len(s):
        raise UsageError(f"pairs(): taus and sigmas differ in length ({len(t)} and {len(s)})")
    if not isinstance(checks, str):
        raise UsageError(f"pairs(): checks must be text, got {type(checks).__name__}")
    import numpy as np
    certified = _args.flag(certified, "pairs", "certified")
    threads = _args.bounded(threads, "pairs", "threads", 0, 4096)
    table = _row_table(len(t))
    notes = _gyrores._pairs_into(np.ascontiguousarray(t), np.ascontiguousarray(s), checks, certified, threads, table)
    return _with_notes(table, notes)

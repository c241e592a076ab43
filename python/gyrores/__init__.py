"""gyrores: certified high-precision analysis of gyroscopically coupled oscillators.

Python bindings of the gyrores C++ library (the compiled part is ``gyrores._gyrores``). For a
resonant pair ``(tau, sigma)`` (coprime integers ``tau > sigma >= 1``, any size) ``pair`` gives
the inscribed radius ``r_res``, its minimisers and the first-hit time with every digit verified,
as ``gyrores pair --json`` does; ``certify`` and ``check`` produce and re-prove interval
certificates; ``asymptotics``, ``design``, ``pareto`` and ``coupling`` mirror the commands of the
same names; ``enumerate_pairs`` and ``sweep`` visit every pair up to an order. Reals come back as
Python floats for ``digits <= 15``, as ``mpmath.mpf`` beyond when mpmath is installed, and as
decimal strings otherwise (an ``mpf`` holds every verified digit, but mpmath prints and computes at
its own ``mpmath.mp.dps``: raise it to see or keep them all); certificates keep the exact strings
of their JSON form. Bad input
raises ``UsageError`` (a ``ValueError``), a result that cannot be computed honestly
``ComputeError`` (an ``ArithmeticError``), with the library's one-line messages. Every function
may be called from several threads at once, and the library takes no lock: ``pair``,
``asymptotics``, ``certify``, ``design``, ``pareto``, ``coupling`` and ``sweep`` release the GIL
while they compute, so threads (e.g. a ``concurrent.futures.ThreadPoolExecutor``) run them in
parallel.
"""

import json as _json
import os as _os

from . import _gyrores
from ._gyrores import ComputeError, UsageError

try:
    import mpmath as _mpmath
except ImportError:  # optional: reals beyond 15 digits are then decimal strings
    _mpmath = None

__all__ = [
    "ComputeError", "PairResult", "UsageError", "asymptotics", "certify", "check", "coupling", "design",
    "enumerate_pairs", "pair", "pareto", "sweep",
]

# The keys whose values are verified reals (decimal strings in the library's JSON).
_REAL_KEYS = frozenset({
    "beat_ratio", "n", "omega1", "omega2", "rho0", "qdot0", "r_res", "h_min", "h_z_max", "theta_first",
    "t_first", "minimisers", "t_min_paper", "s", "u_asy", "theta_asy", "theta_c", "error", "bound", "ratio",
    "r_res_asy", "r_res_asy_rel_error", "h_min_horizon", "t_min_horizon", "inf_all_time",
})
# Keys whose values are never converted: the caller's input echoed back,
_INPUT_KEYS = frozenset({"input", "enclosures"})  # and the enclosures: outward decimal text, kept as it is


def _real_converter(digits):
    """The function turning a verified decimal string of `digits` digits into a Python real."""
    if digits <= 15:
        return float  # every digit fits a double
    if _mpmath is not None:
        def to_mpf(text):
            with _mpmath.workdps(digits + 3):  # the mpf keeps this precision after the block
                return _mpmath.mpf(text)
        return to_mpf
    return str


def _convert(value, real, key=None):
    """A JSON-shaped value with the reals under _REAL_KEYS converted by `real`; lists become tuples."""
    if isinstance(value, dict):
        return {k: v if k in _INPUT_KEYS else _convert(v, real, k) for k, v in value.items()}
    if isinstance(value, list):
        return tuple(_convert(v, real, key) for v in value)
    if isinstance(value, str) and key in _REAL_KEYS:
        return real(value)
    return value


def _text(value):
    """A number given as int, float, str or Decimal, as the decimal text the library parses."""
    return repr(value) if isinstance(value, float) else str(value)


class PairResult:
    """What gyrores reports about one resonant pair: the fields of ``gyrores pair --json``.

    Fields are attributes (``r.r_res``, ``r.minimisers``, ``r.asymptotic``...) and items
    (``r["r_res"]``), in the CLI's order; reals are converted as the module docstring says. Every
    real is the correct rounding of a proved enclosure (``r.theorem``: the theorem the proofs rest
    on); with ``enclosures=True`` also ``r.enclosures``, the same keys with ``(lo, hi)`` decimal
    strings rounded outward.
    """

    def __init__(self, raw):
        self._raw = raw
        self._values = _convert(raw, _real_converter(raw["digits"]))

    def __getattr__(self, name):
        try:
            return self.__dict__["_values"][name]
        except KeyError:
            raise AttributeError(name) from None

    def __getitem__(self, name):
        return self._values[name]

    def __dir__(self):
        return list(super().__dir__()) + list(self._values)

    def to_dict(self, raw=False):
        """The fields as a dict; ``raw=True``: exactly the CLI's JSON (reals as decimal strings)."""
        return _json.loads(_json.dumps(self._raw)) if raw else dict(self._values)

    def __repr__(self):
        v = self._raw
        shown = ", ".join(f"{k}={v[k]}" for k in ("r_res", "theta_first", "t_first", "n"))
        return (f"PairResult(tau={v['tau']}, sigma={v['sigma']}, {shown}, minimisers={len(v['minimisers'])}, "
                f"degenerate={v['degenerate']}, digits={v['digits']}, proved by {v['theorem']})")


def pair(tau, sigma, digits=17, qdot0="1", enclosures=False):
    """Inscribed radius, minimisers and first-hit time of the resonant pair (tau, sigma).

    tau, sigma: Python ints of any size, coprime, tau > sigma >= 1. digits: significant digits
    of every real, 1..10000, each the correct rounding of an enclosure proved by interval
    arithmetic on the lattice theorem. qdot0: impulse amplitude > 0 (an exact decimal or
    fraction as text, or an int; a float is taken as its repr). enclosures: also the enclosures
    (``r.enclosures``). Returns a PairResult; raises UsageError / ComputeError.
    """
    return PairResult(_gyrores._pair(tau, sigma, digits, _text(qdot0), enclosures))


def asymptotics(tau, sigma, digits=17):
    """The paper's asymptotics of the pair (the ``asymptotic`` object of ``gyrores pair --json``).

    A dict: applicable, reason, lobes (per lobe k, m, s, u_asy, theta_asy, the exact lobe root
    theta_c, error, bound pi^3 x^2/a, ratio, holds_global_min), r_res_asy (the x -> 0 limit form)
    and r_res_asy_rel_error (None when not applicable), digits; qdot0 = 1. Every real proved.
    """
    return _convert(_gyrores._asymptotics(tau, sigma, digits), _real_converter(digits))


def certify(tau, sigma, digits=30):
    """An interval certificate of r_res, theta_first and t_first of (tau, sigma), qdot0 = 1.

    Returns the dict of ``gyrores certify``, "gyrores-certificate/2" (the lattice theorem, any
    pair: the minimisers' lobes, a bracket of u*, enclosures as [lo, hi] decimal strings with at
    least `digits` correct digits). Pass it to check(), or json.dump it for ``gyrores check``.
    Raises UsageError / ComputeError.
    """
    return _gyrores._certify(tau, sigma, digits)


def check(cert):
    """Re-prove a certificate independently; returns (holds, failure).

    cert: the dict of certify(), its JSON text, or the path of a certificate file. failure
    names the first claim or fact that does not hold ("" when it holds). Malformed content, and
    a certificate of the retired format "gyrores-certificate/1" (the interval cover; re-certify
    with certify()), raise UsageError at once (``gyrores check`` exits 2 there).
    """
    if isinstance(cert, dict):
        text = _json.dumps(cert)
    elif isinstance(cert, str) and cert.lstrip().startswith("{"):
        text = cert
    elif isinstance(cert, (str, _os.PathLike)):
        try:
            with open(cert, encoding="utf-8") as f:
                text = f.read()
        except OSError as e:
            raise UsageError(f"cannot read certificate '{_os.fspath(cert)}': {e.strerror}") from None
    else:
        raise UsageError(f"cert must be a dict, JSON text or a path, got {type(cert).__name__}")
    holds, failure = _gyrores._check_text(text)
    return bool(holds), failure


def design(problem, tmax, beat=None, max_order=200, exclude_low=0, delta=None, proxy=False, candidates=5,
           digits=10):
    """Choose a resonant pair: "absorb" (min r_res) or "contain" (max r_res) with time <= tmax.

    tmax, beat: rationals (int, float, Decimal, "17", "1/4"); beat: (tau+sigma)/(tau-sigma) >=
    beat; max_order 3..5000; exclude_low: drop tau + sigma <= exclude_low; delta: only tau -
    sigma = delta; proxy: use the paper's proxy pi/|n| instead of the exact first-hit time.
    Returns the dict of ``gyrores design --json``; ComputeError when no pair is feasible.
    """
    raw = _gyrores._design(problem, _text(tmax), None if beat is None else _text(beat), max_order, exclude_low,
                           delta, proxy, candidates, digits)
    return _convert(raw, _real_converter(digits))


def pareto(max_order, orientation="absorb", proxy=False, exclude_degenerate=False, beat=None, exclude_low=0,
           digits=10):
    """The Pareto front of (r_res, time) over the resonant pairs with tau + sigma <= max_order.

    orientation "absorb" (lower r_res and time better) or "contain" (higher r_res, lower time);
    proxy: time = pi/|n| instead of t_first. Returns the dict of ``gyrores pareto --json``
    without its file keys (csv, plot).
    """
    raw = _gyrores._pareto(max_order, orientation, proxy, exclude_degenerate,
                           None if beat is None else _text(beat), exclude_low, digits)
    return _convert(raw, _real_converter(digits))


def coupling(n=None, n2=None, horizon="100", convergents=8, digits=12):
    """Any coupling n (or its square n2, e.g. "1/12"): resonance test, min of H_q, convergents.

    Exactly one of n, n2 (rationals: int, float, Decimal or text such as "1/4"). horizon: T >= 0
    for the minimum of H_q over [0, T]; convergents: how many convergents of W1/W2 (0..60).
    Returns the dict of ``gyrores coupling --json``.
    """
    raw = _gyrores._coupling(None if n is None else _text(n), None if n2 is None else _text(n2), _text(horizon),
                             convergents, digits)
    return _convert(raw, _real_converter(digits))


def enumerate_pairs(max_order, min_order=3):
    """A lazy iterator over the resonant pairs (tau, sigma) with min_order <= tau + sigma <= max_order.

    Coprime tau > sigma >= 1, by order ascending then sigma ascending; nothing is materialised.
    """
    return _gyrores._enumerate_pairs(max_order, min_order)


def sweep(max_order, min_order=3, rows=True, progress=None, checks="default", threads=0, cross_check_max_order=300,
          examples=5):
    """Check the paper's claims on every pair with min_order <= tau + sigma <= max_order (in double).

    Returns (rows, summary): rows a NumPy structured array, one record per pair in enumeration
    order, with the columns of ``gyrores sweep --out`` (not applicable: NaN for reals, -1 for
    flags; check_* columns 1 pass, 0 fail, -1 not run; failed bool; note str), or None when
    rows=False; summary the dict of ``gyrores sweep --json``. The work runs on `threads` workers
    (0: every core) with the GIL released; progress, if given, is called as progress(done, total)
    after every block of pairs, and an exception it raises (or Ctrl-C) stops the sweep.
    checks: "default" (the paper's four claims), "all" (with the opt-in cross-check against the
    global search, order <= cross_check_max_order) or a comma-separated list (degeneracy,
    paper-node, asy-bound, structure, cross-check).
    """
    columns, summary = _gyrores._sweep(max_order, min_order, rows, progress, checks, threads,
                                       cross_check_max_order, examples)
    if columns is None:
        return None, summary
    import numpy as np
    columns["failed"] = columns["failed"].astype(bool)
    columns["note"] = np.array(columns["note"], dtype=object)
    table = np.empty(len(columns["tau"]), dtype=[(name, col.dtype) for name, col in columns.items()])
    for name, col in columns.items():
        table[name] = col
    return table, summary

# The module on 8 Python threads at once: every function releases the GIL and runs the library
# concurrently (no lock of its own), so each call's result must equal the same call made alone.
#
# What it catches: library code that sets process-wide state, such as Boost's default MPFR
# precision, makes a concurrent call compute at another precision (its digits differ, or it
# fails); a binding that touches Python objects without the GIL, or a lock taken in the wrong
# order against the GIL (the sweep's progress callback takes it back), crashes or hangs.
# tests/test_threads.cpp does the same in C++ and watches the default precision itself.
import json
from concurrent.futures import ThreadPoolExecutor

import pytest

import gyrores

PAIRS = [(6, 5), (9, 4), (11, 9), (10**30 + 1, 10**30)]


def _sweep(max_order, **kw):
    """Rows (every column, as text) and the summary without its run time."""
    rows, summary = gyrores.sweep(max_order, progress=lambda done, total: None, **kw)
    summary.pop("seconds")
    return json.dumps({name: [repr(v) for v in rows[name].tolist()] for name in rows.dtype.names}), summary


def _certify_and_check(tau, sigma):
    cert = gyrores.certify(tau, sigma, digits=40)
    return cert, gyrores.check(cert)


def _calls():
    calls = []
    for tau, sigma in PAIRS:
        for digits in (17, 50, 300):
            calls.append((f"pair {tau} {sigma} {digits}",
                          lambda t=tau, s=sigma, d=digits: gyrores.pair(t, s, digits=d, enclosures=True).to_dict(raw=True)))
        calls.append((f"certify {tau} {sigma}", lambda t=tau, s=sigma: _certify_and_check(t, s)))
    calls.append(("sweep 60", lambda: _sweep(60)))
    calls.append(("sweep 60 on 2 workers", lambda: _sweep(60, threads=2, checks="degeneracy,structure")))
    for digits in (12, 25, 40, 100):
        calls.append((f"coupling 2 {digits}", lambda d=digits: gyrores.coupling(n=2, horizon=30, convergents=3, digits=d)))
    calls.append(("coupling 1/12", lambda: gyrores.coupling(n2="1/12", convergents=3, digits=20)))
    return calls


def test_eight_threads_give_the_serial_results():
    pytest.importorskip("numpy")
    calls = _calls()
    serial = [fn() for _, fn in calls]
    for (name, _), result in zip(calls, serial):
        if name.startswith("certify"):
            assert result[1] == {"holds": True, "failure": ""}, name
    # Every call four times, interleaved so that each kind overlaps the others.
    order = [k for _ in range(4) for k in range(len(calls))]
    order = order[::3] + order[1::3] + order[2::3]
    with ThreadPoolExecutor(max_workers=8) as pool:
        futures = [(k, pool.submit(calls[k][1])) for k in order]
        for k, future in futures:
            assert future.result(timeout=120) == serial[k], calls[k][0]

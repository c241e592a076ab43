# Ctrl-C: SIGINT during a long call raises KeyboardInterrupt promptly, not when the work ends, and
# the module stays usable; a progress callback may call back into gyrores.
#
# The latency is printed (pytest -s) and checked against a generous bound (5 s, against the
# seconds to minutes the uninterrupted calls take), not against the 0.2 s the module is designed
# for (interruptible.hpp: 20 ms slices): the tests must not depend on the machine's load.
import os
import signal
import threading
import time

import pytest

import gyrores

GENEROUS = 5.0


def _latency_of_sigint(call, delay):
    """Seconds from SIGINT (sent after `delay`) to KeyboardInterrupt; fails if the call ends first."""
    sent = []

    def fire():
        time.sleep(delay)
        sent.append(time.monotonic())
        os.kill(os.getpid(), signal.SIGINT)

    thread = threading.Thread(target=fire)
    thread.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            call()
            time.sleep(2 * GENEROUS)  # the call ended before the signal: let it arrive here (and fail)
        return time.monotonic() - sent[0]
    finally:
        thread.join()


@pytest.mark.parametrize("name, call", [
    ("pair(6, 5, digits=10000)", lambda: gyrores.pair(6, 5, digits=10000, enclosures=True)),
    # the horizon is O(log T) now: the long part is the analysis of a resonant pair of order 10^4000
    # (which the library runs without the stop flag: KeyboardInterrupt at once, the work ends later)
    ("coupling of a 2000-digit pair", lambda: gyrores.coupling(n2=f"1/{10**2000 * (10**2000 + 1)}", digits=1000)),
    # bands take milliseconds; this one (2000 digits over four decades of n to T = 10^50) minutes
    ("coupling band [0.01, 100] to T = 10^50, 2000 digits",
     lambda: gyrores.coupling(band=(0.01, 100), horizon="1e50", band_digits=2000)),
    ("couplings over 10^5 couplings", lambda: gyrores.couplings([0.1 + i * 1e-4 for i in range(10**5)], horizon="1e30")),
    ("pairs over 2.10^6 pairs", lambda: gyrores.pairs(range(2, 2 * 10**6), range(1, 2 * 10**6 - 1))),
    ("sweep(10^5)", lambda: gyrores.sweep(10**5, rows=False)),
])
def test_sigint_raises_keyboard_interrupt_promptly(name, call):
    latency = _latency_of_sigint(call, 0.05)  # early: the calls take 1 s (pair) to minutes
    print(f"{name}: KeyboardInterrupt {latency * 1000:.1f} ms after SIGINT")
    assert latency < GENEROUS
    assert gyrores.pair(6, 5, digits=20).digits == 20  # still usable


def test_progress_callback_may_call_gyrores():
    seen = []

    def progress(done, total):
        seen.append(gyrores.pair(9, 4, digits=25).r_res)

    gyrores.sweep(300, rows=False, progress=progress)
    assert seen and all(v == seen[0] for v in seen)


def test_an_exception_in_progress_stops_the_sweep():
    def progress(done, total):
        raise RuntimeError("stop here")

    with pytest.raises(RuntimeError, match="stop here"):
        gyrores.sweep(2000, rows=False, progress=progress)

# Ctrl-C: SIGINT during a long call raises KeyboardInterrupt promptly, not when the work ends, the
# work itself stops (the calls run on the calling thread, python/src/interruptible.hpp: no thread is
# left behind), and the module stays usable; a progress callback may call back into gyrores.
#
# The latency is printed (pytest -s) and checked against a generous bound (5 s, against the
# seconds to minutes the uninterrupted calls take), not against the 0.2 s the module is designed
# for: the tests must not depend on the machine's load.
import os
import signal
import threading
import time

import numpy  # noqa: F401  (imported first: OpenBLAS starts its worker threads at import, and
              # gyrores imports NumPy on its first array call; those threads are not the work's)
import pytest

import gyrores

GENEROUS = 5.0


def _os_threads():
    """The threads of this process as the kernel counts them (C++ workers included)."""
    try:
        return len(os.listdir("/proc/self/task"))
    except OSError:  # pragma: no cover - not Linux
        return threading.active_count()


def _latency_of_sigint(call, delay):
    """Seconds from SIGINT (sent after `delay`) to KeyboardInterrupt.

    Fails if the signal was sent while the call ran and the call still ended normally. On a loaded
    machine the signalling thread may wake only after the call has ended: that says nothing about
    the call, so the measurement is taken again (three tries)."""
    for _ in range(3):
        sent = []

        def fire():
            time.sleep(delay)
            sent.append(time.monotonic())
            os.kill(os.getpid(), signal.SIGINT)

        thread = threading.Thread(target=fire)
        thread.start()
        try:
            call()
            ended = time.monotonic()  # inside the try: a signal just after the call counts too
        except KeyboardInterrupt:
            latency = time.monotonic() - sent[0]
            thread.join()
            return latency
        # The call ended before KeyboardInterrupt: take the signal here, so that it does not reach
        # the next test (it may arrive in join() or in the sleep).
        try:
            thread.join()
            time.sleep(0.5)
        except KeyboardInterrupt:
            pass
        thread.join()
        if sent[0] < ended:
            pytest.fail("SIGINT was sent during the call, which still ended without KeyboardInterrupt")
    pytest.fail("the call ended before SIGINT three times: it must last longer than the delay")


@pytest.mark.parametrize("name, call", [
    ("pair(6, 5, digits=10000)", lambda: gyrores.pair(6, 5, digits=10000, enclosures=True)),
    # a second at T = 10^1000 (the horizon theorem's rotation minimum on 3000-digit numbers)
    ("coupling n = 2 to T = 10^1000", lambda: gyrores.coupling(2, horizon="1e1000")),
    # bands take milliseconds; this one (2000 digits over four decades of n to T = 10^50) minutes
    ("coupling band [0.01, 100] to T = 10^50, 2000 digits",
     lambda: gyrores.coupling(band=(0.01, 100), horizon="1e50", band_digits=2000)),
    ("couplings over 10^5 couplings", lambda: gyrores.couplings([0.1 + i * 1e-4 for i in range(10**5)], horizon="1e30")),
    ("couplings at T = 10^300", lambda: gyrores.couplings([2, 3, 5, 6, 7] * 100, horizon="1e300")),
    ("pairs over 2.10^6 pairs", lambda: gyrores.pairs(range(2, 2 * 10**6), range(1, 2 * 10**6 - 1))),
    ("sweep(10^5)", lambda: gyrores.sweep(10**5, rows=False)),
])
def test_sigint_raises_keyboard_interrupt_promptly(name, call):
    before = _os_threads()
    latency = _latency_of_sigint(call, 0.05)  # early: the calls take 1 s (pair) to minutes
    print(f"{name}: KeyboardInterrupt {latency * 1000:.1f} ms after SIGINT")
    assert latency < GENEROUS
    # The work stopped: no thread of it left running. The test's own signalling thread has been
    # joined, but the kernel may list it for a moment after join() returns (Python releases the
    # join before the thread exits): wait up to a second for that, far less than any call lasts.
    deadline = time.monotonic() + 1.0
    while _os_threads() != before and time.monotonic() < deadline:
        time.sleep(0.01)
    assert _os_threads() == before
    assert gyrores.pair(6, 5, digits=20).digits == 20  # still usable


def test_sigint_is_python_s_own_outside_calls_and_with_a_user_handler():
    # The module's handler is chained in front of Python's only while a call runs, and only when
    # SIGINT raises KeyboardInterrupt: afterwards SIGINT is Python's alone, and with a handler of
    # the user's the call is not stopped (the handler runs when it ends, as after any C call).
    gyrores.pair(6, 5)
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler
    seen = []
    previous = signal.signal(signal.SIGINT, lambda signum, frame: seen.append(signum))
    try:
        gyrores.pair(6, 5)
        os.kill(os.getpid(), signal.SIGINT)
        time.sleep(0.05)
        assert seen == [signal.SIGINT]
        timer = threading.Timer(0.05, os.kill, (os.getpid(), signal.SIGINT))
        timer.start()
        assert gyrores.coupling(2, horizon="1e600").horizon_lobe > 0  # runs to its end
        timer.join()
        time.sleep(0.05)
        assert seen == [signal.SIGINT, signal.SIGINT]
    finally:
        signal.signal(signal.SIGINT, previous)


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

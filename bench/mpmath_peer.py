#!/usr/bin/env python3
"""The mpmath peer of gyrores-bench: mpmath's findroot on the naive formulation.

Run by gyrores-bench (bench/speed_error/peer_mpmath.cpp) in the same benchmark run; not meant
to be used alone. Reads tasks from the file named on the command line, one per line:

    id <TAB> tau <TAB> sigma <TAB> dps <TAB> x0 <TAB> x1

and for each solves q'(theta) = W1 cos(tau theta) + W2 cos(sigma theta) = 0 with
mpmath.findroot(f, (x0, x1)) (the default solver, secant, from two nearby starts) at
mp.dps = dps, then r = rho0 |sin(tau theta) + sin(sigma theta)|, everything at mp.dps. The
timed call includes the constants W1, W2, rho0 (as gyrores' timed calls include theirs).

Prints one line per task:

    id <TAB> median_seconds <TAB> repetitions <TAB> calls_per_repetition <TAB> evaluations
       <TAB> theta <TAB> r <TAB> error

Timing: time.process_time (CPU time, like the C++ side); each repetition runs the call enough
times to last >= 20 ms; the median of 5 repetitions (3 when one call exceeds 0.3 s).
A first line "# mpmath <version> backend <backend> python <version>" describes the peer.
"""
import statistics
import sys
import time

import mpmath
from mpmath import mp, mpf


def solve(tau, sigma, dps, x0, x1):
    mp.dps = dps
    t = mpf(tau)
    s = mpf(sigma)
    w1 = mp.sqrt(t / s)
    w2 = mp.sqrt(s / t)
    rho0 = 1 / (w1 + w2)
    calls = [0]

    def qdot(th):
        calls[0] += 1
        return w1 * mp.cos(t * th) + w2 * mp.cos(s * th)

    th = mp.findroot(qdot, (mpf(x0), mpf(x1)))
    r = rho0 * abs(mp.sin(t * th) + mp.sin(s * th))
    return th, r, calls[0]


def timed(fn, *args):
    t0 = time.process_time()
    fn(*args)
    one = time.process_time() - t0
    per_rep = max(1, int(0.02 / one)) if one > 0 else 1000
    reps = 3 if one > 0.3 else 5
    samples = []
    for _ in range(reps):
        t0 = time.process_time()
        for _ in range(per_rep):
            fn(*args)
        samples.append((time.process_time() - t0) / per_rep)
    return statistics.median(samples), reps, per_rep


def main():
    print("# mpmath %s backend %s python %s" % (mpmath.__version__, mpmath.libmp.BACKEND,
                                                 sys.version.split()[0]), flush=True)
    with open(sys.argv[1]) as f:
        tasks = [line.rstrip("\n").split("\t") for line in f if line.strip()]
    for tid, tau, sigma, dps, x0, x1 in tasks:
        tau, sigma, dps = int(tau), int(sigma), int(dps)
        try:
            th, r, evals = solve(tau, sigma, dps, x0, x1)
            med, reps, per_rep = timed(solve, tau, sigma, dps, x0, x1)
            mp.dps = dps
            print("%s\t%.9e\t%d\t%d\t%d\t%s\t%s\t" % (tid, med, reps, per_rep, evals,
                                                     mpmath.nstr(th, dps + 5, min_fixed=1, max_fixed=0),
                                                     mpmath.nstr(r, dps + 5, min_fixed=1, max_fixed=0)),
                  flush=True)
        except Exception as e:  # the peer's own failure is a result, reported as such
            msg = ("%s: %s" % (type(e).__name__, e)).replace("\t", " ").replace("\n", " ")
            print("%s\tnan\t0\t0\t0\t\t\t%s" % (tid, msg[:300]), flush=True)


if __name__ == "__main__":
    main()

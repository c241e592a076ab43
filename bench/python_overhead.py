#!/usr/bin/env python3
"""What a Python call costs over the library work it wraps (issue 35: at most 1.5x; sweep rows
within 2x of the CLI's wall time).

Rows, each the median over interleaved rounds (a round times every case once, so load common to
both sides of a ratio cancels):

  pair(6, 5)          gyrores.pair(6, 5) (17 digits, the default), per call, against the library
                      work it wraps: app::run_pair with the same request, timed inside the module
                      (gyrores._gyrores._library_pair_seconds) on the same thread;
  pair(6, 5).r_res    the same call and reading r_res (its conversion to an mpmath number);
  pair(6, 5, 15)      digits=15: floats, each the double nearest its exact value (the library
                      work: the 17-digit report with its doubles decided);
  sweep(N) rows       gyrores.sweep(N) with its rows (a NumPy table) against `gyrores sweep
                      --max-order N --out FILE --quiet` (the CLI writing its rows as CSV), wall time.

Per-call times are thread CPU time (time.thread_time; CLOCK_THREAD_CPUTIME_ID in C++), whose
ratio a loaded machine disturbs least; wall times are printed beside them.

Run from the repository after building the module and the CLI
(cmake --build build --target gyrores_python gyrores_cli):

    PYTHONPATH=build/python python3 bench/python_overhead.py [--cli build/src/gyrores]
        [--rounds 7] [--calls 2000] [--sweep-order 5000]

Timing assertions belong here, never in the tests.
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time

import gyrores


def per_call(fn, calls):
    """(thread CPU, wall) seconds per call: the medians of `calls` single calls."""
    cpu, wall = [], []
    for _ in range(calls):
        c0, w0 = time.thread_time(), time.perf_counter()
        fn()
        cpu.append(time.thread_time() - c0)
        wall.append(time.perf_counter() - w0)
    return statistics.median(cpu), statistics.median(wall)


def library_pair(digits, calls):
    """(thread CPU, wall) seconds per call of the library work of pair(6, 5, digits): for digits
    <= 15 the 17-digit report with its doubles decided (pair_report_options::doubles)."""
    cpu, wall = [], []
    for _ in range(calls):
        c, w = gyrores._gyrores._library_pair_seconds(6, 5, max(digits, 17), digits <= 15, 1)
        cpu.append(c)
        wall.append(w)
    return statistics.median(cpu), statistics.median(wall)


def python_sweep(order):
    start = time.perf_counter()
    rows, _ = gyrores.sweep(order)
    assert len(rows) == gyrores._gyrores._sweep_pairs(3, order)
    return time.perf_counter() - start


def cli_sweep(cli, order, out):
    start = time.perf_counter()
    subprocess.run([cli, "sweep", "--max-order", str(order), "--out", out, "--quiet"], check=True,
                   stdout=subprocess.DEVNULL)
    return time.perf_counter() - start


def us(s):
    return f"{s * 1e6:.1f} us"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--cli", default=os.environ.get("GYRORES_CLI", "build/src/gyrores"))
    ap.add_argument("--rounds", type=int, default=7)
    ap.add_argument("--calls", type=int, default=2000, help="calls per round of the per-call rows")
    ap.add_argument("--sweep-order", type=int, default=5000)
    ap.add_argument("--sweep-rounds", type=int, default=3)
    ap.add_argument("--markdown", help="also write the section to this file (bench/run appends "
                    "bench/python_overhead.md to bench/RESULTS.md)")
    a = ap.parse_args()
    lines = []

    def say(text=""):
        print(text)
        lines.append(text)

    for digits in (17, 15):  # warm up: first calls fill MPFR's and FLINT's caches
        gyrores.pair(6, 5, digits=digits).r_res
        library_pair(digits, 10)

    cases = {
        "pair(6, 5)": (lambda: gyrores.pair(6, 5), 17),
        "pair(6, 5).r_res": (lambda: gyrores.pair(6, 5).r_res, 17),
        "pair(6, 5, digits=15)": (lambda: gyrores.pair(6, 5, digits=15), 15),
    }
    ratios = {name: [] for name in cases}
    times = {name: [] for name in cases}
    for _ in range(a.rounds):
        for name, (fn, digits) in cases.items():
            py_cpu, py_wall = per_call(fn, a.calls)
            lib_cpu, lib_wall = library_pair(digits, a.calls)
            ratios[name].append(py_cpu / lib_cpu)
            times[name].append((py_cpu, py_wall, lib_cpu, lib_wall))

    say("## Python at the user's end (bench/python_overhead.py)")
    say()
    say(f"Measured {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())} by `bench/python_overhead.py` "
        f"(not by `bench/run`, which appends this file, `bench/python_overhead.md`, as it is): gyrores "
        f"{gyrores.__version__}, python {sys.version.split()[0]}, {os.cpu_count()} CPUs, load "
        f"{os.getloadavg()[0]:.2f}; {a.rounds} rounds of {a.calls} calls. Targets (issue 35): a call at "
        f"most 1.5x the library work it wraps (CPU, the same thread); `sweep()` rows within 2x of the "
        f"CLI's wall time.")
    say()
    say("| call | Python (CPU / wall) | library work (CPU / wall) | ratio (CPU, median of rounds) |")
    say("|---|---|---|---|")
    for name in cases:
        med = [statistics.median(t[i] for t in times[name]) for i in range(4)]
        say(f"| {name} | {us(med[0])} / {us(med[1])} | {us(med[2])} / {us(med[3])} | "
              f"{statistics.median(ratios[name]):.2f}x |")

    if a.sweep_order > 0 and os.access(a.cli, os.X_OK):
        py_t, cli_t, sweep_ratios = [], [], []
        with tempfile.TemporaryDirectory() as d:
            out = os.path.join(d, "rows.csv")
            for _ in range(a.sweep_rounds):
                p = python_sweep(a.sweep_order)
                c = cli_sweep(a.cli, a.sweep_order, out)
                py_t.append(p)
                cli_t.append(c)
                sweep_ratios.append(p / c)
        n = gyrores._gyrores._sweep_pairs(3, a.sweep_order)
        say()
        say("| sweep | Python rows (wall) | CLI rows to CSV (wall) | ratio (median of rounds) |")
        say("|---|---|---|---|")
        say(f"| sweep({a.sweep_order}), {n} pairs | {statistics.median(py_t):.2f} s | {statistics.median(cli_t):.2f} s | "
              f"{statistics.median(sweep_ratios):.2f}x |")
    elif a.sweep_order > 0:
        say(f"\n(sweep row skipped: no CLI at {a.cli}; pass --cli)")
    if a.markdown:
        with open(a.markdown, "w") as f:
            f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""What the gyrores CLI costs over its floors (issue 35: the sweep within 1.5x of the 2-core
limit of its own evaluation; `gyrores pair 6 5` within 1.1x of a bare start).

  sweep M        `gyrores sweep --max-order M --quiet --json` (no files named: the resume state
                 in a scratch directory) against gyrores-sweep-limit M 2 (bench/cli_limits/
                 sweep_limit.cpp: the same enumeration and kernel, 2 workers, every value in
                 memory, no file, no process start-up). The limit on 2 cores is the limit's
                 process CPU time over 2 (its sweep alone; the quantiles are timed apart). Ratios:
                 the CLI's wall time over that and over the limit's wall time, and the CLI's CPU
                 time (user + sys) over the limit's; the CLI's user, sys, wall and max RSS as
                 /usr/bin/time gives them.
  pair 6 5       `gyrores pair 6 5` against gyrores-bare-start (bench/cli_limits/bare_start.cpp:
                 main() { return 0; } linked with the CLI's libraries and link options; their
                 dynamic dependencies are checked equal). Instructions of the whole process in
                 user space (valgrind --tool=callgrind, deterministic: the loader, relocations,
                 initialisers, the command, exit), and medians of CPU time and page faults.

Each sweep row is the median over interleaved rounds (a round runs the limit and the CLI once),
so load common to both sides cancels in the ratios; the machine is shared, so wall times are
noisier than CPU times. Build the three programs, then from the repository:

    cmake --build build --target gyrores_cli gyrores-sweep-limit gyrores-bare-start
    python3 bench/cli_overhead.py [--build build] [--orders 3000,5000,8000] [--rounds 5]
        [--markdown bench/cli_overhead.md]

bench/run appends bench/cli_overhead.md to bench/RESULTS.md. Timing assertions belong here,
never in the tests.
"""
import argparse
import datetime
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time


def run_timed(cmd, cwd=None):
    """(stdout, wall s, user s, sys s, max RSS kB, minor faults) of one run of cmd."""
    start = time.perf_counter()
    p = subprocess.Popen(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    out = p.stdout.read()
    err = p.stderr.read()
    _, status, ru = os.wait4(p.pid, 0)
    wall = time.perf_counter() - start
    p.returncode = os.waitstatus_to_exitcode(status)
    if p.returncode != 0:
        sys.exit(f"cli_overhead: {' '.join(cmd)} failed ({p.returncode}): {err.decode()[-500:]}")
    return out.decode(), wall, ru.ru_utime, ru.ru_stime, ru.ru_maxrss, ru.ru_minflt


def needed(path):
    """The shared libraries path names, but the dynamic loader (loaded in every case)."""
    out = subprocess.run(["readelf", "-d", path], check=True, capture_output=True, text=True).stdout
    return sorted(x for x in re.findall(r"\(NEEDED\)\s+Shared library: \[(.*)\]", out) if not x.startswith("ld-linux"))


def callgrind_instructions(cmd):
    """(whole process, main() inclusive, app::run_pair inclusive) instructions of cmd."""
    with tempfile.TemporaryDirectory() as d:
        out = f"{d}/cg.out"
        r = subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}"] + cmd,
                           capture_output=True, text=True)
        m = re.search(r"Collected : (\d+)", r.stderr)
        if r.returncode != 0 or not m:
            sys.exit(f"cli_overhead: callgrind failed on {' '.join(cmd)}: {r.stderr[-500:]}")
        ann = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--threshold=100", out],
                             capture_output=True, text=True).stdout

        def inclusive(pattern):
            for line in ann.splitlines():
                f = re.match(r"\s*([\d,]+) \([ \d.]+%\)\s+(.*)$", line)
                if f and re.search(pattern, f.group(2)):
                    return int(f.group(1).replace(",", ""))
            return 0

        return int(m.group(1)), inclusive(r"\?\?\?:main \["), inclusive(r"gyrores::app::run_pair\(")


def sweep_rows(a):
    rows = []
    for order in a.orders:
        cli, lim = [], []
        with tempfile.TemporaryDirectory() as d:
            for _ in range(a.rounds):
                out, *t = run_timed([a.limit, str(order), "2"])
                lim.append(json.loads(out))
                out, *t = run_timed([a.cli, "sweep", "--max-order", str(order), "--quiet", "--json"], cwd=d)
                s = json.loads(out)
                cli.append((s, *t))
        # The two computed the same sweep: pair count and quantiles (exact, bit for bit).
        s = cli[0][0]
        q = s["t_first_over_proxy"]
        if s["pairs"] != lim[0]["pairs"] or float(q["median"]) != lim[0]["median"] or float(q["p99"]) != lim[0]["p99"]:
            sys.exit(f"cli_overhead: the CLI and the limit disagree at order {order}")
        med = lambda xs: statistics.median(xs)
        limit_cpu = med([x["sweep_cpu"] for x in lim])
        cli_cpu = [c[2] + c[3] for c in cli]
        rows.append({
            "order": order, "pairs": s["pairs"],
            "limit_cpu": limit_cpu, "limit_2core": limit_cpu / 2, "limit_wall": med([x["sweep_wall"] for x in lim]),
            "quantiles_cpu": med([x["quantiles_cpu"] for x in lim]),
            "cli_user": med([c[2] for c in cli]), "cli_sys": med([c[3] for c in cli]),
            "cli_wall": med([c[1] for c in cli]), "cli_rss_mb": med([c[4] for c in cli]) / 1024,
            "wall_ratio": med([c[1] / (x["sweep_cpu"] / 2) for c, x in zip(cli, lim)]),
            "wall_wall_ratio": med([c[1] / x["sweep_wall"] for c, x in zip(cli, lim)]),
            "cpu_ratio": med([cc / x["sweep_cpu"] for cc, x in zip(cli_cpu, lim)]),
        })
    return rows


def pair_row(a):
    if needed(a.cli) != needed(a.bare):
        sys.exit(f"cli_overhead: {a.bare} does not link what {a.cli} links: {needed(a.bare)} vs {needed(a.cli)}")
    row = {"needed": len(needed(a.cli))}
    if shutil.which("valgrind"):
        row["cli_ir"], row["cli_main"], row["cli_work"] = callgrind_instructions([a.cli, "pair", "6", "5"])
        row["bare_ir"], row["bare_main"], _ = callgrind_instructions([a.bare])
    cpu = {"cli": [], "bare": []}
    faults = {"cli": [], "bare": []}
    for _ in range(a.start_runs):
        for name, cmd in (("cli", [a.cli, "pair", "6", "5"]), ("bare", [a.bare])):
            _, _, user, sys_, _, minflt = run_timed(cmd)
            cpu[name].append(user + sys_)
            faults[name].append(minflt)
    for name in cpu:
        row[name + "_cpu"] = statistics.median(cpu[name])
        row[name + "_faults"] = statistics.median(faults[name])
    return row


def ms(s):
    return f"{s * 1e3:.0f} ms" if s >= 0.1 else f"{s * 1e3:.1f} ms"


def markdown(a, sweeps, pair):
    now = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    load = os.getloadavg()
    lines = [
        "## The CLI at the user's end (bench/cli_overhead.py)",
        "",
        f"Measured {now} by `bench/cli_overhead.py` ({os.cpu_count()} logical CPUs, shared; load "
        f"{load[0]:.2f}/{load[1]:.2f}/{load[2]:.2f} at the end), not by `bench/run`, which appends this "
        "file (`bench/cli_overhead.md`) as it is. Targets (issue 35): the sweep within 1.5x of the 2-core "
        "limit of its own evaluation; `gyrores pair 6 5` within 1.1x of a bare start.",
        "",
        "**Sweep.** `gyrores sweep --max-order M --quiet --json` against `gyrores-sweep-limit M 2`: the "
        "same enumeration and kernel in memory (2 workers, every value kept, no file, no start-up); its "
        "2-core limit is its process CPU time over 2 (what 2 idle cores would take). Medians of "
        f"{a.rounds} interleaved rounds; the ratios are medians of the rounds' ratios. On a loaded machine the "
        "CLI's wall time grows and the limit's CPU time does not: *CLI wall / limit wall* (both under the same "
        "load) and the CPU ratio are then the fair comparisons. The CLI and the limit print the same quantiles "
        "(checked).",
        "",
        "| M | pairs | limit: CPU (ns/pair) / 2-core / wall / its quantiles' CPU | CLI: user / sys / wall / max RSS | CLI wall / 2-core limit | CLI wall / limit wall | CLI CPU / limit CPU |",
        "|---|---|---|---|---|---|---|",
    ]
    for r in sweeps:
        lines.append(
            f"| {r['order']} | {r['pairs']:,} | {ms(r['limit_cpu'])} ({r['limit_cpu'] / r['pairs'] * 1e9:.1f}) / "
            f"{ms(r['limit_2core'])} / {ms(r['limit_wall'])} / {ms(r['quantiles_cpu'])} | {ms(r['cli_user'])} / "
            f"{ms(r['cli_sys'])} / {ms(r['cli_wall'])} / {r['cli_rss_mb']:.0f} MB | {r['wall_ratio']:.2f}x | "
            f"{r['wall_wall_ratio']:.2f}x | {r['cpu_ratio']:.2f}x |")
    lines += ["", "**Start-up.** `gyrores pair 6 5` against `gyrores-bare-start` (an empty main() linked with the "
              f"CLI's libraries and link options: the same {pair['needed']} shared libraries)."]
    lines += ["", "| | gyrores pair 6 5 | bare start | ratio |", "|---|---|---|---|"]
    if "cli_ir" in pair:
        b = pair["bare_ir"]
        lines.append(f"| instructions, whole process, user space (callgrind) | {pair['cli_ir']:,} | {b:,} | "
                     f"{pair['cli_ir'] / b:.3f}x |")
        outside = pair["cli_ir"] - pair["cli_main"], b - pair["bare_main"]
        lines.append(f"| of which outside main(): loader, relocations, initialisers, exit | {outside[0]:,} | "
                     f"{outside[1]:,} | {outside[0] / outside[1]:.3f}x |")
        lines.append(f"| of which main(): parsing, the command, its output | {pair['cli_main']:,} | {pair['bare_main']:,} | "
                     f"+{pair['cli_main'] / b * 100:.1f}% of the bare start |")
        lines.append(f"| of which the library's work (`app::run_pair`: the proof and every rounding) | "
                     f"{pair['cli_work']:,} | | +{pair['cli_work'] / b * 100:.1f}% of the bare start |")
    lines.append(f"| CPU time, median of {a.start_runs} | {ms(pair['cli_cpu'])} | {ms(pair['bare_cpu'])} | "
                 f"{pair['cli_cpu'] / pair['bare_cpu']:.2f}x |")
    lines.append(f"| minor page faults, median | {pair['cli_faults']:.0f} | {pair['bare_faults']:.0f} | "
                 f"{pair['cli_faults'] / pair['bare_faults']:.2f}x |")
    return "\n".join(lines) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--build", default="build")
    ap.add_argument("--cli", help="the gyrores binary to measure (default: BUILD/src/gyrores; e.g. an older one)")
    ap.add_argument("--orders", default="3000,5000,8000")
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--start-runs", type=int, default=41)
    ap.add_argument("--markdown", help="write the section to this file (else stdout only)")
    a = ap.parse_args()
    a.cli = os.path.abspath(a.cli or os.path.join(a.build, "src", "gyrores"))
    a.limit = os.path.abspath(os.path.join(a.build, "bench", "gyrores-sweep-limit"))
    a.bare = os.path.abspath(os.path.join(a.build, "bench", "gyrores-bare-start"))
    for p in (a.cli, a.limit, a.bare):
        if not os.access(p, os.X_OK):
            sys.exit(f"cli_overhead: {p} not built (cmake --build {a.build} --target gyrores_cli "
                     "gyrores-sweep-limit gyrores-bare-start)")
    a.orders = [int(x) for x in a.orders.split(",") if x]
    sweeps = sweep_rows(a)
    pair = pair_row(a)
    text = markdown(a, sweeps, pair)
    print(text, end="")
    if a.markdown:
        with open(a.markdown, "w") as f:
            f.write(text)


if __name__ == "__main__":
    main()

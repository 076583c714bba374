#!/usr/bin/env python3
"""Regenerates the performance table of docs/performance.md (issue 13, "Scale").

Runs build/bench/linkproof_bench once, with a filter built from ROWS and
--benchmark_format=json, times the SymPy derivation of the same closed omega-dot in the same
run (python3-sympy), and writes one table row per entry of ROWS: row, goal, measured, and
whether the goal is met (or missed by how much). Standard library only (SymPy is optional: its
row says "not measured" without it).

Ratio goals (x times faster than another benchmark, than SymPy) are judged on medians: the
benchmarks of both sides run again, REPETITIONS times each in random interleaved order
(--benchmark_repetitions, --benchmark_enable_random_interleaving), SymPy as often, and the
ratio is that of the medians. One run of each side on a 2-core machine shared with other work
gave ratios 30-60 % apart between regenerations; a drift of the machine during the run now
reaches both sides alike.

Adding a row is adding an entry to ROWS. A row whose benchmark is absent from the binary (for
instance the proof, count and mechanism rows before their benchmarks exist) is listed as
"not measured yet".

    python3 bench/performance_table.py                      # run the benchmarks, rewrite the doc
    python3 bench/performance_table.py --json results.json  # use a saved benchmark run
"""

import argparse
import json
import os
import re
import subprocess
import sys
import time

# One entry per table row.
#   row      what is measured, as the table shows it
#   bench    regular expression matched against the benchmark's full name (the first match is used)
#   goal     ("max_seconds", s): time per iteration at most s
#            ("min_per_second", r): items per second at least r
#            ("faster_than", other_bench_regex, factor): at least `factor` times faster than other
#            ("faster_than_sympy", factor): at least `factor` times faster than the SymPy derivation
#            ("max_counter", name, s): the benchmark's counter `name` (seconds) at most s
#            None: no goal set yet (the row shows the measurement only)
#   note     shown beside the goal (the wording)
ROWS = [
    {"row": "derivation of the closed omega-dot, n = 24", "bench": r"^BM_SymbolicDerivation/24$",
     "goal": ("faster_than_sympy", 100), "note": "keep far below SymPy (Cramer, same run)"},
    {"row": "derivation of the closed omega-dot, n = 1000", "bench": r"^BM_SymbolicDerivation/1000$",
     "goal": ("max_seconds", 0.020), "note": "<= 20 ms"},
    {"row": "GiNaC's derivation of the same tape (the reference), n = 24", "bench": r"^BM_GiNaCDerivation/24$",
     "goal": None},
    {"row": "GiNaC's derivation of the same tape (the reference), n = 1000", "bench": r"^BM_GiNaCDerivation/1000$",
     "goal": None},
    {"row": "check, one polygon, every claim, exact, n = 10", "bench": r"^BM_CheckExact/10$", "goal": None},
    {"row": "check, one polygon, every claim, exact, n = 20", "bench": r"^BM_CheckExact/20$", "goal": None},
    {"row": "check, one polygon, every claim, exact, n = 40", "bench": r"^BM_CheckExact/40$", "goal": None},
    {"row": "check, one polygon, every claim, exact, n = 100", "bench": r"^BM_CheckExact/100$",
     "goal": ("max_seconds", 1.0), "note": "<= 1 s"},
    {"row": "check, one polygon, every claim, exact, n = 1000", "bench": r"^BM_CheckExact/1000(/|$)",
     "goal": ("max_seconds", 30.0), "note": "<= 30 s (issue 28; issue 13's was 60 s)"},
    {"row": "check, double, n = 10", "bench": r"^BM_CheckDouble/10$",
     "goal": ("faster_than", r"^BM_CheckExact/10$", 10), "note": ">= 10x faster than exact"},
    {"row": "check, double, n = 20", "bench": r"^BM_CheckDouble/20$",
     "goal": ("faster_than", r"^BM_CheckExact/20$", 10), "note": ">= 10x faster than exact"},
    {"row": "check, double, n = 40", "bench": r"^BM_CheckDouble/40$",
     "goal": ("faster_than", r"^BM_CheckExact/40$", 10), "note": ">= 10x faster than exact"},
    {"row": "check, double, n = 100", "bench": r"^BM_CheckDouble/100$",
     "goal": ("faster_than", r"^BM_CheckExact/100$", 10), "note": ">= 10x faster than exact"},
    {"row": "check, double, n = 1000", "bench": r"^BM_CheckDouble/1000(/|$)",
     "goal": ("max_seconds", 3.0), "note": "<= 3 s (issue 28; issue 13's was 5 s)"},
    {"row": "random exact pentagons, every claim, one core", "bench": r"^BM_ExactCheckAllClaims/5$",
     "goal": ("min_per_second", 10000), "note": ">= 10,000/s"},
    # Rows of the proof, count and mechanism benchmarks (another part of issue 13).
    {"row": "proofs", "bench": r"^BM_Prove(Eq22AllN|PerN)", "goal": None},
    {"row": "every bundled claim proved, default options (`prove`)", "bench": r"^BM_ProveAllBundledClaims(/|$)",
     "goal": ("max_seconds", 10.0), "note": "<= 10 s"},
    {"row": "`count --n 3..200`, every claim of every n", "bench": r"^BM_CountRange/200(/|$)",
     "goal": ("max_seconds", 30.0), "note": "<= 30 s"},
    {"row": "count, every claim of one n, n = 60", "bench": r"^BM_CountClaims/60$", "goal": None},
    {"row": "count, every claim of one n, n = 200", "bench": r"^BM_CountClaims/200$", "goal": None},
    {"row": "count, triangle rank alone, n = 60", "bench": r"^BM_CountTriangleRank/60$", "goal": None},
    {"row": "mechanism chains", "bench": r"^BM_MechanismChain", "goal": None},
    {"row": "prove --topology, every claim of fourbar.yaml (7)", "bench": r"^BM_TopologyProofEveryClaim/0$",
     "goal": ("max_counter", "slowest_claim_s", 5), "note": "<= 5 s per claim (the slowest; measured: all claims, then the slowest)"},
    {"row": "prove --topology, the notes' four-bar acceleration polygon (9)", "bench": r"^BM_TopologyProofEveryClaim/1$",
     "goal": ("max_counter", "slowest_claim_s", 5), "note": "<= 5 s per claim (the slowest; measured: all claims, then the slowest)"},
    {"row": "prove --topology, slider-crank claims (5)", "bench": r"^BM_TopologyProofEveryClaim/2$",
     "goal": ("max_counter", "slowest_claim_s", 5), "note": "<= 5 s per claim (the slowest; measured: all claims, then the slowest)"},
    {"row": "prove --topology, inverted slider-crank claims (6)", "bench": r"^BM_TopologyProofEveryClaim/3$",
     "goal": ("max_counter", "slowest_claim_s", 5), "note": "<= 5 s per claim (the slowest; measured: all claims, then the slowest)"},
    {"row": "prove --topology, Watt six-bar claims (9)", "bench": r"^BM_TopologyProofEveryClaim/4$",
     "goal": ("max_counter", "slowest_claim_s", 60), "note": "<= 60 s per claim (the slowest; measured: all claims, then the slowest)"},
    {"row": "prove --topology, Stephenson six-bar claims (8)", "bench": r"^BM_TopologyProofEveryClaim/5$",
     "goal": ("max_counter", "slowest_claim_s", 60), "note": "<= 60 s per claim (the slowest; measured: all claims, then the slowest)"},
    {"row": "random exact four-bar configurations, a point-acceleration claim, one core",
     "bench": r"^BM_TopologySamplesExact$", "goal": ("min_per_second", 2000), "note": ">= 2,000/s"},
    {"row": "random double four-bar configurations, the same claim", "bench": r"^BM_TopologySamplesDouble$",
     "goal": ("faster_than", r"^BM_TopologySamplesExact$", 10), "note": ">= 10x faster than exact"},
]

BEGIN = "<!-- performance-table:begin (bench/performance_table.py writes this part) -->"
END = "<!-- performance-table:end -->"

UNIT_SECONDS = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}

# Repetitions of each side of a ratio goal (and of the SymPy derivation).
REPETITIONS = 5


def bench_pattern(regex):
    return regex.lstrip("^").split("(")[0].rstrip("$")


def run(binary, patterns, extra=(), whole_names=False):
    """whole_names: a pattern matches a name only up to a "/" or the end (BM_CheckExact/10 is
    not BM_CheckExact/100); otherwise as a prefix (BM_Prove is every BM_Prove...)."""
    bench_filter = "^(" + "|".join(sorted(set(patterns))) + ")" + ("(/|$)" if whole_names else "")
    cmd = [binary, "--benchmark_filter=" + bench_filter, "--benchmark_format=json", *extra]
    print("running:", " ".join(cmd), file=sys.stderr)
    out = subprocess.run(cmd, check=True, stdout=subprocess.PIPE, text=True).stdout
    return json.loads(out)


def ratio_patterns():
    """The benchmarks on either side of a ratio goal."""
    patterns = []
    for r in ROWS:
        goal = r["goal"]
        if goal and goal[0] == "faster_than":
            patterns += [bench_pattern(r["bench"]), bench_pattern(goal[1])]
        if goal and goal[0] == "faster_than_sympy":
            patterns.append(bench_pattern(r["bench"]))
    return patterns


def run_benchmarks(binary):
    """One run of every row's benchmark, then the ratio rows' benchmarks repeated and
    interleaved; the medians of the second run are added as run_type "aggregate"."""
    data = run(binary, [bench_pattern(r["bench"]) for r in ROWS])
    repeated = run(binary, ratio_patterns(),
                   [f"--benchmark_repetitions={REPETITIONS}", "--benchmark_enable_random_interleaving=true",
                    "--benchmark_report_aggregates_only=true"], whole_names=True)
    data["benchmarks"] += [b for b in repeated["benchmarks"] if b.get("aggregate_name") == "median"]
    return data


def sympy_derivation_seconds(n=24):
    """Seconds SymPy takes to derive omega-dot_{n-1,n} of an n-side loop from the twice
    differentiated closure by Cramer's rule written structurally, without a global simplifier
    (as BM_SymbolicDerivation/n derives it)."""
    try:
        import sympy
    except ImportError:
        return None
    from sympy.core.cache import clear_cache
    clear_cache()  # a repetition must not reuse the previous one's cached expressions
    start = time.perf_counter()
    x = sympy.symbols(f"x1:{n}")
    y = sympy.symbols(f"y1:{n}")
    w = sympy.symbols(f"w1:{n}")
    wd = sympy.symbols(f"wd1:{n}")
    # d/dt of sum L_j (cos t_j, sin t_j) = 0 with side n fixed: sum w_j (-y_j, x_j) = 0, and again.
    vel = [sum(-w[j] * y[j] for j in range(n - 1)), sum(w[j] * x[j] for j in range(n - 1))]
    acc = [sum(-wd[j] * y[j] - w[j] ** 2 * x[j] for j in range(n - 1)),
           sum(wd[j] * x[j] - w[j] ** 2 * y[j] for j in range(n - 1))]
    # Cramer's rule on the 2x2 systems in the unknowns of sides n-2 and n-1 (same matrix for
    # velocity and acceleration); the velocity solution is substituted into the acceleration.
    u, v, ud, vd = w[n - 3], w[n - 2], wd[n - 3], wd[n - 2]
    a = [sympy.expand(e).coeff(u) for e in vel]
    b = [sympy.expand(e).coeff(v) for e in vel]
    det = a[0] * b[1] - a[1] * b[0]
    c = [-sympy.expand(e).subs({u: 0, v: 0}) for e in vel]
    u_sol = (c[0] * b[1] - c[1] * b[0]) / det
    v_sol = (a[0] * c[1] - a[1] * c[0]) / det
    ac = [-sympy.expand(e).subs({ud: 0, vd: 0}).subs({u: u_sol, v: v_sol}) for e in acc]
    vd_sol = (a[0] * ac[1] - a[1] * ac[0]) / det
    _ = vd_sol
    return time.perf_counter() - start


def sympy_median_seconds(n=24):
    times = [sympy_derivation_seconds(n) for _ in range(REPETITIONS)]
    return None if None in times else sorted(times)[len(times) // 2]


def find(benchmarks, pattern):
    rx = re.compile(pattern)
    for b in benchmarks:
        if b.get("run_type", "iteration") == "iteration" and rx.search(b["name"]):
            return b
    return None


def find_median(benchmarks, pattern):
    """The median of the repeated run (its name is the benchmark's with "_median"); None if the
    run was not repeated (a saved --json of a plain run)."""
    rx = re.compile(pattern.rstrip("$").replace("(/|$)", "") + r"(/[^_]*)?_median$")
    for b in benchmarks:
        if b.get("aggregate_name") == "median" and rx.search(b["name"]):
            return b
    return None


def seconds(b):
    return b["real_time"] * UNIT_SECONDS[b.get("time_unit", "ns")]


def fmt_time(s):
    if s >= 1:
        return f"{s:.3g} s"
    if s >= 1e-3:
        return f"{s * 1e3:.3g} ms"
    return f"{s * 1e6:.3g} us"


def factor(x):
    """A ratio to three significant digits: a row 2 % over its goal reads 1.02x, not 1x."""
    return f"{x:.3g}"


def evaluate(row, benchmarks, sympy_s):
    b = find(benchmarks, row["bench"])
    if b is None:
        return "not measured yet", "-"
    if b.get("error_occurred"):
        return "error: " + b.get("error_message", ""), "-"
    t = seconds(b)
    goal = row["goal"]
    measured = fmt_time(t)
    if "items_per_second" in b and goal and goal[0] == "min_per_second":
        # Each item's time: an iteration may process many items (1,000 topology samples).
        measured = f"{b['items_per_second']:,.0f}/s ({fmt_time(1 / b['items_per_second'])} each)"
    if goal is None:
        return measured, "no goal set"
    kind = goal[0]
    if kind == "max_seconds":
        return measured, "met" if t <= goal[1] else f"missed: {factor(t / goal[1])}x the goal"
    if kind == "min_per_second":
        rate = b.get("items_per_second", 1 / t)
        return measured, "met" if rate >= goal[1] else f"missed: {factor(goal[1] / rate)}x too slow"
    if kind == "max_counter":
        value = b.get(goal[1])
        if value is None:
            return measured, f"counter {goal[1]} not reported"
        measured += f"; slowest claim {fmt_time(value)}"
        return measured, "met" if value <= goal[2] else f"missed: {factor(value / goal[2])}x the goal"
    if kind == "faster_than":
        mine, other = find_median(benchmarks, row["bench"]), find_median(benchmarks, goal[1])
        of = f"medians of {REPETITIONS} interleaved runs"
        if mine is None or other is None:  # a saved plain run: one run each
            mine, other, of = b, find(benchmarks, goal[1]), "one run each"
        if other is None:
            return measured, "reference not measured"
        ratio = seconds(other) / seconds(mine)
        name = other["name"].removesuffix("_median")
        measured = f"{fmt_time(seconds(mine))}; {ratio:.3g}x faster than {name} ({of})"
        return measured, "met" if ratio >= goal[2] else f"missed: {factor(ratio)}x, goal {goal[2]}x"
    if kind == "faster_than_sympy":
        if sympy_s is None:
            return measured + "; SymPy not measured", "-"
        mine = find_median(benchmarks, row["bench"])
        of = f"medians of {REPETITIONS} runs" if mine is not None else "one run each"
        t = seconds(mine) if mine is not None else t
        ratio = sympy_s / t
        measured = f"{fmt_time(t)}; SymPy {fmt_time(sympy_s)}, {ratio:,.0f}x ({of})"
        return measured, "met" if ratio >= goal[1] else f"missed: {factor(ratio)}x, goal {goal[1]}x"
    raise ValueError(f"unknown goal {kind}")


def goal_text(row):
    if row["goal"] is None:
        return row.get("note", "-")
    return row.get("note", str(row["goal"]))


def table(benchmarks, sympy_s, context):
    lines = [
        f"Measured {context.get('date', '?')} on {context.get('host_name', '?')} "
        f"({context.get('num_cpus', '?')} CPUs, Google Benchmark library built as {context.get('library_build_type', '?')}), "
        "one run of `bash bench/make_performance_table.sh` (ratios: medians of repeated runs).",
        "",
        "| row | benchmark | goal | measured | goal met |",
        "|---|---|---|---|---|",
    ]
    for row in ROWS:
        measured, verdict = evaluate(row, benchmarks, sympy_s)
        name = row["bench"].lstrip("^").replace("(/|$)", "").rstrip("$")
        lines.append(f"| {row['row']} | `{name}` | {goal_text(row)} | {measured} | {verdict} |")
    return "\n".join(lines) + "\n"


SYMPY_KEY = "linkproof_sympy_median_seconds"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bench", default="build/bench/linkproof_bench", help="the benchmark binary")
    ap.add_argument("--json", help="a saved --benchmark_format=json output instead of running")
    ap.add_argument("--doc", default="docs/performance.md", help="the page whose table is rewritten")
    ap.add_argument("--no-sympy", action="store_true", help="skip the SymPy timing")
    ap.add_argument("--save-json", help="also write the benchmark results (both runs) to this file")
    args = ap.parse_args()

    data = json.load(open(args.json)) if args.json else run_benchmarks(args.bench)
    # SymPy's timing belongs to the run: a saved run keeps its own, and re-rendering it does not
    # time SymPy again (a ratio would otherwise mix two runs).
    if SYMPY_KEY in data:
        sympy_s = data[SYMPY_KEY]
    else:
        sympy_s = None if args.no_sympy else sympy_median_seconds(24)
        data[SYMPY_KEY] = sympy_s
    if args.save_json:
        with open(args.save_json, "w") as f:
            json.dump(data, f, indent=1)
    text = table(data.get("benchmarks", []), sympy_s, data.get("context", {}))

    doc = open(args.doc).read() if os.path.exists(args.doc) else f"# Performance\n\n{BEGIN}\n{END}\n"
    if BEGIN not in doc or END not in doc:
        sys.exit(f"{args.doc}: the markers {BEGIN!r} and {END!r} are missing")
    head, rest = doc.split(BEGIN, 1)
    _, tail = rest.split(END, 1)
    with open(args.doc, "w") as f:
        f.write(head + BEGIN + "\n" + text + END + tail)
    print(text)


if __name__ == "__main__":
    main()

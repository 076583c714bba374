#!/usr/bin/env bash
# Regenerates the table of docs/performance.md: builds linkproof_bench (Release-like flags of the
# configured build/), runs the rows' benchmarks once with --benchmark_format=json and times the
# SymPy derivation in the same run (bench/performance_table.py).
#   bash bench/make_performance_table.sh            # uses build/
#   BUILD=build-release bash bench/make_performance_table.sh
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${BUILD:-build}
# cmake --build, not ninja: build/ is a Makefile tree when scripts/build.sh made it.
nice -n 10 cmake --build "$BUILD" -j2 --target linkproof_bench
python3 bench/performance_table.py --bench "$BUILD/bench/linkproof_bench" --doc docs/performance.md "$@"

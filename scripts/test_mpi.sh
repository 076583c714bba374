#!/usr/bin/env bash
# The MPI driver against a plain single-process sweep: `mpirun -np 2 linkproof_mpi` must write
# the same result file, byte for byte, and the same JSON and text reports (but for their run
# time), for a polygon sweep and for a sweep of a mechanism topology (the bundled four-bar, whose
# claim file has true and wrong claims).
#   scripts/test_mpi.sh [BUILD_DIR]     (default: build)
# Runs as root in CI (--allow-run-as-root) and oversubscribes the one machine (--oversubscribe).
set -euo pipefail
build="$(cd "${1:-build}" && pwd)"
source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
if [[ ! -x "$build/linkproof_mpi" ]]; then
  echo "test_mpi: ERROR: $build/linkproof_mpi was not built (is libopenmpi-dev installed?)" >&2
  exit 1
fi
work="$(mktemp -d "${TMPDIR:-/tmp}/linkproof-mpi.XXXXXX")"
trap 'rm -rf -- "$work"' EXIT
start=$SECONDS
rc=0

# The text reports print the run time on one line: "... cases in S s" (polygons) or "...; S s"
# (topology); that line is the only one allowed to differ.
without_time() { grep -v -E '[0-9.]+ s$' "$1"; }

# compare NAME SWEEP_OPTIONS...: `linkproof sweep` (one process) against `mpirun -np 2
# linkproof_mpi` with the same options: the result file, the JSON report, the text report.
compare() {
  local name="$1"
  shift
  echo "==> test_mpi ($name): linkproof sweep $* --jobs 1 --out single.jsonl --json"
  "$build/linkproof" sweep "$@" --jobs 1 --out "$work/$name-single.jsonl" --json > "$work/$name-single.json" ||
    [[ $? == 1 ]]
  "$build/linkproof" sweep "$@" --jobs 1 > "$work/$name-single.txt" || [[ $? == 1 ]]
  echo "==> test_mpi ($name): mpirun -np 2 linkproof_mpi $* --out mpi.jsonl --json"
  local code=0
  mpirun -np 2 --oversubscribe --allow-run-as-root "$build/linkproof_mpi" "$@" \
    --out "$work/$name-mpi.jsonl" --json > "$work/$name-mpi.json" || code=$?
  mpirun -np 2 --oversubscribe --allow-run-as-root "$build/linkproof_mpi" "$@" > "$work/$name-mpi.txt" || true
  local single_code
  single_code="$(grep -o '"exit_status": *[0-9]*' "$work/$name-single.json" | grep -o '[0-9]*$')"
  if [[ "$code" != "$single_code" ]]; then
    echo "test_mpi: ERROR ($name): linkproof_mpi exited $code, linkproof sweep $single_code" >&2
    rc=1
  fi
  if cmp "$work/$name-single.jsonl" "$work/$name-mpi.jsonl"; then
    echo "==> test_mpi ($name): result files identical ($(wc -l < "$work/$name-mpi.jsonl") lines)"
  else
    echo "test_mpi: ERROR ($name): the MPI result file differs from the single-process one" >&2
    rc=1
  fi
  if diff <(grep -v '"seconds"' "$work/$name-single.json") <(grep -v '"seconds"' "$work/$name-mpi.json"); then
    echo "==> test_mpi ($name): JSON reports identical (but for \"seconds\")"
  else
    echo "test_mpi: ERROR ($name): the MPI JSON report differs from the single-process one" >&2
    rc=1
  fi
  if diff <(without_time "$work/$name-single.txt") <(without_time "$work/$name-mpi.txt"); then
    echo "==> test_mpi ($name): text reports identical (but for the run time)"
  else
    echo "test_mpi: ERROR ($name): the MPI text report differs from the single-process one" >&2
    rc=1
  fi
}

compare polygons --n 4..9 --count 8 --seed 13
# 300 configurations: the wrong claims fail on most of them (disproved, counterexamples shrunk).
compare topology --topology "$source_dir/verify/scenes/mechanisms/seed001_fourbar.yaml" \
  --claims "$source_dir/verify/claims/mechanisms/fourbar.yaml" --count 300 --seed 3

echo "==> test_mpi: done in $((SECONDS - start)) s"
exit "$rc"

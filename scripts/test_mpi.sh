#!/usr/bin/env bash
# The MPI driver against a plain single-process sweep: `mpirun -np 2 linkproof_mpi` must write
# the same result file, byte for byte, and the same JSON report (but for its run time).
#   scripts/test_mpi.sh [BUILD_DIR]     (default: build)
# Runs as root in CI (--allow-run-as-root) and oversubscribes the one machine (--oversubscribe).
set -euo pipefail
build="$(cd "${1:-build}" && pwd)"
if [[ ! -x "$build/linkproof_mpi" ]]; then
  echo "test_mpi: ERROR: $build/linkproof_mpi was not built (is libopenmpi-dev installed?)" >&2
  exit 1
fi
work="$(mktemp -d "${TMPDIR:-/tmp}/linkproof-mpi.XXXXXX")"
trap 'rm -rf -- "$work"' EXIT
sweep=(--n 4..9 --count 8 --seed 13)
start=$SECONDS

echo "==> test_mpi: linkproof sweep ${sweep[*]} --jobs 1 --out single.jsonl --json"
"$build/linkproof" sweep "${sweep[@]}" --jobs 1 --out "$work/single.jsonl" --json > "$work/single.json"
echo "==> test_mpi: mpirun -np 2 linkproof_mpi ${sweep[*]} --out mpi.jsonl --json"
mpirun -np 2 --oversubscribe --allow-run-as-root "$build/linkproof_mpi" "${sweep[@]}" \
  --out "$work/mpi.jsonl" --json > "$work/mpi.json"

rc=0
if cmp "$work/single.jsonl" "$work/mpi.jsonl"; then
  echo "==> test_mpi: result files identical ($(wc -l < "$work/mpi.jsonl") lines)"
else
  echo "test_mpi: ERROR: the MPI result file differs from the single-process one" >&2
  rc=1
fi
if diff <(grep -v '"seconds"' "$work/single.json") <(grep -v '"seconds"' "$work/mpi.json"); then
  echo "==> test_mpi: JSON reports identical (but for \"seconds\")"
else
  echo "test_mpi: ERROR: the MPI report differs from the single-process one" >&2
  rc=1
fi
echo "==> test_mpi: done in $((SECONDS - start)) s"
exit "$rc"

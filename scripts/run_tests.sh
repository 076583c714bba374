#!/usr/bin/env bash
# Builds (build.sh), then runs the whole test suite with ctest, one job per core. Exits with
# ctest's exit code. Extra arguments are passed to build.sh (cmake configure arguments).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/build.sh "$@"

jobs="$(nproc)"
echo "==> run_tests: ctest --test-dir build --output-on-failure -j${jobs}"
rc=0
ctest --test-dir build --output-on-failure -j"${jobs}" || rc=$?
echo "==> run_tests: ctest exited with ${rc}"
exit "${rc}"

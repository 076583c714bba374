#!/usr/bin/env bash
# Builds (build.sh), then runs the main job: checks the bundled pentagon scene and prints the
# claim table. Exits with linkproof's exit code (0 as expected, 1 a claim failed, 2 bad input,
# 3 internal error). Extra arguments are passed to build.sh (cmake configure arguments).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

# The main job needs the program alone: the tests and benchmarks are built by run_tests.sh.
LINKPROOF_BUILD_TARGETS=linkproof bash scripts/build.sh "$@"

echo "==> run_example: build/linkproof check verify/scenes/pentagon.yaml"
rc=0
build/linkproof check verify/scenes/pentagon.yaml || rc=$?
echo "==> run_example: linkproof exited with ${rc}"
exit "${rc}"

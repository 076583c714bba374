#!/usr/bin/env bash
# Builds the unit tests under AddressSanitizer + UndefinedBehaviorSanitizer (Debug, in
# build-asan/, -DLINKPROOF_SANITIZE=ON) and runs the fast label (`ctest -L unit`). Any sanitizer
# report aborts the test that triggered it. Extra arguments go to the cmake configure step.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/install_deps.sh

jobs="$(nproc)"
echo "==> sanitizer: cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DLINKPROOF_SANITIZE=ON $*"
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DLINKPROOF_SANITIZE=ON -DLINKPROOF_BUILD_BENCH=OFF "$@"
echo "==> sanitizer: cmake --build build-asan --target linkproof_tests -j${jobs}"
cmake --build build-asan --target linkproof_tests -j"${jobs}"
# Leaks are not checked: GiNaC and CLN keep global tables alive until exit by design.
export ASAN_OPTIONS="detect_leaks=0:abort_on_error=1:strict_string_checks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
echo "==> sanitizer: ctest --test-dir build-asan -L unit -j${jobs}"
rc=0
ctest --test-dir build-asan -L unit --output-on-failure -j"${jobs}" || rc=$?
echo "==> sanitizer: ctest exited with ${rc}"
exit "${rc}"

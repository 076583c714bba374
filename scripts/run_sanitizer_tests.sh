#!/usr/bin/env bash
# The second stage of CI (docs/fuzzing.md): one clang tree, build-fuzz/, with every linkproof
# object instrumented for AddressSanitizer + UndefinedBehaviorSanitizer and libFuzzer coverage
# (-DLINKPROOF_FUZZ=ON, -O1). In it:
#   1. the unit tests (target linkproof_unit_tests, every test outside tests/verify/ and
#      tests/slow/) under the sanitizers (`ctest -L unit`): any report aborts its test;
#   2. the fuzz targets (tests/fuzz/CMakeLists.txt), LINKPROOF_FUZZ_RUNS executions each from the seed corpus
#      (`ctest -L fuzz`): a crash, a sanitizer report, a hang (> 10 s) or > 2 GB fails.
# In CI (CI set, as .ci/run is run) a compiler warning fails the build, as in scripts/build.sh:
# -DLINKPROOF_WERROR=ON (cmake/LinkproofWarnings.cmake), so clang's warnings count as g++'s do,
# and the tree is a unity build, -DLINKPROOF_UNITY=ON (cmake/LinkproofUnity.cmake), as CI's g++ one.
# Extra arguments go to the cmake configure step (e.g. -DLINKPROOF_FUZZ_RUNS=100000).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/install_deps.sh

jobs="$(nproc)"
launcher=()
if command -v ccache >/dev/null 2>&1; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
generator=()
if command -v ninja >/dev/null 2>&1; then generator=(-G Ninja); fi
ci_flags=()
if [[ -n "${CI:-}" ]]; then ci_flags=(-DLINKPROOF_WERROR=ON -DLINKPROOF_UNITY=ON); fi
configure=(cmake -S . -B build-fuzz "${generator[@]}" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Debug
           "-DCMAKE_CXX_FLAGS_DEBUG=-O1 -gline-tables-only" -DLINKPROOF_FUZZ=ON -DLINKPROOF_BUILD_BENCH=OFF
           "${launcher[@]}" "${ci_flags[@]}" "$@")
echo "==> sanitizer: ${configure[*]}"
"${configure[@]}"
targets=(linkproof_unit_tests fuzz_polygon_scene fuzz_mechanism_scene fuzz_claim_file fuzz_cli_args fuzz_report
         fuzz_check_data)
echo "==> sanitizer: cmake --build build-fuzz --target ${targets[*]} -j${jobs}"
build_start=$SECONDS
cmake --build build-fuzz --target "${targets[@]}" -j"${jobs}"
echo "==> sanitizer: build took $((SECONDS - build_start)) s"

# Leaks are not checked: GiNaC and CLN keep global tables alive until exit by design.
# Leak checking is off in the binaries themselves (cmake/sanitizer_defaults.cpp).
export ASAN_OPTIONS="detect_leaks=0:abort_on_error=1:strict_string_checks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
rc=0
echo "==> sanitizer: ctest --test-dir build-fuzz -L unit -j${jobs}"
ctest --test-dir build-fuzz -L unit --output-on-failure -j"${jobs}" || rc=$?
echo "==> sanitizer: unit tests exited with ${rc}"
fuzz_rc=0
echo "==> sanitizer: ctest --test-dir build-fuzz -L fuzz -j${jobs}"
ctest --test-dir build-fuzz -L fuzz --output-on-failure -j"${jobs}" || fuzz_rc=$?
echo "==> sanitizer: fuzz runs exited with ${fuzz_rc}"
if [[ ${rc} -eq 0 ]]; then rc=${fuzz_rc}; fi
exit "${rc}"

#!/usr/bin/env bash
# Installs the dependencies (install_deps.sh), then configures build/ (Release at -O2, the code
# generation of RelWithDebInfo without its debug information, which costs about a quarter of the
# compile time; configure build/ yourself with RelWithDebInfo to debug or profile) and builds it
# with one job per core. Extra arguments are passed to the cmake configure step, e.g.
#   scripts/build.sh -DLINKPROOF_BUILD_BENCH=OFF
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/install_deps.sh

jobs="$(nproc)"
configure=(cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-O2 -DNDEBUG")
# In CI a warning fails the build (cmake/LinkproofWarnings.cmake); a build prints none. CI also
# builds from cold as a unity build (cmake/LinkproofUnity.cmake: batches of sources per
# translation unit, about half the compile CPU); developers keep one translation unit per file.
if [[ -n "${CI:-}" ]]; then configure+=(-DLINKPROOF_WERROR=ON -DLINKPROOF_UNITY=ON); fi
configure+=("$@")
echo "==> build: ${configure[*]}"
"${configure[@]}"
# LINKPROOF_BUILD_TARGETS (space separated) builds only those targets (run_example.sh: linkproof).
targets=()
for t in ${LINKPROOF_BUILD_TARGETS:-}; do targets+=(--target "$t"); done
echo "==> build: cmake --build build -j${jobs} ${targets[*]}"
cmake --build build -j"${jobs}" "${targets[@]}"
echo "==> build: done"

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
configure=(cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-O2 -DNDEBUG" "$@")
echo "==> build: ${configure[*]}"
"${configure[@]}"
echo "==> build: cmake --build build -j${jobs}"
cmake --build build -j"${jobs}"
echo "==> build: done"

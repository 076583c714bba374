#!/usr/bin/env bash
# Installs the dependencies (install_deps.sh), then configures build/ (RelWithDebInfo) and builds
# it with one job per core. Extra arguments are passed to the cmake configure step, e.g.
#   scripts/build.sh -DLINKPROOF_BUILD_BENCH=OFF
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/install_deps.sh

jobs="$(nproc)"
echo "==> build: cmake -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo $*"
cmake -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo "$@"
echo "==> build: cmake --build build -j${jobs}"
cmake --build build -j"${jobs}"
echo "==> build: done"

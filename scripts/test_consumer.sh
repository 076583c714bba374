#!/usr/bin/env bash
# Tests the installed package: installs an already-built linkproof build tree into a temporary
# prefix, then configures, builds and runs the consumer project tests/consumer against it with
# find_package(linkproof); then, when linkproof::testing was installed, the oracle consumer
# tests/oracle_consumer (property tests with linkproof's generators and matchers): its correct
# properties must pass, its planted bug must be caught with a small shrunk scene, and the
# installed `linkproof check` must read that scene. The build tree is only read; everything else lives in temporary
# directories that are removed on exit.
#   scripts/test_consumer.sh [BUILD_DIR]     (default: build; relative to the current directory)
set -euo pipefail
build_arg="${1:-build}"
# Resolve the build directory before leaving the caller's directory.
if [[ ! -d "$build_arg" ]]; then
  echo "test_consumer: ERROR: build directory '$build_arg' does not exist (build first)" >&2
  exit 2
fi
build_dir="$(cd "$build_arg" && pwd)"
cd "$(dirname "${BASH_SOURCE[0]}")/.."
repo_root="$(pwd)"

prefix="$(mktemp -d "${TMPDIR:-/tmp}/linkproof-prefix.XXXXXX")"
consumer_build="$(mktemp -d "${TMPDIR:-/tmp}/linkproof-consumer.XXXXXX")"
oracle_build="$(mktemp -d "${TMPDIR:-/tmp}/linkproof-oracle.XXXXXX")"
cleanup() { rm -rf -- "$prefix" "$consumer_build" "$oracle_build"; }
trap cleanup EXIT

# Build the consumer with the compiler and build type of the installed tree.
cache="$build_dir/CMakeCache.txt"
cmake_args=()
compiler="$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$cache" 2>/dev/null | head -n1)"
[[ -n "$compiler" ]] && cmake_args+=("-DCMAKE_CXX_COMPILER=$compiler")
build_type="$(sed -n 's/^CMAKE_BUILD_TYPE:[A-Z]*=//p' "$cache" 2>/dev/null | head -n1)"
[[ -n "$build_type" ]] && cmake_args+=("-DCMAKE_BUILD_TYPE=$build_type")

echo "==> test_consumer: cmake --install $build_dir --prefix $prefix"
cmake --install "$build_dir" --prefix "$prefix"
if [[ ! -x "$prefix/bin/linkproof" ]]; then
  echo "test_consumer: ERROR: the install did not provide bin/linkproof" >&2
  exit 1
fi

echo "==> test_consumer: cmake -S tests/consumer -B $consumer_build -DCMAKE_PREFIX_PATH=$prefix ${cmake_args[*]}"
cmake -S "$repo_root/tests/consumer" -B "$consumer_build" \
  -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON "${cmake_args[@]}"

# The package must come from the fresh install, not from some other linkproof on the system.
found_dir="$(sed -n 's/^linkproof_DIR:[A-Z]*=//p' "$consumer_build/CMakeCache.txt")"
echo "==> test_consumer: find_package(linkproof) used $found_dir"
if [[ "$found_dir" != "$prefix"/* ]]; then
  echo "test_consumer: ERROR: linkproof was found outside the test prefix $prefix" >&2
  exit 1
fi

echo "==> test_consumer: cmake --build $consumer_build -j$(nproc)"
cmake --build "$consumer_build" -j"$(nproc)"

echo "==> test_consumer: $consumer_build/linkproof_consumer"
rc=0
"$consumer_build/linkproof_consumer" || rc=$?
echo "==> test_consumer: consumer exited with ${rc}"
[[ "$rc" -eq 0 ]] || exit "$rc"

if [[ ! -f "$prefix/lib/cmake/linkproof/linkproofTestingTargets.cmake" ]]; then
  echo "==> test_consumer: linkproof::testing not installed (no RapidCheck/GTest at build time): oracle consumer skipped"
  exit 0
fi
# Asked for without RapidCheck, the component must be refused with a message that names it and
# what it needs (CMake's own message names neither).
missing_build="$(mktemp -d "${TMPDIR:-/tmp}/linkproof-missing.XXXXXX")"
missing_src="$missing_build/src"
mkdir -p "$missing_src"
printf '%s\n' 'cmake_minimum_required(VERSION 3.22)' 'project(missing_testing LANGUAGES CXX)' \
  'find_package(linkproof 0.1 REQUIRED COMPONENTS testing)' >"$missing_src/CMakeLists.txt"
missing_log="$missing_build/configure.log"
if cmake -S "$missing_src" -B "$missing_build/b" -DCMAKE_PREFIX_PATH="$prefix" \
     -DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON -DCMAKE_DISABLE_FIND_PACKAGE_rapidcheck=ON >"$missing_log" 2>&1; then
  echo "test_consumer: ERROR: COMPONENTS testing was found without RapidCheck" >&2
  exit 1
fi
if ! tr '\n' ' ' <"$missing_log" | tr -s ' ' | grep -q 'component `testing` (linkproof::testing) is not available: it needs RapidCheck'; then
  cat "$missing_log"
  echo "test_consumer: ERROR: the refusal does not name the component and RapidCheck" >&2
  exit 1
fi
rm -rf -- "$missing_build"
echo "==> test_consumer: COMPONENTS testing without RapidCheck is refused, naming what is missing"

echo "==> test_consumer: oracle consumer (tests/oracle_consumer) against linkproof::testing"
cmake -S "$repo_root/tests/oracle_consumer" -B "$oracle_build" \
  -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON "${cmake_args[@]}"
cmake --build "$oracle_build" -j"$(nproc)"
export RC_PARAMS="${RC_PARAMS:-seed=20261121 max_success=100}"
echo "==> test_consumer: RC_PARAMS=$RC_PARAMS"
"$oracle_build/oracle_consumer" --gtest_filter='-*PlantedBug*'
log="$oracle_build/planted_bug.log"
rc=0
"$oracle_build/oracle_consumer" --gtest_filter='*PlantedBug*' >"$log" 2>&1 || rc=$?
cat "$log"
if [[ "$rc" -eq 0 ]]; then
  echo "test_consumer: ERROR: the planted bug was not caught" >&2
  exit 1
fi
scene="$oracle_build/shrunk_scene.yaml"
sed -n '/^--- scene ---$/,/^--- end scene ---$/p' "$log" | sed '1d;$d' >"$scene"
if [[ ! -s "$scene" ]]; then
  echo "test_consumer: ERROR: the failure printed no scene" >&2
  exit 1
fi
echo "==> test_consumer: the shrunk scene, read by the installed linkproof check:"
"$prefix/bin/linkproof" check "$scene"
echo "==> test_consumer: planted bug caught and shrunk; oracle consumer OK"
exit 0

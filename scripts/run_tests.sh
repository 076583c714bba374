#!/usr/bin/env bash
# Builds (build.sh), then runs the whole test suite with ctest, one job per core, then the MPI
# driver against a single-process sweep (test_mpi.sh). Exits non-zero if either fails. Extra
# arguments are passed to build.sh (cmake configure arguments).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash scripts/build.sh "$@"

jobs="$(nproc)"
echo "==> run_tests: ctest --test-dir build --output-on-failure -j${jobs}"
rc=0
ctest --test-dir build --output-on-failure -j"${jobs}" || rc=$?
echo "==> run_tests: ctest exited with ${rc}"

# The MPI driver against the single-process sweep (linkproof_mpi is built when MPI is found;
# install_deps.sh installs OpenMPI). About 10 s on 2 cores.
echo "==> run_tests: scripts/test_mpi.sh build"
mpi_rc=0
bash scripts/test_mpi.sh build || mpi_rc=$?
echo "==> run_tests: test_mpi.sh exited with ${mpi_rc}"
if [[ "${rc}" -eq 0 ]]; then rc="${mpi_rc}"; fi
exit "${rc}"

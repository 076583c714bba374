#!/usr/bin/env bash
# Installs linkproof's build and test dependencies from Debian (12, bookworm) packages.
# Idempotent: if every package is already installed, apt is not touched at all, so reruns are fast.
# Runs apt as root, or through sudo when not root; fails with a clear message otherwise.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

PACKAGES=(
  build-essential g++ cmake pkg-config
  libginac-dev libcln-dev libeigen3-dev libyaml-cpp-dev nlohmann-json3-dev libcli11-dev libfmt-dev
  libgtest-dev librapidcheck-dev libbenchmark-dev
  libopenmpi-dev openmpi-bin
  # `linkproof report`: KaTeX inlined into HTML reports; the tests render them in headless
  # Chromium and compile the LaTeX with pdflatex (texlive-latex-base alone suffices).
  libjs-katex chromium texlive-latex-base
  # The sanitizer and fuzzing stage of CI (scripts/run_sanitizer_tests.sh): clang with libFuzzer
  # and the sanitizer runtimes, and Ninja.
  clang libclang-rt-14-dev ninja-build
)

echo "==> install_deps: checking ${#PACKAGES[@]} Debian packages with dpkg-query"
missing=()
for pkg in "${PACKAGES[@]}"; do
  status="$(dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null || true)"
  if [[ "$status" != "install ok installed" ]]; then
    missing+=("$pkg")
  fi
done

if [[ ${#missing[@]} -eq 0 ]]; then
  echo "==> install_deps: all packages already installed; skipping apt"
  exit 0
fi
echo "==> install_deps: missing: ${missing[*]}"

if [[ "$(id -u)" -eq 0 ]]; then
  as_root=()
elif command -v sudo >/dev/null 2>&1; then
  as_root=(sudo)
else
  echo "install_deps: ERROR: packages missing (${missing[*]}), and this script is neither running" >&2
  echo "install_deps: as root nor able to find sudo. Rerun as root, or install them yourself:" >&2
  echo "  apt-get install ${missing[*]}" >&2
  exit 1
fi

echo "==> install_deps: ${as_root[*]:+${as_root[*]} }apt-get update"
"${as_root[@]}" apt-get update
echo "==> install_deps: ${as_root[*]:+${as_root[*]} }apt-get install -y --no-install-recommends ${PACKAGES[*]}"
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive \
  apt-get install -y --no-install-recommends "${PACKAGES[@]}"
echo "==> install_deps: done"

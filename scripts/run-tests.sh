#!/usr/bin/env bash
# One command from a fresh Debian 12 machine to a tested build: install
# dependencies, build (Release), run the whole ctest suite.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/install-dependencies.sh"
bash "$root/scripts/build.sh"
cd "${BUILD_DIR:-$root/build}"
ctest --output-on-failure -j "$(nproc)"

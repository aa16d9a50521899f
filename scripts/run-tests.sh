#!/usr/bin/env bash
# One command from a fresh Debian 12 machine to a tested build: install
# dependencies, check the format (.clang-format) and the layers of the
# source areas, build Release and run every case test, then build Debug
# (deal.II's debug library: every Assert on) and run the unit tests and the
# cases labelled "debug" there. The unit programs are compiled once, in
# Debug. FORMSOLVE_SKIP_DEBUG=1 leaves the Debug part out and runs the unit
# tests in Release instead.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/install-dependencies.sh"
bash "$root/scripts/format.sh" --check
/usr/bin/python3 "$root/scripts/check-layers.py"
if [ "${FORMSOLVE_SKIP_DEBUG:-0}" = 1 ]; then
  bash "$root/scripts/build.sh"
else
  FORMSOLVE_UNIT_TESTS=OFF bash "$root/scripts/build.sh"
fi
# The BLAS kernels formsolve-run would choose (OpenBLAS may fall back to
# Prescott's on a virtual machine): the same results, faster.
eval "$(bash "$root/scripts/formsolve-run" --env)"
(cd "${BUILD_DIR:-$root/build}" && ctest --output-on-failure -j "$(nproc)")
if [ "${FORMSOLVE_SKIP_DEBUG:-0}" != 1 ]; then
  BUILD_DIR="$root/build-debug" BUILD_TYPE=Debug bash "$root/scripts/build.sh"
  (cd "$root/build-debug" && ctest --output-on-failure -j "$(nproc)" -L "unit|debug")
fi

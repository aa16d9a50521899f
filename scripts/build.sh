#!/usr/bin/env bash
# Configures and builds formsolve in build/ (or $BUILD_DIR), as $BUILD_TYPE
# (Release unless set; Debug links deal.II's debug library, assertions on).
# FORMSOLVE_UNIT_TESTS=OFF leaves the unit test programs out.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$root/build}
type=${BUILD_TYPE:-Release}
mkdir -p "$build"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE="$type" \
  -DFORMSOLVE_UNIT_TESTS="${FORMSOLVE_UNIT_TESTS:-ON}" > "$build/cmake.log" 2>&1 \
  || { cat "$build/cmake.log"; exit 1; }
cmake --build "$build" -j "$(nproc)"

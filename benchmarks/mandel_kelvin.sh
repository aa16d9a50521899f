#!/usr/bin/env bash
# material/mandel.h's fixed-size conversions against deal.II's
# Physics::Notation::Kelvin, ns per call (doc/theory.md, section 5a).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$root/build}
[ -f "$build/Makefile" ] || bash "$root/scripts/build.sh"
make -C "$build" mandel_kelvin > /dev/null
for run in 1 2 3; do "$build/mandel_kelvin"; done

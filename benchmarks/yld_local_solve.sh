#!/usr/bin/env bash
# One Yld2004-18p local solve and one evaluation of sigma_bar with its
# Hessian, microseconds per call (doc/forming-results.md, the cost of the
# non-quadratic law); three runs.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$root/build}
[ -f "$build/Makefile" ] || bash "$root/scripts/build.sh"
make -C "$build" yld_local_solve > /dev/null
for run in 1 2 3; do "$build/yld_local_solve"; done

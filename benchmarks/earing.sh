#!/usr/bin/env bash
# Regenerates the earing-cup section of doc/forming-results.md: both Hill48
# calibrations, planar isotropy and the holder, friction and flow-curve
# variants, quarter model on 2 ranks (9 runs, about 20 min on 2 cores; runs
# in results/earing/ are reused unless --force).
# Usage: bash benchmarks/earing.sh [--force]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
eval "$(bash "$root/scripts/formsolve-run" --env)"
[ -x "$root/build/formsolve" ] || bash "$root/scripts/build.sh"
export OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cd "$root/benchmarks"
exec /usr/bin/python3 "$root/benchmarks/earing_report.py" "$@"

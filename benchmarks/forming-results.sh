#!/usr/bin/env bash
# Regenerates doc/forming-results.md's tables and charts (predictions of the
# reference cup and the limiting drawing ratio); about 30 min on 2 cores.
# Usage: bash benchmarks/forming-results.sh [--jobs N] [--force] [--part predictions|ldr|all]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# The BLAS kernels formsolve-run would choose (unless OPENBLAS_CORETYPE is set).
eval "$(bash "$root/scripts/formsolve-run" --env)"
[ -x "$root/build/formsolve" ] || bash "$root/scripts/build.sh"
export OMP_NUM_THREADS=1
exec /usr/bin/python3 "$root/benchmarks/forming_results.py" "$@"

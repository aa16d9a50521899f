#!/usr/bin/env bash
# Regenerates the sensitivity study of doc/forming-results.md (one modelling
# choice at a time, four reference cups, 60 axisymmetric runs; about 25 min on
# 2 cores, runs already in results/forming/ are reused unless --force).
# Usage: bash benchmarks/sensitivity.sh [--jobs N] [--force]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
eval "$(bash "$root/scripts/formsolve-run" --env)"
[ -x "$root/build/formsolve" ] || bash "$root/scripts/build.sh"
export OMP_NUM_THREADS=1
cd "$root/benchmarks"
exec /usr/bin/python3 "$root/benchmarks/sensitivity.py" "$@"

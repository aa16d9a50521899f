#!/usr/bin/env bash
# Hosford a = 6 beside Hill48 for the reference cups of the three steels
# (doc/forming-results.md, "Hosford's criterion for the steels"; 8 axisymmetric
# runs, a few minutes; runs in results/forming/ are reused unless --force).
# Usage: bash benchmarks/hosford_steels.sh [--force]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
eval "$(bash "$root/scripts/formsolve-run" --env)"
[ -x "$root/build/formsolve" ] || bash "$root/scripts/build.sh"
export OMP_NUM_THREADS=1
cd "$root/benchmarks"
exec /usr/bin/python3 "$root/benchmarks/hosford_steels.py" "$@"

#!/usr/bin/env bash
# Regenerates the draw-bead section of doc/forming-results.md: a strip drawn
# through a round bead as tool geometry and as an equivalent line bead
# (benchmarks/bead-strip/, 4 runs on 1 rank, about 15 min on 2 cores; runs
# in results/bead-strip/ are reused unless --force).
# Usage: bash benchmarks/bead_strip.sh [--force]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
eval "$(bash "$root/scripts/formsolve-run" --env)"
[ -x "$root/build/formsolve" ] || bash "$root/scripts/build.sh"
export OMP_NUM_THREADS=1
cd "$root/benchmarks"
exec /usr/bin/python3 "$root/benchmarks/bead_strip_report.py" "$@"

#!/usr/bin/env bash
# Regenerates the draw-bead sections of doc/forming-results.md: a strip drawn
# through a round bead as tool geometry and as an equivalent line bead
# (benchmarks/bead-strip/, 4 runs, about 30 min), and the square cup with
# beads along its sides (3 runs, about 3 min); all on 1 rank. Runs in
# results/bead-strip/ and results/bead-square-cup/ are reused unless --force.
# Usage: bash benchmarks/beads.sh [--force]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
eval "$(bash "$root/scripts/formsolve-run" --env)"
[ -x "$root/build/formsolve" ] || bash "$root/scripts/build.sh"
export OMP_NUM_THREADS=1
cd "$root/benchmarks"
/usr/bin/python3 "$root/benchmarks/bead_strip_report.py" "$@"
/usr/bin/python3 "$root/benchmarks/bead_square_cup.py" "$@"

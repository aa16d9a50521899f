#!/usr/bin/env bash
# Mesh convergence of the square cup (doc/tools.md section 2, "How sure the
# prediction is"): prm/square-cup-reference.prm one level finer in the plane
# (Planform refinements 6: 1.17 mm, 0.59 mm at the radii, 4x the cells),
# drawn 40 mm on 2 ranks, against the run of benchmarks/square_cup.sh
# (COARSE, default results/square-cup/square-cup-reference). Prints both
# columns and the draw-in difference over the whole draw. About 1 h 50 min on
# 2 cores, so not part of benchmarks/tools.sh; a checkpoint every 10 steps,
# and an interrupted run continues with RESUME=1 (doc/user-guide.md, 1.5).
#   [RESUME=1] bash benchmarks/square_cup_convergence.sh [OUTDIR] [COARSE]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/results/square-cup}/square-cup-reference-fine
coarse=${2:-$root/results/square-cup/square-cup-reference}
export OPENBLAS_CORETYPE=${OPENBLAS_CORETYPE:-Haswell}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mkdir -p "$(dirname "$out")"
resume=()
if [ "${RESUME:-0}" = 1 ]; then resume=(--resume); else : > "$out.log"; fi
(cd "$root" && mpirun -np 2 build/formsolve prm/square-cup-reference.prm \
  --set "Mesh/Planform refinements=6" --set "Output/Checkpoint interval=10" \
  --set "Output/Output directory=$out" "${resume[@]}") >> "$out.log" 2>&1
/usr/bin/python3 "$root/benchmarks/square_cup_table.py" \
  "2.34 mm (Planform refinements 5)=$coarse" \
  "1.17 mm (Planform refinements 6)=$out"

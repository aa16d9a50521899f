#!/usr/bin/env bash
# Uniform meshes (planform refinements 3, 4, 5) against refinement near the
# radii (prm/cup-drawing-3d.prm) on the default cup, RANKS (default 2)
# MPI ranks; writes doc/refinement.csv, doc/refinement-accuracy.png,
# doc/refinement-thickness-strain.png and doc/refinement-mesh.png.
# Usage: bash benchmarks/refinement.sh [--force]   (runs are kept in
# results/refinement/ and reused unless --force)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# The BLAS kernels formsolve-run would choose (unless OPENBLAS_CORETYPE is set).
eval "$(bash "$root/scripts/formsolve-run" --env)"
exe=$root/build/formsolve
[ -x "$exe" ] || bash "$root/scripts/build.sh"
ranks=${RANKS:-2}
out=$root/results/refinement
mkdir -p "$out"
# The scene doc/performance.md and doc/refinement.md measured (before the
# process model of issue 8): quarter model, blank holder at a fixed 0.05 mm
# gap, fixed penalty, 15 mm, a failed step ends the run.
legacy=(--set "Tools/Blank holder/Control=gap" --set "Tools/Blank holder/Gap=0.05"
        --set "Contact/Penalty strategy=fixed" --set "Tools/Punch/Stroke=15"
        --set "Time stepping/End of run=stroke" --set "Time stepping/Max cutbacks=0")
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
export OMP_NUM_THREADS=1
run() { # name prm sets...
  local name=$1 prm=$2
  shift 2
  if [ "${FORCE:-}" = 1 ] || [ ! -f "$out/$name/run-summary.txt" ]; then
    echo "== $name"
    (cd "$root/prm" && mpirun -np "$ranks" "$exe" "$prm" "${legacy[@]}" "$@" --set "Output/Output interval=30" \
      --set "Output/Output directory=$out/$name") > "$out/$name.log" 2>&1
  fi
  tail -2 "$out/$name/run-summary.txt"
}
[ "${1:-}" = --force ] && FORCE=1
uniform=(--set "Mesh refinement/Interval=0" --set "Mesh/Layers through thickness=4")
for l in 3 4 5; do
  run uniform-$l cup-drawing-3d.prm "${uniform[@]}" --set "Mesh/Planform refinements=$l"
done
run adaptive cup-drawing-3d.prm
# Variants: 4 layers everywhere (8 at the radii) with a 2 mm band, and the
# shipped settings on the level-4 planform.
run adaptive-3-4layers cup-drawing-3d.prm --set "Mesh/Layers through thickness=4" \
  --set "Mesh refinement/Band width=2"
run adaptive-4-2layers cup-drawing-3d.prm --set "Mesh/Planform refinements=4"
/usr/bin/python3 "$root/benchmarks/refinement_chart.py" "$out" "$root/doc"

#!/usr/bin/env bash
# Times the default case (prm/cup-drawing.prm) at three planform refinements on
# RANKS (default 2) MPI ranks and writes the table of doc/performance.md.
# Usage: bash benchmarks/mesh-sizes.sh [refinements...]   (default: 3 4 5)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# The BLAS kernels formsolve-run would choose (unless OPENBLAS_CORETYPE is set).
eval "$(bash "$root/scripts/formsolve-run" --env)"
exe=$root/build/formsolve
[ -x "$exe" ] || bash "$root/scripts/build.sh"
ranks=${RANKS:-2}
levels=${*:-3 4 5}
out=$root/results/benchmarks
mkdir -p "$out"
# The scene doc/performance.md and doc/refinement.md measured (before the
# process model of issue 8): quarter model, blank holder at a fixed 0.05 mm
# gap, fixed penalty, 15 mm, a failed step ends the run.
legacy=(--set "Tools/Blank holder/Control=gap" --set "Tools/Blank holder/Gap=0.05"
        --set "Contact/Penalty strategy=fixed" --set "Tools/Punch/Stroke=15"
        --set "Time stepping/End of run=stroke" --set "Time stepping/Max cutbacks=0")
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
export OMP_NUM_THREADS=1
for l in $levels; do
  echo "== planform refinements $l on $ranks rank(s)"
  mpirun -np "$ranks" "$exe" "$root/prm/cup-drawing-3d.prm" "${legacy[@]}" \
    --set "Mesh refinement/Interval=0" --set "Mesh/Layers through thickness=4" \
    --set "Mesh/Planform refinements=$l" --set "Output/Output interval=0" \
    --set "Output/Output directory=$out/level-$l" > "$out/level-$l.log" 2>&1
  tail -1 "$out/level-$l/history.csv"
done
/usr/bin/python3 "$root/benchmarks/tabulate.py" "$out" $levels > "$out/table.md"
cat "$out/table.md"
echo "table written to $out/table.md; copy it into doc/performance.md"

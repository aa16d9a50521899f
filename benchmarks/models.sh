#!/usr/bin/env bash
# The default cup (force control, adaptive-strict) drawn through, as the
# axisymmetric model (three section resolutions), the quarter 3-D model
# (uniform planform levels 3, 4, 5 and refined at the radii) and the full 3-D
# model; writes doc/models.csv, doc/models-force.png,
# doc/models-thickness-strain.png and the table for doc/models.md.
# 3-D runs use RANKS (default 2) MPI ranks, axisymmetric runs 1 rank.
# Usage: bash benchmarks/models.sh [--force] [--quick]
#   runs are kept in results/models/ and reused unless --force;
#   --quick leaves out the two longest runs (quarter level 5, full level 4).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# The BLAS kernels formsolve-run would choose (unless OPENBLAS_CORETYPE is set).
eval "$(bash "$root/scripts/formsolve-run" --env)"
exe=$root/build/formsolve
[ -x "$exe" ] || bash "$root/scripts/build.sh"
ranks=${RANKS:-2}
out=$root/results/models
mkdir -p "$out"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
export OMP_NUM_THREADS=1
FORCE=0 QUICK=0
for a in "$@"; do
  case $a in --force) FORCE=1 ;; --quick) QUICK=1 ;; *) echo "unknown option $a"; exit 1 ;; esac
done
run() { # name ranks prm sets...
  local name=$1 n=$2 prm=$3
  shift 3
  if [ "$FORCE" = 1 ] || [ ! -f "$out/$name/run-summary.txt" ]; then
    echo "== $name ($n rank(s))"
    rm -rf "$out/$name"
    (cd "$root/prm" && mpirun -np "$n" "$exe" "$prm" "$@" --set "Output/Output interval=8" \
      --set "Output/Revolved copy=false" --set "Output/Output directory=$out/$name") \
      > "$out/$name.log" 2>&1 || { tail -3 "$out/$name.log"; exit 1; }
  fi
  grep -E "^(dofs|steps|wall_time|end_reason) " "$out/$name/run-summary.txt" | tr '\n' ' '; echo
}
uniform=(--set "Mesh refinement/Interval=0" --set "Mesh/Layers through thickness=4")
run axisymmetric 1 cup-drawing.prm
run axisymmetric-6 1 cup-drawing.prm --set "Mesh/Planform refinements=6"
run axisymmetric-7 1 cup-drawing.prm --set "Mesh/Planform refinements=7"
run quarter-refined "$ranks" cup-drawing-3d.prm
run quarter-3 "$ranks" cup-drawing-3d.prm "${uniform[@]}" --set "Mesh/Planform refinements=3"
run quarter-4 "$ranks" cup-drawing-3d.prm "${uniform[@]}" --set "Mesh/Planform refinements=4"
run full-3 "$ranks" cup-drawing-3d.prm "${uniform[@]}" --set "Geometry/Model=full" \
  --set "Mesh/Planform refinements=3"
if [ "$QUICK" = 0 ]; then
  run quarter-5 "$ranks" cup-drawing-3d.prm "${uniform[@]}" --set "Mesh/Planform refinements=5"
fi
/usr/bin/python3 "$root/benchmarks/models_report.py" "$out" "$root/doc"

#!/usr/bin/env bash
# Newton iterations per step over the full draw of the default cup (force
# control), axisymmetric section and quarter 3-D (uniform planform level 3,
# 4 layers), for the penalty strategies fixed (1e5 N/mm^3), adaptive and
# adaptive-strict (delta = 1e-3 mm); writes doc/convergence.csv,
# doc/convergence-histogram.png and the tables for doc/convergence.md.
# Usage: [REPORT_TAGS="before ..."] bash benchmarks/convergence.sh [--force] [--exe PATH --tag NAME]
#          [--set "Section/Entry=value"]...
#   runs are kept in results/convergence/<tag>/ and reused unless --force;
#   --exe/--tag run another build (e.g. an older commit's) under its own tag;
#   --set passes an entry to every run (an A/B on one parameter, own tag).
# 3-D runs use RANKS (default 1) MPI ranks.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# The BLAS kernels formsolve-run would choose (unless OPENBLAS_CORETYPE is set).
eval "$(bash "$root/scripts/formsolve-run" --env)"
exe=$root/build/formsolve
tag=current
FORCE=0
extra=()
while [ $# -gt 0 ]; do
  case $1 in
    --force) FORCE=1 ;;
    --exe) exe=$(realpath "$2"); shift ;;
    --tag) tag=$2; shift ;;
    --set) extra+=(--set "$2"); shift ;;
    *) echo "unknown option $1"; exit 1 ;;
  esac
  shift
done
[ -x "$exe" ] || bash "$root/scripts/build.sh"
ranks=${RANKS:-1}
out=$root/results/convergence/$tag
mkdir -p "$out"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
export OMP_NUM_THREADS=1
run() { # name ranks prm sets...
  local name=$1 n=$2 prm=$3
  shift 3
  if [ "$FORCE" = 1 ] || [ ! -f "$out/$name/run-summary.txt" ]; then
    echo "== $tag/$name ($n rank(s))"
    rm -rf "$out/$name"
    (cd "$root/prm" && mpirun -np "$n" "$exe" "$prm" "$@" ${extra[@]+"${extra[@]}"} --set "Output/Output interval=0" \
      --set "Output/Revolved copy=false" --set "Output/Output directory=$out/$name") \
      > "$out/$name.log" 2>&1 || { tail -3 "$out/$name.log"; exit 1; }
  fi
  grep -E "^(steps|newton_iterations|wall_time|end_reason) " "$out/$name/run-summary.txt" | tr '\n' ' '; echo
}
quarter=(--set "Geometry/Model=quarter" --set "Mesh refinement/Interval=0"
  --set "Mesh/Layers through thickness=4" --set "Mesh/Planform refinements=3")
fixed=(--set "Contact/Penalty strategy=fixed" --set "Contact/Penalty factor=1e5")
adaptive=(--set "Contact/Penalty strategy=adaptive")
for model in axisymmetric quarter; do
  sets=()
  n=1
  [ "$model" = quarter ] && sets=("${quarter[@]}") && n=$ranks
  run "$model-fixed" "$n" cup-drawing.prm "${sets[@]}" "${fixed[@]}"
  run "$model-adaptive" "$n" cup-drawing.prm "${sets[@]}" "${adaptive[@]}"
  run "$model-adaptive-strict" "$n" cup-drawing.prm "${sets[@]}"
done
# Earlier builds' runs, oldest first (REPORT_TAGS, default "before"), then
# this build's.
if [ "$tag" = current ]; then
  tags=()
  for t in ${REPORT_TAGS:-before}; do [ -d "$out/../$t" ] && tags+=("$t"); done
  /usr/bin/python3 "$root/benchmarks/convergence_report.py" "$root/results/convergence" \
    "$root/doc" "${tags[@]}" current
fi

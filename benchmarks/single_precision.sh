#!/usr/bin/env bash
# Single-precision MUMPS factors as GMRES's preconditioner against double
# factors (Linear solver/Factor precision): the quarter 3-D cup of
# benchmarks/scaling.sh (fixed penalty, 4 layers, no adaptive refinement, the
# first 0.5 mm in 2 steps) at planform levels 5 and 6 (47.5k and 187k DoFs)
# on 2 ranks. single runs at Reuse tolerance 1e-10 (the default) and 1e-6.
# Per run: Newton iterations, GMRES iterations per solve, seconds per Newton
# iteration split into factorisation and substitution, factor memory and
# peak memory. Writes doc/single-precision.csv and prints the table of
# doc/performance.md.
# Usage: bash benchmarks/single_precision.sh [--force] [max level, default 6]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# The BLAS kernels formsolve-run would choose (unless OPENBLAS_CORETYPE is set).
eval "$(bash "$root/scripts/formsolve-run" --env)"
exe=${FORMSOLVE_EXE:-$root/build/formsolve}
[ -x "$exe" ] || bash "$root/scripts/build.sh"
. "$root/benchmarks/from_rest.sh" && from_rest "$exe" # as the figures in doc/
out=$root/results/single-precision
mkdir -p "$out"
FORCE=""
MAX=6
for a in "$@"; do
  case $a in --force) FORCE=--force ;; *) MAX=$a ;; esac
done
export OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
runs=()
run() { # name level precision reuse-tolerance
  local name=$1 level=$2 precision=$3 tolerance=$4
  if [ "$FORCE" = --force ] || [ ! -f "$out/$name/run-summary.txt" ]; then
    echo "== $name" >&2
    rm -rf "${out:?}/$name"
    (cd "$root/prm" && mpirun -np 2 "$exe" cup-drawing.prm ${rest[@]+"${rest[@]}"} \
      --set "Geometry/Model=quarter" --set "Mesh refinement/Interval=0" \
      --set "Mesh/Layers through thickness=4" --set "Mesh/Planform refinements=$level" \
      --set "Contact/Penalty strategy=fixed" --set "Tools/Punch/Stroke=0.5" \
      --set "Time stepping/End of run=stroke" --set "Output/Output interval=0" \
      --set "Output/Revolved copy=false" --set "Output/Output directory=$out/$name" \
      --set "Linear solver/Factor precision=$precision" \
      --set "Linear solver/Reuse tolerance=$tolerance") \
      > "$out/$name.log" 2>&1 || { tail -3 "$out/$name.log"; return 1; }
  fi
  runs+=("$name")
}
for level in 5 6; do
  [ "$level" -le "$MAX" ] || continue
  run "l$level-double" "$level" double 1e-10
  run "l$level-single" "$level" single 1e-10
  run "l$level-single-1e-6" "$level" single 1e-6
done
PYTHONPATH="$root/benchmarks" /usr/bin/python3 - "$out" "$root/doc/single-precision.csv" "${runs[@]}" <<'PY'
import sys
from run_tables import section, summary, write
out, csv_path = sys.argv[1:3]
rows = []
for name in sys.argv[3:]:
    s = summary(f"{out}/{name}")
    log = open(f"{out}/{name}.log").read()
    newton, dofs = int(s["newton_iterations"]), float(s["dofs"])
    solves = section(log, "linear solve")[0] * 2  # the body's and the holder's
    _, tf = section(log, "linear solve: factorisation")
    _, ts = section(log, "linear solve: substitution")
    _, tl = section(log, "linear solve")
    wall = float(s["newton_wall_time"])
    rows.append(dict(run=name, dofs=int(dofs), newton=newton,
                     gmres_per_solve=int(s["linear_iterations"]) / solves,
                     s_per_iteration=wall / newton, factorisation_s_per_iteration=tf / newton,
                     substitution_s_per_iteration=ts / newton, linear_s_per_iteration=tl / newton,
                     linear_share=tl / wall,
                     factor_kB_per_dof=float(s["factorisation_memory_mb"]) * 1e3 / dofs,
                     peak_memory_MB=float(s["peak_memory_kb_all_ranks"]) / 1024,
                     peak_punch_force_N=float(s["peak_punch_force"]),
                     max_penetration_mm=float(s["max_penetration"])))
write(rows, csv_path)
PY

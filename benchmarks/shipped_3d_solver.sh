#!/usr/bin/env bash
# The solver settings of the shipped 3-D case (prm/cup-drawing-3d.prm: single-
# precision factors reused within a Newton solve, inexact Newton) against
# exact solves (fresh double-precision factors at every Newton iteration) and
# against single-precision factors with inexact Newton but no reuse: the full
# draw of the shipped case as it ships (adaptive-strict, force control,
# refinement at the radii), on 1 and 2 ranks, VTU output off. About 10 min on
# 2 quiet cores. Runs in results/shipped-3d-solver/<name>/ and <name>.log;
# writes doc/shipped-3d-solver.csv and prints the table of doc/performance.md
# ("The shipped 3-D case's solver settings").
# Usage: bash benchmarks/shipped_3d_solver.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# The BLAS kernels formsolve-run would choose (unless OPENBLAS_CORETYPE is set).
eval "$(bash "$root/scripts/formsolve-run" --env)"
exe=${FORMSOLVE_EXE:-$root/build/formsolve}
[ -x "$exe" ] || bash "$root/scripts/build.sh"
out=$root/results/shipped-3d-solver
mkdir -p "$out"
git -C "$root" rev-parse --short HEAD > "$out/commit"
export OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
exact=(--set "Linear solver/Factor precision=double"
  --set "Linear solver/Reuse factorisation iterations=0" --set "Nonlinear solver/Forcing=0")
fresh_single=(--set "Linear solver/Reuse factorisation iterations=0")
run() { # name ranks sets...
  local name=$1 n=$2
  shift 2
  echo "== $name"
  (cd "$root/prm" && mpirun -np "$n" "$exe" cup-drawing-3d.prm \
    --set "Output/Output directory=$out/$name" --set "Output/Output interval=0" \
    --set "Output/Report=false" "$@" > "$out/$name.log" 2>&1)
}
names=()
for n in 1 2; do
  run "exact-$n" "$n" "${exact[@]}"
  run "single-inexact-$n" "$n" "${fresh_single[@]}"
  run "shipped-$n" "$n"
  names+=("exact-$n" "single-inexact-$n" "shipped-$n")
done
cd "$root/benchmarks"
/usr/bin/python3 - "$out" "$root/doc/shipped-3d-solver.csv" "${names[@]}" <<'PY'
import sys
from run_tables import section, summary, write
out, csv_path = sys.argv[1:3]
rows = []
for name in sys.argv[3:]:
    s = summary(f"{out}/{name}")
    log = open(f"{out}/{name}.log").read()
    wall = float(s["wall_time"])
    rows.append(dict(run=name, ranks=int(s["ranks"]), steps=int(s["steps"]),
                     newton=int(s["newton_iterations"]), factorisations=int(s["factorisations"]),
                     substitutions=section(log, "linear solve: substitution")[0],
                     factorisation_s=section(log, "linear solve: factorisation")[1],
                     substitution_s=section(log, "linear solve: substitution")[1],
                     linear_s=section(log, "linear solve")[1],
                     assembly_s=section(log, "assembly: body, tangent")[1],
                     wall_s=wall, linear_share=section(log, "linear solve")[1] / wall,
                     peak_punch_force_N=float(s["peak_punch_force"]),
                     max_penetration_mm=float(s["max_penetration"]),
                     max_thinning_percent=float(s["max_thinning_percent"]),
                     cutbacks=int(s["cutbacks"])))
write(rows, csv_path)
PY

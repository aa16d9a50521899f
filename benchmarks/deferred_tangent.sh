#!/usr/bin/env bash
# Nonlinear solver/Deferred tangent on and off, on the default cup's full
# draw (1 rank; the axisymmetric model and the quarter of
# benchmarks/convergence.sh; fixed 1e5 and adaptive-strict): matrix and
# residual-only assemblies, their time, the wall time. The runs of each pair
# alternate (on, off, on, off, ...) so that a drift of the machine hits both.
# The physics must agree to the last digit (checked here: every history.csv
# column but the wall time).
# Writes doc/deferred-tangent.csv and prints the table of doc/convergence.md.
# Usage: REPS=2 bash benchmarks/deferred_tangent.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# The BLAS kernels formsolve-run would choose (unless OPENBLAS_CORETYPE is set).
eval "$(bash "$root/scripts/formsolve-run" --env)"
exe=${FORMSOLVE_EXE:-$root/build/formsolve}
[ -x "$exe" ] || bash "$root/scripts/build.sh"
out=$root/results/deferred-tangent
reps=${REPS:-2}
mkdir -p "$out"
export OMP_NUM_THREADS=1
quarter=(--set "Geometry/Model=quarter" --set "Mesh refinement/Interval=0"
  --set "Mesh/Layers through thickness=4" --set "Mesh/Planform refinements=3")
fixed=(--set "Contact/Penalty strategy=fixed" --set "Contact/Penalty factor=1e5")
strict=(--set "Contact/Penalty strategy=adaptive-strict")
for model in axisymmetric quarter; do
  for method in fixed-1e5 adaptive-strict; do
    for k in $(seq "$reps"); do
      for deferred in true false; do
        name=$model-$method-$deferred-$k
        echo "== $name" >&2
        sets=()
        [ "$model" = quarter ] && sets+=("${quarter[@]}")
        if [ "$method" = fixed-1e5 ]; then sets+=("${fixed[@]}"); else sets+=("${strict[@]}"); fi
        (cd "$root/prm" && "$exe" cup-drawing.prm "${sets[@]}" \
          --set "Nonlinear solver/Deferred tangent=$deferred" \
          --set "Output/Output interval=0" --set "Output/Revolved copy=false" \
          --set "Output/Report=false" --set "Output/Output directory=$out/$name") \
          > "$out/$name.log" 2>&1 || { tail -3 "$out/$name.log"; exit 1; }
      done
    done
  done
done
PYTHONPATH="$root/benchmarks" /usr/bin/python3 - "$out" "$root/doc/deferred-tangent.csv" "$reps" <<'PY'
import csv, sys
from run_tables import summary, section, write
out, csv_path, reps = sys.argv[1], sys.argv[2], int(sys.argv[3])

def physics(run):
    rows = list(csv.reader(open(f"{run}/history.csv")))
    wall = rows[0].index("wall_time") if "wall_time" in rows[0] else None
    return [[v for i, v in enumerate(r) if i != wall] for r in rows]

rows = []
for model in ["axisymmetric", "quarter"]:
    for method in ["fixed-1e5", "adaptive-strict"]:
        for deferred in ["true", "false"]:
            for k in range(1, reps + 1):
                run = f"{out}/{model}-{method}-{deferred}-{k}"
                s, log = summary(run), open(run + ".log").read()
                if physics(run) != physics(f"{out}/{model}-{method}-true-1"):
                    sys.exit(f"{run}: history differs from {model}-{method}-true-1")
                newton = int(s["newton_iterations"]) + int(s.get("coarse_start_iterations", 0))
                tangent, residual = section(log, "assembly: body, tangent"), section(log, "assembly: body, residual only")
                rows.append(dict(model=model, method=method, deferred=deferred, run=k,
                                 newton=newton, matrix=int(s["matrix_assemblies"]),
                                 matrix_per_iteration=int(s["matrix_assemblies"]) / newton,
                                 residual_only=residual[0],
                                 assembly_s=tangent[1] + residual[1],
                                 wall_s=float(s["wall_time"])))
write(rows, csv_path)
PY

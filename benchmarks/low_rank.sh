#!/usr/bin/env bash
# Block low-rank (BLR) MUMPS factors (Linear solver/Low-rank tolerance, with
# GMRES to Reuse tolerance = 1e-10 on them) against full-rank factors: the
# quarter 3-D cup (fixed penalty, 4 layers, no adaptive refinement), 1 rank,
# planform level 5 (47.5k DoFs, first 0.5 mm) and level 6 (187k DoFs, first
# 0.25 mm). Per run: factor entries and memory, time per factorisation and
# per Newton iteration, GMRES iterations per solve.
# Writes doc/low-rank.csv and prints the table of doc/performance.md.
# Usage: bash benchmarks/low_rank.sh [--force]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# The BLAS kernels formsolve-run would choose (unless OPENBLAS_CORETYPE is set).
eval "$(bash "$root/scripts/formsolve-run" --env)"
exe=$root/build/formsolve
[ -x "$exe" ] || bash "$root/scripts/build.sh"
. "$root/benchmarks/from_rest.sh" && from_rest "$exe" # as the figures in doc/
out=$root/results/low-rank
mkdir -p "$out"
FORCE=${1:-}
export OMP_NUM_THREADS=1
runs=()
run() { # name level stroke tolerance
  local name=$1 level=$2 stroke=$3 tolerance=$4
  if [ "$FORCE" = --force ] || [ ! -f "$out/$name/run-summary.txt" ]; then
    echo "== $name" >&2
    rm -rf "$out/$name"
    (cd "$root/prm" && "$exe" cup-drawing.prm ${rest[@]+"${rest[@]}"} --set "Geometry/Model=quarter" \
      --set "Mesh refinement/Interval=0" --set "Mesh/Layers through thickness=4" \
      --set "Mesh/Planform refinements=$level" --set "Contact/Penalty strategy=fixed" \
      --set "Tools/Punch/Stroke=$stroke" --set "Time stepping/End of run=stroke" \
      --set "Linear solver/Low-rank tolerance=$tolerance" \
      --set "Output/Output interval=0" --set "Output/Revolved copy=false" \
      --set "Output/Output directory=$out/$name") \
      > "$out/$name.log" 2>&1 || { tail -3 "$out/$name.log"; exit 1; }
  fi
  runs+=("$name $tolerance")
}
for tolerance in 0 1e-8 1e-6; do
  run "l5-blr$tolerance" 5 0.5 "$tolerance"
done
for tolerance in 0 1e-8 1e-6; do
  run "l6-blr$tolerance" 6 0.25 "$tolerance"
done
PYTHONPATH="$root/benchmarks" /usr/bin/python3 - "$out" "$root/doc/low-rank.csv" "${runs[@]}" <<'PY'
import csv, sys
from run_tables import steps
from run_tables import section, summary, write
out, csv_path = sys.argv[1:3]
rows = []
for item in sys.argv[3:]:
    name, tolerance = item.split()
    s = summary(f"{out}/{name}")
    log = open(f"{out}/{name}.log").read()
    newton = int(s["newton_iterations"])
    dofs = float(s["dofs"])
    nf, tf = section(log, "linear solve: factorisation")
    ns, ts = section(log, "linear solve: substitution")
    _, tl = section(log, "linear solve")
    # Solves: one per Newton iteration plus the holder's second one; the
    # full-rank run does one substitution per solve.
    rows.append(dict(run=name, tolerance=tolerance, dofs=int(dofs), newton=newton,
                     factor_entries_M=float(s["factor_entries"]) / 1e6,
                     factor_kB_per_dof=float(s["factorisation_memory_mb"]) * 1e3 / dofs,
                     s_per_factorisation=tf / nf, substitutions=ns,
                     linear_s_per_newton=tl / newton,
                     s_per_newton=float(s["newton_wall_time"]) / newton,
                     peak_memory_MB=float(s["peak_memory_kb_all_ranks"]) / 1024,
                     final_force_kN=float(steps(f"{out}/{name}")[-1]["punch_force"]) / 1e3))
write(rows, csv_path, 6, 4)
PY

#!/usr/bin/env bash
# Memory of a run against the direct solver's setting: MUMPS LU, LDL^T of the
# symmetric part (Unsymmetric tangent = symmetric part), and both with the
# factors out of core (Linear solver/Out-of-core directory). The quarter 3-D
# cup (fixed penalty, no adaptive refinement), the first step (0.25 mm),
# planform levels 5 and 6 with 4 layers on 1 rank, level 6 on 2 ranks, and
# level 7 with 6 layers (1.04M DoFs) on 2 ranks, out of core. Per run: peak
# resident memory of all ranks and of the largest, MUMPS's own memory
# (INFOG(22)), the factor size, and the time per Newton iteration split into
# factorisation and substitution. Writes doc/memory.csv and prints its table.
# Usage: bash benchmarks/memory.sh [--force] [--no-1m]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# The BLAS kernels formsolve-run would choose (unless OPENBLAS_CORETYPE is set).
eval "$(bash "$root/scripts/formsolve-run" --env)"
exe=${FORMSOLVE_EXE:-$root/build/formsolve} # FORMSOLVE_EXE: another binary
[ -x "$exe" ] || bash "$root/scripts/build.sh"
. "$root/benchmarks/from_rest.sh" && from_rest "$exe" # as the figures in doc/
out=$root/results/memory
ooc=$out/factors # the out-of-core files, removed by MUMPS after each run
mkdir -p "$out" "$ooc"
FORCE="" ONE_M=1
for a in "$@"; do
  case $a in --force) FORCE=--force ;; --no-1m) ONE_M=0 ;; esac
done
export OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
runs=()
run() { # name ranks level layers setting...
  local name=$1 ranks=$2 level=$3 layers=$4
  shift 4
  local sets=()
  for s in "$@"; do sets+=(--set "$s"); done
  if [ "$FORCE" = --force ] || [ ! -f "$out/$name/run-summary.txt" ]; then
    echo "== $name" >&2
    rm -rf "$out/$name"
    (cd "$root/prm" && mpirun -np "$ranks" "$exe" cup-drawing.prm ${rest[@]+"${rest[@]}"} \
      --set "Geometry/Model=quarter" --set "Mesh refinement/Interval=0" \
      --set "Mesh/Layers through thickness=$layers" --set "Mesh/Planform refinements=$level" \
      --set "Contact/Penalty strategy=fixed" --set "Tools/Punch/Stroke=0.25" \
      --set "Time stepping/End of run=stroke" --set "Output/Output interval=0" \
      --set "Output/Revolved copy=false" --set "Output/Report=false" \
      --set "Output/Output directory=$out/$name" ${sets[@]+"${sets[@]}"}) \
      > "$out/$name.log" 2>&1 || { tail -3 "$out/$name.log"; return 1; }
  fi
  runs+=("$name $ranks")
}
sym="Linear solver/Unsymmetric tangent=symmetric part"
disk="Linear solver/Out-of-core directory=$ooc"
for level in 5 6; do
  run "l$level-lu" 1 "$level" 4
  run "l$level-sym" 1 "$level" 4 "$sym"
  run "l$level-lu-ooc" 1 "$level" 4 "$disk"
  run "l$level-sym-ooc" 1 "$level" 4 "$sym" "$disk"
done
# 2 ranks: the transposes on the other rank, MUMPS's distributed fronts.
run l6-lu-2ranks 2 6 4
run l6-sym-2ranks 2 6 4 "$sym"
run l6-sym-ooc-2ranks 2 6 4 "$sym" "$disk"
if [ "$ONE_M" = 1 ]; then
  run l7x6-sym-ooc-2ranks 2 7 6 "$sym" "$disk"
fi
PYTHONPATH="$root/benchmarks" /usr/bin/python3 - "$out" "$root/doc/memory.csv" "${runs[@]}" <<'PY'
import sys
from run_tables import section, summary, write
out, csv_path = sys.argv[1:3]
rows = []
for item in sys.argv[3:]:
    name, ranks = item.split()
    s = summary(f"{out}/{name}")
    log = open(f"{out}/{name}.log").read()
    newton = int(s["newton_iterations"])
    dofs = float(s["dofs"])
    _, tf = section(log, "linear solve: factorisation")
    _, ts = section(log, "linear solve: substitution")
    rows.append(dict(run=name, ranks=int(ranks), dofs=int(dofs), newton=newton,
                     linear_iterations=int(s["linear_iterations"]),
                     s_per_iteration=float(s["newton_wall_time"]) / newton,
                     factorisation_s_per_iteration=tf / newton,
                     substitution_s_per_iteration=ts / newton,
                     mumps_in_core_kB_per_dof=float(s["factorisation_memory_mb"]) * 1e3 / dofs,
                     factors_kB_per_dof=float(s["factor_entries"]) * 8e-3 / dofs,
                     peak_kB_per_dof=float(s["peak_memory_kb_all_ranks"]) * 1.024 / dofs,
                     peak_all_ranks_MB=float(s["peak_memory_kb_all_ranks"]) / 1024,
                     peak_max_rank_MB=float(s["peak_memory_kb_max_rank"]) / 1024,
                     setup_max_rank_MB=float(s["setup_memory_kb_max_rank"]) / 1024,
                     peak_force_kN=float(s["peak_punch_force"]) / 1e3))
write(rows, csv_path)
PY

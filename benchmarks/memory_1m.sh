#!/usr/bin/env bash
# The 1.04M-DoF first step of benchmarks/memory.sh (quarter 3-D cup, planform
# level 7, 6 layers, fixed penalty, LDL^T of the symmetric part, factors out
# of core, 2 ranks), twice: from rest, as in doc/memory.csv, and with the
# default start since a4144b7 (the first step solved first on the mesh one
# level coarser). Does the default still fit in 8 GB? Per run: the peak of
# all ranks and of the largest, the set-up peak, the iterations on both
# meshes, MUMPS's own memory, the Newton time and the first step's force.
# About 30 minutes on 2 cores (28 on 0ea70f1; 39 on 6339678, part of it beside a CI run). Writes doc/memory-1m.csv and prints its table.
# Usage: bash benchmarks/memory_1m.sh [--force]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# The BLAS kernels formsolve-run would choose (unless OPENBLAS_CORETYPE is set).
eval "$(bash "$root/scripts/formsolve-run" --env)"
exe=${FORMSOLVE_EXE:-$root/build/formsolve}
[ -x "$exe" ] || bash "$root/scripts/build.sh"
out=$root/results/memory-1m
ooc=$out/factors # removed by MUMPS after each run
mkdir -p "$out" "$ooc"
export OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
for start in rest "coarser mesh"; do
  name=l7x6-sym-ooc-2ranks-${start// /-}
  [ "${1:-}" != --force ] && [ -f "$out/$name/run-summary.txt" ] && continue
  echo "== $name" >&2
  rm -rf "${out:?}/$name"
  (cd "$root/prm" && mpirun -np 2 "$exe" cup-drawing.prm \
    --set "Geometry/Model=quarter" --set "Mesh refinement/Interval=0" \
    --set "Mesh/Layers through thickness=6" --set "Mesh/Planform refinements=7" \
    --set "Contact/Penalty strategy=fixed" --set "Tools/Punch/Stroke=0.25" \
    --set "Time stepping/End of run=stroke" --set "Output/Output interval=0" \
    --set "Output/Revolved copy=false" --set "Output/Report=false" \
    --set "Linear solver/Unsymmetric tangent=symmetric part" \
    --set "Linear solver/Out-of-core directory=$ooc" \
    --set "Nonlinear solver/First step start=$start" \
    --set "Output/Output directory=$out/$name") > "$out/$name.log" 2>&1 ||
    { tail -3 "$out/$name.log"; exit 1; }
done
PYTHONPATH="$root/benchmarks" /usr/bin/python3 - "$out" "$root/doc/memory-1m.csv" <<'PY'
import sys
from run_tables import summary, write
out, csv_path = sys.argv[1:3]
rows = []
for start in ["rest", "coarser-mesh"]:
    s = summary(f"{out}/l7x6-sym-ooc-2ranks-{start}")
    dofs = float(s["dofs"])
    rows.append(dict(start=start, dofs=int(dofs),
                     coarse_iterations=int(s.get("coarse_start_iterations", 0)),
                     newton=int(s["newton_iterations"]),
                     newton_time_s=float(s["newton_wall_time"]),
                     wall_s=float(s["wall_time"]),
                     mumps_in_core_kB_per_dof=float(s["factorisation_memory_mb"]) * 1e3 / dofs,
                     peak_all_ranks_MB=float(s["peak_memory_kb_all_ranks"]) / 1024,
                     peak_max_rank_MB=float(s["peak_memory_kb_max_rank"]) / 1024,
                     setup_max_rank_MB=float(s["setup_memory_kb_max_rank"]) / 1024,
                     peak_force_kN=float(s["peak_punch_force"]) / 1e3))
write(rows, csv_path)
PY

#!/usr/bin/env bash
# Scale: the quarter 3-D cup (fixed penalty, 4 element layers, no adaptive
# refinement) from planform refinement 3 to 7 (3k to 0.75M DoFs), the first
# steps of the draw, on 1 rank, and planform refinements 6 and 7 (187k and
# 743k DoFs) on 2 ranks. Per size: time per Newton iteration split into assembly,
# factorisation and substitution; factorisations per step; memory per DoF;
# then the exponent alpha of time per iteration ~ N^alpha.
# Writes doc/scaling.csv and prints the table of doc/performance.md.
# Usage: [TAG=name] [SET="section/entry=value"] bash benchmarks/scaling.sh [--force] [max level, default 7]
#   TAG: runs in results/scaling-TAG/ and the table in doc/scaling-TAG.csv
#   (default: results/scaling/, doc/scaling.csv).
#   SET: one more parameter for every run, e.g.
#   SET="Linear solver/Unsymmetric tangent=symmetric part".
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# The BLAS kernels formsolve-run would choose (unless OPENBLAS_CORETYPE is set).
eval "$(bash "$root/scripts/formsolve-run" --env)"
exe=${FORMSOLVE_EXE:-$root/build/formsolve} # FORMSOLVE_EXE: another binary
[ -x "$exe" ] || bash "$root/scripts/build.sh"
. "$root/benchmarks/from_rest.sh" && from_rest "$exe" # as the figures in doc/
out=$root/results/scaling${TAG:+-$TAG}
csv=$root/doc/scaling${TAG:+-$TAG}.csv
mkdir -p "$out"
FORCE=""
MAX=7
for a in "$@"; do
  case $a in --force) FORCE=--force ;; *) MAX=$a ;; esac
done
export OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
run() { # name ranks level stroke
  local name=$1 ranks=$2 level=$3 stroke=$4
  if [ "$FORCE" = --force ] || [ ! -f "$out/$name/run-summary.txt" ]; then
    echo "== $name" >&2
    rm -rf "$out/$name"
    (cd "$root/prm" && mpirun -np "$ranks" "$exe" cup-drawing.prm ${rest[@]+"${rest[@]}"} \
      --set "Geometry/Model=quarter" --set "Mesh refinement/Interval=0" \
      --set "Mesh/Layers through thickness=4" --set "Mesh/Planform refinements=$level" \
      --set "Contact/Penalty strategy=fixed" --set "Tools/Punch/Stroke=$stroke" \
      --set "Time stepping/End of run=stroke" --set "Output/Output interval=0" \
      --set "Output/Revolved copy=false" --set "Output/Output directory=$out/$name" \
      ${SET:+--set "$SET"}) \
      > "$out/$name.log" 2>&1 || { tail -3 "$out/$name.log"; return 1; }
  fi
}
runs=()
for level in 3 4 5 6 7; do
  [ "$level" -le "$MAX" ] || continue
  stroke=0.5
  [ "$level" -ge 7 ] && stroke=0.25 # one step
  run "l$level-1rank" 1 "$level" "$stroke" && runs+=("l$level-1rank 1")
done
if [ "$MAX" -ge 6 ]; then
  run l6-2ranks 2 6 0.5 && runs+=("l6-2ranks 2")
fi
if [ "$MAX" -ge 7 ]; then
  run l7-2ranks 2 7 0.25 && runs+=("l7-2ranks 2")
fi
PYTHONPATH="$root/benchmarks" /usr/bin/python3 - "$out" "$csv" "${runs[@]}" <<'PY'
import math, sys
from run_tables import section, summary, write
out, csv_path = sys.argv[1:3]
rows = []
for item in sys.argv[3:]:
    name, ranks = item.split()
    s = summary(f"{out}/{name}")
    log = open(f"{out}/{name}.log").read()
    newton = int(s["newton_iterations"])
    dofs = float(s["dofs"])
    assembly = sum(section(log, k)[1] for k in ("assembly: body, tangent", "assembly: body, residual only",
                                                 "assembly: contact terms", "contact", "penalty estimate"))
    nf, tf = section(log, "linear solve: factorisation")
    _, ta = section(log, "linear solve: analysis")
    _, ts = section(log, "linear solve: substitution")
    _, tl = section(log, "linear solve")
    newton_wall = float(s["newton_wall_time"])
    rows.append(dict(run=name, ranks=int(ranks), dofs=int(dofs), steps=int(s["steps"]), newton=newton,
                     s_per_iteration=newton_wall / newton, assembly_s_per_iteration=assembly / newton,
                     factorisation_s_per_iteration=tf / newton, substitution_s_per_iteration=ts / newton,
                     analysis_s=ta, linear_share=tl / newton_wall,
                     factorisations_per_step=nf / int(s["steps"]),
                     factor_kB_per_dof=float(s["factorisation_memory_mb"]) * 1e3 / dofs,
                     peak_kB_per_dof=float(s["peak_memory_kb_all_ranks"]) * 1.024 / dofs,
                     peak_memory_MB=float(s["peak_memory_kb_all_ranks"]) / 1024,
                     peak_max_rank_MB=float(s.get("peak_memory_kb_max_rank", "nan")) / 1024,
                     setup_max_rank_MB=float(s.get("setup_memory_kb_max_rank", "nan")) / 1024))
serial = [r for r in rows if r["ranks"] == 1 and r["dofs"] >= 10000]
def fit(key):
    if len(serial) < 2:
        return float("nan")
    x = [math.log(r["dofs"]) for r in serial]
    y = [math.log(r[key]) for r in serial]
    mx, my = sum(x) / len(x), sum(y) / len(y)
    return sum((a - mx) * (b - my) for a, b in zip(x, y)) / sum((a - mx) ** 2 for a in x)
write(rows, csv_path)
print(f"\nalpha (1 rank, >= 10k DoFs): time per iteration {fit('s_per_iteration'):.2f}, "
      f"assembly {fit('assembly_s_per_iteration'):.2f}, factorisation {fit('factorisation_s_per_iteration'):.2f}")
PY

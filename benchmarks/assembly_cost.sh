#!/usr/bin/env bash
# Body assembly cost per cell (issue 10 section 3): the full draw of the
# default cup with the fixed penalty (1e5 N/mm^3), axisymmetric section and
# uniform quarter 3-D (planform level 3, 4 layers), 1 rank. From the timer
# sections "assembly: body, tangent" and "assembly: body, residual only":
# microseconds per cell and call. Several builds side by side:
#   bash benchmarks/assembly_cost.sh [--exe PATH --tag NAME]...   (default: build/formsolve as "current")
# Writes doc/assembly-cost.csv and prints the table. OPENBLAS_CORETYPE is
# fixed (SkylakeX if the CPU has AVX-512, else Haswell) so that older builds
# without formsolve's own kernel choice use the same BLAS.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# The BLAS kernels formsolve-run would choose (unless OPENBLAS_CORETYPE is set).
eval "$(bash "$root/scripts/formsolve-run" --env)"
exes=() tags=()
while [ $# -gt 0 ]; do
  case $1 in
    --exe) exes+=("$(realpath "$2")"); shift ;;
    --tag) tags+=("$2"); shift ;;
    *) echo "unknown option $1"; exit 1 ;;
  esac
  shift
done
if [ ${#exes[@]} -eq 0 ]; then
  [ -x "$root/build/formsolve" ] || bash "$root/scripts/build.sh"
  exes=("$root/build/formsolve") tags=(current)
fi
grep -q avx512f /proc/cpuinfo && kernel=SkylakeX || kernel=Haswell
export OPENBLAS_CORETYPE=${OPENBLAS_CORETYPE:-$kernel} OMP_NUM_THREADS=1
out=$root/results/assembly-cost
mkdir -p "$out"
quarter=(--set "Geometry/Model=quarter" --set "Mesh refinement/Interval=0"
  --set "Mesh/Layers through thickness=4" --set "Mesh/Planform refinements=3")
runs=()
. "$root/benchmarks/from_rest.sh"
for k in "${!exes[@]}"; do
  for model in axisymmetric quarter; do
    name=${tags[$k]}-$model
    from_rest "${exes[$k]}" # as the figures in doc/
    sets=()
    [ "$model" = quarter ] && sets=("${quarter[@]}")
    echo "== $name" >&2
    rm -rf "${out:?}/$name"
    # The library next to an older build's executable is the one it was
    # built with (a copied build: LD_LIBRARY_PATH=its directory).
    (cd "$root/prm" && LD_LIBRARY_PATH=$(dirname "${exes[$k]}") "${exes[$k]}" cup-drawing.prm ${rest[@]+"${rest[@]}"} "${sets[@]}" \
      --set "Contact/Penalty strategy=fixed" --set "Contact/Penalty factor=1e5" \
      --set "Output/Output interval=0" --set "Output/Revolved copy=false" \
      --set "Output/Report=false" --set "Output/Output directory=$out/$name") \
      > "$out/$name.log" 2>&1 || { tail -3 "$out/$name.log"; exit 1; }
    runs+=("$name")
  done
done
PYTHONPATH="$root/benchmarks" /usr/bin/python3 - "$out" "$root/doc/assembly-cost.csv" "${runs[@]}" <<'PY'
import re, sys
from run_tables import section, summary, write
out, csv_path = sys.argv[1:3]
rows = []
for name in sys.argv[3:]:
    log = open(f"{out}/{name}.log").read()
    s = summary(f"{out}/{name}")
    cells = int(re.search(r"rank\(s\), (\d+) cells", log).group(1))
    nt, tt = section(log, "assembly: body, tangent")
    nr, tr = section(log, "assembly: body, residual only")
    rows.append(dict(run=name, cells=cells, newton=int(s["newton_iterations"]),
                     tangent_calls=nt, tangent_s=tt, tangent_us_per_cell=tt / nt / cells * 1e6,
                     residual_calls=nr, residual_s=tr,
                     residual_us_per_cell=tr / nr / cells * 1e6 if nr else float("nan"),
                     wall_s=float(s["wall_time"]), peak_force_N=float(s["peak_punch_force"])))
write(rows, csv_path)
PY

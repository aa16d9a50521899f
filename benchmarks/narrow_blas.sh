#!/usr/bin/env bash
# The opt-in narrow-BLAS library (preload/narrow_blas.cc, started by
# scripts/formsolve-run --narrow-blas), measured:
# 1. the kernels: GEMM/TRSM with one and two columns against GEMV/TRSV
#    (benchmarks/blas_narrow_kernels.c, linked with the system's libblas)
#    -> doc/narrow-blas-kernels.csv;
# 2. the whole shipped 3-D draw (prm/cup-drawing-3d.prm as shipped, VTU off)
#    on 1 and 2 ranks through formsolve-run, without the library ("plain")
#    and with it ("preload"), REPS times each, interleaved
#    -> doc/narrow-blas.csv; runs in results/narrow-blas/.
# About 2.5 min per 1-rank run and 2 min per 2-rank run on 2 quiet cores.
# Usage: [REPS=2] [RANKS="1 2"] bash benchmarks/narrow_blas.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# The BLAS kernels formsolve-run would choose (unless OPENBLAS_CORETYPE is set).
eval "$(bash "$root/scripts/formsolve-run" --env)"
build=${BUILD_DIR:-$root/build}
[ -x "$build/formsolve" ] || bash "$root/scripts/build.sh"
out=$root/results/narrow-blas
mkdir -p "$out"
git -C "$root" rev-parse --short HEAD > "$out/commit"
export OMP_NUM_THREADS=1

gcc -O2 -o "$out/blas_narrow_kernels" "$root/benchmarks/blas_narrow_kernels.c" -lblas
"$out/blas_narrow_kernels" | tee "$root/doc/narrow-blas-kernels.csv"

run() { # name ranks formsolve-run options...
  local name=$1 n=$2
  shift 2
  echo "== $name"
  (cd "$root/prm" && "$build/formsolve-run" -np "$n" "$@" cup-drawing-3d.prm \
    --set "Output/Output directory=$out/$name" --set "Output/Output interval=0" \
    --set "Output/Report=false" > "$out/$name.log" 2>&1)
}
names=()
for n in ${RANKS:-1 2}; do
  for rep in $(seq 1 "${REPS:-2}"); do
    run "plain-$n-$rep" "$n"
    run "preload-$n-$rep" "$n" --narrow-blas
    grep -q "narrow calls to BLAS-2" "$out/preload-$n-$rep.log" \
      || { echo "the preload run did not report the library" >&2; exit 1; }
    names+=("plain-$n-$rep" "preload-$n-$rep")
  done
done
cd "$root/benchmarks"
/usr/bin/python3 - "$out" "$root/doc/narrow-blas.csv" "${names[@]}" <<'PY'
import sys
from run_tables import section, summary, write
out, csv_path = sys.argv[1:3]
rows = []
for name in sys.argv[3:]:
    s = summary(f"{out}/{name}")
    log = open(f"{out}/{name}.log").read()
    wall = float(s["wall_time"])
    subs, sub_s = section(log, "linear solve: substitution")
    facs, fac_s = section(log, "linear solve: factorisation")
    rows.append(dict(run=name.rsplit("-", 2)[0], ranks=int(s["ranks"]), newton=int(s["newton_iterations"]),
                     factorisations=facs, factorisation_s=fac_s, substitutions=subs,
                     substitution_s=sub_s, ms_per_substitution=1e3 * sub_s / max(subs, 1),
                     linear_s=section(log, "linear solve")[1],
                     assembly_s=section(log, "assembly: body, tangent")[1],
                     wall_s=wall, linear_share=section(log, "linear solve")[1] / wall,
                     peak_punch_force_N=float(s["peak_punch_force"]),
                     max_penetration_mm=float(s["max_penetration"]),
                     max_thinning_percent=float(s["max_thinning_percent"]),
                     cutbacks=int(s["cutbacks"])))
write(rows, csv_path)
PY

#!/usr/bin/env bash
# A restructuring must not change results or cost: the shipped cases run by
# an older build (BASE_EXE) and by this one, interleaved, on 1 and 2 ranks:
# - default axisymmetric case (prm/cup-drawing.prm) and shipped 3-D case
#   (prm/cup-drawing-3d.prm), as shipped, with VTU output and report off;
# - this build plain, and with the opt-in narrow-BLAS library preloaded
#   (formsolve-run --narrow-blas), which the older build had built in;
# - every run with the OPENBLAS_CORETYPE formsolve-run chooses.
# Writes doc/results-unchanged.csv: per run the Newton iterations, steps,
# wall time, and the largest difference of history.csv from the older
# build's, relative to each column's largest magnitude: over every column
# (iteration counts, locations and the condition estimate left out; they are
# compared as totals), and over the physics an engineer reads (forces,
# volume, strain, thickness, damage, rim radius). ANALYSE_ONLY=1 rewrites
# the CSV from the runs in results/results-unchanged/.
# Usage: BASE_EXE=/path/to/old/formsolve [REPS=1] [RANKS="1 2"]
#        [CASES="cup-drawing cup-drawing-3d"] bash benchmarks/results_unchanged.sh
# About 12 min with REPS=1 on 2 quiet cores (the 3-D case: 1.5 min per run on 1 rank).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$root/build}
base=${BASE_EXE:?set BASE_EXE to the formsolve of the build to compare with}
out=$root/results/results-unchanged
mkdir -p "$out"
eval "$(bash "$root/scripts/formsolve-run" --env)"
export OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
lib=$build/libformsolve_narrow_blas.so

run() { # name case ranks exe [preload]
  local name=$1 case=$2 n=$3 exe=$4 pre=${5:-}
  echo "== $name"
  local env=(-x OPENBLAS_CORETYPE)
  [ -n "$pre" ] && env+=(-x "LD_PRELOAD=$pre")
  (cd "$root/prm" && mpirun -np "$n" "${env[@]}" "$exe" "$case.prm" \
    --set "Output/Output directory=$out/$name" --set "Output/Output interval=0" \
    --set "Output/Report=false" > "$out/$name.log" 2>&1)
}
names=()
for case in ${CASES:-cup-drawing cup-drawing-3d}; do
  for n in ${RANKS:-1 2}; do
    for rep in $(seq 1 "${REPS:-1}"); do
      if [ "${ANALYSE_ONLY:-0}" != 1 ]; then
        run "$case-$n-$rep-base" "$case" "$n" "$base"
        run "$case-$n-$rep-plain" "$case" "$n" "$build/formsolve"
        run "$case-$n-$rep-preload" "$case" "$n" "$build/formsolve" "$lib"
      fi
      names+=("$case-$n-$rep")
    done
  done
done
PYTHONPATH="$root/benchmarks" /usr/bin/python3 - "$out" "$root/doc/results-unchanged.csv" "${names[@]}" <<'PY'
import csv, re, sys
from run_tables import steps
out, path = sys.argv[1:3]
skip = re.compile(r"_[xyz]$|iterations|strict_passes|condition|locked_pairs|wall")
physics = re.compile(r"^(punch_force|force_die|force_blank_holder|volume|max_equivalent_strain|"
                     r"min_thickness|max_oyane|rim_radius.*)$")

def history(name):
    return steps(f"{out}/{name}")

def summary(name):
    return dict(l.rstrip("\n").split(" = ", 1) for l in open(f"{out}/{name}/run-summary.txt") if " = " in l)

def difference(a, b, only=None):
    if len(a) != len(b):
        return float("inf"), f"{len(a)} rows against {len(b)}"
    worst, where = 0.0, ""
    for k in a[0]:
        if k not in b[0] or skip.search(k) or (only and not only.match(k)):
            continue
        try:
            u = [float(r[k]) for r in a]
            v = [float(r[k]) for r in b]
        except ValueError:
            continue
        scale = max(max(map(abs, u)), max(map(abs, v)), 1e-300)
        for i, (x, y) in enumerate(zip(u, v)):
            d = abs(x - y) / scale
            if d > worst:
                worst, where = d, f"{k}, step {i + 1}"
    return worst, where

rows = []
for name in sys.argv[3:]:
    base = history(name + "-base")
    sb = summary(name + "-base")
    for variant in ("base", "plain", "preload"):
        s = summary(f"{name}-{variant}")
        h = history(f"{name}-{variant}")
        d, where = difference(h, base)
        p, _ = difference(h, base, physics)
        rows.append(dict(case=name.rsplit("-", 2)[0], ranks=s["ranks"], variant=variant,
                         steps=s["steps"], newton=s["newton_iterations"],
                         newton_vs_base=f"{int(s['newton_iterations']) / int(sb['newton_iterations']):.3f}",
                         wall_s=f"{float(s['wall_time']):.1f}",
                         wall_vs_base=f"{float(s['wall_time']) / float(sb['wall_time']):.3f}",
                         history_difference=f"{d:.2e}", largest_at=where,
                         physics_difference=f"{p:.2e}"))
with open(path, "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=list(rows[0]))
    w.writeheader()
    w.writerows(rows)
for r in rows:
    print(r)
PY

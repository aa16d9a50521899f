#!/usr/bin/env bash
# The default cup drawn and redrawn (ratio 40/32 = 1.25) as the axisymmetric
# section (prm/cup-drawing.prm, prm/cup-redraw.prm, 1 rank) and as the
# quarter 3-D model (prm/cup-drawing-3d.prm with the redraw's tools, RANKS
# ranks, default 2); then the cost of a start from an earlier run: the
# set-up (--validate) of the 3-D redraw against the fresh 3-D case's, the
# median of 7 whole processes each. Prints the table of
# doc/next-operation.md. Runs are kept in results/next-operation/ and
# reused unless --force.
# Usage: bash benchmarks/next_operation.sh [--force]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
eval "$(bash "$root/scripts/formsolve-run" --env)"
exe=$root/build/formsolve
[ -x "$exe" ] || bash "$root/scripts/build.sh"
ranks=${RANKS:-2}
out=$root/results/next-operation
mkdir -p "$out"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
cd "$root"
# The 3-D redraw: the quarter cup's Geometry, Mesh and Material, the
# redraw's tools.
cat > "$out/cup-redraw-3d.prm" <<PRM
include $root/prm/cup-drawing-3d.prm
subsection Geometry
  set Start from = $out/first-3d
end
subsection Tools
  subsection Punch
    set Diameter          = 32
    set Profile radius    = 6
    set Gap               = 0.05
    set Gap measured from = part
    set Stroke            = 45
  end
  subsection Die
    set Diameter          = 34.5
    set Profile radius    = 6
    set Gap               = 0
    set Gap measured from = part
  end
  subsection Blank holder
    set Enabled = false
  end
end
PRM
force=0
[ "${1:-}" = --force ] && force=1
run() { # run NAME RANKS PRM [ARGS...]
  local name=$1 n=$2 prm=$3
  shift 3
  [ "$force" = 0 ] && [ -f "$out/$name/run-summary.txt" ] && return
  rm -rf "$out/$name"
  echo "== $name"
  mpirun -np "$n" "$exe" "$prm" --set "Output/Output directory=$out/$name" \
    --set "Output/Report=false" "$@" > "$out/$name.log"
}
run first-2d 1 prm/cup-drawing.prm
run redraw-2d 1 prm/cup-redraw.prm --set "Geometry/Start from=$out/first-2d"
run first-3d "$ranks" prm/cup-drawing-3d.prm
run redraw-3d "$ranks" "$out/cup-redraw-3d.prm"

median() { # median wall time (s) of 7 runs of the command
  for _ in 1 2 3 4 5 6 7; do
    /usr/bin/time -f %e "$@" 2>&1 > /dev/null | tail -1
  done | sort -g | sed -n 4p
}
fresh=$(median mpirun -np "$ranks" "$exe" prm/cup-drawing-3d.prm --validate)
start=$(median mpirun -np "$ranks" "$exe" "$out/cup-redraw-3d.prm" --validate \
  --set "Output/Output directory=$out/validate")

/usr/bin/python3 - "$out" "$fresh" "$start" <<'PY'
import csv, sys
out, fresh, start = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
def summary(name):
    s = {}
    for line in open(f"{out}/{name}/run-summary.txt"):
        if " = " in line:
            k, v = line.rstrip("\n").split(" = ", 1)
            s[k] = v
    return s
def rim(row):  # the sections' column; the 3-D models report the ears
    return f"{float(row['rim_radius']):.2f}" if "rim_radius" in row else "–"
def last(name):
    return list(csv.DictReader(open(f"{out}/{name}/history.csv")))[-1]
print("| run | punch travel (mm) | peak force (kN) at (mm) | cup height (mm) | rim radius (mm) | largest ε̄ | thinning (%) | thickening (%) | steps | Newton | wall (s) |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for name, what in [("first-2d", "axisymmetric, first draw"), ("redraw-2d", "axisymmetric, redraw"),
                   ("first-3d", "quarter 3-D, first draw"), ("redraw-3d", "quarter 3-D, redraw")]:
    s, h = summary(name), last(name)
    print(f"| {what} | {float(s['final_punch_travel']):.2f} | {float(s['peak_punch_force'])/1e3:.1f} at "
          f"{float(s['peak_force_travel']):.2f} | {float(h['cup_height']):.2f} | {rim(h)} | "
          f"{float(h['max_equivalent_strain']):.3f} | {float(s['max_thinning_percent']):.1f} | "
          f"{float(h['max_thickening_percent']):.1f} | {s['steps']} | {s['newton_iterations']} | "
          f"{float(s['wall_time']):.1f} |")
wall = float(summary("first-3d")["wall_time"])
print(f"\nset-up of the 3-D redraw (start from, --validate): {start:.2f} s; of the fresh 3-D case: "
      f"{fresh:.2f} s; the difference is {100 * (start - fresh) / wall:.1f} % and the whole set-up "
      f"{100 * start / wall:.1f} % of the first draw's {wall:.1f} s")
PY

#!/usr/bin/env bash
# The axisymmetric comparison case of issue 62, section 6 (material B, blank
# 77 mm, punch profile radius 8 mm, 20 mm stroke, adaptive-strict with
# delta = 1e-3 mm, output every 10 steps, no report), whole-process wall
# time with material B as shipped (Hill48, r = 0.81) and as von Mises (the
# material B of the code before Hill48 existed), interleaved N times;
# prints each run and the medians. OLD=path/formsolve also times an older
# build on the same scene (OLD_PRM: the cup-drawing.prm folder of its
# checkout, whose B.prm must be read by it).
# Usage: bash benchmarks/comparison_case.sh [N]      (N = 7)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
n=${1:-7}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
scene() { # prm folder
  cat <<PRM
include $1/cup-drawing.prm
include $1/materials/B.prm
subsection Geometry
  set Blank diameter = 77
end
subsection Tools
  subsection Punch
    set Profile radius = 8
    set Stroke = 20
  end
end
subsection Output
  set Output interval = 10
  set Report = false
end
PRM
}
scene "$root/prm" > "$tmp/case.prm"
[ -n "${OLD:-}" ] && scene "${OLD_PRM:?OLD_PRM: the prm folder of the OLD checkout}" > "$tmp/old.prm"
run() { # label, command...
  local label=$1; shift
  local start=$EPOCHREALTIME
  "$@" --set "Output/Output directory=$tmp/out" > /dev/null 2>&1
  echo -e "$label\t$(echo "$EPOCHREALTIME - $start" | bc)" | tee -a "$tmp/walls.txt"
}
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
for k in $(seq "$n"); do
  run "Hill48" "$root/build/formsolve" "$tmp/case.prm"
  run "von Mises" "$root/build/formsolve" "$tmp/case.prm" --set "Material/Yield criterion=von Mises"
  [ -n "${OLD:-}" ] && (cd "$(dirname "$OLD_PRM")" && run "old" "$OLD" "$tmp/old.prm")
done
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "medians (s):"
for label in "Hill48" "von Mises" "old"; do
  grep -P "^$label\t" "$tmp/walls.txt" | cut -f2 | sort -n |
    awk -v l="$label" '{a[NR]=$1} END {if (NR) printf "  %s: %.2f (%d runs)\n", l, a[int((NR+1)/2)], NR}'
done

#!/usr/bin/env bash
# formsolve against CalculiX on the cup of prm/cup-drawing.prm drawn 20 mm
# and released (issue 63 section 5; doc/calculix.md): formsolve's
# axisymmetric section at 5 and 7 planform refinements, CalculiX's (the
# deck of cup_deck.py) with 96 x 2 and, unless FINE=0, 192 x 4 CAX8R
# elements (about 10 minutes more on one core). Writes doc/calculix-cup.csv and
# doc/calculix-cup.png; runs are kept in results/calculix-cup/ and reused
# unless --force. CalculiX comes from Debian (calculix-ccx), installed here:
# a benchmark's peer, not a dependency of formsolve.
# Usage: bash benchmarks/calculix/cup.sh [--force]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
exe=$root/build/formsolve
[ -x "$exe" ] || bash "$root/scripts/build.sh"
command -v ccx > /dev/null || apt-get install -y calculix-ccx
out=$root/results/calculix-cup
force=${1:-}
mkdir -p "$out"
: > "$out/times.csv"
formsolve_case() { # refinements
  local dir=$out/formsolve-r$1
  if [ "$force" = --force ] || [ ! -f "$dir/run-summary.txt" ]; then
    "$exe" "$root/prm/cup-drawing.prm" --set "Mesh/Planform refinements=$1" \
      --set "Tools/Punch/Stroke=20" --set "Time stepping/End of run=stroke" \
      --set "Material/Young's modulus=210000" --set "Material/Poisson's ratio=0.3" \
      --set "Springback/Enabled=true" --set "Output/Output interval=0" \
      --set "Output/Report=false" --set "Output/Output directory=$dir" > "$dir.log"
  fi
  echo "formsolve ($1 refinements),$(sed -n 's/^wall_time = //p' "$dir/run-summary.txt")" >> "$out/times.csv"
}
ccx_case() { # NX NY
  local job=$out/ccx-$1x$2
  if [ "$force" = --force ] || [ ! -f "$job.time" ]; then
    /usr/bin/python3 "$root/benchmarks/calculix/cup_deck.py" "$1" "$2" 20 "$job.inp" --springback
    local t0 t1
    t0=$(date +%s.%N)
    (cd "$out" && OMP_NUM_THREADS=1 ccx -i "$(basename "$job")" > "$job.log")
    t1=$(date +%s.%N)
    /usr/bin/python3 -c "print(round($t1 - $t0, 1))" > "$job.time"
  fi
  echo "CalculiX ($1 x $2 CAX8R),$(cat "$job.time")" >> "$out/times.csv"
}
formsolve_case 5
formsolve_case 7
ccx_case 96 2
cases=("formsolve (5 refinements)=$out/formsolve-r5" "formsolve (7 refinements)=$out/formsolve-r7"
       "CalculiX (96 x 2 CAX8R)=$out/ccx-96x2.dat:96:2")
if [ "${FINE:-1}" != 0 ]; then
  ccx_case 192 4
  cases+=("CalculiX (192 x 4 CAX8R)=$out/ccx-192x4.dat:192:4")
fi
/usr/bin/python3 "$root/benchmarks/calculix/cup_compare.py" "$root/doc/calculix-cup.csv" \
  "$root/doc/calculix-cup.png" "$out/times.csv" "${cases[@]}"

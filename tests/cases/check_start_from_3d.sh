#!/usr/bin/env bash
# A next operation in 3-D on a refined mesh (hanging nodes): the shipped
# quarter cup (cup-adaptive-short.prm: refined at the radii before the first
# step) drawn 0.75 mm, then from its end 0.75 mm more with the tools where it
# left them and the mesh as loaded (Mesh refinement/Interval = 0 in the
# second run), against the cup drawn 1.5 mm in one run: the same steps
# within 2e-3 (the contact's penalty factors start again from rest; 9.7e-4
# in ε̄ at the first step measured, 1e-4 at the last).
# Usage: check_start_from_3d.sh FORMSOLVE CASES OUTDIR RANKS PYTHON
set -uo pipefail
exe=$1 cases=$2 out=$3 ranks=$4 py=$5
rm -rf "$out"; mkdir -p "$out"
cd "$cases"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
run() { # run NAME [ARGS...]
  local name=$1; shift
  timeout 600 mpirun -np "$ranks" "$exe" cup-adaptive-short.prm --set "Output/Output directory=$out/$name" \
    --set "Output/Report=false" "$@" > "$out/$name.log" 2>&1 || { cat "$out/$name.log"; echo "FAIL: $name"; exit 1; }
}
run one --set "Mesh refinement/Interval=100"
run first --set "Mesh refinement/Interval=100" --set "Tools/Punch/Stroke=0.75"
holder=$("$py" -c "
import csv
print(list(csv.DictReader(open('$out/first/history.csv')))[-1]['holder_displacement'])")
run second --set "Mesh refinement/Interval=0" --set "Tools/Punch/Stroke=0.75" \
  --set "Geometry/Start from=$out/first" --set "Tools/Punch/Gap=-0.75" --set "Tools/Blank holder/Gap=$holder"
grep -q "adapted mesh: 1770 cells" "$out/first.log" || { echo "FAIL: the first run's mesh is not the refined one"; exit 1; }
grep -q "quarter model, $ranks rank(s), 1770 cells" "$out/second.log" ||
  { echo "FAIL: the second run did not load the refined mesh"; exit 1; }
"$py" "$cases/check_start_from.py" "$out/one" "$out/second" 0.75 3 2e-3

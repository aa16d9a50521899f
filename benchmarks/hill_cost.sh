#!/usr/bin/env bash
# Hill48's cost (issue 46): the shipped quarter cup (prm/cup-drawing-3d.prm,
# VTU off) on 1 rank, von Mises against Hill48 at r0 = r45 = r90 = 1 (the
# same physics: the histories agree, so the iterations do too), REPS runs
# each, interleaved. Hill assembles the general 6x6 tangent with the frame
# from the reference Jacobians instead of the isotropic product form.
# Writes doc/hill-cost.csv (run, criterion, newton iterations, tangent
# assembly s, residual assembly s, state update s, wall s); runs in
# results/hill-cost/. About 1.5 min per run on a quiet core.
# Usage: [REPS=2] bash benchmarks/hill_cost.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
eval "$(bash "$root/scripts/formsolve-run" --env)"
[ -x "$root/build/formsolve" ] || bash "$root/scripts/build.sh"
out=$root/results/hill-cost
mkdir -p "$out"
export OMP_NUM_THREADS=1
reps=${REPS:-2}
csv=$root/doc/hill-cost.csv
echo "run,criterion,newton_iterations,tangent_assembly_s,residual_assembly_s,state_update_s,wall_s" > "$csv"
section() { # log name -> wall seconds of the timer section
  grep -F "| $2 " "$1" | head -1 | awk -F'|' '{gsub(/[ s]/, "", $4); print $4}'
}
for k in $(seq "$reps"); do
  for criterion in "von Mises" "Hill48"; do
    tag=$(echo "$criterion" | tr -d ' ')-$k
    (cd "$root/prm" && "$root/build/formsolve" cup-drawing-3d.prm \
      --set "Output/Output directory=$out/$tag" --set "Output/Output interval=0" \
      --set "Output/Report=false" --set "Material/Yield criterion=$criterion" \
      --set "Material/R-values=1, 1, 1" > "$out/$tag.log" 2>&1)
    log=$out/$tag.log
    echo "$k,$criterion,$(grep '^newton_iterations' "$out/$tag/run-summary.txt" | cut -d' ' -f3),$(section "$log" "assembly: body, tangent"),$(section "$log" "assembly: body, residual only"),$(section "$log" "state update"),$(grep '^wall_time' "$out/$tag/run-summary.txt" | cut -d' ' -f3)" | tee -a "$csv"
  done
done

#!/usr/bin/env bash
# Kill and resume (issue 12): a run killed with SIGKILL mid-way and resumed
# with --resume ends with the same history.csv and refinement.csv as an
# uninterrupted run (numdiff), and no truncated or temporary file is left.
# Twice: killed before a step is solved (resumes from the last checkpoint),
# and killed half-way through writing a checkpoint (the incomplete one is
# ignored, the one before it is used).
# Usage: check_resume.sh FORMSOLVE PRM OUTDIR RANKS KILL_STEP CHECKPOINT_STEP
set -uo pipefail
exe=$1 prm=$2 out=$3 ranks=$4 kill_step=$5 checkpoint_step=$6
rm -rf "$out"; mkdir -p "$out"
cd "$(dirname "$prm")"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
run() { # run DIR [ARGS...]
  local dir=$1; shift
  if [ "$ranks" -gt 1 ]; then
    timeout 600 mpirun -np "$ranks" "$exe" "$prm" --set "Output/Output directory=$dir" "$@"
  else
    timeout 600 "$exe" "$prm" --set "Output/Output directory=$dir" "$@"
  fi
}
same() { # same FILE A B
  numdiff -q -s ', \t\n' -r 1e-8 -a 1e-10 "$2/$1" "$3/$1" ||
    { echo "FAIL: $3/$1 differs from the uninterrupted run"; numdiff -s ', \t\n' -r 1e-8 -a 1e-10 "$2/$1" "$3/$1" | head -20; exit 1; }
}
run "$out/uninterrupted" > "$out/uninterrupted.log" 2>&1 || { cat "$out/uninterrupted.log"; exit 1; }

for kill in "step:$kill_step" "checkpoint:$checkpoint_step"; do
  dir="$out/killed-${kill%%:*}"
  FORMSOLVE_KILL_AT=$kill run "$dir" > "$dir.log" 2>&1
  rc=$?
  [ $rc -ne 0 ] && [ $rc -ne 124 ] || { echo "FAIL: the run to be killed at $kill exited $rc"; exit 1; }
  grep -q "^done" "$dir.log" && { echo "FAIL: the run to be killed at $kill was not killed"; exit 1; }
  [ -f "$dir/checkpoint/complete" ] || { echo "FAIL: no complete checkpoint after the kill at $kill"; exit 1; }
  at=$(sed -n 's/^step = //p' "$dir/checkpoint/meta.txt")
  run "$dir" --resume > "$dir.resume.log" 2>&1 || { cat "$dir.resume.log"; exit 1; }
  grep -q "resumed from the checkpoint at step $at" "$dir.resume.log" ||
    { echo "FAIL: did not say where it resumed"; head "$dir.resume.log"; exit 1; }
  same history.csv "$out/uninterrupted" "$dir"
  same solver.csv "$out/uninterrupted" "$dir"
  [ -f "$out/uninterrupted/refinement.csv" ] && same refinement.csv "$out/uninterrupted" "$dir"
  same sheet.csv "$out/uninterrupted" "$dir"
  leftovers=$(find "$dir" -name '*.tmp' -o -name 'checkpoint.new' -o -name 'checkpoint.old')
  [ -z "$leftovers" ] || { echo "FAIL: left behind: $leftovers"; exit 1; }
  # The .pvd lists the same outputs, and each exists.
  [ -f "$out/uninterrupted/solution.pvd" ] && { diff <(grep -o 'file="[^"]*"' "$out/uninterrupted/solution.pvd") \
       <(grep -o 'file="[^"]*"' "$dir/solution.pvd") ||
    { echo "FAIL: solution.pvd lists other files"; exit 1; }
  for f in $(grep -o 'file="[^"]*"' "$dir/solution.pvd" | cut -d'"' -f2); do
    [ -s "$dir/$f" ] || { echo "FAIL: $f is missing"; exit 1; }
  done; }
  echo "ok: killed at $kill, resumed from step $at: history.csv, solver.csv, refinement.csv, sheet.csv and solution.pvd as uninterrupted"
done

#!/usr/bin/env bash
# Checkpoints by wall time (Output/Checkpoint wall time, on by default at 10
# min): with the interval set below one step's time and no step interval, a
# run killed before step 6 has a complete checkpoint of step 5 and resumes
# from it to the stroke; with 0 (off) the same kill leaves none.
# Usage: check_wall_checkpoint.sh FORMSOLVE PRM OUTDIR
set -uo pipefail
exe=$1 prm=$2 out=$3
rm -rf "$out"; mkdir -p "$out"
cd "$(dirname "$prm")"
base=(--set "Output/Checkpoint interval=0" --set "Output/Report=false")
FORMSOLVE_KILL_AT=step:6 "$exe" "$prm" --set "Output/Output directory=$out/on" "${base[@]}" \
  --set "Output/Checkpoint wall time=1e-6" > "$out/on.log" 2>&1
[ -f "$out/on/checkpoint/complete" ] || { echo "FAIL: no complete checkpoint by wall time"; exit 1; }
at=$(sed -n 's/^step = //p' "$out/on/checkpoint/meta.txt")
[ "$at" = 5 ] || { echo "FAIL: the checkpoint is of step $at, not 5"; exit 1; }
"$exe" "$prm" --set "Output/Output directory=$out/on" "${base[@]}" \
  --set "Output/Checkpoint wall time=1e-6" --resume > "$out/on.resume.log" 2>&1 \
  || { cat "$out/on.resume.log"; echo "FAIL: --resume"; exit 1; }
grep -q "^done" "$out/on.resume.log" || { echo "FAIL: the resumed run did not finish"; exit 1; }
FORMSOLVE_KILL_AT=step:6 "$exe" "$prm" --set "Output/Output directory=$out/off" "${base[@]}" \
  --set "Output/Checkpoint wall time=0" > "$out/off.log" 2>&1
[ ! -e "$out/off/checkpoint/complete" ] || { echo "FAIL: a checkpoint with the wall time off"; exit 1; }
echo "ok: checkpoint of step 5 by wall time, resumed to the end; none with it off"

#!/usr/bin/env bash
# An exception on one rank only (injected at step 2 on rank R while the other
# rank works on in its collectives) must end every rank: exit status non-zero
# within the time limit (no hang), and exactly one formsolve message, naming
# the rank when it is not 0.
# Usage: check_rank_error.sh FORMSOLVE PRM OUTDIR RANK
set -uo pipefail
exe=$1 prm=$2 out=$3 rank=$4
rm -rf "$out"; mkdir -p "$(dirname "$out")"
cd "$(dirname "$prm")"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
start=$(date +%s)
FORMSOLVE_FAIL_ON_RANK=$rank FORMSOLVE_FAIL_AT_STEP=2 timeout 120 \
  mpirun -np 2 "$exe" "$prm" --set "Output/Output directory=$out" --set "Output/Report=false" \
  > "$out.log" 2> "$out.err"
rc=$?
took=$(( $(date +%s) - start ))
grep "formsolve" "$out.err"
[ $rc -ne 0 ] || { echo "FAIL: exit status 0"; exit 1; }
[ $rc -ne 124 ] || { echo "FAIL: hung (killed by timeout after $took s)"; exit 1; }
[ "$(grep -c '^formsolve: error' "$out.err")" -eq 1 ] || { echo "FAIL: not exactly one message"; cat "$out.err"; exit 1; }
grep -q "injected failure" "$out.err" || { echo "FAIL: the message does not say what failed"; exit 1; }
if [ "$rank" -ne 0 ]; then
  grep -q "(rank $rank)" "$out.err" || { echo "FAIL: the message does not name rank $rank"; exit 1; }
fi
grep -q "^step    1" "$out.log" || { echo "FAIL: step 1 should have been solved"; exit 1; }
echo "ok: exit $rc after $took s, one message"

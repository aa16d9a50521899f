#!/usr/bin/env bash
# The iteration log's contact changes (Nonlinear solver/Log iterations: the
# pairs each tool closed and opened at every search) and rigid-zone counts
# (quadrature points at or below the limiting strain rate, and how many
# became rigid and plastic): logging changes no result, and the counts,
# summed over ranks, are the same on 1 and 2 ranks.
# Usage: check_iteration_log.sh FORMSOLVE PRM OUTDIR [--set "..."]...
set -uo pipefail
. "$(dirname "$0")/ab_runs.sh" "$@"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
run quiet
run logged --set "Nonlinear solver/Log iterations=true"
mpirun -np 2 "$exe" "$prm" --set "Output/Output directory=$out/logged2" \
  --set "Output/Report=false" "${common[@]}" \
  --set "Nonlinear solver/Log iterations=true" > "$out/logged2.log" 2>&1 ||
  { echo "FAIL: run logged2 failed"; tail -5 "$out/logged2.log"; exit 1; }
for f in history.csv solver.csv; do
  cmp -s "$out/quiet/$f" "$out/logged/$f" ||
    { echo "FAIL: $f differs with Log iterations = true"; exit 1; }
done
changes() { grep -E '^ +it ' "$1" | sed -n 's/.*\(it *[0-9]*\) .*pairs: \([^ ]* [^ ]*\( [^ ]* [^ ]*\)*\)  .*/\1 \2/p'; }
# Quadrature points in the rigid zone and their transitions (+rigid/-plastic).
rigid() { grep -E '^ +it ' "$1" | sed -n 's/.*\(it *[0-9]*\) .*rigid points: \([0-9]* ([^)]*)\).*/\1 \2/p'; }
one=$(changes "$out/logged.log")
two=$(changes "$out/logged2.log")
[ -n "$one" ] || { echo "FAIL: no contact changes in the log: the case tests nothing"; exit 1; }
[ "$one" = "$two" ] ||
  { echo "FAIL: contact changes differ between 1 and 2 ranks"; diff <(echo "$one") <(echo "$two") | head; exit 1; }
echo "$(echo "$one" | wc -l) iterations with contact changes, the same on 1 and 2 ranks"
one=$(rigid "$out/logged.log")
two=$(rigid "$out/logged2.log")
echo "$one" | grep -q '(+[1-9]\|/-[1-9]' ||
  { echo "FAIL: no rigid-plastic transitions in the log: the case tests nothing"; exit 1; }
[ "$one" = "$two" ] ||
  { echo "FAIL: rigid points differ between 1 and 2 ranks"; diff <(echo "$one") <(echo "$two") | head; exit 1; }
echo "$(echo "$one" | grep -c '(+[1-9]\|/-[1-9]') iterations with rigid-plastic transitions, the same on 1 and 2 ranks"

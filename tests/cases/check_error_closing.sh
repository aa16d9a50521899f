#!/usr/bin/env bash
# An error past the first step (injected at step 3 on the only rank) ends the
# run with exit 1 and one message, after rank 0 wrote the closing files of
# the last converged step: run-summary.txt whose end_reason names the error,
# sheet.csv and the report; the checkpoint of step 2 (Checkpoint interval =
# 1) is left complete, and --resume continues from it to the stroke with the
# same history as an uninterrupted run.
# Usage: check_error_closing.sh FORMSOLVE PRM OUTDIR PYTHON
set -uo pipefail
exe=$1 prm=$2 out=$3 python=$4
rm -rf "$out" "$out.ref"; mkdir -p "$(dirname "$out")"
cd "$(dirname "$prm")"
set_=(--set "Output/Checkpoint interval=1" --set "Output/Report=true")
FORMSOLVE_FAIL_ON_RANK=0 FORMSOLVE_FAIL_AT_STEP=3 "$exe" "$prm" --set "Output/Output directory=$out" \
  "${set_[@]}" > "$out.log" 2> "$out.err"
rc=$?
cat "$out.err"
[ $rc -ne 0 ] || { echo "FAIL: exit status 0"; exit 1; }
[ "$(grep -c '^formsolve: error' "$out.err")" -eq 1 ] || { echo "FAIL: not exactly one error message"; exit 1; }
grep -q "^end_reason = error in step 3 (punch travel 0.5 mm): injected failure" "$out/run-summary.txt" \
  || { echo "FAIL: run-summary.txt does not name the error"; grep end_reason "$out/run-summary.txt"; exit 1; }
[ "$(wc -l < "$out/history.csv")" -eq 3 ] || { echo "FAIL: history.csv should hold steps 1 and 2"; exit 1; }
[ -s "$out/sheet.csv" ] || { echo "FAIL: no sheet.csv"; exit 1; }
"$python" "$(dirname "$0")/check_report.py" "$out" > "$out.report-check" \
  || { cat "$out.report-check"; echo "FAIL: the report"; exit 1; }
[ -f "$out/checkpoint/complete" ] || { echo "FAIL: the checkpoint of step 2 is not complete"; exit 1; }
"$exe" "$prm" --set "Output/Output directory=$out" "${set_[@]}" --resume > "$out.resume.log" 2>&1 \
  || { cat "$out.resume.log"; echo "FAIL: --resume after the error"; exit 1; }
"$exe" "$prm" --set "Output/Output directory=$out.ref" --set "Output/Report=false" > "$out.ref.log" 2>&1 \
  || { cat "$out.ref.log"; exit 1; }
"$python" "$(dirname "$0")/check_regression.py" "$out" "$out.ref/history.csv" \
  || { echo "FAIL: the resumed run differs from the uninterrupted one"; exit 1; }
echo "ok: exit $rc, one message, closing files and report of step 2, resumed to the stroke"

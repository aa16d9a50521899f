#!/usr/bin/env bash
# A step that fails at the minimum time step ends the run: exit 1, one
# message naming Time stepping/Minimum time step, and the closing files of
# the last converged step (here the initial state) written: the VTU,
# sheet.csv, run-summary.txt whose end_reason says so, and the report
# (check_report.py reads it). RANKS=2: the same under mpirun, where the
# report, made after every rank has met the error, must not cost the job.
set -uo pipefail
exe=$1 prm=$2 out=$3
rm -rf "$out"; mkdir -p "$(dirname "$out")"
cd "$(dirname "$prm")"
launch=("$exe")
if [ "${RANKS:-1}" -gt 1 ]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
  launch=(timeout 300 mpirun -np "$RANKS" "$exe")
fi
"${launch[@]}" "$prm" --set "Output/Output directory=$out" --set "Output/Output interval=1" \
  --set "Time stepping/Minimum time step=0.5" --set "Output/Report=true" > "$out.log" 2> "$out.err"
rc=$?
cat "$out.err"
[ $rc -ne 124 ] || { echo "FAIL: hung"; exit 1; }
[ "$(grep -c '^formsolve' "$out.err")" -eq 1 ] || { echo "FAIL: not exactly one formsolve message"; exit 1; }
[ $rc -ne 0 ] || { echo "FAIL: exit status 0"; exit 1; }
grep -q "Minimum time step" "$out.err" || { echo "FAIL: no message naming the entry"; exit 1; }
[ -f "$out/solution_00000.pvtu" ] && grep -q solution_00000 "$out/solution.pvd" \
  || { echo "FAIL: the last converged step was not written"; exit 1; }
[ "$(wc -l < "$out/history.csv")" -eq 1 ] || { echo "FAIL: history.csv should hold the header only"; exit 1; }
grep -q "^end_reason = step 1 (punch travel 0 mm): Newton did not converge.*Minimum time step" "$out/run-summary.txt" \
  || { echo "FAIL: run-summary.txt does not say why the run ended"; cat "$out/run-summary.txt"; exit 1; }
[ -s "$out/sheet.csv" ] || { echo "FAIL: no sheet.csv"; exit 1; }
[ -s "$out/report/report.md" ] || { echo "FAIL: no report"; cat "$out/report.log"; exit 1; }
python3=${PYTHON3:-/usr/bin/python3}
"$python3" "$(dirname "$0")/check_report.py" "$out" || { echo "FAIL: the report"; exit 1; }
echo "ok: stopped with the reason, the closing files and the report of the last converged step written"

#!/usr/bin/env bash
# A step that fails at the minimum time step ends the run: exit 1, one
# message naming Time stepping/Minimum time step, and the output of the last
# converged step (here the initial state) written.
set -uo pipefail
exe=$1 prm=$2 out=$3
rm -rf "$out"; mkdir -p "$(dirname "$out")"
cd "$(dirname "$prm")"
"$exe" "$prm" --set "Output/Output directory=$out" --set "Output/Output interval=1" \
  --set "Time stepping/Minimum time step=0.5" > "$out.log" 2> "$out.err"
rc=$?
cat "$out.err"
[ $rc -ne 0 ] || { echo "FAIL: exit status 0"; exit 1; }
grep -q "Minimum time step" "$out.err" || { echo "FAIL: no message naming the entry"; exit 1; }
[ "$(grep -c . "$out.err")" -le 3 ] || { echo "FAIL: more than one message"; exit 1; }
[ -f "$out/solution_00000.pvtu" ] && grep -q solution_00000 "$out/solution.pvd" \
  || { echo "FAIL: the last converged step was not written"; exit 1; }
[ "$(wc -l < "$out/history.csv")" -eq 1 ] || { echo "FAIL: history.csv should hold the header only"; exit 1; }
echo "ok: stopped with the reason, output of the last converged step written"

#!/usr/bin/env bash
# The tiny case (tiny.prm: two steps with output and a checkpoint) under
# valgrind memcheck: no invalid read or write, no use of uninitialised
# values, no definite leak outside Open MPI's start-up (tests/valgrind.supp,
# Open MPI's own openmpi-valgrind.supp).
# Usage: check_valgrind.sh FORMSOLVE CASES OUTDIR
set -uo pipefail
exe=$1 cases=$2 out=$3
rm -rf "$out"; mkdir -p "$(dirname "$out")"
command -v valgrind > /dev/null || { echo "FAIL: valgrind is not installed (scripts/install-dependencies.sh)"; exit 1; }
cd "$cases"
supp=(--suppressions="$cases/../valgrind.supp")
[ -f /usr/share/openmpi/openmpi-valgrind.supp ] && supp+=(--suppressions=/usr/share/openmpi/openmpi-valgrind.supp)
# Valgrind's virtual CPU has no AVX-512: OpenBLAS's SkylakeX kernels (which
# run-tests.sh or OpenBLAS itself may choose) stop with SIGILL under it. The
# generic SSE3 kernels run on every x86-64 CPU.
export OPENBLAS_CORETYPE=Prescott
valgrind --error-exitcode=42 --leak-check=full --show-leak-kinds=definite \
  --errors-for-leak-kinds=definite "${supp[@]}" \
  "$exe" tiny.prm --set "Output/Output directory=$out" > "$out.log" 2> "$out.valgrind"
rc=$?
grep "ERROR SUMMARY" "$out.valgrind"
[ $rc -eq 0 ] || { echo "FAIL: exit $rc"; grep -A25 -E "Invalid|uninitialised|definitely lost in" "$out.valgrind" | head -80; exit 1; }
grep -q "^done: 2 steps" "$out.log" || { echo "FAIL: the run did not finish"; tail "$out.log"; exit 1; }
[ -f "$out/checkpoint/complete" ] || { echo "FAIL: no checkpoint"; exit 1; }
echo "ok: memcheck clean"

#!/usr/bin/env bash
# run_case.sh FORMSOLVE PRM RANKS OUTDIR PYTHON CHECK [ARGS...]
# Runs one case into OUTDIR (on RANKS MPI ranks), then the check script. The
# run report is left out unless CASE_REPORT=true.
# CASE_OUT_OF_CORE=1: MUMPS's factors go to the new, empty directory
# OUTDIR.factors (Linear solver/Out-of-core directory).
set -euo pipefail
exe=$1 prm=$2 ranks=$3 out=$4 python=$5 check=$6
shift 6
rm -rf "$out"
mkdir -p "$(dirname "$out")"
cd "$(dirname "$prm")"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
report=${CASE_REPORT:-false}
extra=()
if [ "${CASE_OUT_OF_CORE:-0}" = 1 ]; then
  rm -rf "$out.factors"
  mkdir -p "$out.factors"
  extra=(--set "Linear solver/Out-of-core directory=$out.factors")
fi
if [ "$ranks" -gt 1 ]; then
  mpirun -np "$ranks" "$exe" "$prm" --set "Output/Output directory=$out" --set "Output/Report=$report" \
    ${extra[@]+"${extra[@]}"} > "$out.log" 2>&1 || { cat "$out.log"; exit 1; }
else
  "$exe" "$prm" --set "Output/Output directory=$out" --set "Output/Report=$report" \
    ${extra[@]+"${extra[@]}"} > "$out.log" 2>&1 || { cat "$out.log"; exit 1; }
fi
grep -E '^step|^done' "$out.log" | tail -3
case "$check" in
  *.py) exec "$python" "$check" "$out" "$@" ;;
  *) exec bash "$check" "$out" "$@" ;;
esac

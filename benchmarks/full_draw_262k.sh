#!/usr/bin/env bash
# The full draw of the quarter 3-D cup at 262k DoFs (planform level 6, 6
# layers), 2 ranks, single-precision factors reused as GMRES's
# preconditioner (Reuse tolerance 1e-6); everything else the default case.
# Needs both cores for about 1.8 h (1.3 h with "reuse", 55 min with
# "forcing" since 0d1e0c6, measured on this machine). Writes results/full-draw-262k/run/,
# run.log and time.txt (/usr/bin/time -v); doc/performance.md reports it.
# With "reuse": factorisations also reused between close velocities (Reuse
# factorisation iterations = 10, Reuse velocity change = 2e-3), into
# results/full-draw-262k-reuse/. With "forcing": inexact Newton as well
# (Nonlinear solver/Forcing = 1) and factors tried up to Reuse velocity
# change = 3e-2, into results/full-draw-262k-forcing/, with a checkpoint
# every 10 steps and the Newton iterations logged (to replay a hard step).
# With "forcing-symmetric": as "forcing", with the factors those of the
# symmetric part (LDL^T), into results/full-draw-262k-forcing-symmetric/.
# Usage: [STROKE=mm] bash benchmarks/full_draw_262k.sh [reuse|forcing|forcing-symmetric]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# The BLAS kernels formsolve-run would choose (unless OPENBLAS_CORETYPE is set).
eval "$(bash "$root/scripts/formsolve-run" --env)"
exe=${FORMSOLVE_EXE:-$root/build/formsolve}
[ -x "$exe" ] || bash "$root/scripts/build.sh"
. "$root/benchmarks/from_rest.sh" && from_rest "$exe" # as the figures in doc/
out=$root/results/full-draw-262k
extra=()
if [ "${1:-}" = reuse ]; then
  out=$root/results/full-draw-262k-reuse
  extra=(--set "Linear solver/Reuse factorisation iterations=10"
    --set "Linear solver/Reuse velocity change=2e-3")
elif [ "${1:-}" = forcing ] || [ "${1:-}" = forcing-symmetric ]; then
  out=$root/results/full-draw-262k-$1
  extra=(--set "Linear solver/Reuse factorisation iterations=10"
    --set "Linear solver/Reuse velocity change=3e-2"
    --set "Nonlinear solver/Forcing=1"
    --set "Output/Checkpoint interval=10"
    --set "Nonlinear solver/Log iterations=true")
  # LDL^T of the symmetric part (single precision) as GMRES's preconditioner.
  [ "$1" = forcing-symmetric ] &&
    extra+=(--set "Linear solver/Unsymmetric tangent=symmetric part")
fi
# STROKE=mm stops the draw there (the same steps as the whole draw's first).
[ -n "${STROKE:-}" ] && extra+=(--set "Tools/Punch/Stroke=$STROKE"
  --set "Time stepping/End of run=stroke")
mkdir -p "$out"
export OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
git -C "$root" rev-parse --short HEAD > "$out/commit"
cd "$root/prm"
/usr/bin/time -v mpirun -np 2 "$exe" cup-drawing.prm ${rest[@]+"${rest[@]}"} \
  --set "Geometry/Model=quarter" --set "Mesh refinement/Interval=0" \
  --set "Mesh/Layers through thickness=6" --set "Mesh/Planform refinements=6" \
  --set "Output/Output directory=$out/run" --set "Output/Revolved copy=false" \
  --set "Linear solver/Factor precision=single" \
  --set "Linear solver/Reuse tolerance=1e-6" ${extra[@]+"${extra[@]}"} \
  > "$out/run.log" 2> "$out/time.txt"
grep "^done" "$out/run.log"
grep -E "Elapsed|Maximum resident" "$out/time.txt"

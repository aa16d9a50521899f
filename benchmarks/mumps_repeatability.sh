#!/usr/bin/env bash
# MUMPS run to run (doc/reliability.md, section 5): one matrix factorised and
# solved six times through formsolve's MumpsDirect on 1 and 2 ranks, every
# solution compared bit for bit with the first (benchmarks/mumps_repeatability.cc,
# a 3-D operator on M^3 nodes). A few seconds.
#   [M=30] bash benchmarks/mumps_repeatability.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
eval "$(bash "$root/scripts/formsolve-run" --env)"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
build=${BUILD_DIR:-$root/build}
[ -f "$build/Makefile" ] || bash "$root/scripts/build.sh"
make -C "$build" mumps_repeatability > /dev/null
for n in 1 2; do
  echo "== $n rank(s)"
  mpirun -np "$n" "$build/mumps_repeatability" "${M:-30}"
done

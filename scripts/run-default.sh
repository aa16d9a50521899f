#!/usr/bin/env bash
# One command from a fresh Debian 12 machine to results: install dependencies,
# build (Release), run the default case prm/cup-drawing.prm on all cores.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/install-dependencies.sh"
bash "$root/scripts/build.sh"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cd "$root"
ranks=${RANKS:-$(nproc)}
mpirun -np "$ranks" "$root/build/formsolve" prm/cup-drawing.prm "$@"
echo
echo "results: $root/results/cup-drawing (history.csv, solution.pvd for ParaView, parameters.prm)"

#!/usr/bin/env bash
# One command from a fresh Debian 12 machine to results: install dependencies,
# build (Release), run the default case prm/cup-drawing.prm (the axisymmetric
# cup: a few hundred DoFs, fastest on one rank; RANKS=n for more).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/install-dependencies.sh"
bash "$root/scripts/build.sh"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cd "$root"
ranks=${RANKS:-1}
mpirun -np "$ranks" "$root/build/formsolve" prm/cup-drawing.prm "$@"
echo
echo "results: $root/results/cup-drawing (history.csv; solution.pvd and revolved.pvd for ParaView; parameters.prm)"
echo "the same cup in 3-D: mpirun -np 2 build/formsolve prm/cup-drawing-3d.prm"

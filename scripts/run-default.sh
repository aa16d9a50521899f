#!/usr/bin/env bash
# One command from a fresh Debian 12 machine to results: install dependencies,
# build (Release), run the default case prm/cup-drawing.prm (the axisymmetric
# cup: a few hundred DoFs, fastest on one rank; RANKS=n for more).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/install-dependencies.sh"
bash "$root/scripts/build.sh"
cd "$root"
"$root/build/formsolve-run" -np "${RANKS:-1}" prm/cup-drawing.prm "$@"
echo
echo "results: $root/results/cup-drawing (history.csv; solution.pvd and revolved.pvd for ParaView; parameters.prm; report/report.md)"
echo "the same cup in 3-D: build/formsolve-run -np 2 --narrow-blas prm/cup-drawing-3d.prm"

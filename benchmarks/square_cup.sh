#!/usr/bin/env bash
# The square cup of doc/reference-scenes.md (section 3), quarter, drawn
# 40 mm on 2 ranks: analytic tools, meshed tools (1 mm facets) and the Hill48
# variant (analytic tools). Writes the runs to OUTDIR (results/square-cup
# unless given), the thickness-strain CSV and PNG files into each run folder
# (the three figures of doc/tools.md copied into doc/), and prints the table
# of doc/tools.md section 2. About 70 min (2 cores).
#   bash benchmarks/square_cup.sh [OUTDIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/results/square-cup}
export OPENBLAS_CORETYPE=${OPENBLAS_CORETYPE:-Haswell}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mkdir -p "$out"
for case in square-cup-reference square-cup-reference-meshed \
  square-cup-reference-anisotropic; do
  (cd "$root" && mpirun -np 2 build/formsolve "prm/$case.prm" \
    --set "Output/Output directory=$out/$case") > "$out/$case.log" 2>&1
done
/usr/bin/python3 "$root/benchmarks/square_cup_profiles.py" \
  "$out/square-cup-reference" "$out/square-cup-reference-meshed" > /dev/null
/usr/bin/python3 "$root/benchmarks/square_cup_profiles.py" \
  "$out/square-cup-reference-anisotropic" "$out/square-cup-reference" > /dev/null
for travel in 15 40; do
  cp "$out/square-cup-reference/thickness_strain_${travel}mm.png" \
    "$root/doc/square-cup-thickness-strain-${travel}mm.png"
done
cp "$out/square-cup-reference-anisotropic/thickness_strain_40mm.png" \
  "$root/doc/square-cup-anisotropic-thickness-strain-40mm.png"
/usr/bin/python3 "$root/benchmarks/square_cup_table.py" \
  "analytic tools=$out/square-cup-reference" \
  "meshed tools (1 mm facets)=$out/square-cup-reference-meshed" \
  "Hill48, analytic tools=$out/square-cup-reference-anisotropic"

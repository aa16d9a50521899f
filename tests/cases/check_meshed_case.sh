#!/usr/bin/env bash
# check_meshed_cup.sh FORMSOLVE TOOLS_DIR OUTDIR PYTHON: the quarter cup of
# cup-quarter.prm (5 mm of travel, 2 ranks) with its analytic tools and with
# meshed copies of them (meshes/tools/make-tools.sh cup) at facets of 2, 1
# and 0.5 mm; compare_meshed_cup.py compares the punch forces.
set -euo pipefail
exe=$1 tools=$2 out=$3 python=$4
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$out"
mkdir -p "$out"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
cd "$here"
run() { # name extra-settings...
  local name=$1; shift
  mpirun -np 2 "$exe" cup-quarter.prm --set "Output/Output directory=$out/$name" \
    --set "Output/Report=false" "$@" > "$out/$name.log" 2>&1 ||
    { cat "$out/$name.log"; exit 1; }
  grep -E '^done' "$out/$name.log"
}
run analytic
for size in 2 1 0.5; do
  bash "$tools/make-tools.sh" cup "$size" "$out/tools-$size" stl > /dev/null
  settings=()
  for tool in Punch:punch Die:die "Blank holder:holder"; do
    settings+=(--set "Tools/${tool%%:*}/Shape=mesh"
               --set "Tools/${tool%%:*}/Mesh file=$out/tools-$size/${tool##*:}.stl")
  done
  run "meshed-$size" "${settings[@]}"
done
exec "$python" "$here/compare_meshed_cup.py" "$out"

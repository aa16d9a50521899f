#!/usr/bin/env bash
# check_meshed_case.sh FORMSOLVE TOOLS_DIR OUTDIR PYTHON PRM TOOLSET SIZES
#   COMPARE [ARGS...]: the case PRM (in tests/cases or a path; 2 ranks) with
# its analytic tools and with meshed copies (meshes/tools/make-tools.sh
# TOOLSET; STL, or .msh profiles for cup-profile) at each facet size of
# SIZES ("2 1 0.5"); ARGS are further --set
# options for every run. COMPARE (a .py beside this script, with its own
# arguments after OUTDIR in the same word: "compare_meshed_cup.py 0.015")
# then compares OUTDIR/analytic with OUTDIR/meshed-<size>.
set -euo pipefail
exe=$1 tools=$2 out=$3 python=$4 prm=$5 toolset=$6 sizes=$7 compare=$8
shift 8
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$out"
mkdir -p "$out"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
cd "$here"
run() { # name settings...
  local name=$1; shift
  mpirun -np 2 "$exe" "$prm" --set "Output/Output directory=$out/$name" \
    --set "Output/Report=false" "$@" > "$out/$name.log" 2>&1 ||
    { cat "$out/$name.log"; exit 1; }
  grep -E '^done' "$out/$name.log"
}
run analytic "$@"
format=stl
[[ $toolset == *-profile ]] && format=msh
for size in $sizes; do
  bash "$tools/make-tools.sh" "$toolset" "$size" "$out/tools-$size" $format > /dev/null
  settings=()
  for tool in Punch:punch Die:die "Blank holder:holder"; do
    settings+=(--set "Tools/${tool%%:*}/Shape=mesh"
               --set "Tools/${tool%%:*}/Mesh file=$out/tools-$size/${tool##*:}.$format")
  done
  run "meshed-$size" "${settings[@]}" "$@"
done
read -r -a compare_args <<< "$compare"
exec "$python" "$here/${compare_args[0]}" "$out" "${compare_args[@]:1}"

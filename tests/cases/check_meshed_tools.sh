#!/usr/bin/env bash
# check_meshed_tools.sh TEST_PROGRAM MESHES_TOOLS_DIR OUTDIR: the default
# cup's tools meshed by gmsh at facets of 2, 1 and 0.5 mm
# (meshes/tools/make-tools.sh), then compared with the analytic tools.
set -euo pipefail
program=$1 tools=$2 out=$3
rm -rf "$out"
for size in 2 1 0.5; do
  bash "$tools/make-tools.sh" cup "$size" "$out/$size" stl
done
exec "$program" "$out/2" "$out/1" "$out/0.5"

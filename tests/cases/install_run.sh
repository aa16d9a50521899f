#!/usr/bin/env bash
# install_run.sh BUILD OUT PYTHON CHECK
# cmake --install into OUT/prefix, then, from a folder outside the source
# and build trees, the installed formsolve-run on the installed default
# example (drawn 5 mm) with the report on; the check reads the report. The
# installed pan (meshed tools from the gmsh scripts installed beside the
# examples, named relative to pan.prm) passes the input checks from that
# other folder too; the user documentation is installed.
set -euo pipefail
build=$1 out=$2 python=$3 check=$4
rm -rf "$out"
mkdir -p "$out/elsewhere"
cmake --install "$build" --prefix "$out/prefix" > "$out/install.log" 2>&1 \
  || { cat "$out/install.log"; exit 1; }
for f in bin/formsolve bin/formsolve-run bin/formsolve-report lib/libformsolve_narrow_blas.so \
         share/formsolve/examples/cup-drawing.prm share/formsolve/examples/materials/B.prm \
         share/formsolve/meshes/tools/pan/punch.geo share/doc/formsolve/user-guide.md \
         share/doc/formsolve/README.md; do
  [ -e "$out/prefix/$f" ] || { echo "not installed: $f"; exit 1; }
done
cd "$out/elsewhere"
"$out/prefix/bin/formsolve-run" "$out/prefix/share/formsolve/examples/cup-drawing.prm" \
  --set "Tools/Punch/Stroke=5" --set "Output/Output directory=run" --set "Output/Report=true" \
  > "$out/run.log" 2>&1 || { cat "$out/run.log"; exit 1; }
grep -q "report: run/report/report.md" "$out/run.log" || { echo "no report line in the run's output"; exit 1; }
"$out/prefix/bin/formsolve" "$out/prefix/share/formsolve/examples/pan.prm" --validate \
  > "$out/pan.log" 2>&1 || { cat "$out/pan.log"; exit 1; }
[ ! -e "$out/prefix/share/doc/formsolve/dev" ] || { echo "development logs installed"; exit 1; }
exec "$python" "$check" "$out/elsewhere/run"

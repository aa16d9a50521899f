#!/usr/bin/env bash
# The shipped redraw (prm/cup-redraw.prm) as the guide runs it, after the
# default case, from the repository folder, with both output folders moved
# to OUTDIR: the redraw starts from the default cup, places its tools
# against it, and draws it through the 34.5 mm die; its rim ends inside the
# die opening, its strain continues the first draw's, the first draw's
# folder is left as it was.
# Usage: check_redraw_example.sh FORMSOLVE SOURCE_DIR OUTDIR PYTHON
set -uo pipefail
exe=$1 src=$2 out=$3 py=$4
rm -rf "$out"; mkdir -p "$out"
cd "$src"
fail() { echo "FAIL: $*"; exit 1; }
"$exe" prm/cup-drawing.prm --set "Output/Output directory=$out/cup-drawing" \
  --set "Output/Report=false" > "$out/first.log" 2>&1 || { cat "$out/first.log"; fail "the default case"; }
before=$(cd "$out/cup-drawing" && find . -type f | sort | xargs md5sum | md5sum)
"$exe" prm/cup-redraw.prm --set "Geometry/Start from=$out/cup-drawing" \
  --set "Output/Output directory=$out/cup-redraw" --set "Output/Report=false" \
  > "$out/redraw.log" 2>&1 || { cat "$out/redraw.log"; fail "the redraw"; }
grep -q "Tools/Punch: moved .* mm down .* to 0.05 mm from the part" "$out/redraw.log" ||
  fail "the punch was not placed against the cup"
grep -q "^done: .*drawn through" "$out/redraw.log" || fail "the redraw did not draw the cup through"
[ "$(cd "$out/cup-drawing" && find . -type f | sort | xargs md5sum | md5sum)" = "$before" ] ||
  fail "the redraw changed the first draw's folder"
"$py" - "$out" <<'PY' || exit 1
import csv, sys
first = list(csv.DictReader(open(sys.argv[1] + "/cup-drawing/history.csv")))[-1]
second = list(csv.DictReader(open(sys.argv[1] + "/cup-redraw/history.csv")))
last = second[-1]
rim, eps1, eps2 = float(last["rim_radius"]), float(first["max_equivalent_strain"]), \
    float(last["max_equivalent_strain"])
print(f"rim radius {float(first['rim_radius']):.3f} -> {rim:.3f} mm, largest strain {eps1:.3f} -> {eps2:.3f}, "
      f"cup height {float(first['cup_height']):.2f} -> {float(last['cup_height']):.2f} mm")
# The rim inside the die opening (17.25 mm) and outside the punch (16 mm).
if not 16 < rim < 17.25:
    sys.exit(f"FAIL: the redrawn rim lies at {rim} mm, not between punch and die opening")
# The first step starts from the first draw's strain: it cannot fall.
if float(second[0]["max_equivalent_strain"]) < eps1 - 1e-9:
    sys.exit("FAIL: the redraw starts with less strain than the first draw left")
if eps2 <= eps1:
    sys.exit("FAIL: the redraw added no strain")
PY
echo "ok: the default cup redrawn"

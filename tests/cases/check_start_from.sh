#!/usr/bin/env bash
# A next operation (Geometry/Start from): the default cup's coarse section
# drawn 2.5 mm, then from its end 2.5 mm more with the tools where the first
# run left them, against the same cup drawn 5 mm in one run
# (check_start_from.py: the second run's steps are the one run's last ones).
# Also: the earlier folder is left exactly as it was; a sprung start begins
# from the sprung shape; every bad Start from gets one message naming the
# entry, before any work.
# Usage: check_start_from.sh FORMSOLVE CASES OUTDIR RANKS PYTHON
set -uo pipefail
exe=$1 cases=$2 out=$3 ranks=$4 py=$5
rm -rf "$out"; mkdir -p "$out"
cd "$cases"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
prm=cup-axisymmetric.prm
run() { # run LOG [ARGS...]
  local log=$1; shift
  if [ "$ranks" -gt 1 ]; then
    timeout 600 mpirun -np "$ranks" "$exe" "$prm" "$@" > "$log" 2>&1
  else
    timeout 600 "$exe" "$prm" "$@" > "$log" 2>&1
  fi
}
fail() { echo "FAIL: $*"; exit 1; }
quiet=(--set "Output/Report=false" --set "Output/Output interval=0")
snapshot() { (cd "$1" && find . -type f | sort | xargs md5sum) | md5sum; }

run "$out/one.log" --set "Output/Output directory=$out/one" "${quiet[@]}" ||
  { cat "$out/one.log"; fail "the one run"; }
run "$out/first.log" --set "Output/Output directory=$out/first" "${quiet[@]}" \
  --set "Tools/Punch/Stroke=2.5" || { cat "$out/first.log"; fail "the first run"; }
before=$(snapshot "$out/first")
holder=$(tail -1 "$out/first/history.csv" | "$py" -c "
import csv, sys
rows = list(csv.DictReader(open('$out/first/history.csv')))
print(rows[-1]['holder_displacement'])")
# The tools where the first run left them: the punch 2.5 mm down, the holder
# lifted by the flange's thickening.
# (The elastic constants may differ: the forming does not use them.)
next=(--set "Geometry/Start from=$out/first" --set "Tools/Punch/Stroke=2.5"
      --set "Tools/Punch/Gap=-2.5" --set "Tools/Blank holder/Gap=$holder"
      --set "Material/Young's modulus=70000")
run "$out/second.log" --set "Output/Output directory=$out/second" "${quiet[@]}" "${next[@]}" ||
  { cat "$out/second.log"; fail "the second run"; }
grep -q "next operation: the part of $out/first (as formed, after 10 steps to punch travel 2.5 mm" \
  "$out/second.log" || { head -20 "$out/second.log"; fail "the second run did not say what it starts from"; }
[ "$(snapshot "$out/first")" = "$before" ] || fail "the second run changed $out/first"
"$py" "$cases/check_start_from.py" "$out/one" "$out/second" 2.5 || exit 1
if [ "$ranks" -gt 1 ]; then # the same second operation on one rank
  timeout 600 "$exe" "$prm" --set "Output/Output directory=$out/second-1rank" "${quiet[@]}" \
    "${next[@]}" > "$out/second-1rank.log" 2>&1 || { cat "$out/second-1rank.log"; fail "the second run on 1 rank"; }
  numdiff -q -s ', \t\n' -r 1e-8 -a 1e-10 "$out/second/history.csv" "$out/second-1rank/history.csv" ||
    fail "the second operation's history.csv differs between $ranks ranks and 1"
  echo "ok: the second operation's history.csv is the same on $ranks ranks and 1"
fi

# Tools placed against the part (Gap measured from = part): on the flat
# blank the same run as by the blank's planes; in the second operation the
# punch and holder land where the first run left them, within the allowed
# penetration (1e-3 mm) by which they pressed into it.
part=(--set "Tools/Punch/Gap measured from=part" --set "Tools/Die/Gap measured from=part"
      --set "Tools/Blank holder/Gap measured from=part")
run "$out/one-placed.log" --set "Output/Output directory=$out/one-placed" "${quiet[@]}" "${part[@]}" ||
  { cat "$out/one-placed.log"; fail "the one run with tools placed against the blank"; }
numdiff -q -s ', \t\n' -r 1e-8 -a 1e-10 "$out/one/history.csv" "$out/one-placed/history.csv" ||
  fail "tools placed against a flat blank changed the run"
run "$out/second-placed.log" --set "Output/Output directory=$out/second-placed" "${quiet[@]}" \
  --set "Geometry/Start from=$out/first" --set "Tools/Punch/Stroke=2.5" --set "Tools/Punch/Gap=0" \
  --set "Tools/Blank holder/Gap=0" "${part[@]}" || { cat "$out/second-placed.log"; fail "the second run with placed tools"; }
"$py" - "$out/second-placed.log" "$holder" <<'PY' || exit 1
import re, sys
text = open(sys.argv[1]).read()
moved = {m[0]: (float(m[1]) if m[2] == "up" else -float(m[1])) for m in
         re.findall(r"Tools/(\w[\w ]*): moved ([-0-9.e]+) mm (down|up)", text)}
# Where the first run left each tool, and its side: a tool above lands up to
# the penetration higher, one below up to it lower.
want = {"Punch": (-2.5, 1), "Die": (0.0, -1), "Blank holder": (float(sys.argv[2]), 1)}
for tool, (z, side) in want.items():
    if tool not in moved or not (-1e-6 <= side * (moved[tool] - z) <= 1.001e-3):
        sys.exit(f"FAIL: {tool} placed at {moved.get(tool)} mm along z, not within the "
                 f"allowed penetration above {z} mm")
    print(f"ok: {tool} placed {moved[tool]:+.6f} mm along z (first run left it at {z:+.6f})")
PY
# A sprung start: the first run released, the second starts from the
# sprung shape (its first output's points are the sprung part's).
spring=(--set "Springback/Enabled=true" --set "Material/Young's modulus=200000")
run "$out/sprung-first.log" --set "Output/Output directory=$out/sprung-first" \
  --set "Output/Report=false" --set "Tools/Punch/Stroke=2.5" "${spring[@]}" ||
  { cat "$out/sprung-first.log"; fail "the first run with springback"; }
run "$out/sprung-second.log" --set "Output/Output directory=$out/sprung-second" \
  --set "Output/Report=false" "${spring[@]}" --set "Geometry/Start from=$out/sprung-first" \
  --set "Tools/Punch/Stroke=0.5" --set "Tools/Punch/Gap=-2.3" \
  --set "Tools/Die/Gap=0.6" --set "Tools/Blank holder/Gap=-0.3" ||
  { cat "$out/sprung-second.log"; fail "the second run from the sprung part"; }
grep -q "(sprung back, after" "$out/sprung-second.log" || fail "the sprung start was not said"
"$py" "$cases/check_start_from.py" --sprung "$out/sprung-first" "$out/sprung-second" || exit 1

# A part that split in its run: said at the start and in the summary's
# warnings (the split written into a copy's run-summary.txt).
cp -r "$out/first" "$out/split"
sed -i 's/^split = no/split = yes/; s/^split_travel = .*/split_travel = 2.25/;
        s/^split_location = .*/split_location = r 20.1 z -1.2/; s/^split_measure = .*/split_measure = neck/' \
  "$out/split/run-summary.txt"
run "$out/from-split.log" --set "Output/Output directory=$out/from-split" "${quiet[@]}" "${next[@]}" \
  --set "Geometry/Start from=$out/split" --set "Tools/Punch/Stroke=0.25" ||
  { cat "$out/from-split.log"; fail "the run from a split part"; }
grep -q "warning: that part split in its run (at punch travel 2.25 mm, at r 20.1 z -1.2 (neck))" "$out/from-split.log" ||
  fail "the split of the earlier part was not said"
grep -q "^warning_.* had split in that run" "$out/from-split/run-summary.txt" ||
  fail "the split of the earlier part is not in run-summary.txt"
echo "ok: a split part is said"

# Bad Start from: one message naming the entry, before any work, nothing
# written into the earlier folder.
bad() { # bad NAME PATTERN [ARGS...]
  local name=$1 pattern=$2; shift 2
  run "$out/bad-$name.log" --set "Output/Output directory=$out/bad-$name" "${quiet[@]}" "$@"
  local rc=$?
  local lines; lines=$(grep -c "^formsolve: error\|^\[.*\] formsolve: error\|formsolve: error" "$out/bad-$name.log")
  { [ $rc -ne 0 ] && [ $rc -ne 124 ] && grep -qF -- "$pattern" "$out/bad-$name.log" && [ "$lines" -eq 1 ]; } ||
    { cat "$out/bad-$name.log"; fail "bad Start from '$name': expected one message naming '$pattern' (exit $rc)"; }
  [ ! -e "$out/bad-$name/history.csv" ] || fail "bad Start from '$name' started to work"
  echo "ok   bad $name: $(grep -m1 "formsolve: error" "$out/bad-$name.log" | head -c 250)"
}
bad missing "Geometry/Start from: '$out/nowhere' is not a folder" --set "Geometry/Start from=$out/nowhere"
mkdir -p "$out/empty"
bad no_run "Geometry/Start from: '$out/empty' holds no finished formsolve run" --set "Geometry/Start from=$out/empty"
cp -r "$out/first" "$out/unfinished"
sed -i 's/^finished = 1/finished = 0/' "$out/unfinished/checkpoint/meta.txt"
bad unfinished "has not finished" --set "Geometry/Start from=$out/unfinished"
cp -r "$out/first" "$out/broken"
sed -i '/^punch_travel = /d' "$out/broken/checkpoint/meta.txt"
bad broken_meta "meta.txt is incomplete (no 'punch_travel')" --set "Geometry/Start from=$out/broken"
cp -r "$out/first" "$out/older"
sed -i '/^finished = /d' "$out/older/checkpoint/meta.txt"
bad older "was made by a formsolve without next operations" --set "Geometry/Start from=$out/older"
bad material "Material/Strength coefficient = '829' in the earlier run, '800' now" \
  --set "Geometry/Start from=$out/first" --set "Material/Strength coefficient=800"
bad frame "Material/Rolling direction = " \
  --set "Geometry/Start from=$out/first" --set "Material/Rolling direction=30"
bad mesh "Mesh/Layers through thickness = '4' in the earlier run, '2' now" \
  --set "Geometry/Start from=$out/first" --set "Mesh/Layers through thickness=2"
bad same_folder "Output/Output directory: '$out/first' is the folder Geometry/Start from reads" \
  --set "Geometry/Start from=$out/first" --set "Output/Output directory=$out/first"
bad inside_folder "Output/Output directory: '$out/first/next' lies in the folder Geometry/Start from reads" \
  --set "Geometry/Start from=$out/first" --set "Output/Output directory=$out/first/next"
[ "$(snapshot "$out/first")" = "$before" ] || fail "a bad Start from changed $out/first"
echo "ok: next operation on $ranks rank(s)"

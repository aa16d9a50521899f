#!/usr/bin/env bash
# A next operation on a trimmed part (Geometry/Start from after Trimming):
# the part is meshed anew without its cut-away cells (trimming/part_mesh.cc)
# and the earlier run's shape and history carried onto it.
# - A cut that removes nothing takes the same path and must give the same
#   next operation as a start from the untrimmed run (history.csv within
#   1e-8): the new mesh, the nodes' shape and the history come over exactly.
# - A real cut: the part's volume and its integral of the equivalent plastic
#   strain at the start match the earlier run's trimmed part
#   (trimming_volume, trimming_strain_integral), the run goes to its stroke,
#   the earlier folder is left as it was, and RANKS > 1 gives the same
#   history as 1 rank.
# - Axisymmetric (default): also from the trimmed and sprung part, and from
#   a run whose trim failed (a warning, the untrimmed part). With "3d":
#   the quarter cup cut by a circle (Trimming/Curve file).
# Usage: check_start_trimmed.sh FORMSOLVE CASES OUTDIR RANKS PYTHON [3d]
set -uo pipefail
exe=$1 cases=$2 out=$3 ranks=$4 py=$5 mode=${6:-axisymmetric}
rm -rf "$out"; mkdir -p "$out"
cd "$cases"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
fail() { echo "FAIL: $*"; exit 1; }
quiet=(--set "Output/Report=false" --set "Output/Output interval=0")
snapshot() { (cd "$1" && find . -type f | sort | xargs md5sum) | md5sum; }
run() { # run NP NAME [ARGS...]
  local np=$1 name=$2; shift 2
  local cmd=("$exe" "$prm" --set "Output/Output directory=$out/$name" "${quiet[@]}" "${first[@]}" "$@")
  [ "$np" -gt 1 ] && cmd=(mpirun -np "$np" "${cmd[@]}")
  timeout 900 "${cmd[@]}" > "$out/$name.log" 2>&1 || { tail -20 "$out/$name.log"; fail "run $name"; }
}
holder() { "$py" -c "
import csv
print(list(csv.DictReader(open('$out/$1/history.csv')))[-1]['holder_displacement'])"; }

if [ "$mode" = 3d ]; then
  prm=cup-adaptive-short.prm # the shipped 3-D cup, refined at the radii
  first=(--set "Tools/Punch/Stroke=2")
  "$py" -c "
import math
with open('$out/circle.csv', 'w') as f:
    for i in range(145):
        a = 2 * math.pi * i / 144
        f.write(f'{34 * math.cos(a):.9f}, {34 * math.sin(a):.9f}\n')"
  cut=(--set "Trimming/Curve file=$out/circle.csv")
  nothing=(--set "Trimming/Planes=z > -100")
  next=(--set "Tools/Punch/Stroke=0.5" --set "Tools/Punch/Gap=-2")
  volume_limit=3e-3 strain_limit=1e-3
else
  prm=cup-axisymmetric.prm
  first=()
  cut=(--set "Trimming/Planes=r < 34")
  nothing=(--set "Trimming/Planes=r < 1000")
  next=(--set "Tools/Punch/Stroke=2.5" --set "Tools/Punch/Gap=-5")
  volume_limit=1e-5 strain_limit=5e-3
fi

run "$ranks" plain
run "$ranks" nothing "${nothing[@]}"
run "$ranks" cut "${cut[@]}"
before=$(snapshot "$out/cut")
grep -q "trimming = done" "$out/cut/run-summary.txt" || fail "the first run did not trim"
for name in plain nothing cut; do
  first=()
  run "$ranks" "next-$name" --set "Geometry/Start from=$out/$name" "${next[@]}" \
    --set "Tools/Blank holder/Gap=$(holder "$name")"
done
[ "$(snapshot "$out/cut")" = "$before" ] || fail "the next operation changed $out/cut"
numdiff -q -s ', \t\n' -r 1e-8 -a 1e-10 "$out/next-plain/history.csv" "$out/next-nothing/history.csv" ||
  fail "a trim that removes nothing changed the next operation"
echo "ok: a trim that removes nothing leaves the next operation as it was"
grep -q "^trimmed part: on a mesh of its own" "$out/next-cut.log" ||
  fail "the next operation did not say it meshed the trimmed part"

check_start() { # check_start RUN LIMIT_VOLUME LIMIT_STRAIN
  "$py" - "$out/$1/run-summary.txt" "$2" "$3" <<'PY' || exit 1
import sys
s = dict(l.rstrip("\n").split(" = ", 1) for l in open(sys.argv[1]) if " = " in l)
if s.get("end_reason") != "the punch stroke was reached":
    sys.exit(f"FAIL: the next operation ended with '{s.get('end_reason')}'")
if s.get("start_from_trimmed") != "yes":
    sys.exit("FAIL: start_from_trimmed is not yes")
for what, limit in (("volume", float(sys.argv[2])), ("strain_integral", float(sys.argv[3]))):
    now, was = float(s[f"start_from_{what}"]), float(s[f"start_from_earlier_{what}"])
    if abs(now / was - 1) > limit:
        sys.exit(f"FAIL: the part's {what} at the start is {now}, the trimmed part's {was} "
                 f"(limit {limit:g} relative)")
    print(f"ok: {what} at the start {now} against {was} ({now / was - 1:+.2e})")
PY
}
check_start next-cut "$volume_limit" "$strain_limit"

if [ "$ranks" -gt 1 ]; then
  run 1 next-cut-1rank --set "Geometry/Start from=$out/cut" "${next[@]}" \
    --set "Tools/Blank holder/Gap=$(holder cut)"
  numdiff -q -s ', \t\n' -r 1e-8 -a 1e-10 "$out/next-cut/history.csv" "$out/next-cut-1rank/history.csv" ||
    fail "the next operation on the trimmed part differs between $ranks ranks and 1"
  echo "ok: the next operation on the trimmed part is the same on $ranks ranks and 1"
fi

if [ "$mode" != 3d ]; then # a trim that failed: the untrimmed part, with a warning
  first=()
  run "$ranks" failed --set "Trimming/Planes=r < 0.01"
  grep -q "^trimming = failed" "$out/failed/run-summary.txt" || fail "the trim keeping nothing did not fail"
  run "$ranks" next-failed --set "Geometry/Start from=$out/failed" "${next[@]}" \
    --set "Tools/Blank holder/Gap=$(holder failed)"
  grep -q "^warning: the trimming of that part failed" "$out/next-failed.log" ||
    fail "no warning that the earlier trim failed"
  grep -q "start_from_trimmed = no" "$out/next-failed/run-summary.txt" ||
    fail "a failed trim was taken as trimmed"
  echo "ok: a failed trim is said and the untrimmed part formed"
fi

if [ "$mode" != 3d ]; then # the trimmed and sprung part, tools placed against it
  first=()
  run "$ranks" sprung "${cut[@]}" --set "Springback/Enabled=true" --set "Material/Young's modulus=200000"
  run "$ranks" next-sprung --set "Geometry/Start from=$out/sprung" --set "Tools/Punch/Stroke=2.5" \
    --set "Tools/Punch/Gap=0" --set "Tools/Blank holder/Gap=0" \
    --set "Tools/Punch/Gap measured from=part" --set "Tools/Die/Gap measured from=part" \
    --set "Tools/Blank holder/Gap measured from=part"
  grep -q "start_from_shape = sprung" "$out/next-sprung/run-summary.txt" ||
    fail "the next operation did not start from the sprung shape"
  # The released part changes its volume by the elastic dilatation (1e-3).
  check_start next-sprung 1e-3 "$strain_limit"
fi
echo "ok: next operations on the trimmed part"

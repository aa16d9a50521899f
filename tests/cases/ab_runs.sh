# Sourced by the case checks that compare runs of one .prm under different
# settings: `. ab_runs.sh FORMSOLVE PRM OUTDIR [--set "..."]...` empties
# OUTDIR, enters the .prm's directory and defines
#   run NAME [--set "..."]...
# which writes OUTDIR/NAME/ and OUTDIR/NAME.log (the common sets, then its
# own, later ones winning), prints the summary line and exits on failure.
exe=$1 prm=$2 out=$3
shift 3
common=("$@")
rm -rf "$out"; mkdir -p "$out"
cd "$(dirname "$prm")" || exit 1
run() { # name sets...
  local name=$1; shift
  "$exe" "$prm" --set "Output/Output directory=$out/$name" --set "Output/Report=false" \
    "${common[@]}" "$@" > "$out/$name.log" 2>&1 ||
    { echo "FAIL: run $name failed"; tail -5 "$out/$name.log"; exit 1; }
  grep '^done' "$out/$name.log"
}

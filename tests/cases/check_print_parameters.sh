#!/usr/bin/env bash
# --print-parameters writes a complete parameter file that formsolve reads
# back (--validate), with what each entry accepts above its 'set' line.
set -uo pipefail
exe=$1 work=$2
rm -rf "$work"; mkdir -p "$work"
"$exe" --print-parameters > "$work/all.prm" || { echo "FAIL: --print-parameters exited non-zero"; exit 1; }
sets=$(grep -c '^ *set ' "$work/all.prm")
accepts=$(grep -c '^ *# Accepts: ' "$work/all.prm")
echo "entries: $sets, with 'Accepts': $accepts"
[ "$sets" -gt 100 ] && [ "$sets" -eq "$accepts" ] || { echo "FAIL: every entry needs its Accepts line"; exit 1; }
grep -q '# Accepts: a number from 0 to 1, dimensionless' "$work/all.prm" || { echo "FAIL: no range in words"; exit 1; }
# What an entry accepts is said in words, never as deal.II's pattern text.
! grep -n 'MAX_DOUBLE\|MAX_INT\|\[Double\|\[Integer\|List of\|Selection ' "$work/all.prm" || { echo "FAIL: a pattern description, not words"; exit 1; }
(cd "$work" && "$exe" --validate all.prm) || { echo "FAIL: the printed file does not read back"; exit 1; }
echo "ok"

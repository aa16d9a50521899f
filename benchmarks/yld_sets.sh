#!/usr/bin/env bash
# The earing cup's Yld2004-18p sets side by side (doc/forming-results.md,
# "Yld2004-18p fitted by formsolve"): RMS errors against the sheet's data
# and the pure-shear flow stress k(theta)/sigma_0 of each, for the two
# published sets and the sets formsolve fitted in the runs of
# benchmarks/earing.sh (read from results/earing/*/run-summary.txt).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$root/build}
[ -f "$build/Makefile" ] || bash "$root/scripts/build.sh"
make -C "$build" yld_sets > /dev/null
{
  echo "team 1;1.1998,1.2289,0.1315,0.8081,1.1386,0.2870,1.3739;1.1510,-0.2576,0.4873,0.9934,0.9110,0.7965,0.2679"
  echo "team 2;1.0,1.0,-0.0870,0.4496,1.0192,1.1724,0.0;1.3329,1.2510,1.0948,1.0855,-0.0065,0.4812,1.5461"
  for run in yld2004-18p-fitted-by-formsolve yld2004-18p-fitted-by-formsolve-1-start; do
    s=$root/results/earing/$run/run-summary.txt
    [ -f "$s" ] || continue
    c1=$(sed -n 's/^yld_fit_c1 = //p' "$s" | tr -d ' ')
    c2=$(sed -n 's/^yld_fit_c2 = //p' "$s" | tr -d ' ')
    echo "$run;$c1;$c2"
  done
} | "$build/yld_sets"

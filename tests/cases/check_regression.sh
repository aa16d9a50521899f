#!/usr/bin/env bash
# history.csv against the stored reference, with numdiff tolerances.
set -euo pipefail
out=$1 reference=$2
numdiff -q -s ', \t\n' -r 1e-5 -a 1e-7 "$reference" "$out/history.csv" && echo "history.csv matches $reference" && exit 0
numdiff -s ', \t\n' -r 1e-5 -a 1e-7 "$reference" "$out/history.csv" | head -40
exit 1

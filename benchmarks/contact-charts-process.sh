#!/usr/bin/env bash
# The contact charts on the default process (doc/contact.md, issue 10):
# speed vs accuracy over the full draw (axisymmetric and quarter 3-D panels)
# and the stability map of the axisymmetric full draw (r_p = 8 and 2 mm).
# Runs are kept in results/contact-charts/process*/ and reused; --force
# redoes them. About 40 min on 2 cores (--jobs 2).
# Usage: bash benchmarks/contact-charts-process.sh [--jobs N] [--force] [--groups ...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# The BLAS kernels formsolve-run would choose (unless OPENBLAS_CORETYPE is set).
eval "$(bash "$root/scripts/formsolve-run" --env)"
[ -x "$root/build/formsolve" ] || bash "$root/scripts/build.sh"
cd "$root/benchmarks"
exec /usr/bin/python3 contact_charts_process.py "$@"

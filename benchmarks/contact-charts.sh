#!/usr/bin/env bash
# Regenerates every contact chart of doc/contact.md (PNG + CSV in doc/):
# speed vs accuracy on the default cup, stability maps, condition estimates
# and AMG counts, penetration map. Runs are kept in results/contact-charts/
# and reused; pass --force to redo them. About 50 min on 2 cores (--jobs 2).
# Usage: bash benchmarks/contact-charts.sh [--jobs N] [--force] [--groups ...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# The BLAS kernels formsolve-run would choose (unless OPENBLAS_CORETYPE is set).
eval "$(bash "$root/scripts/formsolve-run" --env)"
[ -x "$root/build/formsolve" ] || bash "$root/scripts/build.sh"
exec /usr/bin/python3 "$root/benchmarks/contact_charts.py" "$@"

#!/usr/bin/env bash
# adaptive-strict checks its bound within the solve (Contact/Strict check
# residual) instead of only after convergence. Both ways must keep every
# step within delta (unless all Max strict passes were used) and give the
# same forces and volume (relative 1e-3 and 1e-6: the two paths differ by
# penetrations below delta); the in-solve check must actually correct.
# Usage: check_strict_in_solve.sh FORMSOLVE PRM OUTDIR [--set "..."]...
set -uo pipefail
. "$(dirname "$0")/ab_runs.sh" "$@"
common+=(--set "Contact/Penalty strategy=adaptive-strict" --set "Nonlinear solver/Log iterations=true")
run after --set "Contact/Strict check residual=0"
run within --set "Contact/Strict check residual=0.1"
corrected=$(grep -c "strict check: factors corrected" "$out/within.log")
[ "$(grep -c "strict check: factors corrected" "$out/after.log")" = 0 ] ||
  { echo "FAIL: Strict check residual = 0 corrected within a solve"; exit 1; }
CASES_DIR="$(cd "$(dirname "$0")" && pwd)" /usr/bin/python3 - "$out" "$corrected" <<'PY'
import csv, sys
import os
sys.path.insert(0, os.environ["CASES_DIR"])
import results
out, corrected = sys.argv[1], int(sys.argv[2])
delta, max_passes = 1e-3, 5
runs = {n: results.read(f"{out}/{n}") for n in ("after", "within")}
fail = []
if corrected == 0:
    fail.append("no correction within a solve: the case tests nothing")
for name, rows in runs.items():
    for r in rows:
        if float(r["max_penetration"]) > delta * (1 + 1e-9) and int(r["strict_passes"]) < max_passes:
            fail.append(f"{name}, step {r['step']}: penetration {r['max_penetration']} > delta")
a, b = runs["after"], runs["within"]
if len(a) != len(b):
    fail.append(f"{len(b)} steps against {len(a)}")
for x, y in zip(a, b):
    for key, tol in (("punch_force", 1e-3), ("force_die", 1e-3), ("volume", 1e-6)):
        u, v = float(x[key]), float(y[key])
        if abs(u - v) > tol * max(abs(u), 1e-9):
            fail.append(f"step {x['step']}, {key}: {v} within, {u} after")
for f in fail[:20]:
    print("FAIL", f)
its = {n: sum(int(r["newton_iterations"]) for r in rows) for n, rows in runs.items()}
print(f"{corrected} corrections within solves; Newton iterations {its['within']} "
      f"(checked within) and {its['after']} (after convergence)")
sys.exit(1 if fail else 0)
PY

#!/usr/bin/env bash
# Nonlinear solver/First step start = coarser mesh: the first step solved on
# the mesh one level coarser starts the run's first step. It must come back
# to the run's mesh exactly, converge to the same steps as the start from
# rest (forces 1e-3, volume 1e-6, penetrations 5e-5 mm: the two paths differ
# within Newton's tolerance and the adaptive factors), do the same on 1 and
# 2 ranks, and be skipped, with its message, where the coarser cells would
# exceed Coarse cell size limit.
# Usage: check_coarse_start.sh FORMSOLVE PRM OUTDIR [--set "..."]...
set -uo pipefail
. "$(dirname "$0")/ab_runs.sh" "$@"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
run rest --set "Nonlinear solver/First step start=rest"
run coarse --set "Nonlinear solver/First step start=coarser mesh"
mpirun -np 2 "$exe" "$prm" --set "Output/Output directory=$out/coarse2" \
  --set "Output/Report=false" "${common[@]}" \
  --set "Nonlinear solver/First step start=coarser mesh" > "$out/coarse2.log" 2>&1 ||
  { echo "FAIL: run coarse2 failed"; tail -5 "$out/coarse2.log"; exit 1; }
run skipped --set "Nonlinear solver/First step start=coarser mesh" \
  --set "Nonlinear solver/Coarse cell size limit=1"
CASES_DIR="$(cd "$(dirname "$0")" && pwd)" /usr/bin/python3 - "$out" <<'PY'
import csv, re, sys
out = sys.argv[1]
fail = []
def log(n): return open(f"{out}/{n}.log").read()
def summary(n):
    return dict(l.split(" = ", 1) for l in open(f"{out}/{n}/run-summary.txt").read().splitlines() if " = " in l)
import os
sys.path.insert(0, os.environ["CASES_DIR"])
import results
def history(n): return results.read(f"{out}/{n}")
pattern = r"first step on the coarser mesh \((\d+) DoFs\): (\d+) Newton iterations; its solution is the start"
starts = {}
for n in ("coarse", "coarse2"):
    m = re.search(pattern, log(n))
    run_dofs = int(re.search(r"cells, (\d+) DoFs", log(n)).group(1))
    if not m:
        fail.append(f"{n}: no converged coarse start in the log")
        continue
    dofs, its = int(m.group(1)), int(m.group(2))
    starts[n] = (dofs, its)
    if not 0 < dofs < run_dofs / 2:
        fail.append(f"{n}: coarse mesh of {dofs} DoFs for a run of {run_dofs}")
    if int(summary(n)["coarse_start_iterations"]) != its:
        fail.append(f"{n}: run-summary coarse_start_iterations differs from the log")
if len(starts) == 2 and starts["coarse"] != starts["coarse2"]:
    fail.append(f"coarse start on 1 rank {starts['coarse']}, on 2 ranks {starts['coarse2']}")
if "first step from rest: the coarser cells would be" not in log("skipped"):
    fail.append("skipped: no message that the coarser mesh was too coarse")
if summary("skipped")["coarse_start_iterations"] != "0" or summary("rest")["coarse_start_iterations"] != "0":
    fail.append("coarse iterations reported without a coarse start")
# The run's mesh came back: the same cells and DoFs as without the coarse start.
for key in ("cells", "dofs"):
    if summary("coarse")[key] != summary("rest")[key]:
        fail.append(f"{key}: {summary('coarse')[key]} after the coarse start, {summary('rest')[key]} from rest")
def compare(a, b, tols, what):
    ra, rb = history(a), history(b)
    if len(ra) != len(rb):
        fail.append(f"{what}: {len(rb)} steps against {len(ra)}")
    for x, y in zip(ra, rb):
        for key, tol in tols:
            u, v = float(x[key]), float(y[key])
            if abs(u - v) > tol * max(abs(u), 1e-9):
                fail.append(f"{what}, step {x['step']}, {key}: {v} against {u}")
        if abs(float(x["max_penetration"]) - float(y["max_penetration"])) > 5e-5:
            fail.append(f"{what}, step {x['step']}: penetration {y['max_penetration']} against {x['max_penetration']}")
compare("rest", "coarse", (("punch_force", 1e-3), ("force_die", 1e-3), ("volume", 1e-6)), "coarse start against rest")
compare("coarse", "coarse2", (("punch_force", 1e-6), ("force_die", 1e-6), ("volume", 1e-9)), "2 ranks against 1")
for f in fail[:20]:
    print("FAIL", f)
its = {n: [int(r["newton_iterations"]) for r in history(n)] for n in ("rest", "coarse")}
print(f"coarse start {starts.get('coarse')} (DoFs, iterations); Newton iterations per step "
      f"{its['coarse']} after it, {its['rest']} from rest")
sys.exit(1 if fail else 0)
PY

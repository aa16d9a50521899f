#!/usr/bin/env bash
# Where a step's Newton iterations go: the contact set's changes per
# iteration, from the iteration log (Nonlinear solver/Log iterations, which
# prints the pairs each tool closed (+) and opened (-) at every search).
# The default cup's full draw, axisymmetric and quarter (the models of
# benchmarks/convergence.sh, 1 rank), with fixed and adaptive-strict.
# Per run: the steps grouped by the last iteration that changed the contact
# set, with their mean iterations, and the pairs changed per tool in
# iteration 1 and in iterations 2 and later.
# QUARTER_LEVELS="4 5" adds the quarter at those planform levels (4 layers,
# adaptive-strict only) to the table.
# LOGS="label=path/run.log ..." adds runs made elsewhere with Log iterations
# (their history in path/run/history.csv; label model-strategy), e.g. the
# 262k full draw of benchmarks/full_draw_262k.sh forcing.
# Writes doc/contact-changes.csv and prints the tables of doc/convergence.md.
# Usage: [QUARTER_LEVELS="4 5"] [LOGS=...] bash benchmarks/contact_changes.sh [--force]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# The BLAS kernels formsolve-run would choose (unless OPENBLAS_CORETYPE is set).
eval "$(bash "$root/scripts/formsolve-run" --env)"
exe=${FORMSOLVE_EXE:-$root/build/formsolve}
[ -x "$exe" ] || bash "$root/scripts/build.sh"
. "$root/benchmarks/from_rest.sh" && from_rest "$exe" # as the figures in doc/
out=$root/results/contact-changes
mkdir -p "$out"
FORCE=${1:-}
export OMP_NUM_THREADS=1
levels=${QUARTER_LEVELS:-}
runs=(axisymmetric-fixed axisymmetric-adaptive-strict quarter-fixed quarter-adaptive-strict)
for level in $levels; do runs+=("quarter$level-adaptive-strict"); done
for name in "${runs[@]}"; do
    model=${name%%-*} strategy=${name#*-}
    [ "$FORCE" != --force ] && [ -f "$out/$name/run-summary.txt" ] && continue
    echo "== $name" >&2
    sets=()
    if [ "$model" != axisymmetric ]; then
      level=${model#quarter}
      sets=(--set "Geometry/Model=quarter" --set "Mesh refinement/Interval=0"
        --set "Mesh/Layers through thickness=4" --set "Mesh/Planform refinements=${level:-3}")
    fi
    (cd "$root/prm" && "$exe" cup-drawing.prm ${rest[@]+"${rest[@]}"} ${sets[@]+"${sets[@]}"} \
      --set "Contact/Penalty strategy=$strategy" \
      --set "Nonlinear solver/Log iterations=true" \
      --set "Output/Output interval=0" --set "Output/Revolved copy=false" \
      --set "Output/Output directory=$out/$name") > "$out/$name.log" 2>&1 ||
      { tail -3 "$out/$name.log"; exit 1; }
done
for spec in ${LOGS:-}; do runs+=("$spec"); done
PYTHONPATH="$root/benchmarks" /usr/bin/python3 - "$out" "$root/doc/contact-changes.csv" "${runs[@]}" <<'PY'
import collections, csv, os, re, sys
from run_tables import steps as read_steps
out, csv_path, runs = sys.argv[1], sys.argv[2], sys.argv[3:]
tools = ["punch", "die", "blank_holder"]
rows = []
for spec in runs:
        # A run of this script, or label=path/run.log from LOGS.
        run, _, log = spec.partition("=")
        log = log or f"{out}/{run}.log"
        history_path = os.path.join(os.path.dirname(log), "run", "history.csv") \
            if "=" in spec else f"{out}/{run}/history.csv"
        model, strategy = run.split("-", 1)
        steps, current = [], []  # per step: (iteration, {tool: changes})
        for line in open(log):
            if line.startswith("step "):
                steps.append(current)
                current = []
                continue
            m = re.match(r"\s+it\s+(\d+)", line)
            if not m:
                continue
            changes = {t: int(a) + int(b) for t, a, b in
                       re.findall(r"(\w+) \+(\d+)/-(\d+)", line.split("pairs:")[1])} \
                if "pairs:" in line and "contact set changed" in line else {}
            current.append((int(m.group(1)), changes))
        groups = collections.defaultdict(list)
        pairs = {(t, late): 0 for t in tools for late in (False, True)}
        for s in steps:
            # Every Newton iteration of the step, re-solve passes included
            # (each pass counts from 1 again).
            iterations = sum(i > 0 for i, _ in s)
            last = max([i for i, c in s if c and i > 0] + [0])
            groups[min(last, 4)].append(iterations)
            for i, c in s:
                for t, n in c.items():
                    if i > 0:
                        pairs[(t, i > 1)] += n
        dofs = re.search(r"(\d+) DoFs", open(log).readline())
        row = dict(model=model, strategy=strategy, dofs=int(dofs.group(1)),
                   steps=len(steps),
                   iterations=sum(sum(i > 0 for i, _ in s) for s in steps))
        history = read_steps(history_path)
        assert row["iterations"] == sum(int(h["newton_iterations"]) for h in history), run
        for g in range(5):
            its = groups.get(g, [])
            row[f"steps_last_change_{g}"] = len(its)
            row[f"mean_iterations_last_change_{g}"] = \
                round(sum(its) / len(its), 2) if its else ""
        for t in tools:
            row[f"{t}_changes_it1"] = pairs[(t, False)]
            row[f"{t}_changes_it2plus"] = pairs[(t, True)]
        rows.append(row)
with open(csv_path, "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=list(rows[0]))
    w.writeheader()
    w.writerows(rows)
print("| run | DoFs | iterations/step | steps by the last iteration that changed the set: none / 1 / 2 / 3 / ≥ 4 | their mean iterations | pairs changed in iteration 1: punch / die / holder | in iterations ≥ 2 |")
print("|---|---|---|---|---|---|---|")
for r in rows:
    counts = " / ".join(str(r[f"steps_last_change_{g}"]) for g in range(5))
    means = " / ".join(str(r[f"mean_iterations_last_change_{g}"] or "–") for g in range(5))
    it1 = " / ".join(str(r[f"{t}_changes_it1"]) for t in tools)
    late = " / ".join(str(r[f"{t}_changes_it2plus"]) for t in tools)
    print(f"| {r['model']}-{r['strategy']} | {r['dofs']} | {r['iterations'] / r['steps']:.2f} | {counts} | {means} | {it1} | {late} |")
PY

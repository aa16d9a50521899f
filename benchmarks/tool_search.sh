#!/usr/bin/env bash
# Contact search cost of meshed tools against their number of triangles:
# the quarter cup of tests/cases/cup-quarter.prm (768 cells, 5 mm, 2 ranks)
# with the analytic tools and with meshed copies (meshes/tools/make-tools.sh
# cup) at facets of 8 to 0.25 mm. Prints a markdown table: triangles of the
# three tools, time in the contact search per Newton iteration, its share of
# the time-stepping loop, and the punch force's largest deviation from the
# analytic tools' from 2 mm of travel on.
#   bash benchmarks/tool_search.sh [OUTDIR] [SIZES]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/results/tool-search}
sizes=${2:-8 4 2 1 0.5 0.25}
exe=$root/build/formsolve
export OPENBLAS_CORETYPE=${OPENBLAS_CORETYPE:-Haswell}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mkdir -p "$out"
run() { # name settings...
  local name=$1; shift
  (cd "$root/tests/cases" && mpirun -np 2 "$exe" cup-quarter.prm \
    --set "Output/Output directory=$out/$name" --set "Output/Report=false" "$@") \
    > "$out/$name.log" 2>&1
}
run analytic
for size in $sizes; do
  bash "$root/meshes/tools/make-tools.sh" cup "$size" "$out/tools-$size" stl > /dev/null
  args=()
  for tool in Punch:punch Die:die "Blank holder:holder"; do
    args+=(--set "Tools/${tool%%:*}/Shape=mesh"
           --set "Tools/${tool%%:*}/Mesh file=$out/tools-$size/${tool##*:}.stl")
  done
  run "meshed-$size" "${args[@]}"
done
ROOT=$root /usr/bin/python3 - "$out" $sizes <<'PY'
import os, re, sys
out, sizes = sys.argv[1], sys.argv[2:]
sys.path.insert(0, os.path.join(os.environ.get("ROOT", "."), "tests", "cases"))
import results

def timing(name):
    """Contact search time, Newton iterations, time in the timed step
    sections (the steps' work) and the rest of the run (set-up: reading the
    tools, building their trees, the mesh) in s."""
    log = open(os.path.join(out, name + ".log")).read()
    sections = {m.group(1).strip(): float(m.group(2)) for m in
                re.finditer(r"^\| ([a-z][^|]*?) +\| +\d+ \| +([0-9.e+-]+)s", log, re.M)}
    total = float(re.search(r"Total wallclock time elapsed since start +\| +([0-9.e+-]+)s", log).group(1))
    steps = sum(v for k, v in sections.items() if ":" not in k)
    iterations = int(re.search(r"done: \d+ steps, (\d+) Newton iterations", log).group(1))
    return sections["contact"], iterations, steps, total - steps

def triangles(size):
    n = 0
    for tool in ("punch", "die", "holder"):
        n += sum(1 for line in open(os.path.join(out, f"tools-{size}", tool + ".stl")) if line.lstrip().startswith("facet"))
    return n

analytic = results.read(os.path.join(out, "analytic"))
c, it, work, setup = timing("analytic")
print("| tools | triangles | contact search per Newton iteration (ms) | share of the steps' time | set-up (s) | punch force vs analytic |")
print("|---|---|---|---|---|---|")
print(f"| analytic | – | {1000 * c / it:.2f} | {100 * c / work:.1f} % | {setup:.1f} | – |")
for s in sizes:
    rows = results.read(os.path.join(out, f"meshed-{s}"))
    dev = max(abs(float(m["punch_force"]) / float(a["punch_force"]) - 1)
              for a, m in zip(analytic, rows) if float(a["punch_travel"]) >= 2)
    c, it, work, setup = timing(f"meshed-{s}")
    print(f"| {s} mm facets | {triangles(s)} | {1000 * c / it:.1f} | {100 * c / work:.0f} % | {setup:.1f} | {100 * dev:.3f} % |")
PY

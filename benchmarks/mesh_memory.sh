#!/usr/bin/env bash
# Memory per rank of the mesh set-up: `formsolve --validate` builds the mesh,
# the DoFs, the quadrature history and the contact nodes, then stops. Peak
# resident set of every rank (/usr/bin/time), quarter 3-D cup, 4 layers,
# planform refinement 5 to 7 (47k to 750k DoFs), on 1 and 2 ranks.
# With a second executable, the same for it: e.g. one built from commit
# 3cf79bd, whose p4est coarse mesh was the refined planform on every rank.
# Writes doc/mesh-memory.csv and prints its table.
# Usage: bash benchmarks/mesh_memory.sh [other executable [its label]]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# The BLAS kernels formsolve-run would choose (unless OPENBLAS_CORETYPE is set).
eval "$(bash "$root/scripts/formsolve-run" --env)"
exe=$root/build/formsolve
[ -x "$exe" ] || bash "$root/scripts/build.sh"
out=$root/results/mesh-memory
mkdir -p "$out"
export OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
exes=("distributed coarse mesh=$exe")
[ $# -ge 1 ] && exes+=("${2:-replicated coarse mesh}=$1")
rows=$out/rows.csv
echo "coarse_mesh,level,ranks,cells,dofs,max_rank_MB,sum_ranks_MB,kB_per_dof_per_rank" > "$rows"
for item in "${exes[@]}"; do
  label=${item%%=*} bin=${item#*=}
  for level in 5 6 7; do
    for ranks in 1 2; do
      log=$out/${label// /-}-l$level-$ranks.log
      rm -f "$log".rank*
      # Open MPI names the rank in the environment: one file per rank.
      (cd "$root/prm" && mpirun -np "$ranks" sh -c \
        '/usr/bin/time -f "rss_kb %M" -o "$0.rank$OMPI_COMM_WORLD_RANK" "$@"' "$log" "$bin" \
        cup-drawing.prm --validate --set "Geometry/Model=quarter" \
        --set "Mesh/Layers through thickness=4" --set "Mesh/Planform refinements=$level" \
        --set "Mesh refinement/Interval=0" --set "Output/Revolved copy=false") > "$log" 2>&1
      /usr/bin/python3 - "$log" "$label" "$level" "$ranks" >> "$rows" <<'PY'
import re, sys
log, label, level, ranks = sys.argv[1:]
import glob
text = open(log).read()
rss = [int(re.search(r"rss_kb (\d+)", open(f).read()).group(1)) for f in glob.glob(log + ".rank*")]
m = re.search(r"input valid: \w+ model, (\d+) cells, (\d+) DoFs", text)
cells, dofs = int(m.group(1)), int(m.group(2))
print(f"{label},{level},{ranks},{cells},{dofs},{max(rss) / 1024:.0f},{sum(rss) / 1024:.0f},"
      f"{max(rss) * 1.024 / dofs:.2f}")
PY
      tail -1 "$rows" >&2
    done
  done
done
cp "$rows" "$root/doc/mesh-memory.csv"
/usr/bin/python3 - "$rows" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
keys = list(rows[0])
print("| " + " | ".join(keys) + " |")
print("|" + "---|" * len(keys))
for r in rows:
    print("| " + " | ".join(r[k] for k in keys) + " |")
PY

#!/usr/bin/env bash
# The run report's wall time (issue 62, section 6: at most 2 s on the
# default cup): formsolve-report on a results folder N times, the report
# written to a scratch folder (--output) so that the results stay as they
# are. Prints the median wall time and where it goes: the median of each
# stage that the report and its VTK subprocess time themselves
# (FORMSOLVE_REPORT_TIMES, scripts/formsolve_report/timing.py; the two run
# at the same time, so their stages overlap), and the fixed costs measured
# alone: Python's start-up, importing matplotlib and the VTK classes,
# xvfb-run. Prints the load average before and after: run it on an idle
# machine or say the load.
# Usage: bash benchmarks/report_time.sh RESULTS [N]      (N = 7)
#   REPORT=path/formsolve-report bash benchmarks/... times another copy of the
#   report (an older one prints the wall times only).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
results=$(realpath "${1:?usage: report_time.sh RESULTS [N]}")
n=${2:-7}
report=${REPORT:-$root/scripts/formsolve-report}
python=/usr/bin/python3  # Debian's, with matplotlib and VTK
[ -f "$results/history.csv" ] || { echo "$results: no history.csv"; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "report: $report"
echo "results: $results; DISPLAY=${DISPLAY:-unset (xvfb-run)}; $(nproc) cores"
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
walls=()
for k in $(seq "$n"); do
  start=$EPOCHREALTIME
  FORMSOLVE_REPORT_TIMES=$tmp/times-$k.txt "$python" "$report" "$results" --output "$tmp/report" \
    > "$tmp/out.txt" 2>&1 || { cat "$tmp/out.txt"; exit 1; }
  walls+=("$(echo "$EPOCHREALTIME - $start" | bc)")
done
# The fixed costs alone, each as often.
fixed() { # label, command...
  local label=$1; shift
  for k in $(seq "$n"); do
    start=$EPOCHREALTIME
    "$@" > /dev/null 2>&1 || { echo "$label: failed"; return; }
    echo -e "alone\t$label\t$(echo "$EPOCHREALTIME - $start" | bc)" >> "$tmp/fixed.txt"
  done
}
fixed "python3 -c pass" "$python" -c pass
fixed "python3: import matplotlib.pyplot (Agg)" "$python" -c \
  "import matplotlib; matplotlib.use('Agg'); import matplotlib.pyplot"
# (no __pycache__ in the source tree, as the launcher keeps it)
fixed "python3: import the VTK classes the report uses" env PYTHONDONTWRITEBYTECODE=1 \
  PYTHONPATH="$root/scripts" "$python" -c "import formsolve_report.vtkclasses"
fixed "python3: import vtk (all of VTK)" "$python" -c "import vtk"
command -v xvfb-run > /dev/null && fixed "xvfb-run -a true" xvfb-run -a true
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
"$python" - "$tmp" "${walls[@]}" <<'PY'
import collections, glob, os, statistics, sys
tmp, walls = sys.argv[1], [float(w) for w in sys.argv[2:]]
print(f"wall time of the report, {len(walls)} runs: median {statistics.median(walls):.2f} s "
      f"(min {min(walls):.2f}, max {max(walls):.2f})")
stages = collections.OrderedDict()
for path in sorted(glob.glob(os.path.join(tmp, "times-*.txt"))) + [os.path.join(tmp, "fixed.txt")]:
    for line in open(path):
        process, stage, seconds = line.rstrip("\n").split("\t")
        stages.setdefault((process, stage), []).append(float(seconds))
if not any(p != "alone" for p, _ in stages):
    print("(this copy of the report times no stages)")
for (process, stage), values in stages.items():
    print(f"  {process:7s} {stage:50s} {statistics.median(values):6.3f} s")
PY

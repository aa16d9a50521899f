"""Merge the first-step runs of several builds (benchmarks/first_step.sh):
one CSV row per case with the iterations and cutbacks of each tag, and a
summary table (markdown) on stdout.
Usage: first_step_report.py RESULTS_DIR OUT_CSV TAG..."""
import csv
import statistics
import sys

results, out_csv, tags = sys.argv[1], sys.argv[2], sys.argv[3:]
key_fields = ["model", "planform", "layers", "strategy", "setting"]
runs = {}
for tag in tags:
    for row in csv.DictReader(open(f"{results}/{tag}.csv")):
        key = tuple(row[k] for k in key_fields)
        runs.setdefault(key, {})[tag] = (int(row["iterations"]), int(row["cutbacks"]))

with open(out_csv, "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(key_fields + [f"{c}_{t}" for t in tags for c in ("iterations", "cutbacks")])
    for key, by_tag in runs.items():
        w.writerow(list(key) + [v for t in tags for v in by_tag.get(t, ("", ""))])

print("| build | cases | median | max | cases > 10 | cases > 15 | cases cut back |")
print("|---|---|---|---|---|---|---|")
for t in tags:
    its = [by_tag[t][0] for by_tag in runs.values() if t in by_tag]
    cuts = [by_tag[t][1] for by_tag in runs.values() if t in by_tag]
    print(f"| {t} | {len(its)} | {statistics.median(its):g} | {max(its)} | "
          f"{sum(i > 10 for i in its)} | {sum(i > 15 for i in its)} | {sum(c > 0 for c in cuts)} |")
for group, match in (("axisymmetric, default settings", lambda k: k[0] == "axisymmetric" and k[4] == "default"),
                     ("quarter, default settings", lambda k: k[0] == "quarter"),
                     ("axisymmetric level 5, other settings", lambda k: k[4] != "default")):
    keys = [k for k in runs if match(k)]
    print(f"\n{group} ({len(keys)} cases): " + "; ".join(
        f"{t}: median {statistics.median(runs[k][t][0] for k in keys):g}, max "
        f"{max(runs[k][t][0] for k in keys)}, cut {sum(runs[k][t][1] > 0 for k in keys)}"
        for t in tags))

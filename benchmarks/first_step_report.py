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
        # coarse: iterations on the coarser mesh before step 1 (absent
        # before First step start existed).
        runs.setdefault(key, {})[tag] = (int(row["iterations"]), int(row["cutbacks"]),
                                         int(row.get("coarse") or 0))

with open(out_csv, "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(key_fields + [f"{c}_{t}" for t in tags for c in ("iterations", "cutbacks", "coarse")])
    for key, by_tag in runs.items():
        w.writerow(list(key) + [v for t in tags for v in by_tag.get(t, ("", "", ""))])

print("| build | cases | median | max | cases > 10 | cases > 15 | cases cut back | cases started on the coarser mesh | their coarse iterations (median, max) |")
print("|---|---|---|---|---|---|---|---|---|")
for t in tags:
    its = [by_tag[t][0] for by_tag in runs.values() if t in by_tag]
    cuts = [by_tag[t][1] for by_tag in runs.values() if t in by_tag]
    coarse = [by_tag[t][2] for by_tag in runs.values() if t in by_tag and by_tag[t][2] > 0]
    print(f"| {t} | {len(its)} | {statistics.median(its):g} | {max(its)} | "
          f"{sum(i > 10 for i in its)} | {sum(i > 15 for i in its)} | {sum(c > 0 for c in cuts)} | "
          f"{len(coarse)} | " + (f"{statistics.median(coarse):g}, {max(coarse)} |" if coarse else "– |"))
for group, match in (("axisymmetric, default settings", lambda k: k[0] == "axisymmetric" and k[4] == "default"),
                     ("quarter, default settings", lambda k: k[0] == "quarter"),
                     ("axisymmetric level 5, other settings", lambda k: k[4] != "default")):
    keys = [k for k in runs if match(k)]
    # Tags before the grid grew lack the newer cases: each over its own.
    print(f"\n{group} ({len(keys)} cases): " + "; ".join(
        f"{t} ({len(ks)}): median {statistics.median(runs[k][t][0] for k in ks):g}, max "
        f"{max(runs[k][t][0] for k in ks)}, cut {sum(runs[k][t][1] > 0 for k in ks)}"
        for t in tags for ks in [[k for k in keys if t in runs[k]]] if ks))

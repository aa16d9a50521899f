"""Tables and a histogram of Newton iterations per step from the runs of
benchmarks/convergence.sh: results/convergence/<tag>/<model>-<strategy>/.
Usage: convergence_report.py RESULTS_DIR DOC_DIR TAG_BEFORE TAG_AFTER"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

results, doc, before, after = sys.argv[1:5]
runs = [f"{m}-{s}" for m in ("axisymmetric", "quarter")
        for s in ("fixed", "adaptive", "adaptive-strict")]


def summary(path):
    out = {}
    with open(os.path.join(path, "run-summary.txt")) as f:
        for line in f:
            if " = " in line:
                k, v = line.rstrip("\n").split(" = ", 1)
                out[k] = v
    return out


def load(tag, run):
    path = os.path.join(results, tag, run)
    rows = list(csv.DictReader(open(os.path.join(path, "history.csv"))))
    its = [int(r["newton_iterations"]) for r in rows]
    s = summary(path)
    return {
        "its": its,
        "steps": len(its),
        "total": sum(its),
        "mean": sum(its) / len(its),
        "first": its[0],
        "max": max(its),
        "over15": sum(i > 15 for i in its),
        "passes": sum(int(r["strict_passes"]) for r in rows),
        "wall": float(s["wall_time"]),
        "assemblies": int(s.get("matrix_assemblies", "0")),
        "peak": max(float(r["punch_force"]) for r in rows) / 1e3,
        "pen": max(float(r["max_penetration"]) for r in rows),
        "travel": float(rows[-1]["punch_travel"]),
    }


data = {(t, r): load(t, r) for t in (before, after) for r in runs}
with open(os.path.join(doc, "convergence.csv"), "w") as f:
    w = csv.writer(f)
    w.writerow(["run", "tag", "steps", "newton_iterations", "mean_per_step",
                "first_step", "max_step", "steps_over_15", "strict_passes",
                "matrix_assemblies", "wall_time_s", "peak_force_kN",
                "max_penetration_mm", "final_travel_mm"])
    for r in runs:
        for t in (before, after):
            d = data[(t, r)]
            w.writerow([r, t, d["steps"], d["total"], f"{d['mean']:.2f}",
                        d["first"], d["max"], d["over15"], d["passes"],
                        d["assemblies"] or "", f"{d['wall']:.1f}",
                        f"{d['peak']:.3f}", f"{d['pen']:.3e}",
                        f"{d['travel']:.2f}"])

print("| run | iterations/step before → after | first step | largest step | steps > 15 | strict passes | matrix assemblies / iteration | wall time (s) | peak force (kN) | max penetration (mm) |")
print("|---|---|---|---|---|---|---|---|---|---|")
for r in runs:
    b, a = data[(before, r)], data[(after, r)]
    print(f"| {r} | {b['mean']:.2f} → **{a['mean']:.2f}** | {b['first']} → {a['first']} "
          f"| {b['max']} → {a['max']} | {b['over15']} → {a['over15']} "
          f"| {b['passes']} → {a['passes']} | {a['assemblies'] / a['total']:.2f} "
          f"| {b['wall']:.1f} → {a['wall']:.1f} | {b['peak']:.3f} → {a['peak']:.3f} "
          f"| {b['pen']:.2e} → {a['pen']:.2e} |")

fig, axes = plt.subplots(2, 3, figsize=(13, 6.5), sharex=True)
bins = range(0, 52)
for ax, r in zip(axes.flat, runs):
    for t, c in ((before, "tab:gray"), (after, "tab:blue")):
        d = data[(t, r)]
        ax.hist([min(i, 50) for i in d["its"]], bins=bins, color=c, alpha=0.6,
                label=f"{t}: {d['mean']:.1f}/step")
    ax.axvline(5, color="k", ls=":", lw=1)
    ax.set_title(r, fontsize=10)
    ax.legend(fontsize=8)
for ax in axes[1]:
    ax.set_xlabel("Newton iterations in the step (50 = 50 or more)")
for ax in axes[:, 0]:
    ax.set_ylabel("steps")
fig.suptitle("Default cup drawn through (force-controlled holder): Newton "
             "iterations per step, strict re-solves included")
fig.tight_layout()
fig.savefig(os.path.join(doc, "convergence-histogram.png"), dpi=110)

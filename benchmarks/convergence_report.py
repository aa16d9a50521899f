"""Tables and a histogram of Newton iterations per step from the runs of
benchmarks/convergence.sh: results/convergence/<tag>/<model>-<strategy>/.
Usage: convergence_report.py RESULTS_DIR DOC_DIR TAG [TAG ...]
(oldest first; the table shows each figure as old → ... → newest)"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from run_tables import steps  # noqa: E402

results, doc, tags = sys.argv[1], sys.argv[2], sys.argv[3:]
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
    rows = steps(path)
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


data = {(t, r): load(t, r) for t in tags for r in runs}
with open(os.path.join(doc, "convergence.csv"), "w") as f:
    w = csv.writer(f)
    w.writerow(["run", "tag", "steps", "newton_iterations", "mean_per_step",
                "first_step", "max_step", "steps_over_15", "strict_passes",
                "matrix_assemblies", "wall_time_s", "peak_force_kN",
                "max_penetration_mm", "final_travel_mm"])
    for r in runs:
        for t in tags:
            d = data[(t, r)]
            w.writerow([r, t, d["steps"], d["total"], f"{d['mean']:.2f}",
                        d["first"], d["max"], d["over15"], d["passes"],
                        d["assemblies"] or "", f"{d['wall']:.1f}",
                        f"{d['peak']:.3f}", f"{d['pen']:.3e}",
                        f"{d['travel']:.2f}"])

def chain(r, key, fmt="{}"):
    return " → ".join(fmt.format(data[(t, r)][key]) for t in tags)


print(f"| run ({' → '.join(tags)}) | iterations/step | first step | largest step | steps > 15 | strict passes | matrix assemblies / iteration | wall time (s) | peak force (kN) | max penetration (mm) |")
print("|---|---|---|---|---|---|---|---|---|---|")
for r in runs:
    a = data[(tags[-1], r)]
    assemblies = " → ".join(f"{data[(t, r)]['assemblies'] / data[(t, r)]['total']:.2f}"
                            if data[(t, r)]["assemblies"] else "–" for t in tags)
    print(f"| {r} | {chain(r, 'mean', '{:.2f}')} | {chain(r, 'first')} "
          f"| {chain(r, 'max')} | {chain(r, 'over15')} "
          f"| {chain(r, 'passes')} | {assemblies} "
          f"| {chain(r, 'wall', '{:.1f}')} | {chain(r, 'peak', '{:.3f}')} "
          f"| {chain(r, 'pen', '{:.2e}')} |")

fig, axes = plt.subplots(2, 3, figsize=(13, 6.5), sharex=True)
bins = range(0, 52)
for ax, r in zip(axes.flat, runs):
    colours = ("tab:gray", "tab:orange", "tab:blue", "tab:green")
    for t, c in zip(tags, colours[len(colours) - len(tags):] if len(tags) < 4 else colours):
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

"""Runs the contact benchmarks of doc/contact.md and draws their charts.

  speed      default cup: wall time vs max penetration and peak punch force
             error, fixed eps over 9 decades, adaptive / adaptive-strict with
             delta in {1e-2, 1e-3, 1e-4} mm, augmented Lagrangian
  stability  short cup (3 mm stroke): fixed eps x time step and x mesh, and the
             same axes for adaptive / adaptive-strict with delta
  condition  short frictionless cup: Lanczos condition estimate against eps
             and delta
  map        penetration map of the adaptive-strict delta = 1e-3 run at its
             worst step

Each run goes to results/contact-charts/<group>/<name>/ and is skipped when its
status file exists (--force reruns). CSV and PNG files are written to doc/.
Usage: bash benchmarks/contact-charts.sh (or /usr/bin/python3 benchmarks/contact_charts.py) [--jobs N] [--force]
       [--groups speed,stability,condition,map]
"""
import argparse
import csv
import math
import os
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from run_tables import steps  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# FORMSOLVE_EXE: another binary (e.g. a copy, so that a long map keeps one
# build while build/ is rebuilt).
EXE = os.environ.get("FORMSOLVE_EXE", os.path.join(ROOT, "build", "formsolve"))
PRM = os.path.join(ROOT, "prm", "cup-drawing-3d.prm")
# The scene doc/contact.md measured (before the process model of issue 8):
# quarter model, uniform level 4 x 4 layers, blank holder at a fixed 0.05 mm
# gap, fixed penalty unless a run says otherwise, 15 mm, and a failed step
# ends the run (no time-step cuts).
LEGACY = [("Mesh refinement/Interval", "0"), ("Mesh/Layers through thickness", "4"),
          ("Mesh/Planform refinements", "4"), ("Tools/Blank holder/Control", "gap"),
          ("Tools/Blank holder/Gap", "0.05"), ("Contact/Penalty strategy", "fixed"),
          ("Tools/Punch/Stroke", "15"), ("Time stepping/End of run", "stroke"),
          ("Time stepping/Max cutbacks", "0")]
OUT = os.path.join(ROOT, "results", "contact-charts")
DOC = os.path.join(ROOT, "doc")
DELTAS = [1e-2, 1e-3, 1e-4]
DELTA_FIXED = 1e-3  # the allowed penetration fixed-eps runs are judged by


def fixed(eps):
    return [("Contact/Penalty strategy", "fixed"), ("Contact/Penalty factor", "%g" % eps)]


def adaptive(strategy, delta):
    return [("Contact/Penalty strategy", strategy), ("Contact/Allowed penetration", "%g" % delta)]


SHORT = [("Tools/Punch/Stroke", "3"), ("Mesh/Planform refinements", "3")]
FRICTIONLESS = [("Tools/%s/Friction coefficient" % t, "0") for t in ("Punch", "Die", "Blank holder")]
SMALL = [("Tools/Punch/Stroke", "1"), ("Mesh/Planform refinements", "2")] + FRICTIONLESS


def runs_speed():
    runs = []
    for e in range(1, 10):
        runs.append(dict(group="speed", name="fixed-1e%d" % e, kind="fixed", eps=10.0**e,
                         delta=DELTA_FIXED, sets=fixed(10.0**e)))
    for s in ("adaptive", "adaptive-strict"):
        for d in DELTAS:
            runs.append(dict(group="speed", name="%s-%g" % (s, d), kind=s, delta=d, sets=adaptive(s, d)))
    for inner in ("fixed", "adaptive"):
        runs.append(dict(group="speed", name="al-%s-0.001" % inner, kind="augmented-lagrangian (%s)" % inner,
                         delta=1e-3, sets=adaptive("augmented-lagrangian", 1e-3)
                         + [("Contact/Augmented Lagrangian penalty", inner)]))
    for r in runs:
        r["timeout"] = 1800
        if r["name"] == "adaptive-strict-0.001":
            r["sets"] = r["sets"] + [("Output/Output interval", "1")]  # for the map
    return runs


def runs_stability():
    runs = []
    axes = [("dt", dt, SHORT + [("Time stepping/Time step", str(dt))]) for dt in (0.125, 0.25, 0.5, 1.0)]
    axes += [("level", lv, [("Tools/Punch/Stroke", "3"), ("Mesh/Planform refinements", str(lv))])
             for lv in (2, 4)]
    for axis, value, base in axes:
        for e in range(2, 10):
            runs.append(dict(group="stability", name="fixed-1e%d-%s-%g" % (e, axis, value), kind="fixed",
                             eps=10.0**e, delta=DELTA_FIXED, axis=axis, value=value, sets=base + fixed(10.0**e)))
        for s in ("adaptive", "adaptive-strict"):
            for d in DELTAS:
                runs.append(dict(group="stability", name="%s-%g-%s-%g" % (s, d, axis, value), kind=s, delta=d,
                                 axis=axis, value=value, sets=base + adaptive(s, d)))
    for r in runs:
        r["timeout"] = 900
        r["sets"] = r["sets"] + [("Output/Output interval", "0")]
    return runs


def runs_condition():
    runs = []
    for solver, extra in (("direct", [("Linear solver/Condition estimate iterations", "400")]),):
        scene = SMALL
        for e in range(1, 11):
            runs.append(dict(group="condition", name="%s-fixed-1e%d" % (solver, e), kind="fixed", solver=solver,
                             eps=10.0**e, delta=DELTA_FIXED, sets=scene + extra + fixed(10.0**e)))
        for s in ("adaptive", "adaptive-strict"):
            for d in DELTAS:
                runs.append(dict(group="condition", name="%s-%s-%g" % (solver, s, d), kind=s, solver=solver,
                                 delta=d, sets=scene + extra + adaptive(s, d)))
    for r in runs:
        r["timeout"] = 900
        r["sets"] = r["sets"] + [("Output/Output interval", "0")]
    return runs


def read_history(path):
    """history.csv with solver.csv beside it, as numbers."""
    if not os.path.exists(path):
        return []
    return [{k: float(v) for k, v in row.items()} for row in steps(path)]


def execute(run, force):
    out = os.path.join(OUT, run["group"], run["name"])
    status_file = os.path.join(out, "status.txt")
    if force or not os.path.exists(status_file):
        os.makedirs(out, exist_ok=True)
        # A failed run leaves its earlier rows; start every run afresh.
        for f in ("history.csv", "run-summary.txt"):
            if os.path.exists(os.path.join(out, f)):
                os.remove(os.path.join(out, f))
        # A run may name its own scene (contact_charts_process.py: the
        # default process, prm/cup-drawing.prm as it is).
        cmd = [EXE, run.get("prm", PRM), "--set", "Output/Output directory=" + out]
        for key, value in run.get("base", LEGACY) + run["sets"]:
            cmd += ["--set", "%s=%s" % (key, value)]
        start = time.time()
        with open(os.path.join(out, "log.txt"), "w") as log:
            log.write(" ".join("'%s'" % c if " " in c else c for c in cmd) + "\n")
            log.flush()
            try:
                p = subprocess.run(cmd, stdout=log, stderr=subprocess.STDOUT, timeout=run["timeout"],
                                   env=dict(os.environ, OMP_NUM_THREADS="1"))
                code = p.returncode
            except subprocess.TimeoutExpired:
                code = None
        wall = time.time() - start
        text = open(os.path.join(out, "log.txt")).read()
        if code == 0:
            status = "converged"
        elif code is None:
            status = "timeout"
        elif "linear solver failed" in text:
            status = "linear solver failed"
        elif "Newton" in text:
            status = "Newton diverged"
        else:
            status = "error"
        with open(status_file, "w") as f:
            f.write("%s\n%.3f\n" % (status, wall))
    lines = open(status_file).read().split("\n")
    run["status"], run["wall"] = lines[0], float(lines[1])
    rows = read_history(os.path.join(out, "history.csv"))
    run["steps"] = len(rows)
    run["max_penetration"] = max((r["max_penetration"] for r in rows), default=float("nan"))
    run["peak_force"] = max((r["punch_force"] for r in rows), default=float("nan"))
    its = sum(r["newton_iterations"] for r in rows)
    run["newton_per_step"] = its / len(rows) if rows else float("nan")
    run["max_linear"] = max((r["max_linear_iterations"] for r in rows), default=float("nan"))
    run["condition"] = max((r["condition_estimate"] for r in rows), default=float("nan"))
    run["passes"] = sum(r["strict_passes"] for r in rows)
    run["final_travel"] = rows[-1]["punch_travel"] if rows else 0.0
    if run["status"] == "converged" and run["max_penetration"] > run["delta"] * (1 + 1e-9):
        run["status"] = "penetration > delta"
    return run


def execute_all(runs, jobs, force):
    def one(r):
        r = execute(r, force)
        print("%-10s %-34s %-22s %8.1f s  steps %3d  pen %.3g  F %.5g" % (
            r["group"], r["name"], r["status"], r["wall"], r["steps"], r["max_penetration"], r["peak_force"]),
            flush=True)
        return r
    with ThreadPoolExecutor(max_workers=jobs) as pool:
        return list(pool.map(one, runs))


def write_csv(path, runs, keys):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(keys)
        for r in runs:
            w.writerow([r.get(k, "") for k in keys])


COLORS = {"fixed": "tab:gray", "adaptive": "tab:blue", "adaptive-strict": "tab:green",
          "augmented-lagrangian (fixed)": "tab:red", "augmented-lagrangian (adaptive)": "tab:purple"}


def speed_panels(axes, runs, ok, tag_of, xlabel):
    """Max penetration and peak-force error (r["force_error"]) against wall time
    on two axes; runs not in @p ok are drawn as failed, those without any row
    listed in a corner."""
    for ax, key, label in ((axes[0], "max_penetration", "max penetration over the run (mm)"),
                           (axes[1], "force_error", "|peak punch force - reference| / reference")):
        for r in runs:
            y = r[key]
            if not (y > 0 and math.isfinite(y)):
                continue  # the reference itself (zero error), or no row at all (listed below)
            failed = r not in ok
            ax.scatter(r["wall"], y, marker="x" if failed else "o", s=40, color=COLORS.get(r["kind"], "k"))
            tag = tag_of(r)
            if failed:
                tag += " FAILED (%s, %.1f mm)" % (r["status"], r["final_travel"])
            ax.annotate(tag, (r["wall"], y), fontsize=6, xytext=(3, 3), textcoords="offset points",
                        color="tab:red" if failed else "k")
        early = ["%s (%s in step %d, %.0f s)" % (tag_of(r), r["status"], r["steps"] + 1, r["wall"])
                 for r in runs if r not in ok and r["steps"] == 0]
        if early:
            ax.text(0.98, 0.98, "failed at once:\n" + "\n".join(early), transform=ax.transAxes, fontsize=7,
                    ha="right", va="top", color="tab:red")
        ax.set_xscale("log")
        # Plain numbers: over less than a decade matplotlib labels the
        # minor ticks as 2.2x10^0, 2.4x10^0, ..., which overlap.
        from matplotlib.ticker import FuncFormatter

        plain = FuncFormatter(lambda v, _: "%g" % v)
        ax.xaxis.set_major_formatter(plain)
        ax.xaxis.set_minor_formatter(plain)
        ax.tick_params(axis="x", which="minor", labelsize=7)
        ax.set_yscale("log")
        ax.set_xlabel(xlabel)
        ax.set_ylabel(label)
        ax.grid(True, which="both", alpha=0.3)
    axes[0].axhline(1e-3, color="k", lw=0.8, ls="--")


def chart_speed(runs, plt):
    ok = [r for r in runs if r["status"] in ("converged", "penetration > delta")]
    ref_runs = [r for r in ok if r["name"] == "adaptive-strict-0.0001"]
    ref = ref_runs[0]["peak_force"] if ref_runs else float("nan")
    for r in runs:
        r["force_error"] = abs(r["peak_force"] - ref) / ref if r in ok else float("nan")
    write_csv(os.path.join(DOC, "contact-speed-accuracy.csv"), runs,
              ["name", "kind", "eps", "delta", "status", "steps", "final_travel", "wall", "max_penetration",
               "peak_force", "force_error", "newton_per_step", "passes"])
    fig, axes = plt.subplots(1, 2, figsize=(13, 5.2))
    speed_panels(axes, runs, ok, lambda r: r["name"].replace("adaptive-strict", "strict").replace("fixed-", ""),
                 "wall time of the run (s, 1 rank, 2 runs at a time on 2 cores)")
    handles = [plt.Line2D([], [], marker="o", ls="", color=c, label=k) for k, c in COLORS.items()]
    handles.append(plt.Line2D([], [], marker="x", ls="", color="k", label="failed (partial run)"))
    axes[0].legend(handles=handles, fontsize=7, loc="lower left")
    fig.suptitle("Default cup (prm/cup-drawing.prm): speed vs accuracy; reference force: adaptive-strict, "
                 "delta = 1e-4 mm (%.5g N)" % ref, fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(DOC, "contact-speed-accuracy.png"), dpi=130)


STATUS_STYLE = {"converged": ("o", "tab:green"), "penetration > delta": ("s", "tab:orange"),
                "Newton diverged": ("X", "tab:red"), "linear solver failed": ("D", "tab:purple"),
                "timeout": ("P", "k"), "error": ("*", "k")}


def chart_stability(runs, plt):
    write_csv(os.path.join(DOC, "contact-stability.csv"), runs,
              ["name", "kind", "eps", "delta", "axis", "value", "status", "steps", "final_travel", "wall",
               "max_penetration", "newton_per_step", "passes"])
    fig, axes = plt.subplots(2, 2, figsize=(13, 8.5))
    for col, axis, values, label in ((0, "dt", [0.125, 0.25, 0.5, 1.0], "time step (s) at planform level 3"),
                                     (1, "level", [2, 3, 4], "planform refinements at dt = 0.25 s")):
        sel = [r for r in runs if (r["axis"] == axis) or (axis == "level" and r["axis"] == "dt" and r["value"] == 0.25)]
        for r in sel:
            r["_x"] = values.index(3 if (axis == "level" and r["axis"] == "dt") else r["value"])
        ax = axes[0][col]
        for r in sel:
            if r["kind"] != "fixed":
                continue
            m, c = STATUS_STYLE[r["status"]]
            ax.scatter(r["_x"], math.log10(r["eps"]), marker=m, color=c, s=90)
            ax.annotate("%.0e" % r["max_penetration"] if math.isfinite(r["max_penetration"]) else "",
                        (r["_x"], math.log10(r["eps"])), fontsize=6, xytext=(7, -3), textcoords="offset points")
        ax.set_yticks(range(2, 10))
        ax.set_yticklabels(["1e%d" % e for e in range(2, 10)])
        ax.set_ylabel("fixed penalty factor (N/mm^3)")
        ax = axes[1][col]
        rows = [(s, d) for s in ("adaptive", "adaptive-strict") for d in DELTAS]
        for r in sel:
            if r["kind"] == "fixed":
                continue
            y = rows.index((r["kind"], r["delta"]))
            m, c = STATUS_STYLE[r["status"]]
            ax.scatter(r["_x"], y, marker=m, color=c, s=90)
            ax.annotate("%.0e" % r["max_penetration"] if math.isfinite(r["max_penetration"]) else "",
                        (r["_x"], y), fontsize=6, xytext=(7, -3), textcoords="offset points")
        ax.set_yticks(range(len(rows)))
        ax.set_yticklabels(["%s d=%g" % (s.replace("adaptive-strict", "strict"), d) for s, d in rows])
        for a in (axes[0][col], axes[1][col]):
            a.set_xticks(range(len(values)))
            a.set_xticklabels([str(v) for v in values])
            a.set_xlim(-0.5, len(values) - 0.5)
            a.set_xlabel(label)
            a.grid(True, alpha=0.3)
    handles = [plt.Line2D([], [], marker=m, ls="", color=c, label=k) for k, (m, c) in STATUS_STYLE.items()]
    axes[0][0].legend(handles=handles, fontsize=7, loc="upper left", bbox_to_anchor=(0, 1.25), ncol=3)
    fig.suptitle("Stability map, cup drawn 3 mm (penetration judged against delta = 1e-3 mm for fixed eps; "
                 "numbers: max penetration, mm)", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(DOC, "contact-stability.png"), dpi=130)


def chart_condition(runs, plt):
    write_csv(os.path.join(DOC, "contact-condition.csv"), runs,
              ["name", "solver", "kind", "eps", "delta", "status", "steps", "max_penetration", "condition",
               "max_linear", "newton_per_step"])
    fig, axes = plt.subplots(1, 1, figsize=(7, 4.5))
    for ax, solver, key, label in ((axes, "direct", "condition", "Lanczos estimate of cond(K) (400 CG steps)"),):
        fx = [r for r in runs if r["solver"] == solver and r["kind"] == "fixed"]
        ok = [r for r in fx if r["status"] in ("converged", "penetration > delta") and r[key] > 0]
        ax.plot([r["eps"] for r in ok], [r[key] for r in ok], "o-", color="tab:gray", label="fixed eps")
        for r in fx:
            if r not in ok:
                ax.axvline(r["eps"], color="tab:red", lw=0.8, ls=":")
                ax.annotate(r["status"], (r["eps"], 0.95), xycoords=("data", "axes fraction"), rotation=90,
                            fontsize=7, color="tab:red", va="top")
        for s, c in (("adaptive", "tab:blue"), ("adaptive-strict", "tab:green")):
            for r in runs:
                if r["solver"] == solver and r["kind"] == s:
                    if r["status"] in ("converged", "penetration > delta") and r[key] > 0:
                        ax.axhline(r[key], color=c, lw=0.8, ls="--")
                        ax.annotate("%s d=%g" % (s, r["delta"]), (0.02, r[key]), xycoords=("axes fraction", "data"),
                                    fontsize=7, color=c)
                    else:
                        ax.annotate("%s d=%g: %s" % (s, r["delta"], r["status"]), (0.02, 0.9 - 0.05 * DELTAS.index(r["delta"])),
                                    xycoords="axes fraction", fontsize=7, color="tab:red")
        ax.set_xscale("log")
        if any(r["solver"] == solver and r["status"] in ("converged", "penetration > delta") and r[key] > 0
               for r in runs):
            ax.set_yscale("log")
        else:
            ax.set_xlim(5, 2e10)
            ax.text(0.5, 0.5, "no run completed:\nsee the status of each run", transform=ax.transAxes,
                    ha="center", color="tab:red")
        ax.set_xlabel("fixed penalty factor (N/mm^3)")
        ax.set_ylabel(label)
        ax.grid(True, which="both", alpha=0.3)
    fig.suptitle("Cup drawn 1 mm, planform level 2, frictionless (symmetric tangent); dashed: adaptive runs",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(DOC, "contact-condition.png"), dpi=130)


def chart_map(plt):
    import xml.etree.ElementTree as ET
    import numpy as np
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
    out = os.path.join(OUT, "speed", "adaptive-strict-0.001")
    rows = read_history(os.path.join(out, "history.csv"))
    if not rows:
        print("map: no adaptive-strict-0.001 run")
        return
    worst = max(rows, key=lambda r: r["max_penetration"])
    step = int(worst["step"])
    sets = ET.parse(os.path.join(out, "solution.pvd")).getroot().findall(".//DataSet")
    files = [d.get("file") for d in sets]
    name = [f for f in files if f.endswith("%04d.pvtu" % step) or ("_%d." % step) in f or ("-%d." % step) in f]
    name = name[0] if name else files[min(step, len(files) - 1)]
    reader = vtk.vtkXMLPUnstructuredGridReader()
    reader.SetFileName(os.path.join(out, name))
    reader.Update()
    grid = reader.GetOutput()
    x = vtk_to_numpy(grid.GetPoints().GetData())
    gap = vtk_to_numpy(grid.GetPointData().GetArray("contact_gap"))
    p = vtk_to_numpy(grid.GetPointData().GetArray("contact_pressure"))
    c = p > 0
    pen = np.maximum(-gap[c], 0) / 1e-3
    r = np.hypot(x[c, 0], x[c, 1])
    fig, axes = plt.subplots(1, 2, figsize=(13, 4.8), gridspec_kw=dict(width_ratios=[2, 1]))
    sc = axes[0].scatter(r, x[c, 2], c=pen, cmap="viridis", vmin=0, vmax=1.0, s=6)
    fig.colorbar(sc, ax=axes[0], label="penetration / delta")
    axes[0].set_xlabel("radius (mm)")
    axes[0].set_ylabel("z (mm)")
    axes[0].set_title("contact nodes at step %d (punch travel %.2f mm), %s" % (step, worst["punch_travel"], name),
                      fontsize=9)
    axes[1].hist(pen, bins=40, color="tab:green")
    axes[1].set_xlabel("penetration / delta")
    axes[1].set_ylabel("contact nodes")
    axes[1].set_title("max %.4f delta over %d nodes" % (pen.max(), c.sum()), fontsize=9)
    fig.suptitle("adaptive-strict, delta = 1e-3 mm on every contact node, default cup, worst step", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(DOC, "contact-penetration-map.png"), dpi=130)
    with open(os.path.join(DOC, "contact-penetration-map.csv"), "w") as f:
        f.write("step,punch_travel,nodes,max_penetration_over_delta,mean_penetration_over_delta\n")
        f.write("%d,%g,%d,%.6f,%.6f\n" % (step, worst["punch_travel"], c.sum(), pen.max(), pen.mean()))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--jobs", type=int, default=os.cpu_count())
    ap.add_argument("--force", action="store_true")
    ap.add_argument("--groups", default="speed,stability,condition,map")
    a = ap.parse_args()
    if not os.access(EXE, os.X_OK):
        sys.exit("contact_charts: %s missing; run bash scripts/build.sh" % EXE)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    groups = a.groups.split(",")
    if "speed" in groups:
        chart_speed(execute_all(runs_speed(), a.jobs, a.force), plt)
    if "stability" in groups:
        chart_stability(execute_all(runs_stability(), a.jobs, a.force), plt)
    if "condition" in groups:
        chart_condition(execute_all(runs_condition(), a.jobs, a.force), plt)
    if "map" in groups:
        chart_map(plt)


if __name__ == "__main__":
    main()

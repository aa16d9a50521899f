"""The contact charts of doc/contact.md on the default process (issue 10 section 4):
prm/cup-drawing.prm as it is, blank holder under force control, drawn through
(or to the stroke), with step control.

  process            speed vs accuracy, full draw: axisymmetric section and
                     quarter 3-D (planform level 3, 4 layers) panels; fixed eps
                     over 9 decades, adaptive / adaptive-strict with delta in
                     {1e-2, 1e-3, 1e-4} mm, augmented Lagrangian
  process-stability  stability map, full draw of the axisymmetric section:
                     time step x (fixed eps | delta), for the default punch
                     radius r_p = 8 mm and for r_p = 2 mm (the sharpest radius
                     of the reference cups)
  process-stability-quarter
                     the same map for the quarter 3-D model (planform level 3,
                     4 layers) at time steps 0.25, 0.5 and 1 s, with fixed eps
                     1e3 and 1e5 to 1e9, adaptive delta = 1e-3 mm and
                     adaptive-strict delta = 1e-3 and 1e-4 mm; 300 s per run at
                     most (a longer run is a timeout)

Runs go to results/contact-charts/<group>/<name>/ and are reused unless --force.
Usage: /usr/bin/python3 benchmarks/contact_charts_process.py [--jobs N] [--force]
           [--groups process,process-stability,process-stability-quarter]
"""
import argparse
import math
import os

import contact_charts as cc

PROCESS_PRM = os.path.join(cc.ROOT, "prm", "cup-drawing.prm")
QUIET = [("Output/Output interval", "0"), ("Output/Revolved copy", "false"), ("Output/Report", "false")]
QUARTER = [("Geometry/Model", "quarter"), ("Mesh refinement/Interval", "0"),
           ("Mesh/Layers through thickness", "4"), ("Mesh/Planform refinements", "3")]
MODELS = {"axisymmetric": [], "quarter": QUARTER}
RADII = [8, 2]
STEPS = [0.125, 0.25, 0.5, 1.0]
QUARTER_STEPS = [0.25, 0.5, 1.0]
QUARTER_METHODS = {("adaptive", 1e-3), ("adaptive-strict", 1e-3), ("adaptive-strict", 1e-4)}
# 1e2 and 1e4 behave as 1e3 in every cell of the axisymmetric map but one.
QUARTER_EPS = [3, 5, 6, 7, 8, 9]


def strategies(eps_exponents):
    """(name, kind, eps, delta, sets) of every contact method compared."""
    out = [("fixed-1e%d" % e, "fixed", 10.0**e, cc.DELTA_FIXED, cc.fixed(10.0**e)) for e in eps_exponents]
    out += [("%s-%g" % (s, d), s, float("nan"), d, cc.adaptive(s, d))
            for s in ("adaptive", "adaptive-strict") for d in cc.DELTAS]
    return out


def runs_process():
    runs = []
    for model, sets in MODELS.items():
        methods = strategies(range(1, 10))
        methods += [("al-%s-0.001" % inner, "augmented-lagrangian (%s)" % inner, float("nan"), 1e-3,
                     cc.adaptive("augmented-lagrangian", 1e-3) + [("Contact/Augmented Lagrangian penalty", inner)])
                    for inner in ("fixed", "adaptive")]
        for name, kind, eps, delta, extra in methods:
            runs.append(dict(group="process", name="%s-%s" % (model, name), model=model, kind=kind, eps=eps,
                             delta=delta, prm=PROCESS_PRM, base=QUIET + sets, sets=extra, timeout=1800))
    return runs


def runs_process_stability(model="axisymmetric"):
    runs = []
    quarter = model == "quarter"
    for rp in RADII:
        for dt in QUARTER_STEPS if quarter else STEPS:
            for name, kind, eps, delta, extra in strategies(QUARTER_EPS if quarter else range(2, 10)):
                if quarter and kind != "fixed" and (kind, delta) not in QUARTER_METHODS:
                    continue
                runs.append(dict(group="process-stability" + ("-quarter" if quarter else ""),
                                 name="rp%g-dt%g-%s" % (rp, dt, name), kind=kind,
                                 eps=eps, delta=delta, rp=rp, dt=dt, prm=PROCESS_PRM, timeout=300 if quarter else 900,
                                 base=QUIET + MODELS[model] + [("Tools/Punch/Profile radius", str(rp)),
                                                               ("Time stepping/Time step", str(dt))],
                                 sets=extra))
    return runs


def speed_panels(axes, runs, plt):
    """One model's runs: force error against its adaptive-strict delta = 1e-4
    run, then contact_charts' two panels. Returns the reference force."""
    ok = [r for r in runs if r["status"] in ("converged", "penetration > delta")]
    ref_runs = [r for r in ok if r["kind"] == "adaptive-strict" and r["delta"] == 1e-4]
    ref = ref_runs[0]["peak_force"] if ref_runs else float("nan")
    for r in runs:
        r["force_error"] = abs(r["peak_force"] - ref) / ref if r in ok else float("nan")
    cc.speed_panels(axes, runs, ok,
                    lambda r: r["name"].split("-", 1)[1].replace("adaptive-strict", "strict").replace("fixed-", ""),
                    "wall time of the full draw (s, 1 rank, 2 runs at a time on 2 cores)")
    return ref


def chart_process(runs, plt):
    fig, axes = plt.subplots(2, 2, figsize=(13, 10))
    for row, model in enumerate(MODELS):
        ref = speed_panels(axes[row], [r for r in runs if r["model"] == model], plt)
        axes[row][0].set_title("%s: reference force (adaptive-strict, delta = 1e-4 mm) %.5g N" % (model, ref),
                               fontsize=9)
    # After the panels: they compute force_error.
    cc.write_csv(os.path.join(cc.DOC, "contact-process-speed-accuracy.csv"), runs,
                 ["name", "model", "kind", "eps", "delta", "status", "steps", "final_travel", "wall",
                  "max_penetration", "peak_force", "force_error", "newton_per_step", "passes"])
    handles = [plt.Line2D([], [], marker="o", ls="", color=c, label=k) for k, c in cc.COLORS.items()]
    handles.append(plt.Line2D([], [], marker="x", ls="", color="k", label="failed (partial run)"))
    axes[0][0].legend(handles=handles, fontsize=7, loc="lower left")
    fig.suptitle("Default process (prm/cup-drawing.prm: holder under force control, drawn through): "
                 "speed vs accuracy over the full draw", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(cc.DOC, "contact-process-speed-accuracy.png"), dpi=130)


def chart_process_stability(runs, plt, model="axisymmetric"):
    quarter = model == "quarter"
    stem = "contact-process-stability" + ("-quarter" if quarter else "")
    steps = QUARTER_STEPS if quarter else STEPS
    cc.write_csv(os.path.join(cc.DOC, stem + ".csv"), runs,
                 ["name", "kind", "eps", "delta", "rp", "dt", "status", "steps", "final_travel", "wall",
                  "max_penetration", "newton_per_step", "passes"])
    fig, axes = plt.subplots(2, 2, figsize=(13, 8.5))
    rows = [(s, d) for s in ("adaptive", "adaptive-strict") for d in cc.DELTAS
            if not quarter or (s, d) in QUARTER_METHODS]
    for col, rp in enumerate(RADII):
        for r in (r for r in runs if r["rp"] == rp):
            x = steps.index(r["dt"])
            fixed = r["kind"] == "fixed"
            ax = axes[0 if fixed else 1][col]
            y = math.log10(r["eps"]) if fixed else rows.index((r["kind"], r["delta"]))
            m, c = cc.STATUS_STYLE[r["status"]]
            ax.scatter(x, y, marker=m, color=c, s=90)
            text = "%.0e" % r["max_penetration"] if math.isfinite(r["max_penetration"]) else ""
            if r["status"] not in ("converged", "penetration > delta"):
                text += " @%.1f" % r["final_travel"]
            ax.annotate(text, (x, y), fontsize=6, xytext=(7, -3), textcoords="offset points")
        axes[0][col].set_yticks(range(2, 10))
        axes[0][col].set_yticklabels(["1e%d" % e for e in range(2, 10)])
        axes[0][col].set_ylabel("fixed penalty factor (N/mm^3)")
        axes[1][col].set_yticks(range(len(rows)))
        axes[1][col].set_yticklabels(["%s d=%g" % (s.replace("adaptive-strict", "strict"), d) for s, d in rows])
        for a in (axes[0][col], axes[1][col]):
            a.set_xticks(range(len(steps)))
            a.set_xticklabels([str(v) for v in steps])
            a.set_xlim(-0.5, len(steps) - 0.5)
            a.set_xlabel("time step (s) = punch travel per step (mm)")
            a.set_title("punch profile radius r_p = %g mm" % rp, fontsize=9)
            a.grid(True, alpha=0.3)
    handles = [plt.Line2D([], [], marker=m, ls="", color=c, label=k) for k, (m, c) in cc.STATUS_STYLE.items()]
    axes[0][0].legend(handles=handles, fontsize=7, loc="upper left", bbox_to_anchor=(0, 1.3), ncol=3)
    fig.suptitle("Stability map, full draw of the %s default process (numbers: max penetration, mm; " % model +
                 "@: travel reached by a failed run; fixed eps judged against delta = 1e-3 mm)", fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(cc.DOC, stem + ".png"), dpi=130)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--jobs", type=int, default=os.cpu_count())
    ap.add_argument("--force", action="store_true")
    ap.add_argument("--groups", default="process,process-stability,process-stability-quarter")
    a = ap.parse_args()
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    groups = a.groups.split(",")
    if "process" in groups:
        chart_process(cc.execute_all(runs_process(), a.jobs, a.force), plt)
    if "process-stability" in groups:
        chart_process_stability(cc.execute_all(runs_process_stability(), a.jobs, a.force), plt)
    if "process-stability-quarter" in groups:
        chart_process_stability(cc.execute_all(runs_process_stability("quarter"), a.jobs, a.force), plt, "quarter")


if __name__ == "__main__":
    main()

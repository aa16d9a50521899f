"""A strip drawn through a round draw bead, modelled twice (issue 65,
section 3): as tool geometry (bead-strip/geometric.prm: groove in the die,
bead insert through the holder) and as an equivalent line bead on flat tools
(bead-strip/equivalent.prm) with the force the geometric run measured and
with the force of formsolve's bead model (Model = geometry); a run without a
bead for reference. The plane-strain U-channel of prm/channel.prm, drawn
20 mm deep after the bead has closed.

The geometric run's bead force: the x force of the sheet on the groove tool
and the bead insert (history.csv `force_x_groove`, `force_x_bead`; one
flange, 35 mm wide) per unit length, with the flat faces' friction of the
groove tool (x = 80 ... 200) in it, and apart the holder's share (the strip,
curled by the bead, rubs its flat face); its opening force the bead insert's z
force per flange and unit length; the strip tension the punch force per
flange and unit width. These are means over punch travel 15 mm to the end
(the geometric run's die force flickers from step to step); draw-in and
thickness are the end's. Written into doc/forming-results.md between the beads markers.

Usage: bead_strip_report.py [--force]; runs are kept in results/bead-strip/
and reused unless --force."""
import argparse, csv, os, subprocess, time

import forming_results as fr

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.path.join(ROOT, "build", "formsolve")
OUT = os.path.join(ROOT, "results", "bead-strip")
HERE = os.path.join(ROOT, "benchmarks", "bead-strip")
WIDTH = 35.0  # mm, the strip's width (one flange's bead is this long)
STEADY = 15.0  # mm of punch travel from which forces are averaged


def run(label, prm, sets, force):
    out = os.path.join(OUT, label)
    summary = os.path.join(out, "run-summary.txt")
    if force or not os.path.exists(summary):
        os.makedirs(out, exist_ok=True)
        sets = {**sets, "Output/Output directory": out, "Output/Report": "false"}
        cmd = [EXE, os.path.join(HERE, prm)] + sum((["--set", f"{k}={v}"] for k, v in sets.items()), [])
        start = time.time()
        with open(os.path.join(out, "log.txt"), "w") as log:
            ok = subprocess.call(cmd, stdout=log, stderr=subprocess.STDOUT, cwd=HERE) == 0
        with open(os.path.join(out, "elapsed.txt"), "w") as f:
            f.write(f"{time.time() - start:.1f}\n")
        if not ok:
            with open(summary, "w") as f:
                f.write("end_reason = failed\n")
    s = dict(l.rstrip("\n").split(" = ", 1) for l in open(summary) if " = " in l)
    s["elapsed"] = float(open(os.path.join(out, "elapsed.txt")).read())
    path = os.path.join(out, "history.csv")
    s["history"] = list(csv.DictReader(open(path))) if os.path.exists(path) else []
    return s


def steady_mean(history, f):
    vals = [f(r) for r in history if float(r["punch_travel"]) >= STEADY]
    return sum(vals) / len(vals)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--force", action="store_true")
    a = ap.parse_args()
    subprocess.check_call(["/usr/bin/python3", "make_profiles.py"], cwd=HERE)
    geo = run("geometric", "geometric.prm", {}, a.force)
    h = geo["history"]
    restraint = steady_mean(h, lambda r: -(float(r["force_x_groove"]) + float(r["force_x_bead"])) / WIDTH)
    holder = steady_mean(h, lambda r: -float(r["force_x_bead_holder"]) / WIDTH)
    opening = steady_mean(h, lambda r: float(r["force_bead"]) / 2 / WIDTH)
    given = {"Tools/Draw beads/bead/Model": "forces",
             "Tools/Draw beads/bead/Restraining force": f"{restraint:.6g}",
             "Tools/Draw beads/bead/Opening force": f"{opening:.6g}"}
    runs = [("bead as tool geometry", geo),
            ("line bead, the geometric run's force", run("equivalent-measured", "equivalent.prm", given, a.force)),
            ("line bead, the geometric run's force with the holder's share",
             run("equivalent-measured-all", "equivalent.prm",
                 {**given, "Tools/Draw beads/bead/Restraining force": f"{restraint + holder:.6g}"}, a.force)),
            ("line bead, its bead model's force", run("equivalent-model", "equivalent.prm", {}, a.force)),
            # A bead of zero force changes nothing (test bead_channel_zero_force).
            ("no bead", run("no-bead", "equivalent.prm",
                            {"Tools/Draw beads/bead/Model": "forces",
                             "Tools/Draw beads/bead/Restraining force": 0,
                             "Tools/Draw beads/bead/Opening force": 0}, a.force))]
    ref = runs[0][1]

    def final(s, key):
        return float(s["history"][-1][key]) if s["history"] else float("nan")

    def strip_tension(s):
        return steady_mean(s["history"], lambda r: float(r["punch_force"])) / 2 / WIDTH

    lines = ["| run | bead force (N/mm) | draw-in (mm) | strip tension (N/mm, mean) | min. thickness (mm) | "
             "wall time (s) | end |", "|---|---|---|---|---|---|---|"]
    for label, s in runs:
        if label.startswith("bead as"):
            force = f"{restraint:.1f} (+ {holder:.1f} on the holder's flat faces)"
        elif label != "no bead":
            force = f"{steady_mean(s['history'], lambda r: float(r['bead_bead_force'])) / 2 / WIDTH:.1f}"
        else:
            force = "–"
        row = [final(s, "draw_in"), strip_tension(s), final(s, "min_thickness")]
        dev = "" if s is ref else " (" + ", ".join(
            f"{100 * (v / w - 1):+.1f} %" for v, w in zip(row, [final(ref, "draw_in"), strip_tension(ref),
                                                                 final(ref, "min_thickness")])) + ")"
        lines.append(f"| {label} | {force} | {row[0]:.3f} | {row[1]:.1f} | {row[2]:.4f} | {s['elapsed']:.0f} | "
                     f"{s.get('end_reason', '').split(':')[0]} |")
        if dev:
            lines[-1] = lines[-1][:-1] + f" vs geometric:{dev} |"
    model = float(runs[3][1].get("bead_bead_restraining_per_mm", "nan"))
    lines += ["", f"The geometric run's bead: {restraint:.1f} N/mm restraining, {opening:.1f} N/mm opening "
              f"(means from {STEADY:g} mm of punch travel on); formsolve's bead model (Model = geometry): "
              f"{model:.1f} N/mm restraining ({100 * (model / restraint - 1):+.1f} %), "
              f"{float(runs[3][1].get('bead_bead_opening_per_mm', 'nan')):.1f} N/mm opening; "
              f"with the holder's share {restraint + holder:.1f} N/mm ({100 * (model / (restraint + holder) - 1):+.1f} %)."]
    fr.write_block("beads", lines)


if __name__ == "__main__":
    main()

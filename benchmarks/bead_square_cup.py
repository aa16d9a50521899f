"""The square cup (prm/square-cup.prm, quarter model, 1 rank) with a
straight draw bead along each side of the flange (prm/square-cup-beads.prm):
no bead, 30 N/mm, and a bead force large enough to lock the flange at the
side centres, drawn 20 mm (the locking one to the full stroke, so that the
split report can say where it splits). Draw-in at the side centre (x), the
diagonal and y, peak punch force, the split, and what the beads cost: the
`draw beads` share of the run's timer. Written into doc/forming-results.md
between the beads-square markers.

Usage: bead_square_cup.py [--force]; runs are kept in
results/bead-square-cup/ and reused unless --force."""
import argparse, csv, os, re, subprocess, time

import forming_results as fr

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.path.join(ROOT, "build", "formsolve")
OUT = os.path.join(ROOT, "results", "bead-square-cup")
PRM = os.path.join(ROOT, "prm")
LOCK = 300  # N/mm
RUNS = [("no bead", "square-cup.prm", {"Tools/Punch/Stroke": 20}),
        ("beads 30 N/mm", "square-cup-beads.prm", {"Tools/Punch/Stroke": 20}),
        (f"beads {LOCK} N/mm", "square-cup-beads.prm",
         {f"Tools/Draw beads/side {a}/Restraining force": LOCK for a in "xy"})]


def run(label, prm, sets, force):
    out = os.path.join(OUT, re.sub(r"[^a-z0-9]+", "-", label.lower()).strip("-"))
    summary = os.path.join(out, "run-summary.txt")
    if force or not os.path.exists(summary):
        os.makedirs(out, exist_ok=True)
        sets = {**sets, "Output/Output directory": out, "Output/Output interval": 0, "Output/Report": "false"}
        cmd = [EXE, os.path.join(PRM, prm)] + \
            sum((["--set", f"{k}={v}"] for k, v in sets.items()), [])
        start = time.time()
        with open(os.path.join(out, "log.txt"), "w") as log:
            subprocess.call(cmd, stdout=log, stderr=subprocess.STDOUT, cwd=PRM)
        with open(os.path.join(out, "elapsed.txt"), "w") as f:
            f.write(f"{time.time() - start:.1f}\n")
    s = dict(l.rstrip("\n").split(" = ", 1) for l in open(summary) if " = " in l)
    s["elapsed"] = float(open(os.path.join(out, "elapsed.txt")).read())
    s["history"] = list(csv.DictReader(open(os.path.join(out, "history.csv"))))
    s["bead_share"] = "–"
    for line in open(os.path.join(out, "log.txt")):
        if line.startswith("| draw beads"):
            s["bead_share"] = line.split("|")[4].strip()
    return s


def at(s, travel, key):
    """The column at the row nearest @travel."""
    row = min(s["history"], key=lambda r: abs(float(r["punch_travel"]) - travel))
    return float(row[key])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--force", action="store_true")
    a = ap.parse_args()
    results = [(label, run(label, prm, sets, a.force)) for label, prm, sets in RUNS]
    lines = ["| run | draw-in at 10 mm: side x / diagonal (mm) | at 20 mm | peak punch force (kN) | "
             "bead force at 10 mm (kN) | split | beads' share of the run time | wall time (s) | end |",
             "|---|---|---|---|---|---|---|---|---|"]
    for label, s in results:
        beads = [k for k in s["history"][0] if k.startswith("bead_") and k.endswith("_force")]
        force = sum(at(s, 10, k) for k in beads) / 1000 if beads else None
        split = (f"at {float(s['split_travel']):.2f} mm, {s['split_location']} ({s['split_measure']})"
                 if s.get("split") == "yes" else "no")
        reached = float(s["history"][-1]["punch_travel"])

        def draw_in(travel):
            if reached < travel - 1e-6:
                return "–"
            return " / ".join(f"{at(s, travel, 'draw_in' + d):.3f}" for d in ("_x", "_diagonal"))
        lines.append(
            f"| {label} | {draw_in(10)} | {draw_in(20)} | {float(s['peak_punch_force']) / 1000:.1f} | "
            f"{'–' if force is None else f'{force:.2f}'} | {split} | {s['bead_share']} | {s['elapsed']:.0f} | "
            f"{s.get('end_reason', '').split(':')[0]} |")
    fr.write_block("beads-square", lines)


if __name__ == "__main__":
    main()

"""The earing cup (`doc/reference-scenes.md` (section 2)) with both Hill48
calibrations, planar isotropy and the variants the scene asks for (holder
force halved and doubled, the positional holder at 1.04 mm over the die,
mu = 0.1, the Voce flow curve) and Yld2004-18p with the two published
coefficient sets (their own Voce curves and friction), quarter model on 2
ranks; written into
doc/forming-results.md between the earing markers, with
doc/earing-profiles.png (cup height against the angle to RD) and
doc/earing-sections.png (thickness along the 0, 45 and 90 degree sections).

Usage: earing_report.py [--force]; runs are kept in results/earing/ and
reused unless --force."""
import argparse, csv, os, re, subprocess

import forming_results as fr

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.path.join(ROOT, "build", "formsolve")
OUT = os.path.join(ROOT, "results", "earing")
DOC = os.path.join(ROOT, "doc")
PRM = os.path.join(ROOT, "prm", "cups")
VOCE = {"Material/Flow curve": "voce", "Material/Voce saturation stress": 330.2,
        "Material/Voce hardening amplitude": 190.0, "Material/Voce hardening rate": 12.4}
# (label, prm file, --set entries)
RUNS = [
    ("r-values", "earing-AA6016-r-values.prm", {}),
    ("yield stresses", "earing-AA6016-yield-stresses.prm", {}),
    ("planar isotropy", "earing-AA6016.prm", {}),
    ("r-values, holder 1150 N", "earing-AA6016-r-values.prm", {"Tools/Blank holder/Force": 1150}),
    ("r-values, holder 4600 N", "earing-AA6016-r-values.prm", {"Tools/Blank holder/Force": 4600}),
    ("r-values, holder fixed at 1.04 mm", "earing-AA6016-r-values.prm",
     {"Tools/Blank holder/Control": "gap", "Tools/Blank holder/Gap": 0.04}),
    ("r-values, mu = 0.1", "earing-AA6016-r-values.prm",
     {f"Tools/{t}/Friction coefficient": 0.1 for t in ("Punch", "Die", "Blank holder")}),
    ("r-values, Voce", "earing-AA6016-r-values.prm", VOCE),
    ("yield stresses, Voce", "earing-AA6016-yield-stresses.prm", VOCE),
    ("Yld2004-18p, team 1", "earing-AA6016-yld2004-team1.prm", {}),
    ("Yld2004-18p, team 2", "earing-AA6016-yld2004-team2.prm", {}),
    ("Yld2004-18p, fitted by formsolve", "earing-AA6016-yld2004-fit.prm", {}),
    ("Yld2004-18p, fitted by formsolve, 1 start", "earing-AA6016-yld2004-fit.prm",
     {"Material/Yld2004-18p fit/Starts": 1}),
    ("Yld2004-18p, team 1, holder 1150 N", "earing-AA6016-yld2004-team1.prm",
     {"Tools/Blank holder/Force": 1150}),
    ("Yld2004-18p, team 1, holder 4600 N", "earing-AA6016-yld2004-team1.prm",
     {"Tools/Blank holder/Force": 4600}),
    ("Yld2004-18p, team 1, mu = 0.07", "earing-AA6016-yld2004-team1.prm",
     {f"Tools/{t}/Friction coefficient": 0.07 for t in ("Punch", "Die", "Blank holder")}),
    ("Yld2004-18p, team 1, 3 layers", "earing-AA6016-yld2004-team1.prm",
     {"Mesh/Layers through thickness": 3}),
    ("Yld2004-18p, team 1, planform refinements 4", "earing-AA6016-yld2004-team1.prm",
     {"Mesh/Planform refinements": 4}),
]
SECTIONS = (0, 45, 90)


def slug(label):
    return re.sub(r"[^a-z0-9]+", "-", label.lower()).strip("-")


def run(label, prm, sets, force):
    out = os.path.join(OUT, slug(label))
    summary = os.path.join(out, "run-summary.txt")
    if force or not os.path.exists(summary):
        os.makedirs(out, exist_ok=True)
        sets = {**sets, "Output/Output directory": out, "Output/Output interval": 0,
                "Output/Report": "false"}
        cmd = ["mpirun", "-np", "2", EXE, os.path.join(PRM, prm)] + \
            sum((["--set", f"{k}={v}"] for k, v in sets.items()), [])
        with open(os.path.join(out, "log.txt"), "w") as log:
            if subprocess.call(cmd, stdout=log, stderr=subprocess.STDOUT, cwd=PRM) != 0:
                with open(summary, "w") as f:
                    f.write("end_reason = failed\n")
    return dict(l.rstrip("\n").split(" = ", 1) for l in open(summary) if " = " in l)


def profile(label):
    path = os.path.join(OUT, slug(label), "earing.csv")
    if not os.path.exists(path):
        return [], []
    rows = list(csv.DictReader(open(path)))
    return [float(r["angle_deg"]) for r in rows], [float(r["cup_height_mm"]) for r in rows]


def section(label, angle):
    """Columns of sheet.csv nearest the section at @angle (degrees from RD =
    x), by initial radius: (R0, height of the mid-surface above the cup
    bottom, thickness)."""
    path = os.path.join(OUT, slug(label), "sheet.csv")
    if not os.path.exists(path):
        return []
    cols = [{k: float(v) for k, v in r.items() if k != "zone_name"} for r in csv.DictReader(open(path))]
    near = min(abs(c["reference_angle"] - angle) for c in cols if c["reference_radius"] > 1)
    bottom = min(c["z"] for c in cols)
    pts = [(c["reference_radius"], c["z"] - bottom, c["thickness"]) for c in cols
           if abs(abs(c["reference_angle"] - angle) - near) < 1e-9 or c["reference_radius"] <= 1e-9]
    return sorted(pts)


def wall(label, angle):
    """Mean wall thickness of the section between 20 % and 80 % of the cup
    height, and the largest thickness above (the rim region)."""
    pts = section(label, angle)
    if not pts:
        return float("nan"), float("nan")
    top = max(p[1] for p in pts)
    w = [p[2] for p in pts if 0.2 * top <= p[1] <= 0.8 * top]
    return (sum(w) / len(w) if w else float("nan"), max(p[2] for p in pts if p[1] > 0.8 * top))


def write(results):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    lines = ["| run | ears | at (degrees from RD) | mean cup height (mm) | amplitude (mm) | peak punch force (kN) | "
             "wall thickness 0 / 45 / 90 (mm) | thickest near the rim 0 / 45 / 90 (mm) | end |",
             "|---|---|---|---|---|---|---|---|---|"]
    for label, s in results:
        walls = [wall(label, a) for a in SECTIONS]
        lines.append(
            f"| {label} | {s.get('ears', '')} | {s.get('ear_angles', '').strip() or '–'} | "
            f"{float(s.get('cup_height_mean', 'nan')):.2f} | {float(s.get('earing_amplitude', 'nan')):.3f} | "
            f"{float(s.get('peak_punch_force', 'nan')) / 1000:.1f} | "
            + " / ".join(f"{w[0]:.3f}" for w in walls) + " | " + " / ".join(f"{w[1]:.3f}" for w in walls)
            + f" | {s.get('end_reason', '').split(':')[0]} |")
    fig, ax = plt.subplots(figsize=(8, 4.5))
    for label, _ in results:
        a, h = profile(label)
        main = "," not in label or (label.startswith("Yld") and label.count(",") == 1)
        if a:
            ax.plot(a, h, label=label, lw=2 if main else 1, ls="-" if main else "--")
    ax.set_xlabel("angle to the rolling direction (degrees)")
    ax.set_ylabel("cup height (mm)")
    ax.set_xticks(range(0, 91, 15))
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, ncol=2)
    ax.set_title("Earing cup AA6016-T4, quarter model: cup height at the end of the draw")
    fig.tight_layout()
    fig.savefig(os.path.join(DOC, "earing-profiles.png"), dpi=110)
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.2), sharey=True)
    for ax, label in zip(axes, ("r-values", "yield stresses", "Yld2004-18p, team 1")):
        for a in SECTIONS:
            pts = section(label, a)
            ax.plot([p[1] for p in pts], [p[2] for p in pts], "o-", ms=2, label=f"{a} degrees")
        ax.set_title(label if label.startswith("Yld") else f"Hill48 from {label}")
        ax.set_xlabel("height of the mid-surface above the cup bottom (mm)")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    axes[0].set_ylabel("thickness (mm)")
    fig.tight_layout()
    fig.savefig(os.path.join(DOC, "earing-sections.png"), dpi=110)
    fr.write_block("earing", lines)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--force", action="store_true")
    ap.add_argument("--skip", default="", help="labels containing this are not run")
    a = ap.parse_args()
    results = [(label, run(label, prm, sets, a.force)) for label, prm, sets in RUNS
               if not (a.skip and a.skip in label)]
    write(results)


if __name__ == "__main__":
    main()

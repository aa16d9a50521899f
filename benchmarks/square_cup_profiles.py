"""Thickness strain of the square cup along the x axis, the y axis and the
diagonal at the travels of Output/Profile travels (sheet_<travel>mm.csv): one CSV per
line and travel, and one PNG per travel with both lines, for a run folder of
prm/square-cup-reference.prm (or its meshed variant).
    /usr/bin/python3 benchmarks/square_cup_profiles.py RUN_DIR [RUN_DIR2]
With a second folder its curves are drawn dashed over the first's (e.g.
meshed against analytic tools). The y axis is drawn for an anisotropic run
only (von Mises: it is the x axis mirrored). Columns: the reference (initial) distance
from the centre, the current one in the plane, thickness (mm), thickness
strain ln(t/t0)."""
import csv
import glob
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def lines(path):
    """{'x': rows, 'y': rows, 'diagonal': rows} of one sheet_<travel>mm.csv, sorted."""
    rows = list(csv.DictReader(open(path)))
    t0 = max(float(r["thickness"]) / (1 - float(r["thinning_percent"]) / 100)
             for r in rows if float(r["thinning_percent"]) != 100)
    out = {}
    for name, angle in (("x", 0.0), ("y", 90.0), ("diagonal", 45.0)):
        pick = [r for r in rows if abs(float(r["reference_angle"]) - angle) < 1e-6]
        pick.sort(key=lambda r: float(r["reference_radius"]))
        out[name] = [(float(r["reference_radius"]), float(r["r"]), float(r["thickness"]),
                      math.log(float(r["thickness"]) / t0)) for r in pick]
    return out


def isotropic(run):
    summary = os.path.join(run, "run-summary.txt")
    return "yield_criterion = von Mises" in open(summary).read()


def main():
    runs = sys.argv[1:]
    files = sorted(glob.glob(os.path.join(runs[0], "sheet_*mm.csv")))
    if not files:
        raise SystemExit(f"no sheet_<travel>mm.csv in {runs[0]} (Output/Profile travels)")
    for f in files:
        travel = re.search(r"sheet_(.*)mm\.csv", f).group(1)
        fig, ax = plt.subplots(figsize=(7, 4.2))
        for k, run in enumerate(runs):
            path = os.path.join(run, os.path.basename(f))
            if not os.path.exists(path):
                continue
            for name, rows in lines(path).items():
                out = os.path.join(run, f"thickness_strain_{name}_{travel}mm.csv")
                with open(out, "w") as o:
                    o.write("reference_distance_mm,current_distance_mm,thickness_mm,thickness_strain\n")
                    for r in rows:
                        o.write("%.6g,%.6g,%.6g,%.6g\n" % r)
                if name == "y" and isotropic(run):
                    continue
                ax.plot([r[0] for r in rows], [r[3] for r in rows],
                        "-" if k == 0 else "--", color={"x": "C0", "y": "C2", "diagonal": "C1"}[name],
                        label=f"{name} ({os.path.basename(os.path.normpath(run))})")
        ax.set_xlabel("initial distance from the centre along the line (mm)")
        ax.set_ylabel("thickness strain ln(t/t0)")
        ax.set_title(f"square cup at {travel} mm punch travel")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(runs[0], f"thickness_strain_{travel}mm.png"), dpi=110)
        print(f"{runs[0]}: thickness strain at {travel} mm written")


main()

"""Report of benchmarks/models.sh: the default cup drawn through as
axisymmetric, quarter and full models.

For every run in RESULTS (results/models/<name>/): wall time, DoFs, steps,
Newton iterations per step, cutbacks, peak punch force, holder release and
draw-through travel, from history.csv and run-summary.txt; the thickness
strain along the section at 20 mm of punch travel and at the end, from the
VTU files: the cells that touch the plane y = 0 (x > 0) in 3-D, all cells in
axisymmetry, grouped into columns through the thickness by their original
radius R0; per column the mean thickness strain and the mid-surface point,
whose cumulative distance from the axis is the arc length from the pole.
Minimum thickness t0 exp(min thickness strain). Writes DOC/models.csv,
DOC/models-force.png, DOC/models-thickness-strain.png and the tables between
the markers of DOC/models.md.

Usage: models_report.py RESULTS DOC"""
import csv, math, os, re, sys
import xml.etree.ElementTree as ET
import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import vtk
from vtk.util.numpy_support import vtk_to_numpy
from run_tables import steps  # noqa: E402

results, doc = sys.argv[1], sys.argv[2]
T0 = 0.78  # Geometry/Thickness of the default cup (mm)
ORDER = ["axisymmetric", "axisymmetric-6", "axisymmetric-7", "quarter-3", "quarter-4",
         "quarter-5", "quarter-refined", "full-3"]
LABEL = {"axisymmetric": "axisymmetric (shipped, 64 x 4)",
         "axisymmetric-6": "axisymmetric, 128 x 4", "axisymmetric-7": "axisymmetric, 256 x 4",
         "quarter-3": "quarter, uniform level 3", "quarter-4": "quarter, uniform level 4",
         "quarter-5": "quarter, uniform level 5", "quarter-refined": "quarter, refined at the radii (shipped)",
         "full-3": "full, uniform level 3"}
REFERENCE = "axisymmetric-7"


def summary(run):
    text = open(os.path.join(results, run, "run-summary.txt")).read().splitlines()
    return dict(l.split(" = ", 1) for l in text if " = " in l)


def history(run):
    return steps(os.path.join(results, run))


def section(vtu):
    """(R0, arc length, thickness strain) per column through the thickness."""
    reader = vtk.vtkXMLPUnstructuredGridReader()
    reader.SetFileName(vtu)
    reader.Update()
    grid = reader.GetOutput()
    points = vtk_to_numpy(grid.GetPoints().GetData()).astype(float)
    pdata = grid.GetPointData()
    disp = vtk_to_numpy(pdata.GetArray("displacement")).astype(float)
    eps = vtk_to_numpy(pdata.GetArray("thickness_strain")).astype(float)
    ncell = grid.GetNumberOfCells()
    conn = vtk_to_numpy(grid.GetCells().GetConnectivityArray()).reshape(ncell, -1)
    x = points[conn].mean(axis=1)
    ref = (points - disp)[conn]
    x0 = ref.mean(axis=1)
    e = eps[conn].mean(axis=1)
    if ref.shape[1] == 8:  # 3-D: the row of cells touching y = 0 on the x > 0 side
        ymin, ymax = ref[:, :, 1].min(axis=1), ref[:, :, 1].max(axis=1)
        keep = (ymin <= 1e-9) & (ymax >= -1e-9) & (x0[:, 0] > 0)
        r0 = np.hypot(x0[:, 0], x0[:, 1])[keep]
        mid = np.column_stack([np.hypot(x[:, 0], x[:, 1]), x[:, 2]])[keep]
        e = e[keep]
    else:  # axisymmetric section (r, z)
        r0 = x0[:, 0]
        mid = x[:, :2]
    # Columns: cells whose original radii agree to 1e-3 mm (the files are
    # float32, so x - u recovers R0 only to ~1e-5 mm; cells are >= 0.1 mm).
    order = np.argsort(r0)
    r0, mid, e = r0[order], mid[order], e[order]
    starts = np.concatenate([[0], np.nonzero(np.diff(r0) > 1e-3)[0] + 1, [len(r0)]])
    groups = [slice(a, b) for a, b in zip(starts[:-1], starts[1:])]
    R0 = np.array([r0[g].mean() for g in groups])
    mids = np.array([mid[g].mean(axis=0) for g in groups])
    strain = np.array([e[g].mean() for g in groups])
    s = np.concatenate([[mids[0, 0]], mids[0, 0] + np.cumsum(np.linalg.norm(np.diff(mids, axis=0), axis=1))])
    return R0, s, strain


def record_at(run, time):
    """The VTU of the .pvd record nearest to @p time (punch travel, mm)."""
    root = ET.parse(os.path.join(results, run, "solution.pvd")).getroot()
    records = [(float(d.get("timestep")), d.get("file")) for d in root.findall(".//DataSet")]
    t, f = min(records, key=lambda r: abs(r[0] - time)) if time is not None else records[-1]
    return t, os.path.join(results, run, f)


runs = [r for r in ORDER if os.path.exists(os.path.join(results, r, "run-summary.txt"))]
data = {}
for run in runs:
    s, h = summary(run), history(run)
    travel = np.array([float(r.get("force_travel", r["punch_travel"])) for r in h])
    force = np.array([float(r["punch_force"]) for r in h])
    i = int(force.argmax())
    t20, f20 = record_at(run, 20.0)
    tend, fend = record_at(run, None)
    data[run] = dict(summary=s, travel=travel, force=force, peak=force[i], peak_at=travel[i],
                     it=sum(float(r["newton_iterations"]) for r in h) / len(h),
                     at20=(t20,) + section(f20), end=(tend,) + section(fend))

ref = data.get(REFERENCE)
rows = []
for run in runs:
    d, s = data[run], data[run]["summary"]
    row = {"run": run, "model": s["model"], "ranks": s["ranks"], "dofs": int(float(s["dofs"])),
           "mean_dofs": int(float(s["mean_dofs"])), "steps": s["steps"],
           "newton_per_step": round(d["it"], 2), "cutbacks": s["cutbacks"],
           "wall_time_s": round(float(s["wall_time"]), 1),
           "peak_force_kN": round(d["peak"] / 1000, 3), "peak_at_mm": d["peak_at"],
           "release_mm": s["holder_release_travel"], "end_mm": s["final_punch_travel"]}
    for key in ("at20", "end"):
        t, R0, arc, strain = d[key]
        k = int(strain.argmin())
        row[f"min_thickness_{key}_mm"] = round(T0 * math.exp(strain[k]), 4)
        row[f"min_thickness_{key}_arc_mm"] = round(arc[k], 2)
        row[f"min_thickness_{key}_R0_mm"] = round(R0[k], 2)
        if ref is not None:
            _, Rr, _, er = ref[key]
            grid = R0[(R0 >= Rr.min()) & (R0 <= Rr.max())]
            row[f"strain_dev_{key}"] = round(float(np.abs(np.interp(grid, R0, strain) - np.interp(grid, Rr, er)).max()), 4)
    if ref is not None:
        row["peak_vs_reference_%"] = round(100 * (d["peak"] / ref["peak"] - 1), 2)
    rows.append(row)

with open(os.path.join(doc, "models.csv"), "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
    w.writeheader()
    w.writerows(rows)

fig, ax = plt.subplots(figsize=(8, 5))
for run in runs:
    ax.plot(data[run]["travel"], data[run]["force"] / 1000, label=LABEL[run],
            ls="-" if data[run]["summary"]["model"] == "axisymmetric" else "--")
ax.set_xlabel("punch travel (mm)")
ax.set_ylabel("punch force, full part (kN)")
ax.set_title("Default cup (d0 = 77 mm, material B, Siebel holder force), drawn through")
ax.grid(alpha=0.3)
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(os.path.join(doc, "models-force.png"), dpi=120)

fig, axes = plt.subplots(1, 2, figsize=(12, 4.5), sharey=True)
for ax, key in zip(axes, ("at20", "end")):
    for run in runs:
        t, R0, arc, strain = data[run][key]
        ax.plot(arc, strain, label=f"{LABEL[run]} ({t:.2f} mm)",
                ls="-" if data[run]["summary"]["model"] == "axisymmetric" else "--")
    ax.set_xlabel("arc length from the pole along the mid-surface (mm)")
    ax.set_title("punch travel 20 mm" if key == "at20" else "end of the draw")
    ax.grid(alpha=0.3)
axes[0].set_ylabel("thickness strain (through-thickness mean)")
axes[1].legend(fontsize=7)
fig.tight_layout()
fig.savefig(os.path.join(doc, "models-thickness-strain.png"), dpi=120)

# Tables for doc/models.md.
lines = ["| run | ranks | DoFs (max / mean) | steps | Newton it./step | cutbacks | wall (s) |"
         " peak punch force (kN) at (mm) | vs " + REFERENCE + " | holder released at (mm) | drawn through at (mm) |",
         "|---|---|---|---|---|---|---|---|---|---|---|"]
for r in rows:
    lines.append(f"| {LABEL[r['run']]} | {r['ranks']} | {r['dofs']} / {r['mean_dofs']} | {r['steps']} | "
                 f"{r['newton_per_step']} | {r['cutbacks']} | {r['wall_time_s']} | {r['peak_force_kN']} at "
                 f"{r['peak_at_mm']:.2f} | {r.get('peak_vs_reference_%', '')} % | {float(r['release_mm']):.2f} | "
                 f"{float(r['end_mm']):.2f} |")
lines += ["", "| run | min thickness at 20 mm (mm), arc length / R0 (mm) | max thickness-strain deviation from "
          + REFERENCE + " at 20 mm | min thickness at the end (mm), arc / R0 | deviation at the end |",
          "|---|---|---|---|---|"]
for r in rows:
    lines.append(f"| {LABEL[r['run']]} | {r['min_thickness_at20_mm']} at {r['min_thickness_at20_arc_mm']} / "
                 f"{r['min_thickness_at20_R0_mm']} | {r.get('strain_dev_at20', '')} | {r['min_thickness_end_mm']} at "
                 f"{r['min_thickness_end_arc_mm']} / {r['min_thickness_end_R0_mm']} | {r.get('strain_dev_end', '')} |")
table = "\n".join(lines)
path = os.path.join(doc, "models.md")
text = open(path).read() if os.path.exists(path) else "<!-- models:begin -->\n<!-- models:end -->\n"
text = re.sub(r"<!-- models:begin -->.*<!-- models:end -->",
              "<!-- models:begin -->\n" + table + "\n<!-- models:end -->", text, flags=re.S)
open(path, "w").write(text)
print(table)

"""Charts of benchmarks/refinement.sh: peak punch force against wall time and
DoFs, thickness strain along the cup, and the adapted mesh at mid-stroke.
Usage: /usr/bin/python3 benchmarks/refinement_chart.py RESULTS DOC"""
import csv, os, sys
import xml.etree.ElementTree as ET
import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.collections import PolyCollection
import vtk
from vtk.util.numpy_support import vtk_to_numpy
from run_tables import steps  # noqa: E402

res, doc = sys.argv[1], sys.argv[2]
names = [n for n in ["uniform-3", "uniform-4", "uniform-5", "adaptive", "adaptive-3-4layers", "adaptive-4-2layers"]
         if os.path.exists(os.path.join(res, n, "run-summary.txt"))]


def summary(name):
    """The numeric entries of run-summary.txt (text ones, e.g. model, are left out)."""
    d = {}
    for line in open(os.path.join(res, name, "run-summary.txt")):
        k, _, v = line.partition(" = ")
        try:
            d[k.strip()] = float(v)
        except ValueError:
            pass
    return d


def history(name):
    return [{k: float(v) for k, v in r.items()} for r in steps(os.path.join(res, name))]


def grid(name, step=None):
    sets = ET.parse(os.path.join(res, name, "solution.pvd")).getroot().findall(".//DataSet")
    d = sets[-1] if step is None else min(sets, key=lambda s: abs(float(s.get("timestep")) - step))
    r = vtk.vtkXMLPUnstructuredGridReader()
    r.SetFileName(os.path.join(res, name, d.get("file")))
    r.Update()
    return r.GetOutput(), float(d.get("timestep"))


def cell_centres(g):
    """Reference (undeformed) and current cell centres."""
    x = vtk_to_numpy(g.GetPoints().GetData())
    u = vtk_to_numpy(g.GetPointData().GetArray("displacement"))
    conn = vtk_to_numpy(g.GetCells().GetConnectivityArray()).reshape(-1, 8)
    return (x - u)[conn].mean(axis=1), x[conn].mean(axis=1), conn, x


def cell_field(g, name):
    """Cell values: deal.II writes them on each cell's own nodes."""
    conn = vtk_to_numpy(g.GetCells().GetConnectivityArray()).reshape(-1, 8)
    return vtk_to_numpy(g.GetPointData().GetArray(name))[conn].mean(axis=1)


def profile(name):
    """Thickness strain at the last step, mean per 1 mm of original radius."""
    g, _ = grid(name)
    ref_c, _, _, _ = cell_centres(g)
    eps = cell_field(g, "thickness_strain")
    r0 = np.hypot(ref_c[:, 0], ref_c[:, 1])
    bins = np.arange(0, 39.0, 1.0)
    idx = np.digitize(r0, bins)
    rc = np.array([0.5 * (bins[i - 1] + bins[i]) for i in range(1, len(bins))])
    ev = np.array([eps[idx == i].mean() if np.any(idx == i) else np.nan for i in range(1, len(bins))])
    return rc, ev


profiles = {n: profile(n) for n in names}
rows = []
ref = max(r["punch_force"] for r in history("uniform-5"))
for n in names:
    s, h = summary(n), history(n)
    peak = max(r["punch_force"] for r in h)
    rows.append(dict(run=n, max_dofs=s["dofs"], mean_dofs=s.get("mean_dofs", s["dofs"]), wall_time=s["wall_time"],
                     newton_iterations=s["newton_iterations"], peak_punch_force=peak,
                     error_vs_uniform5=(peak - ref) / ref, ranks=s["ranks"],
                     thickness_strain_max_deviation=float(np.nanmax(np.abs(profiles[n][1] - profiles["uniform-5"][1])))))
with open(os.path.join(doc, "refinement.csv"), "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=list(rows[0]))
    w.writeheader()
    w.writerows(rows)
for r in rows:
    print("%-10s dofs %7.0f (mean %7.0f)  wall %7.1f s  peak %8.1f N  error %+.2f %%  thickness strain dev %.4f" % (
        r["run"], r["max_dofs"], r["mean_dofs"], r["wall_time"], r["peak_punch_force"], 100 * r["error_vs_uniform5"],
        r["thickness_strain_max_deviation"]))

fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
for r in rows:
    c = "tab:green" if r["run"].startswith("adaptive") else "tab:gray"
    for a, key in ((ax[0], "wall_time"), (ax[1], "mean_dofs")):
        a.scatter(r[key], r["peak_punch_force"] / 1000, color=c, s=40)
        a.annotate(r["run"], (r[key], r["peak_punch_force"] / 1000), fontsize=8, xytext=(4, 4),
                   textcoords="offset points")
for a, lab in ((ax[0], "wall time (s, %d ranks)" % rows[0]["ranks"]), (ax[1], "DoFs (mean over the steps)")):
    a.set_xscale("log")
    a.set_xlabel(lab)
    a.set_ylabel("peak punch force (kN)")
    a.axhspan(ref / 1000 * 0.99, ref / 1000 * 1.01, color="tab:green", alpha=0.1, label="uniform-5 +- 1 %")
    a.grid(True, which="both", alpha=0.3)
ax[0].legend(fontsize=8)
fig.suptitle("Default cup: uniform meshes vs refinement near the radii", fontsize=10)
fig.tight_layout()
fig.savefig(os.path.join(doc, "refinement-accuracy.png"), dpi=130)

# Thickness strain along the cup (final step), cells binned by their original radius.
fig, ax = plt.subplots(figsize=(7, 4.2))
for n in names:
    rc, ev = profiles[n]
    ax.plot(rc, ev, "-", lw=2 if n.startswith("adaptive") else 1, label=n)
ax.set_xlabel("original radius of the material (mm)")
ax.set_ylabel("thickness strain (-), through-thickness mean")
ax.grid(True, alpha=0.3)
ax.legend(fontsize=8)
ax.set_title("Thickness strain at 15 mm punch travel", fontsize=10)
fig.tight_layout()
fig.savefig(os.path.join(doc, "refinement-thickness-strain.png"), dpi=130)

# Adapted mesh at mid-stroke: the faces on the symmetry plane y = 0.
g, t = grid("adaptive", step=7.5)
_, _, conn, x = cell_centres(g)
eps = cell_field(g, "equivalent_strain")
polys, vals = [], []
for c, cell in enumerate(conn):
    p = x[cell]
    on = np.abs(p[:, 1]) < 1e-6
    if on.sum() == 4:
        q = p[on][:, [0, 2]]
        ctr = q.mean(axis=0)
        order = np.argsort(np.arctan2(q[:, 1] - ctr[1], q[:, 0] - ctr[0]))
        polys.append(q[order])
        vals.append(eps[c])
fig, axes = plt.subplots(2, 1, figsize=(12, 7), gridspec_kw=dict(height_ratios=[1, 1.4]))
for ax, zoom in ((axes[0], None), (axes[1], (21, 33, -4, 1.5))):
    pc = PolyCollection(polys, array=np.array(vals), cmap="viridis", edgecolors="k", linewidths=0.3)
    ax.add_collection(pc)
    ax.autoscale()
    if zoom:
        ax.set_xlim(zoom[0], zoom[1])
        ax.set_ylim(zoom[2], zoom[3])
        ax.set_title("zoom on the die radius", fontsize=9)
    ax.set_aspect("equal")
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("z (mm)")
    fig.colorbar(pc, ax=ax, label="equivalent plastic strain")
axes[0].set_title("Adapted mesh at t = %.2f s (punch travel %.1f mm), section y = 0" % (t, t), fontsize=10)
fig.tight_layout()
fig.savefig(os.path.join(doc, "refinement-mesh.png"), dpi=130)

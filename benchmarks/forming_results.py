"""Predictions for the reference cup (`doc/reference-scenes.md` (section 1)),
axisymmetric model, blank holder at Siebel's force, mu = 0.1, Oyane's
criterion read through the thickness (Material/Fracture measure, the
default; the local maximum's stroke is reported beside it), Hill's normal
anisotropy (prm/materials); written into doc/forming-results.md between its markers, with
doc/forming-results-thickness.png and doc/forming-results-ldr.png.

1. The critical punch stroke of materials A, B, C with d0 = 80 mm, r_p = 2 mm
   and of A with d0 = 77 mm, r_p = 8 mm; where fracture starts and the
   thickness distribution at that moment (the runs stop at fracture).
2. How they move with the mesh (64, 128, 256 radial elements, 4 and 8
   layers) and the time step (0.25, 0.125, 0.0625 s).
3. The limiting drawing ratio: for each material and r_p in {2, 4, 8, 20}
   the largest d0 (1 mm steps, as in the experiments) that draws through
   before the criterion reaches 1, by bracketing and bisection.

Usage: forming_results.py [--jobs N] [--force] [--part predictions|ldr|all]
Runs are kept in results/forming/ and reused unless --force."""
import argparse, csv, math, os, re, subprocess, sys
from concurrent.futures import ThreadPoolExecutor

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.path.join(ROOT, "build", "formsolve")
OUT = os.path.join(ROOT, "results", "forming")
DOC = os.path.join(ROOT, "doc")
MATERIALS = {"A": (0.70, 748), "B": (0.78, 488), "C": (1.00, 672)}  # t0 (mm), R_m (MPa)
CASES = [("A", 80, 2), ("B", 80, 2), ("C", 80, 2), ("A", 77, 8)]
MESHES = [("64 x 4", 5, 4), ("128 x 4", 6, 4), ("256 x 4", 7, 4), ("128 x 8", 6, 8)]
STEPS = [0.25, 0.125, 0.0625]


def siebel(d0, t0, rm, dp=40.0, c=0.0025):
    """Blank-holder force (N): p = c [(beta - 1)^2 + d_p/(200 t0)] R_m on
    the initial flange under the holder, pi/4 (d0^2 - 58.5^2)."""
    p = c * ((d0 / dp - 1) ** 2 + dp / (200 * t0)) * rm
    return p * math.pi / 4 * (d0 ** 2 - 58.5 ** 2)


def run(name, material, d0, rp, refinements=5, layers=4, dt=0.25, force=False, extra=None, c=0.0025):
    """One axisymmetric draw, stopped at fracture or at draw-through; extra:
    further --set entries (path: value), c: Siebel's constant."""
    out = os.path.join(OUT, name)
    summary = os.path.join(out, "run-summary.txt")
    if force or not os.path.exists(summary):
        os.makedirs(out, exist_ok=True)
        prm = os.path.join(out, "case.prm")
        t0, rm = MATERIALS[material]
        with open(prm, "w") as f:
            f.write(f"include {ROOT}/prm/cup-drawing.prm\ninclude {ROOT}/prm/materials/{material}.prm\n")
        sets = {"Geometry/Blank diameter": d0, "Tools/Punch/Profile radius": rp,
                "Tools/Blank holder/Force": round(siebel(d0, t0, rm, c=c)), "Tools/Punch/Stroke": 60,
                "Mesh/Planform refinements": refinements, "Mesh/Layers through thickness": layers,
                "Time stepping/Time step": dt, "Split/Measures": "fracture criterion",
                "Split/Travel past the split": 0,
                "Output/Output interval": 0, "Output/Report": "false", "Output/Revolved copy": "false",
                "Output/Output directory": out, **(extra or {})}
        cmd = [EXE, prm] + sum((["--set", f"{k}={v}"] for k, v in sets.items()), [])
        with open(os.path.join(out, "log.txt"), "w") as log:
            code = subprocess.call(cmd, stdout=log, stderr=subprocess.STDOUT)
        if code != 0 and not os.path.exists(summary):
            with open(summary, "w") as f:  # a failed run is a result too
                f.write("end_reason = failed: " + open(os.path.join(out, "log.txt")).read().strip().splitlines()[-1] + "\n")
    return dict(l.rstrip("\n").split(" = ", 1) for l in open(summary) if " = " in l)


def outcome(s):
    reason = s.get("end_reason", "")
    if reason.startswith("drawn through"):
        return "drawn"
    if s.get("split_measure") == "fracture criterion":
        return "fracture"
    return "failed"


def predictions(jobs, force):
    runs = []
    for m, d0, rp in CASES:
        for label, ref, layers in MESHES:
            runs.append((f"{m}-d{d0}-rp{rp}-ref{ref}-l{layers}-dt0.25", m, d0, rp, ref, layers, 0.25))
        for dt in STEPS[1:]:
            runs.append((f"{m}-d{d0}-rp{rp}-ref6-l4-dt{dt}", m, d0, rp, 6, 4, dt))
    with ThreadPoolExecutor(jobs) as pool:
        results = list(pool.map(lambda r: (r, run(*r, force=force)), runs))
    return results


def ldr(jobs, force):
    """The largest d0 (mm, integer) that draws through, per (material, r_p)."""
    def search(material, rp):
        tried = {}
        def draws(d0):
            if d0 not in tried:
                tried[d0] = outcome(run(f"ldr-{material}-rp{rp}-d{d0}", material, d0, rp, force=force))
            return tried[d0] == "drawn"
        lo, hi = 60, None  # the holder must have flange under it: d0 > 58.5
        if not draws(lo):
            return None, tried
        d0 = lo
        while hi is None:
            d0 += 8
            if d0 > 130:
                return math.inf, tried
            if draws(d0):
                lo = d0
            else:
                hi = d0
        while hi - lo > 1:
            mid = (lo + hi) // 2
            if draws(mid):
                lo = mid
            else:
                hi = mid
        return lo, tried
    keys = [(m, rp) for m in MATERIALS for rp in (2, 4, 8, 20)]
    with ThreadPoolExecutor(jobs) as pool:
        found = dict(zip(keys, pool.map(lambda k: search(*k), keys)))
    return found


def fmt(x, d=2):
    try:
        return f"{float(x):.{d}f}"
    except ValueError:
        return str(x)


def write(pred, found):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    lines = []
    if pred:
        lines += ["### Critical strokes", "",
                  "| case | mesh (radial x layers) | time step (s) | critical stroke (mm), through-thickness average | fracture at (r, z) mm | critical stroke (mm), local maximum | min thickness (mm) at R0 (mm) | peak punch force (kN) | end |",
                  "|---|---|---|---|---|---|---|---|---|"]
        for (name, m, d0, rp, ref, layers, dt), s in pred:
            cs = float(s.get("critical_stroke_through_thickness", -1))
            cl = float(s.get("critical_stroke_local", -1))
            lines.append(f"| {m}, d0 = {d0}, r_p = {rp} | {2 ** (ref + 1)} x {layers} | {dt} | "
                         f"{fmt(cs) if cs >= 0 else 'none'} | {s.get('fracture_location_through_thickness', '')} | "
                         f"{fmt(cl) if cl >= 0 else 'none'} | "
                         f"{fmt(s.get('min_thickness', 'nan'), 4)} at {fmt(s.get('min_thickness_R0', 'nan'))} | "
                         f"{fmt(float(s.get('peak_punch_force', 'nan')) / 1000)} | {s.get('end_reason', '')} |")
        fig, ax = plt.subplots(figsize=(8, 4.5))
        for (name, m, d0, rp, ref, layers, dt), s in pred:
            if ref == 6 and layers == 4 and dt == 0.25:
                path = os.path.join(OUT, name, "sheet.csv")
                if os.path.exists(path):
                    cols = sorted(({k: float(v) for k, v in c.items() if k != "zone_name"} for c in csv.DictReader(open(path))),
                                  key=lambda c: c["reference_radius"])
                    s_arc, prev, pts = 0.0, None, []
                    for c in cols:
                        p = (c["r"], c["z"])
                        s_arc = p[0] if prev is None else s_arc + math.dist(p, prev)
                        prev = p
                        pts.append((s_arc, c["thickness"] / MATERIALS[m][0]))
                    ax.plot([p[0] for p in pts], [p[1] for p in pts],
                            label=f"{m}, d0 = {d0}, r_p = {rp} ({outcome(s)} at {fmt(s.get('final_punch_travel'))} mm)")
        ax.set_xlabel("arc length from the pole along the mid-surface (mm)")
        ax.set_ylabel("t / t0")
        ax.set_title("Thickness at fracture (or at the end of the draw), 128 x 4 elements")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(DOC, "forming-results-thickness.png"), dpi=120)
    if found:
        lines += ["", "### Limiting drawing ratio (d0 / 40 mm)", "",
                  "| material | r_p = 2 | r_p = 4 | r_p = 8 | r_p = 20 |", "|---|---|---|---|---|"]
        for m in MATERIALS:
            row = []
            for rp in (2, 4, 8, 20):
                d, tried = found[(m, rp)]
                fails = sorted(k for k, v in tried.items() if v != "drawn")
                note = "" if not any(tried[k] == "failed" for k in tried) else " (solver failures among the runs)"
                row.append("< 1.50 (d0 = 60 fails)" if d is None else
                           f"{d / 40:.3f} (d0 = {d}){note}")
            lines.append(f"| {m} | " + " | ".join(row) + " |")
        fig, ax = plt.subplots(figsize=(6, 4))
        for m in MATERIALS:
            pts = [(rp, found[(m, rp)][0] / 40) for rp in (2, 4, 8, 20) if found[(m, rp)][0] not in (None, math.inf)]
            ax.plot([p[0] for p in pts], [p[1] for p in pts], "o-", label=f"material {m}")
        ax.set_xlabel("punch profile radius r_p (mm)")
        ax.set_ylabel("limiting drawing ratio d0 / d_p")
        ax.grid(alpha=0.3)
        ax.legend()
        fig.tight_layout()
        fig.savefig(os.path.join(DOC, "forming-results-ldr.png"), dpi=120)
    write_block("forming", lines)


def write_block(marker, lines):
    """Replace what stands between <!-- marker:begin --> and <!-- marker:end -->
    in doc/forming-results.md by @lines, and print them."""
    path = os.path.join(DOC, "forming-results.md")
    text = open(path).read() if os.path.exists(path) else f"<!-- {marker}:begin -->\n<!-- {marker}:end -->\n"
    table = "\n".join(lines)
    text = re.sub(rf"<!-- {marker}:begin -->.*<!-- {marker}:end -->",
                  lambda _: f"<!-- {marker}:begin -->\n{table}\n<!-- {marker}:end -->", text, flags=re.S)
    open(path, "w").write(text)
    print(table)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--force", action="store_true")
    ap.add_argument("--part", default="all", choices=["predictions", "ldr", "all"])
    a = ap.parse_args()
    if not os.path.exists(EXE):
        subprocess.check_call(["bash", os.path.join(ROOT, "scripts", "build.sh")])
    pred = predictions(a.jobs, a.force) if a.part in ("predictions", "all") else []
    found = ldr(a.jobs, a.force) if a.part in ("ldr", "all") else {}
    write(pred, found)


if __name__ == "__main__":
    main()

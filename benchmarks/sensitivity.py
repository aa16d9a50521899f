"""How far each modelling choice the reference scene does not fix moves the
fracture prediction of the four reference cups (doc/forming-results.md,
"Sensitivity"): one choice at a time against the baseline of that page
(128 x 4 elements, Q1, dt = 0.25 s, Hill's normal anisotropy, L = M = N,
eps0 = 0.002, mu = 0.1, Siebel's c = 0.0025, limiting strain rate 1e-4/s,
the element pressure as sigma_m).

For each run: the critical stroke by both measures, and the peak over the
draw of the through-thickness column average of Oyane's I and of its local
maximum (the runs stop where the column average reaches 1, so its peak is
the margin to fracture of the cups that draw through).

Usage: sensitivity.py [--jobs N] [--force]; runs are kept in
results/forming/ and reused unless --force."""
import argparse, csv, os
from concurrent.futures import ThreadPoolExecutor

import forming_results as fr

FRICTION = ("Punch", "Die", "Blank holder")


def friction(mu):
    return {f"Tools/{t}/Friction coefficient": mu for t in FRICTION}


# (label, run-name suffix, keyword arguments of forming_results.run)
CHOICES = [
    ("baseline", "ref6-l4-dt0.25", {}),
    ("radial mesh x2 (256 x 4)", "ref7-l4-dt0.25", {"refinements": 7}),
    ("8 layers", "ref6-l8-dt0.25", {"layers": 8}),
    ("16 layers", "ref6-l16-dt0.25", {"layers": 16}),
    ("element degree 2", "ref6-l4-q2", {"extra": {"Mesh/Element degree": 2}}),
    ("time step / 2", "ref6-l4-dt0.125", {"dt": 0.125}),
    ("eps0 = 0.01", "eps0.01", {"extra": {"Material/Prestrain": 0.01}}),
    ("mu = 0.05", "mu0.05", {"extra": friction(0.05)}),
    ("mu = 0.15", "mu0.15", {"extra": friction(0.15)}),
    ("friction regularisation x10", "v0x10",
     {"extra": {"Contact/Friction regularisation velocity": 1e-2}}),
    ("Siebel c = 0.002", "c0.002", {"c": 0.002}),
    ("Siebel c = 0.003", "c0.003", {"c": 0.003}),
    ("von Mises instead of Hill", "vonmises", {"extra": {"Material/Yield criterion": "von Mises"}}),
    ("L = M = 3/2 (isotropic shear)", "LM1.5", {"extra": {"Material/Transverse shear": "isotropic"}}),
    ("limiting strain rate x10", "rc1e-3", {"extra": {"Material/Limiting strain rate": 1e-3}}),
    ("limiting strain rate / 10", "rc1e-5", {"extra": {"Material/Limiting strain rate": 1e-5}}),
    ("mean stress projected", "sm-projected", {"extra": {"Material/Fracture mean stress": "projected"}}),
]


def peaks(name):
    """Peak of the column average and of the local maximum of I over the run."""
    path = os.path.join(fr.OUT, name, "history.csv")
    if not os.path.exists(path):
        return float("nan"), float("nan")
    rows = list(csv.DictReader(open(path)))
    return (max(float(r["max_oyane_through_thickness"]) for r in rows),
            max(float(r["max_oyane"]) for r in rows))


def study(jobs, force):
    runs = []
    for m, d0, rp in fr.CASES:
        for label, suffix, kw in CHOICES:
            runs.append(((m, d0, rp), label, f"{m}-d{d0}-rp{rp}-{suffix}", kw))

    def one(r):
        case, label, name, kw = r
        s = fr.run(name, *case, force=force, **{"refinements": 6, **kw})
        return case, label, name, s, peaks(name)

    with ThreadPoolExecutor(jobs) as pool:
        return list(pool.map(one, runs))


def stroke(s, key):
    v = float(s.get(key, -1) or -1)
    return v if v >= 0 else None


def chart(case, rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    labels = [r[1] for r in rows]
    avg = [r[4][0] for r in rows]
    loc = [stroke(r[3], "critical_stroke_local") for r in rows]
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 5.5), sharey=True)
    y = range(len(rows))
    change = [v - avg[0] for v in avg]
    a1.barh(y, change, color=["C3" if v >= 1 else "C0" for v in avg])
    for i, (c, v) in enumerate(zip(change, avg)):
        a1.text(c, i, f" {v:.3f} " + ("(fracture)" if v >= 1 else ""), va="center",
                ha="left" if c >= 0 else "right", fontsize=7)
    a1.axvline(0, color="0.3", lw=1)
    a1.axvline(1 - avg[0], color="C3", lw=1.5, ls="--", label=f"I = 1 (baseline + {1 - avg[0]:.3f})")
    a1.set_xlabel(f"change of the peak column-average I from the baseline's {avg[0]:.3f}")
    a1.set_yticks(list(y))
    a1.set_yticklabels(labels, fontsize=8)
    a1.invert_yaxis()
    a1.legend(fontsize=8, loc="lower right")
    a1.grid(axis="x", alpha=0.3)
    lo = min(change + [0])
    a1.set_xlim(lo - 0.06, max(max(change), 1 - avg[0]) + 0.06)
    a2.barh(y, [v if v is not None else 0 for v in loc], color=["0.5"] + ["C1"] * (len(rows) - 1))
    for i, v in enumerate(loc):
        if v is None:
            a2.text(0.2, i, "local I stays < 1", va="center", fontsize=7)
    a2.set_xlabel("punch stroke where the local maximum of I reaches 1 (mm)")
    a2.grid(axis="x", alpha=0.3)
    m, d0, rp = case
    fig.suptitle(f"Sensitivity, material {m}, d0 = {d0} mm, r_p = {rp} mm (one choice at a time)")
    fig.tight_layout()
    name = f"sensitivity-{m}-d{d0}-rp{rp}.png"
    fig.savefig(os.path.join(fr.DOC, name), dpi=110)
    plt.close(fig)
    return name


def write(results):
    lines = []
    for case in fr.CASES:
        rows = [r for r in results if r[0] == case]
        m, d0, rp = case
        base = rows[0][4][0]
        lines += [f"### {m}, d0 = {d0}, r_p = {rp}", "",
                  "| choice | peak column-average I | change | critical stroke, column average (mm) | peak local I | critical stroke, local (mm) | peak punch force (kN) | end |",
                  "|---|---|---|---|---|---|---|---|"]
        for _, label, name, s, (pa, pl) in rows:
            ct = stroke(s, "critical_stroke_through_thickness")
            cl = stroke(s, "critical_stroke_local")
            end = s.get("end_reason", "").split(":")[0]
            lines.append(f"| {label} | {pa:.3f} | {pa - base:+.3f} | {fr.fmt(ct) if ct else 'none'} | {pl:.3f} | "
                         f"{fr.fmt(cl) if cl else 'none'} | {fr.fmt(float(s.get('peak_punch_force', 'nan')) / 1000)} | {end} |")
        lines += ["", f"![sensitivity {m} d{d0} rp{rp}]({chart(case, rows)})", ""]
    fr.write_block("sensitivity", lines)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--force", action="store_true")
    a = ap.parse_args()
    write(study(a.jobs, a.force))


if __name__ == "__main__":
    main()

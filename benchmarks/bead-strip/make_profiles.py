"""The tools of the strip drawn through a round draw bead (plane-strain x-z
section, mm; README.md of this folder): the die up to x = 80, where its face
steps down, and the groove tool from x = 80 on, whose face steps down there
too: a seam, so that a node on the sheet meets one face or the other, never
the end of a face (an open end in mid-face pushes sideways) nor two
overlapping faces (which clamp the strip twice under a fixed holder) (two shoulders of radius R_s, the groove R_b + t0 wide on
each side of the bead's axis, the tightest groove of doc/theory.md 6b), and
the holder, flat on the strip with a slot at x = 100 for the bead: an
insert that a cap of radius R_b ends, which closes h into the groove while the
holder keeps the strip flat on both sides (a strip bent over the groove with
free ends would turn about the shoulders: a mechanism of a rigid-plastic
sheet).
The equivalent bead's run has the same die and holder without groove and
slot (die-flat.csv, holder-flat.csv): the two runs differ in the bead alone.
    /usr/bin/python3 make_profiles.py   (writes die.csv, groove.csv,
                                         holder.csv, bead.csv, die-flat.csv,
                                         holder-flat.csv)"""
import math

T0, RB, RS, H, XB = 0.78, 4.0, 4.0, 3.0, 100.0


def arc(cx, cz, r, a0, a1, n=24):
    return [(cx + r * math.cos(math.radians(a0 + (a1 - a0) * i / n)),
             cz + r * math.sin(math.radians(a0 + (a1 - a0) * i / n))) for i in range(n + 1)]


def write(name, points):
    with open(name, "w") as f:
        for x, z in points:
            f.write(f"{x:.9g}, {z:.9g}\n")


# The die: its opening wall at x = 36, radius 5 mm, flat to x = 80.
write("die.csv", [(36, -40)] + arc(41, -5, 5, 180, 90) + [(80, 0), (80, -10)])
write("die-flat.csv", [(36, -40)] + arc(41, -5, 5, 180, 90) + [(200, 0)])
# The groove: shoulder centres R_s + R_b + t0 from the bead's axis.
a = RS + RB + T0
groove = [(80, -10), (80, 0)] + arc(XB - a, -RS, RS, 90, 0)
groove += [(XB - a + RS, -12), (XB + a - RS, -12)]
groove += arc(XB + a, -RS, RS, 180, 90) + [(200, 0)]
write("groove.csv", groove)
# The holder: an edge fillet of 2 mm at x = 41, its face on the sheet
# (z = t0), a slot 8 mm wide for the insert.
holder = arc(43, T0 + 2, 2, 180, 270, 12)
holder += [(XB - 4, T0), (XB - 4, T0 + 5), (XB + 4, T0 + 5), (XB + 4, T0), (200, T0), (200, T0 + 4)]
write("holder.csv", holder)
write("holder-flat.csv", arc(43, T0 + 2, 2, 180, 270, 12) + [(200, T0), (200, T0 + 4)])
# The insert, closed: a cap of radius R_b reaching h below the holder's face.
half = math.degrees(math.asin((RB - H) / RB))
foot = math.sqrt(RB * RB - (RB - H) ** 2)
bead = [(XB - foot, T0 + 8)] + arc(XB, T0 + RB - H, RB, 180 + half, 360 - half, 48)
bead += [(XB + foot, T0 + 8)]
write("bead.csv", bead)

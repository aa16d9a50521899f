"""The CalculiX deck of the U-channel of prm/channel.prm, for the comparison
of issue 63 section 5 (not done yet; doc/plane-strain.md, Limits).

Plane strain, the half model x >= 0 (CalculiX's x-y plane: y is formsolve's
z), the strip as NX x NY CPE8R elements with the section width 35 mm, von
Mises with the channel's Swift curve on the plastic strain and E = 206 GPa,
nu = 0.3; the tools as bands of CPE4 elements whose every node is
prescribed (punch moving, die and holder standing: the holder at a fixed
gap 0, formsolve's `Tools/Blank holder/Control = gap`), surface-to-surface
penalty contact (slope K) with Coulomb friction 0.144; the punch force is
the sum of its nodes' reactions (the half model's: twice it for the part).
With --springback a last step removes the contact pairs and holds the
strip's centre.

What CalculiX 2.20 does with it (6 December 2026):
- *RIGID BODY reference nodes report RF = 0, hence the prescribed tool
  nodes; at a zero initial gap the contact opens and the strip floats (no
  convergence), hence the tools overlap it by EPS = 1e-8 mm; K = 1e6 N/mm^3
  diverges at the first increment, K = 1e4 runs.
- 256 x 2 elements stop converging at 4.46 mm (increments cut to 2e-4 of
  the stroke); at 4 mm the punch force is 2 x 482 N and the holder's 2 x
  770 N, where formsolve's 256 x 4 Q1 section under the same settings
  (`build/formsolve prm/channel.prm --set "Tools/Blank holder/Control=gap"
  --set "Material/Yield criterion=von Mises"`) gives 1414 N and 4417 N.
  64 x 2 elements reach 5 mm (2 x 1435 N against formsolve's 1558 N). The
  springback step diverges. Not a comparison yet.
- --holder-force (the holder held in x and tied in z to one node carrying
  9.8 kN, the half of formsolve's `Control = force`, as the cup's deck
  does; 7 December 2026, 128 x 2): with the stick slope LAM = 1e4 N/mm^3
  every increment takes 55-60 iterations from the first on; with LAM=1e3
  the draw reaches 0.44 mm and then cuts its increment without converging.
- --holder-force --clamp (a first step presses the holder with the punch
  standing; LAM=1e3): 128 x 2 elements reach 10.75 mm, 256 x 2 8.75 mm,
  then the increments are cut to 2e-5 of the stroke and the residual
  grows to 1e12 N at nodes between punch and die.

Usage: [LAM=slope] channel_deck.py NX NY STROKE OUT.inp [--springback]
       [--holder-force [--clamp]]; ccx -i OUT
"""
import math
import os
import sys

import deck

T, L, B = 0.78, 175.0, 35.0        # thickness, half length, width (mm)
NX = int(sys.argv[1]) if len(sys.argv) > 1 else 256
NY = int(sys.argv[2]) if len(sys.argv) > 2 else 2
STROKE = float(sys.argv[3]) if len(sys.argv) > 3 else 50.0
MU, K = 0.144, 1.0e4
LAM = float(os.environ.get("LAM", "1e4"))   # the friction's stick slope
HOLDER_FORCE = "--holder-force" in sys.argv
E, NU = 206000.0, 0.3
out = []


def node_id(i, j):
    return deck.node_id(NX, i, j)


out += ["*HEADING", "U-channel, plane strain half model (formsolve prm/channel.prm)", "*NODE, NSET=SHEETN"]
sheet = deck.sheet(NX, NY, L, T, out)
eid = len(sheet)
line, arc, chain = deck.line, deck.arc, deck.chain

# Tool profiles (x, y = formsolve's z), each with a point inside the tool.
# The tools overlap the sheet by EPS so that contact is closed from the
# start (at a zero gap it opens, and the sheet floats): 0.01 MPa at K.
EPS = 1e-8
tools = {
    "PUNCH": (chain(line((0, T - EPS), (30, T - EPS), 60), arc(30, T + 5 - EPS, 5, -math.pi / 2, 0, 40),
                    line((35, T + 5 - EPS), (35, T + 70), 50)), (10, T + 20)),
    "DIE": (chain(line((200, EPS), (41, EPS), 200), arc(41, -5 + EPS, 5, math.pi / 2, math.pi, 40),
                  line((36, -5 + EPS), (36, -70), 50)), (60, -20)),
    "HOLDER": (line((41, T - EPS), (200, T - EPS), 200), (60, T + 20)),
}
tool_elems, tool_faces, ref = deck.tool_bands(tools, eid, out)

HM = ref["HOLDER"][0]
deck.elements_and_sets(out, sheet, "CPE8R", tool_elems, "CPE4", ref)
out += ["*NSET, NSET=SYMM"] + [str(node_id(0, j)) for j in range(2 * NY + 1)]
out += ["*NSET, NSET=MID"] + [str(node_id(i, NY)) for i in range(2 * NX + 1)]
out += ["*NSET, NSET=CENTRE", str(node_id(0, NY))]
deck.surfaces(out, sheet, NX, tool_faces)

# Material: the channel's Swift curve on plastic strain (von Mises).
out += ["*MATERIAL, NAME=STEEL", "*ELASTIC", f"{E}, {NU}", "*PLASTIC"]
deck.swift_table(out, 565.32, 0.007117, 0.2589)
out += ["*MATERIAL, NAME=RIGID", "*ELASTIC", "210000, 0.3"]
out += ["*SOLID SECTION, ELSET=SHEET, MATERIAL=STEEL", f"{B}"]
for name in tools:
    out += [f"*SOLID SECTION, ELSET={name}, MATERIAL=RIGID", f"{B}"]

if HOLDER_FORCE:
    deck.tie_in_y(out, ref["HOLDER"])
out += ["*SURFACE INTERACTION, NAME=TOOLS", "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR",
        f"{K}, 1e-3, 1e-3", "*FRICTION", f"{MU}, {LAM}"]
for slave, master in [("SHEETTOP", "PUNCHS"), ("SHEETBOT", "DIES"), ("SHEETTOP", "HOLDERS")]:
    out += [f"*CONTACT PAIR, INTERACTION=TOOLS, TYPE=SURFACE TO SURFACE", f"{slave}, {master}"]

# Die and holder (at the fixed gap 0) stand, the punch moves: every tool
# node is prescribed (the tools are rigid); the punch force is the sum of
# its nodes' reactions.
out += ["*BOUNDARY", "SYMM, 1, 1", "DIEN, 1, 2", "HOLDERN, 1, 1" if HOLDER_FORCE else "HOLDERN, 1, 2",
        "PUNCHN, 1, 1"]
holder_load = ["*CLOAD", f"{HM}, 2, -9800."] if HOLDER_FORCE else []
holder_hold = [f"{HM}, 2, 2", "*CLOAD, OP=NEW", f"{HM}, 2, 0."] if HOLDER_FORCE else []
# With --clamp a first step presses the holder, the punch standing.
if HOLDER_FORCE and "--clamp" in sys.argv:
    out += ["*STEP, NLGEOM, INC=1000", "*STATIC", "0.1, 1.0, 1e-6, 0.5", *holder_load, "*END STEP"]
# Step 2: the draw.
out += ["*STEP, NLGEOM, INC=100000", "*STATIC", f"{0.05 / STROKE}, 1.0, 1e-7, {0.25 / STROKE}",
        "*BOUNDARY", f"PUNCHN, 2, 2, {-STROKE}", *holder_load,
        "*NODE PRINT, NSET=PUNCHN, TOTALS=ONLY", "RF",
        "*NODE PRINT, NSET=HOLDERN, TOTALS=ONLY", "RF",
        "*NODE PRINT, NSET=MID", "U", "*NODE FILE", "U", "*EL FILE", "S, PEEQ", "*END STEP"]
# Step 3: springback: the tools let go; the centre holds the rigid motion.
if "--springback" in sys.argv:
  out += ["*STEP, NLGEOM, INC=1000", "*STATIC", "0.1, 1.0, 1e-6, 0.25",
        "*MODEL CHANGE, TYPE=CONTACT PAIR, REMOVE", "SHEETTOP, PUNCHS", "SHEETBOT, DIES", "SHEETTOP, HOLDERS",
        "*BOUNDARY, FIXED", "CENTRE, 2, 2", *holder_hold,
        "*NODE PRINT, NSET=MID", "U", "*NODE FILE", "U", "*EL FILE", "S, PEEQ", "*END STEP"]
open(sys.argv[4] if len(sys.argv) > 4 else "channel.inp", "w").write("\n".join(out) + "\n")

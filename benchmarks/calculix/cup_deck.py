"""The CalculiX deck of the cup of prm/cup-drawing.prm drawn 20 mm and
released, for the comparison of issue 63 section 5 (doc/calculix.md).

Axisymmetric (CalculiX's x = r, y = formsolve's z), the blank (r 38.5 mm,
t 0.78 mm, z from 0 to t) as NX x NY CAX8R elements; von Mises with the
cup's Swift curve on the plastic strain, E = 210 GPa, nu = 0.3 (the split
ring's prm/cup-split-ring.prm); the tools as bands of CAX4 elements whose
nodes are prescribed (punch moving 20 mm, die standing) or, for the
holder, held in r and tied in z to one node that carries the holder force
(2671 N); surface-to-surface penalty contact (slope K) with Coulomb
friction 0.1. The tools overlap the sheet by EPS so that contact is closed
from the start (at a zero gap it opens and the sheet floats). With
--springback a second step removes the contact pairs, holds the holder and
the sheet's centre in z and releases the sheet.

CalculiX gives forces of axisymmetric elements for a 2 degree segment: the
punch force is 180 times the sum of its nodes' reactions.

Usage: cup_deck.py NX NY STROKE OUT.inp [--springback]; ccx -i OUT
"""
import math
import sys

import deck

T, R0 = 0.78, 38.5
NX, NY, STROKE, OUT = int(sys.argv[1]), int(sys.argv[2]), float(sys.argv[3]), sys.argv[4]
SPRING = "--springback" in sys.argv
MU, K, LAM = 0.1, 1.0e4, 1.0e4
E, NU = 210000.0, 0.3
HOLDER_F = 2671.0
RP, RPR, RD, RDR, RH = 20.0, 8.0, 21.25, 8.0, 29.25
out = []

def node_id(i, j):
    return deck.node_id(NX, i, j)


out += ["*HEADING", "cup, axisymmetric (formsolve prm/cup-drawing.prm)", "*NODE, NSET=SHEETN"]
sheet = deck.sheet(NX, NY, R0, T, out)
eid = len(sheet)
line, arc, chain = deck.line, deck.arc, deck.chain

EPS = 1e-8
tools = {
    "PUNCH": (chain(line((0, T - EPS), (RP - RPR, T - EPS), 48), arc(RP - RPR, T + RPR - EPS, RPR, -math.pi / 2, 0, 64),
                    line((RP, T + RPR - EPS), (RP, T + 60), 60)), (5, T + 20)),
    "DIE": (chain(line((50, EPS), (RD + RDR, EPS), 80), arc(RD + RDR, -RDR + EPS, RDR, math.pi / 2, math.pi, 64),
                  line((RD, -RDR + EPS), (RD, -60), 60)), (40, -20)),
    "HOLDER": (line((RH, T - EPS), (50, T - EPS), 80), (40, T + 20)),
}
tool_elems, tool_faces, ref = deck.tool_bands(tools, eid, out)

deck.elements_and_sets(out, sheet, "CAX8R", tool_elems, "CAX4", ref)
out += ["*NSET, NSET=SYMM"] + [str(node_id(0, j)) for j in range(2 * NY + 1)]
out += ["*NSET, NSET=BOTN"] + [str(node_id(i, 0)) for i in range(2 * NX + 1)]
out += ["*NSET, NSET=TOPN"] + [str(node_id(i, 2 * NY)) for i in range(2 * NX + 1)]
out += ["*NSET, NSET=HM", str(ref["HOLDER"][0])]
deck.surfaces(out, sheet, NX, tool_faces)
out += ["*MATERIAL, NAME=STEEL", "*ELASTIC", f"{E}, {NU}", "*PLASTIC"]
deck.swift_table(out, 829.0, 0.002, 0.2)
out += ["*MATERIAL, NAME=RIGID", "*ELASTIC", "210000, 0.3"]
out += ["*SOLID SECTION, ELSET=SHEET, MATERIAL=STEEL"]
for name in tools:
    out += [f"*SOLID SECTION, ELSET={name}, MATERIAL=RIGID"]
HM = ref["HOLDER"][0]
deck.tie_in_y(out, ref["HOLDER"])
out += ["*SURFACE INTERACTION, NAME=TOOLS", "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR",
        f"{K}, 1e-3, 1e-3", "*FRICTION", f"{MU}, {LAM}"]
for slave, master in [("SHEETTOP", "PUNCHS"), ("SHEETBOT", "DIES"), ("SHEETTOP", "HOLDERS")]:
    out += ["*CONTACT PAIR, INTERACTION=TOOLS, TYPE=SURFACE TO SURFACE", f"{slave}, {master}"]
out += ["*BOUNDARY", "SYMM, 1, 1", "DIEN, 1, 2", "PUNCHN, 1, 1", "HOLDERN, 1, 1"]
out += ["*STEP, NLGEOM, INC=100000", "*STATIC", f"{0.02 / STROKE}, 1.0, 1e-8, {0.1 / STROKE}",
        "*BOUNDARY", f"PUNCHN, 2, 2, {-STROKE}", "*CLOAD", f"{HM}, 2, {-HOLDER_F / 180:.8g}",
        "*NODE PRINT, NSET=PUNCHN, TOTALS=ONLY", "RF", "*NODE PRINT, NSET=HM", "U",
        "*NODE PRINT, NSET=BOTN, FREQUENCY=100000", "U", "*NODE PRINT, NSET=TOPN, FREQUENCY=100000", "U", "*NODE PRINT, NSET=SHEETN, FREQUENCY=100000", "U",
        "*EL PRINT, ELSET=SHEET, FREQUENCY=100000", "S, PEEQ, COORD",
        "*NODE FILE, FREQUENCY=20", "U", "*EL FILE, FREQUENCY=20", "S, PEEQ", "*END STEP"]
if SPRING:
    out += ["*STEP, NLGEOM, INC=1000", "*STATIC", "0.1, 1.0, 1e-6, 0.25",
            "*MODEL CHANGE, TYPE=CONTACT PAIR, REMOVE", "SHEETTOP, PUNCHS", "SHEETBOT, DIES", "SHEETTOP, HOLDERS",
            "*BOUNDARY, FIXED", f"{node_id(0, 0)}, 2, 2", f"{HM}, 2, 2", "*CLOAD, OP=NEW", f"{HM}, 2, 0.",
            "*NODE PRINT, NSET=BOTN", "U", "*NODE PRINT, NSET=TOPN", "U", "*NODE PRINT, NSET=SHEETN", "U",
            "*EL PRINT, ELSET=SHEET", "S, PEEQ, COORD", "*NODE FILE", "U", "*EL FILE", "S, PEEQ", "*END STEP"]
open(OUT, "w").write("\n".join(out) + "\n")

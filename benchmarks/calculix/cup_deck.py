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

T, R0 = 0.78, 38.5
NX, NY, STROKE, OUT = int(sys.argv[1]), int(sys.argv[2]), float(sys.argv[3]), sys.argv[4]
SPRING = "--springback" in sys.argv
MU, K, LAM = 0.1, 1.0e4, 1.0e4
E, NU = 210000.0, 0.3
HOLDER_F = 2671.0
RP, RPR, RD, RDR, RH = 20.0, 8.0, 21.25, 8.0, 29.25
out = []

def node_id(i, j):
    return 1 + j * (2 * NX + 1) + i

out += ["*HEADING", "cup, axisymmetric (formsolve prm/cup-drawing.prm)", "*NODE, NSET=SHEETN"]
for j in range(2 * NY + 1):
    for i in range(2 * NX + 1):
        if i % 2 == 0 or j % 2 == 0:
            out.append(f"{node_id(i, j)}, {R0 * i / (2 * NX):.10g}, {T * j / (2 * NY):.10g}")
sheet = []
for jj in range(NY):
    for ii in range(NX):
        i, j = 2 * ii, 2 * jj
        sheet.append((1 + jj * NX + ii, [node_id(i, j), node_id(i + 2, j), node_id(i + 2, j + 2), node_id(i, j + 2),
                                          node_id(i + 1, j), node_id(i + 2, j + 1), node_id(i + 1, j + 2),
                                          node_id(i, j + 1)]))
eid = len(sheet)

def line(a, b, n):
    return [(a[0] + (b[0] - a[0]) * k / n, a[1] + (b[1] - a[1]) * k / n) for k in range(n + 1)]

def arc(cx, cy, r, a0, a1, n):
    return [(cx + r * math.cos(a0 + (a1 - a0) * k / n), cy + r * math.sin(a0 + (a1 - a0) * k / n)) for k in range(n + 1)]

def chain(*pieces):
    pts = []
    for p in pieces:
        for q in p:
            if not pts or math.dist(pts[-1], q) > 1e-9:
                pts.append(q)
    return pts

EPS = 1e-8
tools = {
    "PUNCH": (chain(line((0, T - EPS), (RP - RPR, T - EPS), 48), arc(RP - RPR, T + RPR - EPS, RPR, -math.pi / 2, 0, 64),
                    line((RP, T + RPR - EPS), (RP, T + 60), 60)), (5, T + 20)),
    "DIE": (chain(line((50, EPS), (RD + RDR, EPS), 80), arc(RD + RDR, -RDR + EPS, RDR, math.pi / 2, math.pi, 64),
                  line((RD, -RDR + EPS), (RD, -60), 60)), (40, -20)),
    "HOLDER": (line((RH, T - EPS), (50, T - EPS), 80), (40, T + 20)),
}
next_node = 100000
tool_elems, tool_faces, ref = {}, {}, {}
for name, (prof, inside) in tools.items():
    a, b = [], []
    for k, p in enumerate(prof):
        q0, q1 = prof[max(k - 1, 0)], prof[min(k + 1, len(prof) - 1)]
        tx, ty = q1[0] - q0[0], q1[1] - q0[1]
        le = math.hypot(tx, ty)
        nx, ny = -ty / le, tx / le
        if (inside[0] - p[0]) * nx + (inside[1] - p[1]) * ny < 0:
            nx, ny = -nx, -ny
        next_node += 1
        a.append(next_node)
        out.append(f"{next_node}, {p[0]:.10g}, {p[1]:.10g}")
        next_node += 1
        b.append(next_node)
        out.append(f"{next_node}, {p[0] + nx:.10g}, {p[1] + ny:.10g}")
    els, faces = [], []
    for k in range(len(prof) - 1):
        eid += 1
        pa, pb = prof[k], prof[k + 1]
        d = (pb[0] - pa[0], pb[1] - pa[1])
        n = (inside[0] - pa[0], inside[1] - pa[1])
        if d[0] * n[1] - d[1] * n[0] > 0:
            els.append((eid, [a[k], a[k + 1], b[k + 1], b[k]]))
            faces.append((eid, "S1"))
        else:
            els.append((eid, [a[k], b[k], b[k + 1], a[k + 1]]))
            faces.append((eid, "S4"))
    tool_elems[name], tool_faces[name] = els, faces
    ref[name] = a + b

out.append("*ELEMENT, TYPE=CAX8R, ELSET=SHEET")
out += [f"{e}, " + ", ".join(map(str, n)) for e, n in sheet]
for name, els in tool_elems.items():
    out.append(f"*ELEMENT, TYPE=CAX4, ELSET={name}")
    out += [f"{e}, " + ", ".join(map(str, n)) for e, n in els]
for name in tools:
    out += [f"*NSET, NSET={name}N"] + [str(n) for n in ref[name]]
out += ["*NSET, NSET=SYMM"] + [str(node_id(0, j)) for j in range(2 * NY + 1)]
out += ["*NSET, NSET=BOTN"] + [str(node_id(i, 0)) for i in range(2 * NX + 1)]
out += ["*NSET, NSET=TOPN"] + [str(node_id(i, 2 * NY)) for i in range(2 * NX + 1)]
out += ["*NSET, NSET=HM", str(ref["HOLDER"][0])]
out += ["*SURFACE, NAME=SHEETTOP"] + [f"{e}, S3" for e, _ in sheet[-NX:]]
out += ["*SURFACE, NAME=SHEETBOT"] + [f"{e}, S1" for e, _ in sheet[:NX]]
for name, faces in tool_faces.items():
    out += [f"*SURFACE, NAME={name}S"] + [f"{e}, {f}" for e, f in faces]
out += ["*MATERIAL, NAME=STEEL", "*ELASTIC", f"{E}, {NU}", "*PLASTIC"]
for k in range(41):
    ep = 0 if k == 0 else 10 ** (-4 + 4.3 * (k - 1) / 39)
    out.append(f"{829.0 * (0.002 + ep) ** 0.2:.6f}, {ep:.6g}")
out += ["*MATERIAL, NAME=RIGID", "*ELASTIC", "210000, 0.3"]
out += ["*SOLID SECTION, ELSET=SHEET, MATERIAL=STEEL"]
for name in tools:
    out += [f"*SOLID SECTION, ELSET={name}, MATERIAL=RIGID"]
HM = ref["HOLDER"][0]
out += ["*EQUATION"]
for n in ref["HOLDER"][1:]:
    out += ["2", f"{n}, 2, 1., {HM}, 2, -1."]
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

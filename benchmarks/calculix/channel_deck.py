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
    return 1 + j * (2 * NX + 1) + i


out += ["*HEADING", "U-channel, plane strain half model (formsolve prm/channel.prm)", "*NODE, NSET=SHEETN"]
for j in range(2 * NY + 1):
    for i in range(2 * NX + 1):
        if i % 2 == 0 or j % 2 == 0:
            out.append(f"{node_id(i, j)}, {L * i / (2 * NX):.10g}, {T * j / (2 * NY):.10g}")
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
    return [(cx + r * math.cos(a0 + (a1 - a0) * k / n), cy + r * math.sin(a0 + (a1 - a0) * k / n))
            for k in range(n + 1)]


def chain(*pieces):
    pts = []
    for p in pieces:
        for q in p:
            if not pts or math.dist(pts[-1], q) > 1e-9:
                pts.append(q)
    return pts


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
next_node = 100000
tool_elems, tool_faces, ref = {}, {}, {}
for name, (prof, inside) in tools.items():
    a, b = [], []
    for k, p in enumerate(prof):
        q0, q1 = prof[max(k - 1, 0)], prof[min(k + 1, len(prof) - 1)]
        tx, ty = q1[0] - q0[0], q1[1] - q0[1]
        le = math.hypot(tx, ty)
        nx, ny = -ty / le, tx / le
        # into the tool: towards its inside point for a flat, by continuity otherwise
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
        q = [a[k], a[k + 1], b[k + 1], b[k]]
        pa, pb = prof[k], prof[k + 1]
        # signed area of (a_k, a_k+1, b_k+1): positive keeps the order
        xs = {a[k]: pa, a[k + 1]: pb}
        d = (pb[0] - pa[0], pb[1] - pa[1])
        # b_k+1 = pb + n; area sign = cross(d, n)
        n = (inside[0] - pa[0], inside[1] - pa[1])
        if d[0] * n[1] - d[1] * n[0] > 0:
            els.append((eid, q))
            faces.append((eid, "S1"))
        else:
            els.append((eid, [a[k], b[k], b[k + 1], a[k + 1]]))
            faces.append((eid, "S4"))
    tool_elems[name], tool_faces[name] = els, faces
    ref[name] = a + b

HM = ref["HOLDER"][0]
out.append("*ELEMENT, TYPE=CPE8R, ELSET=SHEET")
out += [f"{e}, " + ", ".join(map(str, n)) for e, n in sheet]
for name, els in tool_elems.items():
    out.append(f"*ELEMENT, TYPE=CPE4, ELSET={name}")
    out += [f"{e}, " + ", ".join(map(str, n)) for e, n in els]
for name in tools:
    out += [f"*NSET, NSET={name}N"] + [str(n) for n in ref[name]]
out += ["*NSET, NSET=SYMM"] + [str(node_id(0, j)) for j in range(2 * NY + 1)]
out += ["*NSET, NSET=MID"] + [str(node_id(i, NY)) for i in range(2 * NX + 1)]
out += ["*NSET, NSET=CENTRE", str(node_id(0, NY))]
# Surfaces: the sheet's bottom (S1) and top (S3) faces, the tools' faces.
out += ["*SURFACE, NAME=SHEETTOP"] + [f"{e}, S3" for e, _ in sheet[-NX:]]
out += ["*SURFACE, NAME=SHEETBOT"] + [f"{e}, S1" for e, _ in sheet[:NX]]
for name, faces in tool_faces.items():
    out += [f"*SURFACE, NAME={name}S"] + [f"{e}, {f}" for e, f in faces]

# Material: the channel's Swift curve on plastic strain (von Mises).
out += ["*MATERIAL, NAME=STEEL", "*ELASTIC", f"{E}, {NU}", "*PLASTIC"]
for k in range(41):
    ep = 0 if k == 0 else 10 ** (-4 + 4.3 * (k - 1) / 39)   # 1e-4 .. 2
    out.append(f"{565.32 * (0.007117 + ep) ** 0.2589:.6f}, {ep:.6g}")
out += ["*MATERIAL, NAME=RIGID", "*ELASTIC", "210000, 0.3"]
out += ["*SOLID SECTION, ELSET=SHEET, MATERIAL=STEEL", f"{B}"]
for name in tools:
    out += [f"*SOLID SECTION, ELSET={name}, MATERIAL=RIGID", f"{B}"]

if HOLDER_FORCE:
    out += ["*EQUATION"]
    for n in ref["HOLDER"][1:]:
        out += ["2", f"{n}, 2, 1., {HM}, 2, -1."]
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

"""What the CalculiX decks of cup_deck.py and channel_deck.py share: the
sheet as NX x NY eight-node quadrilaterals over LENGTH x T, the tools'
profiles, and each tool as a band of four-node elements on its profile."""
import math


def node_id(NX, i, j):
    """The sheet's node in column i, row j (half-element steps)."""
    return 1 + j * (2 * NX + 1) + i


def sheet(NX, NY, LENGTH, T, out):
    """Writes the sheet's nodes into out; returns its elements
    [(id, 8 nodes)] (corners counter-clockwise, then the mid-sides)."""
    for j in range(2 * NY + 1):
        for i in range(2 * NX + 1):
            if i % 2 == 0 or j % 2 == 0:
                out.append(f"{node_id(NX, i, j)}, {LENGTH * i / (2 * NX):.10g}, {T * j / (2 * NY):.10g}")
    elements = []
    for jj in range(NY):
        for ii in range(NX):
            i, j = 2 * ii, 2 * jj
            n = [node_id(NX, *p) for p in ((i, j), (i + 2, j), (i + 2, j + 2), (i, j + 2),
                                           (i + 1, j), (i + 2, j + 1), (i + 1, j + 2), (i, j + 1))]
            elements.append((1 + jj * NX + ii, n))
    return elements


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


def tool_bands(tools, eid, out, first_node=100000):
    """Each tool {name: (profile, a point inside it)} as a band of 4-node
    elements 1 mm deep on its profile, numbered after eid; writes the nodes
    into out. Returns the elements, the contact faces (on the profile) and
    the nodes of each tool."""
    next_node = first_node
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
            pa, pb = prof[k], prof[k + 1]
            # counter-clockwise: the profile's side first when the inside
            # point lies to the left of the profile's direction
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
    return tool_elems, tool_faces, ref


def elements_and_sets(out, sheet_elements, sheet_type, tool_elems, tool_type, ref):
    """The sheet's and the tools' elements, and each tool's node set
    <NAME>N."""
    out.append(f"*ELEMENT, TYPE={sheet_type}, ELSET=SHEET")
    out += [f"{e}, " + ", ".join(map(str, n)) for e, n in sheet_elements]
    for name, els in tool_elems.items():
        out.append(f"*ELEMENT, TYPE={tool_type}, ELSET={name}")
        out += [f"{e}, " + ", ".join(map(str, n)) for e, n in els]
    for name in tool_elems:
        out += [f"*NSET, NSET={name}N"] + [str(n) for n in ref[name]]


def surfaces(out, sheet_elements, NX, tool_faces):
    """The sheet's bottom (S1) and top (S3) faces, the tools' faces."""
    out += ["*SURFACE, NAME=SHEETTOP"] + [f"{e}, S3" for e, _ in sheet_elements[-NX:]]
    out += ["*SURFACE, NAME=SHEETBOT"] + [f"{e}, S1" for e, _ in sheet_elements[:NX]]
    for name, faces in tool_faces.items():
        out += [f"*SURFACE, NAME={name}S"] + [f"{e}, {f}" for e, f in faces]


def swift_table(out, K, e0, n):
    """*PLASTIC rows of K (e0 + ep)^n at 41 plastic strains from 0 and 1e-4
    to 2."""
    for k in range(41):
        ep = 0 if k == 0 else 10 ** (-4 + 4.3 * (k - 1) / 39)
        out.append(f"{K * (e0 + ep) ** n:.6f}, {ep:.6g}")


def tie_in_y(out, nodes):
    """Every node of nodes moves in y with the first (which carries the
    load)."""
    out += ["*EQUATION"]
    for n in nodes[1:]:
        out += ["2", f"{n}, 2, 1., {nodes[0]}, 2, -1."]

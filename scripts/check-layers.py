#!/usr/bin/python3
"""The layers of formsolve's source areas, checked (CI runs this).

Each area (include/formsolve/<area>/ with source/<area>/) may include only
areas of a lower layer. The order is the architecture (doc/architecture.md):
a new include that goes up or sideways, or a new area not placed here, fails
with the file and line. Exit status 0 when every include goes down.
    /usr/bin/python3 scripts/check-layers.py"""
import os
import re
import sys

LAYERS = [
    ["app", "model"],  # utilities without formsolve dependencies
    ["parameters"],  # the .prm subsections
    ["geometry", "tools", "material"],  # the blank, the tools, the point law
    ["contact"],  # pairs, contact law, penalty strategies
    ["state"],  # what a step changes: State, quadrature history
    ["newton", "linear"],  # Newton on a NonlinearProblem; linear solves
    ["beads"],  # equivalent draw beads: line forces on the sheet
    ["forming", "refinement"],  # the forming operators and step; adaptation
    ["postprocess"],  # measures, history.csv, VTU
    ["trimming"],  # the cut of the formed part
    ["springback"],  # the release of the formed part
    ["simulation"],  # the time loop
]
layer = {area: k for k, names in enumerate(LAYERS) for area in names}
root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
include = re.compile(r'^\s*#\s*include\s*[<"]formsolve/([a-z_]+)/')
bad = []
for top, depth in (("include/formsolve", 0), ("source", 0)):
    for folder, _, files in os.walk(os.path.join(root, top)):
        rel = os.path.relpath(folder, os.path.join(root, top))
        if rel == ".":
            continue  # source/main.cc: the executable, above every layer
        area = rel.split(os.sep)[0]
        if area not in layer:
            bad.append(f"{top}/{rel}: area '{area}' has no layer in scripts/check-layers.py")
            continue
        for f in files:
            path = os.path.join(folder, f)
            for n, line in enumerate(open(path, encoding="utf-8"), 1):
                m = include.match(line)
                if m and m.group(1) != area:
                    to = m.group(1)
                    if to not in layer or layer[to] >= layer[area]:
                        bad.append(f"{os.path.relpath(path, root)}:{n}: {area} (layer {layer[area]}) "
                                   f"includes {to} (layer {layer.get(to, '?')})")
for b in bad:
    print(b)
print(f"layers: {'ok, every include goes down' if not bad else f'{len(bad)} include(s) against the layers'}")
sys.exit(1 if bad else 0)

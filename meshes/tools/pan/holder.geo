// The pan's blank holder (gmsh, OpenCASCADE kernel), in mm: a flat block on
// the sheet's top surface z = t0 with an opening 1 mm outside the die's entry
// radius (die.geo), its inner edge rounded by 1 mm.
SetFactory("OpenCASCADE");
DefineConstant[ length = 70, width = 50, rc = 12, draft = 5, c = 1, rd = 6,
                step = 4, height_b = 1.5, t0 = 0.8, stroke = 20, reach = 85,
                h = 10, size = 1.5 ];
// The die's opening at its face z = 0 (die.geo), plus rd + 1.
td = Tan(draft * Pi / 180);
grow = c / Cos(draft * Pi / 180) + (stroke - height_b - step - t0) * td;
ax = length / 2 + grow + rd + 1;
ay = width / 2 + grow + rd + 1;
ar = rc + grow + rd + 1;
Box(1) = {-reach, -reach, t0, 2 * reach, 2 * reach, h};
s1 = news; Rectangle(s1) = {-ax, -ay, t0 - 1, 2 * ax, 2 * ay, ar};
opening() = Extrude{0, 0, h + 2}{ Surface{s1}; };
holder = newv;
BooleanDifference(holder) = { Volume{1}; Delete; }{ Volume{opening(1)}; Delete; };
eps = 1e-3;
edge() = Curve In BoundingBox{-ax - eps, -ay - eps, t0 - eps, ax + eps,
                              ay + eps, t0 + eps};
Fillet{holder}{edge()}{1}
// Facets: up to size (formsolve: Facet size), 12 per full turn on radii.
Mesh.MeshSizeMax = size;
Mesh.MeshSizeMin = size / 8;
Mesh.MeshSizeFromCurvature = 12;

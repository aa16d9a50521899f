// The die's r-z profile for the axisymmetric model (gmsh, lines in the x-z
// plane, r = x), in mm: its face at z = 0 from r = reach in to the entry
// radius rd of the opening of diameter d, and the opening's wall down to
// z = -h. An open profile: formsolve works it on the side the sheet sees.
SetFactory("OpenCASCADE");
DefineConstant[ d = 42.5, rd = 8, reach = 60, h = 45, size = 1 ];
Point(1) = {reach, 0, 0};
Point(2) = {d / 2 + rd, 0, 0};
Point(3) = {d / 2 + rd, 0, -rd};
Point(4) = {d / 2, 0, -rd};
Point(5) = {d / 2, 0, -h};
Line(1) = {1, 2};
Circle(2) = {2, 3, 4};
Line(3) = {4, 5};
Mesh.MeshSizeMax = size;
Mesh.MeshSizeMin = size / 8;
Mesh.MeshSizeFromCurvature = 12;

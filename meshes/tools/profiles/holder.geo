// The blank holder's r-z profile for the axisymmetric model (gmsh, lines in
// the x-z plane, r = x), in mm: the wall of its opening of diameter d from
// z0 + h down to its face at z = z0 (on the sheet's top surface), a sharp
// edge, and the face out to r = reach. An open profile: formsolve works it on
// the side the sheet sees.
SetFactory("OpenCASCADE");
DefineConstant[ d = 58.5, z0 = 0.78, reach = 60, h = 10, size = 1 ];
Point(1) = {d / 2, 0, z0 + h};
Point(2) = {d / 2, 0, z0};
Point(3) = {reach, 0, z0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Mesh.MeshSizeMax = size;
Mesh.MeshSizeMin = size / 8;

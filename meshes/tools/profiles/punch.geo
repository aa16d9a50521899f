// The punch's r-z profile for the axisymmetric model (gmsh, lines in the x-z
// plane, r = x), in mm: its face at z = z0 (on the sheet's top surface)
// from the axis to the nose of radius rp, and its wall of diameter d up to
// z0 + h. An open profile: formsolve works it on the side the sheet sees.
SetFactory("OpenCASCADE");
DefineConstant[ d = 40, rp = 8, z0 = 0.78, h = 45, size = 1 ];
Point(1) = {0, 0, z0};
Point(2) = {d / 2 - rp, 0, z0};
Point(3) = {d / 2 - rp, 0, z0 + rp};
Point(4) = {d / 2, 0, z0 + rp};
Point(5) = {d / 2, 0, z0 + h};
Line(1) = {1, 2};
Circle(2) = {2, 3, 4};
Line(3) = {4, 5};
Mesh.MeshSizeMax = size;
Mesh.MeshSizeMin = size / 8;
Mesh.MeshSizeFromCurvature = 12;

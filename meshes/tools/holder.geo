// The blank holder as a solid for a meshed tool (gmsh, OpenCASCADE kernel),
// in mm: its face at z = z0 (on the sheet's top surface), a block of
// half-size reach and height h with the opening (shape 0: round of diameter
// d; 1: rounded rectangle length x width with corner radius rc), the
// opening's lower edge rounded by rh (0: sharp).
SetFactory("OpenCASCADE");
DefineConstant[ shape = 0, d = 58.5, length = 58.5, width = 58.5, rc = 19.25,
                rh = 0, z0 = 0.78, reach = 50, h = 10, size = 1 ];
Box(1) = {-reach, -reach, z0, 2 * reach, 2 * reach, h};
If (shape == 0)
  hole = newv;
  Cylinder(hole) = {0, 0, z0 - 1, 0, 0, h + 2, d / 2};
Else
  s = news;
  Rectangle(s) = {-length / 2, -width / 2, z0 - 1, length, width, rc};
  ex[] = Extrude {0, 0, h + 2} { Surface{s}; };
  hole = ex[1];
EndIf
body = newv;
BooleanDifference(body) = { Volume{1}; Delete; }{ Volume{hole}; Delete; };
If (rh > 0)
  edge() = Curve In BoundingBox{-reach + 1, -reach + 1, z0 - 1e-6, reach - 1, reach - 1, z0 + 1e-6};
  Fillet{body}{edge()}{rh}
EndIf
Mesh.MeshSizeMax = size;
Mesh.MeshSizeMin = size / 8;
Mesh.MeshSizeFromCurvature = 12;

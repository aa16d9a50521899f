// The die as a solid for a meshed tool (gmsh, OpenCASCADE kernel), in mm:
// its face at z = 0 (under the sheet), a block of half-size reach and depth
// h with the opening (shape 0: round of diameter d; 1: rounded rectangle
// length x width with corner radius rc) whose entry is rounded by rd.
SetFactory("OpenCASCADE");
DefineConstant[ shape = 0, d = 42.5, length = 42.5, width = 42.5, rc = 11.25,
                rd = 8, reach = 50, h = 30, size = 1 ];
Box(1) = {-reach, -reach, -h, 2 * reach, 2 * reach, h};
If (shape == 0)
  hole = newv;
  Cylinder(hole) = {0, 0, -h - 1, 0, 0, h + 2, d / 2};
Else
  s = news;
  Rectangle(s) = {-length / 2, -width / 2, -h - 1, length, width, rc};
  ex[] = Extrude {0, 0, h + 2} { Surface{s}; };
  hole = ex[1];
EndIf
body = newv;
BooleanDifference(body) = { Volume{1}; Delete; }{ Volume{hole}; Delete; };
entry() = Curve In BoundingBox{-reach + 1, -reach + 1, -1e-6, reach - 1, reach - 1, 1e-6};
Fillet{body}{entry()}{rd}
Mesh.MeshSizeMax = size;
Mesh.MeshSizeMin = size / 8;
Mesh.MeshSizeFromCurvature = 12;

// The punch as a solid for a meshed tool (gmsh, OpenCASCADE kernel), in mm:
// its face at z = z0 (on the sheet's top surface), the working edge rounded
// by the profile radius rp, the body up to z0 + h. shape 0: round of
// diameter d; 1: rounded rectangle length x width with corner radius rc.
// gmsh -2 punch.geo -setnumber d 40 ... -format stl -o punch.stl
SetFactory("OpenCASCADE");
DefineConstant[ shape = 0, d = 40, length = 40, width = 40, rc = 10,
                rp = 8, z0 = 0.78, h = 30, size = 1 ];
If (shape == 0)
  Cylinder(1) = {0, 0, z0, 0, 0, h, d / 2};
Else
  Rectangle(1) = {-length / 2, -width / 2, z0, length, width, rc};
  Extrude {0, 0, h} { Surface{1}; }
EndIf
edge() = Curve In BoundingBox{-1e4, -1e4, z0 - 1e-6, 1e4, 1e4, z0 + 1e-6};
Fillet{1}{edge()}{rp}
Mesh.MeshSizeMax = size;
Mesh.MeshSizeMin = size / 8;
Mesh.MeshSizeFromCurvature = 12; // elements per 2 pi of curvature

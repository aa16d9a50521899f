// One segment of the square cup's blank holder (gmsh, OpenCASCADE kernel),
// in mm: the holder of ../holder.geo with shape 1 (opening 58.5 x 58.5,
// corner radius 19.25, face at z0 on the sheet's top surface) cut where its
// opening's straight edges end (|x| = |y| = a = 58.5/2 - 19.25 = 10): part
// 0 the sides (|x| < a or |y| < a), part 1 the four corners (|x|, |y| > a).
// Included by holder-sides.geo and holder-corners.geo, which set part.
SetFactory("OpenCASCADE");
DefineConstant[ length = 58.5, rc = 19.25, z0 = 0.78, reach = 50, h = 10,
                size = 1 ];
a = length / 2 - rc;
Box(1) = {-reach, -reach, z0, 2 * reach, 2 * reach, h};
s = news;
Rectangle(s) = {-length / 2, -length / 2, z0 - 1, length, length, rc};
ex[] = Extrude {0, 0, h + 2} { Surface{s}; };
holder = newv;
BooleanDifference(holder) = { Volume{1}; Delete; }{ Volume{ex[1]}; Delete; };
// The four corner blocks.
c1 = newv; Box(c1) = {a, a, z0 - 1, reach, reach, h + 2};
c2 = newv; Box(c2) = {-a - reach, a, z0 - 1, reach, reach, h + 2};
c3 = newv; Box(c3) = {-a - reach, -a - reach, z0 - 1, reach, reach, h + 2};
c4 = newv; Box(c4) = {a, -a - reach, z0 - 1, reach, reach, h + 2};
If (part == 0)
  piece() = BooleanDifference{ Volume{holder}; Delete; }{ Volume{c1, c2, c3, c4}; Delete; };
Else
  piece() = BooleanIntersection{ Volume{holder}; Delete; }{ Volume{c1, c2, c3, c4}; Delete; };
EndIf
Mesh.MeshSizeMax = size;
Mesh.MeshSizeMin = size / 8;
Mesh.MeshSizeFromCurvature = 12;

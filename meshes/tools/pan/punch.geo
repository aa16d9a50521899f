// The pan's punch (gmsh, OpenCASCADE kernel), in mm: a rounded rectangle
// length x width (corners rc) at its face, walls with a draft angle widening
// upwards, the nose rounded by rp; on the face a stepped centre (length_s x
// width_s, corners rc_s) standing out by step with walls at angle_s from
// the vertical, its edges rounded by r_s; on the step an embossing rib along
// x (length_b x width_b at its crest, standing out by height_b, flanks at
// angle_s, crest rounded by r_b, root by r_r). Its lowest point, the rib's
// crest, is placed on the sheet's top surface z = t0. die.geo is its
// negative at the end of the stroke.
SetFactory("OpenCASCADE");
DefineConstant[ length = 70, width = 50, rc = 12, rp = 6, draft = 5, h = 30,
                length_s = 34, width_s = 20, rc_s = 6, step = 4, angle_s = 30,
                r_s = 2, length_b = 20, width_b = 3, height_b = 1.5, r_b = 0.8,
                r_r = 1.5,
                t0 = 0.8, size = 1.5 ];
t = Tan(angle_s * Pi / 180);
z1 = t0 + height_b; // the step's face
z0 = z1 + step;     // the main face
grow = h * Tan(draft * Pi / 180);
s1 = news; Rectangle(s1) = {-length / 2, -width / 2, z0, length, width, rc};
s2 = news; Rectangle(s2) = {-length / 2 - grow, -width / 2 - grow, z0 + h,
                            length + 2 * grow, width + 2 * grow, rc + grow};
l1 = newll; Curve Loop(l1) = {Boundary{Surface{s1};}};
l2 = newll; Curve Loop(l2) = {Boundary{Surface{s2};}};
body = newv; ThruSections(body) = {l1, l2};
Delete{ Surface{s1, s2}; }
// The step and the rib each overlap the solid above by 1 mm so that they
// fuse into one.
in = step * t;
s3 = news; Rectangle(s3) = {-length_s / 2 + in, -width_s / 2 + in, z1,
                            length_s - 2 * in, width_s - 2 * in, rc_s - in};
s4 = news; Rectangle(s4) = {-length_s / 2 - t, -width_s / 2 - t, z0 + 1,
                            length_s + 2 * t, width_s + 2 * t, rc_s + t};
l3 = newll; Curve Loop(l3) = {Boundary{Surface{s3};}};
l4 = newll; Curve Loop(l4) = {Boundary{Surface{s4};}};
centre = newv; ThruSections(centre) = {l3, l4};
Delete{ Surface{s3, s4}; }
out = (height_b + 1) * t;
s5 = news; Rectangle(s5) = {-length_b / 2, -width_b / 2, t0, length_b,
                            width_b, 0.49 * width_b};
s6 = news; Rectangle(s6) = {-length_b / 2 - out, -width_b / 2 - out, z1 + 1,
                            length_b + 2 * out, width_b + 2 * out,
                            0.49 * width_b + out};
l5 = newll; Curve Loop(l5) = {Boundary{Surface{s5};}};
l6 = newll; Curve Loop(l6) = {Boundary{Surface{s6};}};
rib = newv; ThruSections(rib) = {l5, l6};
Delete{ Surface{s5, s6}; }
punch = newv;
BooleanUnion(punch) = { Volume{body}; Delete; }{ Volume{centre, rib}; Delete; };
// Round the nose (rp), the step's edges (r_s below, r_s + 1 where it meets
// the face) and the rib's crest (r_b) and root (r_r).
eps = 1e-3;
at_face() = Curve In BoundingBox{-length / 2 - eps, -width / 2 - eps, z0 - eps,
                                 length / 2 + eps, width / 2 + eps, z0 + eps};
inner() = Curve In BoundingBox{-length_s / 2 - eps, -width_s / 2 - eps,
                               z0 - eps, length_s / 2 + eps, width_s / 2 + eps,
                               z0 + eps};
lower() = Curve In BoundingBox{-length_s / 2, -width_s / 2, z1 - eps,
                               length_s / 2, width_s / 2, z1 + eps};
root() = Curve In BoundingBox{-length_b / 2 - 2, -width_b / 2 - 2, z1 - eps,
                              length_b / 2 + 2, width_b / 2 + 2, z1 + eps};
lower() -= root();
crest() = Curve In BoundingBox{-length_b / 2 - eps, -width_b / 2 - eps,
                               t0 - eps, length_b / 2 + eps,
                               width_b / 2 + eps, t0 + eps};
nose() = at_face();
nose() -= inner();
edges() = {};
radii() = {};
For k In {0 : #nose() - 1}
  edges() += nose(k);
  radii() += rp;
EndFor
For k In {0 : #lower() - 1}
  edges() += lower(k);
  radii() += r_s;
EndFor
For k In {0 : #inner() - 1}
  edges() += inner(k);
  radii() += r_s + 1;
EndFor
For k In {0 : #root() - 1}
  edges() += root(k);
  radii() += r_r;
EndFor
For k In {0 : #crest() - 1}
  edges() += crest(k);
  radii() += r_b;
EndFor
Fillet{punch}{edges()}{radii()}
// Facets: up to size (formsolve: Facet size), 12 per full turn on radii.
Mesh.MeshSizeMax = size;
Mesh.MeshSizeMin = size / 8;
Mesh.MeshSizeFromCurvature = 12;

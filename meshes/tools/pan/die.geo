// The pan's die (gmsh, OpenCASCADE kernel), in mm: a block below its face
// z = 0 with a cavity, the negative of the punch of punch.geo at the end of
// its stroke (same dimensions): drafted walls with the clearance c, entry
// rounded by rd; a bottom t0 below the punch's main face with pockets for
// the punch's step and rib, offset by t0 along the normal (flanks at
// angle_s: the outline grows by t0 (1 - sin angle_s) / cos angle_s), their
// radii those of the punch plus or minus t0.
SetFactory("OpenCASCADE");
DefineConstant[ length = 70, width = 50, rc = 12, rp = 6, draft = 5, c = 1,
                rd = 6, length_s = 34, width_s = 20, rc_s = 6, step = 4,
                angle_s = 30, r_s = 2, length_b = 20, width_b = 3,
                height_b = 1.5, r_b = 0.8, r_r = 1.5, t0 = 0.8, stroke = 20,
                reach = 85, h = 40, size = 1.5 ];
t = Tan(angle_s * Pi / 180);
grow_n = t0 * (1 - Sin(angle_s * Pi / 180)) / Cos(angle_s * Pi / 180);
zr = t0 - stroke;         // the punch's rib crest at the end
zs = zr + height_b;       // its step face
zm = zs + step;           // its main face
zb = zm - t0;             // the die's bottom
// The walls: the punch's outline at the bottom plus c along the normal,
// widening upwards with the draft.
td = Tan(draft * Pi / 180);
cw = c / Cos(draft * Pi / 180) - (zm - zb) * td;
up = (1 - zb) * td;
Box(1) = {-reach, -reach, -h, 2 * reach, 2 * reach, h};
s1 = news; Rectangle(s1) = {-length / 2 - cw, -width / 2 - cw, zb,
                            length + 2 * cw, width + 2 * cw, rc + cw};
s2 = news; Rectangle(s2) = {-length / 2 - cw - up, -width / 2 - cw - up, 1,
                            length + 2 * (cw + up), width + 2 * (cw + up),
                            rc + cw + up};
l1 = newll; Curve Loop(l1) = {Boundary{Surface{s1};}};
l2 = newll; Curve Loop(l2) = {Boundary{Surface{s2};}};
cavity = newv; ThruSections(cavity) = {l1, l2};
Delete{ Surface{s1, s2}; }
// The step's pocket: floor t0 below the step face, up to 1 mm into the
// cavity so that the volumes overlap.
in = step * t;
zf = zs - t0;
g = grow_n - in;
s3 = news; Rectangle(s3) = {-length_s / 2 - g, -width_s / 2 - g, zf,
                            length_s + 2 * g, width_s + 2 * g, rc_s + g};
o = (zb + 1 - zf) * t;
s4 = news; Rectangle(s4) = {-length_s / 2 - g - o, -width_s / 2 - g - o,
                            zb + 1, length_s + 2 * (g + o),
                            width_s + 2 * (g + o), rc_s + g + o};
l3 = newll; Curve Loop(l3) = {Boundary{Surface{s3};}};
l4 = newll; Curve Loop(l4) = {Boundary{Surface{s4};}};
pocket = newv; ThruSections(pocket) = {l3, l4};
Delete{ Surface{s3, s4}; }
// The rib's groove in the pocket's floor.
zg = zr - t0;
o = (zf + 1 - zg) * t;
s5 = news; Rectangle(s5) = {-length_b / 2 - grow_n, -width_b / 2 - grow_n, zg,
                            length_b + 2 * grow_n, width_b + 2 * grow_n,
                            0.49 * width_b + grow_n};
s6 = news; Rectangle(s6) = {-length_b / 2 - grow_n - o,
                            -width_b / 2 - grow_n - o, zf + 1,
                            length_b + 2 * (grow_n + o),
                            width_b + 2 * (grow_n + o),
                            0.49 * width_b + grow_n + o};
l5 = newll; Curve Loop(l5) = {Boundary{Surface{s5};}};
l6 = newll; Curve Loop(l6) = {Boundary{Surface{s6};}};
groove = newv; ThruSections(groove) = {l5, l6};
Delete{ Surface{s5, s6}; }
die = newv;
BooleanDifference(die) = { Volume{1}; Delete; }{ Volume{cavity, pocket, groove}; Delete; };
// Radii: the entry rd; the bottom's edge, the pocket's and the groove's
// edges those of the punch, concave ones plus t0, convex ones minus t0.
eps = 1e-3;
ex = length / 2 + cw + up + 1;
ey = width / 2 + cw + up + 1;
entry() = Curve In BoundingBox{-ex, -ey, -eps, ex, ey, eps};
bottom() = Curve In BoundingBox{-ex, -ey, zb - eps, ex, ey, zb + eps};
rim() = Curve In BoundingBox{-length_s / 2 - 1, -width_s / 2 - 1, zb - eps,
                             length_s / 2 + 1, width_s / 2 + 1, zb + eps};
bottom() -= rim();
floor() = Curve In BoundingBox{-length_s / 2, -width_s / 2, zf - eps,
                               length_s / 2, width_s / 2, zf + eps};
lip() = Curve In BoundingBox{-length_b / 2 - 2, -width_b / 2 - 2, zf - eps,
                             length_b / 2 + 2, width_b / 2 + 2, zf + eps};
floor() -= lip();
base() = Curve In BoundingBox{-ex, -ey, zg - eps, ex, ey, zg + eps};
edges() = {};
radii() = {};
For k In {0 : #entry() - 1}
  edges() += entry(k); radii() += rd;
EndFor
For k In {0 : #bottom() - 1}
  edges() += bottom(k); radii() += rp + t0;
EndFor
For k In {0 : #rim() - 1}
  edges() += rim(k); radii() += r_s + 1 - t0;
EndFor
For k In {0 : #floor() - 1}
  edges() += floor(k); radii() += r_s + t0;
EndFor
For k In {0 : #lip() - 1}
  edges() += lip(k); radii() += r_r - t0;
EndFor
For k In {0 : #base() - 1}
  edges() += base(k); radii() += r_b + t0;
EndFor
Fillet{die}{edges()}{radii()}
// Facets: up to size (formsolve: Facet size), 12 per full turn on radii.
Mesh.MeshSizeMax = size;
Mesh.MeshSizeMin = size / 8;
Mesh.MeshSizeFromCurvature = 12;

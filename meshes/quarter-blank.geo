// Quarter of the 77 mm round blank of the reference cup (planform only: formsolve
// extrudes it through the thickness). x = 0 and y = 0 are symmetry planes.
R = 38.5;   // blank radius (mm)
h = 2.0;    // target element size (mm)
Point(1) = {0, 0, 0, h};
Point(2) = {R, 0, 0, h};
Point(3) = {0, R, 0, h};
Line(1) = {1, 2};
Circle(2) = {2, 1, 3};
Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Recombine Surface{1};

// One 9-node quadrangle (Gmsh type 10, not supported by PECPLAS): the reader must refuse it.
// Regenerate: gmsh -2 -format msh41 q9.geo -o q9.msh
SetFactory("Built-in");
Point(1) = {0, 0, 0, 1.0};
Point(2) = {1, 0, 0, 1.0};
Point(3) = {1, 1, 0, 1.0};
Point(4) = {0, 1, 0, 1.0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = 2;
Transfinite Surface{1};
Recombine Surface{1};
Physical Surface("block") = {1};
Mesh.ElementOrder = 2;

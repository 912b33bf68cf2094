// Unit square in 3-node triangles without any physical group: Gmsh then saves every
// element (points, lines, triangles) and the reader puts the triangles in set ALL_T3.
// Regenerate: gmsh -2 -format msh41 nophys.geo -o nophys.msh
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

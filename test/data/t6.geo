// 2 m x 1 m block meshed with 6-node triangles (type 9) and 3-node boundary lines (type 8).
// Regenerate: gmsh -2 -format msh41 t6.geo -o t6.msh
SetFactory("Built-in");
Point(1) = {0, 0, 0, 0.5};
Point(2) = {2, 0, 0, 0.5};
Point(3) = {2, 1, 0, 0.5};
Point(4) = {0, 1, 0, 0.5};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Surface("soil") = {1};
Physical Curve("bottom") = {1};
Physical Curve("top") = {3};
Physical Curve("sides") = {2, 4};
Mesh.ElementOrder = 2;
Mesh.Algorithm = 6;

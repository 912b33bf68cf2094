// 2 m x 1 m block in 2 x 1 eight-node quadrangles (type 16) with 3-node lines (type 8).
// The curve loop runs clockwise, so Gmsh writes clockwise elements: check_elements must
// renumber them. Regenerate: gmsh -2 -format msh41 q8.geo -o q8.msh
SetFactory("Built-in");
Point(1) = {0, 0, 0, 1.0};
Point(2) = {2, 0, 0, 1.0};
Point(3) = {2, 1, 0, 1.0};
Point(4) = {0, 1, 0, 1.0};
Line(1) = {1, 4};
Line(2) = {4, 3};
Line(3) = {3, 2};
Line(4) = {2, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{2, 4} = 3;
Transfinite Curve{1, 3} = 2;
Transfinite Surface{1};
Recombine Surface{1};
Physical Surface("wall") = {1};
Physical Curve("base") = {4};
Physical Curve("top") = {2};
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 1;

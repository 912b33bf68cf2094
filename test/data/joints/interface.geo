// Two blocks [0,2]x[0,1] ("lower") and [0,2]x[1,2] ("upper") sharing the curve y = 1
// ("interface"): one node row there, split by *JOINTS, EDGES=interface, SIDE=upper.
// 8-node quadrangles (2 x 1 per block). Regenerate:
//   gmsh -2 -format msh41 interface.geo -o interface.msh
SetFactory("Built-in");
Point(1) = {0, 0, 0, 1.0};
Point(2) = {2, 0, 0, 1.0};
Point(3) = {2, 1, 0, 1.0};
Point(4) = {0, 1, 0, 1.0};
Point(5) = {2, 2, 0, 1.0};
Point(6) = {0, 2, 0, 1.0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Line(5) = {3, 5};
Line(6) = {5, 6};
Line(7) = {6, 4};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Curve Loop(2) = {-3, 5, 6, 7};
Plane Surface(2) = {2};
Transfinite Curve{1, 3, 6} = 3;
Transfinite Curve{2, 4, 5, 7} = 2;
Transfinite Surface{1};
Transfinite Surface{2};
Recombine Surface{1, 2};
Physical Surface("lower") = {1};
Physical Surface("upper") = {2};
Physical Curve("interface") = {3};
Physical Curve("base") = {1};
Physical Curve("sides") = {2, 4, 5, 7};
Physical Curve("top") = {6};
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 1;

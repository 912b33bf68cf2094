// Two unit squares sharing the edge x = 1: the left one in 4-node quadrangles (type 3),
// the right one in 3-node triangles (type 2), both in the physical surface "soil";
// the reader splits it into soil_Q4 and soil_T3. Curve "interface" is interior.
// Regenerate: gmsh -2 -format msh41 mixed.geo -o mixed.msh
SetFactory("Built-in");
Point(1) = {0, 0, 0, 0.5};
Point(2) = {1, 0, 0, 0.5};
Point(3) = {2, 0, 0, 0.5};
Point(4) = {2, 1, 0, 0.5};
Point(5) = {1, 1, 0, 0.5};
Point(6) = {0, 1, 0, 0.5};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 6};
Line(6) = {6, 1};
Line(7) = {2, 5};
Curve Loop(1) = {1, 7, 5, 6};
Plane Surface(1) = {1};
Curve Loop(2) = {2, 3, 4, -7};
Plane Surface(2) = {2};
Transfinite Curve{1, 7, 5, 6} = 3;
Transfinite Surface{1};
Recombine Surface{1};
Physical Surface("soil") = {1, 2};
Physical Curve("bottom") = {1, 2};
Physical Curve("interface") = {7};
Physical Point("origin") = {1};

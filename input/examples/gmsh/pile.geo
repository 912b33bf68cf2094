// Bored pile in sand, axisymmetric (x = r, y = z; the pile's axis is r = 0).
// Mesh:  gmsh pile.geo -2 -o pile.msh      then:  pecplas pile.inp
// doc/gmsh.md explains every line. Lengths in m.
a  = 0.4;        // pile radius
Lp = 8.0;        // pile length (head at y = 0)
R  = 8.0;        // radius of the soil cylinder
H  = 14.0;       // depth of the soil cylinder
lc_pile = 0.4;   // element size along the pile
lc_far  = 2.5;   // element size far from it

Point(1) = {0, 0,   0, lc_pile};   // head, on the axis
Point(2) = {a, 0,   0, lc_pile};   // head, at the shaft
Point(3) = {R, 0,   0, lc_far};
Point(4) = {R, -H,  0, lc_far};
Point(5) = {0, -H,  0, lc_far};
Point(6) = {0, -Lp, 0, lc_pile};   // tip, on the axis
Point(7) = {a, -Lp, 0, lc_pile};   // tip, at the shaft

Line(1) = {1, 2};   // pile head
Line(2) = {2, 7};   // shaft (pile | soil)
Line(3) = {7, 6};   // tip (pile | soil)
Line(4) = {6, 1};   // axis in the pile
Line(5) = {2, 3};   // ground surface
Line(6) = {3, 4};   // far side
Line(7) = {4, 5};   // base
Line(8) = {5, 6};   // axis below the pile

Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};            // pile
Curve Loop(2) = {5, 6, 7, 8, -3, -2};
Plane Surface(2) = {2};            // soil

// The pile as a structured grid of quadrilaterals (2 across, 20 along): generated joints
// take one element type on their SIDE= body. The soil is meshed freely.
Transfinite Curve{1, 3} = 3;
Transfinite Curve{2, 4} = 21;
Transfinite Surface{1} = {1, 2, 7, 6};

Physical Surface("pile") = {1};
Physical Surface("soil") = {2};
Physical Curve("head") = {1};
Physical Curve("shaft") = {2};
Physical Curve("tip") = {3};
Physical Curve("axis") = {4, 8};
Physical Curve("side") = {6};
Physical Curve("base") = {7};
Physical Point("head_axis") = {1};

Mesh.RecombineAll = 1;
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 1;   // 8-node quadrilaterals (Q8), 6-node triangles (T6)
Mesh.MshFileVersion = 4.1;

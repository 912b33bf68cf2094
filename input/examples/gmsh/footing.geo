// Strip footing on clay, plane strain, half model (the footing's axis is x = 0).
// Mesh:  gmsh footing.geo -2 -o footing.msh      then:  pecplas footing.inp
// doc/gmsh.md explains every line. Lengths in m.
B2 = 1.0;        // half-width of the footing
W  = 6.0;        // half-width of the soil block
D  = 4.0;        // depth of the soil block
lc_edge = 0.1;   // element size at the footing's edge, where the soil yields first
lc_far  = 0.8;   // element size far from it

Point(1) = {0,  0,  0, 2*lc_edge};   // footing centre
Point(2) = {B2, 0,  0, lc_edge};     // footing edge
Point(3) = {W,  0,  0, lc_far};
Point(4) = {W,  -D, 0, lc_far};
Point(5) = {0,  -D, 0, lc_far};

Line(1) = {1, 2};   // under the footing
Line(2) = {2, 3};   // free ground surface
Line(3) = {3, 4};   // far side
Line(4) = {4, 5};   // base
Line(5) = {5, 1};   // symmetry axis

Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};

// Names that the deck uses: element set 'soil', edge and node sets of the curves, node
// set 'centre'. Only what belongs to a physical group is written to the .msh file.
Physical Surface("soil") = {1};
Physical Curve("footing") = {1};
Physical Curve("surface") = {2};
Physical Curve("side") = {3};
Physical Curve("base") = {4};
Physical Curve("axis") = {5};
Physical Point("centre") = {1};

// Quadrilaterals (triangles where they cannot be paired) with 8 nodes (Q8, and T6):
// ELEMENT=Q8R on the deck's *SECTION then integrates them with 2 x 2 points.
Mesh.RecombineAll = 1;
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 1;   // 8-node quadrilaterals, not Gmsh's 9-node ones
Mesh.MshFileVersion = 4.1;        // the format *MESH reads

// A mirror-symmetric mesh for tests/coupling/symmetry.cc: the box [0, 2] x [0, 1] with a "V" of
// two fractures, fracture 1 from (0.4, 0.8) down to the apex (1, 0.35) and fracture 2, its mirror
// image about x = 1, from (1.6, 0.8) to the apex (an L junction on the axis).
//
// gmsh does not mesh a symmetric geometry symmetrically by itself. Here the domain is split along
// x = 1 into two surfaces; the right one (and its curves) is declared periodic of the left one
// through the reflection x -> 2 - x, so gmsh meshes the left half and copies its mesh to the
// right: every vertex, triangle and fracture face has its mirror image (vertex coordinates agree
// to about 1e-12, the round-off of the affine map).
h  = 0.1;   // far from the fractures
hf = 0.05;  // at the fracture ends
Point(1) = {0, 0, 0, h}; Point(2) = {1, 0, 0, h}; Point(3) = {1, 1, 0, h}; Point(4) = {0, 1, 0, h};
Point(8) = {2, 0, 0, h}; Point(9) = {2, 1, 0, h};
Point(5) = {0.4, 0.8, 0, hf}; Point(6) = {1, 0.35, 0, hf}; Point(7) = {1.6, 0.8, 0, hf};
// Left half: bottom, axis (below and above the apex), top, left side; fracture 1.
Line(1) = {1, 2}; Line(2) = {2, 6}; Line(3) = {6, 3}; Line(4) = {3, 4}; Line(5) = {4, 1};
Line(6) = {5, 6};
// Right half: the mirror images of lines 1, 5, 4 and 6 (same orientation under the reflection).
Line(7) = {8, 2}; Line(8) = {9, 8}; Line(9) = {3, 9};
Line(10) = {7, 6};
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};
Curve Loop(2) = {7, 2, 3, 9, 8};
Plane Surface(2) = {2};
Curve{6} In Surface{1};
Curve{10} In Surface{2};
Transfinite Curve{6} = 16; // 15 fracture faces per arm
Periodic Curve{7} = {1} Affine {-1, 0, 0, 2, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
Periodic Curve{8} = {5} Affine {-1, 0, 0, 2, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
Periodic Curve{9} = {4} Affine {-1, 0, 0, 2, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
Periodic Curve{10} = {6} Affine {-1, 0, 0, 2, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
Periodic Surface{2} = {1} Affine {-1, 0, 0, 2, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
// Boundary ids are the physical tags (gmsh reserves 0, hence 10-13); fractures are named.
Physical Curve("left", 10)   = {5};
Physical Curve("right", 11)  = {8};
Physical Curve("bottom", 12) = {1, 7};
Physical Curve("top", 13)    = {4, 9};
Physical Curve("fracture 1", 101) = {6};
Physical Curve("fracture 2", 102) = {10};
Physical Surface("rock", 1) = {1, 2};

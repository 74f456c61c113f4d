// A unit square with an X of two fractures, for the mesh-file reader test. Physical curves named
// "fracture N" are fractures; other physical curves give boundary ids (their tag).
h = 0.1;
Point(1) = {0, 0, 0, h}; Point(2) = {1, 0, 0, h}; Point(3) = {1, 1, 0, h}; Point(4) = {0, 1, 0, h};
Point(5) = {0.2, 0.5, 0, h}; Point(6) = {0.5, 0.5, 0, h}; Point(7) = {0.8, 0.5, 0, h};
Point(8) = {0.5, 0.2, 0, h}; Point(9) = {0.5, 0.8, 0, h};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {8, 6}; Line(8) = {6, 9};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Curve{5, 6, 7, 8} In Surface{1};
Physical Curve("bottom", 12) = {1};
Physical Curve("right", 11) = {2};
Physical Curve("top", 13) = {3};
Physical Curve("left", 10) = {4};
Physical Curve("fracture 1") = {5, 6};
Physical Curve("fracture 2") = {7, 8};
Physical Surface("rock", 1) = {1};

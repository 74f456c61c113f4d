// A unit square with an embedded curve but a fracture id too large to be stored:
// its digits would wrap around into another id.
h = 0.25;
Point(1) = {0, 0, 0, h}; Point(2) = {1, 0, 0, h}; Point(3) = {1, 1, 0, h}; Point(4) = {0, 1, 0, h};
Point(5) = {0.2, 0.5, 0, h}; Point(6) = {0.8, 0.5, 0, h};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Curve{5} In Surface{1};
Physical Curve("fracture 4294967297") = {5};
Physical Surface("rock", 1) = {1};

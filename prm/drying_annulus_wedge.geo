// A quarter of the hollow cylinder of the drying scene (axis x, 0 <= x <= 10 m, 5 <= r <= 35 m,
// the quadrant y <= 0, z >= 0) with one planar fracture: the annular sector x = 5 m,
// 5 <= r <= 6.5 m, from the inner wall. Boundary ids: 10 x = 0, 11 x = 10, 12 inner wall, 13 outer
// surface, 14 the cut plane y = 0, 15 the cut plane z = 0. Cell size h0 at the inner wall,
// growing by g per metre of radius (both may be set by a file that includes this one).
SetFactory("OpenCASCADE");
If (!Exists(h0))
  h0 = 0.4;
EndIf
If (!Exists(g))
  g = 0.2;
EndIf
L = 10; Ri = 5; Re = 35; xf = 5; rf = 6.5;
Cylinder(1) = {0, 0, 0, L, 0, 0, Re, Pi/2};
Cylinder(2) = {0, 0, 0, L, 0, 0, Ri, Pi/2};
BooleanDifference(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
Point(101) = {xf, -Ri, 0}; Point(102) = {xf, -rf, 0}; Point(103) = {xf, 0, rf}; Point(104) = {xf, 0, Ri};
Point(105) = {xf, 0, 0};
Line(101) = {101, 102}; Circle(102) = {102, 105, 103}; Line(103) = {103, 104}; Circle(104) = {104, 105, 101};
Curve Loop(101) = {101, 102, 103, 104}; Plane Surface(101) = {101};
v() = BooleanFragments{ Volume{3}; Delete; }{ Surface{101}; Delete; };
e = 1e-6;
Physical Surface("x min", 10) = Surface In BoundingBox{-e, -Re-e, -Re-e, e, Re+e, Re+e};
Physical Surface("x max", 11) = Surface In BoundingBox{L-e, -Re-e, -Re-e, L+e, Re+e, Re+e};
inner() = Surface In BoundingBox{-e, -Ri-e, -e, L+e, e, Ri+e};
Physical Surface("inner wall", 12) = inner();
y0() = Surface In BoundingBox{-e, -e, -Re-e, L+e, e, Re+e};
Physical Surface("y 0", 14) = y0();
z0() = Surface In BoundingBox{-e, -Re-e, -e, L+e, Re+e, e};
Physical Surface("z 0", 15) = z0();
fr() = Surface In BoundingBox{xf-e, -rf-e, -e, xf+e, e, rf+e};
Physical Surface("fracture 1", 101) = fr();
x0() = Surface In BoundingBox{-e, -Re-e, -Re-e, e, Re+e, Re+e};
x1() = Surface In BoundingBox{L-e, -Re-e, -Re-e, L+e, Re+e, Re+e};
outer() = Surface{:};
outer() -= {x0(), x1(), inner(), y0(), z0(), fr()};
Physical Surface("outer surface", 13) = outer();
Field[1] = MathEval;
Field[1].F = Sprintf("%g + %g*(Sqrt(y*y+z*z)-5)", h0, g);
Background Field = 1;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Physical Volume("rock", 1) = Volume{:};

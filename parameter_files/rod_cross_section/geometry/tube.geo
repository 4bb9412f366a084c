// A hollow circular tube: outer radius 1, inner radius 0.8 (wall 0.2).
// Boundary parts `outer` and `inner` (e.g. for surface layers), region `wall`.
// Each circle is four quarter arcs (a gmsh Circle spans less than pi).
R  = 1.0;   // outer radius
Ri = 0.8;   // inner radius
lc = 0.06;  // element size

Point(1) = {0, 0, 0, lc};
Point(2) = { R, 0, 0, lc}; Point(3) = {0,  R, 0, lc};
Point(4) = {-R, 0, 0, lc}; Point(5) = {0, -R, 0, lc};
Point(6) = { Ri, 0, 0, lc}; Point(7) = {0,  Ri, 0, lc};
Point(8) = {-Ri, 0, 0, lc}; Point(9) = {0, -Ri, 0, lc};
Circle(1) = {2, 1, 3}; Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5}; Circle(4) = {5, 1, 2};
Circle(5) = {6, 1, 7}; Circle(6) = {7, 1, 8};
Circle(7) = {8, 1, 9}; Circle(8) = {9, 1, 6};
Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(1) = {1, 2};

Physical Surface("wall", 1) = {1};
Physical Curve("outer", 1) = {1, 2, 3, 4};
Physical Curve("inner", 2) = {5, 6, 7, 8};

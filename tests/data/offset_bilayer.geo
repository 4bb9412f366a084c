// A 1 x 0.5 bilayer rectangle, deliberately not centred at the origin
// (lower-left corner at (2, 1)): the reader must shift it. Regions by
// physical surface tag: 7 (lower layer), 9 (upper layer).
lc = 0.25;
Point(1) = {2, 1, 0, lc};    Point(2) = {3, 1, 0, lc};
Point(3) = {3, 1.25, 0, lc}; Point(4) = {2, 1.25, 0, lc};
Point(5) = {3, 1.5, 0, lc};  Point(6) = {2, 1.5, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {3, 5}; Line(6) = {5, 6}; Line(7) = {6, 4};
Curve Loop(1) = {1, 2, 3, 4};  Plane Surface(1) = {1};
Curve Loop(2) = {-3, 5, 6, 7}; Plane Surface(2) = {2};
Transfinite Curve{1, 3, 6} = 9; Transfinite Curve{2, 4, 5, 7} = 3;
Transfinite Surface{1}; Transfinite Surface{2};
Recombine Surface{1, 2};
Physical Surface(7) = {1};
Physical Surface(9) = {2};
Physical Curve(1) = {1, 2, 5, 6, 7, 4};

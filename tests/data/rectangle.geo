// The built-in rectangle of Width 2 (along X1) and Height 1 (along X2),
// centred at the origin, with its sides as named boundary parts. Any
// straight-sided quadrilateral mesh of it has exactly the rectangle's area
// and second moments (test_geometry rectangle_geo).
lc = 0.25;
Point(1) = {-1, -0.5, 0, lc}; Point(2) = {1, -0.5, 0, lc};
Point(3) = {1, 0.5, 0, lc};   Point(4) = {-1, 0.5, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Surface("section", 1) = {1};
Physical Curve("left", 1) = {4};
Physical Curve("right", 2) = {2};
Physical Curve("bottom", 3) = {1};
Physical Curve("top", 4) = {3};

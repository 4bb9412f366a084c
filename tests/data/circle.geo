// A disc of radius 1 as four quarter arcs, with a point size larger than the
// disc so that the Mesh size given to the reader (gmsh -clmax) sets the
// element size alone (test_geometry circle_area_convergence).
R  = 1;
lc = 2;
Point(1) = {0, 0, 0, lc};
Point(2) = {R, 0, 0, lc}; Point(3) = {0, R, 0, lc};
Point(4) = {-R, 0, 0, lc}; Point(5) = {0, -R, 0, lc};
Circle(1) = {2, 1, 3}; Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5}; Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Surface("section", 1) = {1};
Physical Curve("outer", 1) = {1, 2, 3, 4};

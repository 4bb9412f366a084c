// An I-beam (H) section: two flanges joined by a web, symmetric about both
// axes so its centroid is the origin. Height 1 along X2, flange width 0.6
// along X1, flange thickness 0.1, web thickness 0.08.
// Meshed to quadrilaterals by the rod_cross_section application (Shape = gmsh,
// Mesh file = this file); `Mesh size` there caps lc.
H  = 1.0;   // overall height
B  = 0.6;   // flange width
tf = 0.1;   // flange thickness
tw = 0.08;  // web thickness
lc = 0.04;  // target element size: >= 2 elements across the thinnest wall

Point(1)  = {-B/2, -H/2, 0, lc};
Point(2)  = { B/2, -H/2, 0, lc};
Point(3)  = { B/2, -H/2 + tf, 0, lc};
Point(4)  = { tw/2, -H/2 + tf, 0, lc};
Point(5)  = { tw/2,  H/2 - tf, 0, lc};
Point(6)  = { B/2,  H/2 - tf, 0, lc};
Point(7)  = { B/2,  H/2, 0, lc};
Point(8)  = {-B/2,  H/2, 0, lc};
Point(9)  = {-B/2,  H/2 - tf, 0, lc};
Point(10) = {-tw/2,  H/2 - tf, 0, lc};
Point(11) = {-tw/2, -H/2 + tf, 0, lc};
Point(12) = {-B/2, -H/2 + tf, 0, lc};
For i In {1:11}
  Line(i) = {i, i + 1};
EndFor
Line(12) = {12, 1};
Curve Loop(1) = {1:12};
Plane Surface(1) = {1};

Physical Surface("section", 1) = {1};
Physical Curve("outer", 1) = {1:12};

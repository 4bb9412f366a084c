// A thin-walled open channel (C) section: web along X2 at the left, two
// flanges pointing to +X1. Height 1, flange width 0.5, wall thickness 0.1
// (a tenth of the height). Not symmetric about X2: the application shifts the
// mesh so that its centroid is the origin (and reports the shift).
H  = 1.0;   // overall height (outer)
B  = 0.5;   // flange width (outer)
t  = 0.1;   // wall thickness
lc = 0.04;  // >= 2 elements across the wall before quad subdivision
x0 = -0.15; // roughly centres the section (the centroid is near X1 = 0)

Point(1) = {x0,         -H/2,     0, lc};
Point(2) = {x0 + B,     -H/2,     0, lc};
Point(3) = {x0 + B,     -H/2 + t, 0, lc};
Point(4) = {x0 + t,     -H/2 + t, 0, lc};
Point(5) = {x0 + t,      H/2 - t, 0, lc};
Point(6) = {x0 + B,      H/2 - t, 0, lc};
Point(7) = {x0 + B,      H/2,     0, lc};
Point(8) = {x0,          H/2,     0, lc};
For i In {1:7}
  Line(i) = {i, i + 1};
EndFor
Line(8) = {8, 1};
Curve Loop(1) = {1:8};
Plane Surface(1) = {1};

Physical Surface("section", 1) = {1};
Physical Curve("outer", 1) = {1:8};

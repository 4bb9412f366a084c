// A cross (+) section: two bars of length A and thickness T crossing at
// the origin, along X1 and X2. Its four-fold symmetry makes its bending
// isotropic (I11 = I22, I12 = 0) and puts its shear centre at the centroid;
// as an open thin-walled section its torsional stiffness is small against
// its bending stiffness (C/B about 0.77 (T/(A/2))^2 for thin bars): the
// section of a tendril that overwinds when pulled (parameter_files/rod/
// tendril_overwinding.prm). Meshed to quadrilaterals by rod_cross_section
// (Shape = gmsh, Mesh file = this file).
A  = 0.01;   // bar length (tip to tip)
T  = 0.0025; // bar thickness
lc = 0.000625; // element size: 4 across a bar

Point(1)  = { T/2, -T/2, 0, lc};
Point(2)  = { A/2, -T/2, 0, lc};
Point(3)  = { A/2,  T/2, 0, lc};
Point(4)  = { T/2,  T/2, 0, lc};
Point(5)  = { T/2,  A/2, 0, lc};
Point(6)  = {-T/2,  A/2, 0, lc};
Point(7)  = {-T/2,  T/2, 0, lc};
Point(8)  = {-A/2,  T/2, 0, lc};
Point(9)  = {-A/2, -T/2, 0, lc};
Point(10) = {-T/2, -T/2, 0, lc};
Point(11) = {-T/2, -A/2, 0, lc};
Point(12) = { T/2, -A/2, 0, lc};
For i In {1:11}
  Line(i) = {i, i + 1};
EndFor
Line(12) = {12, 1};
Curve Loop(1) = {1:12};
Plane Surface(1) = {1};

Physical Surface("section", 1) = {1};
Physical Curve("outer", 1) = {1:12};

// A disc of radius 1 (region `matrix`) with four embedded circular filaments
// of radius 0.15 centred at radius 0.6 on the X1 and X2 axes (region
// `filaments`), e.g. stiffer or differently growing fibres. The filament
// boundaries are interfaces, not boundary parts; the only boundary part is
// `outer`.
R  = 1.0;   // disc radius
a  = 0.15;  // filament radius
d  = 0.6;   // radius of the filament centres
lc = 0.08;  // element size; the quad subdivision halves it, so a filament
            // boundary has about 24 straight segments

Point(1) = {0, 0, 0, lc};
Point(2) = { R, 0, 0, lc}; Point(3) = {0,  R, 0, lc};
Point(4) = {-R, 0, 0, lc}; Point(5) = {0, -R, 0, lc};
Circle(1) = {2, 1, 3}; Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5}; Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4};

// Filament k at angle k*90 degrees: centre point, four quarter arcs, a loop
// and its plane surface.
For k In {0:3}
  cx = d * Cos(k * Pi / 2); cy = d * Sin(k * Pi / 2);
  c  = newp; Point(c) = {cx, cy, 0, lc};
  p1 = newp; Point(p1) = {cx + a, cy, 0, lc};
  p2 = newp; Point(p2) = {cx, cy + a, 0, lc};
  p3 = newp; Point(p3) = {cx - a, cy, 0, lc};
  p4 = newp; Point(p4) = {cx, cy - a, 0, lc};
  l1 = newc; Circle(l1) = {p1, c, p2};
  l2 = newc; Circle(l2) = {p2, c, p3};
  l3 = newc; Circle(l3) = {p3, c, p4};
  l4 = newc; Circle(l4) = {p4, c, p1};
  loops[k] = newll; Curve Loop(loops[k]) = {l1, l2, l3, l4};
  fibres[k] = news; Plane Surface(fibres[k]) = {loops[k]};
EndFor
matrix = news; Plane Surface(matrix) = {1, loops[]};

Physical Surface("matrix", 1) = {matrix};
Physical Surface("filaments", 2) = {fibres[]};
Physical Curve("outer", 1) = {1, 2, 3, 4};

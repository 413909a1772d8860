// Idealized fusiform aneurysm: a surface of revolution about the z axis (lengths in mm).
//
//   parent artery radius  R0 = 2 mm, from z = -L/2 to z = L/2 with L = 40 mm
//   axisymmetric bulge    r(z) = R0 (1 + (k - 1) (1 + cos(pi z / a)) / 2)  for |z| <= a,
//                         r(z) = R0 elsewhere; k = 2.5 (maximum radius k R0 = 5 mm at z = 0),
//                         a = 10 mm (the bulge spans -10 mm <= z <= 10 mm; the profile has a
//                         continuous slope where it meets the straight parts)
//
// The meridian profile (in the plane y = 0, x = r) is a straight line, a spline through
// points of r(z) and a straight line; it runs from the outlet (z = +L/2) down to the inlet
// (z = -L/2), so that the revolved surface's parametrization (along the profile, then
// counterclockwise about +z) gives element normals pointing OUT of the vessel, the
// direction along which the internal pressure acts. It is revolved about z in four
// quarter turns (Gmsh's built-in kernel revolves by less than pi at a time).
//
// Physical groups: Surface("wall"); Curve("inlet") (the circle z = -L/2) and
// Curve("outlet") (the circle z = +L/2).
//
// Mesh size: lc = 0.6 mm gives about 5000 linear triangles. Refine by lowering lc,
// e.g. on the command line `gmsh -2 -setnumber lc 0.3 aneurysm.geo` (about 4 times as
// many triangles; the count grows as 1/lc^2). Mesh.ElementOrder = 2 gives 6-node curved
// triangles, far more accurate for their nodes (docs/user-guide.md §3.1); Tunica reads
// 3-node and 6-node triangles and 4-node quadrangles (for those add `Recombine Surface{:};`
// and keep order 1).

DefineConstant[ lc = {0.6, Name "Parameters/mesh size lc (mm)"} ];
R0 = 2;      // parent artery radius (mm)
L = 40;      // length (mm)
k = 2.5;     // bulge: maximum radius / R0
a = 10;      // half-length of the bulge (mm)
nb = 21;     // points on the bulge spline

Mesh.CharacteristicLengthMax = lc;
Mesh.CharacteristicLengthFromPoints = 1;
Mesh.ElementOrder = 1;

// Profile from the outlet (z = L/2) to the inlet (z = -L/2).
Point(1) = {R0, 0, L / 2, lc};
Point(2) = {R0, 0, a, lc};
For i In {1 : nb - 2}
  z = a - 2 * a * i / (nb - 1);
  Point(2 + i) = {R0 * (1 + (k - 1) * (1 + Cos(Pi * z / a)) / 2), 0, z, lc};
EndFor
Point(nb + 1) = {R0, 0, -a, lc};
Point(nb + 2) = {R0, 0, -L / 2, lc};

Line(1) = {1, 2};
Spline(2) = {2 : nb + 1};
Line(3) = {nb + 1, nb + 2};

// Revolve in four quarter turns; for each curve, Extrude returns the rotated curve
// (e[0], e[4], e[8]) and the surface (e[1], e[5], e[9]), then the swept arcs.
wall[] = {};
c[] = {1, 2, 3};
For q In {0 : 3}
  e[] = Extrude {{0, 0, 1}, {0, 0, 0}, Pi / 2} { Curve{c[]}; };
  wall[] += {e[1], e[5], e[9]};
  c[] = {e[0], e[4], e[8]};
EndFor
Coherence;  // merge the duplicate points and curves where the last quarter meets the first

// The end circles: the curves lying in the planes z = -L/2 and z = L/2.
eps = 1e-3;
inlet[] = Curve In BoundingBox {-R0 - eps, -R0 - eps, -L / 2 - eps, R0 + eps, R0 + eps, -L / 2 + eps};
outlet[] = Curve In BoundingBox {-R0 - eps, -R0 - eps, L / 2 - eps, R0 + eps, R0 + eps, L / 2 + eps};

Physical Surface("wall") = {wall[]};
Physical Curve("inlet") = {inlet[]};
Physical Curve("outlet") = {outlet[]};

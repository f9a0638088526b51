// triboFoam: pear-shaped tube expansion, gmsh mesh of the half tube
// (x >= 0), the same structured mesh as base/system/blockMeshDict: inner
// radius 26.9 mm, outer 28.5 mm (source), centred at the origin, one cell
// layer 1 mm thick in z (plane strain). Units: m.
//   gmsh -3 -format msh2 -setnumber nWall 4 -setnumber nQuarter 90 tube.geo
//   gmshToFoam tube.msh
// then set the patch types in constant/polyMesh/boundary: outer wall,
// symmetry symmetryPlane, frontAndBack empty (../Allrun -gmsh does all).
// nWall: cells through the wall; nQuarter: cells around each quarter
// (from system/meshParameters).
DefineConstant[ nWall = 4, nQuarter = 90 ];

Ri = 0.0269;
Ro = 0.0285;
h = 0.001;

Point(1) = {0, 0, 0};           // centre of the arcs
Point(2) = {0, -Ri, 0};  Point(3) = {0, -Ro, 0};    // bottom
Point(4) = {Ri, 0, 0};   Point(5) = {Ro, 0, 0};     // side
Point(6) = {0, Ri, 0};   Point(7) = {0, Ro, 0};     // top

Line(1) = {2, 3};               // through the wall: bottom, side, top
Line(2) = {4, 5};
Line(3) = {6, 7};
Circle(4) = {3, 1, 5};          // outer surface, two quarters
Circle(5) = {5, 1, 7};
Circle(6) = {2, 1, 4};          // inner surface
Circle(7) = {4, 1, 6};

Curve Loop(1) = {1, 4, -2, -6};
Plane Surface(1) = {1};         // lower quarter
Curve Loop(2) = {2, 5, -3, -7};
Plane Surface(2) = {2};         // upper quarter

Transfinite Curve{1, 2, 3} = nWall + 1;
Transfinite Curve{4, 5, 6, 7} = nQuarter + 1;
Transfinite Surface{1, 2};
Recombine Surface{1, 2};

// one layer of hexahedra; lateral surfaces follow the curve loops:
// b[2] <- 1, b[3] <- 4, b[4] <- 2 (shared), b[5] <- 6;
// t[2] <- 2 (shared), t[3] <- 5, t[4] <- 3, t[5] <- 7
b[] = Extrude {0, 0, h} { Surface{1}; Layers{1}; Recombine; };
t[] = Extrude {0, 0, h} { Surface{2}; Layers{1}; Recombine; };

Physical Surface("inner") = {b[5], t[5]};
Physical Surface("outer") = {b[3], t[3]};
Physical Surface("symmetry") = {b[2], t[4]};
Physical Surface("frontAndBack") = {1, 2, b[0], t[0]};
Physical Volume("tube") = {b[1], t[1]};

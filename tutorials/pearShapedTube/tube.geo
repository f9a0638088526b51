// triboFoam: pear-shaped tube expansion, gmsh mesh of the half tube
// (x >= 0), the same structured mesh as base/system/blockMeshDict: inner
// radius 26.9 mm, outer 28.5 mm (source), centred at the origin, one cell
// layer 1 mm thick in z (plane strain). Units: m.
//   gmsh -3 -format msh2 -setnumber nWall 4 -setnumber nQuarter 90 \
//        -setnumber wallRatio 2 tube.geo
//   gmshToFoam tube.msh
// then set the patch types in constant/polyMesh/boundary: outer wall,
// symmetry symmetryPlane, frontAndBack empty (../Allrun -gmsh does all).
// nWall: cells through the wall; nQuarter: cells around each quarter;
// wallRatio: the through-wall grading, largest over
// smallest cell of each half of the wall, the cells thinnest at both
// surfaces (blockMesh's wallGrading ((0.5 0.5 r) (0.5 0.5 1/r)); 1:
// uniform). From system/meshParameters (nQuarter: its nTop; ../Allrun -gmsh
// needs the cells around uniform, nBottom = nTop and both gradings 1).
DefineConstant[ nWall = 4, nQuarter = 90, wallRatio = 1 ];

Ri = 0.0269;
Ro = 0.0285;
Rm = 0.5*(Ri + Ro);             // mid-wall: the grading's turning point
h = 0.001;

Point(1) = {0, 0, 0};           // centre of the arcs
Point(2) = {0, -Ri, 0};  Point(3) = {0, -Ro, 0};    // bottom
Point(4) = {Ri, 0, 0};   Point(5) = {Ro, 0, 0};     // side
Point(6) = {0, Ri, 0};   Point(7) = {0, Ro, 0};     // top
Point(8) = {0, -Rm, 0};  Point(9) = {Rm, 0, 0};  Point(10) = {0, Rm, 0};

// through the wall in two halves, inner -> middle -> outer: bottom, side,
// top
Line(1) = {2, 8};  Line(11) = {8, 3};
Line(2) = {4, 9};  Line(12) = {9, 5};
Line(3) = {6, 10}; Line(13) = {10, 7};
Circle(4) = {3, 1, 5};          // outer surface, two quarters
Circle(5) = {5, 1, 7};
Circle(6) = {2, 1, 4};          // inner surface
Circle(7) = {4, 1, 6};

Curve Loop(1) = {1, 11, 4, -12, -2, -6};
Plane Surface(1) = {1};         // lower quarter
Curve Loop(2) = {2, 12, 5, -13, -3, -7};
Plane Surface(2) = {2};         // upper quarter

// each half of the wall: nWall/2 cells growing by the factor
// wallRatio^(1/(nWall/2 - 1)) from the surface to the middle
nHalf = nWall/2;
p = 1;
If (nHalf > 1)
    p = wallRatio^(1/(nHalf - 1));
EndIf
Transfinite Curve{1, 2, 3} = nHalf + 1 Using Progression p;
Transfinite Curve{11, 12, 13} = nHalf + 1 Using Progression 1/p;
Transfinite Curve{4, 5, 6, 7} = nQuarter + 1;
Transfinite Surface{1} = {2, 3, 5, 4};
Transfinite Surface{2} = {4, 5, 7, 6};
Recombine Surface{1, 2};

b[] = Extrude {0, 0, h} { Surface{1}; Layers{1}; Recombine; };
t[] = Extrude {0, 0, h} { Surface{2}; Layers{1}; Recombine; };

// one layer of hexahedra; lateral surfaces follow the curve loops:
// b[2], b[3] <- 1, 11; b[4] <- 4; b[5], b[6] <- 12, 2 (shared); b[7] <- 6;
// t[2], t[3] <- 2, 12 (shared); t[4] <- 5; t[5], t[6] <- 13, 3; t[7] <- 7
Physical Surface("inner") = {b[7], t[7]};
Physical Surface("outer") = {b[4], t[4]};
Physical Surface("symmetry") = {b[2], b[3], t[5], t[6]};
Physical Surface("frontAndBack") = {1, 2, b[0], t[0]};
Physical Volume("tube") = {b[1], t[1]};

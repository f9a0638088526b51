#!/usr/bin/env python3
# Two disconnected blocks of different materials (cell zones, doc/theory.md
# [C9]) under the same compressive traction p, plane strain, lateral sides
# free: in each block sigma_yy = -p, sigma_xx = 0, so with Hooke's law
# ([S3], linear in the displacement gradient, exact on any mesh)
#   eps_yy = -(1 - nu^2) p/E,  eps_xx = nu (1 + nu) p/E,
#   u_y = eps_yy y,  u_x = eps_xx (x - x0)  (x0 the block's symmetry plane).
# Writes results.dat: the largest error of the cell displacements of each
# block relative to the block's largest displacement.
import os
import sys

sys.path.insert(0, os.path.join(os.environ["TRIBOFOAM_DIR"], "bin", "python"))
import foamio

p = 1e8
blocks = {  # name: (x0, E, nu), block on x0 <= x <= x0 + 1
    "steel": (0.0, 200e9, 0.3),
    "aluminium": (2.0, 70e9, 0.33),
}

case = sys.argv[1] if len(sys.argv) > 1 else "."
t = foamio.latestTime(case)
D = foamio.readInternalField(os.path.join(case, t, "D"))
C = foamio.readInternalField(os.path.join(case, "0", "C"), len(D))

res = {}
for name, (x0, E, nu) in blocks.items():
    exx = nu*(1 + nu)*p/E
    eyy = -(1 - nu*nu)*p/E
    err, scale, n = 0.0, 0.0, 0
    for d, c in zip(D, C):
        if x0 <= c[0] <= x0 + 1:
            ex = (exx*(c[0] - x0), eyy*c[1])
            err = max(err, abs(d[0] - ex[0]), abs(d[1] - ex[1]))
            scale = max(scale, abs(ex[0]), abs(ex[1]))
            n += 1
    res[name + "RelError"] = err/scale
    res[name + "Cells"] = n
    res[name + "StrainYY"] = eyy
    print("twoBodies: %s (E %.3g Pa, nu %.2f): %d cells, eps_yy %.6e, largest"
          " displacement error %.2e of the largest displacement"
          % (name, E, nu, n, eyy, err/scale))
foamio.writeResults(os.path.join(case, "results.dat"), res,
                    "two bodies with their own laws under the same traction")
